#!/usr/bin/python3
"""Body surfaces of a run for ParaView (docs/study.md, "Pictures"): writes
<name>_surfaces.h5 + <name>_surfaces.xdmf next to the body trace, and with --png a picture of
the last output time (bodies coloured by v_z, a slice of the fluid velocity) by pvbatch.

    /usr/bin/python3 tools/body_mesh.py runs/study/small/cube_phi0.300/scene.yaml [--png]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import bodymesh  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("scene")
    p.add_argument("--png", action="store_true")
    args = p.parse_args()
    xdmf = bodymesh.write_surfaces(args.scene)
    print(f"body surfaces: {xdmf}")
    if args.png:
        png = bodymesh.render_png(args.scene, xdmf)
        if png:
            print(f"picture: {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
