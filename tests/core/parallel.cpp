// SPDX-License-Identifier: MIT
#include <prism/core/parallel.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

TEST_CASE("parallel_blocks: every block once, on a worker numbered below workers_for, for any thread count")
{
    for (const unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
        for (const std::size_t blocks : {std::size_t(0), std::size_t(1), std::size_t(5), std::size_t(1000)}) {
            CAPTURE(threads);
            CAPTURE(blocks);
            const unsigned workers = prism::detail::workers_for(blocks, threads);
            CHECK(workers >= 1);
            CHECK(workers <= std::max<std::size_t>(blocks, 1));
            std::vector<std::atomic<int>> seen(blocks);
            std::atomic<bool> bad_worker{false};
            prism::detail::parallel_blocks(blocks, threads, [&](std::size_t b, unsigned worker) {
                ++seen[b];
                if (worker >= workers) bad_worker = true;
            });
            CHECK(!bad_worker);
            for (const auto& count : seen) CHECK(count == 1);
        }
    }
}

TEST_CASE("parallel_blocks with an observer: the calling thread watches, seeing the blocks done rise, and every block is still done once")
{
    constexpr std::size_t blocks = 40;
    std::vector<std::atomic<int>> seen(blocks);
    std::vector<std::size_t> reports;
    const auto caller = std::this_thread::get_id();
    std::atomic<bool> worked_on_caller{false};
    prism::detail::parallel_blocks(
        blocks, 2,
        [&](std::size_t b, unsigned) {
            if (std::this_thread::get_id() == caller) worked_on_caller = true;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            ++seen[b];
        },
        [&](std::size_t done) { reports.push_back(done); }, std::chrono::milliseconds(10));
    CHECK(!worked_on_caller);
    for (const auto& count : seen) CHECK(count == 1);
    REQUIRE(!reports.empty()); // 40 blocks of 5 ms on 2 workers: about 100 ms, ten reports
    for (std::size_t i = 1; i < reports.size(); ++i) CHECK(reports[i] >= reports[i - 1]);
    CHECK(reports.back() <= blocks);
}

TEST_CASE("parallel_for: f(i) once for every i, for chunk sizes that do and do not divide the count")
{
    for (const std::size_t chunk : {std::size_t(1), std::size_t(7), std::size_t(256)}) {
        std::vector<std::atomic<int>> seen(1001);
        prism::detail::parallel_for(seen.size(), 3, [&](std::size_t i) { ++seen[i]; }, chunk);
        for (const auto& count : seen) CHECK(count == 1);
    }
}
