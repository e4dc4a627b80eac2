// SPDX-License-Identifier: MIT
// Accumulation: a render's samples summed exactly per pixel over a window of the image,
// so that a render split by pixels (crop windows), by passes, over threads or over
// machines adds up to the same bits as the render made in one piece.
//
// Floating-point addition is not associative: (a + b) + c and a + (b + c) can differ in
// the last bit, and far more when a and c differ by many orders of magnitude, so sums
// made in parts and added in another order would not reproduce the whole. Here each
// sample is rounded once, to the nearest multiple of 2^-64, and summed as a 128-bit
// integer (ExactSum, core/int128.hpp), whose addition is exact, associative and commutative. That one
// rounding depends on the sample alone; it keeps every float sample in [2^-41, 2^40)
// (4.5e-13 to 1.1e12) exactly and moves any other by at most 2^-65 (2.7e-20).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/int128.hpp>
#include <prism/core/math.hpp>
#include <prism/render/film.hpp>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace prism {

/// A rectangle of an image's pixels, [x0, x1) x [y0, y1); pbrt's pixel bounds.
struct PixelWindow {
    int x0 = 0; ///< the first column
    int y0 = 0; ///< the first row (rows count from the top)
    int x1 = 0; ///< one past the last column
    int y1 = 0; ///< one past the last row

    /// The window's width in pixels.
    [[nodiscard]] constexpr int width() const noexcept { return x1 - x0; }
    /// The window's height in pixels.
    [[nodiscard]] constexpr int height() const noexcept { return y1 - y0; }
    /// Whether the window holds no pixel.
    [[nodiscard]] constexpr bool empty() const noexcept { return x1 <= x0 || y1 <= y0; }
    /// The number of pixels in the window.
    [[nodiscard]] constexpr std::size_t area() const noexcept { return empty() ? 0 : std::size_t(width()) * std::size_t(height()); }
    /// Whether pixel (x, y) is in the window.
    [[nodiscard]] constexpr bool contains(int x, int y) const noexcept { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    /// Whether all of `w` is in the window.
    [[nodiscard]] constexpr bool contains(const PixelWindow& w) const noexcept
    {
        return w.x0 >= x0 && w.x1 <= x1 && w.y0 >= y0 && w.y1 <= y1;
    }
    /// Whether the windows share a pixel.
    [[nodiscard]] constexpr bool overlaps(const PixelWindow& w) const noexcept
    {
        return w.x0 < x1 && x0 < w.x1 && w.y0 < y1 && y0 < w.y1;
    }
    /// The whole of a width x height image.
    [[nodiscard]] static constexpr PixelWindow whole(int width, int height) noexcept { return {0, 0, width, height}; }
    /// Windows are equal when their bounds are.
    friend constexpr bool operator==(const PixelWindow&, const PixelWindow&) = default;
};

/// A range of passes [first, last): camera samples of each pixel, or photon passes.
struct PassRange {
    std::uint64_t first = 0; ///< the first pass
    std::uint64_t last = 0;  ///< one past the last pass

    /// The number of passes in the range.
    [[nodiscard]] constexpr std::uint64_t count() const noexcept { return last > first ? last - first : 0; }
    /// Whether the range holds no pass.
    [[nodiscard]] constexpr bool empty() const noexcept { return last <= first; }
    /// Whether the ranges share a pass.
    [[nodiscard]] constexpr bool overlaps(const PassRange& r) const noexcept { return r.first < last && first < r.last; }
    /// Ranges are equal when their bounds are.
    friend constexpr bool operator==(const PassRange&, const PassRange&) = default;
};

/// A signed fixed-point number with 64 integer and 64 fraction bits: samples rounded
/// once to a multiple of 2^-64 and summed with no further rounding. `Integer` is one of
/// core/int128.hpp's 128-bit integers (their bits are the same); ExactSum takes Int128.
template <class Integer>
class BasicExactSum {
public:
    /// Samples are refused from this magnitude on (the render counts them as rejected,
    /// as it does NaN): 2^23 such samples could not overflow the 64 integer bits.
    static constexpr double limit = 0x1p40;

    constexpr BasicExactSum() noexcept = default;

    /// x rounded to the nearest multiple of 2^-64 (halves away from zero), which is
    /// round(ldexp(x, 64)) as an integer. |x| < limit.
    [[nodiscard]] static constexpr BasicExactSum of(double x) noexcept
    {
        PRISM_ASSERT(x > -limit && x < limit);
        // From x's bits, in integers: |x| = m 2^(e - 1075) (e the biased exponent, m
        // with its leading one, or a denormal's m at e = 1), so |x| 2^64 = m 2^s. (The
        // library's ldexp, round and double-to-integer conversion are calls, one a
        // sample and channel: 5 % of a Whitted render of the Cornell box.)
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const auto biased = int((bits >> 52) & 0x7ff);
        const std::uint64_t fraction = bits & ((std::uint64_t(1) << 52) - 1);
        const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t(1) << 52);
        const int s = (biased == 0 ? 1 : biased) - 1075 + 64; // below 40 + 12 (|x| < 2^40)
        // The two 64-bit halves, each by one shift (a shift of the whole 128 bits by a
        // variable count is a branch or a select more, and this is done for every
        // sample and channel).
        std::uint64_t high = 0, low = 0;
        if (s >= 0) {
            low = m << s;
            high = (m >> 1) >> (63 - s); // m >> (64 - s), and 0 for s = 0
        } else if (s > -54) {
            low = (m + (std::uint64_t(1) << (-s - 1))) >> -s; // half up: away from zero
        } // (s <= -54: m 2^s < 2^53 2^-54, nearer 0.)
        const Integer value = Integer::from_words(low, high);
        return from_bits((bits >> 63) != 0 ? -value : value);
    }

    /// Whether x is a sample this type takes: finite and |x| < limit.
    [[nodiscard]] static constexpr bool takes(double x) noexcept { return x > -limit && x < limit; }

    /// The sum whose value is bits 2^-64.
    [[nodiscard]] static constexpr BasicExactSum from_bits(Integer bits) noexcept
    {
        BasicExactSum s;
        s.bits_ = bits;
        return s;
    }
    /// The sum in units of 2^-64.
    [[nodiscard]] constexpr Integer bits() const noexcept { return bits_; }

    /// Add `other`; false (and this unchanged) when the sum would pass 2^63 in magnitude.
    [[nodiscard]] constexpr bool add(const BasicExactSum& other) noexcept { return bits_.add(other.bits_); }

    /// The sum, rounded once to double.
    [[nodiscard]] double value() const noexcept { return bits_.to_double() * 0x1p-64; } // exact scaling: the double is 0 or at least 1

    /// Sums are equal when their bits are.
    friend constexpr bool operator==(const BasicExactSum&, const BasicExactSum&) = default;

private:
    Integer bits_{};
};

/// The exact sum every film, render and file of prism uses.
using ExactSum = BasicExactSum<Int128>;

namespace detail {

/// The mean a sum of `weight` samples stands for, as the film stores it: the one place
/// an Accumulation becomes a float, so every way of making the same sums gives the same
/// bits.
[[nodiscard]] inline float mean(const ExactSum& sum, std::uint64_t weight) noexcept
{
    return weight == 0 ? 0.0f : static_cast<float>(sum.value() / static_cast<double>(weight));
}

} // namespace detail

/// Exact per-pixel sums of named channels ("R", "G", "B" first) and the per-pixel
/// weight (samples or passes summed) over a window of a width x height image. Threads
/// may add to distinct pixels at once.
class Accumulation {
public:
    /// Zeroed sums over `window` of a width x height image, for `channels` (R, G, B first); throws std::invalid_argument, naming the value, for a bad size, window or channel list, and a clear error when the memory cannot be had.
    Accumulation(int width, int height, PixelWindow window, std::vector<std::string> channels = {"R", "G", "B"})
        : width_(width), height_(height), window_(window), channels_(std::move(channels))
    {
        if (width <= 0 || height <= 0) detail::throw_invalid("Accumulation size must be positive, got ", width, " x ", height);
        if (window.empty() || !PixelWindow::whole(width, height).contains(window))
            detail::throw_invalid("Accumulation window [", window.x0, ", ", window.x1, ") x [", window.y0, ", ", window.y1,
                                  ") must be a non-empty part of the ", width, " x ", height, " image");
        if (channels_.size() < 3 || channels_[0] != "R" || channels_[1] != "G" || channels_[2] != "B")
            detail::throw_invalid("Accumulation channels must begin with R, G, B");
        const std::size_t pixels = window.area();
        const double bytes = double(pixels) * double(channels_.size() * sizeof(ExactSum) + sizeof(std::uint64_t));
        const std::string what = "an Accumulation of " + std::to_string(window.width()) + " x " + std::to_string(window.height()) + " pixels";
        detail::require_memory(what, bytes);
        try {
            sums_.assign(pixels * channels_.size(), ExactSum{});
            weights_.assign(pixels, 0);
        } catch (const std::bad_alloc&) {
            throw allocation_error("prism: " + what + " needs " + detail::describe_bytes(bytes) + ", which could not be allocated");
        }
    }

    /// A copy of the sums and the flags.
    Accumulation(const Accumulation& other)
        : width_(other.width_), height_(other.height_), window_(other.window_), channels_(other.channels_), sums_(other.sums_),
          weights_(other.weights_), rejected_(other.rejected()), overflowed_(other.overflowed())
    {
    }
    /// Takes the sums over.
    Accumulation(Accumulation&& other) noexcept
        : width_(other.width_), height_(other.height_), window_(other.window_), channels_(std::move(other.channels_)),
          sums_(std::move(other.sums_)), weights_(std::move(other.weights_)), rejected_(other.rejected()), overflowed_(other.overflowed())
    {
    }
    /// Copy or move assignment.
    Accumulation& operator=(Accumulation other) noexcept
    {
        width_ = other.width_;
        height_ = other.height_;
        window_ = other.window_;
        channels_ = std::move(other.channels_);
        sums_ = std::move(other.sums_);
        weights_ = std::move(other.weights_);
        rejected_.store(other.rejected(), std::memory_order_relaxed);
        overflowed_.store(other.overflowed(), std::memory_order_relaxed);
        return *this;
    }

    /// The image's width (the whole image, not the window).
    [[nodiscard]] int width() const noexcept { return width_; }
    /// The image's height (the whole image, not the window).
    [[nodiscard]] int height() const noexcept { return height_; }
    /// The pixels summed here.
    [[nodiscard]] const PixelWindow& window() const noexcept { return window_; }
    /// The channels' names, R, G, B first.
    [[nodiscard]] const std::vector<std::string>& channels() const noexcept { return channels_; }

    /// Pixel (x, y)'s sums, one per channel; (x, y) in image coordinates, inside the window.
    [[nodiscard]] std::span<const ExactSum> sums(int x, int y) const noexcept
    {
        return {sums_.data() + index(x, y) * channels_.size(), channels_.size()};
    }
    /// Pixel (x, y)'s weight: the samples or passes its sums hold.
    [[nodiscard]] std::uint64_t weight(int x, int y) const noexcept { return weights_[index(x, y)]; }

    /// Add sums (one per channel) and a weight to pixel (x, y). A sum that would
    /// overflow is left out and flagged (overflowed()).
    void add(int x, int y, std::span<const ExactSum> sums, std::uint64_t weight) noexcept
    {
        PRISM_ASSERT(sums.size() == channels_.size());
        const std::size_t i = index(x, y);
        for (std::size_t c = 0; c < sums.size(); ++c)
            if (!sums_[i * channels_.size() + c].add(sums[c])) overflowed_.store(true, std::memory_order_relaxed);
        if (weight > std::numeric_limits<std::uint64_t>::max() - weights_[i])
            overflowed_.store(true, std::memory_order_relaxed);
        else
            weights_[i] += weight;
    }

    /// Count sample values left out for not being finite (or negative, or past
    /// ExactSum::limit) where the channel allows no such value.
    void reject(std::size_t count) noexcept { rejected_.fetch_add(count, std::memory_order_relaxed); }
    /// How many sample values were left out (reject()).
    [[nodiscard]] std::size_t rejected() const noexcept { return rejected_.load(std::memory_order_relaxed); }
    /// Whether some sum or weight would have overflowed (and was left out): the sums
    /// are then wrong, and image() refuses them.
    [[nodiscard]] bool overflowed() const noexcept { return overflowed_.load(std::memory_order_relaxed); }

    /// Add a part of the same image: its window inside this one, the same channels.
    Accumulation& operator+=(const Accumulation& part)
    {
        if (part.width_ != width_ || part.height_ != height_)
            detail::throw_invalid("Accumulation of a ", part.width_, " x ", part.height_, " image added to one of ", width_, " x ", height_);
        if (part.channels_ != channels_) detail::throw_invalid("Accumulation added to one with other channels");
        if (!window_.contains(part.window_))
            detail::throw_invalid("Accumulation window [", part.window_.x0, ", ", part.window_.x1, ") x [", part.window_.y0, ", ", part.window_.y1,
                                  ") added to one of [", window_.x0, ", ", window_.x1, ") x [", window_.y0, ", ", window_.y1, ")");
        for (int y = part.window_.y0; y < part.window_.y1; ++y)
            for (int x = part.window_.x0; x < part.window_.x1; ++x) add(x, y, part.sums(x, y), part.weight(x, y));
        reject(part.rejected());
        if (part.overflowed()) overflowed_.store(true, std::memory_order_relaxed);
        return *this;
    }

    /// The mean of channels first, first + 1, first + 2 over the window, per pixel:
    /// sum / weight, 0 where the weight is 0.
    [[nodiscard]] Film image(std::size_t first = 0) const
    {
        if (overflowed()) detail::throw_invalid("Accumulation overflowed (a sum passed 2^63): its image would be wrong");
        if (first + 3 > channels_.size()) detail::throw_invalid("Accumulation image from channel ", first, " of ", channels_.size());
        Film film(window_.width(), window_.height());
        for (int y = window_.y0; y < window_.y1; ++y)
            for (int x = window_.x0; x < window_.x1; ++x) {
                const auto s = sums(x, y);
                const std::uint64_t w = weight(x, y);
                film.set(x - window_.x0, y - window_.y0,
                         Rgb<float>(detail::mean(s[first], w), detail::mean(s[first + 1], w), detail::mean(s[first + 2], w)));
            }
        film.count_rejected(rejected());
        return film;
    }

private:
    [[nodiscard]] std::size_t index(int x, int y) const noexcept
    {
        PRISM_ASSERT(window_.contains(x, y));
        return std::size_t(y - window_.y0) * std::size_t(window_.width()) + std::size_t(x - window_.x0);
    }

    int width_;
    int height_;
    PixelWindow window_;
    std::vector<std::string> channels_;
    std::vector<ExactSum> sums_;
    std::vector<std::uint64_t> weights_;
    std::atomic<std::size_t> rejected_{0};
    std::atomic<bool> overflowed_{false};
};

} // namespace prism
