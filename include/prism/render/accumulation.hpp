// SPDX-License-Identifier: MIT
// Accumulation: a render's samples summed exactly per pixel over a window of the image,
// so that a render split by pixels (crop windows), by passes, over threads or over
// machines adds up to the same bits as the render made in one piece.
//
// Floating-point addition is not associative: (a + b) + c and a + (b + c) can differ in
// the last bit, and far more when a and c differ by many orders of magnitude, so sums
// made in parts and added in another order would not reproduce the whole. Here each
// sample is rounded once, to the nearest multiple of 2^-64, and summed as a 256-bit
// integer (ExactSum, of two core/int128.hpp halves), whose addition is exact, associative
// and commutative. That one rounding depends on the sample alone; it keeps every float
// sample from 2^-41 (4.5e-13) up exactly and moves a smaller one by at most 2^-65
// (2.7e-20). Every finite float sample is taken, up to 3.4e38. An Accumulation stores
// each sum's lower 128 bits, and its upper bits only once some sum passes 2^63.
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
#include <mutex>
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

/// A signed fixed-point number with 192 integer and 64 fraction bits: samples rounded
/// once to a multiple of 2^-64 and summed with no further rounding. It is a 256-bit
/// two's-complement integer of 2^-64 steps, held as two of core/int128.hpp's 128-bit
/// integers (`Integer`; their bits are the same): the lower half's bits, and the upper
/// half, signed. A sample takes only the lower half unless it is 2^52 or more; a sum
/// needs the upper half only past 2^63 (Accumulation then keeps it, and not before).
template <class Integer>
class BasicExactSum {
public:
    /// The largest magnitude a sample may have: the largest finite float. Every sample
    /// a float scene makes is taken, and a mean of such samples is a finite float. (2^63
    /// such samples could not overflow the 192 integer bits.)
    static constexpr double limit = double(std::numeric_limits<float>::max());

    constexpr BasicExactSum() noexcept = default;

    /// x rounded to the nearest multiple of 2^-64 (halves away from zero), which is
    /// round(ldexp(x, 64)) as an integer. |x| <= limit.
    [[nodiscard]] static constexpr BasicExactSum of(double x) noexcept
    {
        PRISM_ASSERT(x >= -limit && x <= limit);
        // From x's bits, in integers: |x| = m 2^(e - 1075) (e the biased exponent, m
        // with its leading one, or a denormal's m at e = 1), so |x| 2^64 = m 2^s. (The
        // library's ldexp, round and double-to-integer conversion are calls, one a
        // sample and channel: 5 % of a Whitted render of the Cornell box.)
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const auto biased = int((bits >> 52) & 0x7ff);
        const std::uint64_t fraction = bits & ((std::uint64_t(1) << 52) - 1);
        const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t(1) << 52);
        const int s = (biased == 0 ? 1 : biased) - 1075 + 64; // below 128 + 12 (|x| < 2^128)
        const BasicExactSum magnitude = placed(m, s);
        if ((bits >> 63) == 0) return magnitude;
        // -(high 2^128 + low) = (2^128 - low) + (-high - 1) 2^128, or -high 2^128 when low is 0.
        Integer negated_high = -magnitude.high_;
        if (!(magnitude.low_ == Integer{})) (void)negated_high.add(Integer::from_int64(-1)); // |high| < 2^12: no overflow
        return from_bits(-magnitude.low_, negated_high);
    }

    /// of(double(x)) for a float x with 0 <= x <= limit, from the float's own bits: x 2^64
    /// = m 2^(e - 86), m its 24-bit significand and e its biased exponent (1 for a
    /// denormal). A radiance sample of a float scene takes this one; the same integer.
    [[nodiscard]] static constexpr BasicExactSum of_float(float x) noexcept
    {
        PRISM_ASSERT(x >= 0.0f && x <= float(limit));
        const auto bits = std::bit_cast<std::uint32_t>(x);
        const auto biased = int(bits >> 23); // (the sign bit is 0)
        const std::uint64_t fraction = bits & ((std::uint32_t(1) << 23) - 1);
        const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t(1) << 23);
        return placed(m, (biased == 0 ? 1 : biased) - 86); // (s below 169: x < 2^128)
    }

    /// Whether x is a sample this type takes: finite and |x| <= limit.
    [[nodiscard]] static constexpr bool takes(double x) noexcept { return x >= -limit && x <= limit; }

    /// The sum whose value is bits 2^-64, for a 128-bit signed `bits`.
    [[nodiscard]] static constexpr BasicExactSum from_bits(Integer bits) noexcept
    {
        return from_bits(bits, bits.negative() ? Integer::from_int64(-1) : Integer{});
    }
    /// The sum whose value is (high 2^128 + low) 2^-64, `low` read as unsigned.
    [[nodiscard]] static constexpr BasicExactSum from_bits(Integer low, Integer high) noexcept
    {
        BasicExactSum s;
        s.low_ = low;
        s.high_ = high;
        return s;
    }
    /// The lower 128 bits of the sum in units of 2^-64 (as a signed 128-bit integer,
    /// the sum itself when narrow()).
    [[nodiscard]] constexpr Integer low() const noexcept { return low_; }
    /// The upper 128 bits, signed.
    [[nodiscard]] constexpr Integer high() const noexcept { return high_; }
    /// Whether the sum is low() alone: its magnitude is below 2^63 (high() only extends
    /// low()'s sign).
    [[nodiscard]] constexpr bool narrow() const noexcept
    {
        return high_ == (low_.negative() ? Integer::from_int64(-1) : Integer{});
    }

    /// Add `other`; false (and this unchanged) when the sum would pass 2^191 in magnitude.
    [[nodiscard]] constexpr bool add(const BasicExactSum& other) noexcept
    {
        Integer low = low_, high = high_;
        const bool carry = low.add_with_carry(other.low_);
        if (!high.add(other.high_) || (carry && !high.add(Integer::from_int64(1)))) return false;
        low_ = low;
        high_ = high;
        return true;
    }

    /// The sum, rounded once to double (ties to even).
    [[nodiscard]] double value() const noexcept
    {
        if (narrow()) return low_.to_double() * 0x1p-64; // exact scaling: the double is 0 or at least 1
        // The magnitude's four words, low first.
        const bool negative = high_.negative();
        Integer low = low_, high = high_;
        if (negative) {
            high = -high;
            if (!(low == Integer{})) (void)high.add(Integer::from_int64(-1));
            low = -low;
        }
        const std::uint64_t words[4] = {low.low(), low.high(), high.low(), high.high()};
        int top = 3;
        while (words[top] == 0) --top; // not narrow: some upper word is not 0
        // The leading one is bit `length - 1`; the 64 bits below it and it, and whether
        // any bit further down is set, decide the double.
        const int length = 64 * top + 64 - std::countl_zero(words[top]);
        const auto bits_at = [&](int at) { // the 64 bits from bit `at` up (at > -64)
            std::uint64_t r = 0;
            for (int k = 0; k < 4; ++k) {
                const int shift = 64 * k - at;
                if (shift > -64 && shift < 64) r |= shift >= 0 ? words[k] << shift : words[k] >> -shift;
            }
            return r;
        };
        const int first = length - 64;
        const std::uint64_t leading = bits_at(first);
        bool below = false;
        for (int k = 0; k < 4; ++k) {
            const int from = 64 * k; // the word's bits under `first`
            if (from >= first) break;
            below |= (first - from >= 64 ? words[k] : words[k] & ((std::uint64_t(1) << (first - from)) - 1)) != 0;
        }
        std::uint64_t mantissa = leading >> 11;
        const std::uint64_t rest = leading & 0x7ff, half = 0x400;
        if (rest > half || (rest == half && (below || (mantissa & 1) != 0))) ++mantissa; // 2^53 at most: exact
        const double magnitude = std::ldexp(double(mantissa), first + 11 - 64);
        return negative ? -magnitude : magnitude;
    }

    /// Sums are equal when their bits are.
    friend constexpr bool operator==(const BasicExactSum&, const BasicExactSum&) = default;

private:
    /// m 2^s rounded to an integer (halves away from zero), as the sum's two halves, where
    /// m 2^(s - 128) < 2^64 (a double's m < 2^53 with s < 140, a float's m < 2^24 with s <
    /// 169) and m < 2^53. The words of m 2^s, each by one shift (a
    /// shift of the whole by a variable count is a branch or a select more, and this is
    /// done for every sample and channel). Below 2^52 (s < 64) the upper half is 0.
    [[nodiscard]] static constexpr BasicExactSum placed(std::uint64_t m, int s) noexcept
    {
        Integer low{}, high{};
        if (s >= 128) {
            high = Integer::from_words(m << (s - 128), 0);
        } else if (s >= 64) {
            low = Integer::from_words(0, m << (s - 64));
            high = Integer::from_words((m >> 1) >> (127 - s), 0); // m >> (128 - s)
        } else if (s >= 0) {
            low = Integer::from_words(m << s, (m >> 1) >> (63 - s)); // m >> (64 - s), and 0 for s = 0
        } else if (s > -54) {
            low = Integer::from_words((m + (std::uint64_t(1) << (-s - 1))) >> -s, 0); // half up: away from zero
        } // (s <= -54: m 2^s < 2^53 2^-54, nearer 0.)
        return from_bits(low, high);
    }

    Integer low_{};
    Integer high_{};
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
/// may add to distinct pixels at once. Each sum's lower 128 bits are stored; its upper
/// bits are stored from the first sum past 2^63 on (a plane as large again, which a
/// render whose pixel sums stay below 2^63 = 9.2e18 never makes).
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
        const double bytes = double(pixels) * double(channels_.size() * sizeof(Int128) + sizeof(std::uint64_t));
        const std::string what = "an Accumulation of " + std::to_string(window.width()) + " x " + std::to_string(window.height()) + " pixels";
        detail::require_memory(what, bytes);
        try {
            low_.assign(pixels * channels_.size(), Int128{});
            weights_.assign(pixels, 0);
        } catch (const std::bad_alloc&) {
            throw allocation_error("prism: " + what + " needs " + detail::describe_bytes(bytes) + ", which could not be allocated");
        }
    }

    /// A copy of the sums and the flags.
    Accumulation(const Accumulation& other)
        : width_(other.width_), height_(other.height_), window_(other.window_), channels_(other.channels_), low_(other.low_),
          high_(other.high_), weights_(other.weights_), rejected_(other.rejected()), overflowed_(other.overflowed())
    {
        wide_.store(!high_.empty(), std::memory_order_relaxed);
    }
    /// Takes the sums over.
    Accumulation(Accumulation&& other) noexcept
        : width_(other.width_), height_(other.height_), window_(other.window_), channels_(std::move(other.channels_)), low_(std::move(other.low_)),
          high_(std::move(other.high_)), weights_(std::move(other.weights_)), rejected_(other.rejected()), overflowed_(other.overflowed())
    {
        wide_.store(!high_.empty(), std::memory_order_relaxed);
    }
    /// Copy or move assignment.
    Accumulation& operator=(Accumulation other) noexcept
    {
        width_ = other.width_;
        height_ = other.height_;
        window_ = other.window_;
        channels_ = std::move(other.channels_);
        low_ = std::move(other.low_);
        high_ = std::move(other.high_);
        weights_ = std::move(other.weights_);
        wide_.store(!high_.empty(), std::memory_order_relaxed);
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

    /// Pixel (x, y)'s sum of channel c; (x, y) in image coordinates, inside the window.
    [[nodiscard]] ExactSum sum(int x, int y, std::size_t c) const noexcept
    {
        PRISM_ASSERT(c < channels_.size());
        const std::size_t i = index(x, y) * channels_.size() + c;
        const ExactSum narrow = ExactSum::from_bits(low_[i]);
        if (!wide_.load(std::memory_order_acquire)) return narrow;
        Int128 high = narrow.high();
        (void)high.add(high_[i]); // the stored correction was made from this sum: no overflow
        return ExactSum::from_bits(low_[i], high);
    }
    /// Pixel (x, y)'s sums, one per channel.
    [[nodiscard]] std::vector<ExactSum> sums(int x, int y) const
    {
        std::vector<ExactSum> out(channels_.size());
        for (std::size_t c = 0; c < out.size(); ++c) out[c] = sum(x, y, c);
        return out;
    }
    /// Pixel (x, y)'s weight: the samples or passes its sums hold.
    [[nodiscard]] std::uint64_t weight(int x, int y) const noexcept { return weights_[index(x, y)]; }
    /// Whether some sum has passed 2^63 (its upper bits are stored).
    [[nodiscard]] bool wide() const noexcept { return wide_.load(std::memory_order_acquire); }

    /// Add sums (one per channel) and a weight to pixel (x, y). A sum that would
    /// overflow is left out and flagged (overflowed()), as is one past 2^63 when the
    /// memory for the upper bits cannot be had.
    void add(int x, int y, std::span<const ExactSum> sums, std::uint64_t weight) noexcept
    {
        PRISM_ASSERT(sums.size() == channels_.size());
        const std::size_t i = index(x, y), n = sums.size();
        std::size_t c = 0;
        // Every sum so far narrow, and each of these: a 128-bit add that does not overflow
        // gives the narrow total the general path below would (its correction 0).
        if (!wide_.load(std::memory_order_acquire)) {
            Int128* low = low_.data() + i * n;
            for (; c < n; ++c) {
                Int128 total = low[c];
                if (!sums[c].narrow() || !total.add(sums[c].low())) break;
                low[c] = total;
            }
        }
        for (; c < n; ++c) {
            const std::size_t k = i * n + c;
            ExactSum total = sum(x, y, c);
            if (!total.add(sums[c])) {
                overflowed_.store(true, std::memory_order_relaxed);
                continue;
            }
            // The upper half less the lower half's sign: 0 for a narrow sum (and for the
            // few sums within 2^128 of 2^255, one that does not fit: an overflow).
            Int128 correction = total.high();
            const bool fits = !total.low().negative() || correction.add(Int128::from_int64(1));
            if (!fits || (!(correction == Int128{}) && !make_wide())) {
                overflowed_.store(true, std::memory_order_relaxed);
                continue;
            }
            low_[k] = total.low();
            if (wide_.load(std::memory_order_acquire)) high_[k] = correction;
        }
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
    /// Whether some sum or weight would have overflowed, or a sum past 2^63 found no
    /// memory for its upper bits (and was left out): the sums are then wrong, and image()
    /// refuses them.
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
        if (overflowed())
            detail::throw_invalid("Accumulation overflowed (a sum passed 2^191, a weight 2^64, or a sum past 2^63 found no memory): its image would be wrong");
        if (first + 3 > channels_.size()) detail::throw_invalid("Accumulation image from channel ", first, " of ", channels_.size());
        Film film(window_.width(), window_.height());
        for (int y = window_.y0; y < window_.y1; ++y)
            for (int x = window_.x0; x < window_.x1; ++x) {
                const std::uint64_t w = weight(x, y);
                film.set(x - window_.x0, y - window_.y0,
                         Rgb<float>(detail::mean(sum(x, y, first), w), detail::mean(sum(x, y, first + 1), w), detail::mean(sum(x, y, first + 2), w)));
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

    /// Make the plane of upper bits, once; false when its memory cannot be had.
    [[nodiscard]] bool make_wide() noexcept
    {
        if (wide_.load(std::memory_order_acquire)) return true;
        const std::lock_guard lock(widening_);
        if (wide_.load(std::memory_order_relaxed)) return true;
        try {
            high_.assign(low_.size(), Int128{}); // zeros: every sum so far is narrow
        } catch (const std::bad_alloc&) {
            return false;
        }
        wide_.store(true, std::memory_order_release);
        return true;
    }

    int width_;
    int height_;
    PixelWindow window_;
    std::vector<std::string> channels_;
    std::vector<Int128> low_;  // each sum's lower 128 bits
    std::vector<Int128> high_; // empty, or each sum's upper 128 bits less its lower half's sign
    std::vector<std::uint64_t> weights_;
    std::atomic<bool> wide_{false};
    std::mutex widening_;
    std::atomic<std::size_t> rejected_{0};
    std::atomic<bool> overflowed_{false};
};

} // namespace prism
