// SPDX-License-Identifier: MIT
// What the fuzz targets share: a reader that turns the fuzzer's bytes into the numbers a
// hostile caller would pass (exact zeros, denormals, huge and tiny magnitudes, far
// origins, axis-aligned and grazing directions), and a check that aborts, so that
// libFuzzer (and the corpus driver in the test suite) report the input that broke it.
#pragma once

// The headers each target needs, not prism/prism.hpp: clang 14 (Debian's) cannot yet
// compile a lambda that captures a structured binding, which two integrators do.
#include <prism/accel/kd_tree.hpp>
#include <prism/csg/difference.hpp>
#include <prism/csg/intersection.hpp>
#include <prism/csg/union.hpp>
#include <prism/geometry/box.hpp>
#include <prism/geometry/quadric.hpp>
#include <prism/geometry/sphere.hpp>
#include <prism/geometry/transformed.hpp>
#include <prism/photon/photon_map.hpp>

#include "check.hpp"

#include <bit>
#include <cmath>
#include <limits>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace fuzz {

/// Bytes read in order; past the end, zeros.
class Input {
public:
    Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    std::uint32_t word()
    {
        std::uint32_t w = 0;
        for (int i = 0; i < 4; ++i) w = w << 8 | byte();
        return w;
    }
    /// An integer in [lo, hi].
    int integer(int lo, int hi) { return lo + int(word() % std::uint32_t(hi - lo + 1)); }
    /// A finite float: one of the awkward values, or sign x mantissa x 10^e with e in
    /// [-max_exponent, max_exponent], or a raw bit pattern where that is finite.
    float number(int max_exponent = 6)
    {
        switch (byte() % 8) {
        case 0: return 0.0f;
        case 1: return byte() % 2 ? -1.0f : 1.0f;
        case 2: return std::numeric_limits<float>::denorm_min() * float(1 + byte());
        case 3: {
            const float raw = std::bit_cast<float>(word());
            return std::isfinite(raw) && std::abs(raw) < std::pow(10.0f, float(max_exponent)) ? raw : 0.5f;
        }
        default: {
            const float mantissa = float(word() % 2000001) / 1000000.0f - 1.0f;
            return mantissa * std::pow(10.0f, float(integer(-max_exponent, max_exponent)));
        }
        }
    }
    prism::Vec3<float> vector(int max_exponent = 6) { return {number(max_exponent), number(max_exponent), number(max_exponent)}; }
    /// A direction: axis-aligned, nearly so (a denormal or tiny component), or any.
    prism::Vec3<float> direction()
    {
        prism::Vec3<float> d = vector(3);
        if (byte() % 4 == 0) d[integer(0, 2)] = 1.0f;
        if (prism::length_squared(d) == 0.0f) d = {0.0f, 0.0f, 1.0f};
        return d;
    }
    [[nodiscard]] bool done() const { return at_ >= size_; }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

template <class V>
bool finite(const V& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The checks every list of crossings passes: at most its capacity, t strictly inside
/// the range and rising, every field finite, the normal of unit length.
template <class C>
void check_crossings(const C& crossings, prism::Interval<float> range)
{
    FUZZ_CHECK(crossings.size() <= C::capacity);
    float previous = range.min;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        const auto& c = crossings[i];
        FUZZ_CHECK(std::isfinite(c.t));
        FUZZ_CHECK(c.t > range.min && c.t < range.max);
        FUZZ_CHECK(c.t >= previous);
        previous = c.t;
        FUZZ_CHECK(finite(c.point) && finite(c.error) && finite(c.normal));
        FUZZ_CHECK(std::abs(prism::length(c.normal) - 1.0f) < 1e-3f);
    }
}

} // namespace fuzz
