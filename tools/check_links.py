#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Check that every relative link and image of README.md, CHANGELOG.md and docs/*.md names a
file that exists, and every #anchor a heading of the page it points to (GitHub's rule:
lower case, punctuation dropped, spaces to hyphens).

    tools/check_links.py
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LINK = re.compile(r"\]\(([^)\s]+)\)|<img src=\"([^\"]+)\"")
FENCE = re.compile(r"^```")


def anchors(path):
    found, fenced = set(), False
    for line in path.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            fenced = not fenced
        elif not fenced and line.startswith("#"):
            title = line.lstrip("#").strip().lower()
            found.add(re.sub(r"\s", "-", re.sub(r"[^\w\s-]", "", title)))
    return found


def main():
    pages = [ROOT / "README.md", ROOT / "CHANGELOG.md", *sorted((ROOT / "docs").glob("*.md"))]
    bad = []
    for page in pages:
        fenced = False
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if fenced:
                continue
            for match in LINK.finditer(line):
                target = match.group(1) or match.group(2)
                if re.match(r"[a-z]+:", target):
                    continue  # http:, https:, mailto:
                file, _, anchor = target.partition("#")
                path = (page.parent / file).resolve() if file else page
                where = f"{page.relative_to(ROOT)}:{number}"
                if not path.exists():
                    bad.append(f"{where}: {target}: no such file")
                elif anchor and path.suffix == ".md" and anchor not in anchors(path):
                    bad.append(f"{where}: {target}: no heading #{anchor} in {path.relative_to(ROOT)}")
    if bad:
        sys.exit("\n".join(bad))
    print(f"links: every link of {len(pages)} pages resolves")


if __name__ == "__main__":
    main()
