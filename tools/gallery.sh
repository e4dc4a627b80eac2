#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Render the example gallery: install what is missing, configure, build, run every example.
#   tools/gallery.sh [OUT_DIR]      (default: gallery/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-gallery}")
"$root/tools/setup.sh"
cmake -S "$root" -B "$root/build/release" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_TESTS=OFF >/dev/null
cmake --build "$root/build/release" --target examples
mkdir -p "$out"
for example in $(cat "$root/build/release/examples/list.txt"); do
  "$root/build/release/examples/$example" --out "$out"
done
echo "gallery: images in $out"
