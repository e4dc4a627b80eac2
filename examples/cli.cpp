// SPDX-License-Identifier: MIT
// The examples' command line: what does not depend on a scene's types, compiled once.
#include "cli.hpp"

#include <prism/io/image.hpp>
#include <prism/io/output.hpp>
#include <prism/photon/photon_map.hpp>
#ifdef PRISM_EXAMPLES_EXR
#include <prism/io/exr.hpp>
#endif

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <unistd.h>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace examples {
namespace {

void print_photon_help(const Options& defaults)
{
    std::printf("  photon mapping:\n"
                "  --photons N          photons emitted for the global map (default %zu)\n"
                "  --caustic-photons N  photons aimed at specular objects (default %zu)\n"
                "  --photon-sampler S   the photons' points, as --sampler's (default: --sampler's; zsobol draws sobol's)\n"
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
                "                       pixel and as many light paths), bdpt (bidirectional path tracing) or vcm (vertex\n"
                "                       connection and merging): --spp passes of a camera path per pixel and as many light\n"
                "                       paths (default %s)\n"
                "  --passes N           progressive photon mapping's passes, or A:B for passes [A, B) of them (default %zu)\n",
                defaults.photons, defaults.caustic_photons, defaults.gather, defaults.method.c_str(), defaults.passes);
}

} // namespace

void print_help(const char* program, const char* description, const Options& defaults, Accepts accepts)
{
    std::printf("%s: %s\n\n"
                "usage: %s [options]\n"
                "  --width N     image width in pixels (default %d)\n"
                "  --height N    image height in pixels (default %d)\n"
                "  --spp N       samples per pixel; 1 samples pixel centres (default %d)\n"
                "  --threads N   worker threads, 0 = all cores (default 0)\n"
                "  --seed N      random seed (default 0)\n"
                "  --sampler S   the samples' and photons' points: zsobol (Owen-scrambled Sobol laid over the image in\n"
                "                Morton order: every 2^m samples of a pixel stratified, the error blue noise once all --spp\n"
                "                are taken; photons draw sobol's), sobol (per pixel, its error white), halton (Halton's\n"
                "                sequence, Owen-scrambled: photon emission as in progressive photon mapping) or independent\n"
                "                (default zsobol)\n"
                "  --out DIR     folder for the images, created if missing (default .)\n"
                "  --crop X0,X1,Y0,Y1\n"
                "                render only pixels [X0, X1) x [Y0, Y1), from the top left; with a decimal point, as\n"
                "                fractions of the width and height (pbrt's --cropwindow); the same bits as those pixels\n"
                "                of the whole render (default: the whole image)\n"
                "  --passes A:B  render only passes [A, B): samples of --spp, or progressive photon mapping's passes;\n"
                "                parts add up with prism_merge to the whole render's bits (default: all)\n"
                "  --seconds S   a time budget: the samples (or passes) in rounds, each pixel's count doubling, up to\n"
                "                the round S seconds end in; --spp (--passes) the most taken (default 0: all of them)\n"
                "  --preview     write each image as OUT/NAME.preview.png after every round of samples, a picture\n"
                "                converging; removed when the finished image is written (default: off)\n"
                "  --exr         also write each image as EXR (float RGB and the render's settings); a part (--crop,\n"
                "                --passes A:B) always writes EXR, with its exact sums (default: off)\n"
                "  --help        this text\n",
                program, description, program, defaults.render.width, defaults.render.height, defaults.render.spp);
    if (accepts.povray)
        std::printf("  --povray PNG  POV-Ray's picture of the same scene (same size): also write prism | POV-Ray | difference\n");
    if (accepts.photons) print_photon_help(defaults);
}

/// A number in (lo, hi] that is still > lo once rounded to float (the estimators keep
/// floats: --radius 1e-300 would become 0).
prism::SamplerKind parse_sampler(std::string_view flag, const char* text)
{
    for (const prism::SamplerKind kind : prism::sampler_kinds)
        if (std::string_view(text) == prism::sampler_name(kind)) return kind;
    throw std::invalid_argument(std::string(flag) + " must be zsobol, sobol, halton or independent, got '" + std::string(text) + "'");
}

double parse_number(std::string_view flag, const char* text, double lo, double hi)
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

/// --crop X0,X1,Y0,Y1 for a width x height image: pixels [X0, X1) x [Y0, Y1), or, if
/// any value has a decimal point or an exponent, fractions of the image (pbrt's
/// --cropwindow: pixels from ceil(X0 width) to ceil(X1 width), and so for y).
prism::PixelWindow parse_crop(const std::string& text, int width, int height)
{
    const auto refuse = [&](const std::string& why) {
        throw std::invalid_argument("--crop expects X0,X1,Y0,Y1 as pixels (0 <= X0 < X1 <= width) or fractions of the image (0.0 to 1.0), got '" + text +
                                    "'" + why);
    };
    std::array<std::string, 4> parts;
    std::size_t start = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t comma = text.find(',', start);
        if ((k < 3) == (comma == std::string::npos)) refuse("");
        parts[k] = text.substr(start, k < 3 ? comma - start : std::string::npos);
        start = comma + 1;
    }
    const bool fractions = text.find_first_of(".eE") != std::string::npos;
    std::array<double, 4> v{};
    for (std::size_t k = 0; k < 4; ++k) {
        char* end = nullptr;
        errno = 0;
        v[k] = fractions ? std::strtod(parts[k].c_str(), &end) : double(std::strtoll(parts[k].c_str(), &end, 10));
        if (parts[k].empty() || errno != 0 || *end != '\0' || !(v[k] >= 0.0 && v[k] <= (fractions ? 1.0 : double(k < 2 ? width : height)))) refuse("");
    }
    prism::PixelWindow w;
    if (fractions)
        w = {int(std::ceil(v[0] * width)), int(std::ceil(v[2] * height)), int(std::ceil(v[1] * width)), int(std::ceil(v[3] * height))};
    else
        w = {int(v[0]), int(v[2]), int(v[1]), int(v[3])};
    if (w.empty())
        refuse(fractions ? " (no pixel of the " + std::to_string(width) + "x" + std::to_string(height) + " image is inside)"
                         : " (X0 < X1 and Y0 < Y1 within the " + std::to_string(width) + "x" + std::to_string(height) + " image)");
    return w;
}

/// --passes A:B, a range of passes; nullopt when the text is a single count.
std::optional<prism::PassRange> parse_pass_range(const char* text)
{
    const std::string_view t = text;
    const std::size_t colon = t.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    const std::string first(t.substr(0, colon)), last(t.substr(colon + 1));
    const auto a = parse_integer<std::uint64_t>("--passes", first.c_str(), 0, 1LL << 40);
    const auto b = parse_integer<std::uint64_t>("--passes", last.c_str(), 1, 1LL << 40);
    if (a >= b) throw std::invalid_argument("--passes expects A:B with A < B, got '" + std::string(t) + "'");
    return prism::PassRange{a, b};
}

/// Refuse an output folder that cannot be written, before anything is rendered.
void check_writable(const std::string& folder_name)
{
    const std::filesystem::path folder = folder_name;
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw std::invalid_argument("--out " + folder.string() + " is not writable: " + error.message());
    // Named by the process and the time: processes started together (MPI ranks) probe
    // the same folder at once, and one's probe must not be taken for the other's.
    const std::filesystem::path probe = folder / (".prism-write-check-" + std::to_string(::getpid()) + "-" +
                                                  std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::FILE* file = std::fopen(probe.c_str(), "wbx");
    if (file == nullptr) throw std::invalid_argument("--out " + folder.string() + " is not writable: " + std::strerror(errno));
    std::fclose(file);
    std::filesystem::remove(probe);
}

/// Refuse, before anything is rendered, an output file the example could not write: one
/// of its images' names (PNG, and EXR where it writes one) taken by a directory, or a
/// file that is there and not writable.
void check_outputs(const Options& options)
{
    std::vector<std::string> extensions{".png"};
    if (options.exr || options.part) extensions.push_back(".exr");
    for (const std::string& image : options.images)
        for (const std::string& extension : extensions) {
            const std::filesystem::path path = output_file(options, image + extension);
            std::error_code error;
            const auto status = std::filesystem::status(path, error);
            if (status.type() == std::filesystem::file_type::directory)
                throw std::invalid_argument("--out: " + path.string() + " is a directory, where the example writes its image");
            if (status.type() == std::filesystem::file_type::regular && ::access(path.c_str(), W_OK) != 0)
                throw std::invalid_argument("--out: " + path.string() + " is not writable: " + std::strerror(errno));
        }
}

prism::OutputSet& outputs()
{
    static prism::OutputSet set;
    return set;
}

namespace {

/// The previews written so far: removed once the finished images are.
std::vector<std::filesystem::path>& previews()
{
    static std::vector<std::filesystem::path> written;
    return written;
}

} // namespace

void commit_outputs()
{
    outputs().commit();
    for (const std::filesystem::path& preview : previews()) {
        std::error_code ignored; // a preview someone already removed is no error
        std::filesystem::remove(preview, ignored);
    }
    previews().clear();
}

void save_preview(const prism::Film& film, const Options& options, const std::string& name)
{
    const std::filesystem::path path = output_file(options, name + ".preview.png");
    prism::write_png(film, path);
    if (std::find(previews().begin(), previews().end(), path) == previews().end()) previews().push_back(path);
}

void remove_partial_files_on_signal() { prism::remove_partial_files_on_signal(); }

void save_png(const prism::Film& film, const Options& options, const std::string& name)
{
    outputs().add(output_file(options, name + ".png"), prism::encode_png(film));
}

/// Refuse a --povray picture that cannot be read or has another size, before rendering.
void check_povray_picture(const std::string& png, int width, int height)
{
    const prism::Film picture = prism::read_png(png);
    if (picture.width() != width || picture.height() != height)
        throw std::invalid_argument("--povray: " + png + " is " + std::to_string(picture.width()) + "x" +
                                    std::to_string(picture.height()) + ", the render is " + std::to_string(width) + "x" + std::to_string(height));
}

/// Parse the shared options and the families the example accepts; returns false when
/// --help was printed. Checks the output folder and a --povray picture before returning,
/// so that a bad one is reported before the render, not after it.
bool parse(int argc, char** argv, Options& options, const char* description, Accepts accepts)
{
    const Options defaults = options;
    options.program = std::filesystem::path(argv[0]).filename().string();
    options.photon_example = accepts.photons;
    std::optional<prism::PassRange> pass_range;
    bool pass_count = false;
    constexpr std::string_view photon_flags[] = {"--photons", "--caustic-photons", "--gather", "--radius", "--global-radius",
                                                 "--max-height-ratio", "--k",               "--visibility", "--filter", "--light",
                                                 "--method", "--photon-sampler"};
    for (int i = 1; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            print_help(argv[0], description, defaults, accepts);
            return false;
        }
        if (flag == "--exr") {
            options.exr = true;
            continue;
        }
        if (flag == "--preview") {
            options.preview = true;
            continue;
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
        else if (flag == "--sampler") options.render.sampler = parse_sampler(flag, value);
        else if (flag == "--photon-sampler") options.photon_sampler = parse_sampler(flag, value);
        else if (flag == "--seconds") options.render.seconds = parse_number(flag, value, 0, 1e9);
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
            if (m != "direct" && m != "gather" && m != "cache" && m != "progressive" && m != "reference" && m != "bdpt" && m != "vcm")
                throw std::invalid_argument("--method expects direct, gather, cache, progressive, reference, bdpt or vcm, got '" + std::string(m) + "'");
            options.method = m;
        }
        else if (flag == "--crop") options.crop = value;
        else if (flag == "--passes") {
            if (const auto range = parse_pass_range(value)) {
                pass_range = range;
            } else {
                if (!accepts.photons)
                    throw std::invalid_argument("--passes N counts progressive photon mapping's passes; to render samples A to B of --spp give A:B, got '" +
                                                std::string(value) + "'");
                options.passes = parse_integer<std::size_t>(flag, value, 1, 1000000);
                pass_count = true;
            }
        }
        else if (flag == "--light") {
            const std::string_view l = value;
            if (l != "physical" && l != "povray") throw std::invalid_argument("--light expects physical or povray, got '" + std::string(l) + "'");
            options.povray_light = l == "povray";
        }
        else throw std::invalid_argument("unknown option '" + std::string(flag) + "' (see --help)");
    }
    // The parts of a render split across machines.
    if (!options.crop.empty()) options.render.crop = parse_crop(options.crop, options.render.width, options.render.height);
    const bool progressive = accepts.photons && options.method == "progressive";
    if (pass_count && !progressive)
        throw std::invalid_argument("--passes " + std::to_string(options.passes) + " counts progressive photon mapping's passes (--method progressive); "
                                    "to render samples A to B of --spp give A:B");
    if (pass_range) {
        if (progressive) {
            options.first_pass = pass_range->first;
            options.passes = pass_range->count();
        } else {
            if (pass_range->last > std::uint64_t(options.render.spp))
                throw std::invalid_argument("--passes " + std::to_string(pass_range->first) + ":" + std::to_string(pass_range->last) + " reaches past the " +
                                            std::to_string(options.render.spp) + " samples of --spp");
            options.render.passes = *pass_range;
        }
    }
    options.part = !options.crop.empty() || pass_range.has_value();
    if (options.part && !options.povray.empty())
        throw std::invalid_argument("--povray compares whole pictures: it cannot go with --crop or --passes A:B");
    if (options.part && options.render.seconds > 0)
        throw std::invalid_argument("--seconds takes the samples it has time for, and the parts of a render (--crop, --passes A:B) must each take all of theirs");
#ifndef PRISM_EXAMPLES_EXR
    if (options.part || options.exr)
        throw std::invalid_argument(std::string(options.part ? "--crop and --passes A:B write" : "--exr writes") +
                                    " EXR, and this build has no OpenEXR (Debian: libopenexr-dev)");
#endif
    check_writable(options.out);
    check_outputs(options);
    if (!options.povray.empty()) check_povray_picture(options.povray, options.render.width, options.render.height);
    return true;
}

/// Every setting that changes a bit of the image, written out: parts of one render
/// must agree on it (prism_merge refuses them otherwise). Thread count, output and the
/// part's own window and passes change no bit and are left out.
std::string settings(const Options& options)
{
    const auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", x);
        return std::string(text);
    };
    const prism::RenderConfig& r = options.render;
    std::string text = "program=" + options.program + " width=" + std::to_string(r.width) + " height=" + std::to_string(r.height) +
                       " spp=" + std::to_string(r.spp) + " seed=" + std::to_string(r.seed) +
                       " sampler=" + prism::sampler_name(r.sampler);
    if (options.photon_example) {
        const char* filters[] = {"box", "cone", "gaussian"};
        text += " method=" + options.method + " photons=" + std::to_string(options.photons) + " caustic-photons=" +
                std::to_string(options.caustic_photons) + " gather=" + std::to_string(options.gather) + " radius=" + number(options.radius) +
                " k=" + std::to_string(options.k) + " global-radius=" + number(options.global_radius) + " filter=" + filters[int(options.filter)] +
                " max-height-ratio=" + number(options.max_height_ratio) + " visibility=" + std::to_string(options.visibility) +
                " light=" + (options.povray_light ? "povray" : "physical") + " photon-sampler=" + prism::sampler_name(options.photon_sampler.value_or(r.sampler));
    }
    return text;
}

/// Queue an image as name.png (and name.pfm, exact floats, with `pfm`); as name.exr too
/// with --exr, and always for a part of a render (--crop, --passes A:B), with the exact
/// sums and the metadata prism_merge needs to add it to the other parts. run() writes
/// them, with every other output, once the example has finished.
void save(const Rendered& rendered, const Options& options, bool pfm)
{
    const prism::Film film = rendered.image();
    save_png(film, options, rendered.name);
    if (pfm) outputs().add(output_file(options, rendered.name + ".pfm"), prism::encode_pfm(film));
#ifdef PRISM_EXAMPLES_EXR
    if (options.exr || options.part) {
        const prism::PixelWindow& w = rendered.sums.window();
        const bool progressive = options.photon_example && options.method == "progressive";
        const std::uint64_t first = progressive ? options.first_pass : (options.render.passes.empty() ? 0 : options.render.passes.first);
        const std::uint64_t last = progressive ? options.first_pass + options.passes
                                               : (options.render.passes.empty() ? std::uint64_t(options.render.spp) : options.render.passes.last);
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.3f", rendered.seconds);
        std::map<std::string, std::string> attributes{
            {"prism.image", rendered.name},
            {"prism.settings", settings(options)},
            {"prism.seed", std::to_string(options.render.seed)},
            {"prism.spp", std::to_string(options.render.spp)},
            {"prism.part.crop", std::to_string(w.x0) + "," + std::to_string(w.x1) + "," + std::to_string(w.y0) + "," + std::to_string(w.y1)},
            {"prism.part.passes", std::to_string(first) + ":" + std::to_string(last)},
            {"prism.part.seconds", seconds}};
        if (options.photon_example) {
            attributes["prism.method"] = options.method;
            attributes["prism.photons"] = std::to_string(options.photons) + " global, " + std::to_string(options.caustic_photons) + " caustic" +
                                          (progressive ? " per pass" : "");
        }
        outputs().add(output_file(options, rendered.name + ".exr"), prism::encode_exr(prism::to_exr(rendered.sums, options.part, attributes)));
    }
#endif
}

} // namespace examples
