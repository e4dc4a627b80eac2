#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build the API reference from the headers (Doxygen, docs/Doxyfile) into build/docs/html,
# failing on any warning.
#   tools/docs.sh                  build it; exit 1 on any warning (they are printed)
#   tools/docs.sh --undocumented   also count the public entities without a comment
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
command -v doxygen >/dev/null || "$root/tools/setup.sh"
mkdir -p build/docs
config=$(cat docs/Doxyfile)
if [[ "${1:-}" == "--undocumented" ]]; then
  config+=$'\nWARN_IF_UNDOCUMENTED = YES\nWARN_AS_ERROR = NO'
fi
status=0
printf '%s\n' "$config" | doxygen - >build/docs/doxygen.log 2>&1 || status=$?
warnings=$(grep -c -E "(warning|error):" build/docs/warnings.log || true)
if [[ "${1:-}" == "--undocumented" ]]; then
  echo "docs: $warnings public entities without a comment (build/docs/warnings.log)"
  exit 0
fi
if [[ $status -ne 0 || $warnings -ne 0 ]]; then
  cat build/docs/warnings.log build/docs/doxygen.log | head -n 40 >&2
  echo "docs: $warnings warnings (build/docs/warnings.log)" >&2
  exit 1
fi
echo "docs: API reference in build/docs/html/index.html, 0 warnings"
