#!/usr/bin/env python3
"""The CTest validation table (test, reference, tolerance, measured error) from the tests' own
output: reads a build's Testing/Temporary/LastTest.log and writes docs/validation-table.md.

    cd build && ctest -L validation          # or any run that includes validation tests
    /usr/bin/python3 tools/validation_table.py build/Testing/Temporary/LastTest.log \\
        --out docs/validation-table.md

It recognises the lines the validations print (nothing is re-run or recomputed here):
  * "[validation] <case>: <reference> error <e>, tolerance <t> (run time ...)" (C++ tests);
  * "validation <name>: ... L2 relative velocity error <e>, ..." (fluid_app; the tolerance is
    the scene's fluid.validation.tolerance, read from the scene file on the command line);
  * "<case>: <quantity> = <x> (reference <r>), relative error <e> %, ..." and the momentum and
    invariance lines of tools/validate_case.py (tolerance: its --tolerance argument).
Only tests present in the log appear; their pass/fail status is the one CTest recorded.
"""
import argparse
import os
import re
import shlex
import sys

HEADER = re.compile(r"^\d+/\d+ Test: (\S+)", re.M)
STATUS = re.compile(r"^Test (Passed|Failed|Skipped|Not Run)", re.M)
COMMAND = re.compile(r"^Command: (.*)$", re.M)
GENERIC = re.compile(r"^\[validation\] (?P<case>.+?): (?P<ref>.*?) error (?P<err>\S+), "
                     r"tolerance (?P<tol>[^ ]+) \(run time (?P<wall>[\d.]+) s", re.M)
FLUID = re.compile(r"^validation (?P<case>\S+): cells (?P<cells>\S+), .*L2 relative velocity "
                   r"error (?P<err>[-+.\de]+),.*run time (?P<wall>[\d.e+]+) s", re.M)
CASE = re.compile(r"^(?P<case>[\w.-]+): (?P<q>.+?) = (?P<val>\S+) \(reference (?P<ref>\S+)\), "
                  r"relative error (?P<err>[-\d.e+]+) %.*wall time (?P<wall>[\d.]+) s", re.M)
MOMENTUM = re.compile(r"^momentum audit: .* = (?P<err>\S+) of the body momentum;.*wall time "
                      r"(?P<wall>[\d.]+) s", re.M)
INVARIANCE = re.compile(r"^invariance: ranks (?P<a>\S+) vs (?P<b>\S+): largest relative "
                        r"difference (?P<err>\S+)", re.M)


def command_args(body):
    m = COMMAND.search(body)
    return shlex.split(m.group(1)) if m else []


def option(args, name):
    return args[args.index(name) + 1] if name in args and args.index(name) + 1 < len(args) else None


def scene_tolerance(args):
    """fluid.validation.tolerance of the first .yaml argument (a tiny reader: no PyYAML)."""
    for a in args:
        if a.endswith(".yaml") and os.path.exists(a):
            section = []
            for line in open(a, encoding="utf-8"):
                m = re.match(r"^(\s*)(\w+):\s*(\S*)", line.split("#")[0])
                if not m:
                    continue
                depth = len(m.group(1)) // 2
                section = section[:depth] + [m.group(2)]
                if section == ["fluid", "validation", "tolerance"]:
                    return m.group(3)
    return "?"


def rows_of(name, body, status):
    args = command_args(body)
    rows = []
    for m in GENERIC.finditer(body):
        rows.append((name, f"{m['case']}: {m['ref']}", m["tol"], m["err"], m["wall"], status))
    for m in FLUID.finditer(body):
        rows.append((name, f"{m['case']} ({m['cells']} cells): analytic solution, L2 relative "
                     "velocity error", scene_tolerance(args), m["err"], m["wall"], status))
    tol = option(args, "--tolerance")
    for m in CASE.finditer(body):
        pct = f"{100 * float(tol):.3g} %" if tol else "?"
        rows.append((name, f"{m['q']} = {m['val']} vs {m['ref']} (relative)", pct,
                     f"{float(m['err']):.3g} %", m["wall"], status))
    for m in MOMENTUM.finditer(body):
        rows.append((name, "momentum audit: fluid + bodies - applied impulse, relative to the "
                     "body momentum", tol or "?", m["err"], m["wall"], status))
    worst = [float(m["err"]) for m in INVARIANCE.finditer(body)]
    if worst:
        rows.append((name, "same trajectory on other rank counts (largest relative difference)",
                     tol or "?", f"{max(worst):.3e}", "", status))
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("log", help="build/Testing/Temporary/LastTest.log")
    p.add_argument("--out", default="docs/validation-table.md")
    p.add_argument("--note", default="", help="a line saying which run the table comes from")
    a = p.parse_args()
    text = open(a.log, encoding="utf-8", errors="replace").read()
    rows = []
    heads = list(HEADER.finditer(text))
    for i, h in enumerate(heads):
        body = text[h.end(): heads[i + 1].start() if i + 1 < len(heads) else len(text)]
        st = STATUS.search(body)
        rows += rows_of(h.group(1), body, st.group(1).lower() if st else "?")
    if not rows:
        sys.exit(f"{a.log}: no validation output found (run ctest with validation tests first)")
    rows.sort(key=lambda r: r[0])
    lines = [
        "# Validation table",
        "",
        "Generated from CTest's own log by `tools/validation_table.py`; do not edit by hand.",
        "Each row is one line a validation test printed (reference, the tolerance it asserts, the",
        "error it measured). Regenerate after a test run:",
        "",
        "    (cd build && ctest -L validation)",
        "    /usr/bin/python3 tools/validation_table.py build/Testing/Temporary/LastTest.log \\",
        "        --out docs/validation-table.md",
        "",
    ] + ([a.note, ""] if a.note else []) + [
        "| test | reference | tolerance | measured error | wall s | status |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append("| " + " | ".join(x.replace("|", "/") for x in r) + " |")
    with open(a.out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{a.out}: {len(rows)} rows from {len({r[0] for r in rows})} tests")


if __name__ == "__main__":
    main()
