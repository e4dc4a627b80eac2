// SPDX-License-Identifier: MIT
// Fuzz target: a quadric of any ten coefficients (degenerate, near-degenerate, huge,
// tiny), and a Transformed one, crossed by hostile rays: the crossings are finite, in
// the range and in order, the first crossing is the first of the list, and a ray that
// starts inside says so.
#include "fuzz.hpp"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::Input in(data, size);
    using prism::Quadric;
    std::array<float, 10> k{};
    for (float& c : k) c = in.number(4);
    try {
        const Quadric<float> q = Quadric<float>::from_povray(k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8], k[9]);
        const prism::Transformed<Quadric<float>> moved(
            q, prism::Transform<float>::rotate(in.number(2), in.direction()).then(prism::Transform<float>::translate(in.vector(4))));
        while (!in.done()) {
            const prism::Ray<float> ray{in.vector(6), in.direction()};
            const float far = in.byte() % 2 ? prism::infinity<float> : std::abs(in.number(6)) + 1.0f;
            const prism::Interval<float> range{0.0f, far};
            const auto c = q.crossings(ray, range);
            fuzz::check_crossings(c, range);
            const float first = prism::first_crossing(q, ray, range);
            if (c.empty()) FUZZ_CHECK(!(first < prism::infinity<float>));
            else FUZZ_CHECK(first == c[0].t);
            fuzz::check_crossings(moved.crossings(ray, range), range);
        }
    } catch (const std::invalid_argument&) {
        // refused by name: what a hostile caller should get
    }
    return 0;
}
