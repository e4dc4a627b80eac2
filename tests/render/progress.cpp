// SPDX-License-Identifier: MIT
#include <prism/render/progress.hpp>

#include <doctest/doctest.h>

#include <cstdio>
#include <string>

using prism::detail::formatted;
using prism::detail::ProgressLine;

namespace {

/// What `write` printed into a temporary file.
template <class Write>
std::string printed(Write&& write)
{
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    write(file);
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c; (c = std::fgetc(file)) != EOF;) text += char(c);
    std::fclose(file);
    return text;
}

} // namespace

TEST_CASE("progress on a terminal is one line rewritten in place, and ends with a newline")
{
    const std::string text = printed([](std::FILE* out) {
        ProgressLine line(out, true, "rendering");
        line.update(0.5, formatted("%3d%% (%.1f s)", 5, 0.5)); // under a second: nothing
        line.update(1.5, formatted("%3d%% (%.1f s)", 40, 1.5));
        line.update(2.5, formatted("%3d%% (%.1f s)", 80, 2.5));
        line.finish(3.0, "done");
    });
    CHECK(text == "\rprism: rendering  40% (1.5 s)\rprism: rendering  80% (2.5 s)\rprism: rendering done        \n");
}

TEST_CASE("progress in a log or a pipe is a start line and an end line, with no carriage return")
{
    // (The renders' progress wrote a carriage return and a state per tile into a log
    // file, hundreds of states on one line, before render_pixels took a ProgressLine.)
    const std::string text = printed([](std::FILE* out) {
        ProgressLine line(out, false, "rendering");
        for (int i = 0; i <= 100; ++i) line.update(0.05 * i, formatted("%3d%% (%.1f s)", i, 0.05 * i));
        line.finish(5.0, "100% (5.0 s)");
    });
    CHECK(text == "prism: rendering:  21% (1.1 s), going on\nprism: rendering: 100% (5.0 s)\n");
    CHECK(text.find('\r') == std::string::npos);
}

TEST_CASE("quick work says nothing, unless its end is asked for")
{
    for (const bool terminal : {true, false}) {
        CHECK(printed([&](std::FILE* out) {
                  ProgressLine line(out, terminal, "rendering");
                  line.update(0.3, "30%");
                  line.finish(0.6, "done");
              }).empty());
        CHECK(printed([&](std::FILE* out) {
                  ProgressLine line(out, terminal, "rendering");
                  line.finish(0.6, "done", true);
              }) == (terminal ? "prism: rendering done\n" : "prism: rendering: done\n"));
    }
}
