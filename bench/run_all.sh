#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Run every measurement and draw the charts into bench/results (about an hour: the
# photon accuracy and methods-against-time runs take most of it).
#   bench/run_all.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
results="$root/bench/results"
"$root/tools/setup.sh" --bench
cmake -S "$root" -B "$root/build/release" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build/release"
mkdir -p "$results"
# Debian's python3 has matplotlib; a python3 earlier on PATH may not.
python=/usr/bin/python3
"$python" "$root/bench/vs_povray.py" --build "$root/build/release" --out "$results" | tee "$results/vs_povray.txt"
"$python" "$root/bench/compile_cost.py" --out "$results" | tee "$results/compile_cost.txt"
"$root/build/release/bench/bench_acne" "$results" > "$results/acne.txt"
"$root/build/release/bench/bench_quadric_roots" "$results" | tee "$results/quadric_roots.txt"
"$root/build/release/bench/bench_csg_composition" "$results" | tee "$results/csg_composition.txt"
"$root/build/release/bench/bench_kdtree" "$results" | tee "$results/kdtree.txt"
"$root/build/release/bench/bench_bvh_vs_embree" "$results" 5 "$root/assets/bunny.obj" | tee "$results/bvh_vs_embree.txt"
"$root/build/release/bench/bench_bvh_vs_embree" "$results" 5 "$root/assets/bunny.obj" sse4.2 | tee "$results/bvh_vs_embree_sse4.2.txt"
if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
  "$root/build/release/bench/bench_bvh_vs_embree_avx2" "$results" 5 "$root/assets/bunny.obj" | tee "$results/bvh_vs_embree_prism-avx2.txt"
  "$root/build/release/bench/bench_bvh_vs_embree_avx2" "$results" 5 "$root/assets/bunny.obj" avx2 | tee "$results/bvh_vs_embree_prism-avx2_avx2.txt"
  # prism for this machine's own instruction set, against Embree as it comes.
  if [[ -x "$root/build/release/bench/bench_bvh_vs_embree_native" ]]; then
    "$root/build/release/bench/bench_bvh_vs_embree_native" "$results" 5 "$root/assets/bunny.obj" | tee "$results/bvh_vs_embree_prism-native.txt"
  fi
  # What spatial splits, robust mode and packets are worth to Embree, beside prism's mesh.
  "$python" "$root/bench/mesh_peers.py" "$root/build/release/bench/bench_mesh_rays" "$root/assets/bunny.obj" 3 --out "$results/mesh_peers.csv" | tee "$results/mesh_peers.txt"
  "$python" "$root/bench/mesh_peers.py" --plot "$results/mesh_peers.csv" "$results/mesh_peers.png"
fi
"$root/build/release/bench/bench_bvh_quality" "$results" 3 | tee "$results/bvh_quality.txt"
"$root/build/release/bench/bench_accuracy" "$results" | tee "$results/accuracy.txt"
"$root/build/release/bench/bench_shadow_saving" "$results" | tee "$results/shadow_saving.txt"
"$root/build/release/bench/bench_ray_property" "$results" | tee "$results/ray_property.txt"
"$root/build/release/bench/bench_graded_index" "$results" | tee "$results/graded_index.txt"
"$root/build/release/bench/bench_dispersion" "$results" | tee "$results/dispersion.txt"
"$root/build/release/bench/bench_thin_film" "$results" | tee "$results/thin_film.txt"
"$root/build/release/bench/bench_photon_stage" "$results" | tee "$results/photon_stage.txt"
"$root/build/release/bench/bench_whitted_glossy" "$results" | tee "$results/whitted_glossy.txt"
"$root/build/release/bench/bench_prism_haze" "$results" | tee "$results/prism_haze.txt"
"$python" "$root/bench/methods_vs_time.py" "$root/build/release" | tee "$results/methods_vs_time.txt"
"$python" "$root/bench/cycles_agreement.py" "$root/build/release" | tee "$results/cycles_agreement.txt"
"$python" "$root/bench/surfaces_vs_time.py" "$root/build/release" | tee "$results/surfaces_vs_time.txt"
"$python" "$root/bench/photon_accuracy.py" --build "$root/build/release" --out "$results" | tee "$results/photon_accuracy.txt"
"$python" "$root/bench/mpi_scaling.py" --build "$root/build/release" --out "$results" | tee "$results/mpi_scaling.txt"
"$python" "$root/bench/plot.py" "$results"
