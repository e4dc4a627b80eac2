#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install what prism needs from Debian, if anything is missing.
#   tools/setup.sh          build, test and example needs
#   tools/setup.sh --bench  also POV-Ray, Blender (Cycles, about 700 MB), nanoflann, matplotlib and PIL, for bench/
set -euo pipefail
packages=(g++ cmake ninja-build meson pkgconf python3 doxygen libglm-dev doctest-dev libstb-dev colord-data libtinyobjloader-dev libopenexr-dev openexr libopenmpi-dev openmpi-bin clang-19 libclang-rt-19-dev ccache libc++-19-dev libc++abi-19-dev)
if [[ "${1:-}" == "--bench" ]]; then packages+=(povray blender python3-matplotlib python3-pil libnanoflann-dev libembree-dev); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: missing ${missing[*]}; install them as root" >&2; exit 1; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq "${missing[@]}" >/dev/null
