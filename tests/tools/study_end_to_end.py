#!/usr/bin/python3
"""ctest tools_study_end_to_end: tools/study.py on tests/tools/study_tiny.yaml through both
programs (packing, bodies file, single-body run, suspension run, analysis, summary, plots),
then again: every run must be skipped and the summary be the same. The log holds no warning
and no "None", and the run held the momentum of fluid + bodies (momentum_change below the
study's tolerance).

    /usr/bin/python3 tests/tools/study_end_to_end.py BUILD_DIR
"""
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
STUDY = os.path.join(HERE, "..", "..", "tools", "study.py")


def main():
    build = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="lbdem_study_") as out:
        cmd = ["/usr/bin/python3", STUDY, os.path.join(HERE, "study_tiny.yaml"), "--build", build,
               "--out", out, "--no-render"]
        first = subprocess.run(cmd, capture_output=True, text=True)
        print(first.stdout[-3000:], first.stderr[-3000:])
        if first.returncode != 0:
            return 1
        with open(os.path.join(out, "summary.csv")) as f:
            rows = list(csv.DictReader(f))
        ok = len(rows) == 1 and rows[0]["shape"] == "cube" and float(rows[0]["u_T"]) > 0
        ok = ok and float(rows[0]["settling_velocity"]) > 0 and int(rows[0]["bodies"]) == 8
        change = float(rows[0]["momentum_change"])
        print(f"momentum change of fluid + bodies: {change:.3g} of the bodies' momentum; "
              f"warnings in the log: {first.stdout.count('WARNING')}; 'None': "
              f"{first.stdout.count('None')}")
        ok = ok and change < 1e-3 and "WARNING" not in first.stdout and "None" not in first.stdout
        for png in ("settling.png", "rdf.png", "correlation.png", "vacf.png", "relaxation.png"):
            ok = ok and os.path.getsize(os.path.join(out, png)) > 0
        second = subprocess.run(cmd, capture_output=True, text=True)
        skipped = second.stdout.count("skipped")
        with open(os.path.join(out, "summary.csv")) as f:
            again = list(csv.DictReader(f))
        print(f"second call: {skipped} runs skipped, summary "
              f"{'unchanged' if again == rows else 'CHANGED'}")
        ok = ok and second.returncode == 0 and skipped == 2 and again == rows
        print("study end to end: " + ("ok" if ok else "FAILED"))
        return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
