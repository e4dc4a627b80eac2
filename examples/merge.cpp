// SPDX-License-Identifier: MIT
// prism_merge: add up the parts of a render split across machines (EXR files written by
// an example with --crop or --passes A:B) into the render made in one piece, bit for bit.
//
// The parts must be of the same image rendered with the same settings (every "prism."
// attribute but the part's own "prism.part." ones); where two parts' windows overlap
// their passes must not; and every pixel of the result must have all of the parts'
// passes, once. Each part must hold what it was written with (its prism.part.digest),
// and its sums the passes it says. The result is EXR again, with its exact sums and
// digest, so results can be merged further; --png also writes its picture.
#include <prism/io/exr.hpp>
#include <prism/io/image.hpp>
#include <prism/io/output.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

namespace {

struct Part {
    std::filesystem::path path;
    prism::ExrImage image;
    prism::PassRange passes;
    std::uint64_t samples_per_pass = 0; ///< each pixel's weight over its pass count, from its sums
};

std::string describe(const prism::PixelWindow& w)
{
    return "[" + std::to_string(w.x0) + ", " + std::to_string(w.x1) + ") x [" + std::to_string(w.y0) + ", " + std::to_string(w.y1) + ")";
}

std::string describe(const prism::PassRange& r) { return std::to_string(r.first) + ":" + std::to_string(r.last); }

const std::string& attribute(const Part& part, const std::string& name)
{
    const auto found = part.image.attributes.find(name);
    if (found == part.image.attributes.end())
        throw std::invalid_argument(part.path.string() + " has no '" + name + "' attribute: it is not a part written by a prism example");
    return found->second;
}

prism::PassRange parse_passes(const Part& part)
{
    const std::string& text = attribute(part, "prism.part.passes");
    unsigned long long a = 0, b = 0;
    char end = 0;
    if (std::sscanf(text.c_str(), "%llu:%llu%c", &a, &b, &end) != 2 || a >= b)
        throw std::invalid_argument(part.path.string() + " has prism.part.passes '" + text + "', not A:B with A < B");
    return {a, b};
}

/// The channels whose means the part stores (R, G, B first), in its own order.
std::vector<std::string> mean_channels(const prism::ExrImage& image)
{
    std::vector<std::string> names;
    for (const char* c : {"R", "G", "B"}) names.emplace_back(c);
    for (const prism::ExrChannel& c : image.channels)
        if (std::holds_alternative<std::vector<float>>(c.values) && c.name != "R" && c.name != "G" && c.name != "B") names.push_back(c.name);
    return names;
}

void print_help()
{
    std::printf("prism_merge: add up the parts of a render (EXR files from an example's --crop or --passes A:B)\n\n"
                "usage: prism_merge --out FILE.exr [--png FILE.png] [--pfm FILE.pfm] PART.exr...\n"
                "  --out FILE.exr  the merged render: its means and exact sums (required)\n"
                "  --png FILE.png  also its picture, as the example writes it (default: none)\n"
                "  --pfm FILE.pfm  also its exact floats, as the examples that write PFM do (default: none)\n"
                "  --help          this text\n");
}

int merge(int argc, char** argv)
{
    std::filesystem::path out, png, pfm;
    std::vector<std::filesystem::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            print_help();
            return 0;
        }
        if (flag == "--out" || flag == "--png" || flag == "--pfm") {
            if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a file name");
            (flag == "--out" ? out : flag == "--png" ? png : pfm) = argv[++i];
        } else if (flag.starts_with("--")) {
            throw std::invalid_argument("unknown option '" + flag + "' (see --help)");
        } else {
            inputs.emplace_back(flag);
        }
    }
    if (out.empty()) throw std::invalid_argument("--out FILE.exr is required (see --help)");
    if (out.extension() != ".exr") throw std::invalid_argument("--out " + out.string() + " must end in .exr");
    if (!png.empty() && png.extension() != ".png") throw std::invalid_argument("--png " + png.string() + " must end in .png");
    if (!pfm.empty() && pfm.extension() != ".pfm") throw std::invalid_argument("--pfm " + pfm.string() + " must end in .pfm");
    if (inputs.empty()) throw std::invalid_argument("no parts to merge (see --help)");
    // An output that names an input would overwrite a part (read first, written last).
    for (const std::filesystem::path& output : {out, png, pfm}) {
        if (output.empty()) continue;
        for (const std::filesystem::path& input : inputs) {
            std::error_code error;
            if (std::filesystem::weakly_canonical(output, error) == std::filesystem::weakly_canonical(input, error) ||
                std::filesystem::equivalent(output, input, error))
                throw std::invalid_argument("the output " + output.string() + " is the part " + input.string() + ": it would be overwritten");
        }
    }

    std::vector<Part> parts;
    for (const auto& path : inputs) {
        Part part{path, prism::read_exr(path), {}, 0};
        if (part.image.find("weight.0") == nullptr)
            throw std::invalid_argument(path.string() + " holds no exact sums (no 'weight.0' channel): it is not a part of a render (--crop or --passes A:B write one)");
        // The part as it was written: its metadata and sums still have the digest it was
        // written with (a part whose passes, seed or settings were edited, or whose bytes
        // were damaged on the way, has not).
        if (const std::string& digest = attribute(part, "prism.part.digest"), actual = prism::exr_digest(part.image); digest != actual)
            throw std::invalid_argument(path.string() + " has prism.part.digest '" + digest + "', but what it holds has " + actual +
                                        ": it was changed after it was written");
        part.passes = parse_passes(part);
        (void)attribute(part, "prism.settings");
        // What the part says it holds, against its sums: every pixel took the same number
        // of samples in each of its passes (1, or a progressive pass's camera samples), so
        // its weight is a whole multiple of its pass count, the same for every pixel and
        // (below) every part. A part whose passes were edited, or that claims passes it did
        // not render, is refused.
        if (const prism::ExrChannel* low = part.image.find("weight.0"), *high = part.image.find("weight.1");
            low != nullptr && high != nullptr && std::holds_alternative<std::vector<std::uint32_t>>(low->values) &&
            std::holds_alternative<std::vector<std::uint32_t>>(high->values)) {
            const auto& lo = std::get<std::vector<std::uint32_t>>(low->values);
            const auto& hi = std::get<std::vector<std::uint32_t>>(high->values);
            const std::uint64_t count = part.passes.count();
            for (std::size_t i = 0; i < lo.size() && i < hi.size(); ++i) {
                const std::uint64_t weight = std::uint64_t(hi[i]) << 32 | lo[i];
                if (weight == 0 || weight % count != 0 || (i > 0 && weight / count != part.samples_per_pass))
                    throw std::invalid_argument(path.string() + " says it holds passes " + describe(part.passes) + ", but a pixel's sums hold " + std::to_string(weight) +
                                                " samples, not a whole number of its pixels' samples for each of " + std::to_string(count) +
                                                " passes: its prism.part.passes is not what it rendered");
                part.samples_per_pass = weight / count;
            }
        }
        // A part of samples (not progressive passes) holds samples A to B of its prism.spp,
        // one a pass: what the example's --passes A:B allows, and what its sums must show.
        if (const auto method = part.image.attributes.find("prism.method"); method == part.image.attributes.end() || method->second != "progressive") {
            const std::string& spp_text = attribute(part, "prism.spp");
            unsigned long long spp = 0;
            char end = 0;
            if (std::sscanf(spp_text.c_str(), "%llu%c", &spp, &end) != 1 || spp == 0)
                throw std::invalid_argument(path.string() + " has prism.spp '" + spp_text + "', not a whole number of samples");
            if (part.passes.last > spp)
                throw std::invalid_argument(path.string() + " says it holds passes " + describe(part.passes) + " of prism.spp " + spp_text +
                                            ": passes past its samples per pixel");
            if (part.samples_per_pass != 1)
                throw std::invalid_argument(path.string() + "'s sums hold " + std::to_string(part.samples_per_pass) + " samples a pass where a pass is one sample: its prism.part.passes is not what it rendered");
        }
        parts.push_back(std::move(part));
    }

    // The same image with the same settings: every prism. attribute but the part's own.
    const Part& first = parts.front();
    const auto shared = [](const Part& p) {
        std::map<std::string, std::string> kept;
        for (const auto& [name, value] : p.image.attributes)
            if (name.starts_with("prism.") && !name.starts_with("prism.part.")) kept.emplace(name, value);
        return kept;
    };
    const auto expected = shared(first);
    const std::vector<std::string> channels = mean_channels(first.image);
    for (const Part& p : parts) {
        if (p.image.width != first.image.width || p.image.height != first.image.height)
            throw std::invalid_argument(p.path.string() + " is " + std::to_string(p.image.width) + "x" + std::to_string(p.image.height) + ", " +
                                        first.path.string() + " is " + std::to_string(first.image.width) + "x" + std::to_string(first.image.height));
        const auto mine = shared(p);
        for (const auto& [name, value] : expected) {
            const auto found = mine.find(name);
            if (found == mine.end()) throw std::invalid_argument(p.path.string() + " has no '" + name + "', " + first.path.string() + " has '" + value + "'");
            if (found->second != value)
                throw std::invalid_argument(p.path.string() + " has " + name + " '" + found->second + "', " + first.path.string() + " has '" + value +
                                            "': not parts of one render");
        }
        for (const auto& [name, value] : mine)
            if (!expected.contains(name)) throw std::invalid_argument(p.path.string() + " has '" + name + "', " + first.path.string() + " has not");
        if (mean_channels(p.image) != channels)
            throw std::invalid_argument(p.path.string() + " has other channels than " + first.path.string());
        if (p.samples_per_pass != first.samples_per_pass)
            throw std::invalid_argument(p.path.string() + "'s sums hold " + std::to_string(p.samples_per_pass) + " samples a pass, " + first.path.string() + "'s " +
                                        std::to_string(first.samples_per_pass) + ": one of their prism.part.passes is not what it rendered");
    }

    // No pass of a pixel twice; the result's window is the parts' windows' hull.
    prism::PixelWindow hull = first.image.window;
    prism::PassRange all = first.passes;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const Part& a = parts[i];
        hull = {std::min(hull.x0, a.image.window.x0), std::min(hull.y0, a.image.window.y0), std::max(hull.x1, a.image.window.x1),
                std::max(hull.y1, a.image.window.y1)};
        all = {std::min(all.first, a.passes.first), std::max(all.last, a.passes.last)};
        for (std::size_t j = 0; j < i; ++j) {
            const Part& b = parts[j];
            if (a.image.window.overlaps(b.image.window) && a.passes.overlaps(b.passes))
                throw std::invalid_argument(b.path.string() + " (pixels " + describe(b.image.window) + ", passes " + describe(b.passes) + ") and " +
                                            a.path.string() + " (pixels " + describe(a.image.window) + ", passes " + describe(a.passes) +
                                            ") hold the same passes of some pixels");
        }
    }
    // Every pixel of the hull must have every pass of [all.first, all.last): the passes
    // of each are disjoint, so their count says whether they are all there. First, without
    // allocating the hull: the parts' crops must hold as many pixels as it does (two
    // one-pixel parts at opposite corners of a 65536 x 32768 image cover 2 of its pixels).
    std::uint64_t covered = 0;
    for (const Part& p : parts) covered += p.image.window.area();
    if (covered < hull.area())
        throw std::invalid_argument("the parts' crops hold " + std::to_string(covered) + " pixels, but they span " + describe(hull) + ", " +
                                    std::to_string(hull.area()) + " pixels: a crop is missing");
    std::vector<std::uint64_t> count(hull.area(), 0);
    for (const Part& p : parts)
        for (int y = p.image.window.y0; y < p.image.window.y1; ++y)
            for (int x = p.image.window.x0; x < p.image.window.x1; ++x)
                count[std::size_t(y - hull.y0) * std::size_t(hull.width()) + std::size_t(x - hull.x0)] += p.passes.count();
    for (int y = hull.y0; y < hull.y1; ++y)
        for (int x = hull.x0; x < hull.x1; ++x) {
            const std::uint64_t n = count[std::size_t(y - hull.y0) * std::size_t(hull.width()) + std::size_t(x - hull.x0)];
            if (n != all.count())
                throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") has " + std::to_string(n) + " of the passes " +
                                            describe(all) + " the parts hold: a crop or a range of passes is missing");
        }

    prism::Accumulation sums(first.image.width, first.image.height, hull, channels);
    double seconds = 0;
    for (const Part& p : parts) {
        sums += prism::to_accumulation(p.image, channels);
        seconds += std::strtod(attribute(p, "prism.part.seconds").c_str(), nullptr);
    }
    auto attributes = expected;
    attributes["prism.part.crop"] = std::to_string(hull.x0) + "," + std::to_string(hull.x1) + "," + std::to_string(hull.y0) + "," + std::to_string(hull.y1);
    attributes["prism.part.passes"] = describe(all);
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds);
    attributes["prism.part.seconds"] = text;
    // The merged EXR, PNG and PFM are written together, all or none.
    prism::OutputSet outputs;
    outputs.add(out, prism::encode_exr(prism::to_exr(sums, true, attributes)));
    if (!png.empty() || !pfm.empty()) {
        const prism::Film image = sums.image();
        if (!png.empty()) outputs.add(png, prism::encode_png(image));
        if (!pfm.empty()) outputs.add(pfm, prism::encode_pfm(image));
    }
    outputs.commit();
    std::printf("prism_merge: %zu parts, pixels %s, passes %s, into %s\n", parts.size(), describe(hull).c_str(), describe(all).c_str(), out.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    prism::remove_partial_files_on_signal(); // a merge stopped while it writes leaves no temporary file
    try {
        return merge(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "prism_merge: %s\n", e.what());
        return 1;
    }
}
