// SPDX-License-Identifier: MIT
#include <prism/io/output.hpp>

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace output_test {

fs::path scratch_folder(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("prism-output-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<unsigned char> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::string read_text(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// Files in `dir`, temporaries included.
int files_in(const fs::path& dir)
{
    int n = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
    return n;
}

} // namespace output_test

TEST_CASE("an OutputSet writes every file it holds, and a later add of a path replaces the earlier")
{
    const fs::path dir = output_test::scratch_folder("all");
    prism::OutputSet set;
    set.add(dir / "a.txt", output_test::bytes_of("first"));
    set.add(dir / "b.txt", output_test::bytes_of("bee"));
    set.add(dir / "a.txt", output_test::bytes_of("alpha"));
    CHECK(set.size() == 2);
    set.commit();
    CHECK(set.size() == 0);
    CHECK(output_test::read_text(dir / "a.txt") == "alpha");
    CHECK(output_test::read_text(dir / "b.txt") == "bee");
    CHECK(output_test::files_in(dir) == 2);
    fs::remove_all(dir);
}

TEST_CASE("an OutputSet that cannot write one file writes none, and leaves no temporary")
{
    // Regression: an output that could not be written (a directory, a link to /dev/full) was
    // found after the outputs before it had been written, and they stayed.
    const fs::path dir = output_test::scratch_folder("none");
    std::ofstream(dir / "kept.txt") << "old";
    fs::create_directories(dir / "taken.txt");
    prism::OutputSet set;
    set.add(dir / "kept.txt", output_test::bytes_of("new"));
    set.add(dir / "fresh.txt", output_test::bytes_of("fresh"));
    set.add(dir / "taken.txt", output_test::bytes_of("x"));
    CHECK_THROWS_WITH_AS(set.commit(), doctest::Contains("taken.txt': it is a directory"), std::runtime_error);
    CHECK(output_test::read_text(dir / "kept.txt") == "old");
    CHECK_FALSE(fs::exists(dir / "fresh.txt"));
    CHECK(output_test::files_in(dir) == 2); // kept.txt and the directory: no temporary
    if (::access("/dev/full", W_OK) == 0) {
        fs::create_symlink("/dev/full", dir / "full.txt");
        prism::OutputSet full;
        full.add(dir / "kept.txt", output_test::bytes_of("new"));
        full.add(dir / "full.txt", output_test::bytes_of("bytes"));
        full.add(dir / "fresh.txt", output_test::bytes_of("fresh"));
        CHECK_THROWS_WITH_AS(full.commit(), doctest::Contains("No space left on device"), std::runtime_error);
        CHECK(output_test::read_text(dir / "kept.txt") == "old");
        CHECK_FALSE(fs::exists(dir / "fresh.txt"));
        CHECK(output_test::files_in(dir) == 3);
    }
    fs::remove_all(dir);
}

TEST_CASE("a program stopped by SIGTERM while it writes leaves no temporary file, once it asked remove_partial_files_on_signal()")
{
    // Regression: SIGTERM during the final write left *.prism-partial-* files (90 MB).
    // A child stages a file (as OutputSet::commit does before its renames) and is
    // stopped; with the handler the temporary is gone, without it it stays.
    for (const bool handled : {true, false}) {
        CAPTURE(handled);
        const fs::path dir = output_test::scratch_folder(handled ? "signal" : "signal-unhandled");
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            std::signal(SIGTERM, SIG_DFL); // (not the test runner's crash report)
            if (handled) prism::remove_partial_files_on_signal();
            (void)prism::detail::stage_file(dir / "image.png", dir / "image.png", output_test::bytes_of(std::string(1 << 20, 'x')));
            std::raise(SIGTERM);
            _exit(0); // (not reached)
        }
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == SIGTERM);
        CHECK(output_test::files_in(dir) == (handled ? 0 : 1));
        fs::remove_all(dir);
    }
}
