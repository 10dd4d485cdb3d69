#!/usr/bin/python3
"""A picture of a finished run (docs/study.md, "Pictures"): <dem output>/<name>.png, the body
surfaces dem_app wrote coloured by v_z and a slice of the fluid velocity at the last output time,
drawn by pvbatch (tools/setup_debian.sh --with-paraview installs it).

    /usr/bin/python3 tools/render_run.py runs/study/small/cube_phi0.300/scene.yaml
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import picture  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("scene")
    args = p.parse_args()
    png = picture.render_png(args.scene)
    if not png:
        return 1
    print(f"picture: {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
