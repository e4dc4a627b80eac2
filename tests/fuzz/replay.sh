#!/bin/sh
# SPDX-License-Identifier: MIT
# replay.sh TMP PROGRAM ARGS...: run a fuzz target's corpus replay (tests/fuzz/driver.cpp)
# with its temporary files in the folder TMP, emptied first, and fail if it leaves any there.
set -eu
tmp=$1
shift
rm -rf "$tmp"
mkdir -p "$tmp"
TMPDIR=$tmp "$@"
left=$(ls -A "$tmp")
if [ -n "$left" ]; then
  echo "replay: $1 left files behind in $tmp: $left" >&2
  exit 1
fi
