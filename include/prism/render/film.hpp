// SPDX-License-Identifier: MIT
// Film: a linear HDR RGB image of radiance values, never NaN or Inf.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <atomic>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>


namespace prism {

/// A linear HDR RGB image. Any number of threads may set distinct pixels at once.
class Film {
public:
    /// A black film of width x height pixels; throws std::invalid_argument for a size <= 0 and a clear error when the memory cannot be had.
    Film(int width, int height) : width_(width), height_(height)
    {
        if (width <= 0 || height <= 0) detail::throw_invalid("Film size must be positive, got ", width, " x ", height);
        const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
        const double bytes = double(count) * sizeof(Rgb<float>);
        const std::string what = "a Film of " + std::to_string(width) + " x " + std::to_string(height) + " pixels";
        detail::require_memory(what, bytes);
        try {
            pixels_.assign(count, Rgb<float>(0.0f));
        } catch (const std::bad_alloc&) {
            throw allocation_error("prism: " + what + " needs " + detail::describe_bytes(bytes) + ", which could not be allocated");
        }
    }

    /// A copy of the pixels.
    Film(const Film& other) : width_(other.width_), height_(other.height_), pixels_(other.pixels_), rejected_(other.rejected()) {}
    /// Takes the pixels over.
    Film(Film&& other) noexcept
        : width_(other.width_), height_(other.height_), pixels_(std::move(other.pixels_)), rejected_(other.rejected())
    {
    }
    /// Copy or move assignment.
    Film& operator=(Film other) noexcept
    {
        width_ = other.width_;
        height_ = other.height_;
        pixels_ = std::move(other.pixels_);
        rejected_.store(other.rejected(), std::memory_order_relaxed);
        return *this;
    }

    /// The width in pixels.
    [[nodiscard]] int width() const noexcept { return width_; }
    /// The height in pixels.
    [[nodiscard]] int height() const noexcept { return height_; }
    /// The pixels, row by row from the top.
    [[nodiscard]] const std::vector<Rgb<float>>& pixels() const noexcept { return pixels_; }

    /// Pixel (x, y), from the top left.
    [[nodiscard]] const Rgb<float>& at(int x, int y) const noexcept
    {
        return pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
    }

    /// Store a pixel's radiance. A channel that is NaN, infinite or negative is stored
    /// as 0 and counted, so no bad number ever reaches an image file.
    template <Scalar T>
    void set(int x, int y, const Rgb<T>& radiance) noexcept
    {
        Rgb<float> v;
        for (int c = 0; c < 3; ++c) {
            const float value = static_cast<float>(radiance[c]);
            const bool good = is_finite(value) && value >= 0.0f;
            v[c] = good ? value : 0.0f;
            if (!good) rejected_.fetch_add(1, std::memory_order_relaxed); // render threads share the count
        }
        pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] = v;
    }

    /// How many channel values were replaced by 0 because they were not finite and >= 0.
    [[nodiscard]] std::size_t rejected() const noexcept { return rejected_.load(std::memory_order_relaxed); }
    /// Count values rejected before they reached this film (an Accumulation's samples).
    void count_rejected(std::size_t count) noexcept { rejected_.fetch_add(count, std::memory_order_relaxed); }

private:
    int width_;
    int height_;
    std::vector<Rgb<float>> pixels_;
    std::atomic<std::size_t> rejected_{0};
};

} // namespace prism
