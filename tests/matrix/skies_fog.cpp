// SPDX-License-Identifier: MIT
// The consistency matrix in the full tier (tests/matrix.hpp): the covering cells whose
// scene is of one type, its own translation unit so that the types compile in parallel.
#include "../matrix.hpp"

using namespace test::matrix; // (a program of its own, never a unity batch)

TEST_CASE("the consistency matrix, a uniform sky and an environment map, in fog filling the air")
{
    check_rows(run_agreement<Sky::uniform, true>(matrix_cells(), Effort{}));
    check_rows(run_agreement<Sky::map, true>(matrix_cells(), Effort{}));
}
