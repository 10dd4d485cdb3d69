#!/usr/bin/env python3
"""The CTest validation table (test, reference kind, tolerance, measured error, their ratio,
wall time) from the tests' own output: lists every test with the label `validation` (ctest
--show-only=json-v1 in the build), takes each one's kind from tests/validation_kinds.txt and
its numbers from a build's Testing/Temporary/LastTest.log, and writes
docs/validation-table.md.

    cd build && ctest -L validation          # or any run that includes validation tests
    /usr/bin/python3 tools/validation_table.py build/Testing/Temporary/LastTest.log \\
        --build build --out docs/validation-table.md
    /usr/bin/python3 tools/validation_table.py --check-kinds --build build   # ctest's check

A test that printed no error line shows as such; a row whose tolerance is below 1.3x its
measured error is flagged (unless the test is known off).

It recognises the lines the validations print (nothing is re-run or recomputed here):
  * "[validation] <case>: <reference> error <e>, tolerance <t> (run time ...)" (C++ tests);
  * "validation <name>: ... L2 relative velocity error <e>, ..." (fluid_app; the tolerance is
    the scene's fluid.validation.tolerance, read from the scene file on the command line);
  * "<case>: <quantity> = <x> (reference <r>), relative error <e> %, ..." and the momentum and
    invariance lines of tools/validate_case.py (tolerance: its --tolerance argument).
Only tests present in the log appear; their pass/fail status is the one CTest recorded.
"""
import argparse
import fnmatch
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

HEADER = re.compile(r"^\d+/\d+ Test: (.+?)\s*$", re.M)
STATUS = re.compile(r"^Test (Passed|Failed|Skipped|Not Run)", re.M)
COMMAND = re.compile(r"^Command: (.*)$", re.M)
GENERIC = re.compile(r"^\[validation\] (?P<case>.+?): (?P<ref>.*?) error (?P<err>\S+), "
                     r"tolerance (?P<tol>[^ ]+) \(run time (?P<wall>[\d.]+) s", re.M)
FLUID = re.compile(r"^validation (?P<case>\S+): cells (?P<cells>\S+), .*L2 relative velocity "
                   r"error (?P<err>[-+.\de]+),.*run time (?P<wall>[\d.e+]+) s", re.M)
CASE = re.compile(r"^(?P<case>[\w.-]+): (?P<q>.+?) = (?P<val>\S+) \(reference (?P<ref>\S+)\), "
                  r"relative error (?P<err>[-\d.e+]+) %.*wall time (?P<wall>[\d.na]+) s", re.M)
PUBLISHED = re.compile(r"^[\w.-]+: against the published (?P<pub>\S+): (?P<err>[-+\d.]+) %", re.M)
TEST_TIME = re.compile(r"^Test time =\s*(?P<wall>[\d.]+) sec", re.M)
MOMENTUM = re.compile(r"^momentum audit: .* = (?P<err>\S+) of the momentum scale;.*wall time "
                      r"(?P<wall>[\d.]+) s", re.M)
INVARIANCE = re.compile(r"^invariance: ranks (?P<a>\S+) vs (?P<b>\S+): largest relative "
                        r"difference (?P<err>\S+)", re.M)



HERE = os.path.dirname(os.path.abspath(__file__))
KINDS_FILE = os.path.join(HERE, "..", "tests", "validation_kinds.txt")
KINDS = ("published", "closed_form", "pin", "calibration", "known_off")


def command_args(body):
    m = COMMAND.search(body)
    if not m:
        return []
    args = shlex.split(m.group(1))
    # add_output_test runs the command through cmake -DCMD=a|b|c -P expect_output.cmake.
    out = []
    for a in args:
        out += a[len("-DCMD="):].split("|") if a.startswith("-DCMD=") else [a]
    return out


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


def number(text):
    """A float from '1.0e-05', '3 %' (kept in percent) or None ('?', 'none', a band)."""
    try:
        return float(str(text).replace("%", "").strip())
    except ValueError:
        return None


def rows_of(name, body):
    """(reference, tolerance, measured) of each error line a test printed."""
    args = command_args(body)
    rows = []
    for m in GENERIC.finditer(body):
        rows.append((f"{m['case']}: {m['ref']}", m["tol"], m["err"]))
    for m in FLUID.finditer(body):
        rows.append((f"{m['case']} ({m['cells']} cells): analytic solution, L2 relative "
                     "velocity error", scene_tolerance(args), m["err"]))
    tol = option(args, "--tolerance")
    pub = {m["pub"]: m["err"] for m in PUBLISHED.finditer(body)}
    for m in CASE.finditer(body):
        pct = f"{100 * float(tol):.3g} %" if tol else "?"
        ref = f"{m['q']} = {m['val']} vs {m['ref']} (relative)"
        for p, e in pub.items():
            ref += f"; published {p}: {e} % (reported)"
        rows.append((ref, pct, f"{float(m['err']):.3g} %"))
    for m in MOMENTUM.finditer(body):
        rows.append(("momentum audit: fluid + bodies - applied impulse, relative to the "
                     "momentum scale (the largest body momentum unless stated)", tol or "?",
                     m["err"]))
    worst = [float(m["err"]) for m in INVARIANCE.finditer(body)]
    if worst:
        rows.append(("same trajectory on other rank counts (largest relative difference)",
                     tol or "?", f"{max(worst):.3e}"))
    return rows


def read_kinds(path=KINDS_FILE):
    """[(pattern, kind, reference, note)] from tests/validation_kinds.txt."""
    entries = []
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        parts = [x.strip() for x in line.split("|")] + [""] * 3
        if parts[1] not in KINDS:
            sys.exit(f"{path}:{n}: kind '{parts[1]}' is not one of {', '.join(KINDS)}")
        entries.append(tuple(parts[:4]))
    return entries


def kind_of(test, entries):
    """The first entry whose pattern matches the test, or None."""
    for e in entries:
        if fnmatch.fnmatchcase(test, e[0]):
            return e
    return None


def validation_tests(build):
    """Names of the tests labelled `validation` in a build (ctest --show-only=json-v1). ctest
    rewrites Testing/Temporary/LastTest.log of the folder it runs in, even when it only lists:
    run in the build, it would wipe the log this table is read from (and, as a ctest test, the
    log of the run it belongs to). So it runs in a scratch folder that points at the build."""
    with tempfile.TemporaryDirectory(prefix="lbdem_ctest_list_") as scratch:
        with open(os.path.join(scratch, "CTestTestfile.cmake"), "w") as f:
            f.write(f'subdirs("{os.path.abspath(build)}")\n')
        out = subprocess.run(["ctest", "-L", "validation", "--show-only=json-v1"], cwd=scratch,
                             capture_output=True, text=True, check=True).stdout
    tests = []
    for t in json.loads(out)["tests"]:
        labels = [v for p in t.get("properties", []) if p["name"] == "LABELS" for v in p["value"]]
        if "validation" in labels:
            tests.append(t["name"])
    return tests


def check_kinds(tests, entries):
    """Problems: tests without a kind, and entries that match no test (unless noted as not
    registered by default)."""
    problems = [f"{t}: no reference kind in tests/validation_kinds.txt" for t in tests
                if kind_of(t, entries) is None]
    for e in entries:
        if not any(fnmatch.fnmatchcase(t, e[0]) for t in tests) and \
                "not registered by default" not in e[3]:
            problems.append(f"tests/validation_kinds.txt: '{e[0]}' matches no validation test")
    return problems


def log_sections(path):
    """{test: (body, status, wall)} from CTest's LastTest.log."""
    text = open(path, encoding="utf-8", errors="replace").read()
    heads = list(HEADER.finditer(text))
    out = {}
    for i, h in enumerate(heads):
        body = text[h.end(): heads[i + 1].start() if i + 1 < len(heads) else len(text)]
        st = STATUS.search(body)
        wall = TEST_TIME.search(body)
        out[h.group(1)] = (body, st.group(1).lower() if st else "?",
                           wall.group("wall") if wall else "")
    return out


def shown(test):
    """A parametrized gtest's CTest name without its '# GetParam() = <bytes>' comment."""
    return test.split("  # GetParam()")[0]


def table_rows(tests, entries, sections):
    rows, flagged = [], []
    for test in sorted(tests):
        e = kind_of(test, entries)
        kind = e[1] if e else "MISSING"
        body, status, wall = sections.get(test, ("", "not run", ""))
        lines = rows_of(test, body) if body else []
        if not lines:
            what = "no error line printed" if body else "not in this run"
            rows.append((shown(test), kind, e[2] if e else "", "", what, "", wall, status, ""))
            continue
        for ref, tol, err in lines:
            t, m = number(tol), number(err)
            ratio, flag = "", ""
            if t is not None and m is not None and m != 0:
                r = t / abs(m)
                ratio = f"{r:.3g}"
                if kind == "known_off":
                    flag = "known off"
                elif r < 1.3:
                    flag = "**tolerance < 1.3x measured**"
                    flagged.append(test)
            elif kind == "known_off":
                flag = "known off"
            rows.append((shown(test), kind, ref, tol, err, ratio, wall, status, flag))
    return rows, flagged


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("log", nargs="*", help="build/Testing/Temporary/LastTest.log (several: a "
                   "later log's run of a test replaces an earlier one's, e.g. a rerun)")
    p.add_argument("--build", default="build", help="the build whose validation tests to list")
    p.add_argument("--kinds", default=KINDS_FILE)
    p.add_argument("--out", default="docs/validation-table.md")
    p.add_argument("--note", default="", help="a line saying which run the table comes from")
    p.add_argument("--check-kinds", action="store_true",
                   help="only check that every validation test has a kind (exit 1 if not)")
    a = p.parse_args()
    entries = read_kinds(a.kinds)
    tests = validation_tests(a.build)
    problems = check_kinds(tests, entries)
    if a.check_kinds:
        # A test without a kind fails; a line matching no test is only reported (a build
        # without LAMMPS or an unbuilt gtest target registers fewer tests).
        missing = [pr for pr in problems if "no reference kind" in pr]
        for pr in problems:
            print(pr if pr in missing else f"note: {pr}")
        counts = {}
        for t in tests:
            k = kind_of(t, entries)
            counts[k[1] if k else "MISSING"] = counts.get(k[1] if k else "MISSING", 0) + 1
        print(f"{len(tests)} validation tests: " +
              ", ".join(f"{k} {n}" for k, n in sorted(counts.items())))
        return 1 if missing else 0
    if not a.log:
        p.error("the log is required (or --check-kinds)")
    for pr in problems:
        print(f"warning: {pr}", file=sys.stderr)
    sections = {}
    for path in a.log:
        sections.update(log_sections(path))
    rows, flagged = table_rows(tests, entries, sections)
    lines = [
        "# Validation table",
        "",
        "Generated by `tools/validation_table.py`; do not edit by hand. One row per error line",
        "each validation test (CTest label `validation`) printed: the reference kind (from",
        "`tests/validation_kinds.txt`), the tolerance it asserts, the error it measured, their",
        "ratio and the test's wall time (CTest's, on the machine and load of the run). The",
        "policy behind the kinds and tolerances: docs/testing.md, \"Tolerance policy\".",
        "Regenerate after a test run:",
        "",
        "    (cd build && ctest -L validation -j2)",
        "    /usr/bin/python3 tools/validation_table.py build/Testing/Temporary/LastTest.log \\",
        "        --build build --out docs/validation-table.md",
        "",
        "Kinds: *published* (a published number independent of this code), *closed_form* (an",
        "exact result), *pin* (this code's own earlier result at that resolution: a regression",
        "guard, not a validation), *calibration* (a quantity the code was calibrated on),",
        "*known_off* (passes only while the error stays off, inside its recorded band).",
        "Flagged: tolerance below 1.3x the measured error (not for known-off rows).",
        "",
    ] + ([a.note, ""] if a.note else []) + [
        "| test | kind | reference | tolerance | measured error | tolerance / measured | "
        "wall s | status | flag |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append("| " + " | ".join(str(x).replace("|", "/") for x in r) + " |")
    others = [e for e in entries if "not registered by default" in e[3]]
    if others:
        lines += ["", "Not registered by default (too long for the validation run; the command "
                  "and the recorded figure are in the note):", "",
                  "| test | kind | reference | note |", "|---|---|---|---|"]
        lines += [f"| {e[0]} | {e[1]} | {e[2]} | {e[3]} |" for e in others]
    notes = sorted({(e[0], e[3]) for e in entries if e[3] and e not in others})
    if notes:
        lines += ["", "Notes from tests/validation_kinds.txt:", ""]
        lines += [f"* `{pat}`: {note}" for pat, note in notes]
    with open(a.out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{a.out}: {len(rows)} rows from {len(tests)} validation tests; flagged "
          f"(tolerance < 1.3x measured): {', '.join(sorted({shown(t) for t in flagged})) or 'none'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
