#!/usr/bin/python3
"""The stability study: every scene of configs/stability/ is checked and run, and its outcome
(runs / refused / diagnosed; never nan, crash or hang) compared with the expected one
(docs/stability.md).

    tools/stability_study.py --build build                  # every case
    tools/stability_study.py --build build --only tau_0p505 density_0p1

Prints one line per case and a Markdown table (also written to <out>/stability.md). Exit 1
when a case ends otherwise than expected, or as nan, crash or hang, when its computed error is
above its bound (stability.BOUNDS), or when a refusal or diagnosis does not name its cause
(stability.MESSAGES).
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from lbdem import stability  # noqa: E402
from lbdem import scene as lbdem_scene  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--only", nargs="+", choices=list(stability.CASES))
    ap.add_argument("--timeout", type=float, default=300, help="wall s per run (then: hang)")
    ap.add_argument("--reuse-base", action="store_true",
                    help="use the baseline's trace of an earlier run instead of running it")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "runs", "stability"))
    args = ap.parse_args()
    lbdem_scene.use_build(args.build)  # values of scenes come from this build
    names = args.only or list(stability.CASES)
    if (any(stability.CASES[n][2] == "vs_base" for n in names) and stability.BASE not in names
            and not (args.reuse_base and stability.trace(stability.BASE))):
        names.insert(0, stability.BASE)
    os.makedirs(args.out, exist_ok=True)
    rows, ok = [], True
    for name in names:
        r = stability.study_case(args.build, name, args.timeout, args.out)
        good, why = stability.judge(r)
        ok = ok and good
        err = r["what"] if r["error"] is None else f"{r['error']:.3g} ({r['what']})"
        bound = stability.BOUNDS.get(name)
        if bound is not None:
            err += f", bound {bound:g}"
        print(f"{name}: {r['outcome']} (expected {r['expected']}){'' if good else ' FAILED: ' + why}"
              f"; wall {r['wall_s']:.1f} s; {err} {r['message']}", flush=True)
        rows.append(r)
    md = ["| case | ranks | outcome | error | wall (s) | message |", "|---|---|---|---|---|---|"]
    for r in rows:
        err = r["what"] if r["error"] is None else f"{r['error']:.3g} ({r['what']})"
        msg = r["message"].replace("|", "/")
        md.append(f"| {r['case']} | {r['ranks']} | {r['outcome']} | {err} | {r['wall_s']:.1f} | "
                  f"{msg} |")
    with open(os.path.join(args.out, "stability.md"), "w") as out:
        out.write("\n".join(md) + "\n")
    print("\n".join(md))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
