#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# An example's outputs are checked before it renders and written all or none:
# `outputs.sh CORNELL` runs the cornell example (it writes cornell.png and
# cornell.pfm) into folders where one of its outputs cannot be written.
set -euo pipefail
example=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(--width 16 --height 12 --spp 1)

# An image's name taken by a directory: refused before rendering, in one line.
mkdir -p "$work/taken/cornell.png"
if message=$("$example" "${args[@]}" --out "$work/taken" 2>&1); then echo "accepted a directory as its image"; exit 1; fi
grep -q "is a directory, where the example writes its image" <<<"$message" || { echo "unexpected: $message"; exit 1; }
grep -q "render time" <<<"$message" && { echo "rendered before refusing: $message"; exit 1; }
echo "outputs: refused before rendering: $message"

# The PFM goes to /dev/full: the run fails, and leaves no PNG beside it, nor a temporary.
if [[ -w /dev/full ]]; then
  mkdir -p "$work/full"
  ln -s /dev/full "$work/full/cornell.pfm"
  if message=$("$example" "${args[@]}" --out "$work/full" 2>&1); then echo "a write to /dev/full succeeded"; exit 1; fi
  grep -q "cornell.pfm.*No space left on device" <<<"$message" || { echo "unexpected: $message"; exit 1; }
  leftovers=$(find "$work/full" -name '*.png' -o -name '*prism-partial*' | wc -l)
  [[ $leftovers -eq 0 ]] || { echo "a failed run left $leftovers file(s)"; ls -la "$work/full"; exit 1; }
  echo "outputs: a failed write left no partial set: $(grep "error:" <<<"$message")"
fi

# And where every output can be written, both are.
"$example" "${args[@]}" --out "$work/fine" >/dev/null 2>&1
[[ -s "$work/fine/cornell.png" && -s "$work/fine/cornell.pfm" ]]
echo "outputs: written together"
