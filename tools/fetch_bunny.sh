#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fetch the Stanford bunny from the npm registry (package bunny@1.0.1, Mikola Lysenko's
# closed 3674-triangle version of the Stanford 3D Scanning Repository's bunny, marked
# Public Domain) and write it as assets/bunny.obj, the file the tests, the gallery and
# bench/ read. The package is checked against its registry checksum. The result is
# committed (its licence allows it); this script says where it came from.
#   tools/fetch_bunny.sh [OUT.obj]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/assets/bunny.obj}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
npm pack --silent bunny@1.0.1 >/dev/null
echo "86383da45ab7a99571a5a572b7be0e3564815f9e  bunny-1.0.1.tgz" | sha1sum --check --quiet
tar xzf bunny-1.0.1.tgz
node -e '
const b = require("./package");
const lines = ["# The Stanford bunny (Stanford 3D Scanning Repository), as npm package bunny@1.0.1",
               "# (Public Domain), converted by prism tools/fetch_bunny.sh. Closed, wound outward, y up."];
for (const p of b.positions) lines.push("v " + p.join(" "));
for (const f of b.cells) lines.push("f " + f.map(i => i + 1).join(" "));
process.stdout.write(lines.join("\n") + "\n");' > "$work/bunny.obj"
mkdir -p "$(dirname "$out")"
mv "$work/bunny.obj" "$out"
echo "wrote $out"
