"""Opens fluid_app's XDMF files with ParaView's own reader (run with pvpython) and checks what
a user would see: every output time, the node grid, the SI bounds and the field arrays.

  pvpython paraview_open.py FILE.xdmf TIMES NX NY NZ XMAX_M ARRAY [ARRAY ...]
"""
import sys

from paraview import servermanager
from paraview.simple import XDMFReader


def main():
    path, times = sys.argv[1], int(sys.argv[2])
    dims = tuple(int(v) for v in sys.argv[3:6])
    xmax = float(sys.argv[6])
    arrays = set(sys.argv[7:])
    reader = XDMFReader(FileNames=[path])
    reader.UpdatePipelineInformation()
    steps = list(reader.TimestepValues)
    if len(steps) != times:
        sys.exit(f"FAIL: {len(steps)} time steps in ParaView, expected {times}")
    reader.UpdatePipeline(steps[-1])
    data = servermanager.Fetch(reader)
    if tuple(data.GetDimensions()) != dims:
        sys.exit(f"FAIL: grid {data.GetDimensions()} in ParaView, expected {dims}")
    bounds = data.GetBounds()
    if abs(bounds[1] - xmax) > 1e-9 * xmax:
        sys.exit(f"FAIL: x extends to {bounds[1]} m, expected {xmax} m")
    pd = data.GetPointData()
    names = {pd.GetArray(i).GetName() for i in range(pd.GetNumberOfArrays())}
    if names != arrays:
        sys.exit(f"FAIL: arrays {sorted(names)}, expected {sorted(arrays)}")
    velocity = pd.GetArray("velocity")
    if velocity is not None and velocity.GetNumberOfComponents() != 3:
        sys.exit("FAIL: velocity is not a vector")
    print(f"ParaView reads {path}: {len(steps)} times up to {steps[-1]:.4g} s, grid {dims}, "
          f"bounds {tuple(round(b, 9) for b in bounds)}, arrays {sorted(names)}")


main()
