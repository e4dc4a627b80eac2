#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A CLI refusal: `refuses.sh PATTERN PROGRAM ARGS...` passes when PROGRAM exits non-zero
# at once with a one-line message on stderr that matches PATTERN, and wrote no image.
set -u
pattern=$1
shift
out=$(mktemp -d)
program=$1
shift
stderr=$("$program" --out "$out" "$@" 2>&1 >/dev/null) # a later --out in ARGS overrides
status=$?
images=$(find "$out" -name '*.png' -o -name '*.pfm' -o -name '*.exr' | wc -l)
rm -rf "$out"
lines=$(printf '%s\n' "$stderr" | grep -c .)
echo "exit $status, $lines line(s) on stderr, $images image(s): $stderr"
[[ $status -ne 0 && $lines -eq 1 && $images -eq 0 ]] && grep -qE -- "$pattern" <<<"$stderr"
