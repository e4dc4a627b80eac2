// SPDX-License-Identifier: MIT
// Runs every program of the documentation (README.md and docs/), each in a folder of its own
// under the folder given, and fails if one fails: tools/snippets.py writes them, one
// namespace each, into snippets.cpp, with the documentation's declarations beside them, so
// every ```cpp block a reader copies is compiled here and every program in one is run.
#include "snippets.cpp"

#include <cstdio>
#include <exception>
#include <filesystem>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: prism_snippets WORKDIR\n");
        return 2;
    }
    const std::filesystem::path work = std::filesystem::absolute(argv[1]);
    int failed = 0, index = 0;
    for (const Snippet& program : programs) {
        if (program.main == nullptr)
            continue;
        const std::filesystem::path folder = work / std::to_string(index++);
        std::filesystem::create_directories(folder);
        std::filesystem::current_path(folder);
        int status = 1;
        try {
            status = program.main();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: threw: %s\n", program.where, e.what());
        }
        std::printf("%s: %s (in %s)\n", program.where, status == 0 ? "ran" : "FAILED", folder.c_str());
        failed += status != 0;
    }
    std::printf("documentation programs: %d run, %d failed\n", index, failed);
    return failed == 0 ? 0 : 1;
}
