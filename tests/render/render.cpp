// SPDX-License-Identifier: MIT
#include <prism/render/render.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

using namespace prism;

namespace {

auto busy_scene()
{
    Scene scene{Lights{PointLight<float>{.position = {2, 5, 3}, .intensity = Rgb<float>(40)}},
                Object{Plane<float>({0, 1, 0}, 0), Diffuse<float, Checker<float>>{}},
                Object{Sphere<float>({0, 1, 0}, 1), Dielectric<float>{.ior = 1.5f, .interior = {.absorption = {0.2f, 0.1f, 0.0f}}}},
                Object{Sphere<float>({2, 0.7f, -1}, 0.7f), Mirror<float>{}}};
    scene.background = {0.3f, 0.5f, 0.9f};
    return scene;
}

} // namespace

TEST_CASE("the same bits for 1, 2 and 8 threads")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50};
    RenderConfig config{.width = 96, .height = 64, .spp = 5, .seed = 42, .progress = false, .tile_size = 8};
    for (const SamplerKind kind : {SamplerKind::zsobol, SamplerKind::sobol}) {
        config.sampler = kind;
        config.threads = 1;
        const Film one = render(camera, integrator, config);
        for (unsigned threads : {2u, 8u}) {
            config.threads = threads;
            const Film many = render(camera, integrator, config);
            CHECK(std::memcmp(one.pixels().data(), many.pixels().data(), one.pixels().size() * sizeof(one.pixels()[0])) == 0);
        }
    }
    const Film one = render(camera, integrator, config);
    // A different seed moves the jittered samples.
    config.seed = 43;
    const Film other = render(camera, integrator, config);
    CHECK(std::memcmp(one.pixels().data(), other.pixels().data(), one.pixels().size() * sizeof(one.pixels()[0])) != 0);
    CHECK(one.rejected() == 0);
}

namespace {

/// What `run` writes to stderr (file descriptor 2, as fprintf(stderr) reaches it).
template <class Run>
std::string stderr_of(Run&& run)
{
    char name[] = "/tmp/prism-stderr-XXXXXX";
    const int file = mkstemp(name);
    REQUIRE(file >= 0);
    std::fflush(stderr);
    const int saved = dup(2);
    dup2(file, 2);
    run();
    std::fflush(stderr);
    dup2(saved, 2);
    close(saved);
    std::string text;
    char buffer[4096];
    lseek(file, 0, SEEK_SET);
    for (ssize_t n; (n = read(file, buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
    close(file);
    std::remove(name);
    return text;
}

} // namespace

TEST_CASE("a render carries every finite sample: a light of 2^50 (1.1e15) gives 2^50 times the image of a light of 1, bit for bit")
{
    // Regression: a sample of 2^40 (1.1e12) or more was left out, only counted in
    // Film::rejected(), and the pixels of a light of 10^15 over a floor came out black.
    const auto image = [](float intensity) {
        const Scene scene{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(intensity)}}, Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}};
        const Whitted integrator(scene);
        const Camera<float> camera{.position = {0, 2, 3}, .look_at = {0, 0, 0}, .fov = 30};
        return render(camera, integrator, {.width = 8, .height = 8, .spp = 4, .threads = 2, .progress = false});
    };
    const Film one = image(1.0f), bright = image(0x1p50f); // a power of two scales every sample exactly
    CHECK(bright.rejected() == 0);
    int lit = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            REQUIRE(bright.at(x, y).r == 0x1p50f * one.at(x, y).r);
            lit += one.at(x, y).r > 0;
        }
    CHECK(lit > 32);
}

TEST_CASE("a render that rejects sample values counts them in the film and, reporting progress, says so on stderr")
{
    // A scene in double with a light of 10^300: its samples are finite, but past float's
    // range, and a film of floats cannot hold their mean.
    const Scene scene{Lights{PointLight<double>{.position = {0, 1, 0}, .intensity = Rgb<double>(1e300)}}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}}};
    const Whitted integrator(scene);
    const Camera<double> camera{.position = {0, 2, 3}, .look_at = {0, 0, 0}, .fov = 30};
    Film film(1, 1);
    const std::string said = stderr_of([&] { film = render(camera, integrator, {.width = 8, .height = 8, .spp = 1, .threads = 2}); });
    CHECK(film.rejected() > 0);
    CHECK(said.find("prism: " + std::to_string(film.rejected()) + " sample values were rejected") != std::string::npos);
    // Without progress reports, the count alone.
    const std::string quiet = stderr_of([&] { film = render(camera, integrator, {.width = 8, .height = 8, .spp = 1, .threads = 2, .progress = false}); });
    CHECK(film.rejected() > 0);
    CHECK(quiet.empty());
}

TEST_CASE("a pixel's footprints: every prefix of 2^m samples one in each elementary box, and each sample uniform")
{
    // Sobol's first two dimensions are a (0, 2)-sequence and Owen's scrambling keeps it
    // one: samples [0, 2^m) put one footprint in each box of area 2^-m, of every shape
    // (2^a x 2^(m-a)), whichever pixel and seed.
    for (const std::uint64_t pixel : {0ULL, 7ULL, 123456ULL})
        for (int m = 0; m <= 6; ++m) {
            const int n = 1 << m;
            const RenderConfig config{.spp = 64, .seed = pixel * 3 + 1};
            for (int a = 0; a <= m; ++a) {
                std::vector<int> boxes(std::size_t(n), 0);
                for (int s = 0; s < n; ++s) {
                    const auto c = detail::camera_sample<float>(config, pixel, std::uint64_t(s));
                    REQUIRE(c.footprint[0] >= 0.0f);
                    REQUIRE(c.footprint[0] < 1.0f);
                    ++boxes[std::size_t(int(c.footprint[0] * float(1 << a)) * (n >> a) + int(c.footprint[1] * float(n >> a)))];
                }
                CHECK(std::ranges::count(boxes, 1) == n);
            }
        }
    // With one sample (and single_sample_at_centre), the pixel's centre.
    const auto centre = detail::camera_sample<double>(RenderConfig{.spp = 1}, 5, 0);
    CHECK(centre.footprint == std::array{0.5, 0.5});
    // One sample not at the centre (a pass of progressive photon mapping, whose passes
    // average over the pixel), from either sampler: uniform over the pixel, so 9000
    // pixels' footprints fill every ninth of it alike (a chi-square test of 8 degrees of
    // freedom: 26.1 is its 0.001 quantile from the top).
    for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::zsobol, SamplerKind::independent}) {
        std::array<int, 9> ninths{};
        for (std::uint64_t pixel = 0; pixel < 9000; ++pixel) {
            const auto c = detail::camera_sample<float>(RenderConfig{.width = 100, .height = 90, .spp = 1, .sampler = kind, .single_sample_at_centre = false}, pixel, 0);
            ++ninths[std::size_t(int(c.footprint[0] * 3) * 3 + int(c.footprint[1] * 3))];
        }
        double chi2 = 0;
        for (int h : ninths) chi2 += (h - 1000.0) * (h - 1000.0) / 1000.0;
        CHECK(chi2 < 26.1);
    }
}

namespace {

/// An integrator whose radiance is a function of the camera ray's direction alone: a
/// step (an edge across the pixel) plus a smooth part, so a pixel's value is the mean of
/// the function over the pixel's footprints.
struct Edge {
    using scalar_type = double;
    [[nodiscard]] static double f(const Vec3<double>& d) noexcept { return (d.x > 0.02 * d.z ? 1.0 : 0.0) + 4.0 * d.y * d.y; }
    [[nodiscard]] Rgb<double> radiance(const Ray<double>& ray, Random&) const noexcept { return Rgb<double>(f(normalize(ray.direction))); }
};

} // namespace

TEST_CASE("any prefix of a pixel's samples is unbiased, for every sampler: the mean over seeds of the first 3 of 64 samples is the pixel's integral")
{
    // Regression: sample s of n fell in row s div m of an m x m grid (m = floor(sqrt(n))),
    // so the first samples of a large spp covered only the top of each pixel and a partial
    // render was biased. The integral: a 2048 x 2048 midpoint rule over the pixel, by the
    // camera's own rays.
    const Camera<double> camera{.position = {0, 0, 0}, .look_at = {0.05, 0.1, -1}, .fov = 20};
    const CameraRays<double> rays = camera.rays(1, 1);
    double integral = 0;
    for (int i = 0; i < 2048; ++i)
        for (int j = 0; j < 2048; ++j) integral += Edge::f(normalize(rays.ray((i + 0.5) / 2048, (j + 0.5) / 2048).direction));
    integral /= 2048.0 * 2048.0;
    for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::zsobol, SamplerKind::independent}) {
        const int seeds = 3000;
        double sum = 0, squares = 0;
        for (int seed = 0; seed < seeds; ++seed) {
            const Accumulation sums = render_sums(camera, Edge{}, {.width = 1, .height = 1, .spp = 64, .sampler = kind, .threads = 1, .seed = std::uint64_t(seed),
                                                                   .progress = false, .passes = {0, 3}});
            const double mean = sums.sum(0, 0, 0).value() / 3.0;
            sum += mean;
            squares += mean * mean;
        }
        const double mean = sum / seeds, error = std::sqrt((squares / seeds - mean * mean) / (seeds - 1));
        MESSAGE(std::string(sampler_name(kind)), ": ", mean, " against ", integral, ", standard error ", error);
        CHECK(std::abs(mean - integral) < 4 * error);
        CHECK(error > 0.001); // the edge crosses the pixel: the samples differ
    }
}

TEST_CASE("a progressive render shows rounds of doubling samples, and ends on the bits of the plain render")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50};
    const RenderConfig config{.width = 24, .height = 16, .spp = 11, .threads = 2, .seed = 5, .progress = false};
    std::vector<std::uint64_t> rounds;
    std::vector<Film> previews;
    const Accumulation sums = render_progressive(camera, integrator, config, [&](const Accumulation& so_far) {
        rounds.push_back(so_far.weight(3, 4));
        previews.push_back(so_far.image());
    });
    CHECK(rounds == std::vector<std::uint64_t>{1, 2, 4, 8, 11});
    // Each preview is the render of its first samples; the last is the whole render.
    for (std::size_t k = 0; k < rounds.size(); ++k) {
        RenderConfig prefix = config;
        prefix.passes = {0, rounds[k]};
        const Film film = render_sums(camera, integrator, prefix).image();
        REQUIRE(std::memcmp(film.pixels().data(), previews[k].pixels().data(), film.pixels().size() * sizeof(film.pixels()[0])) == 0);
    }
    const Film whole = render(camera, integrator, config), last = sums.image();
    CHECK(std::memcmp(whole.pixels().data(), last.pixels().data(), whole.pixels().size() * sizeof(whole.pixels()[0])) == 0);
    CHECK(sums.channels() == std::vector<std::string>{"R", "G", "B"});
    // Asked for, the layers ride along: render_layers' channels, and R, G, B the same bits.
    const Accumulation layered = render_progressive(camera, integrator, config, [](const Accumulation&) {}, true);
    CHECK(layered.channels() == layer_channels<Whitted<std::remove_cvref_t<decltype(scene)>>>());
    const Film layered_image = layered.image();
    CHECK(std::memcmp(whole.pixels().data(), layered_image.pixels().data(), whole.pixels().size() * sizeof(whole.pixels()[0])) == 0);
}

TEST_CASE("a render to a time budget takes a prefix of its samples: the bits of the render of that prefix")
{
    const auto scene = busy_scene();
    const PathTracer integrator(scene);
    const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50};
    RenderConfig config{.width = 32, .height = 24, .spp = 1 << 16, .threads = 2, .seed = 9, .progress = false};
    // A budget spent at once: the first round, one sample, and no more.
    config.seconds = 1e-9;
    const Accumulation one = render_sums(camera, integrator, config);
    CHECK(one.weight(0, 0) == 1);
    CHECK(one.weight(31, 23) == 1);
    // A budget of a fifth of a second: some prefix of the 65536 samples, the same in
    // every pixel, whose bits are those of the render of that prefix.
    config.seconds = 0.2;
    const Accumulation some = render_sums(camera, integrator, config);
    const std::uint64_t taken = some.weight(0, 0);
    CHECK(taken >= 1);
    CHECK(taken < (1u << 16));
    CHECK(some.weight(17, 9) == taken);
    RenderConfig prefix = config;
    prefix.seconds = 0;
    prefix.passes = {0, taken};
    const Film expected = render_sums(camera, integrator, prefix).image(), got = some.image();
    CHECK(std::memcmp(expected.pixels().data(), got.pixels().data(), got.pixels().size() * sizeof(got.pixels()[0])) == 0);
    // A budget larger than the render needs: every sample, the plain render's bits.
    RenderConfig small = config;
    small.spp = 3;
    small.seconds = 1e6;
    const Film budgeted = render(camera, integrator, small);
    small.seconds = 0;
    const Film plain = render(camera, integrator, small);
    CHECK(std::memcmp(plain.pixels().data(), budgeted.pixels().data(), plain.pixels().size() * sizeof(plain.pixels()[0])) == 0);
}

TEST_CASE("bad render settings are rejected")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    CHECK_THROWS_WITH_AS((void)render(Camera<float>{}, integrator, {.spp = 0}), doctest::Contains("spp"), std::invalid_argument);
    for (const double seconds : {-1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
        CHECK_THROWS_WITH_AS((void)render(Camera<float>{}, integrator, {.seconds = seconds}), doctest::Contains("RenderConfig seconds must be finite and >= 0"),
                             std::invalid_argument);
    CHECK_THROWS_AS((void)render(Camera<float>{}, integrator, {.width = -4}), std::invalid_argument);
}

TEST_CASE("a tile as large as int renders the same image")
{
    // Regression: tile_size = INT_MAX overflowed the tile arithmetic (UBSan) and rendered black.
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{.position = {0, 1, 6}, .look_at = {0, 0.5f, 0}};
    const Film tiled = render(camera, integrator, {.width = 40, .height = 30, .progress = false});
    const Film whole = render(camera, integrator, {.width = 40, .height = 30, .progress = false, .tile_size = std::numeric_limits<int>::max()});
    CHECK(std::memcmp(tiled.pixels().data(), whole.pixels().data(), tiled.pixels().size() * sizeof(tiled.pixels()[0])) == 0);
    float sum = 0;
    for (const auto& p : whole.pixels()) sum += p.x + p.y + p.z;
    CHECK(sum > 0);
}

namespace {

bool same_bits(const Film& a, const Film& b)
{
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(a.pixels()[0])) == 0;
}

/// The window w of film.
Film cut(const Film& film, PixelWindow w)
{
    Film part(w.width(), w.height());
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) part.set(x - w.x0, y - w.y0, film.at(x, y));
    return part;
}

} // namespace

TEST_CASE("a crop window is the same bits as those pixels of the whole render, through a pinhole or a thin lens")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    // A pinhole camera, and a thin lens whose rays draw their lens points from the sample's stream.
    for (const float aperture : {0.0f, 0.15f}) {
        CAPTURE(aperture);
        const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50, .aperture_radius = aperture};
        for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::zsobol}) {
            RenderConfig config{.width = 61, .height = 43, .spp = 3, .sampler = kind, .threads = 2, .seed = 9, .progress = false, .tile_size = 8};
            const Film whole = render(camera, integrator, config);
            for (const PixelWindow w : {PixelWindow{0, 0, 61, 43}, PixelWindow{0, 0, 1, 1}, PixelWindow{60, 42, 61, 43}, PixelWindow{13, 7, 50, 31},
                                        PixelWindow{5, 0, 6, 43}, PixelWindow{0, 20, 61, 21}}) {
                config.crop = w;
                for (unsigned threads : {1u, 3u}) {
                    config.threads = threads;
                    const Film crop = render(camera, integrator, config);
                    CHECK(crop.width() == w.width());
                    CHECK(crop.height() == w.height());
                    CHECK(same_bits(crop, cut(whole, w)));
                }
            }
        }
    }
}

TEST_CASE("renders of disjoint sample ranges and crops add up to the whole render, bit for bit, through a pinhole or a thin lens")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    // A pinhole camera, and a thin lens whose rays draw their lens points from the sample's stream.
    for (const float aperture : {0.0f, 0.15f}) {
        CAPTURE(aperture);
        const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50, .aperture_radius = aperture};
        for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::zsobol}) {
            const std::string sampler = sampler_name(kind);
            CAPTURE(sampler);
            const RenderConfig config{.width = 40, .height = 30, .spp = 7, .sampler = kind, .threads = 2, .seed = 5, .progress = false};
            const Film whole = render(camera, integrator, config);
            // Samples [0, 2), [2, 3) and [3, 7), on other thread counts, the last in two crops,
            // added in an order of their own.
            Accumulation sums(40, 30, PixelWindow::whole(40, 30));
            RenderConfig part = config;
            part.passes = {3, 7};
            part.threads = 1;
            part.crop = {0, 0, 40, 11};
            sums += render_sums(camera, integrator, part);
            part.crop = {0, 11, 40, 30};
            sums += render_sums(camera, integrator, part);
            part.crop = {};
            part.passes = {0, 2};
            part.threads = 3;
            render_into(sums, camera, integrator, part);
            part.passes = {2, 3};
            sums += render_sums(camera, integrator, part);
            CHECK(sums.weight(0, 0) == 7);
            CHECK(sums.weight(39, 29) == 7);
            CHECK(same_bits(sums.image(), whole));
            CHECK(same_bits(render_sums(camera, integrator, config).image(), whole));

            // Sample s is the same whichever samples go with it: one sample alone is the whole
            // render at spp = 1 only where the render's samples are the same, so compare the
            // sums of [0, 1) with [0, 1) taken in a render of [0, 4).
            part = config;
            part.passes = {1, 2};
            const Accumulation second = render_sums(camera, integrator, part);
            part.passes = {0, 2};
            Accumulation both = render_sums(camera, integrator, part);
            part.passes = {0, 1};
            Accumulation first = render_sums(camera, integrator, part);
            first += second;
            for (int y = 0; y < 30; ++y)
                for (int x = 0; x < 40; ++x) REQUIRE(first.sums(x, y) == both.sums(x, y));
        }
    }
}

TEST_CASE("a crop or a sample range outside the image is refused with its values")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{};
    const RenderConfig base{.width = 8, .height = 6, .spp = 4, .progress = false};
    RenderConfig bad = base;
    bad.crop = {0, 0, 9, 6};
    CHECK_THROWS_WITH_AS((void)render(camera, integrator, bad), doctest::Contains("crop [0, 9) x [0, 6) must be a non-empty part of the 8 x 6 image"),
                         std::invalid_argument);
    bad.crop = {3, 2, 3, 5};
    CHECK_THROWS_WITH_AS((void)render(camera, integrator, bad), doctest::Contains("crop [3, 3) x [2, 5)"), std::invalid_argument);
    bad.crop = {-1, 0, 4, 4};
    CHECK_THROWS_AS((void)render(camera, integrator, bad), std::invalid_argument);
    bad = base;
    bad.passes = {2, 5};
    CHECK_THROWS_WITH_AS((void)render(camera, integrator, bad), doctest::Contains("passes [2, 5) must be a non-empty range of the spp = 4 samples"),
                         std::invalid_argument);
    bad.passes = {3, 3};
    CHECK_THROWS_AS((void)render_sums(camera, integrator, bad), std::invalid_argument);
    Accumulation small(8, 6, {0, 0, 4, 6});
    CHECK_THROWS_WITH_AS(render_into(small, camera, integrator, base), doctest::Contains("does not hold the render's window"), std::invalid_argument);
}

TEST_CASE("random scenes, hostile cameras: no sample of any integrator is NaN, infinite or negative")
{
    // A property test over whole renders: scenes of random spheres (tiny to
    // huge, some coincident), boxes of glass (some a sheet), mirror quadrics (open ones cut
    // to a box) and a CSG lens, at 1 to 10^4 from the origin, lit by a point light and a
    // directional light, seen from cameras far away, inside objects or grazing the
    // floor, rendered by Whitted, the path tracer and the photon mapper. Every sample
    // the render rejects (not finite, or negative) is counted by the film: none may be.
    using S = Sphere<float>;
    Random rng(2026u, 15u);
    const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * rng.uniform<float>(); };
    const auto point = [&](float r) { return Vec3<float>(uniform(-r, r), uniform(-r, r), uniform(-r, r)); };
    std::size_t renders = 0, samples = 0, lit = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const float far = std::pow(10.0f, float(trial % 5)); // 1 to 10^4 from the origin
        const Vec3<float> centre = point(far);
        ObjectArray<S, Diffuse<float>> balls;
        ObjectArray<Box<float>, Dielectric<float>> glass;
        using Cut = Intersection<Transformed<Quadric<float>>, Box<float>>; // an open quadric cut to a box
        ObjectArray<Cut, Mirror<float>> mirrors;
        for (int i = 0; i < 12; ++i) {
            const float size = std::pow(10.0f, uniform(-3.0f, 1.0f));
            const Vec3<float> at = centre + point(4.0f);
            balls.items.emplace_back(S(at, size), Diffuse<float>{.albedo = {.color = Rgb<float>(uniform(0, 1), uniform(0, 1), uniform(0, 1))}});
            if (i % 4 == 0) balls.items.emplace_back(S(at, size), Diffuse<float>{}); // a coincident twin
            const Vec3<float> half_size(size, i % 3 == 0 ? std::max(size * 1e-4f, far * 1e-5f) : size * uniform(0.01f, 1), size); // some a sheet
            glass.items.emplace_back(Box<float>(at - half_size + Vec3<float>(1, 0, 0), at + half_size + Vec3<float>(1, 0, 0)),
                                     Dielectric<float>{.ior = uniform(1.0f, 2.5f)});
        }
        const auto cut = [&](const Quadric<float>& q, const Transform<float>& to_world) {
            const Vec3<float> at = to_world.point({0, 0, 0});
            return Cut(Transformed<Quadric<float>>(q, to_world), Box<float>(at - Vec3<float>(1.5f), at + Vec3<float>(1.5f)));
        };
        mirrors.items.emplace_back(cut(Quadric<float>::cylinder({0, 0, 0}, {0, 1, 0}, 0.5f), Transform<float>::translate(centre + point(3.0f))), Mirror<float>{});
        mirrors.items.emplace_back(cut(Quadric<float>::ellipsoid({0, 0, 0}, {1.0f, 0.2f, 0.5f}),
                                       Transform<float>::rotate(uniform(0, 90), {1, 1, 0}).then(Transform<float>::translate(centre))),
                                   Mirror<float>{});
        mirrors.items.emplace_back(cut(Quadric<float>::hyperboloid_one_sheet(0.3f, 0.3f, 0.5f), Transform<float>::translate(centre + point(2.0f))),
                                   Mirror<float>{});
        const auto lens = intersection_of(S(centre + Vec3<float>(0, 1, 0.5f), 1), S(centre + Vec3<float>(0, 1, -0.5f), 1));
        Scene scene{Lights{PointLight<float>{.position = centre + Vec3<float>(0, 6, 0), .intensity = Rgb<float>(50 * far * far)},
                           DirectionalLight<float>{.direction = normalize(point(1.0f) + Vec3<float>(0, -2, 0)), .irradiance = Rgb<float>(0.5f)}},
                    Object{Plane<float>({0, 1, 0}, centre.y - 2), Diffuse<float>{}}, std::move(balls), std::move(glass), std::move(mirrors),
                    Object{lens, Dielectric<float>{.ior = 1.5f}}};
        scene.background = {0.2f, 0.3f, 0.4f};
        // Far away, inside a ball, grazing the floor.
        const std::array<Camera<float>, 3> cameras{
            Camera<float>{.position = centre + Vec3<float>(0, 3, 40), .look_at = centre, .fov = 30},
            Camera<float>{.position = centre + point(1.0f), .look_at = centre + point(3.0f) + Vec3<float>(5, 0, 0), .fov = 120},
            Camera<float>{.position = centre + Vec3<float>(0, -2.0f + 1e-4f, 8), .look_at = centre + Vec3<float>(0, -2, 0), .fov = 60}};
        const RenderConfig config{.width = 24, .height = 16, .spp = 2, .seed = std::uint64_t(trial), .progress = false};
        const Whitted whitted(scene);
        const PathTracer path(scene, {.max_diffuse_bounces = 4});
        const PhotonMapper mapper(scene, {.tracing = {.global_photons = 3000, .caustic_photons = 3000, .seed = std::uint64_t(trial)}, .gather_rays = 8});
        for (const auto& camera : cameras) {
            for (const Film& film : {render(camera, whitted, config), render(camera, path, config), render(camera, mapper, config)}) {
                CHECK(film.rejected() == 0);
                for (const auto& p : film.pixels()) {
                    REQUIRE(std::isfinite(p.x));
                    REQUIRE(p.x >= 0.0f);
                    lit += p.x > 0.0f;
                }
                ++renders;
                samples += std::size_t(config.width * config.height * config.spp);
            }
        }
    }
    MESSAGE(renders << " renders, " << samples << " camera samples, " << lit << " pixels with light");
    CHECK(renders == 54);
    CHECK(lit > renders * 24 * 16 / 2); // the scenes are seen, not black
}
