// SPDX-License-Identifier: MIT
// The full ray property run (tests/ray_property.hpp): >= 10^7 rays of every kind at every
// shape, Transformed shapes and CSG trees, placed at 1 to 10^4 from the world origin and
// shot from 1 to 10^6 away, sizes 1 and 10^-3, float and double. Prints a table and
// writes bench/results/ray_property.csv; exits 1 on a lost hit, a disagreement, a NaN or
// Inf or a false occlusion. The test suite runs it whole (ray_property_full) and a slice.
//   bench_ray_property [OUT_DIR] [RAYS_PER_CELL]
#include "../tests/ray_property.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

constexpr double distances[] = {1, 1e2, 1e3, 1e4, 1e6};
constexpr double sizes[] = {1, 1e-3};
constexpr int placements = 8;

} // namespace

int main(int argc, char** argv)
{
    using namespace test::property;
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    const std::size_t per_cell = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 42000;
    std::filesystem::create_directories(out);
    std::ofstream csv(out / "ray_property.csv");
    csv << "shape,scalar,distance,size,rays,hits,lost,disagree,non_finite,wrong_side,spawn_checks,undecidable_spawns,false_occlusion,occlusion_checks,"
           "clear_hits,missed_vs_double,skipped_placements\n";
    Counts total[2];
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t seed = 1;
    for_each_case([&]<class Case>() {
        const auto run = [&]<class T>(int which) {
            for (const double distance : distances)
                for (const double size : sizes) {
                    Counts cell;
                    int skipped = 0;
                    prism::Random rng(seed++, 77u);
                    for (int k = 0; k < placements; ++k) {
                        // Shapes up to 10^4 from the world origin; the 10^6 rays come from
                        // that far to a shape near it.
                        const Placement p = place(rng, distance <= 1e4 ? distance : 1.0, size);
                        try {
                            cell += fire<Case, T>(p, distance, seed * 1000 + k, per_cell / placements);
                        } catch (const std::invalid_argument&) {
                            ++skipped; // not representable in this precision (a box of zero extent)
                        }
                    }
                    total[which] += cell;
                    csv << '"' << Case::name << "\"," << (which == 0 ? "float" : "double") << ',' << distance << ',' << size << ','
                        << cell.rays << ',' << cell.hits << ',' << cell.lost << ',' << cell.disagree << ',' << cell.non_finite << ','
                        << cell.wrong_side << ',' << cell.spawn_checks << ',' << cell.ambiguous << ',' << cell.false_occlusion << ',' << cell.occlusion_checks
                        << ',' << cell.clear_hits << ',' << cell.missed << ',' << skipped << '\n';
                    if (cell.failures() > 0 || cell.missed > 0)
                        std::printf("%-30s %-6s distance %-6g size %-6g: %llu rays, lost %llu, disagree %llu, non-finite %llu, "
                                    "wrong side %llu/%llu (%llu undecidable), false occlusion %llu/%llu, missed vs double %llu/%llu\n",
                                    Case::name, which == 0 ? "float" : "double", distance, size, (unsigned long long)cell.rays,
                                    (unsigned long long)cell.lost, (unsigned long long)cell.disagree, (unsigned long long)cell.non_finite,
                                    (unsigned long long)cell.wrong_side, (unsigned long long)cell.spawn_checks, (unsigned long long)cell.ambiguous,
                                    (unsigned long long)cell.false_occlusion, (unsigned long long)cell.occlusion_checks,
                                    (unsigned long long)cell.missed, (unsigned long long)cell.clear_hits);
                }
        };
        run.template operator()<float>(0);
        run.template operator()<double>(1);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (int which = 0; which < 2; ++which) {
        const Counts& c = total[which];
        std::printf("%s: %llu rays, %llu hits: lost %llu, disagree %llu, non-finite %llu, wrong-side spawns %llu of %llu "
                    "(%llu undecidable), false occlusions %llu of %llu, missed vs double %llu of %llu clear hits\n",
                    which == 0 ? "float " : "double", (unsigned long long)c.rays, (unsigned long long)c.hits, (unsigned long long)c.lost,
                    (unsigned long long)c.disagree, (unsigned long long)c.non_finite, (unsigned long long)c.wrong_side,
                    (unsigned long long)c.spawn_checks, (unsigned long long)c.ambiguous, (unsigned long long)c.false_occlusion,
                    (unsigned long long)c.occlusion_checks, (unsigned long long)c.missed, (unsigned long long)c.clear_hits);
    }
    std::printf("ray property: %.1f s; %s\n", seconds, (out / "ray_property.csv").c_str());
    // What must never happen (wrong-side spawns are a known few, tens in millions, at
    // edges too fine for the double twin to call): the test suite runs this whole.
    for (const Counts& c : total)
        if (c.lost + c.disagree + c.non_finite + c.false_occlusion > 0) {
            std::printf("ray property: FAILED (a lost hit, a disagreement, a NaN or Inf, or a false occlusion)\n");
            return 1;
        }
    return 0;
}
