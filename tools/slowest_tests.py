#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print the slowest test cases of a ctest run, from its log (tools/test.sh writes them to
build/logs/RUN-ctest.log):

    tools/slowest_tests.py [LOG] [--count N] [--markdown]

LOG defaults to build/logs/release-ctest.log; N to 20. --markdown prints the table that
docs/contributing.md keeps. The times are wall seconds with ctest running two cases at a
time, as the test command does.

Then the budget: a case takes at most 2 s, except the validation cases named in VALIDATION
below, at most 10 s each; the programs that build a project (the consumer projects, the
compile-error checks, the documentation's programs: BUILDS) are builds, not cases, and are
only listed. Every case over its budget is printed; --check makes that a failure."""
import argparse
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent

# The validation cases: each checks a whole estimator against an outside reference (a
# furnace's closed form, the path tracer, a chi-square over a sampler's whole domain) to a
# tolerance that needs its samples. Named by the beginning of the case's name.
VALIDATION = (
    "the photon mapper's volume furnace",
    "a volumetric caustic through a frosted ball in haze",
    "progressive photon mapping's volume furnace",
    "in fog the photon mapper agrees with the path tracer",
    "the photon mapper's beam estimate reads the global pass's volume photons",
    "progressive photon mapping in fog: the beam estimate's radius shrinks too",
    "the photon mapper's furnace: 1.0 within 0.5 %",
    "rough dielectric: sampling follows the pdf from either side",
    "the consistency matrix's quick slice",
    "in haze, every BDPT strategy alone reads the path tracer's light",
    "VCM's merging alone (progressive photon mapping by its light paths)",
)
BUILDS = ("consumer_", "compile_error_", "documentation_snippets")
CASE_BUDGET, VALIDATION_BUDGET = 2.0, 10.0

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("log", nargs="?", default=root / "build/logs/release-ctest.log", type=pathlib.Path)
parser.add_argument("--count", type=int, default=20)
parser.add_argument("--markdown", action="store_true")
parser.add_argument("--check", action="store_true", help="fail if a case is over its budget")
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
out = sys.stderr if args.markdown else sys.stdout
print(f"{len(cases)} cases, {total:.0f} s in all; {sum(1 for t, _, _ in cases if t > 2)} over 2 s", file=out)
over = []
for t, name, _ in cases:
    if name.startswith(BUILDS):
        continue
    budget = VALIDATION_BUDGET if name.startswith(VALIDATION) else CASE_BUDGET
    if t > budget:
        over.append((t, budget, name))
for t, budget, name in over:
    print(f"over budget: {t:.1f} s > {budget:.0f} s  {name}", file=out)
print(f"{len(over)} cases over their budget (2 s; {VALIDATION_BUDGET:.0f} s for the {len(VALIDATION)} validation cases named in tools/slowest_tests.py)", file=out)
if args.check and over:
    sys.exit(1)
