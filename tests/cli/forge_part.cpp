// SPDX-License-Identifier: MIT
// A hostile user's tool for tests/cli/merge.sh: edits one prism. attribute of a render's
// part, multiplies its pixels' weights by a whole number, and writes the part again with its
// digest computed anew (a checksum, not a signature: whoever edits a part can), so that
// only prism_merge's own checks of what a part claims can refuse it.
//   forge_part IN.exr OUT.exr NAME VALUE WEIGHT_FACTOR
#include <prism/io/exr.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

int main(int argc, char** argv)
{
    if (argc != 6) {
        std::fprintf(stderr, "usage: forge_part IN.exr OUT.exr NAME VALUE WEIGHT_FACTOR\n");
        return 2;
    }
    prism::ExrImage image = prism::read_exr(argv[1]);
    image.attributes[argv[3]] = argv[4];
    const std::uint64_t factor = std::strtoull(argv[5], nullptr, 10);
    std::vector<std::uint32_t>* low = nullptr;
    std::vector<std::uint32_t>* high = nullptr;
    for (prism::ExrChannel& c : image.channels) {
        if (c.name == "weight.0") low = std::get_if<std::vector<std::uint32_t>>(&c.values);
        if (c.name == "weight.1") high = std::get_if<std::vector<std::uint32_t>>(&c.values);
    }
    if (low == nullptr || high == nullptr || low->size() != high->size()) {
        std::fprintf(stderr, "forge_part: %s holds no exact weights\n", argv[1]);
        return 1;
    }
    for (std::size_t i = 0; i < low->size(); ++i) {
        const std::uint64_t weight = (std::uint64_t((*high)[i]) << 32 | (*low)[i]) * factor;
        (*low)[i] = std::uint32_t(weight);
        (*high)[i] = std::uint32_t(weight >> 32);
    }
    image.attributes["prism.part.digest"] = prism::exr_digest(image);
    const std::vector<unsigned char> bytes = prism::encode_exr(image);
    std::ofstream(argv[2], std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return 0;
}
