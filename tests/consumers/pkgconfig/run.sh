#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A build without CMake or meson: the consumer program compiled by hand with the flags
# `pkg-config --cflags --libs prism` gives from an installed prefix.
#   run.sh PREFIX WORKDIR CXX [CXXFLAGS...]
set -euo pipefail
prefix=$1 work=$2 cxx=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
export PKG_CONFIG_PATH="$prefix/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
version=$(pkg-config --modversion prism)
flags=$(pkg-config --cflags --libs prism)
echo "pkg-config: prism $version: $flags"
# prism.pc finds its prefix from where it lies (${pcfiledir}), so the prefix can move.
include=$(pkg-config --variable=includedir prism)
[[ $(realpath "$include") == $(realpath "$prefix/include") ]] || { echo "pkg-config: includedir is $include, not $prefix/include" >&2; exit 1; }
mkdir -p "$work"
# shellcheck disable=SC2086 # the flags are words
"$cxx" "$@" "-DPRISM_EXPECTED_VERSION=\"$version\"" "$here/../cmake/main.cpp" -o "$work/consumer" $flags
"$work/consumer"
