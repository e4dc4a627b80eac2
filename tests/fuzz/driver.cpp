// SPDX-License-Identifier: MIT
// The fuzz targets without libFuzzer: run each file named on the command line (or every
// file in a named folder) through LLVMFuzzerTestOneInput once, so that the committed
// corpus and the inputs that once broke a target are tests of every build (with g++, and
// under the sanitizers), not only of the clang fuzzing run.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
    std::size_t inputs = 0;
    const auto run = [&](const std::filesystem::path& file) {
        std::ifstream in(file, std::ios::binary);
        const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
        ++inputs;
    };
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path path = argv[i];
        if (!std::filesystem::exists(path)) continue; // a target with no regressions yet
        if (std::filesystem::is_directory(path)) {
            for (const auto& entry : std::filesystem::directory_iterator(path))
                if (entry.is_regular_file()) run(entry.path());
        } else {
            run(path);
        }
    }
    std::printf("fuzz corpus: %zu inputs, no check failed\n", inputs);
    return inputs > 0 ? 0 : 1;
}
