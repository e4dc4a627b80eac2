// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

// Every material states its traits; the scene derives what code its integrator needs.
static_assert(prism::Material<prism::Diffuse<float, prism::Checker<float>>>);
static_assert(!prism::Material<int>);

using DiffuseOnly = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Diffuse<float>>,
                                 prism::Object<prism::Plane<float>, prism::Diffuse<float>>>;
using WithMirror = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Mirror<float>>>;
using WithGlass = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Diffuse<float>>,
                               prism::ObjectArray<prism::Sphere<float>, prism::Dielectric<float>>>;
static_assert(!DiffuseOnly::has_transmissive && !DiffuseOnly::has_specular);
static_assert(!WithMirror::has_transmissive && WithMirror::has_specular);
static_assert(WithGlass::has_transmissive && WithGlass::has_specular);

TEST_CASE("scene traits follow from the material types")
{
    CHECK(WithGlass::slot_count == 2);
}
