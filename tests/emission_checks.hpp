// SPDX-License-Identifier: MIT
// Checks of a light's emission for the bidirectional estimators (light/light.hpp's
// EmissionSample): its rays carry the light's power on average, each drawn with the
// densities emission_pdf() gives back for it.
#pragma once

#include <prism/prism.hpp>

#include <doctest/doctest.h>

namespace test {

/// The mean, over n rays of `light`'s emission (emission(sphere, u, v) for independent
/// uniform pairs), of L cos / (pdf_area pdf_direction): its power into the sphere's disk or
/// everywhere; and every ray's densities as emission_pdf(direction, sphere) gives them.
template <class L>
prism::Rgb<double> emitted_power(const L& light, const prism::BoundingSphere<typename L::scalar_type>& sphere, int n)
{
    using T = typename L::scalar_type;
    prism::Random rng(3, 17);
    prism::Rgb<double> sum(0.0);
    int mismatched = 0;
    for (int i = 0; i < n; ++i) {
        const auto [a, b] = rng.uniform2<T>();
        const auto [c, d] = rng.uniform2<T>();
        const prism::EmissionSample<T> e = light.emission(sphere, prism::Vec2<T>(a, b), prism::Vec2<T>(c, d));
        if (!(e.pdf_area > T(0) && e.pdf_direction > T(0))) continue;
        sum += prism::Rgb<double>(e.radiance) * double(e.cos) / (double(e.pdf_area) * double(e.pdf_direction));
        const prism::EmissionPdf<T> pdf = light.emission_pdf(e.ray.direction, sphere);
        if (!(std::abs(pdf.area - e.pdf_area) <= T(1e-4) * e.pdf_area && std::abs(pdf.direction - e.pdf_direction) <= T(1e-3) * e.pdf_direction)) ++mismatched;
    }
    CHECK(mismatched == 0);
    return sum / double(n);
}

} // namespace test
