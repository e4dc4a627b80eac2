// SPDX-License-Identifier: MIT
// The command line shared by every example: size, samples, threads, seed, output folder.
#pragma once

#include <prism/prism.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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
    int gather = 0;
    double radius = 0.1;          ///< the caustic estimate's radius, or its search limit with --k
    std::size_t k = 100;          ///< > 0: the caustic estimate from the k nearest photons, 0: all within radius
    double global_radius = 0.25;  ///< the global map's estimate, where it is read directly
    prism::Filter filter = prism::Filter::cone;
    double disk = 1.0;            ///< < 1 flattens the estimate's sphere to a disk (against leaks)
    std::size_t visibility = 0;   ///< > 0: skip shadow rays where this many nearest photons agree
    bool povray_light = false;    ///< POV-Ray's no-falloff light, as its scene has it
};

inline void print_help(const char* program, const char* description, const Options& defaults)
{
    std::printf("%s: %s\n\n"
                "usage: %s [options]\n"
                "  --width N     image width in pixels (default %d)\n"
                "  --height N    image height in pixels (default %d)\n"
                "  --spp N       samples per pixel; 1 samples pixel centres (default %d)\n"
                "  --threads N   worker threads, 0 = all cores (default 0)\n"
                "  --seed N      random seed (default 0)\n"
                "  --out DIR     folder for the images, created if missing (default .)\n"
                "  --povray PNG  POV-Ray's picture of the same scene: also write prism | POV-Ray | difference\n"
                "  photon mapping examples:\n"
                "  --photons N          photons emitted for the global map (default 200000)\n"
                "  --caustic-photons N  photons aimed at specular objects (default 200000)\n"
                "  --gather N           final-gather rays per diffuse hit, 0 = read the global map (default 0)\n"
                "  --radius R           radius of the caustic estimate, or its search limit with --k (default 0.1)\n"
                "  --k N                caustic estimate from the N nearest photons, 0 = every photon within R (default 100)\n"
                "  --global-radius R    radius of the global map's estimate where read directly (default 0.25)\n"
                "  --filter F           box, cone or gaussian, for both estimates (default cone)\n"
                "  --disk D             keep photons within D R of the tangent plane, < 1 against light leaks (default 1)\n"
                "  --visibility N       skip shadow rays where the N nearest global photons agree (default 0 = never)\n"
                "  --light L            physical (inverse-square) or povray (no falloff, as the .pov file) (default physical)\n"
                "  --help        this text\n",
                program, description, program, defaults.render.width, defaults.render.height, defaults.render.spp);
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

/// A number in (lo, hi].
inline double parse_number(std::string_view flag, const char* text, double lo, double hi)
{
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(value > lo && value <= hi))
        throw std::invalid_argument(std::string(flag) + " expects a number in (" + std::to_string(lo) + ", " + std::to_string(hi) +
                                    "], got '" + text + "'");
    return value;
}

/// Parse the shared options; returns false when --help was printed.
inline bool parse(int argc, char** argv, Options& options, const char* description)
{
    const Options defaults = options;
    for (int i = 1; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            print_help(argv[0], description, defaults);
            return false;
        }
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
        else if (flag == "--gather") options.gather = parse_integer<int>(flag, value, 0, 4096);
        else if (flag == "--radius") options.radius = parse_number(flag, value, 0, 100);
        else if (flag == "--global-radius") options.global_radius = parse_number(flag, value, 0, 100);
        else if (flag == "--disk") options.disk = parse_number(flag, value, 0, 1);
        else if (flag == "--k") options.k = parse_integer<std::size_t>(flag, value, 0, prism::PhotonMap::max_k);
        else if (flag == "--visibility") options.visibility = parse_integer<std::size_t>(flag, value, 0, prism::PhotonMap::max_k);
        else if (flag == "--filter") {
            const std::string_view f = value;
            if (f == "box") options.filter = prism::Filter::box;
            else if (f == "cone") options.filter = prism::Filter::cone;
            else if (f == "gaussian") options.filter = prism::Filter::gaussian;
            else throw std::invalid_argument("--filter expects box, cone or gaussian, got '" + std::string(f) + "'");
        }
        else if (flag == "--light") {
            const std::string_view l = value;
            if (l != "physical" && l != "povray") throw std::invalid_argument("--light expects physical or povray, got '" + std::string(l) + "'");
            options.povray_light = l == "povray";
        }
        else throw std::invalid_argument("unknown option '" + std::string(flag) + "' (see --help)");
    }
    std::filesystem::create_directories(options.out);
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
    return {.k = options.k, .radius = float(options.radius), .filter = options.filter, .disk = float(options.disk)};
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
