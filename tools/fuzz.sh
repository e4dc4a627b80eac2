#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzz prism with libFuzzer (clang 19, Debian: clang-19 libclang-rt-19-dev), one target
# per core at a time, under AddressSanitizer and UndefinedBehaviorSanitizer with
# PRISM_ASSERT active:
#   tools/fuzz.sh [SECONDS]          each target for SECONDS (default 30)
#   tools/fuzz.sh --budget SECONDS   all targets fuzzed within about SECONDS of wall time (their
#                                    builds aside), one per core at a time, each an equal share
#                                    (the full tier: 120)
#   tools/fuzz.sh --runs N           each target for N inputs, however long it takes (the long
#                                    campaigns: 1000000; docs/contributing.md has the last)
#   tools/fuzz.sh ... TARGET...      only the targets named (e.g. --runs 1000000 obj mtl)
# Targets (tests/fuzz/): quadric (crossings of any ten coefficients), csg (trees of
# every operator), photon_map (the KD-tree against brute force, the estimates), and the
# file readers pfm, png, jpeg, hdr, density (a density grid), ply, obj, mtl (an OBJ's
# material library) and exr (any bytes as a file; exr as prism_merge reads a part). Each
# starts from its committed corpus, tests/fuzz/corpus/<target>/, and the inputs that broke
# it before a fix, tests/fuzz/regressions/<target>/ (everything the builds' corpus replays
# run, under the same sanitizers), and writes what it
# finds into build/fuzz/<target>/ (copy inputs worth keeping into the corpus); a crash
# leaves its input as build/fuzz/crash-<target>-*, and the script fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets=(quadric csg photon_map pfm png jpeg hdr density ply obj mtl exr)
cores=$(nproc)
seconds=30 runs=-1
budget=-1
case "${1:-}" in
  --budget) budget=${2:?--budget takes seconds}; shift 2 ;;
  --runs) runs=${2:?--runs takes a count} seconds=0; shift 2 ;;
  "") ;;
  *) if [[ $1 =~ ^[0-9]+$ ]]; then seconds=$1; shift; fi ;;
esac
if (( $# > 0 )); then
  for target in "$@"; do
    [[ " ${targets[*]} " == *" $target "* ]] || { echo "fuzz: no target '$target' (the targets: ${targets[*]})" >&2; exit 2; }
  done
  targets=("$@")
fi
if (( budget >= 0 )); then
  seconds=$(( budget * cores / ${#targets[@]} ))
  (( seconds < 5 )) && seconds=5
fi
out="$root/build/fuzz"
mkdir -p "$out"
flags=(-std=c++20 -O1 -g1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -DPRISM_ENABLE_ASSERTIONS
       -DGLM_FORCE_PURE -I"$root/include")
# fuzz_one TARGET: build it, fuzz it, and leave a line (or a failure and its log) in
# build/fuzz/TARGET.report.
fuzz_one() {
  local target=$1 report="$out/$1.report"
  mkdir -p "$out/$target" "$root/tests/fuzz/corpus/$target"
  local libraries=() max_len=512
  [[ $target == obj || $target == mtl ]] && libraries=(-ltinyobjloader)
  # An EXR part is a few KB; OpenEXR's library, and each run's malloc at most 512 MB.
  [[ $target == exr ]] && libraries=($(pkg-config --cflags --libs OpenEXR)) max_len=8192
  if ! clang++-19 "${flags[@]}" "$root/tests/fuzz/$target.cpp" -o "$out/fuzz_$target" "${libraries[@]}" >"$out/$target.log" 2>&1; then
    { echo "fuzz: $target FAILED to build:"; tail -n 40 "$out/$target.log"; } >"$report"
    return 0
  fi
  local begin=$(date +%s)
  # The file readers' targets write each input to a file of their own: in the build tree,
  # removed when the run ends.
  local tmp="$out/tmp/$target"
  rm -rf "$tmp" && mkdir -p "$tmp"
  local seeds=("$root/tests/fuzz/corpus/$target")
  [[ -d $root/tests/fuzz/regressions/$target ]] && seeds+=("$root/tests/fuzz/regressions/$target")
  if ! TMPDIR="$tmp" "$out/fuzz_$target" "$out/$target" "${seeds[@]}" -max_total_time="$seconds" -runs="$runs" -max_len="$max_len" -malloc_limit_mb=512 \
       -artifact_prefix="$out/crash-$target-" -print_final_stats=1 >"$out/$target.log" 2>&1; then
    { echo "fuzz: $target FAILED; its log ends:"; tail -n 40 "$out/$target.log"; } >"$report"
    return 0
  fi
  if [[ -n $(ls -A "$tmp") ]]; then
    echo "fuzz: $target FAILED: it left $(ls -A "$tmp") behind in $tmp" >"$report"
    return 0
  fi
  local executed
  executed=$(grep -E "stat::number_of_executed_units" "$out/$target.log" | awk '{print $2}')
  echo "fuzz: $target: ${executed:-?} inputs in $(( $(date +%s) - begin )) s, corpus $(ls "$out/$target" "$root/tests/fuzz/corpus/$target" | grep -vc ':$\|^$')" >"$report"
}

# One target per core at a time.
rm -f "$out"/*.report
for target in "${targets[@]}"; do
  while (( $(jobs -rp | wc -l) >= cores )); do wait -n || true; done
  fuzz_one "$target" &
done
wait
status=0
for target in "${targets[@]}"; do
  cat "$out/$target.report" 2>/dev/null || echo "fuzz: $target FAILED: no report"
  grep -q FAILED "$out/$target.report" 2>/dev/null && status=1
done
exit $status
