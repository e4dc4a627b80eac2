#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The test files compile together in any batch: the release and thread trees compile them
# sixteen to a translation unit (PRISM_TESTS_BATCH), so a name at one file's namespace scope
# must not clash with, or be shadowed by, a name in another (-Wshadow is an error there), and
# which files share a batch changes whenever a file is added. This compiles every test file
# in one translation unit, in order and in reverse (a name declared in one file is then seen
# by every other), with g++ and clang, -fsyntax-only. About 4 minutes of compiler; run it
# after adding or renaming a test file:
#   tools/check_unity.sh BUILD_DIR    (a configured tree, for its generated snippet headers)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: tools/check_unity.sh BUILD_DIR (a configured tree)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$root/tests" && ls */*.cpp | grep -vE "^(consumers|compile_fail|fuzz|snippets|matrix|cli)/|^core/config.cpp$" |
  sed "s|.*|#include \"$root/tests/&\"|") >"$work/forward.cpp"
tac "$work/forward.cpp" >"$work/reverse.cpp"
flags=(-std=c++20 -fsyntax-only -DGLM_FORCE_PURE "-DPRISM_TEST_ASSETS=\"$root/assets\"" -I"$root/include" -I"$root/tests"
       -I"$build/tests/snippets" -isystem /usr/include/OpenEXR -isystem /usr/include/Imath
       -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror -include doctest/doctest.h)
failed=0
for compiler in g++ clang++-19; do
  for order in forward reverse; do
    "$compiler" "${flags[@]}" "$work/$order.cpp" >"$work/$compiler-$order.log" 2>&1 &
  done
done
for job in $(jobs -p); do wait "$job" || failed=1; done
for log in "$work"/*.log; do
  if [[ -s $log ]]; then echo "check_unity: $(basename "$log" .log):"; grep -E "error|note" "$log" | head -n 20; fi
done
if [[ $failed -eq 0 ]]; then echo "check_unity: every test file compiles beside every other"; else exit 1; fi
