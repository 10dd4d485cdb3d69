"""Body surfaces for ParaView (docs/study.md, "Pictures"): each shape's triangles placed at each
body's pose, per output time, with the body velocity on its vertices, as HDF5 + XDMF (a temporal
collection of triangle meshes ParaView opens directly); and a headless pvbatch render of a run.

    /usr/bin/python3 tools/body_mesh.py runs/study/small/cube_phi0.300/scene.yaml [--png]

Reads the scene's shapes and the per-body trace <name>_bodies.csv; writes
<dem output>/<name>_surfaces.h5 and <name>_surfaces.xdmf. Shapes: sphere (icosphere, 320
triangles), cube, cuboid, ellipsoid (scaled icosphere); an stl shape is refused.
"""
import os
import shutil
import subprocess

import numpy as np

from . import geometry, io


def icosphere(level=2):
    """Unit sphere: an icosahedron with each triangle split in four `level` times."""
    t = (1 + 5**0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [np.array(p, float) / np.linalg.norm(p) for p in v]
    for _ in range(level):
        cache, faces = {}, []

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in cache:
                m = verts[i] + verts[j]
                verts.append(m / np.linalg.norm(m))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = faces
    return np.array(verts), np.array(f, dtype=np.int64)


def box_mesh(extents):
    """Axis-aligned box centred at the origin: 8 vertices, 12 triangles (outward normals)."""
    h = 0.5 * np.asarray(extents, float)
    v = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * h
    f = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1), (2, 3, 7), (2, 7, 6),
         (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return v, np.array(f, dtype=np.int64)


def shape_mesh(shape):
    """(vertices, triangles) of a scene shape entry in its own frame (centroid at the origin)."""
    kind = shape["kind"]
    if kind == "sphere":
        v, f = icosphere()
        return 0.5 * float(shape["diameter"]) * v, f
    if kind == "cube":
        return box_mesh([float(shape["edge"])] * 3)
    if kind == "cuboid":
        return box_mesh(shape["edges"])
    if kind == "ellipsoid":
        v, f = icosphere()
        return v * np.asarray(shape["semi_axes"], float), f
    raise ValueError(f"shape '{shape.get('name')}': kind {kind} has no surface mesh here "
                     "(sphere, cube, cuboid, ellipsoid)")


def body_shapes(scene_path, scene, ids):
    """Shape entry of each body id (bodies are numbered in scene order; a bodies file, a generator
    or an inline body each give one shape to all their bodies)."""
    shapes = {s["name"]: s for s in scene["shapes"]}
    if len(scene["shapes"]) == 1:
        return [scene["shapes"][0]] * len(ids)
    names = []
    for entry in scene["bodies"]:
        if "file" in entry and "shape" not in entry:
            raise ValueError("a bodies file with a shape column and several shapes: not supported")
        count = 1
        if "file" in entry:
            count = len(io.read_bodies_csv(io.resolve(scene_path, entry["file"]))[0])
        elif "generate" in entry:
            raise ValueError("generated bodies with several shapes: give one shape per scene")
        names += [entry["shape"]] * count
    return [shapes[names[int(i)]] for i in ids]


def write_surfaces(scene_path):
    """Writes <name>_surfaces.h5 + .xdmf next to the body trace; returns the .xdmf path."""
    import h5py
    scene = io.load_scene(scene_path)
    tr = io.Trace(io.trace_path(scene_path, scene))
    meshes = [shape_mesh(s) for s in body_shapes(scene_path, scene, tr.id)]
    nv = np.array([len(v) for v, _ in meshes])
    offsets = np.concatenate([[0], np.cumsum(nv)[:-1]])
    tri = np.concatenate([f + o for (_, f), o in zip(meshes, offsets)])
    local = np.concatenate([v for v, _ in meshes])          # (V, 3) in the body frames
    owner = np.repeat(np.arange(len(meshes)), nv)             # body of each vertex
    out_dir = io.dem_output_dir(scene_path, scene)
    base = scene["name"] + "_surfaces"
    h5_path = os.path.join(out_dir, base + ".h5")
    x, v, q = tr.vectors(""), tr.vectors("v"), tr.quaternions()
    grids = []
    with h5py.File(h5_path, "w") as h5:
        h5["triangles"] = tri
        h5["body_id"] = tr.id[owner]
        for k, t in enumerate(tr.time):
            rot = geometry.rotation_matrices(q[k])[owner]
            pts = np.einsum("vij,vj->vi", rot, local) + x[k][owner]
            g = h5.create_group(f"t{k:06d}")
            g["points"] = pts
            g["velocity"] = v[k][owner]
            g["vz"] = v[k][owner][:, 2]
            grids.append((t, f"t{k:06d}"))
    npts, ntri = len(local), len(tri)
    h5name = os.path.basename(h5_path)
    lines = ['<?xml version="1.0" ?>', '<Xdmf Version="3.0">', " <Domain>",
             '  <Grid Name="bodies" GridType="Collection" CollectionType="Temporal">']
    for t, g in grids:
        lines += [
            f'   <Grid Name="{g}" GridType="Uniform">', f'    <Time Value="{t!r}"/>',
            f'    <Topology TopologyType="Triangle" NumberOfElements="{ntri}">',
            f'     <DataItem Dimensions="{ntri} 3" NumberType="Int" Precision="8" '
            f'Format="HDF">{h5name}:/triangles</DataItem>', "    </Topology>",
            '    <Geometry GeometryType="XYZ">',
            f'     <DataItem Dimensions="{npts} 3" NumberType="Float" Precision="8" '
            f'Format="HDF">{h5name}:/{g}/points</DataItem>', "    </Geometry>",
            '    <Attribute Name="velocity" AttributeType="Vector" Center="Node">',
            f'     <DataItem Dimensions="{npts} 3" NumberType="Float" Precision="8" '
            f'Format="HDF">{h5name}:/{g}/velocity</DataItem>', "    </Attribute>",
            '    <Attribute Name="vz" AttributeType="Scalar" Center="Node">',
            f'     <DataItem Dimensions="{npts}" NumberType="Float" Precision="8" '
            f'Format="HDF">{h5name}:/{g}/vz</DataItem>', "    </Attribute>",
            '    <Attribute Name="body_id" AttributeType="Scalar" Center="Node">',
            f'     <DataItem Dimensions="{npts}" NumberType="Int" Precision="8" '
            f'Format="HDF">{h5name}:/body_id</DataItem>', "    </Attribute>", "   </Grid>"]
    lines += ["  </Grid>", " </Domain>", "</Xdmf>"]
    xdmf = os.path.join(out_dir, base + ".xdmf")
    with open(xdmf, "w") as f:
        f.write("\n".join(lines) + "\n")
    return xdmf


RENDER = r'''
import sys
from paraview.simple import *
bodies_file, fluid_file, png = sys.argv[1], sys.argv[2], sys.argv[3]
view = CreateView("RenderView")
SetActiveView(view)
view.ViewSize = [1200, 900]
view.OrientationAxesVisibility = 1
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [1, 1, 1]
bodies = XDMFReader(FileNames=[bodies_file])
readers = [bodies]
if fluid_file != "-":
    fluid = XDMFReader(FileNames=[fluid_file])
    readers.append(fluid)
# The last output time of either (the fluid's last field may come a step after the bodies' last
# snapshot; each reader then shows its latest data at or before it).
t = max([r.TimestepValues[-1] for r in readers
         if hasattr(r.TimestepValues, "__len__") and len(r.TimestepValues)] or [0.0])
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = t
view.ViewTime = t
d = Show(bodies, view)
ColorBy(d, ("POINTS", "vz"))
d.RescaleTransferFunctionToDataRange(True, False)
d.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction("vz"), view)
bar.Title, bar.ComponentTitle = "body v_z (m/s)", ""
bar.TitleColor, bar.LabelColor = [0, 0, 0], [0, 0, 0]
if fluid_file != "-":
    fluid.UpdatePipeline(t)
    b = fluid.GetDataInformation().GetBounds()
    s = Slice(Input=fluid)
    s.SliceType = "Plane"
    s.SliceType.Origin = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
    s.SliceType.Normal = [0, 1, 0]
    sd = Show(s, view)
    ColorBy(sd, ("POINTS", "velocity", "Magnitude"))
    sd.RescaleTransferFunctionToDataRange(False, False)
    sd.SetScalarBarVisibility(view, True)
    fbar = GetScalarBar(GetColorTransferFunction("velocity"), view)
    fbar.Title, fbar.ComponentTitle = "fluid |u| (m/s)", ""
    fbar.TitleColor, fbar.LabelColor = [0, 0, 0], [0, 0, 0]
    fbar.WindowLocation = "Upper Right Corner"
    GetColorTransferFunction("velocity").ApplyPreset("Viridis (matplotlib)", True)
d.RescaleTransferFunctionToDataRange(False, False)
Render(view)  # the first render places the camera; turn it afterwards (z up, seen from -y)
cam = GetActiveCamera()
cam.SetFocalPoint(0, 0, 0)
cam.SetPosition(0, -1, 0)
cam.SetViewUp(0, 0, 1)
cam.Azimuth(25)
cam.Elevation(20)
view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[1200, 900])
'''


def render_png(scene_path, bodies_xdmf, log=print):
    """PNG of the last output time: bodies coloured by v_z and a y-normal slice of the fluid
    velocity, by `xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch --force-offscreen-rendering`
    (Debian's ParaView 5.11 needs an X display with 24-bit colour even off screen). Returns the
    PNG path, or None (with a message) when pvbatch or xvfb-run is missing."""
    pvbatch, xvfb = shutil.which("pvbatch"), shutil.which("xvfb-run")
    if not pvbatch or not xvfb:
        log("render: pvbatch or xvfb-run not found (Debian: apt-get install paraview "
            "python3-paraview xvfb xauth); no picture")
        return None
    scene = io.load_scene(scene_path)
    out = scene.get("fluid", {}).get("output", {}).get("directory", ".")
    fluid = os.path.join(io.resolve(scene_path, out), scene["name"] + "_volume.xdmf")
    png = os.path.join(os.path.dirname(bodies_xdmf), scene["name"] + ".png")
    script = os.path.join(os.path.dirname(bodies_xdmf), "render.py")
    with open(script, "w") as f:
        f.write(RENDER)
    # Debian's pvbatch 5.11 under Xvfb fails now and then (30-40 % of the calls on the shared
    # machine, "bad X server connection" from a live server; the cause is not known): retry.
    for attempt in range(8):
        display = str(100 + (os.getpid() * 7 + attempt * 131) % 800)
        cmd = [xvfb, "-a", "-n", display, "-s", "-screen 0 1280x1024x24", pvbatch,
               "--force-offscreen-rendering", script, bodies_xdmf,
               fluid if os.path.exists(fluid) else "-", png]
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        if proc.returncode == 0 and os.path.exists(png):
            return png
    raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n"
                       f"{(proc.stdout + proc.stderr)[-3000:]}")
