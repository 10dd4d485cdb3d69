#!/usr/bin/env python3
"""Runs fluid_app on one scene in a fresh directory and checks what it did.

  fluid_case.py --launch "mpirun ... -np 3" --app fluid_app validate SCENE
      exit 0, one validation line (printed with its error and run time), and no files at all
      (the scene asks for none).
  fluid_case.py ... output SCENE
      the HDF5 + XDMF fields and the CSV series the scene asks for, read back with h5py and
      checked against the Taylor-Green initial state (positions from the XDMF geometry, SI).
  fluid_case.py ... diverge SCENE --expect TEXT
      exit 3, the diagnosis printed exactly once and containing TEXT, and the last good state
      file it names, readable and finite.
"""
import argparse
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def run(args, scene, workdir):
    # Output paths in a scene are relative to the scene file: run a copy inside `workdir`.
    local = os.path.join(workdir, os.path.basename(scene))
    shutil.copyfile(scene, local)
    cmd = shlex.split(args.launch) + [args.app, local]
    p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def fail(msg, out="", err=""):
    print("FAIL:", msg)
    if out:
        print("--- stdout ---\n" + out)
    if err:
        print("--- stderr ---\n" + err[-4000:])
    sys.exit(1)


def all_files(d):
    return sorted(os.path.relpath(os.path.join(r, f), d) for r, _, fs in os.walk(d) for f in fs)


def cmd_validate(args, work):
    rc, out, err = run(args, args.scene, work)
    lines = [l for l in out.splitlines() if l.startswith("validation ")]
    if rc != 0:
        fail(f"exit code {rc}", out, err)
    if len(lines) != 1:
        fail("expected one validation line", out, err)
    print(lines[0])
    files = [f for f in all_files(work) if f != os.path.basename(args.scene)]  # but the copy
    if files:
        fail(f"the scene asks for no output but files were written: {files}")


def xdmf_steps(path):
    """[(time, {name: (h5 file, dataset, dims)}, origin_xyz, spacing_xyz)] of a temporal XDMF."""
    root = ET.parse(path).getroot()
    coll = root.find("Domain/Grid")
    assert coll.get("CollectionType") == "Temporal", "not a temporal collection"
    steps = []
    for g in coll.findall("Grid"):
        t = float(g.find("Time").get("Value"))
        topo = g.find("Topology")
        assert topo.get("TopologyType") == "3DCoRectMesh"
        dims = [int(v) for v in topo.get("Dimensions").split()]
        geo = g.find("Geometry")
        assert geo.get("GeometryType") == "ORIGIN_DXDYDZ"
        origin_zyx, spacing_zyx = [[float(v) for v in d.text.split()] for d in geo.findall("DataItem")]
        attrs = {}
        for a in g.findall("Attribute"):
            item = a.find("DataItem")
            f, ds = item.text.strip().split(":")
            adims = [int(v) for v in item.get("Dimensions").split()]
            assert adims[:3] == dims, f"{a.get('Name')}: dimensions {adims} vs topology {dims}"
            attrs[a.get("Name")] = (f, ds, adims)
        steps.append((t, attrs, origin_zyx[::-1], spacing_zyx[::-1]))
    return steps


def cmd_output(args, work):
    rc, out, err = run(args, args.scene, work)
    if rc != 0:
        fail(f"exit code {rc}", out, err)
    outdir = os.path.join(work, args.directory)
    name = args.name
    files = all_files(outdir)
    print("files:", " ".join(files))
    for x in (f"{name}_volume.xdmf", f"{name}_{args.slice}.xdmf", f"{name}_series.csv"):
        if x not in files:
            fail(f"missing {x}")
    # Taylor-Green at t = 0: u = U (sin kx cos ky, -cos kx sin ky, 0), p = rho U^2/4 (cos 2kx + cos 2ky)
    U, L, rho0 = args.amplitude, args.period, args.density
    k = 2 * math.pi / L
    checked = 0
    for view in ("volume", args.slice):
        steps = xdmf_steps(os.path.join(outdir, f"{name}_{view}.xdmf"))
        h5s = sorted(f for f in files if f.endswith(".h5") and "_fields_" in f)
        if len(steps) != len(h5s):
            fail(f"{view}: {len(steps)} XDMF steps but {len(h5s)} field files")
        times = [s[0] for s in steps]
        if times != sorted(times) or times[0] != 0.0:
            fail(f"{view}: output times {times}")
        t, attrs, origin, spacing = steps[0]
        if set(attrs) != {"velocity", "density", "pressure"}:
            fail(f"{view}: attributes {sorted(attrs)}")
        with h5py.File(os.path.join(outdir, attrs["velocity"][0]), "r") as h5:
            if abs(h5.attrs["time"] - t) > 1e-15:
                fail(f"{view}: time attribute {h5.attrs['time']} vs XDMF {t}")
            u = h5[attrs["velocity"][1]][...]
            r = h5[attrs["density"][1]][...]
            p = h5[attrs["pressure"][1]][...]
            pressure_scale = rho0 * h5.attrs["dx"] ** 2 / h5.attrs["dt"] ** 2  # Pa per lattice unit
        nz, ny, nx = u.shape[:3]
        z, y, x = np.meshgrid(*[origin[d] + spacing[d] * np.arange(n) for d, n in ((2, nz), (1, ny), (0, nx))],
                              indexing="ij")
        ux = U * np.sin(k * x) * np.cos(k * y)
        uy = -U * np.cos(k * x) * np.sin(k * y)
        pa = rho0 * U * U / 4 * (np.cos(2 * k * x) + np.cos(2 * k * y))
        eu = max(np.abs(u[..., 0] - ux).max(), np.abs(u[..., 1] - uy).max(), np.abs(u[..., 2]).max())
        ep = np.abs(p - pa).max()
        # Lattice equation of state: p - p0 = c_s^2 (rho - rho0), c_s^2 = 1/3 in lattice units.
        er = np.abs(p - (r / rho0 - 1) / 3 * pressure_scale).max()
        print(f"{view}: {len(steps)} steps, shape {u.shape}, max |u - u_TG| = {eu:.3e} m/s, "
              f"max |p - p_TG| = {ep:.3e} Pa")
        if eu > args.rtol * U or ep > 1e-6 * rho0 * U * U:
            fail(f"{view}: the initial state in the file is not the Taylor-Green field")
        if er > 1e-6 * rho0 * U * U + 4 * args.rtol * pressure_scale:
            fail(f"{view}: density and pressure disagree by {er} Pa")
        checked += 1
    rows = open(os.path.join(outdir, f"{name}_series.csv")).read().splitlines()
    header = rows[0].split(",")
    if header != ["step", "time_s", "mean_ux_m_s", "mean_uy_m_s", "mean_uz_m_s", "kinetic_energy_J",
                  "mean_density_kg_m3", "max_mach"]:
        fail(f"series header {header}")
    data = np.array([[float(v) for v in r.split(",")] for r in rows[1:]])
    if len(data) != args.series_rows:
        fail(f"series has {len(data)} rows, expected {args.series_rows}")
    ke0 = 0.5 * rho0 * U * U / 2 * args.volume  # <|u|^2> = U^2/2 over the nodes
    print(f"series: {len(data)} rows, kinetic energy {data[0, 5]:.6e} J (expected {ke0:.6e}), "
          f"mean density {data[0, 6]}")
    if abs(data[0, 5] - ke0) > 1e-9 * ke0 or abs(data[0, 6] - rho0) > 1e-9 * rho0:
        fail("series values at t = 0")
    if not np.all(np.diff(data[:, 5]) < 0):
        fail("kinetic energy of a decaying vortex must fall every step")
    if np.abs(data[:, 2:5]).max() > 1e-12 * U:
        fail("mean velocity of the vortex array must stay zero")
    if args.pvpython:
        # The same files through ParaView's XDMF reader, as a user opens them.
        for view, nz in (("volume", args.cells[2]), (args.slice, 1)):
            cmd = [args.pvpython, "--force-offscreen-rendering",
                   os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_open.py"),
                   os.path.join(outdir, f"{name}_{view}.xdmf"), str(len(steps)),
                   str(args.cells[0]), str(args.cells[1]), str(nz),
                   repr(args.period - args.period / args.cells[0] / 2),
                   "velocity", "density", "pressure"]
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
            if p.returncode != 0:
                fail(f"ParaView could not read {view}", p.stdout, p.stderr)
            print(p.stdout.strip().splitlines()[-1])


def cmd_diverge(args, work):
    rc, out, err = run(args, args.scene, work)
    if rc != 3:
        fail(f"exit code {rc}, expected 3 (unstable)", out, err)
    n = err.count("fluid is unstable:")
    if n != 1:
        fail(f"the diagnosis was printed {n} times, expected once", out, err)
    diag = err[err.index("fluid is unstable:"):]
    for need in [args.expect, "where: cell (", "when: step", "likely cause:", "Change the scene:",
                 "last good state"]:
        if need not in diag:
            fail(f"diagnosis lacks '{need}'", out, err)
    m = re.search(r"written to (\S+\.h5)", diag)
    if not m:
        fail("no last good state file named", out, err)
    path = os.path.join(work, m.group(1))
    # Every passing check replaced the file; the failing one must have left neither its
    # candidate nor anything but the last passing check's state.
    if os.path.exists(path + ".tmp"):
        fail(f"the failing check's candidate {path}.tmp was left", out, err)
    if not os.path.exists(os.path.splitext(path)[0] + ".xdmf"):
        fail(f"no XDMF next to {path}", out, err)
    with h5py.File(path, "r") as h5:
        u = h5["volume/velocity"][...]
        rho = h5["volume/density"][...]
        step = int(h5.attrs["step"])
    if not (np.all(np.isfinite(u)) and np.all(rho > 0)):
        fail("the last good state is not good")
    said = re.search(r"last good state \(step (\d+),", diag)
    if not said or int(said.group(1)) != step or step != args.last_good_step:
        fail(f"the file holds step {step}; expected step {args.last_good_step}, as the diagnosis"
             " says", out, err)
    print(diag.split("\n[")[0])
    print(f"last good state {m.group(1)}: step {step}, {rho.size} nodes, finite, density > 0")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--launch", required=True)
    ap.add_argument("--app", required=True)
    sub = ap.add_subparsers(dest="cmd", required=True)
    v = sub.add_parser("validate")
    v.add_argument("scene")
    o = sub.add_parser("output")
    o.add_argument("scene")
    o.add_argument("--name", required=True)
    o.add_argument("--directory", required=True)
    o.add_argument("--slice", required=True)
    o.add_argument("--amplitude", type=float, required=True)
    o.add_argument("--period", type=float, required=True)
    o.add_argument("--density", type=float, required=True)
    o.add_argument("--volume", type=float, required=True)
    o.add_argument("--series-rows", type=int, required=True)
    o.add_argument("--cells", type=int, nargs=3, required=True, help="nodes per axis")
    o.add_argument("--pvpython", default="", help="also open the XDMF files with ParaView")
    o.add_argument("--rtol", type=float, default=1e-9, help="relative tolerance (1e-6: float32)")
    d = sub.add_parser("diverge")
    d.add_argument("scene")
    d.add_argument("--expect", required=True)
    d.add_argument("--last-good-step", type=int, required=True,
                   help="the step of the last passing check")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="lbdem_fluid_case_") as work:
        {"validate": cmd_validate, "output": cmd_output, "diverge": cmd_diverge}[args.cmd](args, work)
    print("PASS")


if __name__ == "__main__":
    main()
