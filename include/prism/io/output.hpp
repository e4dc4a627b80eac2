// SPDX-License-Identifier: MIT
// Writing files: whole or not at all. A regular file's bytes go to a temporary file beside
// it, renamed over it only once complete; a device or FIFO is written through, never
// replaced. An OutputSet writes several files together, so that a run that fails leaves
// none of them half done: every target is checked, every regular one staged, every device
// written, and only then is every staged file renamed into place. Any failure throws
// std::runtime_error naming the path and the reason. A program stopped by a signal while
// it writes leaves its temporary files behind unless it asked remove_partial_files_on_signal()
// to remove them.
#pragma once

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

namespace prism {

namespace detail {

[[noreturn]] inline void throw_io(const std::filesystem::path& path, const std::string& reason)
{
    throw std::runtime_error("prism: cannot write '" + path.string() + "': " + reason);
}

/// Write every byte and close the file: 0, or the errno of what failed first.
[[nodiscard]] inline int write_and_close(std::FILE* file, std::span<const unsigned char> bytes) noexcept
{
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written) return write_errno != 0 ? write_errno : EIO;
    return closed ? 0 : (errno != 0 ? errno : EIO);
}

/// Where `path` leads: the file a symbolic link names (the link stays), and whether it is
/// a regular file or nothing yet (else a device or FIFO, written through). A directory is
/// refused.
inline std::pair<std::filesystem::path, bool> output_target(const std::filesystem::path& path)
{
    namespace fs = std::filesystem;
    std::error_code error;
    fs::path target = path;
    if (fs::is_symlink(fs::symlink_status(path, error))) {
        target = fs::weakly_canonical(path, error);
        if (error) throw_io(path, "cannot follow the symbolic link: " + error.message());
    }
    const fs::file_status status = fs::status(target, error);
    if (status.type() == fs::file_type::directory) throw_io(path, "it is a directory");
    return {target, status.type() == fs::file_type::regular || status.type() == fs::file_type::not_found};
}

/// The temporary files being written now, for a signal handler to remove: fixed slots of
/// fixed size, claimed and freed through atomics, so that the handler reads no memory
/// being changed and calls nothing but unlink (async-signal-safe). A path that does not
/// fit, or finds no free slot, goes unlisted.
class PartialFiles {
public:
    static constexpr std::size_t slots = 64, longest = 4095;

    /// List `path` (a temporary file just created).
    void add(const std::filesystem::path& path) noexcept
    {
        const std::string& text = path.native();
        if (text.size() > longest) return;
        for (std::size_t i = 0; i < slots; ++i) {
            bool unclaimed = false;
            if (!claimed_[i].compare_exchange_strong(unclaimed, true)) continue;
            text.copy(paths_[i].data(), text.size());
            paths_[i][text.size()] = '\0';
            listed_[i].store(true); // (after the path: the handler reads only listed slots)
            return;
        }
    }

    /// Unlist `path` (renamed into place, or removed).
    void drop(const std::filesystem::path& path) noexcept
    {
        for (std::size_t i = 0; i < slots; ++i)
            if (listed_[i].load() && path.native() == paths_[i].data()) {
                listed_[i].store(false);
                claimed_[i].store(false);
                return;
            }
    }

    /// Remove every listed file (from a signal handler).
    void remove_all() noexcept
    {
        for (std::size_t i = 0; i < slots; ++i)
            if (listed_[i].load()) {
#if __has_include(<unistd.h>)
                ::unlink(paths_[i].data());
#else
                std::remove(paths_[i].data());
#endif
            }
    }

private:
    std::array<std::atomic<bool>, slots> claimed_{}, listed_{};
    std::array<std::array<char, longest + 1>, slots> paths_{};
};

/// The process's list of temporary files (built before any signal handler can read it:
/// remove_partial_files_on_signal() builds it).
inline PartialFiles& partial_files() noexcept
{
    static PartialFiles files;
    return files;
}

/// Remove a staged temporary file, and unlist it.
inline void discard_staged(const std::filesystem::path& temporary) noexcept
{
    std::remove(temporary.c_str());
    partial_files().drop(temporary);
}

/// Bytes written to a new temporary file beside `target` (created exclusively, never
/// through an existing name); its path, listed in partial_files() until the caller drops
/// it. `path` names the target in messages.
inline std::filesystem::path stage_file(const std::filesystem::path& path, const std::filesystem::path& target, std::span<const unsigned char> bytes)
{
    static std::atomic<unsigned> serial{0};
    std::filesystem::path temporary;
    std::FILE* file = nullptr;
    for (int attempt = 0; attempt < 100 && file == nullptr; ++attempt) {
        temporary = target;
        temporary += ".prism-partial-" + std::to_string(serial++) + "-" + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) % 100000);
        file = std::fopen(temporary.c_str(), "wbx"); // "x": only a file that did not exist
        if (file == nullptr && errno != EEXIST) throw_io(path, std::strerror(errno));
    }
    if (file == nullptr) throw_io(path, "no free temporary name beside it");
    partial_files().add(temporary);
    if (const int failure = write_and_close(file, bytes)) {
        discard_staged(temporary);
        throw_io(path, std::strerror(failure));
    }
    return temporary;
}

/// Write bytes through to a device or FIFO.
inline void write_through(const std::filesystem::path& path, const std::filesystem::path& target, std::span<const unsigned char> bytes)
{
    std::FILE* file = std::fopen(target.c_str(), "wb");
    if (file == nullptr) throw_io(path, std::strerror(errno));
    if (const int failure = write_and_close(file, bytes)) throw_io(path, std::strerror(failure));
}

/// Write bytes to path: whole or not at all where the path is a regular file (or
/// nothing yet). Bytes go to a new temporary file beside it (created exclusively, never
/// through an existing name), which is renamed over the target only once complete. A
/// symbolic link is followed to what it names, so the link stays. Anything that is not
/// a regular file (a device such as /dev/null, a FIFO) is written through, never
/// replaced: renaming over it would turn it into a plain file.
inline void write_file_atomically(const std::filesystem::path& path, std::span<const unsigned char> bytes)
{
    const auto [target, regular] = output_target(path);
    if (!regular) return write_through(path, target, bytes);
    const std::filesystem::path temporary = stage_file(path, target, bytes);
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    partial_files().drop(temporary);
    if (error) {
        std::remove(temporary.c_str());
        throw_io(path, error.message());
    }
}

} // namespace detail

/// Remove the temporary files being written when SIGINT, SIGTERM or SIGHUP stops the
/// program, then stop it as the signal would have (its default action, raised again).
/// For a program (the examples call it first); a library does not take signals on its own.
inline void remove_partial_files_on_signal()
{
    (void)detail::partial_files(); // built now, not first inside a handler
    for (const int number : {SIGINT, SIGTERM, SIGHUP})
        std::signal(number, [](int caught) {
            detail::partial_files().remove_all();
            std::signal(caught, SIG_DFL);
            std::raise(caught);
        });
}

/// Files written together, all or none: add() collects each file's bytes; commit() checks
/// every target (a directory is refused), writes every regular one to a temporary file
/// beside it and writes through every device or FIFO, and only when all of that succeeded
/// renames the temporaries into place. A failure before the renames leaves no file
/// changed but the devices already written (written last, after the staging), and throws.
class OutputSet {
public:
    /// Add a file to write: `bytes` to `path` (a later add of the same path replaces it).
    void add(std::filesystem::path path, std::vector<unsigned char> bytes)
    {
        for (auto& [p, b] : files_)
            if (p == path) {
                b = std::move(bytes);
                return;
            }
        files_.emplace_back(std::move(path), std::move(bytes));
    }

    /// The files added and not yet written.
    [[nodiscard]] std::size_t size() const noexcept { return files_.size(); }

    /// Write every file added, all or none (see the class); then forget them.
    void commit()
    {
        struct Staged {
            std::filesystem::path path, target, temporary;
        };
        std::vector<std::pair<std::size_t, std::filesystem::path>> devices;
        std::vector<Staged> staged;
        const auto discard = [&] {
            for (const Staged& s : staged) detail::discard_staged(s.temporary);
        };
        try {
            std::vector<std::pair<std::filesystem::path, bool>> targets;
            for (const auto& [path, bytes] : files_) targets.push_back(detail::output_target(path));
            for (std::size_t i = 0; i < files_.size(); ++i)
                if (targets[i].second) staged.push_back({files_[i].first, targets[i].first, detail::stage_file(files_[i].first, targets[i].first, files_[i].second)});
                else devices.emplace_back(i, targets[i].first);
            for (const auto& [i, target] : devices) detail::write_through(files_[i].first, target, files_[i].second);
        } catch (...) {
            discard();
            throw;
        }
        for (std::size_t k = 0; k < staged.size(); ++k) {
            std::error_code error;
            std::filesystem::rename(staged[k].temporary, staged[k].target, error);
            detail::partial_files().drop(staged[k].temporary);
            if (error) {
                for (std::size_t j = k; j < staged.size(); ++j) detail::discard_staged(staged[j].temporary);
                detail::throw_io(staged[k].path, error.message());
            }
        }
        files_.clear();
    }

private:
    std::vector<std::pair<std::filesystem::path, std::vector<unsigned char>>> files_;
};

} // namespace prism
