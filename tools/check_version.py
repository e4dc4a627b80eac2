#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Check that the version has one value: include/prism/version.hpp's (CMakeLists.txt reads it
from there), meson.build's project version and CHANGELOG.md's newest release heading.

    tools/check_version.py
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    header = (ROOT / "include/prism/version.hpp").read_text(encoding="utf-8")
    parts = [re.search(rf"^#define PRISM_VERSION_{p} (\d+)$", header, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
    if not all(parts):
        sys.exit("include/prism/version.hpp: PRISM_VERSION_MAJOR, _MINOR or _PATCH is missing")
    version = ".".join(m.group(1) for m in parts)
    meson = re.search(r"project\('prism', 'cpp', version : '([^']+)'", (ROOT / "meson.build").read_text(encoding="utf-8"))
    changelog = re.search(r"^## \[?(\d+\.\d+\.\d+)\]?", (ROOT / "CHANGELOG.md").read_text(encoding="utf-8"), re.M)
    found = {"meson.build": meson and meson.group(1), "CHANGELOG.md (newest release)": changelog and changelog.group(1)}
    wrong = [f"{where} says {value}" for where, value in found.items() if value != version]
    if wrong:
        sys.exit(f"version.hpp says {version}, but " + "; ".join(wrong))
    print(f"version {version}: version.hpp, meson.build and CHANGELOG.md agree")


if __name__ == "__main__":
    main()
