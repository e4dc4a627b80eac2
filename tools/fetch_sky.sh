#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copy the sky of the sky example from Debian's blender-data (installed if missing): the
# studio light sunrise.exr, Greg Zaal's HDRI Haven photograph (CC0, as the package's
# studiolights/world/license.txt says), 1024 x 512, DWA-compressed RGB float, as resized
# by Blender. It is checked against its SHA-256 and written as assets/sky/sunrise.exr,
# which is committed (CC0 allows it); this script says where it came from.
#   tools/fetch_sky.sh [OUT.exr]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/assets/sky/sunrise.exr}")
source=/usr/share/blender/datafiles/studiolights/world/sunrise.exr
if [[ ! -f $source ]]; then
  sudo=""
  [[ $(id -u) -ne 0 ]] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq blender-data >/dev/null
fi
echo "b97206217e29763d62d9a65ad2d7058460acfb4824659e7a59f5bde374f21937  $source" | sha256sum --check --quiet
mkdir -p "$(dirname "$out")"
cp "$source" "$out"
echo "wrote $out"
