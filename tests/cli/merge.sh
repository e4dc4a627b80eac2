#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Parts of a render add up to the whole, bit for bit: `merge.sh MERGE EXAMPLE ARGS...`
# renders EXAMPLE ARGS (which must take 2 samples or passes) whole, then as parts (crops,
# ranges of passes, on other thread counts), merges them with MERGE and compares the
# PNG bytes (and the PFM's floats, where the example writes PFM); then checks that MERGE refuses parts of different renders, parts that hold
# the same passes twice, and parts that leave a pixel short.
set -euo pipefail
merge=$1 example=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name() { basename "$(ls "$1"/*.exr | head -n 1)"; }
run() { local out=$1; shift; mkdir -p "$work/$out"; "$example" "$@" --out "$work/$out" >/dev/null 2>&1; }

run whole "$@" --exr --threads 2
run top "$@" --crop 0.0,1,0,0.5 --passes 0:1 --threads 1
run top2 "$@" --crop 0.0,1,0,0.5 --passes 1:2 --threads 2
run bottom "$@" --crop 0.0,1,0.5,1 --passes 0:2 --threads 2
image=$(name "$work/whole")
"$merge" --out "$work/merged.exr" --png "$work/merged.png" --pfm "$work/merged.pfm" "$work/top/$image" "$work/bottom/$image" "$work/top2/$image" >/dev/null
cmp "$work/merged.png" "$work/whole/${image%.exr}.png"
# The exact floats too, where the example writes PFM.
if [[ -e "$work/whole/${image%.exr}.pfm" ]]; then cmp "$work/merged.pfm" "$work/whole/${image%.exr}.pfm"; fi
echo "merge: parts add up to the whole render ($image)"

# Refusals: one line naming the reason, non-zero exit.
refuses() {
  local pattern=$1
  shift
  if message=$("$merge" "$@" 2>&1 >/dev/null); then echo "merge accepted $*"; exit 1; fi
  [[ $(printf '%s\n' "$message" | grep -c .) -eq 1 ]] || { echo "not one line: $message"; exit 1; }
  grep -qE -- "$pattern" <<<"$message" || { echo "'$message' does not match '$pattern'"; exit 1; }
  [[ ! -e "$work/refused.exr" ]] || { echo "a refused merge wrote its output"; exit 1; }
  echo "merge refuses: $message"
}
run seeded "$@" --crop 0.0,1,0.5,1 --passes 0:2 --seed 77
out=(--out "$work/refused.exr")
refuses "has prism.seed '77'.*has '0': not parts of one render" "${out[@]}" "$work/top/$image" "$work/top2/$image" "$work/seeded/$image"
refuses "hold the same passes of some pixels" "${out[@]}" "$work/top/$image" "$work/top/$image"
refuses "has 1 of the passes 0:2 the parts hold: a crop or a range of passes is missing" "${out[@]}" "$work/top/$image" "$work/bottom/$image"
refuses "has no UINT channel|has no 'prism.part.passes'" "${out[@]}" "$work/whole/$image"
refuses "unknown option '--bogus'" "${out[@]}" --bogus "$work/top/$image"
refuses "--out FILE.exr is required" "$work/top/$image"
