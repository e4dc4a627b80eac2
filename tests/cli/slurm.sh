#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/slurm_strips.sh as Slurm would run it, without Slurm: `slurm.sh BUILD MERGE`
# renders cornell in 3 strips (SLURM_ARRAY_TASK_ID 0 to 2), merges them with MERGE and
# compares the PNG bytes with the whole render.
set -euo pipefail
build=$1 merge=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for task in 0 1 2; do
  PRISM_BUILD=$build SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1 \
    "$root/tools/slurm_strips.sh" cornell --width 64 --height 48 --spp 2 >/dev/null
done
"$merge" --out merged.exr --png merged.png parts/*/cornell.exr >/dev/null
"$build/examples/cornell" --width 64 --height 48 --spp 2 --out whole >/dev/null
cmp merged.png whole/cornell.png
echo "slurm: 3 strips merge to the whole render"
