"""The drag of one body held fixed in a triply periodic box (a simple periodic array), for the
mesh-calibration checks (tools/mesh_vs_analytic_drag.py, tools/torus_drag_convergence.py;
docs/method.md, "Hydrodynamic radius calibration").

The body is pinned by a huge density (1e12 kg/m^3: it does not move within the run), a body
force drives the fluid through the array, and F / U is the body's load over the superficial
velocity, both averaged over the last fifth of the run.
"""
from . import io, run


def scene_text(name, box, dx, tau, radius, shape, force, end, interval):
    """A scene: `box` (m), `shape` one catalogue entry named s (YAML flow text), `force` the
    fluid's body force (m/s^2, 3 numbers), `radius` nominal | calibrated."""
    periodic = ", ".join(f"{a}_{s}: periodic" for a in "xyz" for s in ("min", "max"))
    return f"""name: {name}
time: {{end: {end}, progress_interval: 30}}
fluid:
  domain: {list(box)}
  dx: {dx}
  viscosity: 1.0e-6
  density: 1000
  tau: {tau}
  hydrodynamic_radius: {radius}
  characteristic_velocity: 2.0e-5
  characteristic_length: 4.0e-4
  body_force: {list(force)}
  boundaries: {{{periodic}}}
  output:
    directory: out_{name}
    series: {{interval: {interval}}}
dem:
  gravity: [0, 0, 0]
  periodic: xyz
  output: {{directory: out_{name}}}
shapes:
  - {shape}
bodies:
  - shape: s
    position: {[c / 2 for c in box]}
    density: 1.0e12
coupling:
  output_interval: {interval}
"""


def drag(build, path, axis, timeout=600):
    """Runs the scene at `path` (1 : 1 ranks); returns F, U, F's change since mid-run (relative)
    and the wall time, F and U along `axis` ("x", "y" or "z")."""
    wall, _ = run.run(build, path, 1, 1, timeout=timeout)
    rows = io.read_trace_by_body(io.trace_path(path))[0]
    series = io.read_rows(io.series_path(path))
    tail, st = rows[-len(rows) // 5:], series[-len(series) // 5:]
    force = sum(abs(r["f" + axis]) for r in tail) / len(tail)
    u = sum(abs(r["mean_u" + axis + "_m_s"]) for r in st) / len(st)
    mid = abs(rows[len(rows) // 2]["f" + axis])
    return force, u, (force - mid) / mid, wall
