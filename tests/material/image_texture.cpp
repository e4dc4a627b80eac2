// SPDX-License-Identifier: MIT
#include <prism/material/image_texture.hpp>
#include <prism/material/diffuse.hpp>
#include <prism/material/rough_conductor.hpp>
#include <prism/material/scattering.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using prism::ImageTexture;
using prism::TextureFilter;
using prism::TexturePoint;
using prism::Vec2;
using prism::Wrap;

namespace {

/// A grey picture's value at uv, footprint `width`.
double grey(const ImageTexture<double>& t, double u, double v, double width = 0) { return t.value(TexturePoint<double>{{}, {u, v}, width}); }

/// The grey 2 x 2 picture  1 2 / 3 4  (top row first).
ImageTexture<double> two_by_two(prism::TextureSampling s)
{
    const std::vector<float> texels{1, 2, 3, 4};
    return {2, 2, 1, texels, s};
}

} // namespace

TEST_CASE("bilinear lookups: a texel at its centre, the mean between four, v up the picture, and each wrap mode at the edge")
{
    const auto t = two_by_two({Wrap::clamp, TextureFilter::bilinear});
    // Texel centres at (1/4, 3/4) (top left, row 0) ... (3/4, 1/4) (bottom right).
    CHECK(grey(t, 0.25, 0.75) == doctest::Approx(1));
    CHECK(grey(t, 0.75, 0.75) == doctest::Approx(2));
    CHECK(grey(t, 0.25, 0.25) == doctest::Approx(3));
    CHECK(grey(t, 0.75, 0.25) == doctest::Approx(4));
    CHECK(grey(t, 0.5, 0.5) == doctest::Approx(2.5));
    CHECK(grey(t, 0.375, 0.75) == doctest::Approx(1.25)); // a quarter of the way across
    // At the left edge: clamp reads the edge texel, repeat blends with the right column.
    CHECK(grey(t, 0.0, 0.75) == doctest::Approx(1));
    const auto r = two_by_two({Wrap::repeat, TextureFilter::bilinear});
    CHECK(grey(r, 0.0, 0.75) == doctest::Approx(1.5));
    CHECK(grey(r, 1.25, -0.25) == doctest::Approx(grey(r, 0.25, 0.75)));
    CHECK(grey(r, -3.75, 2.75) == doctest::Approx(1));
    CHECK(grey(t, 7.0, -3.0) == doctest::Approx(4)); // clamp: the bottom-right corner
    // Nearest: the texel the point falls in.
    const auto n = two_by_two({Wrap::repeat, TextureFilter::nearest});
    CHECK(grey(n, 0.49, 0.51) == 1);
    CHECK(grey(n, 0.51, 0.49) == 4);
    // Hostile coordinates read something finite.
    CHECK(std::isfinite(grey(r, std::nan(""), 1e300)));
    CHECK(std::isfinite(grey(t, -prism::infinity<double>, 1e-300)));
}

TEST_CASE("regression: a double texture finds its texel in double: uv a hair short of a texel's edge stays in that texel")
{
    // uv was wrapped in float: 0.5 - 1e-10 rounded to 0.5, the next texel (and 1 - 1e-10 to 1, wrapping to 0).
    const auto n = two_by_two({Wrap::repeat, TextureFilter::nearest});
    CHECK(grey(n, 0.5 - 1e-10, 0.75) == 1);
    CHECK(grey(n, 0.5 + 1e-10, 0.75) == 2);
    CHECK(grey(n, 0.25, 0.5 + 1e-10) == 1);
    CHECK(grey(n, 0.25, 0.5 - 1e-10) == 3);
}

TEST_CASE("the pyramid: every level the area average of the picture, for odd sizes too (against brute-force supersampling)")
{
    prism::Random rng(4, 2);
    for (const auto& [w, h] : {std::pair{8, 8}, std::pair{5, 3}, std::pair{7, 1}, std::pair{1, 6}}) {
        std::vector<float> texels(std::size_t(w * h * 3));
        for (float& x : texels) x = rng.uniform<float>();
        const ImageTexture<double> t(w, h, 3, texels);
        CHECK(t.levels() == std::size_t(1 + std::floor(std::log2(std::max(w, h)))));
        for (std::size_t k = 1; k < t.levels(); ++k) {
            const auto& level = t.level(k);
            for (int y = 0; y < level.height; ++y)
                for (int x = 0; x < level.width; ++x) {
                    // The region of the full picture this texel stands for, integrated
                    // texel by texel: area averages compose, so every level is the average
                    // over its region of the full picture.
                    const double x0 = double(x) * w / level.width, x1 = double(x + 1) * w / level.width;
                    const double y0 = double(y) * h / level.height, y1 = double(y + 1) * h / level.height;
                    double sum = 0;
                    for (int j = 0; j < h; ++j)
                        for (int i = 0; i < w; ++i) {
                            const double ox = std::max(0.0, std::min(x1, i + 1.0) - std::max(x0, double(i)));
                            const double oy = std::max(0.0, std::min(y1, j + 1.0) - std::max(y0, double(j)));
                            sum += ox * oy * texels[(std::size_t(j) * std::size_t(w) + std::size_t(i)) * 3 + 1];
                        }
                    sum /= (x1 - x0) * (y1 - y0);
                    CHECK(level.texels[(std::size_t(y) * std::size_t(level.width) + std::size_t(x)) * 3 + 1] == doctest::Approx(sum).epsilon(1e-5));
                }
        }
        // The last level is one texel: the picture's mean.
        CHECK(t.level(t.levels() - 1).texels.size() == 3);
    }
}

TEST_CASE("a footprint picks its level: log2 of the texels it covers; trilinear blends the two levels around it")
{
    // An 8 x 8 checker of 2 x 2 blocks: level 1 (4 x 4) is a checker of single texels,
    // level 2 (2 x 2) is all 1/2.
    std::vector<float> texels(64);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) texels[std::size_t(y * 8 + x)] = float((x / 2 + y / 2) % 2);
    const ImageTexture<double> t(8, 8, 1, texels);
    CHECK(t.level_for(0) == 0);
    CHECK(t.level_for(1.0 / 8) == 0);
    CHECK(t.level_for(2.0 / 8) == doctest::Approx(1));
    CHECK(t.level_for(4.0 / 8) == doctest::Approx(2));
    CHECK(t.level_for(1e9) == 3);
    // The centre of level 1's texel (0, 0) (value 0 there) is at uv (1/8, 7/8).
    CHECK(grey(t, 0.125, 0.875, 2.0 / 8) == doctest::Approx(0));
    CHECK(grey(t, 0.375, 0.875, 2.0 / 8) == doctest::Approx(1));
    CHECK(grey(t, 0.125, 0.875, 4.0 / 8) == doctest::Approx(0.5));
    // Halfway between levels 1 and 2 (3 texels: log2 3 = 1.585).
    const double f = std::log2(3.0) - 1;
    CHECK(grey(t, 0.375, 0.875, 3.0 / 8) == doctest::Approx((1 - f) * 1 + f * 0.5));
    // Bilinear ignores the footprint.
    const ImageTexture<double> b(8, 8, 1, texels, {Wrap::repeat, TextureFilter::bilinear});
    CHECK(grey(b, 0.0625, 0.9375, 4.0 / 8) == doctest::Approx(0));
}

TEST_CASE("a texture's bad texels and sizes are refused by name; an empty one does not validate")
{
    const std::vector<float> four{0, 1, 2, 3};
    CHECK_THROWS_WITH_AS((ImageTexture<float>(2, 2, 3, four)), doctest::Contains("width x height x channels = 12, got 4"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((ImageTexture<float>(0, 4, 1, four)), doctest::Contains("at least 1 x 1, got 0 x 4"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((ImageTexture<float>(2, 2, 2, four)), doctest::Contains("channels must be 1 or 3, got 2"), std::invalid_argument);
    const std::vector<float> bad{0, -1, 2, 3};
    CHECK_THROWS_WITH_AS((ImageTexture<float>(2, 2, 1, bad)), doctest::Contains("texel 1 (x 1, y 0)"), std::invalid_argument);
    const std::vector<float> nan{0, 1, std::nanf(""), 3};
    CHECK_THROWS_AS((ImageTexture<float>(2, 2, 1, nan)), std::invalid_argument);
    CHECK_THROWS_WITH_AS(ImageTexture<float>().validate(), doctest::Contains("empty"), std::invalid_argument);
    // A roughness texture above 1 is refused by the material.
    prism::RoughConductor<float, prism::ConstantKr<float>, ImageTexture<float>> metal{.roughness = ImageTexture<float>(2, 2, 1, four)};
    CHECK_THROWS_WITH_AS(metal.validate(), doctest::Contains("RoughConductor roughness texture's values must be in [0, 1], got up to 3"), std::invalid_argument);
}

TEST_CASE("a diffuse lobe reads an image texture where the crossing is, with the footprint over its dp/du and dp/dv")
{
    std::vector<float> texels(16 * 16 * 3, 0.2f);
    for (std::size_t i = 0; i < 16 * 3; ++i) texels[i] = 0.9f; // the top row
    const prism::Diffuse<double, ImageTexture<double>> matte{.albedo = ImageTexture<double>(16, 16, 3, texels, {Wrap::clamp, TextureFilter::trilinear})};
    prism::Crossing<double> at = prism::Crossing<double>::flat(1, {0, 0, 0}, {}, {0, 1, 0}, true).with_uv({0.5, 31.0 / 32}, {2, 0, 0}, {0, 0, -2});
    CHECK(prism::diffuse_response(matte, at).albedo.x == doctest::Approx(0.9));
    // A footprint of 0.5 in the scene is 0.25 in uv (a unit of uv spans 2), four texels: level 2.
    at.footprint = 0.5;
    CHECK(prism::texture_point(at).width == doctest::Approx(0.25));
    const double level_2 = (0.9 + 3 * 0.2) / 4; // its top row averages one bright row in four
    CHECK(prism::diffuse_response(matte, at).albedo.x == doctest::Approx(level_2));
}
