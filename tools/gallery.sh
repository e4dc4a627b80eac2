#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Render the example gallery: install what is missing, configure, build, run every example.
#   tools/gallery.sh [--quick] [OUT_DIR]      (default: gallery/)
# --quick renders every example small (96 x 64, one sample a pixel): that each runs, in a
# minute (CI), not the pictures.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
size=()
if [[ "${1:-}" == "--quick" ]]; then
  size=(--width 96 --height 64 --spp 1)
  shift
fi
out=$(realpath -m "${1:-gallery}")
"$root/tools/setup.sh"
# A build tree of its own: sharing the test command's would switch its tests off.
# Through ccache where it is installed: a second run rebuilds only what changed.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$root/build/gallery" -G Ninja "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_TESTS=OFF -DPRISM_BUILD_BENCH=OFF >/dev/null
cmake --build "$root/build/gallery" --target examples
mkdir -p "$out"
for example in $(cat "$root/build/gallery/examples/list.txt"); do
  "$root/build/gallery/examples/$example" "${size[@]}" --out "$out"
done
echo "gallery: images in $out"
