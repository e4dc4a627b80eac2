// SPDX-License-Identifier: MIT
// The consistency matrix: prism's vocabulary as type lists (materials, lights, where a
// medium sits, where the camera stands), a scene made of any one of each, and every
// estimator rendering it, held to what must be true there:
//   furnace      under a uniform sky of radiance 1, with materials and fog that lose no
//                light and no floor, every pixel reads 1: the path tracer, the reference,
//                the photon mapper read directly, by final gathering and behind an
//                irradiance cache, progressive photon mapping, BDPT and VCM, and Whitted
//                where only mirrors and glass are seen;
//   agreement    elsewhere (a grey floor, a fog that absorbs), wherever the path tracer
//                has every path (no delta light meets a mirror or glass), the reference
//                (the path tracer and the light tracer, splitting the paths between them),
//                BDPT, VCM and the photon mappers against it, within the noise of both, the
//                photon mappers and VCM within their bias as well; Whitted against the path tracer's
//                direct light where its model is exact (diffuse and mirror surfaces, no
//                glass in the light's way).
// A cell is estimators x one scene: a material kind, a light kind, a placement, a camera.
// A new kind in a list gets its rows with no new test: the lists below are the vocabulary,
// and the cells are generated from them (tests/integrator/consistency.cpp runs a slice in
// the quick tier, tests/matrix/ all of it in the full tier).
// Each estimator renders independent 8 x 8 images in batches (its own seeds, and photons);
// the mean of the image in each channel and its standard error come from the batches, and
// two estimates agree within 6 standard errors (a photon mapper's also within 6 % for its
// kernels' bias).
#pragma once

#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <array>
#include <optional>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace test::matrix {

using namespace prism;
using T = float;

// ---------------------------------------------------------------------------------------
// Materials. Each kind: `name`, `make()`, and `white()` where it loses no light (the
// furnace's), with what the rules ask of it.

struct Lambert {
    static constexpr const char* name = "diffuse";
    static constexpr bool specular = false; ///< a delta lobe: a delta light meets it in caustics
    static constexpr bool transmissive = false;
    static constexpr bool whitted_exact = true; ///< Whitted's model of it is the path tracer's direct light
    static constexpr bool lossless = true;      ///< white() loses no light
    static constexpr bool diffuse_part = true;  ///< some of its light is not specular
    static auto make() { return Diffuse<T>{.albedo = {.color = {0.7f, 0.5f, 0.3f}}}; }
    static auto white() { return Diffuse<T>{.albedo = {.color = Rgb<T>(1)}}; }
};

struct Plastic {
    static constexpr const char* name = "Phong";
    static constexpr bool specular = false, transmissive = false, whitted_exact = false, lossless = false, diffuse_part = true;
    static auto make() { return Phong<T>{.diffuse = {.color = {0.4f, 0.3f, 0.2f}}, .specular = Rgb<T>(0.4f), .exponent = 20}; }
};

struct RoughMetal {
    static constexpr const char* name = "rough metal";
    static constexpr bool specular = false, transmissive = false, whitted_exact = false, lossless = false, diffuse_part = true;
    static auto make() { return RoughConductor<T>{.fresnel = {.kr = {0.9f, 0.7f, 0.5f}}, .roughness = {0.3f, 0.3f}}; }
};

struct MirrorKind {
    static constexpr const char* name = "mirror";
    static constexpr bool specular = true, transmissive = false, whitted_exact = true, lossless = true, diffuse_part = false;
    static auto make() { return Mirror<T>{{.kr = {0.9f, 0.8f, 0.7f}}}; }
    static auto white() { return Mirror<T>{{.kr = Rgb<T>(1)}}; }
};

struct Coated {
    static constexpr const char* name = "coated";
    static constexpr bool specular = false, transmissive = false, whitted_exact = false, lossless = false, diffuse_part = true;
    static auto make() { return CoatedDiffuse<T>(Solid<T>{.color = {0.6f, 0.4f, 0.2f}}, Coat<T>{.ior = 1.5f, .roughness = 0.2f}); }
};

struct Glass {
    static constexpr const char* name = "glass";
    static constexpr bool specular = true, transmissive = true, whitted_exact = false, lossless = true, diffuse_part = false;
    static auto make() { return Dielectric<T>{.ior = 1.5f, .interior = {.absorption = {0.1f, 0.3f, 0.5f}}}; }
    static auto white() { return Dielectric<T>{.ior = 1.5f}; }
};

struct Frosted {
    static constexpr const char* name = "frosted glass";
    static constexpr bool specular = false, transmissive = true, whitted_exact = false, lossless = false, diffuse_part = true;
    static auto make() { return RoughDielectric<T>{.ior = 1.5f, .roughness = 0.3f}; }
};

struct TwoLobes {
    static constexpr const char* name = "diffuse + mirror mix";
    static constexpr bool specular = true, transmissive = false, whitted_exact = false, lossless = true, diffuse_part = true;
    using Mirrorish = RoughConductor<T>; // at roughness 0: a mirror, the delta part of the mix's lobe
    static auto make()
    {
        return Mix<T, Diffuse<T>, Mirrorish>{.first = {.albedo = {.color = {0.3f, 0.6f, 0.3f}}}, .second = {.fresnel = {.kr = Rgb<T>(0.8f)}, .roughness = Roughness<T>(0)}, .weight = 0.5f};
    }
    static auto white()
    {
        return Mix<T, Diffuse<T>, Mirrorish>{.first = {.albedo = {.color = Rgb<T>(1)}}, .second = {.fresnel = {.kr = Rgb<T>(1)}, .roughness = Roughness<T>(0)}, .weight = 0.5f};
    }
};

using Materials = std::tuple<Lambert, Plastic, RoughMetal, MirrorKind, Coated, Glass, Frosted, TwoLobes>;

/// Calls f(std::integral_constant<std::size_t, I>) for I in [0, N).
template <std::size_t N, class F>
constexpr void for_indices(F&& f)
{
    [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, I>{}), ...); }(std::make_index_sequence<N>{});
}

inline constexpr std::size_t material_count = std::tuple_size_v<Materials>;

/// What the rules ask of material kind i, at run time.
struct MaterialFacts {
    const char* name;
    bool specular, transmissive, whitted_exact, lossless, diffuse_part;
};

inline constexpr std::array<MaterialFacts, material_count> material_facts = [] {
    std::array<MaterialFacts, material_count> facts{};
    for_indices<material_count>([&](auto i) {
        using K = std::tuple_element_t<i, Materials>;
        facts[i] = {K::name, K::specular, K::transmissive, K::whitted_exact, K::lossless, K::diffuse_part};
    });
    return facts;
}();

/// The material kinds' balls: one ObjectArray per kind (its material's type), the ball of
/// radius 0.5 at the origin in kind `chosen`'s, the others empty. With `white`, the
/// kind's lossless twin (the furnace's).
inline auto balls(std::size_t chosen, bool white)
{
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        const auto one = [&]<std::size_t K>(std::integral_constant<std::size_t, K>) {
            using Kind = std::tuple_element_t<K, Materials>;
            ObjectArray<Sphere<T>, decltype(Kind::make())> array;
            if (K == chosen) {
                if constexpr (Kind::lossless) array.items.push_back({Sphere<T>({0, 0, 0}, 0.5f), white ? Kind::white() : Kind::make()});
                else array.items.push_back({Sphere<T>({0, 0, 0}, 0.5f), Kind::make()});
            }
            return array;
        };
        return std::tuple{one(std::integral_constant<std::size_t, I>{})...};
    }(std::make_index_sequence<material_count>{});
}

// ---------------------------------------------------------------------------------------
// Lights: the three delta lights are in every scene, all but the chosen one dark; the
// area lights are emitting objects (an array per shape, empty unless chosen); the two
// lights at infinity are the scene's type (Sky).

enum class LightKind { point, spot, directional, quad, disk, sphere, sky, map };
inline constexpr std::array<LightKind, 8> light_kinds{LightKind::point, LightKind::spot, LightKind::directional, LightKind::quad,
                                                      LightKind::disk, LightKind::sphere, LightKind::sky, LightKind::map};
inline constexpr std::array<const char*, 8> light_names{"point", "spot", "directional", "quad area", "disk area", "sphere area", "uniform sky", "environment map"};
inline const char* name_of(LightKind k) { return light_names[std::size_t(k)]; }
inline constexpr bool is_delta(LightKind k) { return k == LightKind::point || k == LightKind::spot || k == LightKind::directional; }

/// Which light at infinity a scene's type holds.
enum class Sky { none, uniform, map };
inline constexpr Sky sky_of(LightKind k) { return k == LightKind::sky ? Sky::uniform : k == LightKind::map ? Sky::map : Sky::none; }

inline constexpr Vec3<T> lamp{0.6f, 1.6f, 0.9f}; ///< where the point, spot and area lights are

/// The environment map: brighter toward +x and overhead, with a small bright patch.
inline EnvironmentMap<T> sky_map()
{
    std::vector<Rgb<float>> pixels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) pixels.push_back(Rgb<float>(0.2f + 0.1f * float(8 - y)) * (x == 3 && y == 2 ? 8.0f : 1.0f + 0.5f * float(x < 8)));
    return EnvironmentMap<T>(16, 8, pixels);
}

template <Sky S>
auto lights(LightKind k)
{
    const auto on = [&](LightKind which, T value) { return Rgb<T>(k == which ? value : T(0)); };
    const PointLight<T> point{.position = lamp, .intensity = on(LightKind::point, 3)};
    const SpotLight<T> spot{.position = lamp, .direction = -lamp, .intensity = on(LightKind::spot, 4), .inner_angle = 20, .outer_angle = 30};
    const DirectionalLight<T> sun{.direction = {-0.3f, -1, -0.4f}, .irradiance = on(LightKind::directional, 1.5f)};
    if constexpr (S == Sky::none) return Lights{point, spot, sun};
    else if constexpr (S == Sky::uniform) return Lights{point, spot, sun, EnvironmentLight<T>{.radiance = {0.6f, 0.8f, 1.0f}}};
    else return Lights{point, spot, sun, sky_map()};
}

/// The area lights' arrays: quads, disks and spheres that emit.
inline auto emitters(LightKind k)
{
    ObjectArray<Quad<T>, Emissive<T>> quads;
    ObjectArray<Disk<T>, Emissive<T>> disks;
    ObjectArray<Sphere<T>, Emissive<T>> spheres;
    if (k == LightKind::quad) quads.items.push_back({Quad<T>({0.3f, 1.6f, 0.6f}, {0.6f, 0, 0}, {0, 0, 0.6f}), Emissive<T>{.radiance = Rgb<T>(6)}});
    if (k == LightKind::disk) disks.items.push_back({Disk<T>(lamp, {0, -1, 0}, 0.3f), Emissive<T>{.radiance = Rgb<T>(8)}});
    if (k == LightKind::sphere) spheres.items.push_back({Sphere<T>(lamp, 0.2f), Emissive<T>{.radiance = Rgb<T>(6)}});
    return std::tuple{quads, disks, spheres};
}

// ---------------------------------------------------------------------------------------
// Where a medium sits: the fog filling the scene's air (its type: FilledAir), or filling
// objects (an array of them, by placement).

enum class Placement { clear, air, smoke, foggy_glass, nested };
inline constexpr std::array<Placement, 5> placements{Placement::clear, Placement::air, Placement::smoke, Placement::foggy_glass, Placement::nested};
inline constexpr std::array<const char*, 5> placement_names{"no medium", "fog filling the air", "fog inside an index-1 ball", "fog inside glass",
                                                            "glass of fog nested in a ball of smoke"};
inline const char* name_of(Placement p) { return placement_names[std::size_t(p)]; }
/// Glass lies between the lights and a fog (no delta light's light reaches it but through a caustic).
inline constexpr bool has_glass(Placement p) { return p == Placement::foggy_glass || p == Placement::nested; }
inline constexpr bool fills_air(Placement p) { return p == Placement::air; }
/// Where a camera inside the medium stands, where one fits.
inline constexpr std::optional<Vec3<T>> inside_of(Placement p)
{
    if (p == Placement::air) return Vec3<T>(0, 0.3f, 1.6f);
    if (p == Placement::smoke) return Vec3<T>(0, 0.2f, 0.72f);
    if (p == Placement::nested) return Vec3<T>(0.35f, 0.45f, 0.55f);
    return std::nullopt;
}

/// The fog of every placement: it scatters and absorbs (a furnace's absorbs nothing).
inline Fog<T> fog(bool furnace) { return {.absorption = Rgb<T>(furnace ? 0.0f : 0.1f), .scattering = {0.6f, 0.9f, 1.2f}, .phase = {.g = 0.3f}}; }

/// An object's fog behind a boundary of `ior` (1: a ball of smoke). Nested objects win by
/// priority: the material's ball over the smoke about it, the glass in the smoke over it.
using Smoke = Dielectric<T, ExactFresnel, Fog<T>>;

inline ObjectArray<Sphere<T>, Smoke> foggy_objects(Placement p, bool furnace)
{
    ObjectArray<Sphere<T>, Smoke> objects;
    if (p == Placement::smoke || p == Placement::nested) objects.items.push_back({Sphere<T>({0, 0, 0}, 0.8f), Smoke{.ior = 1, .interior = fog(furnace), .priority = -1}});
    if (p == Placement::foggy_glass) objects.items.push_back({Sphere<T>({-0.75f, -0.45f, 0.5f}, 0.35f), Smoke{.ior = 1.33f, .interior = fog(furnace)}});
    if (p == Placement::nested) objects.items.push_back({Sphere<T>({0, 0.1f, 0.62f}, 0.1f), Smoke{.ior = 1.33f, .interior = fog(furnace), .priority = 1}});
    return objects;
}

template <bool Filled>
auto air_of(bool furnace)
{
    if constexpr (Filled) return FilledAir<Fog<T>>{.medium = fog(furnace), .region = {Vec3<T>(-2, -0.9f, -2), Vec3<T>(2, 2, 2)}};
    else return (void)furnace, StraightAir{};
}

// ---------------------------------------------------------------------------------------
// Scenes: the material's ball, a grey floor, the lights and the fog's objects; the
// furnace's: the white ball and the fog's objects under a sky of radiance 1.

inline constexpr T floor_y = -0.85f;

template <Sky S>
auto make_scene(std::size_t material, LightKind light, Placement where)
{
    const auto floor = Object{Quad<T>({-3, floor_y, 3}, {6, 0, 0}, {0, 0, -6}), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}}};
    return std::apply([&](const auto&... slots) { return Scene{lights<S>(light), floor, slots...}; },
                      std::tuple_cat(balls(material, false), emitters(light), std::tuple{foggy_objects(where, false)}));
}

inline auto make_furnace(std::size_t material, Placement where)
{
    return std::apply([&](const auto&... slots) { return Scene{Lights{EnvironmentLight<T>{}}, slots...}; },
                      std::tuple_cat(balls(material, true), std::tuple{foggy_objects(where, true)}));
}

/// The camera outside every medium, or inside the placement's.
inline Camera<T> camera(Placement where, bool inside)
{
    if (inside && inside_of(where)) return {.position = *inside_of(where), .look_at = {0, -0.1f, 0}, .fov = 70};
    return {.position = {0.3f, 0.5f, 3.2f}, .look_at = {0, -0.2f, 0}, .fov = 45};
}

// ---------------------------------------------------------------------------------------
// Estimates and verdicts.

/// An estimator's mean of the image per channel, and its standard error.
struct Estimate {
    Rgb<double> mean{0}, error{0};
};

inline constexpr int size = 8; ///< the images' side in pixels

/// The mean over `batches` renders (render_batch(b): batch b's Film), and its standard
/// error from their spread.
template <class RenderBatch>
Estimate estimate(int batches, RenderBatch&& render_batch)
{
    std::vector<Rgb<double>> means;
    for (int b = 0; b < batches; ++b) {
        const Film film = render_batch(b);
        Rgb<double> m{0};
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) m += Rgb<double>(film.at(x, y)) / double(size * size);
        means.push_back(m);
    }
    Estimate e;
    for (const auto& m : means) e.mean += m / double(batches);
    for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (const auto& m : means) s += (m[c] - e.mean[c]) * (m[c] - e.mean[c]);
        e.error[c] = std::sqrt(s / double(batches - 1) / double(batches));
    }
    return e;
}

/// How hard a cell looks.
struct Effort {
    int batches = 12;            ///< of the path tracer, the reference and Whitted
    int spp = 32;                ///< their samples per pixel in a batch
    int photon_batches = 6;      ///< of each photon mapper (16 samples per pixel each)
    std::size_t photons = 30000; ///< global and caustic photons per batch of a photon mapper
    int passes = 8;              ///< progressive photon mapping's passes per batch (photons / 4 each)
};

/// One comparison's verdict, for the table a run prints.
struct Row {
    std::string cell, estimator, against;
    Rgb<double> value{0}, expected{0}, allowed{0};
    bool ok = true;
};

/// Whether `got` agrees with `want`: within k standard errors of both, plus a relative
/// allowance for an estimator's bias (0 for an unbiased one) and a floor far below the
/// images' light.
inline Row compare(const std::string& cell, const char* estimator, const char* against, const Estimate& got, const Estimate& want, double bias, double k = 6)
{
    Row row{cell, estimator, against, got.mean, want.mean, {}, true};
    for (int c = 0; c < 3; ++c) {
        row.allowed[c] = k * std::hypot(got.error[c], want.error[c]) + bias * std::abs(want.mean[c]) + 1e-4;
        row.ok = row.ok && std::isfinite(got.mean[c]) && std::abs(got.mean[c] - want.mean[c]) <= row.allowed[c];
    }
    return row;
}

inline void print(const Row& row)
{
    std::printf("%-4s %-70s %-19s vs %-19s (%.4f %.4f %.4f) vs (%.4f %.4f %.4f) +- (%.4f %.4f %.4f)\n", row.ok ? "ok" : "FAIL", row.cell.c_str(),
                row.estimator.c_str(), row.against.c_str(), row.value.x, row.value.y, row.value.z, row.expected.x, row.expected.y, row.expected.z,
                row.allowed.x, row.allowed.y, row.allowed.z);
}

/// The photon mappers' bias allowed against the reference: their kernels blur the light
/// over a radius (0.05 on surfaces and in volumes here), a few per cent of these images.
inline constexpr double photon_bias = 0.06;

/// Batch b's render settings.
inline RenderConfig batch_config(int spp, int b) { return {.width = size, .height = size, .spp = spp, .threads = 2, .seed = std::uint64_t(1000 + b), .progress = false}; }

template <class SceneT, class Air>
typename PhotonMapper<SceneT, Air>::Config photon_config(const Effort& effort, int b, int gather_rays)
{
    typename PhotonMapper<SceneT, Air>::Config config;
    config.tracing.global_photons = effort.photons;
    config.tracing.caustic_photons = effort.photons;
    config.tracing.seed = std::uint64_t(77 + b);
    config.caustic.radius = 0.05f;
    config.global.radius = 0.1f;
    config.gather_rays = gather_rays;
    config.volume_radius = 0.05f;
    return config;
}

/// The photon mappers on `scene`: read directly, by final gathering, by the gather behind an
/// irradiance cache, and progressively.
template <class SceneT, class Air>
void photon_rows(std::vector<Row>& rows, const std::string& cell, const SceneT& scene, const Air& air, const Camera<T>& cam, const Effort& effort,
                 const Estimate& want, const char* against, double bias)
{
    rows.push_back(compare(cell, "photon map, direct", against, estimate(effort.photon_batches, [&](int b) {
                               return render(cam, PhotonMapper(scene, photon_config<SceneT, Air>(effort, b, 0), air), batch_config(16, b));
                           }), want, bias));
    rows.push_back(compare(cell, "photon map, gather", against, estimate(effort.photon_batches, [&](int b) {
                               return render(cam, PhotonMapper(scene, photon_config<SceneT, Air>(effort, b, 16), air), batch_config(16, b));
                           }), want, bias));
    rows.push_back(compare(cell, "photon map, cache", against, estimate(effort.photon_batches, [&](int b) {
                               // The irradiance cache in front of the gather: records where the camera needs them.
                               auto config = photon_config<SceneT, Air>(effort, b, 16);
                               config.irradiance_cache.rays = 512;
                               PhotonMapper mapper(scene, config, air);
                               mapper.cache_irradiance(cam, batch_config(16, b));
                               return render(cam, mapper, batch_config(16, b));
                           }), want, bias));
    rows.push_back(compare(cell, "progressive", against, estimate(effort.photon_batches, [&](int b) {
                               typename ProgressivePhotonMapper<SceneT, Air>::Config config;
                               config.pass = photon_config<SceneT, Air>(effort, b, 0);
                               config.pass.tracing.global_photons = config.pass.tracing.caustic_photons = effort.photons / 4;
                               config.pass.global.radius = 0.2f;
                               return render(cam, ProgressivePhotonMapper(scene, config, air), batch_config(effort.passes, b));
                           }), want, bias));
}

/// What VCM's merging may add against the reference: its radius's blur where it merges (a
/// small share of the light at merge_weight 0.05).
inline constexpr double merging_bias = 0.02;

/// Bidirectional path tracing and vertex connection and merging on `scene`: as many passes
/// as the path tracer's samples (a light path a pixel each), paths as long as its.
template <class SceneT, class Air>
void bidirectional_rows(std::vector<Row>& rows, const std::string& cell, const SceneT& scene, const Air& air, const Camera<T>& cam, const Effort& effort,
                        const Estimate& want, const char* against)
{
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        const bool vcm = method == BidirectionalMethod::vcm;
        rows.push_back(compare(cell, vcm ? "VCM" : "BDPT", against, estimate(effort.batches, [&](int b) {
                                   return render(cam, Bidirectional(scene, {.method = method, .max_length = 1024}, air), batch_config(effort.spp, b + 400));
                               }), want, vcm ? merging_bias : 0.0));
    }
}

/// A cell's name.
inline std::string cell_name(std::size_t material, LightKind light, Placement where, bool inside)
{
    return std::string(material_facts[material].name) + ", " + name_of(light) + ", " + name_of(where) + (inside ? ", camera inside" : "");
}

/// The agreement cell of material kind `material` under `light` (of the scene type's
/// sky S) with the fog at `where` (in the air where Filled): each estimator against the
/// reference where it has every path the reference has; Whitted against the path
/// tracer's direct light where its model is exact.
template <Sky S, bool Filled>
std::vector<Row> agreement_cell(std::size_t material, LightKind light, Placement where, bool inside, const Effort& effort)
{
    const auto scene = make_scene<S>(material, light, where);
    const auto air = air_of<Filled>(false);
    const Camera<T> cam = camera(where, inside);
    const std::string cell = cell_name(material, light, where, inside);
    const MaterialFacts& m = material_facts[material];
    std::vector<Row> rows;
    // A delta light's caustics (L S+ D ...) are the light tracer's alone, and what a
    // delta light sends through glass into fog, or shows through a mirror or glass
    // (E S+ D S+ L), no unbiased estimator has: there nothing is compared. Elsewhere the
    // path tracer has every path: the reference (its path tracer and light tracer, which
    // split the paths between them) is held to it, and so are the photon mappers.
    const bool specular_scene = m.specular || m.transmissive || has_glass(where);
    if (!(is_delta(light) && specular_scene)) {
        const Estimate paths = estimate(effort.batches, [&](int b) { return render(cam, PathTracer(scene, {}, air), batch_config(effort.spp, b + 100)); });
        rows.push_back(compare(cell, "reference", "path tracer", estimate(effort.batches, [&](int b) {
                                   return render(cam, Reference(scene, {}, air), batch_config(effort.spp, b));
                               }), paths, 0));
        photon_rows(rows, cell, scene, air, cam, effort, paths, "path tracer", photon_bias);
        bidirectional_rows(rows, cell, scene, air, cam, effort, paths, "path tracer");
    }
    // Whitted's shadow rays pass glass unbent and its glossy lobes see the scene by one
    // mirror ray: its direct light is the path tracer's (max_diffuse_bounces 0) where
    // neither happens.
    if (m.whitted_exact && !m.transmissive && !has_glass(where)) {
        const Estimate direct = estimate(effort.batches, [&](int b) {
            return render(cam, PathTracer(scene, {.max_diffuse_bounces = 0}, air), batch_config(effort.spp, b + 200));
        });
        rows.push_back(compare(cell, "Whitted", "path tracer, direct", estimate(effort.batches, [&](int b) {
                                   return render(cam, Whitted(scene, {}, air), batch_config(effort.spp / 4, b + 300));
                               }), direct, 0));
    }
    return rows;
}

/// The furnace cell: every estimator reads 1 in every channel (a lossless material kind).
template <bool Filled>
std::vector<Row> furnace_cell(std::size_t material, Placement where, bool inside, const Effort& effort)
{
    const auto scene = make_furnace(material, where);
    const auto air = air_of<Filled>(true);
    const Camera<T> cam = camera(where, inside);
    const std::string cell = "furnace: white " + cell_name(material, LightKind::sky, where, inside);
    const MaterialFacts& m = material_facts[material];
    const Estimate one{Rgb<double>(1), Rgb<double>(0)};
    std::vector<Row> rows;
    rows.push_back(compare(cell, "path tracer", "1", estimate(effort.batches, [&](int b) { return render(cam, PathTracer(scene, {}, air), batch_config(effort.spp, b)); }), one, 0));
    rows.push_back(compare(cell, "reference", "1", estimate(effort.batches, [&](int b) { return render(cam, Reference(scene, {}, air), batch_config(effort.spp, b)); }), one, 0));
    photon_rows(rows, cell, scene, air, cam, effort, one, "1", 0.03);
    bidirectional_rows(rows, cell, scene, air, cam, effort, one, "1");
    if (where == Placement::clear && !m.diffuse_part) {
        // Only mirrors and glass seen: Whitted follows every path to the sky.
        rows.push_back(compare(cell, "Whitted", "1", estimate(2, [&](int b) { return render(cam, Whitted(scene, {}, air), batch_config(1, b)); }), one, 1e-3));
    }
    return rows;
}

/// One cell of the matrix: a material kind (its index in Materials), a light, where the
/// fog sits, and whether the camera stands in it.
struct CellSpec {
    std::size_t material;
    LightKind light;
    Placement where;
    bool inside;
    friend bool operator==(const CellSpec&, const CellSpec&) = default;
};

/// Whether a camera can stand inside the placement's fog.
inline std::vector<bool> cameras(Placement p) { return inside_of(p) ? std::vector<bool>{false, true} : std::vector<bool>{false}; }

/// The agreement cells the full tier runs: every pair of the scene's factors in at least
/// one cell (every material under every light, every light in every placement with the
/// camera outside and inside, every material in every placement with the camera outside and
/// inside), the third factor turning with the two: 157 cells. (The whole product, 8
/// materials x 8 lights x 8 placements and cameras, is 512 cells: three times as long.)
inline std::vector<CellSpec> covering_cells()
{
    std::vector<CellSpec> cells;
    const auto add = [&](CellSpec c) {
        if (c.inside && !inside_of(c.where)) c.inside = false;
        for (const CellSpec& d : cells)
            if (d == c) return;
        cells.push_back(c);
    };
    const std::size_t n_l = light_kinds.size(), n_p = placements.size();
    for (std::size_t m = 0; m < material_count; ++m)
        for (std::size_t l = 0; l < n_l; ++l) add({m, light_kinds[l], placements[(m + l) % n_p], (m + l) % 2 == 1});
    for (std::size_t l = 0; l < n_l; ++l)
        for (std::size_t p = 0; p < n_p; ++p)
            for (const bool inside : cameras(placements[p])) add({(l + 3 * p + (inside ? 1 : 0)) % material_count, light_kinds[l], placements[p], inside});
    for (std::size_t m = 0; m < material_count; ++m)
        for (std::size_t p = 0; p < n_p; ++p)
            for (const bool inside : cameras(placements[p])) add({m, light_kinds[(m + 3 * p + (inside ? 5 : 0)) % n_l], placements[p], inside});
    return cells;
}

/// The whole product: every material kind under every light in every placement, the
/// camera outside and (where it can be) inside.
inline std::vector<CellSpec> all_cells()
{
    std::vector<CellSpec> cells;
    for (std::size_t m = 0; m < material_count; ++m)
        for (const LightKind l : light_kinds)
            for (const Placement p : placements)
                for (const bool inside : cameras(p)) cells.push_back({m, l, p, inside});
    return cells;
}

/// The cells the full tier's matrix runs: covering_cells(), or with the environment's
/// PRISM_MATRIX=all the whole product (all_cells(), about three times as long: run by
/// hand, not in CI).
inline std::vector<CellSpec> matrix_cells()
{
    const char* which = std::getenv("PRISM_MATRIX");
    return which != nullptr && std::string(which) == "all" ? all_cells() : covering_cells();
}

/// The furnace cells: every lossless material kind in every placement, the camera
/// outside and inside.
inline std::vector<CellSpec> furnace_cells()
{
    std::vector<CellSpec> cells;
    for (std::size_t m = 0; m < material_count; ++m)
        if (material_facts[m].lossless)
            for (const Placement p : placements)
                for (const bool inside : cameras(p)) cells.push_back({m, LightKind::sky, p, inside});
    return cells;
}

/// The cells of `cells` whose scene is of type (S, Filled).
template <Sky S, bool Filled>
std::vector<CellSpec> of_type(const std::vector<CellSpec>& cells)
{
    std::vector<CellSpec> out;
    for (const CellSpec& c : cells)
        if (sky_of(c.light) == S && fills_air(c.where) == Filled) out.push_back(c);
    return out;
}

/// Every row of the agreement cells `cells` of scene type (S, Filled), printed as it comes.
template <Sky S, bool Filled>
std::vector<Row> run_agreement(const std::vector<CellSpec>& cells, const Effort& effort)
{
    std::vector<Row> rows;
    for (const CellSpec& c : of_type<S, Filled>(cells))
        for (const Row& row : agreement_cell<S, Filled>(c.material, c.light, c.where, c.inside, effort)) {
            print(row);
            rows.push_back(row);
        }
    return rows;
}

/// Every row of the furnace cells `cells` in clear air or fog filling it (Filled).
template <bool Filled>
std::vector<Row> run_furnace(const std::vector<CellSpec>& cells, const Effort& effort)
{
    std::vector<Row> rows;
    for (const CellSpec& c : cells)
        if (fills_air(c.where) == Filled)
            for (const Row& row : furnace_cell<Filled>(c.material, c.where, c.inside, effort)) {
                print(row);
                rows.push_back(row);
            }
    return rows;
}

/// Each row's verdict, as a doctest check naming the cell and the estimator.
inline void check_rows(const std::vector<Row>& rows)
{
    for (const Row& row : rows) {
        CAPTURE(row.cell);
        CAPTURE(row.estimator);
        CHECK(row.ok);
    }
}

} // namespace test::matrix
