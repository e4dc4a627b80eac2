// SPDX-License-Identifier: MIT
// through_memory: a barrier for tests that make a double twin of a float ray or shape.
#pragma once

namespace test {

/// Make the compiler read `value` back from memory, a value it cannot see through. GCC
/// 12.2's SLP vectorizer (-O2, unity builds too) was seen to give code that converts a
/// float back to double the unrounded double the float was made from (a float ray's
/// double copy differed from its bits in 12 of 12 disagreements studied): a double twin
/// of a float ray or shape must be made from the float object's own bits.
template <class V>
void through_memory(V& value)
{
    asm volatile("" : : "r"(&value) : "memory");
}

} // namespace test
