#!/usr/bin/python3
"""Prints runs/validation/results.csv (appended to by tools/validate_case.py) as the markdown
table of docs/validation.md; with --last, only the latest row of each (case, resolution, tau,
ranks).

    /usr/bin/python3 tools/analysis/results_table.py [--last] [results.csv]
"""
import argparse
import csv
import os

DEFAULT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "runs",
                       "validation", "results.csv")


def error(text):
    """Relative errors as percent; other entries (empty, an absolute difference) as they are."""
    try:
        value = float(text)
    except ValueError:
        return text
    return f"{100 * value:.2f} %" if value >= 1e-6 else f"{value:.3g}"


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("csv", nargs="?", default=DEFAULT)
    p.add_argument("--last", action="store_true")
    args = p.parse_args()
    with open(args.csv) as f:
        rows = list(csv.DictReader(f))
    if args.last:
        latest = {}
        for r in rows:
            latest[(r["case"], r["resolution"], r["tau"], r["ranks"])] = r
        rows = list(latest.values())
    print("| case | resolution (cells per d or a) | tau | quantity | reference | result | error | "
          "wall time (s) | ranks fluid:DEM |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {r['resolution']} | {r['tau']} | {r['quantity']} | "
              f"{r['reference']} | {r['result']} | {error(r['error'])} | "
              f"{r['wall_s']} | {r['ranks']} |")


if __name__ == "__main__":
    main()
