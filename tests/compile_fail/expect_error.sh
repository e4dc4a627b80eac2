#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A mistake a user can make must fail to compile with a short error that names the
# user's line and says what is wrong.
#   expect_error.sh COMPILER INCLUDE_DIR SOURCE LINE MESSAGE_REGEX MAX_BYTES
set -uo pipefail
compiler=$1 include=$2 source=$3 line=$4 message=$5 max_bytes=$6
if out=$("$compiler" -std=c++20 -DGLM_FORCE_PURE -I"$include" -fsyntax-only "$source" 2>&1); then
  echo "FAIL: $source compiled, but it must not"; exit 1
fi
name=$(basename "$source")
grep -q "$name:$line:" <<<"$out" || { echo "FAIL: the error does not name $name:$line"; echo "$out"; exit 1; }
grep -Eq "$message" <<<"$out" || { echo "FAIL: the error does not say /$message/"; echo "$out"; exit 1; }
# Measured with the two folders' paths shortened, so the bound does not depend on where
# the checkout lives.
short=${out//"$include"/I}
short=${short//"$(dirname "$source")"/C}
bytes=${#short}
(( bytes <= max_bytes )) || { echo "FAIL: $bytes bytes of diagnostics, more than $max_bytes"; echo "$out"; exit 1; }
echo "ok: $name fails at line $line with $bytes bytes of diagnostics"
