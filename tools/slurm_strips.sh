#!/bin/bash
# SPDX-License-Identifier: MIT
# A Slurm job array that renders an example in horizontal strips, one a task, for
# prism_merge to stitch (README: "Beyond one machine"). Submit from the repository root:
#   sbatch tools/slurm_strips.sh [EXAMPLE] [FLAGS...]
#   build/release/examples/prism_merge --out EXAMPLE.exr parts/*/EXAMPLE.exr
# Without Slurm, SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT may be set by hand.
# PRISM_BUILD (default build/release, from where the job was submitted) names the build.
#SBATCH --array=0-15
#SBATCH --cpus-per-task=8
set -euo pipefail
example=${1:-cornell_caustics}
shift || true
task=${SLURM_ARRAY_TASK_ID:?set by sbatch --array}
tasks=${SLURM_ARRAY_TASK_COUNT:-16}
y0=$(awk -v i="$task" -v n="$tasks" 'BEGIN { printf "%.6f", i / n }')
y1=$(awk -v i="$task" -v n="$tasks" 'BEGIN { printf "%.6f", (i + 1) / n }')
exec "${PRISM_BUILD:-build/release}/examples/$example" "$@" --threads "${SLURM_CPUS_PER_TASK:-0}" --crop "0.0,1,$y0,$y1" --out "parts/$task"
