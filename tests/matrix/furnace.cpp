// SPDX-License-Identifier: MIT
// The consistency matrix in the full tier (tests/matrix.hpp): its furnaces.
#include "../matrix.hpp"

using namespace test::matrix; // (a program of its own, never a unity batch)

TEST_CASE("the consistency matrix, furnaces: every lossless material kind in every place for a fog, the camera outside and inside, reads 1")
{
    check_rows(run_furnace<false>(furnace_cells(), Effort{}));
    check_rows(run_furnace<true>(furnace_cells(), Effort{}));
}
