#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The ray property bench compiled against the library as it was before issue 10
# (commit 0d25082), for the before/after chart: writes bench/results/ray_property_before.csv.
#   bench/ray_property_before.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(mktemp -d)
trap 'rm -rf "$old"' EXIT
git -C "$root" archive 0d25082 include | tar -x -C "$old"
g++ -std=c++20 -O2 -DNDEBUG -DGLM_FORCE_PURE -I"$old/include" "$root/bench/ray_property.cpp" -o "$old/ray_property"
"$old/ray_property" "$old" "${1:-42000}" | tail -n 3
mv "$old/ray_property.csv" "$root/bench/results/ray_property_before.csv"
