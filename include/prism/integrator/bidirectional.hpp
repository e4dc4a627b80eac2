// SPDX-License-Identifier: MIT
// Bidirectional: bidirectional path tracing (BDPT) and vertex connection and merging
// (VCM), one estimator of passes.
//
// Each pass traces N light subpaths (a light chosen by power, its emission drawn with
// known densities: light/light.hpp's EmissionSample) and one camera subpath per pixel, and
// adds every way of completing a path from the two (Veach 1997, chapter 10):
//   s = 0        the camera path meets a light (an area or environment light);
//   s = 1        a camera vertex takes a light sample (next-event estimation);
//   s >= 2, t >= 2  a camera vertex is joined to a vertex of a light path;
//   t = 1        a light path's vertex is joined to the camera (light tracing: a splat);
// s and t are the vertices each subpath gives, so a path of k segments has s + t = k + 1.
// VCM adds merging (Georgiev et al. 2012; Hachisuka et al. 2012): a camera vertex
// gathers the light vertices within a radius of it (a HashGrid of the pass's light
// vertices), as progressive photon mapping does, the radius shrinking from pass to pass
// (r_i = r_0 i^((alpha - 1) / 2)). Every strategy of a path is weighted by the balance
// heuristic over all of them (merges counted merge_weight times, see the config), computed
// as the subpaths are traced from three running quantities per vertex (dVCM, dVC, dVM:
// Georgiev's technical report "Implementing vertex connection and merging", 2012;
// SmallVCM's layout). A connection goes only through vertices with a non-delta lobe
// (transport/path_vertex.hpp); a delta vertex is crossed by the subpaths themselves.
// So with a point light or the sun, the paths E S+ D S+ L (a caustic seen in a mirror
// or through glass), which no connection can join, are found by merging alone, and VCM
// is the one unbiased-in-the-limit estimator that renders them.
//
// The weights count the densities of the subpaths' draws without their Russian
// roulette: any weights that sum to 1 over a path's strategies keep every estimate
// unbiased, and these do, the same functions of the path for every strategy.
// By default light path i is pixel i's: drawn from its sampler (laid over the image in
// ZSobol's order) and joined to its camera paths; or, where a pilot finds the light paths
// worth less than they cost, square i's, of 4 x 4 or 16 x 16 pixels (light_path_plan).
// Connections may be made for a share of the camera paths (BidirectionalConfig::
// connections), the weights counting them that share of the time. Deterministic: every
// number is a function of (seed, pass, pixel or path), splats go to exact sums; the same
// bits for any thread count, crop, range of passes or MPI rank.
//
// Media: where a subpath crosses a medium that scatters (an object's interior, or the
// scene's air filled with fog: FilledAir) it draws where it scatters as the path tracer
// does (the medium's free flight), and a vertex there is a MediumVertex, joined and
// merged like a surface's: its lobe the phase function, its cosines 1. Merging in a
// medium gathers the light vertices within a ball in the same medium (the volume photon
// map's point estimate, 4/3 pi r^3; its radius the surfaces' or volume_radius), dividing
// out the scattering coefficient the light vertex's throughput took. The distances' densities (a flight's
// sigma_t T) are left out of the weights, as pbrt-v3's BDPT leaves them: the weights still
// sum to 1 over a path's strategies, so every estimate stays unbiased, but they no longer
// favour the strategy that samples a long, dense stretch best. A vertex in a medium counts
// for the weights as its kernel's eta, merge_weight 4/3 pi r^3 N times its mean
// scattering coefficient, which a vertex's density there has where a surface's has none.
//
// Dispersion: a white subpath meeting a dispersive interface takes a wavelength band
// there, as the path tracer's and the photons do, and keeps it. The two subpaths of a
// pair (light path i and the camera paths joined to it) take the same band, drawn per pair
// and pass (stepping through the bands from pass to pass): every connection joins two
// subpaths of one wavelength, and the band's share of white over its probability (1 /
// count) is taken once per path, where the subpaths meet. A merge with another pair's
// vertex where both subpaths took a band counts only if the bands agree, and then count
// times: unbiased, at a count-th of the merges (the weights do not see that, and still
// sum to 1).
//
// Scope: straight air, clear or filled with a medium that scatters, the media inside
// objects (nested dielectrics, index-matched boundaries and absorbing interiors
// included), and dispersion; graded air or a light without falloff is refused at compile
// time or by the constructor.
#pragma once

#include <prism/accel/hash_grid.hpp>
#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/light/light.hpp>
#include <prism/light/point_light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/scene.hpp>
#include <prism/transport/direct.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/path_vertex.hpp>
#include <prism/transport/walk_step.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace prism {

/// Which strategies a Bidirectional estimator combines.
enum class BidirectionalMethod {
    bdpt, ///< connections only: bidirectional path tracing
    vcm,  ///< connections and merging: vertex connection and merging
    /// Merges alone, unweighted, at each camera path's first vertex with a non-delta lobe
    /// (and the lights it meets through mirrors and glass before): progressive photon
    /// mapping by VCM's light paths and radii. VCM's merging part, for tests; consistent,
    /// not unbiased.
    merging,
};

/// One strategy (s, t): s vertices from the light, t from the camera (a path of s + t - 1 segments).
struct Strategy {
    int s = 0; ///< light vertices (0: the camera path met a light)
    int t = 0; ///< camera vertices (1: light tracing)
};

/// A Bidirectional estimator's settings.
struct BidirectionalConfig {
    BidirectionalMethod method = BidirectionalMethod::vcm; ///< connections only, or with merging
    /// Segments a path may have, from the camera to the light (1: lights seen directly;
    /// 2: direct light; ...). Every prism estimator counts its depth this way.
    int max_length = 64;
    /// Segments a subpath takes before Russian roulette on its throughput may end it.
    int roulette_length = 3;
    /// The first pass's merging radius in scene units; 0: `footprints` times the width of a
    /// pixel at the median distance of the surfaces the camera sees (the radius then
    /// follows the image's resolution, as stochastic progressive photon mapping's does).
    double radius = 0.0;
    /// The default radius in pixel widths (see `radius`).
    double footprints = 1.0;
    /// The first pass's merging radius in media (a ball about a camera vertex there), in
    /// scene units, shrinking as `radius` does; 0: `radius` (or its default). A ball of
    /// the surfaces' radius holds few light vertices in thin haze, where a merge then
    /// shows as a speck; a wider ball blurs the light in the medium instead.
    double volume_radius = 0.0;
    /// How much a merge counts against a connection in the weights: the merges of a pass
    /// are weighed as merge_weight pi r^2 N light paths' worth (1: Georgiev et al.'s
    /// balance heuristic). Any value keeps every estimate unbiased in the limit; below 1 a
    /// connection that can find a path keeps more of it (a point light's direct light,
    /// which merging estimates with the noise of counting photons), while a path only
    /// merging finds (E S ... D ... S L) is merging's whole whatever the value. The default
    /// was the best of 1, 0.1, 0.05, 0.01 on the point-lit Cornell box (RMSE 2.9 x BDPT's
    /// at 1, 1.02 x at 0.05: docs/benchmarks.md).
    double merge_weight = 0.05;
    /// In (0, 1): how much of the radius's area each pass keeps (Knaus and Zwicker 2011's alpha).
    double alpha = 0.75;
    /// Light subpaths per pass; 0: chosen for the scene and image by a pilot
    /// (Bidirectional::light_path_plan): one a pixel, or one a square of 4 x 4 or 16 x 16
    /// pixels where the light paths cost more than their light is worth (an area light in
    /// a diffuse room, whose light the path tracer's strategies find nearly all of). Light
    /// path i is then pixel (or square) i's, joined to its camera paths; another count's
    /// light paths are joined to camera paths at random.
    std::size_t light_paths = 0;
    /// The share of camera paths joined to their light path by connections (s >= 2,
    /// t >= 2), in (0, 1]: each camera path is, with this probability, and the weights
    /// count the connections as made that many times a camera path (a light sample, a
    /// bounce meeting a light, light tracing and merging as made always). Below 1 a pass
    /// traces fewer shadow rays: under the Cornell box's ceiling lamp, 1/16 of them took
    /// 0.75 of the time for the same error in linear radiance, but a larger one in the
    /// display range (the corners' dim light, which connections carry); so the default is
    /// every camera path, and the pilot does not choose it (docs/benchmarks.md).
    double connections = 1.0;
    /// Only this strategy's estimates (connections only; merges count none): for tests,
    /// and to see what each strategy brings. `weighted`: with its MIS weight (the
    /// strategies' images then add up to the whole), else alone (each an unbiased estimate
    /// of the paths it can find).
    std::optional<Strategy> only{};
    bool weighted = true; ///< see `only`
    /// A white subpath meeting a dispersive interface takes one of this many wavelength
    /// bands (1 to 81), as the path tracer's does: the band its pair drew (see
    /// Bidirectional), its share of white over its probability 1 / count.
    int dispersion_bands = SpectralBands<float>::max_count;
};

/// The multiple importance weights of Bidirectional: a subpath's three running
/// quantities (Georgiev's technical report, section 5; SmallVCM's dVCM, dVC, dVM), how a
/// subpath's vertices update them, and each strategy's balance-heuristic weight from them
/// and the densities where the two subpaths meet. Densities are those of the draws, per
/// steradian, and the cosines at the true normals; a light's are chosen with its
/// probability among the lights (the light paths'), where a light sample takes every
/// light. tests/integrator/bidirectional.cpp checks the weights of every strategy of
/// random paths against the balance heuristic over the paths' densities, written out.
template <Scalar T>
struct VcmMis {
    T dvcm = T(0); ///< the report's d^VCM: the reverse density of the vertex before, over this subpath's forward density of the vertex
    T dvc = T(0);  ///< d^VC: the same summed over the connections further back
    T dvm = T(0);  ///< d^VM: the same over the merges further back

    /// What merging at a vertex is worth: eta = merge_weight V N, V the merging kernel's
    /// size there (pi r^2 on a surface; 4/3 pi r^3 sigma in a medium, sigma its mean
    /// scattering coefficient there: see Bidirectional), 0 without merging; 1 / eta at a
    /// surface; and eta over a surface vertex's. (d^VM is counted in a surface's merges,
    /// d^VC / eta_surface, and a merge at a vertex of another kind takes it by the ratio;
    /// on surfaces alone the ratio is exactly 1, Georgiev's recursion as written.)
    /// With connections made for a share `connect` of the camera paths, every count is
    /// taken against theirs: eta / connect, and a light sample's, a bounce meeting a light's
    /// and light tracing's counts over connect (light_start, camera_start and the weights
    /// of those strategies).
    struct Pass {
        T vm = T(0);    ///< eta at the vertex (over connect): merging's weight against a connection there
        T vc = T(0);    ///< 1 / vm at a surface vertex
        T ratio = T(1); ///< vm vc: eta at the vertex over a surface vertex's (1 without merging)
        T connect = T(1); ///< the share of camera paths joined to their light path (BidirectionalConfig::connections)
    };

    /// A light subpath's start: the light chosen with probability q drew its point with
    /// density pdf_area (1 for a point or from infinity) and its direction with
    /// pdf_direction, at cosine `cos` to its surface (1 for a point or from infinity);
    /// `delta`: no bounce can find the light (a point, spot or parallel light). The
    /// light's own density toward the first hit is completed there (first_hit).
    [[nodiscard]] static VcmMis light_start(T q, T pdf_area, T pdf_direction, T cos, bool from_infinity, bool delta, Pass pass) noexcept
    {
        // (A light sample and a bounce meeting the light, counted against the connections.)
        const T pdf = q * pdf_area * pdf_direction * pass.connect;
        VcmMis m;
        // (31)-(33) begun, delta lights as (48)-(50): the light sample that would find the
        // light's vertex over the emission's density; a delta light's vertex no bounce finds.
        m.dvcm = T(1) / pdf;
        if (from_infinity && !delta) m.dvcm *= pdf_direction; // an environment's sample is by direction
        m.dvc = delta ? T(0) : (from_infinity ? T(1) : cos) / pdf;
        m.dvm = m.dvc * pass.vc;
        return m;
    }

    /// A camera subpath's start: N light paths a pass, the camera's density of its ray per
    /// steradian, and the share of camera paths joined to their light path (Pass::connect).
    [[nodiscard]] static VcmMis camera_start(T light_paths, T camera_pdf, T connect = T(1)) noexcept { return {light_paths / (camera_pdf * connect), T(0), T(0)}; }

    /// Arriving at a vertex `distance2` (squared) along the segment, at cosine `cos` to
    /// its true normal: the report's (31)-(33) completed now the segment is known.
    void arrive(T distance2, T cos) noexcept
    {
        dvcm *= distance2;
        dvcm /= cos;
        dvc /= cos;
        dvm /= cos;
    }

    /// A light subpath's first vertex, from an area light: a light sample from there
    /// finds the light's point with the density `direct` per steradian (the light's own
    /// pdf), at cosine cos_light there; the squared distance cancels the segment's.
    void first_hit_of_area_light(T direct, T cos_light, T cos) noexcept
    {
        dvcm *= direct * cos_light;
        arrive(T(1), cos);
    }

    /// Scattered at a vertex: the next direction drawn with density pdf_forward (per
    /// steradian; 1 for a delta), at cosine cos_out to the true normal (1 in a medium),
    /// where a path arriving the other way would draw the last direction with
    /// pdf_reverse: the report's (34)-(36), or (53)-(55) for a delta; `pass` the vertex's.
    void scattered(T cos_out, T pdf_forward, T pdf_reverse, bool delta, Pass pass) noexcept
    {
        if (delta) {
            dvcm = T(0);
            dvc *= cos_out;
            dvm *= cos_out;
        } else {
            const T g = cos_out / pdf_forward;
            dvc = g * (dvc * pdf_reverse + dvcm + pass.vm);
            dvm = g * (dvm * pdf_reverse + dvcm * pass.vc + pass.ratio);
            dvcm = T(1) / pdf_forward;
        }
    }

    /// s = 0: a camera subpath (these quantities) meets a light, which a light sample from
    /// the vertex before finds with density `direct` per unit area (per steradian from
    /// infinity) and the light paths leave by this way with density `emission` (the
    /// light's probability, area and direction: pdf_area pdf_direction), (42)-(43);
    /// `connect` Pass::connect.
    [[nodiscard]] T met_light_weight(T direct, T emission, T connect = T(1)) const noexcept { return T(1) / (T(1) + direct * dvcm + connect * emission * dvc); }

    /// s = 1: a camera vertex (these quantities) takes a light sample of density `direct`
    /// per steradian (d^2 for a point light, 1 for a parallel one: `delta`), at cosines
    /// cos_camera and cos_light to the true normals; the light paths leave by the
    /// sample's way with `emission` (as met_light_weight's); the vertex's lobe draws the
    /// sample's direction with bsdf_forward and, arriving from the light, the camera's
    /// way with bsdf_reverse. (44)-(45).
    [[nodiscard]] T light_sample_weight(T direct, bool delta, T emission, T cos_camera, T cos_light, T bsdf_forward, T bsdf_reverse, Pass pass) const noexcept
    {
        const T w_light = delta ? T(0) : bsdf_forward / direct;
        const T w_camera = pass.connect * emission * cos_camera / (direct * cos_light) * (pass.vm + dvcm + dvc * bsdf_reverse);
        return T(1) / (w_light + T(1) + w_camera);
    }

    /// s >= 2, t >= 2: a light vertex (`light`) joined to a camera vertex (`camera`) by a
    /// segment of squared length d2 at cosines cos_light and cos_camera; the camera
    /// vertex's lobe draws the segment with camera_forward (and its own arrival, from the
    /// light, with camera_reverse), the light vertex's with light_forward and
    /// light_reverse; each vertex's pass. (40)-(41).
    [[nodiscard]] static T connection_weight(const VcmMis& light, const VcmMis& camera, T d2, T cos_light, T cos_camera, T light_forward, T light_reverse,
                                             T camera_forward, T camera_reverse, Pass light_pass, Pass camera_pass) noexcept
    {
        const T w_light = camera_forward * cos_light / d2 * (light_pass.vm + light.dvcm + light.dvc * light_reverse);
        const T w_camera = light_forward * cos_camera / d2 * (camera_pass.vm + camera.dvcm + camera.dvc * camera_reverse);
        return T(1) / (w_light + T(1) + w_camera);
    }

    /// t = 1: a light vertex (these quantities) joined to the camera, which would draw it
    /// with `camera_area_pdf` per unit area (its image-plane density 1 / A taken to the
    /// ray's solid angle, 1 / cos_c^3, and on to the surface); N light paths a pass; the
    /// vertex's lobe draws its own arrival, coming from the camera, with bsdf_reverse.
    /// (46)-(47).
    [[nodiscard]] T splat_weight(T camera_area_pdf, T light_paths, T bsdf_reverse, Pass pass) const noexcept
    {
        return T(1) / (T(1) + pass.connect * camera_area_pdf / light_paths * (pass.vm + dvcm + dvc * bsdf_reverse));
    }

    /// A merge of a light vertex (`light`, arrived along d) at a camera vertex
    /// (`camera`): the camera vertex's lobe draws -d with camera_forward and its own
    /// arrival, coming the light path's way, with camera_reverse; `pass` the vertex's.
    /// (37)-(39).
    [[nodiscard]] static T merge_weight(const VcmMis& light, const VcmMis& camera, T camera_forward, T camera_reverse, Pass pass) noexcept
    {
        const T w_light = (light.dvcm * pass.vc + light.dvm * camera_forward) / pass.ratio;
        const T w_camera = (camera.dvcm * pass.vc + camera.dvm * camera_reverse) / pass.ratio;
        return T(1) / (w_light + T(1) + w_camera);
    }
};

/// Whether Bidirectional renders scenes of type SceneT in air of type Air: no light that
/// casts its own shadow, straight air.
template <class SceneT, class Air = StraightAir>
inline constexpr bool renders_bidirectionally = !SceneT::has_own_shadow_lights && !Air::curved;

/// Bidirectional path tracing and vertex connection and merging of `scene` in `Air` (an
/// integrator of passes: render/render.hpp's PassEstimator).
template <class SceneT, class Air = StraightAir>
class Bidirectional {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    static_assert(!Air::curved, "Bidirectional joins vertices by straight segments: graded air needs the PathTracer or a PhotonMapper");
    static_assert(!SceneT::has_own_shadow_lights, "Bidirectional: a light that casts its own shadow (PointGridLight, POV-Ray's area_light) has no emission to trace");

    /// The estimator of `scene` (which must outlive it); throws std::invalid_argument,
    /// naming the parameter, for a bad setting or a light without falloff (POV-Ray's
    /// fade_power 0, which no light path can carry).
    explicit Bidirectional(const SceneT& scene, BidirectionalConfig config = {}, Air air = {})
        : scene_(&scene), config_(config), air_(std::move(air)), bands_(checked_bands(config.dispersion_bands))
    {
        scene.validate();
        air_.validate();
        if (config.max_length < 1) detail::throw_invalid("BidirectionalConfig max_length must be >= 1, got ", config.max_length);
        if (config.roulette_length < 0) detail::throw_invalid("BidirectionalConfig roulette_length must be >= 0, got ", config.roulette_length);
        if (!(config.radius >= 0.0 && config.radius < std::numeric_limits<double>::infinity()))
            detail::throw_invalid("BidirectionalConfig radius must be finite and >= 0, got ", config.radius);
        if (!(config.alpha > 0.0 && config.alpha < 1.0)) detail::throw_invalid("BidirectionalConfig alpha must be in (0, 1), got ", config.alpha);
        if (!(config.footprints > 0.0 && config.footprints < 1e6)) detail::throw_invalid("BidirectionalConfig footprints must be in (0, 1e6), got ", config.footprints);
        if (!(config.volume_radius >= 0.0 && config.volume_radius < std::numeric_limits<double>::infinity()))
            detail::throw_invalid("BidirectionalConfig volume_radius must be finite and >= 0, got ", config.volume_radius);
        if (!(config.merge_weight > 0.0 && config.merge_weight <= 1.0)) detail::throw_invalid("BidirectionalConfig merge_weight must be in (0, 1], got ", config.merge_weight);
        if (!(config.connections > 0.0 && config.connections <= 1.0))
            detail::throw_invalid("BidirectionalConfig connections must be in (0, 1], got ", config.connections);
        if (config.only && (config.only->s < 0 || config.only->t < 1))
            detail::throw_invalid("BidirectionalConfig only must have s >= 0 and t >= 1, got (", config.only->s, ", ", config.only->t, ")");
        scene.for_each_light([&]<class L>(const L& light) {
            if constexpr (std::same_as<L, PointLight<T>>)
                if (light.falloff != Falloff::inverse_square) detail::throw_invalid("Bidirectional: a PointLight without falloff (POV-Ray's fade_power 0) has no physical emission");
        });
        Aabb<T> box = scene.bounds();
        // (Light from infinity is aimed at the fog too, where it is bounded.)
        if constexpr (air_scatters<Air>) {
            if (air_.bounds().bounded()) box = box.merged(air_.bounds());
        }
        if (!box.empty()) sphere_ = box.bounding_sphere();
        if (!(sphere_.radius > T(0))) sphere_.radius = T(1);
        // The lights by power, for the light paths.
        std::vector<double> weights;
        const PhotonAim<T> everywhere{nullptr, &sphere_};
        scene.for_each_light([&](const auto& light) {
            const Rgb<T> power = light.photon_power(everywhere);
            weights.push_back(double(power.x + power.y + power.z));
        });
        double total = 0.0;
        for (const double w : weights) total += w;
        if (!(total < std::numeric_limits<double>::infinity()))
            detail::throw_invalid("Bidirectional: the scene's lights' power is not finite (", total, ")");
        // (Lights that all emit nothing send no light paths: every probability 0.)
        double sum = 0.0;
        for (const double w : weights) {
            light_probability_.push_back(total > 0.0 ? T(w / total) : T(0));
            sum += total > 0.0 ? w / total : 0.0;
            light_cdf_.push_back(T(sum));
        }
    }
    Bidirectional(const SceneT&& scene, BidirectionalConfig config = {}, Air air = {}) = delete;

    /// The settings.
    [[nodiscard]] const BidirectionalConfig& config() const noexcept { return config_; }

    /// The first pass's merging radius: BidirectionalConfig::radius, or its default, a few
    /// pixel widths at the median distance of the surfaces the camera sees through a grid
    /// of 16 x 16 pixel centres (1/300 of the scene's radius where it sees none).
    [[nodiscard]] T first_radius(const CameraRays<T>& rays, int width, int height) const noexcept
    {
        if (config_.radius > 0.0) return T(config_.radius);
        std::vector<T> distances;
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i) {
                const Ray<T> ray = rays.ray((T(i) + T(0.5)) * T(width) / T(16), (T(j) + T(0.5)) * T(height) / T(16));
                if (const auto hit = scene_->closest_hit(ray, Interval<T>{T(0), infinity<T>})) distances.push_back(hit->crossing.t);
            }
        if (distances.empty()) return sphere_.radius * T(0.003);
        std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(distances.size() / 2), distances.end());
        return T(config_.footprints) * distances[distances.size() / 2] * prism::sqrt(rays.pixel_area());
    }

    /// Passes config.passes of config.spp: each one camera sample per pixel of the window
    /// (its weight) and the splats of its light paths there.
    void add_passes(Accumulation& sums, const Camera<T>& camera, const RenderConfig& config) const
    {
        const PassRange passes = detail::render_passes(config);
        const CameraRays<T> rays = camera.rays(config.width, config.height);
        const PixelWindow window = detail::render_window(config);
        if (sums.width() != config.width || sums.height() != config.height || !sums.window().contains(window))
            detail::throw_invalid("Bidirectional: the Accumulation does not hold the RenderConfig's window");
        const LightPathPlan plan = light_path_plan(camera, config);
        if (plan.light_paths >= std::numeric_limits<std::uint32_t>::max())
            detail::throw_invalid("Bidirectional: ", plan.light_paths, " light paths a pass overflow a 32-bit index");
        LightPaths light;
        LightPathScratch scratch;
        for (std::uint64_t pass = passes.first; pass < passes.last; ++pass) {
            trace_light_paths(sums, rays, window, config, pass, plan, light, scratch);
            const CameraPaths eye{this, &light, &rays};
            RenderConfig pass_render = config;
            // Pass p takes each pixel's sample p of one sequence (per-pixel Sobol under
            // zsobol, whose layout a part rendered on its own could not know: progressive.hpp).
            if (pass_render.sampler == SamplerKind::zsobol) pass_render.sampler = SamplerKind::sobol;
            pass_render.spp = int(std::min<std::uint64_t>(passes.last, std::uint64_t(std::numeric_limits<int>::max())));
            pass_render.passes = {pass, pass + 1};
            pass_render.seconds = 0;
            pass_render.progress = false;
            pass_render.single_sample_at_centre = false;
            render_into(sums, camera, eye, pass_render);
        }
    }

    /// A pass's light paths: how many, and the share of camera paths joined to theirs by
    /// connections (BidirectionalConfig::connections).
    struct LightPathPlan {
        std::size_t light_paths = 0; ///< light subpaths a pass
        double connections = 1.0;    ///< in (0, 1]
    };

    /// The light paths of a pass for an image of config's size: BidirectionalConfig's
    /// light_paths and connections, or where light_paths is 0 a pilot's choice of one light
    /// path a pixel or one a square of 4 x 4 or 16 x 16 pixels (pairing_side), whichever
    /// the pilot says is the most efficient. The pilot renders the whole frame (whatever
    /// the crop or range of passes) at no more than pilot_pixels pixels, pilot_passes passes
    /// with each choice, and scores each by its variance (a pixel's red, green and blue from
    /// pass to pass, summed over the pilot's pixels and the channels) times its work a pass
    /// (rays traced and merges looked up, counted: a deterministic function of the scene,
    /// camera, size and seed, as every bit of the image is). Fewer light paths must beat one
    /// a pixel by a factor of `pilot_margin`, as the pilot's few passes see a light path's
    /// rare, bright paths (a caustic) less often than the render does. That one, without a pilot, in a
    /// scene with a point, spot or directional light (the sun): the paths that end S+ L
    /// there are found by light paths alone (light tracing and merging), often rare and
    /// bright (a caustic) where a pilot's few passes cannot weigh them (under the sun,
    /// `sun_caustic`'s pilot chose fewer, and its picture's shadow and caustic came out
    /// grainier at its pass count); in a scene with dispersion, where a light path's
    /// wavelength band is its camera paths' (a square's pixels would share one colour's
    /// noise in a pass); and for merging alone and for a single strategy.
    [[nodiscard]] LightPathPlan light_path_plan(const Camera<T>& camera, const RenderConfig& config) const
    {
        const std::size_t pixels = std::size_t(config.width) * std::size_t(config.height);
        LightPathPlan plan{config_.light_paths > 0 ? config_.light_paths : pixels, config_.connections};
        if (config_.light_paths > 0) return plan;
        bool delta_lights = false;
        scene_->for_each_light([&]<class L>(const L&) { delta_lights = delta_lights || is_delta_light<L>; });
        if (delta_lights || SceneT::has_dispersion || config_.method == BidirectionalMethod::merging || config_.only || pixels < 16) return plan;
        const std::size_t shrink = std::size_t(std::ceil(std::sqrt(double(pixels) / double(pilot_pixels))));
        RenderConfig pilot = config;
        pilot.width = int((std::size_t(config.width) + shrink - 1) / shrink);
        pilot.height = int((std::size_t(config.height) + shrink - 1) / shrink);
        pilot.crop = {};
        pilot.seed = config.seed ^ 0x5851f42d4c957f2dULL;
        pilot.seconds = 0;
        pilot.progress = false;
        // Each pass one sample at each pixel's centre, of a seed of its own: the pixels'
        // variance is the light's, not their edges' (anti-aliasing's, the same whatever
        // the light paths, and far more of it in the pilot's large pixels).
        pilot.spp = 1;
        pilot.passes = {0, 1};
        pilot.single_sample_at_centre = true;
        if (pilot.sampler == SamplerKind::zsobol) pilot.sampler = SamplerKind::sobol;
        const CameraRays<T> rays = camera.rays(pilot.width, pilot.height);
        const PixelWindow whole = PixelWindow::whole(pilot.width, pilot.height);
        const std::size_t n = std::size_t(pilot.width) * std::size_t(pilot.height);
        double best_score = -1.0;
        for (const int side : pairing_sides) {
            std::vector<double> first(3 * n, 0.0), second(3 * n, 0.0);
            std::atomic<std::uint64_t> work{0};
            LightPaths light;
            LightPathScratch scratch;
            for (int pass = 0; pass < pilot_passes; ++pass) {
                RenderConfig one = pilot;
                one.seed = detail::sample_seed(pilot.seed, std::uint64_t(pass) + 1);
                Accumulation sums(pilot.width, pilot.height, whole);
                trace_light_paths(sums, rays, whole, one, 0, {squares(pilot, side), config_.connections}, light, scratch);
                // A light path's work: its first ray, and a ray on and a splat from each
                // vertex kept (and its place in the grid, merging), each light_work times
                // a camera path's ray.
                work += light_work * (std::uint64_t(light.count) + light.vertices.size() * (config_.method == BidirectionalMethod::vcm ? 3 : 2));
                light.work = &work;
                render_into(sums, camera, CameraPaths{this, &light, &rays}, one);
                for (int y = 0; y < pilot.height; ++y)
                    for (int x = 0; x < pilot.width; ++x) {
                        const double w = double(sums.weight(x, y));
                        for (std::size_t c = 0; c < 3; ++c) {
                            const double v = w > 0.0 ? sums.sum(x, y, c).value() / w : 0.0;
                            const std::size_t i = 3 * (std::size_t(y) * std::size_t(pilot.width) + std::size_t(x)) + c;
                            first[i] += v;
                            second[i] += v * v;
                        }
                    }
            }
            double variance = 0.0;
            for (std::size_t i = 0; i < 3 * n; ++i) variance += std::max(0.0, second[i] - first[i] * first[i] / pilot_passes) / (pilot_passes - 1);
            const double score = variance * double(work.load()) * (best_score < 0.0 ? 1.0 : pilot_margin);
            if (best_score < 0.0 || score < best_score) {
                best_score = score;
                plan.light_paths = squares(config, side);
            }
        }
        return plan;
    }

    /// The pilot's largest image, in pixels (light_path_plan).
    static constexpr std::size_t pilot_pixels = 1024;
    /// The pilot's passes with each choice of light paths.
    static constexpr int pilot_passes = 8;
    /// The factor by which fewer light paths must win the pilot.
    static constexpr double pilot_margin = 1.25;
    /// The sides of the squares of pixels a pilot chooses a light path for (pairing_side).
    static constexpr std::array<int, 3> pairing_sides{1, 4, 16};
    /// What a light path's ray costs in a camera path's: the light paths of one pass
    /// on the area-lit Cornell box (bench_methods area bdpt, 256 x 256) took 0.092 s of
    /// 0.17 s for a third of its rays (2.4 vertices a path, a ray and a splat each;
    /// the camera paths about 12 rays each): their per-pixel Sobol points and the splats'
    /// projections and exact sums.
    static constexpr std::uint64_t light_work = 3;

private:
    /// Whether a subpath may scatter in a medium (a scene or air without one compiles none of it).
    static constexpr bool has_media = SceneT::has_scattering_media || air_scatters<Air>;

    /// The medium a vertex is in: none (a surface's vertex), the scene's air, or an object's interior.
    struct MediumRef {
        enum class In : std::uint8_t { surface, air, object };
        In in = In::surface;
        std::uint32_t slot = 0;  ///< the object's scene slot
        std::uint32_t index = 0; ///< the object within its slot
        [[nodiscard]] bool operator==(const MediumRef&) const = default;
    };

    /// Where a subpath's vertex is: on a surface (its hit), or at a point in a medium.
    struct Place {
        const Hit<T>* hit = nullptr; ///< the surface; none in a medium
        Vec3<T> point{};             ///< where
        T outside_index = T(1);      ///< a transmissive material's outer index
        MediumRef medium{};          ///< in a medium: which
        Rgb<T> scattering{T(0)};     ///< in a medium: its scattering coefficient at the point

        [[nodiscard]] bool on_surface() const noexcept { return hit != nullptr; }
        /// |cos| of the unit direction w to the true normal (1 in a medium).
        [[nodiscard]] T cos(const Vec3<T>& w) const noexcept { return hit ? std::abs(dot(w, hit->crossing.normal)) : T(1); }
        /// A ray leaving toward the unit direction w (off the surface by its error bound).
        [[nodiscard]] Ray<T> toward(const Vec3<T>& w) const noexcept
        {
            if (!hit) return Ray<T>{point, w};
            const Crossing<T>& c = hit->crossing;
            return spawn_ray(c.point, c.error, c.normal, w);
        }
    };

    /// A light subpath's vertex with a non-delta lobe, kept for connections and merges.
    struct LightVertex {
        Hit<T> hit;          ///< where: the surface, or in a medium only the point (crossing.point)
        Vec3<T> d;           ///< unit, the direction the light path arrived along
        Rgb<T> beta;         ///< its throughput: the light's power estimate carried to here
        VcmMis<T> mis;       ///< the MIS quantities
        T outside_index;     ///< a transmissive material's outer index
        int length;          ///< segments from the light
        MediumRef medium;    ///< the medium it is in (In::surface: on the surface `hit`)
        Rgb<T> scattering;   ///< in a medium: its scattering coefficient there
        int band;            ///< the wavelength band a dispersive interface split it into (-1: white)

        /// Where it is.
        [[nodiscard]] Place place() const noexcept
        {
            return {medium.in == MediumRef::In::surface ? &hit : nullptr, hit.crossing.point, outside_index, medium, scattering};
        }
    };

    /// A light-tracing splat: its pixel and what it adds there.
    struct Splat {
        int x, y;
        std::array<ExactSum, 3> sum;
    };

    /// A worker's splats, added to the image's sums once the light paths are traced (in
    /// any order, as the sums are exact: the same bits), and the values it left out. (A
    /// pass of few light paths then pays for its splats, not for an image of sums a worker.)
    struct Splats {
        std::vector<Splat> list;
        std::size_t rejected = 0;
    };

    /// A pass's light subpaths: their vertices path by path, and VCM's grids of them.
    struct LightPaths {
        std::vector<LightVertex> vertices;
        std::vector<std::uint32_t> ends; ///< path i's vertices are [ends[i], ends[i + 1])
        std::vector<std::uint8_t> bands; ///< with dispersion: path i's (and its pair's) wavelength band
        HashGrid<T> grid;                ///< the vertices on surfaces by position, for merging
        HashGrid<T> volume_grid;         ///< the vertices in media by position
        std::vector<std::uint32_t> on_surfaces, in_media; ///< with media: the grids' points' vertices
        T count = T(0);          ///< N, the light paths traced
        T radius = T(0);         ///< the merging radius
        T volume_radius = T(0);  ///< the merging radius in media
        typename VcmMis<T>::Pass mis; ///< what merging on a surface is worth against a connection
        T volume_eta = T(0);     ///< merge_weight 4/3 pi r^3 N: eta in a medium over its mean scattering coefficient
        T vm_normalization = T(0); ///< 1 / (pi r^2 N)
        T volume_normalization = T(0); ///< 1 / (4/3 pi r^3 N)
        int side = 0;              ///< light path i is square i's, of side x side pixels (0: joined at random: pairing_side)
        std::size_t squares_wide = 0; ///< the squares across the image
        std::atomic<std::uint64_t>* work = nullptr; ///< in a pilot: the camera paths' rays and merges, counted (light_path_plan)
        T connect = T(1);          ///< the share of camera paths joined to it by connections

        /// Empty, as a new pass's, its vectors keeping their memory.
        void reset()
        {
            vertices.clear();
            ends.clear();
            bands.clear();
            on_surfaces.clear();
            in_media.clear();
            LightPaths fresh;
            fresh.vertices.swap(vertices);
            fresh.ends.swap(ends);
            fresh.bands.swap(bands);
            fresh.on_surfaces.swap(on_surfaces);
            fresh.in_media.swap(in_media);
            *this = std::move(fresh);
        }
        int width = 0, height = 0; ///< the image's size
    };

    /// What a pass's light paths are traced through, kept from pass to pass with their
    /// memory: each block's vertices and path lengths, each worker's splats, and the
    /// grid's points.
    struct LightPathScratch {
        std::vector<std::vector<LightVertex>> lists;
        std::vector<std::vector<std::uint32_t>> lengths;
        std::vector<Splats> buffers;
        std::vector<Vec3<T>> points;
    };

    /// A pass's camera side, a RayEstimator for render_into.
    struct CameraPaths {
        using scalar_type = T;
        const Bidirectional* owner;
        const LightPaths* light;
        const CameraRays<T>* rays;
        [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Random& rng) const noexcept { return owner->camera_path(ray, rng, *light, *rays); }
    };

    /// A subpath's running state: throughput and the MIS quantities, and its wavelength.
    /// (The throughput stays white where a dispersive interface splits the light: the
    /// band's share of white is taken once per path where the two subpaths meet, in_band().)
    struct PathState {
        Rgb<T> beta;
        VcmMis<T> mis;
        int length = 0;         ///< segments so far
        bool specular = true;   ///< every scattering so far was a delta
        int band = 0;           ///< the band its pair drew, which it takes at a dispersive interface
        bool dispersed = false; ///< it has met a dispersive interface: its light is the band's

        /// The band it is split into (-1: white).
        [[nodiscard]] int split() const noexcept { return dispersed ? band : -1; }
    };

    /// The sampler's blocks a light path's bounces start at (Random::bounce): past any
    /// camera path's, so the two never read the same dimensions; its emission reads the
    /// block before.
    static constexpr int light_blocks = 1024;
    /// The block a camera path draws whether it is joined to its light path from.
    static constexpr int joining_block = light_blocks - 2;

    /// The squares of side x side pixels across `pixels` of an image's width or height.
    [[nodiscard]] static std::size_t across(int pixels, int side) noexcept { return (std::size_t(pixels) + std::size_t(side) - 1) / std::size_t(side); }

    /// The squares of side x side pixels that cover an image of config's size.
    [[nodiscard]] static std::size_t squares(const RenderConfig& config, int side) noexcept { return across(config.width, side) * across(config.height, side); }

    /// The side of the squares of pixels whose camera paths a light path is joined to, with
    /// `count` light paths a pass: 1, 4 or 16 where count is the number of such squares
    /// (pairing_sides, the pilot's choices), light path i drawn from the sampler of
    /// square i's first pixel, so that the connections of a pixel's passes take stratified
    /// points; 0 for another count (each camera path joined to any light path, at random).
    [[nodiscard]] static int pairing_side(const RenderConfig& config, std::size_t count) noexcept
    {
        for (const int side : pairing_sides)
            if (count == squares(config, side)) return side;
        return 0;
    }

    /// The light path a camera ray is joined to with pairing_side > 0: that of the square
    /// of the pixel it was shot through (the image position it projects to).
    [[nodiscard]] static std::size_t square_of(const CameraRays<T>& rays, const Ray<T>& ray, const LightPaths& light) noexcept
    {
        const auto seen = rays.thin_lens() ? rays.project(ray.origin + ray.direction, ray.origin) : rays.project(ray.origin + ray.direction);
        if (!seen) return 0;
        const auto x = std::size_t(std::clamp(seen->x, T(0), T(light.width - 1))) / std::size_t(light.side);
        const auto y = std::size_t(std::clamp(seen->y, T(0), T(light.height - 1))) / std::size_t(light.side);
        return y * light.squares_wide + x;
    }

    /// Whether a contribution of strategy (s, t) counts, and with which of its weights.
    [[nodiscard]] bool counts(int s, int t) const noexcept { return !config_.only || (config_.only->s == s && config_.only->t == t); }
    [[nodiscard]] T weighed(T w) const noexcept { return config_.only && !config_.weighted ? T(1) : w; }
    /// A merge's weight: 1 where merging is the only strategy.
    [[nodiscard]] T merged(T w) const noexcept { return config_.method == BidirectionalMethod::merging ? T(1) : w; }

    [[nodiscard]] static T cube(T x) noexcept { return x * x * x; }

    [[nodiscard]] static SpectralBands<T> checked_bands(int count)
    {
        if (count < 1 || count > SpectralBands<float>::max_count)
            detail::throw_invalid("BidirectionalConfig dispersion_bands must be in [1, ", SpectralBands<float>::max_count, "], got ", count);
        return SpectralBands<T>(count);
    }

    /// The wavelength of the light in `band` (-1: white, 0).
    [[nodiscard]] T wavelength(int band) const noexcept { return band < 0 ? T(0) : bands_[band].wavelength_nm; }

    /// Pair i's band in pass `pass`: an offset of its own from `seed`'s stream i, uniform and
    /// independent of every other number of the pair and of every other pair's, stepped pass
    /// by pass by the golden ratio (mod 1), so that a pixel's passes spread over the bands
    /// evenly, and another pair's band is the same with probability exactly 1 / count
    /// (merged_band).
    [[nodiscard]] int pair_band(std::uint64_t seed, std::size_t i, std::uint64_t pass) const noexcept
    {
        const double u = double(Pcg32(seed, std::uint64_t(i)).next_u32()) * 0x1p-32 + 0.6180339887498949 * double(pass);
        return std::min(int((u - std::floor(u)) * double(bands_.size())), bands_.size() - 1);
    }

    /// A path's contribution `value` (from white light) of the light in `band` (-1: none,
    /// white): the band's share of white over its probability, 1 / count. (A scene
    /// without dispersion has no band, and nothing to multiply.)
    [[nodiscard]] Rgb<T> in_band(const Rgb<T>& value, int band) const noexcept
    {
        if constexpr (SceneT::has_dispersion) {
            if (band >= 0) return value * bands_[band].photon_weight * T(bands_.size());
        }
        (void)band;
        return value;
    }

    /// The image plane's density of the camera's ray along unit w, per steradian: 1 / (A cos^3).
    [[nodiscard]] static T camera_pdf(const CameraRays<T>& rays, const Vec3<T>& w) noexcept
    {
        const Vec3<T> forward = normalize(cross(rays.pixel_right, rays.pixel_down));
        const T cos = dot(w, forward);
        return cos > T(0) ? T(1) / (rays.pixel_area() * cube(cos)) : T(0);
    }

    /// Walk a subpath from `ray` (starting inside `media`) step by step (walk_step: false
    /// and index-matched interfaces crossed, the media's attenuation and free flights taken
    /// into the state's throughput), calling on_vertex(vertex, place, d, distance, kept)
    /// at every vertex: a SurfaceVertex where it meets a surface, a MediumVertex where it
    /// scatters in a medium; d the unit direction it arrived along, `distance` the length
    /// since the last vertex, `kept` the largest share of the throughput the flight there
    /// kept (1 at a surface). on_vertex returns the direction drawn there (nothing ends the
    /// walk); on_escape(ray) is called when the path leaves the scene. A dispersive
    /// interface splits the path into its band.
    template <class OnVertex, class OnEscape>
    void walk(Ray<T> ray, MediumStack media, PathState& state, Transport mode, Random& rng, int first_block, OnVertex&& on_vertex, OnEscape&& on_escape) const
    {
        T distance = T(0);
        const auto at_surface = [&]<class M>(const M& material, const SurfaceArrival<T>& at) -> std::optional<Vec3<T>> {
            const SurfaceVertex<M> vertex(material, at.hit.crossing, at.direction, mode, at.outside_index, wavelength(state.split()));
            return on_vertex(vertex, Place{&at.hit, at.hit.crossing.point, at.outside_index}, at.direction, distance + at.path, T(1));
        };
        const auto in_medium = [&]<class Md>(const Md& medium, const MediumArrival<T>& at) -> std::optional<Vec3<T>> {
            Place place;
            place.point = at.point;
            place.medium = at.media.top() ? MediumRef{MediumRef::In::object, at.media.top()->slot, at.media.top()->index} : MediumRef{MediumRef::In::air};
            place.scattering = medium.scattering_at(at.point);
            return on_vertex(MediumVertex(medium.phase, at.direction), place, at.direction, distance + at.path, max_component(at.weight));
        };
        const auto hooks = StepHooks{.on_surface = at_surface,
                                     .on_medium = in_medium,
                                     .on_escape = on_escape,
                                     .through_matched =
                                         [&](const Rgb<T>& tint) {
                                             state.beta *= tint;
                                             return true;
                                         },
                                     .at_interface =
                                         [&]<class M>(const M&) {
                                             // A white path takes its band here (its light split by wavelength).
                                             if constexpr (disperses<M>) state.dispersed = true;
                                             return wavelength(state.split());
                                         }};
        for (int bounce = 0;; ++bounce) {
            rng.bounce(first_block + bounce);
            const Step<T> step = walk_step(*scene_, air_, ray, media, state.beta, rng, hooks);
            if (step.end == StepEnd::escaped || step.end == StepEnd::ended) return;
            distance = step.end == StepEnd::passed ? distance + step.path : T(0);
        }
    }

    /// Scatter a subpath at a vertex: draw the next direction, update the throughput and
    /// the MIS quantities (the report's (34)-(36), or (53)-(55) for a delta), and play
    /// Russian roulette past roulette_length (outside the weights) by the share of the
    /// throughput the vertex kept (`kept`: the flight's to a vertex in a medium). Nothing:
    /// it ends.
    template <class V>
    [[nodiscard]] std::optional<Vec3<T>> scatter(const V& vertex, const Place& place, PathState& state, const LightPaths& light, Random& rng,
                                                 T kept) const noexcept
    {
        const std::optional<VertexSample<T>> s = vertex.sample(rng);
        if (!s || !(max_component(s->weight) > T(0)) || !(max_component(s->weight) < infinity<T>)) return std::nullopt;
        state.mis.scattered(place.cos(s->direction), s->pdf_forward, s->pdf_reverse, s->delta, pass_at(place, light));
        if (!s->delta) state.specular = false;
        state.beta *= s->weight;
        if (state.length >= config_.roulette_length) {
            // Roulette by how much of the throughput this scattering kept (at most 1).
            const T keep = std::min(T(1), max_component(s->weight) * kept);
            if (!(keep > T(0)) || !(rng.uniform<T>() < keep)) return std::nullopt;
            state.beta /= keep;
        }
        return s->direction;
    }

    /// What merging at a place is worth against a connection there: the pass's on a
    /// surface; in a medium eta by the ball's volume, times the mean scattering
    /// coefficient there (a vertex's density per volume has the medium's coefficient where
    /// one per area has none).
    [[nodiscard]] typename VcmMis<T>::Pass pass_at(const Place& place, const LightPaths& light) const noexcept
    {
        if (place.on_surface() || !(light.mis.vm > T(0))) return light.mis;
        const T vm = light.volume_eta * (place.scattering.x + place.scattering.y + place.scattering.z) / T(3);
        return {vm, light.mis.vc, vm * light.mis.vc, light.connect};
    }

    /// Call f(medium) with the medium `m` names (nothing for a surface's).
    template <class F>
    void visit_medium(const MediumRef& m, F&& f) const
    {
        if constexpr (air_scatters<Air>) {
            if (m.in == MediumRef::In::air) f(air_.medium);
        }
        if constexpr (SceneT::has_scattering_media) {
            if (m.in == MediumRef::In::object)
                scene_->visit_material(m.slot, m.index, [&]<class N>(const N& material) {
                    if constexpr (has_scattering_interior<N>) f(material.medium());
                });
        }
    }

    /// A stored light vertex's lobe toward the unit direction wo.
    [[nodiscard]] VertexValue<T> value_at(const LightVertex& lv, const Vec3<T>& wo) const noexcept
    {
        if constexpr (has_media) {
            if (lv.medium.in != MediumRef::In::surface) {
                VertexValue<T> v;
                visit_medium(lv.medium, [&](const auto& medium) { v = MediumVertex(medium.phase, lv.d).value(wo); });
                return v;
            }
        }
        return scene_->visit_material(lv.hit, [&]<class N>(const N& material) {
            return SurfaceVertex<N>(material, lv.hit.crossing, lv.d, Transport::importance, lv.outside_index, wavelength(lv.band)).value(wo);
        });
    }

    /// What reaches the end of `ray` (unit direction) over `distance` from its origin:
    /// the scene's transmittance (glass blocks) and its air's.
    [[nodiscard]] Rgb<T> visible(const Ray<T>& ray, T distance) const noexcept
    {
        const T d = distance * (T(1) - shadow_epsilon<T>);
        const Rgb<T> v = scene_->template transmittance<ShadowsThroughGlass::blocked>(ray, d);
        if constexpr (air_scatters<Air>) return v * air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, ray, d);
        else return v;
    }

    /// The pass's light subpaths, traced into `light` (its vectors and the scratch's keep
    /// their memory from the pass before): their vertices kept (and VCM's grid built), and
    /// their light-tracing splats (t = 1) added to `sums` in the window.
    void trace_light_paths(Accumulation& sums, const CameraRays<T>& rays, const PixelWindow& window, const RenderConfig& config, std::uint64_t pass,
                           const LightPathPlan& plan, LightPaths& light, LightPathScratch& scratch) const
    {
        const std::size_t count = plan.light_paths;
        light.reset();
        light.count = T(count);
        light.connect = T(plan.connections);
        light.side = pairing_side(config, count);
        light.squares_wide = light.side > 0 ? across(config.width, light.side) : 0;
        light.width = config.width;
        light.height = config.height;
        const bool merging = config_.method != BidirectionalMethod::bdpt;
        const double shrink = std::pow(double(pass + 1), 0.5 * (config_.alpha - 1.0)); // r_i = r_0 i^((alpha - 1) / 2)
        light.radius = std::max(T(double(first_radius(rays, config.width, config.height)) * shrink), sphere_.radius * T(1e-7));
        light.volume_radius = config_.volume_radius > 0.0 ? std::max(T(config_.volume_radius * shrink), sphere_.radius * T(1e-7)) : light.radius;
        // (Merging counted against the connections: eta over their share.)
        const T eta = pi<T> * light.radius * light.radius * light.count;
        light.mis.vm = merging ? T(config_.merge_weight) * eta / light.connect : T(0);
        light.mis.vc = light.connect / (T(config_.merge_weight) * eta);
        light.mis.connect = light.connect;
        light.vm_normalization = T(1) / eta;
        const T ball = T(4) / T(3) * pi<T> * light.volume_radius * light.volume_radius * light.volume_radius * light.count;
        light.volume_eta = merging ? T(config_.merge_weight) * ball / light.connect : T(0);
        light.volume_normalization = T(1) / ball;
        // Blocks of paths, each into its own list (joined in order) and its worker's splats.
        constexpr std::size_t block = 4096;
        const std::size_t blocks = (count + block - 1) / block;
        std::vector<std::vector<LightVertex>>& lists = scratch.lists;
        std::vector<std::vector<std::uint32_t>>& lengths = scratch.lengths;
        std::vector<Splats>& buffers = scratch.buffers;
        lists.resize(blocks);
        lengths.resize(blocks);
        buffers.resize(detail::workers_for(blocks, config.threads));
        for (std::size_t b = 0; b < blocks; ++b) {
            lists[b].clear();
            lengths[b].clear();
        }
        for (Splats& buffer : buffers) {
            buffer.list.clear();
            buffer.rejected = 0;
        }
        const std::uint64_t seed = detail::sample_seed(config.seed ^ 0x9e3779b97f4a7c15ULL, pass);
        // Under Sobol's points the light paths are laid over the image in ZSobol's order
        // whatever the camera's layout: a pass's light paths are then strided points of one
        // sequence, stratified as a set, which the splats and merges of every pixel share
        // (BDPT's RMSE on the point-lit box at 16 passes 0.021, against 0.040 with each
        // pixel's own sequence and 0.045 with independent numbers).
        RenderConfig layout = config;
        if (layout.sampler == SamplerKind::sobol) layout.sampler = SamplerKind::zsobol;
        // With dispersion, each pair's wavelength band (pair_band).
        [[maybe_unused]] const std::uint64_t band_seed = detail::sample_seed(config.seed ^ 0x2545f4914f6cdd1dULL, 0);
        if constexpr (SceneT::has_dispersion) light.bands.resize(count);
        detail::parallel_blocks(blocks, config.threads, [&](std::size_t b, unsigned worker) {
            for (std::size_t i = b * block; i < std::min(count, (b + 1) * block); ++i) {
                const std::size_t before = lists[b].size();
                // One light path a square of pixels: sample `pass` of its first pixel's place
                // in the layout, in blocks of dimensions its camera path never reads, and a
                // PCG stream of its own; else an independent stream.
                const auto side = std::size_t(light.side);
                Random rng = side > 0 ? Random(Sampler(layout.sampler,
                                                       detail::pixel_key(layout, std::uint32_t(i % light.squares_wide * side), std::uint32_t(i / light.squares_wide * side)),
                                                       std::uint32_t(pass)),
                                               Pcg32(seed, std::uint64_t(i)))
                                      : Random(seed, std::uint64_t(i));
                int band = 0;
                if constexpr (SceneT::has_dispersion) {
                    band = pair_band(band_seed, i, pass);
                    light.bands[i] = std::uint8_t(band);
                }
                light_path(rng, band, light, rays, window, lists[b], buffers[worker]);
                lengths[b].push_back(std::uint32_t(lists[b].size() - before));
            }
        });
        for (const Splats& buffer : buffers) {
            for (const Splat& splat : buffer.list) sums.add(splat.x, splat.y, splat.sum, 0);
            if (buffer.rejected > 0) sums.reject(buffer.rejected);
        }
        light.ends.reserve(count + 1);
        light.ends.push_back(0);
        std::size_t total = 0;
        for (std::size_t b = 0; b < blocks; ++b) total += lists[b].size();
        light.vertices.reserve(total);
        for (std::size_t b = 0; b < blocks; ++b) {
            light.vertices.insert(light.vertices.end(), lists[b].begin(), lists[b].end());
            for (const std::uint32_t n : lengths[b]) light.ends.push_back(light.ends.back() + n);
        }
        if (merging && !light.vertices.empty()) {
            if constexpr (has_media) {
                // Two grids: the vertices on surfaces, and those in media.
                std::vector<Vec3<T>>& points = scratch.points;
                std::vector<Vec3<T>> volume;
                points.clear();
                for (std::size_t i = 0; i < light.vertices.size(); ++i) {
                    const LightVertex& v = light.vertices[i];
                    const bool on_surface = v.medium.in == MediumRef::In::surface;
                    (on_surface ? points : volume).push_back(v.hit.crossing.point);
                    (on_surface ? light.on_surfaces : light.in_media).push_back(std::uint32_t(i));
                }
                if (!points.empty()) light.grid = HashGrid<T>(points, light.radius);
                if (!volume.empty()) light.volume_grid = HashGrid<T>(volume, light.volume_radius);
            } else {
                std::vector<Vec3<T>>& points = scratch.points;
                points.resize(light.vertices.size());
                for (std::size_t i = 0; i < points.size(); ++i) points[i] = light.vertices[i].hit.crossing.point;
                light.grid = HashGrid<T>(points, light.radius);
            }
        }
    }

    /// One light subpath: a light by power, its emission, then the walk; each vertex with
    /// a non-delta lobe kept in `out` and joined to the camera; `band` the wavelength band
    /// it takes at a dispersive interface (its pair's).
    void light_path(Random& rng, int band, const LightPaths& light, const CameraRays<T>& rays, const PixelWindow& window, std::vector<LightVertex>& out,
                    Splats& splats) const
    {
        rng.bounce(light_blocks - 1); // the emission's block
        const T u_light = rng.uniform<T>();
        std::size_t chosen = 0;
        while (chosen + 1 < light_cdf_.size() && !(u_light < light_cdf_[chosen])) ++chosen;
        const T q = light_probability_[chosen];
        const auto [a, b] = rng.uniform2<T>();
        const auto [u, v] = rng.uniform2<T>();
        const T u_pick = rng.uniform<T>();
        PathState state;
        state.band = band;
        EmissionSample<T> e;
        std::optional<Hit<T>> source; // an area light's point
        bool delta_light = true;
        scene_->visit_light(chosen, [&]<class L>(const L& l) {
            delta_light = is_delta_light<L>;
            if constexpr (requires { l.emission(u_pick, Vec2<T>(a, b), Vec2<T>(u, v)).at; }) {
                const auto emitted = l.emission(u_pick, Vec2<T>(a, b), Vec2<T>(u, v));
                e = emitted.emission;
                source = emitted.at;
            } else {
                e = l.emission(sphere_, Vec2<T>(a, b), Vec2<T>(u, v));
            }
        });
        const T pdf = q * e.pdf_area * e.pdf_direction;
        if (!(pdf > T(0)) || !(pdf < infinity<T>) || !(e.cos > T(0)) || !(max_component(e.radiance) > T(0))) return;
        state.beta = e.radiance * (e.cos / pdf);
        state.mis = VcmMis<T>::light_start(q, e.pdf_area, e.pdf_direction, e.cos, e.from_infinity, delta_light, light.mis);
        walk(e.ray, scene_->media_at(e.ray.origin), state, Transport::importance, rng, light_blocks,
             [&]<class V>(const V& vertex, const Place& place, const Vec3<T>& d, T distance, T kept) -> std::optional<Vec3<T>> {
                 const T cos = place.cos(d);
                 if (!(cos > T(0))) return std::nullopt;
                 ++state.length;
                 if (state.length == 1 && source) {
                     // An area light's sample from here finds its point with the density
                     // pdf_W cos_0 / d^2 per unit area.
                     if constexpr (SceneT::has_emitters) state.mis.first_hit_of_area_light(scene_->area_lights().pdf(*source, place.point), e.cos, cos);
                 } else {
                     state.mis.arrive(state.length > 1 || !e.from_infinity ? distance * distance : T(1), cos);
                 }
                 if (vertex.connectible()) {
                     Hit<T> at{};
                     if (place.hit) at = *place.hit;
                     else at.crossing.point = place.point;
                     out.push_back({at, d, state.beta, state.mis, place.outside_index, state.length, place.medium, place.scattering, state.split()});
                     if (state.length + 1 <= config_.max_length && config_.method != BidirectionalMethod::merging)
                         connect_to_camera(out.back(), vertex, light, rays, window, rng, splats);
                 }
                 if (state.length + 2 > config_.max_length) return std::nullopt;
                 return scatter(vertex, place, state, light, rng, kept);
             },
             [](const Ray<T>&) {});
    }

    /// Light tracing (t = 1): a light vertex joined to the camera (a point of a thin lens
    /// drawn uniformly), its splat added where the camera sees it in the window: the
    /// report's (46)-(47).
    template <class V>
    void connect_to_camera(const LightVertex& lv, const V& vertex, const LightPaths& light, const CameraRays<T>& rays, const PixelWindow& window,
                           Random& rng, Splats& splats) const
    {
        const Place place = lv.place();
        Vec3<T> eye = rays.origin;
        if (rays.thin_lens()) {
            const auto [u, v] = rng.template uniform2<T>();
            eye = rays.lens_point(u, v);
        }
        const auto seen = rays.thin_lens() ? rays.project(place.point, eye) : rays.project(place.point);
        if (!counts(lv.length + 1, 1) || !seen || !(seen->x >= T(window.x0) && seen->x < T(window.x1) && seen->y >= T(window.y0) && seen->y < T(window.y1))) return;
        const Vec3<T> to_camera = (eye - place.point) / seen->distance;
        const VertexValue<T> f = vertex.value(to_camera);
        if (f.black()) return;
        const T d2 = seen->distance * seen->distance;
        // The camera's density of this vertex per unit area: its image-plane density 1 / A
        // taken to the ray's solid angle (1 / cos_c^3) and on to the surface.
        const T camera_area_pdf = T(1) / (rays.pixel_area() * cube(seen->cos)) * place.cos(to_camera) / d2;
        const T weight = weighed(lv.mis.splat_weight(camera_area_pdf, light.count, f.pdf_reverse, pass_at(place, light)));
        const Rgb<T> v = visible(place.toward(to_camera), seen->distance);
        if (!(max_component(v) > T(0))) return;
        const Rgb<T> value = in_band((weight / (light.count * rays.pixel_area() * cube(seen->cos) * d2)) * lv.beta * f.f * f.cos * v, lv.band);
        std::array<ExactSum, 3> add{};
        for (int k = 0; k < 3; ++k) {
            const double x = double(float(value[k]));
            if (x >= 0.0 && ExactSum::takes(x)) add[std::size_t(k)] = ExactSum::of(x);
            else ++splats.rejected;
        }
        splats.list.push_back({int(seen->x), int(seen->y), add});
    }

    /// One camera subpath and everything joined to it: the estimate along `ray`.
    [[nodiscard]] Rgb<T> camera_path(const Ray<T>& ray, Random& rng, const LightPaths& light, const CameraRays<T>& rays) const noexcept
    {
        Rgb<T> sum{T(0)};
        // The light subpath this camera path is joined to: its pixel's, or with a number of
        // light paths of its own, any one, uniformly (each is a draw of the light subpaths'
        // distribution independent of the camera path).
        const std::size_t paired = light.side > 0 ? square_of(rays, ray, light) : std::min(std::size_t(rng.uniform<T>() * light.count), light.ends.size() - 2);
        PathState state;
        state.beta = Rgb<T>(T(1));
        const T camera = camera_pdf(rays, ray.direction);
        if (!(camera > T(0))) return sum;
        state.mis = VcmMis<T>::camera_start(light.count, camera, light.connect);
        // Joined to its light path by connections, with probability light.connect (their
        // estimates then over it; no number drawn when every camera path is), drawn from a
        // block of the sampler's no bounce of either subpath reads.
        bool joined = true;
        if (light.connect < T(1)) {
            rng.bounce(joining_block);
            joined = rng.uniform<T>() < light.connect;
        }
        if constexpr (SceneT::has_dispersion) state.band = light.bands[paired];
        Vec3<T> previous = ray.origin;
        std::uint64_t work = 0; // rays and merges, counted for a pilot (LightPaths::work)
        walk(ray, scene_->media_at(ray.origin), state, Transport::radiance, rng, 0,
             [&]<class V>(const V& vertex, const Place& place, const Vec3<T>& d, T distance, T kept) -> std::optional<Vec3<T>> {
                 const T cos = place.cos(d);
                 if (!(cos > T(0))) return std::nullopt;
                 ++state.length;
                 ++work;
                 state.mis.arrive(distance * distance, cos);
                 const int t = state.length + 1;
                 if constexpr (requires { typename V::material_type; }) {
                     if constexpr (emits<typename V::material_type>) {
                         // s = 0: the path met an area light, (42)-(43).
                         const Rgb<T> le = emitted(vertex.material(), place.hit->crossing);
                         if (max_component(le) > T(0) && counts(0, t)) {
                             T weight = T(1);
                             if (state.length > 1 && config_.method != BidirectionalMethod::merging) {
                                 const AreaLights<SceneT> lights = scene_->area_lights();
                                 const T direct = lights.pdf(*place.hit, previous) * cos / (distance * distance);
                                 const T emission = area_light_probability() * lights.emission_pdf(*place.hit, -d).both();
                                 weight = state.mis.met_light_weight(direct, emission, light.connect);
                             }
                             sum += in_band(weighed(weight) * state.beta * le, state.split());
                         }
                     }
                 }
                 if (config_.method == BidirectionalMethod::merging && vertex.connectible()) {
                     sum += state.beta * merges(vertex, place, state, light, paired);
                     return std::nullopt;
                 }
                 if (state.length >= config_.max_length || !vertex.connectible()) {
                     if (state.length >= config_.max_length) return std::nullopt;
                 } else {
                     sum += in_band(state.beta * light_samples(vertex, place, state, light, rng), state.split());
                     if (joined) sum += (state.beta / light.connect) * connections(vertex, place, state, light, paired);
                     if (config_.method == BidirectionalMethod::vcm && !config_.only) sum += state.beta * merges(vertex, place, state, light, paired);
                     work += 1 + (joined ? light.ends[paired + 1] - light.ends[paired] : 0) + (config_.method == BidirectionalMethod::vcm ? 1 : 0);
                 }
                 previous = place.point;
                 return scatter(vertex, place, state, light, rng, kept);
             },
             [&](const Ray<T>& out) {
                 // Leaving the scene: the background where every scattering was a delta
                 // (seen, as in every prism estimator, but lighting nothing), and each
                 // environment light, s = 0.
                 if (state.specular && counts(0, state.length + 1)) sum += in_band(state.beta * scene_->background, state.split());
                 std::size_t index = 0;
                 scene_->for_each_light([&]<class L>(const L& l) {
                     const std::size_t i = index++;
                     if constexpr (is_at_infinity<L>) {
                         if (!counts(0, state.length + 1) || state.length + 1 > config_.max_length) return;
                         const Vec3<T> w = out.direction;
                         const Rgb<T> le = l.arriving_from(w);
                         T weight = T(1);
                         if (state.length > 0 && config_.method != BidirectionalMethod::merging) {
                             const T direct = l.pdf(w);
                             const T emission = reached_from_entry(sphere_, w, out.origin) ? light_probability_[i] * l.emission_pdf(-w, sphere_).both() : T(0);
                             weight = state.mis.met_light_weight(direct, emission, light.connect);
                         }
                         sum += in_band(weighed(weight) * state.beta * le, state.split());
                     }
                 });
             });
        if (light.work) light.work->fetch_add(work + 1, std::memory_order_relaxed);
        return sum;
    }

    /// The area lights' share of the light paths.
    [[nodiscard]] T area_light_probability() const noexcept { return light_probability_.back(); }

    /// Whether a vertex's lobe reaches the side of its surface the unit direction wi
    /// leaves by (both sides for a glossy interface; every way in a medium).
    template <class V>
    [[nodiscard]] static bool reaches(const Place& place, const Vec3<T>& wi) noexcept
    {
        if constexpr (requires { typename V::material_type; }) {
            using M = typename V::material_type;
            const Crossing<T>& c = place.hit->crossing;
            const Vec3<T> n = c.facing_normal(), ns = c.facing_shading();
            if (shading_cosine(ns, n, wi) > T(0)) return true;
            if constexpr (has_glossy<M> && transmits<M>) return shading_cosine(-ns, -n, wi) > T(0);
            return false;
        } else {
            (void)place, (void)wi;
            return true;
        }
    }

    /// s = 1: a light sample from each light at a camera vertex, (44)-(45).
    template <class V>
    [[nodiscard]] Rgb<T> light_samples(const V& vertex, const Place& place, const PathState& state, const LightPaths& light, Random& rng) const noexcept
    {
        Rgb<T> sum{T(0)};
        if (state.length + 1 > config_.max_length) return sum;
        std::size_t index = 0;
        scene_->for_each_light([&]<class L>(const L& l) {
            const T q = light_probability_[index++];
            const auto [u1, u2] = rng.uniform2<T>();
            // The light's sample, and for MIS the point it drew: its emission's density
            // toward here and the cosine there.
            LightSample<T> s;
            T emission = T(0), cos_light = T(1);
            if constexpr (requires { l.sample_point(place.point, Vec2<T>(u1, u2)).at; }) {
                const auto drawn = l.sample_point(place.point, Vec2<T>(u1, u2));
                s = drawn.sample;
                emission = q * l.emission_pdf(drawn.at, -s.wi).both();
                cos_light = std::abs(dot(s.wi, drawn.at.crossing.normal));
            } else {
                s = l.sample(place.point, Vec2<T>(u1, u2));
                if (s.distance < infinity<T> || reached_from_entry(sphere_, s.wi, place.point)) emission = q * l.emission_pdf(-s.wi, sphere_).both();
            }
            if (!reaches<V>(place, s.wi) || !(max_component(s.irradiance) > T(0)) || !(cos_light > T(0))) return;
            const VertexValue<T> f = vertex.value(s.wi);
            if (f.black()) return;
            // The light sample's density per steradian here (a delta light's: d^2 for a
            // point, 1 for a parallel light).
            const bool at_infinity = !(s.distance < infinity<T>);
            const T direct = s.delta() ? (at_infinity ? T(1) : s.distance * s.distance) : s.pdf;
            const T weight = weighed(state.mis.light_sample_weight(direct, s.delta(), emission, place.cos(s.wi), cos_light, f.pdf_forward, f.pdf_reverse,
                                                                   pass_at(place, light)));
            const Rgb<T> v = visible(place.toward(s.wi), s.distance);
            sum += (weight * f.cos) * f.f * s.irradiance * v;
        });
        // (Drawn whatever strategies count, so that every strategy's image takes the same samples.)
        return counts(1, state.length + 1) ? sum : Rgb<T>(T(0));
    }

    /// s >= 2, t >= 2: the camera vertex joined to each vertex of its light path, (40)-(41).
    template <class V>
    [[nodiscard]] Rgb<T> connections(const V& vertex, const Place& place, const PathState& state, const LightPaths& light, std::size_t paired) const noexcept
    {
        Rgb<T> sum{T(0)};
        for (std::uint32_t i = light.ends[paired]; i < light.ends[paired + 1]; ++i) {
            const LightVertex& lv = light.vertices[i];
            if (lv.length + state.length + 1 > config_.max_length) break; // (kept in order of length)
            if (!counts(lv.length + 1, state.length + 1)) continue;
            const Place far_place = lv.place();
            Vec3<T> w = far_place.point - place.point;
            const T d2 = length_squared(w);
            if (!(d2 > T(0))) continue;
            const T distance = prism::sqrt(d2);
            w /= distance;
            const VertexValue<T> camera = vertex.value(w);
            if (camera.black()) continue;
            const VertexValue<T> far = value_at(lv, -w);
            if (far.black()) continue;
            const T cos_camera = place.cos(w), cos_light = far_place.cos(w);
            const T weight = weighed(VcmMis<T>::connection_weight(lv.mis, state.mis, d2, cos_light, cos_camera, far.pdf_forward, far.pdf_reverse, camera.pdf_forward,
                                                                  camera.pdf_reverse, pass_at(far_place, light), pass_at(place, light)));
            const Rgb<T> v = visible(place.toward(w), distance);
            if (!(max_component(v) > T(0))) continue;
            // (Pair i's subpaths take the same band: split either or both, the light is its.)
            sum += in_band((weight * camera.cos * far.cos / d2) * camera.f * far.f * lv.beta * v, std::max(lv.band, state.split()));
        }
        return sum;
    }

    /// VCM's merges: the light vertices within the pass's radius of the camera vertex,
    /// each its light as a photon's density estimate, (37)-(39); in a medium those in the
    /// same medium within a ball, as a volume photon's (their throughput took the
    /// scattering coefficient where they scattered, which the estimate of the light
    /// arriving here divides out: the path takes it once, at the camera's vertex).
    template <class V>
    [[nodiscard]] Rgb<T> merges(const V& vertex, const Place& place, const PathState& state, const LightPaths& light, std::size_t paired) const noexcept
    {
        Rgb<T> sum{T(0)};
        if (place.on_surface()) {
            light.grid.within(place.point, [&](std::uint32_t i, T) {
                const std::uint32_t k = has_media ? light.on_surfaces[i] : i;
                const LightVertex& lv = light.vertices[k];
                if (lv.length + state.length > config_.max_length) return;
                const VertexValue<T> camera = vertex.value(-lv.d);
                if (camera.black()) return;
                sum += merged_band(k, state, light, paired,
                                   merged(VcmMis<T>::merge_weight(lv.mis, state.mis, camera.pdf_forward, camera.pdf_reverse, light.mis)) * camera.f * lv.beta);
            });
            return sum * light.vm_normalization;
        }
        if constexpr (has_media) {
            const typename VcmMis<T>::Pass pass = pass_at(place, light);
            if (!(pass.ratio > T(0))) return sum;
            light.volume_grid.within(place.point, [&](std::uint32_t i, T) {
                const std::uint32_t k = light.in_media[i];
                const LightVertex& lv = light.vertices[k];
                if (lv.medium != place.medium || lv.length + state.length > config_.max_length) return;
                const VertexValue<T> camera = vertex.value(-lv.d);
                if (camera.black()) return;
                sum += merged_band(k, state, light, paired, merged(VcmMis<T>::merge_weight(lv.mis, state.mis, camera.pdf_forward, camera.pdf_reverse, pass)) * camera.f * lv.beta);
            });
            for (int k = 0; k < 3; ++k) sum[k] = place.scattering[k] > T(0) ? sum[k] / place.scattering[k] : T(0);
            return sum * light.volume_normalization;
        }
        return sum;
    }

    /// A merge's contribution `value` of light vertex k at a camera path of pair `paired`,
    /// in the band either subpath took. Where both took one, another pair's vertex counts
    /// only in the camera path's band, and then count times (its band, drawn independently,
    /// is that one with probability 1 / count); the pair's own vertices always share it. (The
    /// weights do not see that such merges have count times fewer vertices: they still sum
    /// to 1 over the path's strategies.)
    [[nodiscard]] Rgb<T> merged_band(std::uint32_t k, const PathState& state, const LightPaths& light, std::size_t paired, const Rgb<T>& value) const noexcept
    {
        if constexpr (SceneT::has_dispersion) {
            const int band = light.vertices[k].band, own = state.split();
            if (band < 0 || own < 0) return in_band(value, std::max(band, own));
            if (band != own) return Rgb<T>(T(0));
            const bool pair = k >= light.ends[paired] && k < light.ends[paired + 1];
            return in_band(pair ? value : value * T(bands_.size()), band);
        } else {
            (void)k, (void)state, (void)light, (void)paired;
            return value;
        }
    }

    const SceneT* scene_;
    BidirectionalConfig config_;
    Air air_;
    BoundingSphere<T> sphere_{};
    std::vector<T> light_probability_; ///< per light (the area lights last), its share of the light paths
    std::vector<T> light_cdf_;
    SpectralBands<T> bands_; ///< the wavelength bands a dispersive interface splits white light into
};

} // namespace prism
