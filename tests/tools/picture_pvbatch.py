#!/usr/bin/python3
"""The run picture drawn by pvbatch from what dem_app wrote (the pour of
tests/dem_app/scenes/pour_small.yaml): a PNG of the right size in which the bodies show as
coloured surfaces. Exits 77 (ctest: skipped) where ParaView is not installed.

    picture_pvbatch.py SCENE
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lbdem import picture  # noqa: E402


def main():
    if not picture.have_pvbatch():
        print("picture_pvbatch: pvbatch or xvfb-run not installed; skipped")
        return 77
    png = picture.render_png(sys.argv[1])
    import matplotlib.image
    img = matplotlib.image.imread(png)[..., :3]
    assert img.shape[:2] == (900, 1200), img.shape
    # The colour map paints the bodies; the background is white and the axes black or grey.
    spread = img.max(axis=2) - img.min(axis=2)
    coloured = int((spread > 0.2).sum())
    print(f"picture_pvbatch: {png}: {coloured} coloured pixels of {img.shape[0] * img.shape[1]}")
    assert coloured > 2000, "the bodies do not show"
    return 0


if __name__ == "__main__":
    sys.exit(main())
