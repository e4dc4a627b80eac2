// SPDX-License-Identifier: MIT
// The consistency matrix's slice in the quick tier (tests/matrix.hpp: every estimator on
// scenes made of one material kind, one light kind and one place for a fog, against the
// reference or a furnace's 1); tests/matrix/ runs the full tier's 157 agreement cells and 32 furnaces. Each
// row is printed (ctest -V shows the table).
#include "../matrix.hpp"

#include <doctest/doctest.h>

TEST_CASE("the consistency matrix's quick slice: four scenes: a point, disk and sphere light, fog in objects and in glass")
{
    using test::matrix::LightKind, test::matrix::Placement;
    // Material kinds by their index in test::matrix::Materials.
    const std::vector<test::matrix::CellSpec> cells{{0, LightKind::point, Placement::smoke, true}, {3, LightKind::point, Placement::clear, false},
                                                    {5, LightKind::disk, Placement::nested, false}, {7, LightKind::sphere, Placement::foggy_glass, false}};
    test::matrix::check_rows(test::matrix::run_agreement<test::matrix::Sky::none, false>(cells, {.batches = 8, .spp = 16, .photons = 30000}));
}

TEST_CASE("the consistency matrix's quick slice: furnaces of a white diffuse ball in a ball of smoke, and of glass, read 1")
{
    using test::matrix::LightKind, test::matrix::Placement;
    test::matrix::check_rows(test::matrix::run_furnace<false>({{0, LightKind::sky, Placement::smoke, true}, {5, LightKind::sky, Placement::clear, false}}, {}));
}
