#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Run prism's tests, in two tiers.
#
#   tools/test.sh          the quick tier, minutes on 2 cores:
#     release   g++ 12 and libstdc++, Release (-O2) with PRISM_ASSERT active: every doctest
#               case once (a ctest test each), the documentation's snippets, the fuzz
#               targets' corpora, the single-header, version, dependency and link checks,
#               the consumer projects, the compile-error checks
#     headers   each public header compiled alone (tools/check_headers.sh)
#     docs      the API reference (Doxygen, tools/docs.sh), failing on any warning
#     meson     a project taking prism as a meson subproject, and the single-header check
#
#   tools/test.sh --full   the quick tier, then:
#     long      in the release tree, the cases too long for the quick tier (ctest label
#               `full`: 10^7 hostile rays) and the examples' command line, render-farm
#               merges and MPI ranks (label `cli`)
#     sanitize  clang 19, AddressSanitizer + UndefinedBehaviorSanitizer, assertions on, the
#               portable paths (no __int128, no vector extensions), the plain build: each
#               test file its own translation unit, nothing precompiled, so each compiles on
#               its own includes (the other builds compile sixteen files to a translation
#               unit, which would hide a missing include); every case, with the statistical
#               ones on fewer samples (tests/effort.hpp), and a small render
#               (the consumer projects that build with the default g++, label `consumer`,
#               run in the release tree only, here and in the thread tree)
#     thread    clang 19 and libc++, ThreadSanitizer, -O2, AVX2 where the CPU has it
#               (Bvh<float>'s 8-wide nodes), assertions off as in a user's release build:
#               every case and the command-line tests, then renders on 2 threads
#     meson     also builds the examples with meson
#     fuzz      each libFuzzer target (tests/fuzz/) for its share of a fixed budget
#               (tools/fuzz.sh --budget), under ASan + UBSan, from its corpus and its
#               regression inputs (so the sanitize tree replays neither itself)
#
# Builds go through ccache where it is installed (tools/setup.sh installs it). Every CMake
# build treats a warning as an error. Each step's output goes to build/logs/; a failing step
# prints the end of its log. tools/slowest_tests.py prints the slowest cases of the last
# run. The last line sums up the cases of every run: "test: N passed, N failed".
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
full=0
case "${1:-}" in
  "") ;;
  --full) full=1 ;;
  *) echo "usage: tools/test.sh [--full]" >&2; exit 2 ;;
esac
jobs=$(nproc)
logs="$root/build/logs"
"$root/tools/setup.sh" || exit 1
mkdir -p "$logs"

# ccache. The release tree precompiles no header: with test files eight to a translation
# unit (sixteen now), prism.hpp precompiled saved nothing (352 s without, 381 s with), and a header
# precompiled anew is never the same bytes twice, so ccache missed every test batch after
# build/ was removed; without it a warm build takes seconds. (The thread tree keeps it: not
# yet timed without. The sanitizers' tree is the plain build, which precompiles nothing.)
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  # Paths inside the checkout hashed as relative ones: another clone shares the cache.
  export CCACHE_BASEDIR="$root"
  ccache --zero-stats >/dev/null 2>&1 || true
fi

passed=0 failed=0 summary=()
# step NAME COMMAND...: run quietly into build/logs/NAME.log; show the log if it fails.
step() {
  local name=$1
  shift
  local begin=$(date +%s)
  if ! "$@" >"$logs/$name.log" 2>&1; then
    echo "test: step '$name' failed after $(( $(date +%s) - begin )) s; its log ($logs/$name.log) ends:" >&2
    tail -n 60 "$logs/$name.log" >&2
    return 1
  fi
  echo "test: $name took $(( $(date +%s) - begin )) s"
}
# count RUN LOG: add the cases passed and failed that LOG, a ctest log, reports.
count() {
  local run=$1 log=$2 p f
  if line=$(grep -E "tests passed, [0-9]+ tests? failed out of [0-9]+" "$log" | tail -n 1); then
    f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
    p=$(( $(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line") - f ))
  else
    p=0 f=1
  fi
  passed=$((passed + p)) failed=$((failed + f))
  summary+=("$run $p/$((p + f))")
  echo "test: $run: $p passed, $f failed"
}
fail() { failed=$((failed + 1)); summary+=("$1 FAILED"); echo "test: $1: failed"; }
# ctest_step RUN BUILD_DIR [CTEST ARGS...]: run ctest in BUILD_DIR, count its cases, and on a
# failure print the failed cases' output.
ctest_step() {
  local run=$1 dir=$2 begin=$(date +%s)
  shift 2
  ctest --test-dir "$dir" -j "$jobs" "$@" >"$logs/$run-ctest.log" 2>&1 ||
    ctest --test-dir "$dir" --rerun-failed --output-on-failure 2>&1 | tail -n 80
  echo "test: $run ctest took $(( $(date +%s) - begin )) s"
  count "$run" "$logs/$run-ctest.log"
}

start=$(date +%s)

# Release with assertions: the tests sixteen files to a translation unit; no examples
# (tools/gallery.sh builds them, the full tier tests their command line).
release="$root/build/release"
if step release-build bash -c "cmake -S '$root' -B '$release' -G Ninja ${launcher[*]} -DCMAKE_BUILD_TYPE=Release '-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG' \
      -DPRISM_BUILD_TESTS=ON -DPRISM_BUILD_BENCH=OFF -DPRISM_ASSERTIONS=ON -DPRISM_WERROR=ON -DPRISM_TESTS_PCH=OFF -DPRISM_TESTS_UNITY=ON &&
      cmake --build '$release' -j $jobs --target prism_tests test_programs"; then
  ctest_step release "$release" -LE 'full|cli'
else
  fail release
fi

# Each public header on its own includes (the builds compile sixteen test files together).
if step headers "$root/tools/check_headers.sh"; then
  passed=$((passed + 1)) summary+=("headers ok")
else
  fail headers
fi

# The API reference (Doxygen): any warning about a comment fails.
if step docs "$root/tools/docs.sh"; then
  passed=$((passed + 1)) summary+=("docs ok")
else
  fail docs
fi

# Meson: a consumer project taking prism as a subproject, and the single-header check (the
# suite itself is the CMake builds' above); the full tier also builds meson's examples.
meson_dir="$root/build/meson"
rebuild=--no-rebuild
[[ $full -eq 1 ]] && rebuild=""
if step meson-setup bash -c "[[ -d '$meson_dir' ]] || meson setup '$meson_dir' '$root'"; then
  if meson test -C "$meson_dir" $rebuild --print-errorlogs >"$logs/meson-test.log" 2>&1 && grep -qE "^Fail: +0 *$" "$logs/meson-test.log"; then
    p=$(sed -nE 's/^Ok: +([0-9]+) *$/\1/p' "$logs/meson-test.log")
    passed=$((passed + p)) summary+=("meson $p/$p")
    echo "test: meson: $p passed, 0 failed"
  else
    tail -n 60 "$logs/meson-test.log"
    fail meson
  fi
else
  fail meson
fi

if [[ $full -eq 1 ]]; then
  # The long cases and the examples' command line, merges and MPI ranks, in the release
  # tree above.
  if step long-build cmake --build "$release" -j "$jobs" --target full_test_programs cli_examples; then
    ctest_step long "$release" -L 'full|cli'
  else
    fail long
  fi

  # Address + undefined-behaviour sanitizers (clang 19, libstdc++), assertions on, and the
  # portable paths: the exact sums in two 64-bit words instead of __int128, and the BVH's
  # and triangle blocks' scalar twins instead of vector extensions. Line tables only (-g1:
  # a third less compile time than -g), and only the examples the tests run. The plain
  # build, as a user configures it: each test file alone, so a missing include fails here
  # (its test files cost 1350 s of compiler against 1020 s in batches of eight with
  # prism.hpp precompiled, less than the separate check of each file it replaces).
  sanitize="$root/build/sanitize"
  if step sanitize-build bash -c "cmake -S '$root' -B '$sanitize' -G Ninja ${launcher[*]} -DCMAKE_CXX_COMPILER=clang++-19 -DCMAKE_BUILD_TYPE=Debug -DPRISM_BUILD_BENCH=OFF \
        -DPRISM_ASSERTIONS=ON -DPRISM_WERROR=ON -DPRISM_TESTS_PCH=OFF -DPRISM_TESTS_UNITY=OFF -DPRISM_TESTS_FUZZ_CORPORA=OFF -DCMAKE_CXX_FLAGS_DEBUG=-g1 \
        -DCMAKE_CXX_FLAGS='-O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -DPRISM_PORTABLE_INT128 -DPRISM_NO_VECTOR_EXTENSIONS' &&
        cmake --build '$sanitize' -j $jobs --target prism_tests cli_examples test_programs"; then
    ctest_step sanitize "$sanitize" -LE 'full|consumer'
    step sanitize-render "$sanitize/examples/cornell" --width 64 --height 64 --spp 2 --out "$sanitize/gallery" || fail sanitize-render
  else
    fail sanitize
  fi

  # ThreadSanitizer with clang 19 and libc++, -O2 with line tables, AVX2 where the CPU has
  # it: the other runs take libstdc++ and the baseline's 4-wide Bvh nodes, this one libc++
  # and Bvh<float>'s 8-wide nodes. Assertions off, NDEBUG, as a user's release build: the
  # other runs keep them on. Every case and the command-line tests, then renders on 2
  # threads.
  thread="$root/build/thread"
  export TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1"
  avx2=""
  grep -qw avx2 /proc/cpuinfo && avx2=-mavx2
  if step thread-build bash -c "cmake -S '$root' -B '$thread' -G Ninja ${launcher[*]} -DCMAKE_CXX_COMPILER=clang++-19 -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_BUILD_BENCH=OFF \
        -DPRISM_WERROR=ON -DPRISM_TESTS_PCH=ON -DPRISM_TESTS_UNITY=ON \
        '-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG' '-DCMAKE_CXX_FLAGS=-fsanitize=thread -stdlib=libc++ $avx2' &&
        cmake --build '$thread' -j $jobs --target prism_tests test_programs cli_examples"; then
    ctest_step thread "$thread" -LE 'full|consumer'
    step thread-render-whitted "$thread/examples/cornell" --width 96 --height 96 --spp 2 --threads 2 --out "$thread/gallery" || fail thread-render-whitted
    step thread-render-photons "$thread/examples/cornell_caustics" --width 64 --height 64 --spp 1 --threads 2 --photons 20000 \
      --caustic-photons 20000 --gather 4 --out "$thread/gallery" || fail thread-render-photons
  else
    fail thread
  fi

  # libFuzzer (clang) under ASan + UBSan: the targets (tests/fuzz/) share a fixed budget,
  # each from its committed corpus; a crash fails the run and leaves its input in build/fuzz/.
  if step fuzz "$root/tools/fuzz.sh" --budget 60; then
    grep "^fuzz:" "$logs/fuzz.log"
    passed=$((passed + 1)) summary+=("fuzz ok")
  else
    fail fuzz
  fi
fi

command -v ccache >/dev/null && ccache --show-stats 2>/dev/null | grep -E "Hits|Misses" | head -n 3 | sed 's/^/test: ccache /'
echo "test: ${summary[*]} in $(( $(date +%s) - start )) s"
echo "test: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
