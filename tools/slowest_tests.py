#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print the slowest test cases of a ctest run, from its log (tools/test.sh writes them to
build/logs/RUN-ctest.log):

    tools/slowest_tests.py [LOG] [--count N] [--markdown]

LOG defaults to build/logs/release-ctest.log; N to 20. --markdown prints the table that
docs/contributing.md keeps. The times are wall seconds with ctest running two cases at a
time, as the test command does."""
import argparse
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("log", nargs="?", default=root / "build/logs/release-ctest.log", type=pathlib.Path)
parser.add_argument("--count", type=int, default=20)
parser.add_argument("--markdown", action="store_true")
args = parser.parse_args()
if not args.log.exists():
    sys.exit(f"slowest_tests: {args.log} does not exist (run tools/test.sh first)")
line = re.compile(r"Test +#\d+: (.*?) \.+\**\s*(Passed|\*+Failed|Failed|\*+Timeout|Not Run).*?([0-9.]+) sec")
cases = []
for text in args.log.read_text(errors="replace").splitlines():
    m = line.search(text)
    if m:
        cases.append((float(m.group(3)), m.group(1).strip(), m.group(2).strip("*")))
cases.sort(reverse=True)
total = sum(t for t, _, _ in cases)
if args.markdown:
    print("| s | case |")
    print("|---:|---|")
    for t, name, status in cases[: args.count]:
        print(f"| {t:.1f} | {name}{'' if status == 'Passed' else ' (' + status + ')'} |")
else:
    for t, name, status in cases[: args.count]:
        print(f"{t:7.2f} s  {name}{'' if status == 'Passed' else '  [' + status + ']'}")
print(f"{len(cases)} cases, {total:.0f} s in all; {sum(1 for t, _, _ in cases if t > 2)} over 2 s", file=sys.stderr if args.markdown else sys.stdout)
