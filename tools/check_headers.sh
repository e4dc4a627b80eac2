#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Each public header compiles on its own includes (clang 19, -fsyntax-only, -Werror), so
# that a user may include any one of them first: the test builds precompile prism.hpp
# and compile test files eight to a translation unit, which would hide a missing include.
#   tools/check_headers.sh        prints one line per header that fails, and its errors
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
flags=(-std=c++20 -fsyntax-only -DGLM_FORCE_PURE -I"$root/include" -isystem /usr/include/OpenEXR -isystem /usr/include/Imath
       -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror)
if command -v mpicxx >/dev/null; then
  for dir in $(mpicxx --showme:incdirs); do flags+=(-isystem "$dir"); done
fi
export flags_text="${flags[*]}"
cd "$root/include"
headers=$(find prism -name '*.hpp' | sort)
failed=0
for header in $headers; do echo "$header"; done |
  xargs -P "$(nproc)" -I{} sh -c 'echo "#include <{}>" | clang++-19 $flags_text -x c++ - -o /dev/null 2>/tmp/prism-header-$$.log ||
                                   { echo "check_headers: {} does not compile alone:"; head -n 20 /tmp/prism-header-$$.log; exit 1; }; rm -f /tmp/prism-header-$$.log' ||
  failed=1
count=$(echo "$headers" | wc -l)
if [[ $failed -eq 0 ]]; then echo "check_headers: all $count headers compile alone"; else exit 1; fi
