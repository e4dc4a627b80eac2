#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Each test file compiles on its own includes (clang 19, -fsyntax-only, -Werror). The test
# builds precompile prism.hpp and compile eight files to a translation unit, which would
# hide a file (or a header it includes) that forgot an include; -fsyntax-only still
# instantiates every template the file uses, so a header whose templates call what it does
# not include fails here, as it would in a user's program.
#   tools/check_tests_alone.sh [SNIPPETS_DIR]   (default build/release/tests/snippets, the
#                                               documentation's headers that the release
#                                               build extracts)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
snippets=$(realpath -m "${1:-$root/build/release/tests/snippets}")
[[ -d $snippets ]] || { echo "check_tests_alone: $snippets does not exist (configure a build with tests first)" >&2; exit 1; }
flags=(-std=c++20 -fsyntax-only -DGLM_FORCE_PURE -DPRISM_TEST_ASSETS=\"$root/assets\" -I"$root/include" -I"$snippets"
       -isystem /usr/include/OpenEXR -isystem /usr/include/Imath
       -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror)
export flags_text="${flags[*]}"
cd "$root/tests"
files=$(find . -mindepth 2 -name '*.cpp' -not -path './fuzz/*' -not -path './consumers/*' -not -path './compile_fail/*' -not -path './snippets/*' | sort)
failed=0
echo "$files" | xargs -P "$(nproc)" -I{} sh -c 'clang++-19 $flags_text {} 2>/tmp/prism-alone-$$.log ||
                                               { echo "check_tests_alone: {} does not compile alone:"; head -n 20 /tmp/prism-alone-$$.log; exit 1; }; rm -f /tmp/prism-alone-$$.log' ||
  failed=1
count=$(echo "$files" | wc -l)
if [[ $failed -eq 0 ]]; then echo "check_tests_alone: all $count test files compile alone"; else exit 1; fi
