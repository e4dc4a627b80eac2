#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Run the whole test suite, five ways, on two compilers and two standard libraries:
#   release   g++ 12 and libstdc++, Release: every doctest case as a ctest test, plus the
#             single-header check, the consumer projects and the command-line tests
#   sanitize  clang 19 and libstdc++, the same cases under AddressSanitizer +
#             UndefinedBehaviorSanitizer, with PRISM_ASSERT kept active, on the portable
#             paths (no __int128, no vector extensions), and a small render
#   thread    clang 19 and libstdc++, the same cases under ThreadSanitizer, with
#             PRISM_ASSERT active, and 2-thread renders (Whitted and photon mapping)
#   libc++    clang 19 and libc++, Release, for AVX2 where the CPU has it (so the suite
#             also runs with Bvh<float>'s 8-wide nodes): every case, the examples and the
#             command-line tests (without OpenEXR, tinyobjloader and MPI, which Debian
#             builds for libstdc++)
#   headers   each public header compiled alone (tools/check_headers.sh)
#   docs      the API reference (Doxygen, tools/docs.sh), failing on any warning
#   fuzz      each libFuzzer target (tests/fuzz/) for 60 s, under ASan + UBSan
# and the meson build's own test (a consumer project takes prism as a subproject).
# Every CMake build treats a warning as an error (-Wall -Wextra -Wpedantic and more, -Werror).
# Build output goes to build/logs/; a failing step prints its log. The last line sums up
# the cases of every run: "test: N passed, N failed".
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
logs="$root/build/logs"
"$root/tools/setup.sh" || exit 1
mkdir -p "$logs"

passed=0 failed=0 summary=()
# step NAME COMMAND...: run quietly into build/logs/NAME.log; show the log if it fails.
step() {
  local name=$1
  shift
  if ! "$@" >"$logs/$name.log" 2>&1; then
    echo "test: step '$name' failed; its log ($logs/$name.log) ends:" >&2
    tail -n 60 "$logs/$name.log" >&2
    return 1
  fi
}
# count RUN LOG: add the cases passed and failed that LOG reports (ctest or doctest).
count() {
  local run=$1 log=$2 p f
  if line=$(grep -E "tests passed, [0-9]+ tests? failed out of [0-9]+" "$log" | tail -n 1); then
    f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
    p=$(( $(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line") - f ))
  elif line=$(grep -E "\[doctest\] test cases:" "$log" | tail -n 1); then
    p=$(sed -E 's/.*\| *([0-9]+) passed.*/\1/' <<<"$line")
    f=$(sed -E 's/.*\| *([0-9]+) failed.*/\1/' <<<"$line")
  else
    p=0 f=1
  fi
  passed=$((passed + p)) failed=$((failed + f))
  summary+=("$run $p/$((p + f))")
  echo "test: $run: $p passed, $f failed"
}
fail() { failed=$((failed + 1)); summary+=("$1 FAILED"); echo "test: $1: failed"; }

start=$(date +%s)

# Release: no benches (they are not tests); the tests, in every build, with prism.hpp
# precompiled and eight files to a translation unit (tools/check_headers.sh then checks
# that each header compiles on its own includes).
release="$root/build/release"
if step release-build bash -c "cmake -S '$root' -B '$release' -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_TESTS=ON -DPRISM_BUILD_BENCH=OFF -DPRISM_WERROR=ON -DPRISM_TESTS_PCH=ON -DPRISM_TESTS_UNITY=ON &&
                                cmake --build '$release' -j $jobs"; then
  ctest --test-dir "$release" -j "$jobs" >"$logs/release-ctest.log" 2>&1 ||
    ctest --test-dir "$release" --rerun-failed --output-on-failure 2>&1 | tail -n 80
  count release "$logs/release-ctest.log"
else
  fail release
fi

# Address + undefined-behaviour sanitizers (clang 19, libstdc++), assertions on, and the
# portable paths: the exact sums in two 64-bit words instead of __int128, and the BVH's
# and triangle blocks' scalar twins instead of vector extensions.
sanitize="$root/build/sanitize"
# Line tables only (-g1: a third less compile time than -g), the tests with prism.hpp
# precompiled, and only the examples the tests run.
if step sanitize-build bash -c "cmake -S '$root' -B '$sanitize' -G Ninja -DCMAKE_CXX_COMPILER=clang++-19 -DCMAKE_BUILD_TYPE=Debug -DPRISM_BUILD_BENCH=OFF -DPRISM_ASSERTIONS=ON -DPRISM_WERROR=ON \
      -DPRISM_TESTS_PCH=ON -DPRISM_TESTS_UNITY=ON -DCMAKE_CXX_FLAGS_DEBUG=-g1 \
      -DCMAKE_CXX_FLAGS='-O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -DPRISM_PORTABLE_INT128 -DPRISM_NO_VECTOR_EXTENSIONS' &&
      cmake --build '$sanitize' -j $jobs --target prism_tests cli_examples test_programs"; then
  ctest --test-dir "$sanitize" -j "$jobs" >"$logs/sanitize-ctest.log" 2>&1 ||
    ctest --test-dir "$sanitize" --rerun-failed --output-on-failure 2>&1 | tail -n 80
  count sanitize "$logs/sanitize-ctest.log"
  step sanitize-render "$sanitize/examples/cornell" --width 64 --height 64 --spp 2 --out "$sanitize/gallery" || fail sanitize-render
else
  fail sanitize
fi

# ThreadSanitizer (clang 19, libstdc++), assertions on, -O2 with line tables: the test
# cases in two processes at once (the photon and integrator files, about half the time,
# and the rest), then renders on 2 threads.
thread="$root/build/thread"
export TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1"
if step thread-build bash -c "cmake -S '$root' -B '$thread' -G Ninja -DCMAKE_CXX_COMPILER=clang++-19 -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_BUILD_BENCH=OFF -DPRISM_ASSERTIONS=ON -DPRISM_WERROR=ON \
      -DPRISM_TESTS_PCH=ON -DPRISM_TESTS_UNITY=ON -DCMAKE_CXX_FLAGS_RELWITHDEBINFO='-O2 -g1 -DNDEBUG' -DCMAKE_CXX_FLAGS=-fsanitize=thread &&
      cmake --build '$thread' -j $jobs --target prism_tests cornell cornell_caustics"; then
  half='*/photon/*,*/integrator/*'
  "$thread/tests/prism_tests" --source-file="$half" >"$logs/thread-tests-1.log" 2>&1 &
  "$thread/tests/prism_tests" --source-file-exclude="$half" >"$logs/thread-tests-2.log" 2>&1 &
  wait
  for part in 1 2; do
    grep -q "Status: SUCCESS" "$logs/thread-tests-$part.log" ||
      grep -B 5 -A 40 -E "ThreadSanitizer|ERROR|FAILED" "$logs/thread-tests-$part.log" | head -n 80
    count "thread ($part/2)" "$logs/thread-tests-$part.log"
  done
  step thread-render-whitted "$thread/examples/cornell" --width 96 --height 96 --spp 2 --threads 2 --out "$thread/gallery" || fail thread-render-whitted
  step thread-render-photons "$thread/examples/cornell_caustics" --width 64 --height 64 --spp 1 --threads 2 --photons 20000 \
    --caustic-photons 20000 --gather 4 --out "$thread/gallery" || fail thread-render-photons
else
  fail thread
fi

# clang 19 with libc++, Release, for AVX2 where the CPU has it: the other runs take the
# baseline's 4-wide Bvh nodes, this one the 8-wide ones.
libcxx="$root/build/libcxx"
avx2=""
grep -qw avx2 /proc/cpuinfo && avx2=-mavx2
if step libcxx-build bash -c "cmake -S '$root' -B '$libcxx' -G Ninja -DCMAKE_CXX_COMPILER=clang++-19 -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_BENCH=OFF -DPRISM_WERROR=ON \
      -DPRISM_TESTS_PCH=ON -DPRISM_TESTS_UNITY=ON -DCMAKE_CXX_FLAGS='-stdlib=libc++ $avx2' && cmake --build '$libcxx' -j $jobs"; then
  ctest --test-dir "$libcxx" -j "$jobs" >"$logs/libcxx-ctest.log" 2>&1 ||
    ctest --test-dir "$libcxx" --rerun-failed --output-on-failure 2>&1 | tail -n 80
  count libc++ "$logs/libcxx-ctest.log"
else
  fail libc++
fi

# Each public header on its own includes (the builds above precompile prism.hpp).
if step headers "$root/tools/check_headers.sh"; then
  tail -n 1 "$logs/headers.log"
  passed=$((passed + 1)) summary+=("headers ok")
else
  fail headers
fi

# The API reference (Doxygen): any warning about a comment fails.
if step docs "$root/tools/docs.sh"; then
  tail -n 1 "$logs/docs.log"
  passed=$((passed + 1)) summary+=("docs ok")
else
  fail docs
fi

# libFuzzer (clang) under ASan + UBSan: each target (tests/fuzz/) for 60 s from its
# committed corpus; a crash fails the run and leaves its input in build/fuzz/.
if step fuzz "$root/tools/fuzz.sh" 60; then
  grep "^fuzz:" "$logs/fuzz.log"
  passed=$((passed + 1)) summary+=("fuzz ok")
else
  fail fuzz
fi

# Meson: its own build of prism as a subproject of a consumer project, and the
# single-header check (the suite itself is the CMake builds' above).
meson_dir="$root/build/meson"
if step meson-setup bash -c "[[ -d '$meson_dir' ]] || meson setup '$meson_dir' '$root'"; then
  if meson test -C "$meson_dir" --print-errorlogs >"$logs/meson-test.log" 2>&1 && grep -qE "^Fail: +0 *$" "$logs/meson-test.log"; then
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

echo "test: ${summary[*]} in $(( $(date +%s) - start )) s"
echo "test: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
