"""A picture of a run for people: the body surfaces dem_app writes with its snapshots
(<dem output>/<name>_surfaces.xdmf, scene key dem.output.surfaces) coloured by v_z, and a
y-normal slice of the fluid velocity, at the last output time, drawn headless by pvbatch.

    /usr/bin/python3 tools/render_run.py runs/study/small/cube_phi0.300/scene.yaml
"""
import os
import shutil
import subprocess

from . import io


def surfaces_path(scene_path, scene=None):
    """<dem output>/<name>_surfaces.xdmf of a scene (written by dem_app when it writes body
    snapshots)."""
    s = scene or io.load_scene(scene_path)
    return os.path.join(io.dem_output_dir(scene_path, s), s["name"] + "_surfaces.xdmf")


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
ColorBy(d, ("POINTS", "body_velocity", "Z"))
d.RescaleTransferFunctionToDataRange(True, False)
d.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction("body_velocity"), view)
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


def have_pvbatch():
    return bool(shutil.which("pvbatch") and shutil.which("xvfb-run"))


def render_png(scene_path, log=print):
    """<dem output>/<name>.png: the last output time, bodies coloured by v_z and a y-normal slice
    of the fluid velocity where the run wrote fields, by `xvfb-run -a -s "-screen 0 1280x1024x24"
    pvbatch --force-offscreen-rendering` (Debian's ParaView 5.11 needs an X display with 24-bit
    colour even off screen). Returns the PNG path, or None (with a message) when pvbatch or
    xvfb-run is missing. Raises FileNotFoundError when the run wrote no body surfaces."""
    if not have_pvbatch():
        log("render: pvbatch or xvfb-run not found (Debian: bash tools/setup_debian.sh "
            "--with-paraview); no picture")
        return None
    scene = io.load_scene(scene_path)
    bodies_xdmf = surfaces_path(scene_path, scene)
    if not os.path.exists(bodies_xdmf):
        raise FileNotFoundError(f"{bodies_xdmf}: no body surfaces (dem_app writes them with its "
                                "body snapshots unless dem.output.surfaces is false)")
    pvbatch, xvfb = shutil.which("pvbatch"), shutil.which("xvfb-run")
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
