#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A render to a time budget, with a preview: `preview.sh CORNELL` runs the cornell example
# (it writes cornell.png and cornell.pfm).
set -euo pipefail
example=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(--width 24 --height 16)

# A budget of half a second out of 2^20 samples a pixel: a prefix of them, said on stdout.
out=$("$example" "${args[@]}" --spp 1048576 --seconds 0.5 --out "$work/budget")
taken=$(sed -n 's/.*24x16, \([0-9]*\) spp, render time.*/\1/p' <<<"$out")
[[ -n $taken && $taken -ge 1 && $taken -lt 1048576 ]] || { echo "unexpected: $out"; exit 1; }
[[ -s "$work/budget/cornell.png" ]]
echo "preview: --seconds 0.5 took $taken of 1048576 samples"

# With --preview, a run that finishes leaves the finished images and no preview.
"$example" "${args[@]}" --spp 8 --preview --out "$work/fine" >/dev/null
[[ -s "$work/fine/cornell.png" && ! -e "$work/fine/cornell.preview.png" ]] || { ls -la "$work/fine"; exit 1; }
echo "preview: removed once the image is written"

# A run whose finished image cannot be written keeps its last preview, a whole PNG (its
# signature), and writes nothing else.
if [[ -w /dev/full ]]; then
  mkdir -p "$work/full"
  ln -s /dev/full "$work/full/cornell.pfm"
  if "$example" "${args[@]}" --spp 8 --preview --out "$work/full" >/dev/null 2>&1; then echo "a write to /dev/full succeeded"; exit 1; fi
  [[ $(head -c 8 "$work/full/cornell.preview.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || { ls -la "$work/full"; exit 1; }
  [[ ! -e "$work/full/cornell.png" ]] || { echo "a failed run wrote its image"; exit 1; }
  echo "preview: a failed run leaves its last preview only"
fi
