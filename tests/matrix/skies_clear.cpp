// SPDX-License-Identifier: MIT
// The consistency matrix in the full tier (tests/matrix.hpp): the covering cells whose
// scene is of one type, its own translation unit so that the types compile in parallel.
#include "../matrix.hpp"

using namespace test::matrix; // (a program of its own, never a unity batch)

TEST_CASE("the consistency matrix, a uniform sky and an environment map, in clear air and with fog in objects")
{
    check_rows(run_agreement<Sky::uniform, false>(matrix_cells(), Effort{}));
    check_rows(run_agreement<Sky::map, false>(matrix_cells(), Effort{}));
}
