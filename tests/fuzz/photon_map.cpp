// SPDX-License-Identifier: MIT
// Fuzz target: point sets of any shape (duplicates, flat, far apart, tiny) in the
// KD-tree, against brute force (the same k nearest, in the same order, within any
// radius); and photon maps of such photons, whose estimates are never NaN nor
// negative for any k, radius and filter.
#include "fuzz.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::Input in(data, size);
    using namespace prism;
    using Point = std::array<float, 3>;
    const int n = in.integer(0, 300);
    std::vector<Point> points;
    std::vector<Photon> photons;
    for (int i = 0; i < n; ++i) {
        // Repeats and shared coordinates are the hard cases: draw from what came before.
        Point p{in.number(5), in.number(5), in.number(5)};
        if (!points.empty() && in.byte() % 3 == 0) p[std::size_t(in.integer(0, 2))] = points[std::size_t(in.integer(0, int(points.size()) - 1))][0];
        points.push_back(p);
        photons.emplace_back(Vec3<float>(p[0], p[1], p[2]), Rgb<float>(std::abs(in.number(3)), std::abs(in.number(3)), std::abs(in.number(3))),
                             normalize(in.direction()), normalize(in.direction()), std::uint8_t(in.byte() & 7));
    }
    const KdTree<ArrayPoints<float, 3>> tree(ArrayPoints<float, 3>{points}, unsigned(in.integer(1, 2)));
    const PhotonMap map(photons, 1);
    while (!in.done()) {
        const Point q{in.number(5), in.number(5), in.number(5)};
        const std::size_t k = std::size_t(in.integer(1, 16));
        const float radius = in.byte() % 2 ? infinity<float> : std::abs(in.number(5));
        // Brute force: every point's (distance^2, index), sorted; the first k within radius.
        std::vector<Neighbour<float>> all;
        for (std::size_t i = 0; i < points.size(); ++i) all.push_back({KdTree<ArrayPoints<float, 3>>::distance2(q, points[i]), std::uint32_t(i)});
        std::sort(all.begin(), all.end());
        std::size_t expected = 0;
        while (expected < all.size() && expected < k && all[expected].distance2 <= radius * radius) ++expected;
        const auto got = tree.nearest<16>(q, k, radius);
        FUZZ_CHECK(got.size() == expected);
        for (std::size_t i = 0; i < expected; ++i) FUZZ_CHECK(got[i] == all[i]);
        // The photon map's estimate: finite, not negative.
        try {
            const Estimator e{.k = in.byte() % 2 ? k : 0, .radius = std::isfinite(radius) && radius > 0.0f ? radius : 1.0f,
                              .filter = Filter(in.integer(0, 2))};
            const Rgb<float> irradiance = map.irradiance({q[0], q[1], q[2]}, normalize(in.direction()), e);
            // (+inf only where the density itself passes float's range: photons of 10^3 W
            // within 10^-19 of each other.)
            FUZZ_CHECK(irradiance.x >= 0.0f && irradiance.y >= 0.0f && irradiance.z >= 0.0f);
        } catch (const std::invalid_argument&) {
            // an estimator refused by name
        }
    }
    return 0;
}
