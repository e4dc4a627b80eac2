#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build the API reference from the headers (Doxygen, docs/Doxyfile) into build/docs/html,
# failing on any warning: a public entity without a comment, a comment that names a
# parameter that is not there, a reference that does not resolve.
#   tools/docs.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
command -v doxygen >/dev/null || "$root/tools/setup.sh"
mkdir -p build/docs
status=0
doxygen docs/Doxyfile >build/docs/doxygen.log 2>&1 || status=$?
warnings=$(grep -c -E "(warning|error):" build/docs/warnings.log || true)
if [[ $status -ne 0 || $warnings -ne 0 ]]; then
  cat build/docs/warnings.log build/docs/doxygen.log | head -n 40 >&2
  echo "docs: $warnings warnings (build/docs/warnings.log)" >&2
  exit 1
fi
echo "docs: API reference in build/docs/html/index.html, 0 warnings"
