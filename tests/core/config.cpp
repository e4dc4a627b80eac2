// SPDX-License-Identifier: MIT
// GLM included first, with SIMD intrinsics forced and without GLM_FORCE_PURE: GLM's
// vectors are then not constexpr. prism must still compile and compute the same
// numbers, with its constexpr vector features off. This translation unit undoes the
// build's GLM_FORCE_PURE to play a user who configured GLM their own way.
#undef GLM_FORCE_PURE
#define GLM_FORCE_INTRINSICS
#include <glm/glm.hpp>

#include <prism/prism.hpp>

#include <doctest/doctest.h>

static_assert(PRISM_CONSTEXPR_VECTORS == 0, "GLM with intrinsics: vectors are not constexpr");

TEST_CASE("prism works when GLM was included first with intrinsics and without GLM_FORCE_PURE")
{
    const prism::Sphere<float> sphere({0.0f, 0.0f, 0.0f}, 1.0f);
    const auto c = sphere.crossings({{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}, prism::Interval<float>::universe());
    REQUIRE(c.size() == 2);
    CHECK(c[0].t == 4.0f);
    CHECK(c[1].t == 6.0f);
    CHECK(prism::fresnel_dielectric(1.0f, 1.5f) == doctest::Approx(0.04));
}

TEST_CASE("PRISM_ASSERT is active where the build asks for it")
{
    // tools/test.sh builds its sanitizer runs with -DPRISM_ASSERTIONS=ON, which defines
    // PRISM_ENABLE_ASSERTIONS and PRISM_EXPECT_ASSERTIONS: the checks must then be live.
#if defined(PRISM_EXPECT_ASSERTIONS)
    CHECK(PRISM_ASSERTIONS_ENABLED == 1);
#elif defined(NDEBUG)
    CHECK(PRISM_ASSERTIONS_ENABLED == 0);
#else
    CHECK(PRISM_ASSERTIONS_ENABLED == 1);
#endif
}
