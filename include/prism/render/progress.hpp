// SPDX-License-Identifier: MIT
// Progress of a long piece of work on stderr, shaped for where stderr goes: on a terminal
// one line rewritten in place (a carriage return before each state), in a log or a pipe a
// line when the work has begun to take time and one when it ends, so a log holds no
// carriage returns and no hundred states.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace prism::detail {

/// Whether stderr is a terminal.
[[nodiscard]] inline bool stderr_is_terminal() noexcept
{
#if defined(_WIN32)
    return _isatty(_fileno(stderr)) != 0;
#else
    return isatty(fileno(stderr)) != 0;
#endif
}

/// printf's formatting into a string (a line of progress: short).
template <class... Args>
[[nodiscard]] std::string formatted(const char* format, Args... args)
{
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, args...);
    return buffer;
}

/// One piece of work's progress ("prism: <what> <state>"), said once the work has taken
/// more than a second. Not for threads: the caller reports from one.
class ProgressLine {
public:
    /// Progress of `what` to `out`: rewritten in place when `terminal`, else a start and
    /// an end line.
    ProgressLine(std::FILE* out, bool terminal, std::string what) : out_(out), terminal_(terminal), what_(std::move(what)) {}
    /// Progress to stderr, shaped for what stderr is.
    explicit ProgressLine(std::string what) : ProgressLine(stderr, stderr_is_terminal(), std::move(what)) {}

    /// The work's state `seconds` after its start: shown on a terminal; in a log, the
    /// first state past a second begins the report.
    void update(double seconds, const std::string& state)
    {
        if (!(seconds > 1.0)) return;
        if (terminal_) {
            std::fprintf(out_, "\rprism: %s %s", what_.c_str(), state.c_str());
            width_ = std::max(width_, state.size());
        } else if (!started_) {
            std::fprintf(out_, "prism: %s: %s, going on\n", what_.c_str(), state.c_str());
        }
        started_ = true;
        std::fflush(out_);
    }

    /// The work ended in `state` after `seconds`: its last line, if it was reported at all
    /// (a second or more); with `always`, also when it was quick.
    void finish(double seconds, const std::string& state, bool always = false)
    {
        if (!started_ && !(always || seconds > 1.0)) return;
        if (terminal_) {
            const std::string pad(width_ > state.size() ? width_ - state.size() : 0, ' ');
            std::fprintf(out_, "%sprism: %s %s%s\n", started_ ? "\r" : "", what_.c_str(), state.c_str(), pad.c_str());
        } else {
            std::fprintf(out_, "prism: %s: %s\n", what_.c_str(), state.c_str());
        }
        std::fflush(out_);
        started_ = false;
        width_ = 0;
    }

    /// Whether a state has been shown since the start or the last finish.
    [[nodiscard]] bool started() const noexcept { return started_; }

private:
    std::FILE* out_;
    bool terminal_;
    std::string what_;
    bool started_ = false;
    std::size_t width_ = 0; // the longest state shown on the terminal's line
};

} // namespace prism::detail
