// SPDX-License-Identifier: MIT
// EnvironmentMap: the light of a latitude-longitude image (an HDR photograph of the world
// around), seen where rays leave the scene and drawn pixel by pixel by what each sends.
//
// The image wraps the sphere of directions with +y up: row 0 is the zenith, the last row
// the nadir, every row the same span of polar angle; the middle column looks toward -z and
// the image's right toward +x, so that a camera looking down -z sees the image's centre the
// right way round (as a viewer standing inside the panorama; Mitsuba 3's envmap has the
// same layout). Radiance between pixel centres is bilinear, wrapping around the horizon.
//
// A direction is drawn by picking a pixel with probability proportional to the radiance
// it sends (the mean of its channels, integrated over the pixel's solid angle), then a
// point of that pixel's patch of sphere uniform in solid angle. Its density is therefore
// constant over each pixel, and positive wherever the bilinear radiance is: a pixel's
// weight is its bilinear radiance integrated over it, which takes in its eight neighbours.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/distribution.hpp>
#include <prism/core/sampling.hpp>
#include <prism/light/light.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace prism {

/// How an EnvironmentMap's image is placed and scaled.
template <Scalar T>
struct EnvironmentMapSettings {
    T strength = T(1);          ///< radiance per pixel value (W/(m^2 sr) per unit)
    T rotation_degrees = T(0);  ///< the image turned about +y, counterclockwise seen from above
};

/// A sky from a latitude-longitude image of linear radiance (an HDR or EXR file read by io/).
/// Copies share the image and its distribution.
template <Scalar T = float>
class EnvironmentMap {
public:
    /// The precision of the light.
    using scalar_type = T;
    /// Not a delta light: drawn direction by direction.
    static constexpr bool delta = false;
    /// Seen by the rays that leave the scene.
    static constexpr bool at_infinity = true;

    /// The light of a width x height image, `pixels` row by row from the top. Throws
    /// std::invalid_argument, naming the parameter or the pixel, for an empty image, a
    /// pixel count that is not width x height, a negative or non-finite pixel, or a
    /// strength or rotation that is not finite (strength > 0).
    EnvironmentMap(int width, int height, std::span<const Rgb<float>> pixels, EnvironmentMapSettings<T> settings = {})
    {
        if (width < 1 || height < 1) detail::throw_invalid("EnvironmentMap size must be at least 1 x 1, got ", width, " x ", height);
        if (pixels.size() != std::size_t(width) * std::size_t(height))
            detail::throw_invalid("EnvironmentMap pixels: ", pixels.size(), " for an image of ", width, " x ", height);
        detail::require_positive("EnvironmentMap strength", settings.strength);
        detail::require_finite("EnvironmentMap rotation_degrees", settings.rotation_degrees);
        auto image = std::make_shared<Image>();
        image->width = width;
        image->height = height;
        image->strength = settings.strength;
        const T turn = settings.rotation_degrees * pi<T> / T(180);
        image->cos_turn = std::cos(turn);
        image->sin_turn = std::sin(turn);
        image->pixels.assign(pixels.begin(), pixels.end());
        for (std::size_t i = 0; i < pixels.size(); ++i)
            if (!(is_finite(pixels[i]) && pixels[i].x >= 0 && pixels[i].y >= 0 && pixels[i].z >= 0))
                detail::throw_invalid("EnvironmentMap pixel (", i % std::size_t(width), ", ", i / std::size_t(width),
                                      ") must be finite and >= 0 in every channel, got ", detail::describe(pixels[i]));
        // Each row's edges, as cosines of the polar angle.
        image->cos_edge.resize(std::size_t(height) + 1);
        for (int y = 0; y <= height; ++y) image->cos_edge[std::size_t(y)] = std::cos(pi<double> * double(y) / double(height));
        image->cos_edge.front() = 1;
        image->cos_edge.back() = -1;
        // A pixel's weight: its bilinear radiance integrated over it ((1 6 1) / 8 across
        // each axis of the 3 x 3 around it), times its solid angle.
        std::vector<double> weights(pixels.size());
        Vec3<double> integral{0.0};
        constexpr double k[3] = {1.0 / 8, 6.0 / 8, 1.0 / 8};
        for (int y = 0; y < height; ++y) {
            const double solid_angle = image->solid_angle(y);
            for (int x = 0; x < width; ++x) {
                Vec3<double> mean{0.0};
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) mean += k[i + 1] * k[j + 1] * Vec3<double>(image->texel(x + i, y + j));
                weights[std::size_t(y) * std::size_t(width) + std::size_t(x)] = (mean.x + mean.y + mean.z) / 3 * solid_angle;
                integral += mean * solid_angle;
            }
        }
        // An image black everywhere sends nothing: drawn uniformly, so the density stays
        // positive and the estimates zero.
        if (!(integral.x + integral.y + integral.z > 0))
            for (int y = 0; y < height; ++y)
                std::fill_n(weights.begin() + std::ptrdiff_t(y) * width, width, image->solid_angle(y));
        // An estimate L / pdf is at most 3 x 64 times the integral of the channels' mean (a
        // channel is at most 3 times the mean, and a pixel's weight takes at least 1/64 of
        // each of its neighbours): that must be finite in T.
        const Vec3<double> scaled = integral * double(settings.strength);
        if (!is_finite(Rgb<T>(scaled * 192.0)))
            detail::throw_invalid("EnvironmentMap: the radiance integrated over the sphere, ", detail::describe(scaled),
                                  ", is too large for this precision (192 times it must be finite)");
        image->integral = Rgb<T>(scaled);
        image->pick = AliasTable2D<T>(std::size_t(width), std::size_t(height), weights, "EnvironmentMap pixel weight");
        image_ = std::move(image);
    }

    /// The image's width in pixels.
    [[nodiscard]] int width() const noexcept { return image_->width; }
    /// The image's height in pixels.
    [[nodiscard]] int height() const noexcept { return image_->height; }

    /// The radiance arriving along -direction (from `direction`'s side of the sky), bilinear
    /// between pixel centres; `direction` of unit length.
    [[nodiscard]] Rgb<T> arriving_from(const Vec3<T>& direction) const noexcept
    {
        const Image& image = *image_;
        const Vec2<T> uv = image.to_uv(direction);
        const T fx = uv.x * T(image.width) - T(0.5), fy = uv.y * T(image.height) - T(0.5);
        const T x0 = std::floor(fx), y0 = std::floor(fy);
        const T tx = fx - x0, ty = fy - y0;
        const int x = int(x0), y = int(y0);
        const Rgb<T> top = (T(1) - tx) * Rgb<T>(image.texel(x, y)) + tx * Rgb<T>(image.texel(x + 1, y));
        const Rgb<T> bottom = (T(1) - tx) * Rgb<T>(image.texel(x, y + 1)) + tx * Rgb<T>(image.texel(x + 1, y + 1));
        return image.strength * ((T(1) - ty) * top + ty * bottom);
    }

    /// A direction drawn pixel by pixel by what each sends, then uniform in solid angle
    /// over the pixel; its estimate L / pdf.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>&, const Vec2<T>& u) const noexcept
    {
        const Image& image = *image_;
        const AliasPick2D<T> pick = image.pick.pick(u);
        const T c0 = T(image.cos_edge[pick.y]), c1 = T(image.cos_edge[pick.y + 1]);
        const T cos_theta = clamp(c0 + pick.rest.x * (c1 - c0), T(-1), T(1));
        const T sin_theta = prism::sqrt(std::max(T(0), T(1) - cos_theta * cos_theta));
        const T phi = T(2) * pi<T> * ((T(pick.x) + pick.rest.y) / T(image.width) - T(0.5));
        const Vec3<T> wi = image.to_world({sin_theta * std::sin(phi), cos_theta, -sin_theta * std::cos(phi)});
        const T pdf = pick.probability / T(image.solid_angle(int(pick.y)));
        return {wi, infinity<T>, arriving_from(wi) / pdf, pdf};
    }

    /// The density sample() draws `direction` with (unit length): its pixel's probability
    /// over the pixel's solid angle.
    [[nodiscard]] T pdf(const Vec3<T>& direction) const noexcept
    {
        const Image& image = *image_;
        const Vec2<T> uv = image.to_uv(direction);
        const int x = std::min(int(uv.x * T(image.width)), image.width - 1);
        const int y = std::min(int(uv.y * T(image.height)), image.height - 1);
        return image.pick.probability(std::size_t(x), std::size_t(y)) / T(image.solid_angle(y));
    }

    /// The power entering the disk of radius R that faces each direction and covers the
    /// scene (or the target): pi R^2 times the radiance integrated over the sphere.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        if (!aim.scene) return Rgb<T>(T(0));
        const T r = aim.target ? aim.target->radius : aim.scene->radius;
        return image_->integral * (pi<T> * r * r);
    }

    /// A photon from a direction drawn as sample() draws it (from `rng`), through the point
    /// (u, v) of the disk facing it, upstream of everything bounded; weighted by L / pdf
    /// over its mean, the radiance integrated over the sphere.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v, Random& rng) const noexcept
    {
        const BoundingSphere<T>& scene = *aim.scene;
        const BoundingSphere<T>& sphere = aim.target ? *aim.target : scene;
        const auto [a, b] = rng.uniform2<T>();
        const LightSample<T> from = sample(sphere.center, {a, b});
        const Vec3<T> travel = -from.wi;
        const T upstream = length(sphere.center - scene.center) + scene.radius + sphere.radius;
        const Rgb<T>& mean = image_->integral;
        const Rgb<T> weight{mean.x > T(0) ? from.irradiance.x / mean.x : T(0), mean.y > T(0) ? from.irradiance.y / mean.y : T(0),
                            mean.z > T(0) ? from.irradiance.z / mean.z : T(0)};
        return {{uniform_disk(sphere.center - upstream * travel, travel, sphere.radius, u, v), travel}, weight};
    }

    /// A ray from a direction drawn as sample() draws it (u_direction), through a point
    /// uniform (u_position) over the disk of the scene's sphere that faces it, upstream of
    /// the sphere, carrying the radiance from there.
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>& scene, const Vec2<T>& u_position, const Vec2<T>& u_direction) const noexcept
    {
        const LightSample<T> from = sample(scene.center, u_direction);
        return {{entry_point(scene, -from.wi, u_position), -from.wi}, arriving_from(from.wi), entry_pdf(scene), from.pdf, T(1), true};
    }

    /// The densities emission() draws a ray travelling along `leaving` (unit) with.
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>& leaving, const BoundingSphere<T>& scene) const noexcept
    {
        return {entry_pdf(scene), pdf(-leaving)};
    }

    /// The image and its settings were checked when the light was made: nothing is left to check.
    constexpr void validate() const noexcept {}

private:
    struct Image {
        int width = 0, height = 0;
        std::vector<Rgb<float>> pixels;  ///< row by row from the top
        std::vector<double> cos_edge;    ///< cos of each row's upper and lower polar angle (height + 1)
        AliasTable2D<T> pick;            ///< the pixels by radiance times solid angle
        Rgb<T> integral{T(0)};           ///< the radiance integrated over the sphere (W/m^2)
        T strength = T(1);
        T cos_turn = T(1), sin_turn = T(0);

        /// Pixel (x, y), x wrapping around the horizon and y held at the poles.
        [[nodiscard]] const Rgb<float>& texel(int x, int y) const noexcept
        {
            x %= width;
            if (x < 0) x += width;
            y = std::clamp(y, 0, height - 1);
            return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
        }

        /// The solid angle of a pixel of row y.
        [[nodiscard]] double solid_angle(int y) const noexcept
        {
            return 2 * pi<double> / double(width) * (cos_edge[std::size_t(y)] - cos_edge[std::size_t(y) + 1]);
        }

        /// The image's (u, v) in [0, 1]^2 of a unit direction in the world.
        [[nodiscard]] Vec2<T> to_uv(const Vec3<T>& d) const noexcept
        {
            const Vec3<T> l{cos_turn * d.x - sin_turn * d.z, d.y, sin_turn * d.x + cos_turn * d.z};
            const T u = std::atan2(l.x, -l.z) / (T(2) * pi<T>) + T(0.5);
            const T v = std::acos(clamp(l.y, T(-1), T(1))) / pi<T>;
            return {clamp(u, T(0), T(1)), clamp(v, T(0), T(1))};
        }

        /// A direction in the image's own frame turned into the world.
        [[nodiscard]] Vec3<T> to_world(const Vec3<T>& l) const noexcept
        {
            return {cos_turn * l.x + sin_turn * l.z, l.y, -sin_turn * l.x + cos_turn * l.z};
        }
    };

    std::shared_ptr<const Image> image_;
};

static_assert(Light<EnvironmentMap<float>>);

} // namespace prism
