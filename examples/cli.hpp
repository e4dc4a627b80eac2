// SPDX-License-Identifier: MIT
// The command line shared by every example: size, samples, threads, seed, output folder.
#pragma once

#include <prism/io/image.hpp>
#include <prism/prism.hpp>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace examples {

struct Options {
    prism::RenderConfig render{};
    std::filesystem::path out = ".";
    std::filesystem::path povray{}; ///< POV-Ray's PNG of the same scene, to compare with
    // Photon mapping (the photon examples only)
    std::size_t photons = 200000;
    std::size_t caustic_photons = 200000;
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
};

inline void print_photon_help(const Options& defaults);

/// Which families of flags an example takes beyond the shared ones: the others are refused,
/// not silently ignored.
struct Accepts {
    bool povray = false;  ///< --povray PNG
    bool photons = false; ///< the photon mapping flags
};

inline void print_help(const char* program, const char* description, const Options& defaults, Accepts accepts)
{
    std::printf("%s: %s\n\n"
                "usage: %s [options]\n"
                "  --width N     image width in pixels (default %d)\n"
                "  --height N    image height in pixels (default %d)\n"
                "  --spp N       samples per pixel; 1 samples pixel centres (default %d)\n"
                "  --threads N   worker threads, 0 = all cores (default 0)\n"
                "  --seed N      random seed (default 0)\n"
                "  --out DIR     folder for the images, created if missing (default .)\n"
                "  --help        this text\n",
                program, description, program, defaults.render.width, defaults.render.height, defaults.render.spp);
    if (accepts.povray)
        std::printf("  --povray PNG  POV-Ray's picture of the same scene (same size): also write prism | POV-Ray | difference\n");
    if (accepts.photons) print_photon_help(defaults);
}

inline void print_photon_help(const Options& defaults)
{
    std::printf("  photon mapping:\n"
                "  --photons N          photons emitted for the global map (default %zu)\n"
                "  --caustic-photons N  photons aimed at specular objects (default %zu)\n"
                "  --gather N           final-gather rays per diffuse hit, for --method gather and cache (default %d)\n"
                "  --radius R           radius of the caustic estimate, or its search limit with --k (default 0.1)\n"
                "  --k N                caustic estimate from the N nearest photons, 0 = every photon within R (default 100)\n"
                "  --global-radius R    radius of the global map's estimate where read directly (default 0.25)\n"
                "  --filter F           box, cone or gaussian, for both estimates (default cone)\n"
                "  --max-height-ratio H keep photons within H R of the tangent plane, < 1 against light leaks (default 1)\n"
                "  --visibility N       skip shadow rays where the N nearest global photons agree (default 0 = never)\n"
                "  --light L            physical (inverse-square) or povray (POV-Ray's model: no falloff, as the .pov file,\n"
                "                       direct light and caustics only) (default physical)\n"
                "  --method M           indirect light by: direct (the global map read at the point), gather (final gathering),\n"
                "                       cache (final gathering behind an irradiance cache), progressive (progressive photon\n"
                "                       mapping: --photons and --caustic-photons per pass, --radius and --global-radius the first\n"
                "                       pass's radii), reference (unbiased: path tracing plus light tracing, --spp samples per\n"
                "                       pixel and as many light paths) (default %s)\n"
                "  --passes N           progressive photon mapping's passes (default %zu)\n",
                defaults.photons, defaults.caustic_photons, defaults.gather, defaults.method.c_str(), defaults.passes);
}

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
inline double parse_number(std::string_view flag, const char* text, double lo, double hi)
{
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(value > lo && value <= hi))
        throw std::invalid_argument(std::string(flag) + " expects a number in (" + std::to_string(lo) + ", " + std::to_string(hi) +
                                    "], got '" + text + "'");
    if (!(double(float(value)) > lo))
        throw std::invalid_argument(std::string(flag) + " expects a number in (" + std::to_string(lo) + ", " + std::to_string(hi) +
                                    "] that float can hold, got '" + text + "' (it rounds to " + std::to_string(float(value)) + ")");
    return value;
}

/// Refuse an output folder that cannot be written, before anything is rendered.
inline void check_writable(const std::filesystem::path& folder)
{
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw std::invalid_argument("--out " + folder.string() + " is not writable: " + error.message());
    const std::filesystem::path probe = folder / (".prism-write-check-" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::FILE* file = std::fopen(probe.c_str(), "wbx");
    if (file == nullptr) throw std::invalid_argument("--out " + folder.string() + " is not writable: " + std::strerror(errno));
    std::fclose(file);
    std::filesystem::remove(probe);
}

/// Refuse a --povray picture that cannot be read or has another size, before rendering.
inline void check_povray_picture(const std::filesystem::path& png, int width, int height)
{
    const prism::Film picture = prism::read_png(png);
    if (picture.width() != width || picture.height() != height)
        throw std::invalid_argument("--povray: " + png.string() + " is " + std::to_string(picture.width()) + "x" +
                                    std::to_string(picture.height()) + ", the render is " + std::to_string(width) + "x" + std::to_string(height));
}

/// Parse the shared options and the families the example accepts; returns false when
/// --help was printed. Checks the output folder and a --povray picture before returning,
/// so that a bad one is reported before the render, not after it.
inline bool parse(int argc, char** argv, Options& options, const char* description, Accepts accepts = {})
{
    const Options defaults = options;
    constexpr std::string_view photon_flags[] = {"--photons", "--caustic-photons", "--gather", "--radius", "--global-radius",
                                                 "--max-height-ratio", "--k",               "--visibility", "--filter", "--light",
                                                 "--method",           "--passes"};
    for (int i = 1; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            print_help(argv[0], description, defaults, accepts);
            return false;
        }
        const bool photon_flag = std::find(std::begin(photon_flags), std::end(photon_flags), flag) != std::end(photon_flags);
        if ((photon_flag && !accepts.photons) || (flag == "--povray" && !accepts.povray))
            throw std::invalid_argument("'" + std::string(flag) + "' does not apply to this example (see --help)");
        if (i + 1 >= argc) throw std::invalid_argument("unknown option or missing value: '" + std::string(flag) + "'");
        const char* value = argv[++i];
        if (flag == "--width") options.render.width = parse_integer<int>(flag, value, 1, 1 << 16);
        else if (flag == "--height") options.render.height = parse_integer<int>(flag, value, 1, 1 << 16);
        else if (flag == "--spp") options.render.spp = parse_integer<int>(flag, value, 1, 1 << 20);
        else if (flag == "--threads") options.render.threads = parse_integer<unsigned>(flag, value, 0, 1024);
        else if (flag == "--seed") options.render.seed = parse_integer<std::uint64_t>(flag, value, 0, (1LL << 62));
        else if (flag == "--out") options.out = value;
        else if (flag == "--povray") options.povray = value;
        else if (flag == "--photons") options.photons = parse_integer<std::size_t>(flag, value, 0, 100000000);
        else if (flag == "--caustic-photons") options.caustic_photons = parse_integer<std::size_t>(flag, value, 0, 100000000);
        else if (flag == "--gather") options.gather = parse_integer<int>(flag, value, 1, 4096);
        else if (flag == "--radius") options.radius = parse_number(flag, value, 0, 100);
        else if (flag == "--global-radius") options.global_radius = parse_number(flag, value, 0, 100);
        else if (flag == "--max-height-ratio") options.max_height_ratio = parse_number(flag, value, 0, 1);
        else if (flag == "--k") options.k = parse_integer<std::size_t>(flag, value, 0, prism::PhotonMap::max_k);
        else if (flag == "--visibility") options.visibility = parse_integer<std::size_t>(flag, value, 0, prism::PhotonMap::max_k);
        else if (flag == "--filter") {
            const std::string_view f = value;
            if (f == "box") options.filter = prism::Filter::box;
            else if (f == "cone") options.filter = prism::Filter::cone;
            else if (f == "gaussian") options.filter = prism::Filter::gaussian;
            else throw std::invalid_argument("--filter expects box, cone or gaussian, got '" + std::string(f) + "'");
        }
        else if (flag == "--method") {
            const std::string_view m = value;
            if (m != "direct" && m != "gather" && m != "cache" && m != "progressive" && m != "reference")
                throw std::invalid_argument("--method expects direct, gather, cache, progressive or reference, got '" + std::string(m) + "'");
            options.method = m;
        }
        else if (flag == "--passes") options.passes = parse_integer<std::size_t>(flag, value, 1, 1000000);
        else if (flag == "--light") {
            const std::string_view l = value;
            if (l != "physical" && l != "povray") throw std::invalid_argument("--light expects physical or povray, got '" + std::string(l) + "'");
            options.povray_light = l == "povray";
        }
        else throw std::invalid_argument("unknown option '" + std::string(flag) + "' (see --help)");
    }
    check_writable(options.out);
    if (!options.povray.empty()) check_povray_picture(options.povray, options.render.width, options.render.height);
    return true;
}

/// The photon tracer's settings from the command line.
inline prism::PhotonTracerConfig photon_tracer_config(const Options& options)
{
    return {.global_photons = options.photons, .caustic_photons = options.caustic_photons, .seed = options.render.seed,
            .threads = options.render.threads};
}

/// The caustic map's estimate from the command line.
inline prism::Estimator caustic_estimator(const Options& options)
{
    return {.k = options.k, .radius = float(options.radius), .filter = options.filter, .max_height_ratio = float(options.max_height_ratio)};
}

/// Run an example's body, turning exceptions into a message and exit code 1.
template <class Body>
int run(Body&& body) noexcept
{
    try {
        return body();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}

/// Render and report the render time (camera rays to finished film) on stdout.
template <class Integrator>
prism::Film timed_render(const char* name, const prism::Camera<typename Integrator::scalar_type>& camera,
                         const Integrator& integrator, const prism::RenderConfig& config)
{
    const auto start = std::chrono::steady_clock::now();
    prism::Film film = prism::render(camera, integrator, config);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %dx%d, %d spp, render time %.4f s\n", name, config.width, config.height, config.spp, seconds);
    return film;
}

} // namespace examples
