// SPDX-License-Identifier: MIT
#include <prism/photon/estimator.hpp>

#include <doctest/doctest.h>

#include <initializer_list>

using namespace prism;

TEST_CASE("each filter's mean is its weight averaged over the disk, by quadrature")
{
    // Uniform over the disk, u = d^2 / r^2 is uniform on [0, 1]: the mean weight is the
    // integral of w(u r^2, r^2) du, taken here by the midpoint rule on 10^6 intervals.
    for (const Filter filter : {Filter::box, Filter::cone, Filter::gaussian}) {
        CAPTURE(int(filter));
        const detail::FilterWeight weight(filter);
        const int n = 1000000;
        const float r2 = 0.04f;
        double sum = 0;
        for (int i = 0; i < n; ++i) sum += weight(float((i + 0.5) / n) * r2, r2);
        CHECK(weight.mean() == doctest::Approx(sum / n).epsilon(1e-5));
        CHECK(weight(0.0f, r2) >= weight(r2, r2)); // weights fall off with distance
    }
    CHECK(detail::FilterWeight(Filter::box).mean() == 1.0f);
    CHECK(detail::FilterWeight(Filter::cone).mean() == doctest::Approx(1.0 / 3.0));
    CHECK(detail::FilterWeight(Filter::gaussian).mean() == doctest::Approx(0.531).epsilon(2e-3)); // Jensen's alpha and beta
    CHECK(detail::FilterWeight(Filter::cone)(0.04f, 0.04f) == 0.0f);
}
