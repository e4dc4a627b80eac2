// SPDX-License-Identifier: MIT
// Fuzz target: a CSG tree of every operator over spheres, boxes and quadrics (one of
// them transformed) from the fuzzer's numbers, crossed by hostile rays: the crossings
// are finite, in the range and in order, and they alternate between entering and
// leaving from the side the ray starts on.
#include "fuzz.hpp"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::Input in(data, size);
    using namespace prism;
    try {
        const Sphere<float> ball(in.vector(3), std::abs(in.number(3)));
        const Vec3<float> a = in.vector(3), b = in.vector(3);
        const Box<float> box(min(a, b), max(a, b));
        std::array<float, 10> k{};
        for (float& c : k) c = in.number(3);
        const Quadric<float> q = Quadric<float>::from_povray(k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8], k[9]);
        const Transformed<Quadric<float>> turned(Quadric<float>::cylinder(in.vector(2), in.direction(), std::abs(in.number(2))),
                                                 Transform<float>::rotate(in.number(2), in.direction()));
        const auto tree = difference_of(intersection_of(ball, q), union_of(box, turned));
        const auto other = union_of(difference_of(box, ball), intersection_of(turned, q), ball);
        while (!in.done()) {
            const Ray<float> ray{in.vector(5), in.direction()};
            const Interval<float> range{0.0f, in.byte() % 2 ? infinity<float> : std::abs(in.number(5)) + 1.0f};
            const auto check = [&](const auto& c) {
                fuzz::check_crossings(c, range);
                bool inside = c.inside_at_start;
                for (std::size_t i = 0; i < c.size(); ++i) {
                    FUZZ_CHECK(c[i].entering == !inside);
                    inside = !inside;
                }
            };
            check(tree.crossings(ray, range));
            check(other.crossings(ray, range));
        }
    } catch (const std::invalid_argument&) {
        // refused by name
    }
    return 0;
}
