#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build and run the meson consumer in a scratch folder: run.sh BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$1"
meson setup "$1" "$here" >/dev/null
meson test -C "$1" --print-errorlogs
