// SPDX-License-Identifier: MIT
// The command line shared by every example: size, samples, threads, seed, output folder,
// and the parts of a render split across machines (crop windows, ranges of passes),
// written as EXR with their exact sums for prism_merge to add up. What does not depend
// on a scene's types is compiled once, in cli.cpp (with the image and EXR writers), not
// in every example.
#pragma once

#include <prism/photon/estimator.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace examples {

struct Options {
    prism::RenderConfig render{};
    std::string out = ".";          ///< the folder the images go to (output_file)
    std::string povray{}; ///< POV-Ray's PNG of the same scene, to compare with
    // Photon mapping (the photon examples only)
    std::size_t photons = 200000;
    std::size_t caustic_photons = 200000;
    std::optional<prism::SamplerKind> photon_sampler{}; ///< the photons' points (--photon-sampler); unset: render.sampler's
    int gather = 64; ///< final-gather rays (gather and cache)
    double radius = 0.1;          ///< the caustic estimate's radius, or its search limit with --k
    std::size_t k = 100;          ///< > 0: the caustic estimate from the k nearest photons, 0: all within radius
    double global_radius = 0.25;  ///< the global map's estimate, where it is read directly
    prism::Filter filter = prism::Filter::cone;
    double max_height_ratio = 1.0; ///< < 1 flattens the estimate's sphere to a disk (against leaks)
    std::size_t visibility = 0;   ///< > 0: skip shadow rays where this many nearest photons agree
    bool povray_light = false;    ///< POV-Ray's model: its no-falloff light, direct light and caustics only
    /// How indirect light is found: direct (the global map read at the point), gather
    /// (final gathering), cache (final gathering behind an irradiance cache),
    /// progressive (progressive photon mapping), reference (path tracing + light tracing)
    std::string method = "cache";
    std::size_t passes = 64; ///< progressive photon mapping's passes
    std::size_t first_pass = 0; ///< its first (--passes a:b)
    // A part of a render split across machines
    std::string crop;          ///< --crop as given (resolved into render.crop once the size is known)
    bool part = false;         ///< --crop or --passes a:b: write EXR with the exact sums
    bool exr = false;          ///< --exr: also write EXR (with the means only, unless a part)
    bool preview = false;      ///< --preview: OUT/NAME.preview.png after each round of samples
    std::string program;       ///< the example's name
    bool photon_example = false; ///< the example takes the photon mapping flags
    /// The images the example writes (names without extension): parse() checks that each
    /// can be written before anything is rendered.
    std::vector<std::string> images;
};

/// Which families of flags an example takes beyond the shared ones: the others are refused,
/// not silently ignored.
struct Accepts {
    bool povray = false;  ///< --povray PNG
    bool photons = false; ///< the photon mapping flags
};

void print_help(const char* program, const char* description, const Options& defaults, Accepts accepts);

template <class Integer>
Integer parse_integer(std::string_view flag, const char* text, long long lo, long long hi)
{
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || value < lo || value > hi)
        throw std::invalid_argument(std::string(flag) + " expects an integer in [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "], got '" + text + "'");
    return static_cast<Integer>(value);
}

/// A number in (lo, hi] that is still > lo once rounded to float (the estimators keep
/// floats: --radius 1e-300 would become 0).
double parse_number(std::string_view flag, const char* text, double lo, double hi);

/// --crop X0,X1,Y0,Y1 for a width x height image: pixels [X0, X1) x [Y0, Y1), or, if
/// any value has a decimal point or an exponent, fractions of the image (pbrt's
/// --cropwindow: pixels from ceil(X0 width) to ceil(X1 width), and so for y).
prism::PixelWindow parse_crop(const std::string& text, int width, int height);

/// --passes A:B, a range of passes; nullopt when the text is a single count.
std::optional<prism::PassRange> parse_pass_range(const char* text);

/// Refuse an output folder that cannot be written, before anything is rendered.
void check_writable(const std::string& folder);

/// Refuse a --povray picture that cannot be read or has another size, before rendering.
void check_povray_picture(const std::string& png, int width, int height);

/// Parse the shared options and the families the example accepts; returns false when
/// --help was printed. Checks the output folder and a --povray picture before returning,
/// so that a bad one is reported before the render, not after it.
bool parse(int argc, char** argv, Options& options, const char* description, Accepts accepts = {});

/// The caustic map's estimate from the command line.
inline prism::Estimator caustic_estimator(const Options& options)
{
    return {.k = options.k, .radius = float(options.radius), .filter = options.filter, .max_height_ratio = float(options.max_height_ratio)};
}

/// The path of `file` in the output folder (--out).
inline std::string output_file(const Options& options, const std::string& file) { return options.out + "/" + file; }

} // namespace examples

namespace prism {
class OutputSet; // io/output.hpp: only cli.cpp and compare.cpp need it whole
}

namespace examples {

/// The files the example writes, written together (all or none) when its body has
/// finished: a run that fails leaves no partial set of outputs.
prism::OutputSet& outputs();

/// Write every file outputs() holds (run() calls it when the body returns 0).
void commit_outputs();
/// Have SIGINT, SIGTERM and SIGHUP remove the temporary files of a write under way
/// (prism::remove_partial_files_on_signal).
void remove_partial_files_on_signal();

/// Queue `film` as OUT/name.png.
void save_png(const prism::Film& film, const Options& options, const std::string& name);

/// Write `film` as OUT/name.preview.png now (whole or not at all), the picture so far of
/// a render under way; commit_outputs() removes it once the finished images are written.
void save_preview(const prism::Film& film, const Options& options, const std::string& name);

/// Run an example's body, turning exceptions into a message on `errors` (none if null)
/// and exit code 1; its outputs are written when it returns 0.
template <class Body>
int run(std::FILE* errors, Body&& body) noexcept
{
    remove_partial_files_on_signal();
    try {
        const int status = body();
        if (status == 0) commit_outputs();
        return status;
    } catch (const std::exception& e) {
        if (errors != nullptr) std::fprintf(errors, "error: %s\n", e.what());
        return 1;
    }
}

template <class Body>
int run(Body&& body) noexcept
{
    return run(stderr, body);
}

/// Every setting that changes a bit of the image, written out: parts of one render
/// must agree on it (prism_merge refuses them otherwise). Thread count, output and the
/// part's own window and passes change no bit and are left out.
std::string settings(const Options& options);

/// An image rendered: its name, the exact sums of its window and passes, the render time.
struct Rendered {
    std::string name;
    prism::Accumulation sums;
    double seconds = 0;

    [[nodiscard]] prism::Film image() const { return sums.image(); }
};

/// Write an image as name.png (and name.pfm, exact floats, with `pfm`); as name.exr too
/// with --exr, and always for a part of a render (--crop, --passes A:B), with the exact
/// sums and the metadata prism_merge needs to add it to the other parts.
void save(const Rendered& rendered, const Options& options, bool pfm = false);

/// The sums of a render of `config` (the options' or a method's own): with the layers the
/// integrator has where EXR is written (render_layers: the image's bits are the same),
/// and with --preview in rounds, each round's picture written by save_preview.
template <class Integrator>
prism::Accumulation render_with(const std::string& name, const prism::Camera<typename Integrator::scalar_type>& camera, const Integrator& integrator,
                                const prism::RenderConfig& config, const Options& options)
{
    const bool layers = options.exr || options.part;
    if (options.preview)
        return prism::render_progressive(camera, integrator, config, [&](const prism::Accumulation& sums) { save_preview(sums.image(), options, name); }, layers);
    return layers ? prism::render_layers(camera, integrator, config) : prism::render_sums(camera, integrator, config);
}

/// The samples (or passes) a render took in each pixel: all of its range, or with a time
/// budget (--seconds) the prefix it had time for.
inline std::uint64_t samples_taken(const prism::Accumulation& sums)
{
    return sums.weight(sums.window().x0, sums.window().y0);
}

/// Render with the options' settings and report the render time (camera rays to
/// finished sums) on stdout.
template <class Integrator>
Rendered timed_render(const std::string& name, const prism::Camera<typename Integrator::scalar_type>& camera, const Integrator& integrator,
                      const Options& options)
{
    const prism::RenderConfig& config = options.render;
    const auto start = std::chrono::steady_clock::now();
    prism::Accumulation sums = render_with(name, camera, integrator, config, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %dx%d, %llu spp, render time %.4f s\n", name.c_str(), config.width, config.height, static_cast<unsigned long long>(samples_taken(sums)),
                seconds);
    return {name, std::move(sums), seconds};
}

} // namespace examples
