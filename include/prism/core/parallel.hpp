// SPDX-License-Identifier: MIT
// The one way prism runs work on threads: blocks of work dealt to workers as they ask
// (render tiles, photon shares, light-tracer paths, irradiance records). Each block
// writes only what belongs to it, or to its worker's own buffer, so the result is the
// same for any thread count; progress is an observer's, on the calling thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace prism::detail {

/// The threads to use for `requested` (0 = all hardware threads).
[[nodiscard]] inline unsigned worker_count(unsigned requested) noexcept
{
    return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

/// The workers parallel_blocks runs for `blocks` blocks on `threads` (0 = all hardware
/// threads): never more than there are blocks, at least one.
[[nodiscard]] inline unsigned workers_for(std::size_t blocks, unsigned threads) noexcept
{
    return unsigned(std::clamp<std::size_t>(worker_count(threads), 1, std::max<std::size_t>(blocks, 1)));
}

/// No observer: the calling thread works as worker 0.
struct Unwatched {};

/// work(block, worker) for every block in [0, blocks), each taken by the next worker to
/// ask; worker in [0, workers_for(blocks, threads)), so a caller may keep a buffer per
/// worker. With an observer, the calling thread leaves the work to the workers and calls
/// watch(blocks_done) every `every` until they finish (a progress report); without one,
/// it works beside them.
template <class Work, class Watch = Unwatched>
void parallel_blocks(std::size_t blocks, unsigned threads, Work&& work, Watch&& watch = {},
                     std::chrono::milliseconds every = std::chrono::milliseconds(250))
{
    constexpr bool watched = !std::is_same_v<std::remove_cvref_t<Watch>, Unwatched>;
    const unsigned workers = workers_for(blocks, threads);
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex mutex;
    std::condition_variable finished;
    unsigned running = workers;
    const auto run = [&](unsigned worker) {
        for (std::size_t b = next++; b < blocks; b = next++) {
            work(b, worker);
            if constexpr (watched) ++done;
        }
        if constexpr (watched) {
            const std::lock_guard lock(mutex);
            if (--running == 0) finished.notify_all();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers);
    for (unsigned w = watched ? 0 : 1; w < workers; ++w) pool.emplace_back(run, w);
    if constexpr (watched) {
        std::unique_lock lock(mutex);
        while (!finished.wait_for(lock, every, [&] { return running == 0; })) watch(done.load());
    } else {
        run(0);
    }
    for (auto& thread : pool) thread.join();
}

/// f(i) for every i in [0, count), in chunks of `chunk` taken by up to `threads` threads
/// (0 = all hardware threads); f must write only what belongs to i.
template <class F>
void parallel_for(std::size_t count, unsigned threads, F&& f, std::size_t chunk = 256)
{
    parallel_blocks((count + chunk - 1) / chunk, threads, [&](std::size_t c, unsigned) {
        for (std::size_t i = c * chunk, end = std::min(count, (c + 1) * chunk); i < end; ++i) f(i);
    });
}

} // namespace prism::detail
