#!/usr/bin/env python3
"""Runs scripts/export-curves.py on a finished indentation run and reads every file back with readers
written here from the formats' definitions (NIGET's doc/dataformat.txt and file-utils.c, the reader
of micromechanics' Indentation.loadHysitron, Gwyddion's GSF specification), comparing with the CSV,
summary.json and indent.h5 of the run. Where the real tools are installed it also reads the files with
them: the micromechanics package (Hysitron text) and gwyddion (--identify and --convert-to-gwy of the
height maps); each line says which reader checked what.

  /usr/bin/python3 tests/check_export_curves.py RUN_DIR --workdir DIR
"""
import argparse
import csv
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

import h5py
import numpy as np
from matplotlib import tri as mtri

from checklist import check, failures, status  # this folder

HERE = os.path.dirname(os.path.abspath(__file__))
EXPORT = os.path.join(HERE, "..", "scripts", "export-curves.py")
SECONDS = 2.5  # not the default 10, so that the option is exercised


def close(a, b, rtol, atol=0.0):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= atol + rtol * np.abs(b)))


# ------------------------------------------------------------------------------------- the run
def run_curve(run_dir):
    with open(os.path.join(run_dir, "load_displacement.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return {c: np.array([float(r[c]) for r in rows]) for c in ("t", "depth_nm", "load_uN", "contact_area_nm2")}


def run_surface(run_dir):
    """Top-surface vertices of the last step from indent.h5 (deformed x, y and the height), mirrored
    across y = 0 (and x = 0) for half (quarter) models, with the top-face triangles."""
    with h5py.File(os.path.join(run_dir, "indent.h5"), "r") as f:
        x = f["geometry/vertices"][:]
        cells = f["topology/cells"][:]
        u = f["fields/displacement"][-1]
    tol = 1e-9 * np.ptp(x, axis=0).max()
    top = np.abs(x[:, 2] - x[:, 2].max()) <= tol
    faces = {4: [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)],
             8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]}[cells.shape[1]]
    tris = []
    for face in faces:
        on = cells[top[cells][:, face].all(axis=1)][:, face]
        tris += [on[:, [0, k, k + 1]] for k in range(1, len(face) - 1)]
    tris = np.concatenate(tris)
    p = np.column_stack([x[:, :2] + u[:, :2], x[:, 2] + u[:, 2] - x[:, 2].max()])
    keep = np.flatnonzero(top)
    for a in (0, 1):  # mirror: copy every point off the plane, and every triangle
        if abs(x[:, a].min()) <= tol:
            n = len(p)
            off = np.abs(p[:, a]) > tol
            image = np.arange(n)
            image[off] = n + np.arange(off.sum())
            q = p[off].copy()
            q[:, a] *= -1
            p = np.vstack([p, q])
            tris = np.vstack([tris, image[tris]])
            keep = np.r_[keep, image[keep[off[keep]]]]
    return p, keep, tris


def run_profile(run_dir):
    """The top profile (deformed radius, height; by radius) of an axisymmetric section's last step, or None for a
    3D run (a section: 2D cells, every vertex on y = 0)."""
    with h5py.File(os.path.join(run_dir, "indent.h5"), "r") as f:
        x = f["geometry/vertices"][:]
        cells = f["topology/cells"][:]
        u = f["fields/displacement"][-1]
    tol = 1e-9 * np.ptp(x, axis=0).max()
    if cells.shape[1] not in (3, 4) or np.abs(x[:, 1]).max() > tol:
        return None
    top = np.flatnonzero(np.abs(x[:, 2] - x[:, 2].max()) <= tol)
    r, h = x[top, 0] + u[top, 0], u[top, 2]
    order = np.argsort(r)
    return r[order], h[order]


# ------------------------------------------------------------------------------------- readers
def read_niget(path):
    """NIGET's reader: the header by sscanf('#NIGET %d %d %d %d'), then every line of which two
    numbers can be read (',' taken as the decimal point, as localize_decimal_points does)."""
    with open(path) as f:
        head = f.readline()
        m = re.fullmatch(r"#NIGET (\d+) (\d+) (\d+) (\d+)\n", head)
        data = []
        for line in f:
            parts = line.replace(",", ".").split()
            try:
                data.append((float(parts[0]), float(parts[1])))
            except (IndexError, ValueError):
                continue
    return (tuple(int(g) for g in m.groups()) if m else None), np.array(data)


def read_hysitron(path):
    """micromechanics' loadHysitron for .txt: line 2 empty, 'Number of Points' in line 3, 'Depth (nm)'
    in line 4, then numbers (columns depth nm, load uN, time s)."""
    with open(path, encoding="iso-8859-1") as f:
        head = [f.readline() for _ in range(4)]
        data = np.loadtxt(f)
    return head, data


def read_gsf(path):
    """Gwyddion Simple Field 1.0: magic line, 'name = value' lines, 1-4 NUL bytes to a multiple of
    4, then XRes*YRes little-endian float32."""
    raw = open(path, "rb").read()
    magic = b"Gwyddion Simple Field 1.0\n"
    if not raw.startswith(magic):
        return None, None, "no magic line"
    end = raw.index(b"\0")
    fields = {}
    for line in raw[len(magic):end].decode("ascii").splitlines():
        name, value = line.split("=", 1)
        fields[name.strip()] = value.strip()
    start = end + (4 - end % 4)
    if raw[end:start] != b"\0" * (start - end):
        return None, None, "padding is not NUL bytes to a multiple of 4"
    nx, ny = int(fields["XRes"]), int(fields["YRes"])
    if len(raw) - start != 4 * nx * ny:
        return None, None, f"{len(raw) - start} data bytes for {nx} x {ny} float32"
    return fields, np.frombuffer(raw, "<f4", offset=start).reshape(ny, nx), ""


# -------------------------------------------------------------------------------------- checks
def check_niget(path, curve, summary, hold):
    idx, data = read_niget(path)
    check(idx is not None, f"{path}: first line '#NIGET a b c d'")
    n = len(curve["t"])
    check(data.shape == (n + 1, 2), f"NIGET: {n + 1} rows (the origin and the {n} CSV rows), read {data.shape}")
    if idx is None or data.shape != (n + 1, 2):
        return
    check(close(data[0], [0, 0], 0), "NIGET row 0 is the undeformed start (0 nm, 0 mN)")
    check(close(data[1:, 0], curve["depth_nm"], 1e-11), "NIGET depth (nm) equals depth_nm of the CSV")
    check(close(data[1:, 1] * 1000, curve["load_uN"], 1e-11, 1e-15), "NIGET force (mN) times 1000 equals load_uN")
    a, b, c, d = idx
    check(0 <= a <= b <= c <= d < len(data),
          f"NIGET indices {idx} ordered within the {len(data)} rows (NIGET's split_hF_data_spec)")
    # Independent of the t-based split: contact at the origin, end of loading at h_max of the summary.
    check(a == 0 and data[1, 1] > 0, f"contact index {a} is the origin (load already rises at the first step)")
    check(abs(data[b, 0] - summary["h_max_nm"]) <= 1e-9 * summary["h_max_nm"] and abs(curve["t"][b - 1] - 1) < 1e-8,
          f"start of hold {b}: t = {curve['t'][b - 1]:.10g}, depth {data[b, 0]} nm = h_max of summary.json")
    t_c = curve["t"][c - 1]
    t_next = curve["t"][c] if c < n else np.inf
    check(abs(t_c - (1 + hold)) < 1e-8 and t_next > 1 + hold + 1e-8,
          f"start of unload {c}: t = {t_c:.10g} = 1 + load_hold {hold:g}, the next row unloads")
    check(d == n and abs(data[d, 0] - summary["final_depth_nm"]) <= 1e-9 * max(summary["final_depth_nm"], 1),
          f"end {d}: the last row, depth {data[d, 0]} nm = final_depth_nm")
    # indent's own reader of measured curves (scripts/indentcurves.py) reads it back: nm, uN and the segments
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
    import indentcurves
    back = indentcurves.read(path)
    check(close(back["depth"][1:], curve["depth_nm"], 1e-11) and close(back["load"][1:], curve["load_uN"], 1e-11, 1e-12)
          and [s[1:] for s in back["segments"]] == [(a, b)] + ([(b, c)] if c > b else []) + ([(c, d)] if d > c else []),
          f"scripts/indentcurves.py reads it back: depth, load (uN) and segments {back['segments']}")


def check_hysitron(path, curve):
    head, data = read_hysitron(path)
    n = len(curve["t"]) + 1
    check(head[0].strip() != "" and head[1] == "\n" and head[2] == f"Number of Points = {n}\n",
          f"Hysitron header: date line, empty line, 'Number of Points = {n}'")
    check(head[3] == "Depth (nm)\tLoad (\u00b5N)\tTime (s)\n",
          "Hysitron column line 'Depth (nm)\\tLoad (µN)\\tTime (s)' (latin-1)")
    ok = data.shape == (n, 3)
    check(ok, f"Hysitron: {n} rows of 3 columns, read {data.shape}")
    if not ok:
        return
    check(close(data[0], [0, 0, 0], 0), "Hysitron row 0 is the undeformed start")
    check(close(data[1:, 0], curve["depth_nm"], 1e-11), "Hysitron depth (nm) equals depth_nm")
    check(close(data[1:, 1], curve["load_uN"], 1e-11), "Hysitron load (uN) equals load_uN")
    check(close(data[1:, 2], SECONDS * curve["t"], 1e-9), f"Hysitron time (s) equals {SECONDS} s times t")
    check(bool(np.all(np.diff(data[:, 2]) > 0)), "Hysitron time increases")
    try:
        from micromechanics import indentation  # the real reader, where installed (PyPI: micromechanics)
    except ImportError:
        print(f"note micromechanics not importable by {sys.executable}: Hysitron file checked by the reader above only")
        return
    ind = indentation.Indentation(path)
    # loadHysitron drops the first point of a non-CSM file (here the origin) and converts to um, mN.
    got = ind.h.size == n - 1 and close(ind.h * 1e3, curve["depth_nm"], 1e-12) and \
        close(ind.p * 1e3, curve["load_uN"], 1e-12) and close(ind.t, SECONDS * curve["t"], 1e-9)
    check(bool(got), f"micromechanics {getattr(sys.modules.get('micromechanics'), '__version__', '?')} "
          f"Indentation() reads it as Hysitron: {ind.h.size} points, depth, load and time equal the CSV")


def check_xyz(path, pts):
    data = np.loadtxt(path)
    ok = data.ndim == 2 and data.shape[1] == 3 and len(data) == len(pts)
    check(ok, f"imprint.xyz: {len(pts)} lines 'x y z' (top-surface vertices, mirrored), read {data.shape}")
    if not ok:
        return
    a = data[np.lexsort((np.round(data[:, 1], 6), np.round(data[:, 0], 6)))]
    b = pts[np.lexsort((np.round(pts[:, 1], 6), np.round(pts[:, 0], 6)))]
    check(close(a, b, 1e-9, 1e-9), f"imprint.xyz equals the deformed top surface of indent.h5 (largest difference "
          f"{np.abs(a - b).max():.3g} nm); height from {a[:, 2].min():.6g} to {a[:, 2].max():.6g} nm")


def check_gsf(path, p, keep, tris, curve):
    fields, grid, why = read_gsf(path)
    check(fields is not None, f"imprint.gsf follows the GSF layout {why}")
    if fields is None:
        return
    nx, ny = int(fields["XRes"]), int(fields["YRes"])
    xr, yr = float(fields["XReal"]) * 1e9, float(fields["YReal"]) * 1e9
    x0, y0 = float(fields["XOffset"]) * 1e9, float(fields["YOffset"]) * 1e9
    check(fields.get("XYUnits") == "m" and fields.get("ZUnits") == "m" and abs(x0 + xr / 2) < 1e-6 * xr,
          f"imprint.gsf: {nx} x {ny} pixels over {xr:.6g} x {yr:.6g} nm centred on the axis, units m")
    radius = np.sqrt(curve["contact_area_nm2"].max() / np.pi)
    check(abs(xr / 2 - 3 * radius) <= 1e-6 * xr,
          f"default half-width {xr / 2:.6g} nm = 3 contact radii ({radius:.6g} nm)")
    # The reference: matplotlib's linear interpolation on the same top-surface triangles, at the pixel
    # centres (Gwyddion's convention: offset + (j + 1/2) * real / res).
    gx = x0 + (np.arange(nx) + 0.5) * xr / nx
    gy = y0 + (np.arange(ny) + 0.5) * yr / ny
    X, Y = np.meshgrid(gx, gy)
    ref = mtri.LinearTriInterpolator(mtri.Triangulation(p[:, 0], p[:, 1], tris), p[:, 2])(X, Y)
    z = grid.astype(float) * 1e9
    covered = ~np.ma.getmaskarray(ref)
    check(bool(covered.all()), f"every pixel centre lies on the top surface ({covered.sum()} of {covered.size})")
    err = np.abs(z - np.ma.filled(ref, np.nan))[covered]
    scale = np.abs(p[keep, 2]).max()
    check(bool(np.all(err <= 1e-6 * scale)), f"imprint.gsf heights equal the interpolated imprint of indent.h5 "
          f"(largest difference {err.max():.3g} nm of {scale:.4g} nm; float32)")
    i, j = np.unravel_index(np.argmin(z), z.shape)
    # A plastic print is deepest under the tip, on the axis; an elastic run leaves none to locate.
    slack = 0.2 * radius + 2 * xr / nx
    near_axis = p[keep, 2].min() >= 0 or (abs(gx[j]) <= slack and abs(gy[i]) <= slack)
    check(z.min() >= p[keep, 2].min() - 1e-6 * scale and near_axis,
          f"deepest pixel {z.min():.5g} nm at ({gx[j]:.4g}, {gy[i]:.4g}) nm (on the axis if plastic); deepest vertex "
          f"{p[keep, 2].min():.5g} nm; pile-up {z.max():.4g} nm")


def check_section(out, profile, curve):
    """A section's imprint.gsf is its profile revolved (interpolated at each pixel's distance from the axis), and
    imprint.xyz the same pixels."""
    r, h = profile
    fields, grid, why = read_gsf(os.path.join(out, "imprint.gsf"))
    check(fields is not None, f"imprint.gsf follows the GSF layout {why}")
    if fields is None:
        return
    nx, ny = int(fields["XRes"]), int(fields["YRes"])
    xr, x0 = float(fields["XReal"]) * 1e9, float(fields["XOffset"]) * 1e9
    radius = np.sqrt(curve["contact_area_nm2"].max() / np.pi)
    check(nx == ny and abs(x0 + xr / 2) < 1e-6 * xr and abs(xr / 2 - 3 * radius) <= 1e-6 * xr,
          f"imprint.gsf: {nx} x {ny} pixels, {xr:.6g} nm wide, centred on the axis: 3 contact radii ({radius:.6g} nm)")
    g = x0 + (np.arange(nx) + 0.5) * xr / nx
    X, Y = np.meshgrid(g, g)
    ref = np.interp(np.hypot(X, Y), r, h)
    z = grid.astype(float) * 1e9
    scale = np.abs(h).max()
    err = np.abs(z - ref).max()
    check(err <= 1e-6 * scale, f"imprint.gsf heights are the section's top profile at each pixel's radius (largest "
          f"difference {err:.3g} nm of {scale:.4g} nm; float32)")
    i, j = np.unravel_index(np.argmin(z), z.shape)
    check(np.hypot(g[j], g[i]) <= xr / nx, f"deepest pixel {z.min():.5g} nm at ({g[j]:.4g}, {g[i]:.4g}) nm, on the "
          f"axis (deepest vertex {h.min():.5g} nm)")
    data = np.loadtxt(os.path.join(out, "imprint.xyz"))
    pts = np.column_stack([X.ravel(), Y.ravel()])
    ok = data.shape == (len(pts), 3)
    if ok:
        data = data[np.lexsort((data[:, 1], data[:, 0]))]
        pts = pts[np.lexsort((pts[:, 1], pts[:, 0]))]
        # the pixels to the 10 digits of the GSF header's width; each height the profile's at the pixel's own printed
        # position, to 10 digits, plus what the 10 digits of that position change it by along the profile's slope
        slope = np.abs(np.diff(h) / np.diff(r)).max()
        rad = np.hypot(data[:, 0], data[:, 1])
        ok = close(data[:, :2], pts, 0.0, 1e-9 * xr) and close(data[:, 2], np.interp(rad, r, h), 1e-9,
                                                                    1e-9 + 1e-9 * slope * rad.max())
    check(ok, f"imprint.xyz: the {len(pts)} pixels of imprint.gsf with the profile's heights, read {data.shape}")


def check_fit_reads(out, run_dir):
    """scripts/indent-fit.py's --imprint reads both files back (centred on the axis, leveled on its ring) as the
    run's own top surface, to float32 and to the leveling (a plane on the map, a mean on the model)."""
    sys.path.insert(0, os.path.join(HERE, "..", "scripts"))
    from indentfit import imprint
    surface = imprint.run_surface(run_dir)
    for name in ("imprint.xyz", "imprint.gsf"):
        try:
            m = imprint.load(os.path.join(out, name), "nm", "0,0")
        except imprint.ImprintError as e:
            # an elastic run, unloaded, leaves no print to fit: refused in one line
            z = np.loadtxt(os.path.join(out, "imprint.xyz"))[:, 2]
            check("no imprint" in str(e) and z.min() > -1e-6,
                  f"indent-fit's --imprint refuses {name} of a run that left no print: {e}")
            continue
        d = float(np.abs(m.model_heights(surface) - m.z).max())
        check(d <= 1e-3 * m.depth, f"indent-fit's --imprint reads {name} as the run's surface: {len(m.z)} points, "
              f"largest difference {d:.3g} nm of the {m.depth:.4g} nm imprint")


def check_gwyddion(out):
    exe = shutil.which("gwyddion")
    if not exe:
        print("note gwyddion not installed: GSF and XYZ checked by the readers above only")
        return
    ident = subprocess.run([exe, "--identify", "imprint.gsf", "imprint.xyz"], cwd=out, capture_output=True, text=True)
    check("imprint.gsf: Gwyddion Simple Field" in ident.stdout and "imprint.xyz: XYZ data" in ident.stdout,
          f"gwyddion --identify: {' | '.join(ident.stdout.strip().splitlines())}")
    for name in ("imprint.gsf", "imprint.xyz"):
        gwy = os.path.join(out, name + ".gwy")
        res = subprocess.run([exe, "--no-log-to-file", f"--convert-to-gwy={gwy}", name], cwd=out,
                             capture_output=True, text=True, timeout=120)
        size = os.path.getsize(gwy) if os.path.isfile(gwy) else 0
        check(res.returncode == 0 and size > 0,
              f"gwyddion --convert-to-gwy reads {name} (exit {res.returncode}, {size} bytes)")


def check_without_fields(run_dir, bare):
    """A run without fields (its CSV and summary.json, no indent.h5): the two curves, as the whole run's, and a
    line naming what it lacks, exit 0."""
    os.makedirs(bare)
    for name in ("load_displacement.csv", "summary.json"):
        shutil.copy(os.path.join(run_dir, name), bare)
    res = subprocess.run([sys.executable, EXPORT, bare, "--segment-seconds", str(SECONDS)], capture_output=True,
                         text=True)
    check(res.returncode == 0 and "-output_fields 0" in res.stdout,
          f"a run without fields: exit {res.returncode}, a line naming what it lacks ('{res.stdout.strip()}')")
    for name in ("curve.niget", "curve_hysitron.txt"):
        with open(os.path.join(bare, name), "rb") as a, open(os.path.join(os.path.dirname(bare), name), "rb") as b:
            check(a.read() == b.read(), f"a run without fields: {name} equals the whole run's")
    check(not os.path.exists(os.path.join(bare, "imprint.xyz")), "a run without fields: no imprint.xyz")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--workdir", required=True)
    args = ap.parse_args()
    out = args.workdir
    shutil.rmtree(out, ignore_errors=True)
    cmd = [sys.executable, EXPORT, args.run_dir, "--out", out, "--segment-seconds", str(SECONDS)]
    print("+", " ".join(cmd), flush=True)
    res = subprocess.run(cmd)
    check(res.returncode == 0, f"export-curves.py exit status {res.returncode}")
    if res.returncode:
        return 1
    curve = run_curve(args.run_dir)
    with open(os.path.join(args.run_dir, "summary.json")) as f:
        summary = json.load(f)
    words = shlex.split(summary["options"])
    hold = float(words[words.index("-load_hold") + 1]) if "-load_hold" in words else 0.0
    check_niget(os.path.join(out, "curve.niget"), curve, summary, hold)
    check_hysitron(os.path.join(out, "curve_hysitron.txt"), curve)
    profile = run_profile(args.run_dir)
    if profile is not None:
        check_section(out, profile, curve)
    else:
        p, keep, tris = run_surface(args.run_dir)
        check_xyz(os.path.join(out, "imprint.xyz"), p[keep])
        check_gsf(os.path.join(out, "imprint.gsf"), p, keep, tris, curve)
    check_fit_reads(out, args.run_dir)
    check_gwyddion(out)
    check_without_fields(args.run_dir, os.path.join(out, "bare"))
    bad = subprocess.run([sys.executable, EXPORT, os.path.join(out, "missing")], capture_output=True, text=True)
    check(bad.returncode == 2 and bad.stderr.startswith("export-curves: error:"),
          f"a missing run directory: exit {bad.returncode}, '{bad.stderr.strip()}'")
    print(f"{len(failures)} failed" if failures else "all checks passed")
    return status()


if __name__ == "__main__":
    sys.exit(main())
