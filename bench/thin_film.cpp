// SPDX-License-Identifier: MIT
// Thin films and measured metals: the tables prism reads per hit against the exact
// spectral integral they approximate (95 wavelengths of Airy's formula, or of the
// conductor Fresnel equations, against the CIE observer). For a soap film 20-900 nm
// thick (and for gold), per table resolution: the worst and RMS RGB error over a grid
// of 200 cosines in [0.05, 1] x 80 thicknesses, the time to build the table, and the
// time per lookup against the time per exact evaluation. (Within 3 degrees of grazing
// the film is a Fabry-Perot etalon of high finesse, both faces reflecting nearly all:
// its resonances are narrower than the 5 nm spectral sum resolves, and R is near 1.)
// Output: results/thin_film.csv.
//   bench_thin_film [results-folder]
#include "common.hpp"

#include <cmath>
#include <cstdio>

namespace {

using namespace prism;

struct Thickness {
    double operator()(const Vec3<double>& p) const { return p.y; } // the thickness is the point's y, in nm
};
using FilmThicknessByY = ThicknessTexture<double, Thickness>;

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "thin_film.csv", "what,cosines,step_nm,entries,worst,rms,build_ms,lookup_ns,exact_ns");
    std::printf("soap film (n 1.33, air both sides), 20-900 nm; error of the table against the exact spectral integral\n");
    const FilmThicknessByY texture{Thickness{}, 20, 900};
    const auto exact_of = [](const CoatedDielectric<double, FilmThicknessByY>& film) {
        return [&film](double c, double l, double d) { return film.spectral_reflectance(c, l, d, true); };
    };
    // The exact integral on the grid, once (it does not depend on the table).
    std::vector<Rgb<double>> exact;
    std::vector<std::pair<double, double>> grid;
    const CoatedDielectric<double, FilmThicknessByY> probe(1.0, 1.33, texture, {}, {.cosines = 2, .thickness_step_nm = 1000});
    for (int i = 0; i < 200; ++i)
        for (int j = 0; j < 80; ++j) {
            const double c = 0.05 + 0.95 * (i + 0.5) / 200, d = 20 + 880 * (j + 0.5) / 80;
            grid.emplace_back(c, d);
            exact.push_back(FilmTable<double>::integrate(exact_of(probe), c, d));
        }
    double exact_seconds = bench::min_seconds(3, [&] {
        volatile double sink = 0;
        for (int k = 0; k < 200; ++k) sink = sink + FilmTable<double>::integrate(exact_of(probe), grid[std::size_t(k)].first, grid[std::size_t(k)].second).x;
    });
    const double exact_ns = 1e9 * exact_seconds / 200;
    for (const int cosines : {17, 33, 65, 129, 257})
        for (const double step : {1.0, 2.0, 4.0, 8.0}) {
            CoatedDielectric<double, FilmThicknessByY>* film = nullptr;
            std::optional<CoatedDielectric<double, FilmThicknessByY>> built;
            const double build = bench::min_seconds(1, [&] { built.emplace(1.0, 1.33, texture, Homogeneous<double>{}, FilmTable<double>::Config{cosines, step}); });
            film = &*built;
            double worst = 0, sum = 0;
            for (std::size_t k = 0; k < grid.size(); ++k) {
                const Rgb<double> t = film->fresnel({grid[k].first, grid[k].first, 1.0, true, {0, grid[k].second, 0}});
                for (int ch = 0; ch < 3; ++ch) {
                    const double e = std::abs(t[ch] - exact[k][ch]);
                    worst = std::max(worst, e);
                    sum += e * e;
                }
            }
            const double rms = std::sqrt(sum / (3.0 * double(grid.size())));
            volatile double sink = 0;
            const int lookups = 1000000;
            const double seconds = bench::min_seconds(3, [&] {
                for (int k = 0; k < lookups; ++k) {
                    const auto& g = grid[std::size_t(k) % grid.size()];
                    sink = sink + film->fresnel({g.first, g.first, 1.0, true, {0, g.second, 0}}).x;
                }
            });
            const double lookup_ns = 1e9 * seconds / lookups;
            std::printf("%3d cosines x %g nm: worst %.2e rms %.2e  build %7.1f ms  lookup %5.1f ns (exact %8.0f ns)\n", cosines, step, worst, rms,
                        1e3 * build, lookup_ns, exact_ns);
            csv.row("soap,%d,%g,%zu,%.6e,%.6e,%.3f,%.3f,%.1f", cosines, step, film->table_entries(), worst, rms, 1e3 * build, lookup_ns, exact_ns);
        }
    // Gold: MeasuredConductor's fixed table of 129 cosines.
    const MeasuredConductor<double> gold(metals::gold);
    double worst = 0;
    for (int i = 0; i <= 10000; ++i) {
        const double c = i / 10000.0;
        const auto a = gold.reflectance(c), b = gold.integrated_reflectance(c);
        worst = std::max({worst, std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
    }
    volatile double sink = 0;
    const double lookup = bench::min_seconds(3, [&] { for (int k = 0; k < 1000000; ++k) sink = sink + gold.reflectance((k % 1000) / 1000.0).x; }) * 1e3;
    const double exact_gold = bench::min_seconds(3, [&] { for (int k = 0; k < 200; ++k) sink = sink + gold.integrated_reflectance(k / 200.0).x; }) / 200 * 1e9;
    std::printf("gold, 129 cosines: worst %.2e  lookup %.1f ns (exact %.0f ns)\n", worst, lookup, exact_gold);
    csv.row("gold,129,0,129,%.6e,0,0,%.3f,%.1f", worst, lookup, exact_gold);
    return 0;
}
