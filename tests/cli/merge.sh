#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Parts of a render add up to the whole, bit for bit: `merge.sh MERGE FORGE EXAMPLE ARGS...`
# renders EXAMPLE ARGS (which must take 2 samples or passes) whole, then as parts (crops,
# ranges of passes, on other thread counts), merges them with MERGE and compares the
# PNG bytes (and the PFM's floats, where the example writes PFM); then checks that MERGE refuses parts of different renders, parts that hold
# the same passes twice, and parts that leave a pixel short.
set -euo pipefail
merge=$1 forge=$2 example=$3
shift 3
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
refuses "whole/$image holds no exact sums \(no 'weight.0' channel\): it is not a part of a render" "${out[@]}" "$work/whole/$image"
refuses "unknown option '--bogus'" "${out[@]}" --bogus "$work/top/$image"
refuses "--out FILE.exr is required" "$work/top/$image"

# Regression: an output that names a part would overwrite it; the part stays as it was.
cp "$work/top/$image" "$work/top-before.exr"
refuses "is the part .*: it would be overwritten" --out "$work/top/$image" "$work/top/$image" "$work/top2/$image" "$work/bottom/$image"
ln -s "$work/top/$image" "$work/alias.exr"
refuses "is the part .*: it would be overwritten" --out "$work/alias.exr" "$work/top/$image" "$work/top2/$image" "$work/bottom/$image"
cmp "$work/top/$image" "$work/top-before.exr"
# A part changed after it was written: its prism.part.digest (over its metadata and sums)
# no longer matches what it holds. A part whose passes were edited (to claim passes it
# did not render, or another part's), whose seed was, or whose bytes were damaged.
edit_attribute() { # edit_attribute IN OUT NAME NEW (NEW as long as the old value)
  python3 - "$@" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
key = sys.argv[3].encode() + b'\0string\0'
at = data.index(key) + len(key)
size = int.from_bytes(data[at:at + 4], 'little')
new = sys.argv[4].encode()
assert len(new) == size, (new, size)
open(sys.argv[2], 'wb').write(data[:at + 4] + new + data[at + 4 + size:])
PY
}
edit_attribute "$work/top/$image" "$work/lying.exr" prism.part.passes "0:2"
refuses "lying.exr has prism.part.digest '[0-9a-f]{16}', but what it holds has [0-9a-f]{16}: it was changed after it was written" \
  "${out[@]}" "$work/lying.exr" "$work/bottom/$image"
# Passes 0:1 sent again as 1:2: the weights alone cannot tell (one pass each), the digest can.
edit_attribute "$work/top/$image" "$work/again.exr" prism.part.passes "1:2"
refuses "again.exr has prism.part.digest .*: it was changed after it was written" "${out[@]}" "$work/top/$image" "$work/again.exr" "$work/bottom/$image"
edit_attribute "$work/top/$image" "$work/reseeded.exr" prism.seed "7"
refuses "reseeded.exr has prism.part.digest .*: it was changed after it was written" "${out[@]}" "$work/reseeded.exr" "$work/top2/$image" "$work/bottom/$image"
python3 - "$work/top/$image" "$work/damaged.exr" <<'PY'
import sys
data = bytearray(open(sys.argv[1], 'rb').read())
data[-40] ^= 0x10  # a bit of the last scan lines' compressed pixels
open(sys.argv[2], 'wb').write(bytes(data))
PY
refuses "damaged.exr" "${out[@]}" "$work/damaged.exr" "$work/top2/$image" "$work/bottom/$image"
# A part forged with its digest computed anew (tests/cli/forge_part.cpp): passes a part of
# samples cannot hold, its weights made to agree. The top part's passes 0:1 and 1:2 claimed
# as 0:4, the bottom's 0:2 as 0:4, of --spp 2: every pixel had the four passes the parts
# claimed, and they merged.
if [[ " $* " != *" progressive "* ]]; then
  "$forge" "$work/top/$image" "$work/forged_top.exr" prism.part.passes 0:4 4
  "$forge" "$work/bottom/$image" "$work/forged_bottom.exr" prism.part.passes 0:4 2
  refuses "forged_top.exr says it holds passes 0:4 of prism.spp 2: passes past its samples per pixel" "${out[@]}" "$work/forged_top.exr" "$work/forged_bottom.exr"
  # Its one pass made three samples a pass.
  "$forge" "$work/top/$image" "$work/thrice.exr" prism.part.passes 0:1 3
  refuses "thrice.exr's sums hold 3 samples a pass where a pass is one sample" "${out[@]}" "$work/thrice.exr" "$work/top2/$image" "$work/bottom/$image"
fi
# Two one-pixel parts at opposite corners of a 65536 x 32768 image: refused before the
# hull (2^31 pixels) is allocated.
if [[ $(basename "$example") == cornell ]]; then
  run corner_a "$@" --width 65536 --height 32768 --crop 0,1,0,1
  run corner_b "$@" --width 65536 --height 32768 --crop 65535,65536,32767,32768
  refuses "the parts' crops hold 2 pixels, but they span .*: a crop is missing" "${out[@]}" "$work/corner_a/$image" "$work/corner_b/$image"
fi
echo "merge: refusals hold"
