// SPDX-License-Identifier: MIT
// Threads for the loops whose every iteration writes its own place: the result is the
// same for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace prism::detail {

/// The threads to use for `requested` (0 = all hardware threads).
[[nodiscard]] inline unsigned worker_count(unsigned requested) noexcept
{
    return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

/// f(i) for every i in [0, count), in chunks of `chunk` taken by up to `threads` threads
/// (0 = all hardware threads); f must write only what belongs to i.
template <class F>
void parallel_for(std::size_t count, unsigned threads, F&& f, std::size_t chunk = 256)
{
    const std::size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t c = next++; c < chunks; c = next++)
            for (std::size_t i = c * chunk, end = std::min(count, (c + 1) * chunk); i < end; ++i) f(i);
    };
    const auto workers_wanted = std::min<std::size_t>(worker_count(threads), std::max<std::size_t>(chunks, 1));
    std::vector<std::thread> workers;
    for (std::size_t i = 1; i < workers_wanted; ++i) workers.emplace_back(work);
    work();
    for (auto& worker : workers) worker.join();
}

} // namespace prism::detail
