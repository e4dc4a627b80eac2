#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Run the whole test suite: release build with ctest, the same tests under
# AddressSanitizer + UndefinedBehaviorSanitizer, and the meson build's `meson test`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
"$root/tools/setup.sh"

echo "== release build (CMake), all targets =="
cmake -S "$root" -B "$root/build/release" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build/release" -j "$jobs"
ctest --test-dir "$root/build/release" --output-on-failure -j "$jobs"

echo "== address + undefined-behaviour sanitizers =="
cmake -S "$root" -B "$root/build/sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPRISM_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS="-O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" >/dev/null
cmake --build "$root/build/sanitize" -j "$jobs"
ctest --test-dir "$root/build/sanitize" --output-on-failure -j "$jobs"
"$root/build/sanitize/examples/cornell" --width 64 --height 64 --spp 2 --out "$root/build/sanitize/gallery" >/dev/null

echo "== meson =="
if [[ ! -d "$root/build/meson" ]]; then meson setup "$root/build/meson" "$root" >/dev/null; fi
meson test -C "$root/build/meson" --print-errorlogs
