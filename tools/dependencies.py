#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The folders of include/prism and which of them each includes, read from the includes.

    tools/dependencies.py            print each folder's dependencies
    tools/dependencies.py --check    fail if two folders depend on each other (directly or
                                     through others), or if docs/DESIGN.md's table says
                                     otherwise than the includes ("depends on" column)
    tools/dependencies.py --write    rewrite that column from the includes
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = ROOT / "include" / "prism"
DESIGN = ROOT / "docs" / "DESIGN.md"
INCLUDE_RE = re.compile(r'^\s*#\s*include\s*<prism/([a-z_]+)/[^>]+>', re.M)
ROW_RE = re.compile(r"^\| ([a-z_]+)/ \| (.*) \| (.*) \|$")


def folder_graph():
    graph = {}
    for header in sorted(INCLUDE.glob("*/*.hpp")):
        folder = header.parent.name
        deps = graph.setdefault(folder, set())
        for target in INCLUDE_RE.findall(header.read_text(encoding="utf-8")):
            if target != folder:
                deps.add(target)
    return graph


def cycles(graph):
    """Strongly connected components of more than one folder (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def design_rows(text):
    rows = {}
    for number, line in enumerate(text.splitlines(), 1):
        m = ROW_RE.match(line)
        if m:
            rows[m.group(1)] = (number, m.group(3))
    return rows


def folders_named(cell, known):
    return {word.rstrip("/") for word in re.split(r"[,\s]+", cell) if word.rstrip("/") in known}


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else ""
    graph = folder_graph()
    if mode == "":
        for folder in sorted(graph):
            print(f"{folder}/: {', '.join(sorted(graph[folder])) or '-'}")
        return 0
    text = DESIGN.read_text(encoding="utf-8")
    rows = design_rows(text)
    known = set(graph)
    if mode == "--write":
        lines = text.splitlines()
        for folder, (number, cell) in rows.items():
            if folder not in graph:
                continue
            others = [w.strip() for w in cell.split(",") if w.strip() and w.strip().rstrip("/") not in known]
            new_cell = ", ".join(sorted(graph[folder]) + others) or "-"
            lines[number - 1] = re.sub(r" \| [^|]*\|$", f" | {new_cell} |", lines[number - 1])
        DESIGN.write_text("\n".join(lines) + "\n", encoding="utf-8")
        return 0
    if mode != "--check":
        print(__doc__, file=sys.stderr)
        return 2
    errors = []
    for component in cycles(graph):
        errors.append(f"folders that depend on each other: {' <-> '.join(component)}")
    for folder in sorted(graph):
        if folder not in rows:
            errors.append(f"{DESIGN.relative_to(ROOT)}: no row for {folder}/")
            continue
        number, cell = rows[folder]
        said = folders_named(cell, known)
        if said != graph[folder]:
            missing, extra = sorted(graph[folder] - said), sorted(said - graph[folder])
            errors.append(f"{DESIGN.relative_to(ROOT)}:{number}: {folder}/ depends on {', '.join(sorted(graph[folder])) or 'nothing'}"
                          + (f"; the table leaves out {', '.join(missing)}" if missing else "")
                          + (f"; the table adds {', '.join(extra)}" if extra else ""))
    for folder in sorted(set(rows) - known):
        errors.append(f"{DESIGN.relative_to(ROOT)}:{rows[folder][0]}: a row for {folder}/, which include/prism does not have")
    for error in errors:
        print(f"dependencies: {error}", file=sys.stderr)
    if not errors:
        print(f"dependencies: {len(graph)} folders, no cycle, docs/DESIGN.md's table matches the includes")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
