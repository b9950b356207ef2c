#!/usr/bin/env python3
"""Checks scripts/groove-profile.py on a finished indent run (it runs no indent itself):

  /usr/bin/python3 tests/check_groove.py --script scripts/groove-profile.py --run RUN_DIR [--out DIR]

runs the script on RUN_DIR with --out DIR (default a fresh temporary directory), then checks that
groove_along.csv, groove_across.csv and groove.png are there, that the profiles parse, are finite and
ordered along their line, that every top-surface vertex on the track's line (y = the axis' y, taken
from scratch.csv here too) is a point of the profile along it at its deformed x with its height
z + u_z - z_top within 1e-9 nm (recomputed here from indent.h5, without the script's code), and for a
half model whose track lies on the mirror plane y = 0 that the profile is exactly those vertices; that
both profiles give the same height where they cross; that the printed groove depth and pile-up lie
within the heights of the surface; and that a missing run directory gives exit status 2 and one line
'groove-profile.py: error: ...'. Prints ok or FAIL per check; exit status 0, 1 on a failed check, 2 on
bad arguments.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from checklist import check, failures, status  # this folder

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
HEIGHT_TOL = 1e-9  # nm: the profile holds the vertices' own values, printed with 15 digits


# ------------------------------------------------------------------------------------- the run
def surface(run_dir):
    """Top-surface vertices of the last step: deformed x, y, height, with the mirror images of a quarter
    model's across x = 0 (the profile along y = 0 runs through both); the plane tolerance; whether the
    model is mirrored on y = 0 (a half or quarter model)."""
    with h5py.File(os.path.join(run_dir, "indent.h5"), "r") as f:
        x = f["geometry/vertices"][:]
        u = f["fields/displacement"][-1]
    tol = 1e-9 * float(np.ptp(x, axis=0).max())
    top = np.abs(x[:, 2] - x[:, 2].max()) <= tol
    p = np.column_stack([x[top, :2] + u[top, :2], x[top, 2] + u[top, 2] - x[:, 2].max()])
    if abs(x[:, 0].min()) <= tol and x[:, 0].max() > tol:
        image = p[np.abs(p[:, 0]) > tol] * [-1, 1, 1]
        p = np.vstack([p, image])
    half = abs(x[:, 1].min()) <= tol and x[:, 1].max() > tol
    return p, tol, half


def track(run_dir):
    """The axis' y and the middle x of the slide, from scratch.csv's rows with distance_nm > 0; the
    origin for a run without scratch.csv or before its slide."""
    path = os.path.join(run_dir, "scratch.csv")
    if not os.path.exists(path):
        return 0.0, 0.0
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if float(r["distance_nm"]) > 0]
    if not rows:
        return 0.0, 0.0
    return float(rows[0]["y_nm"]), 0.5 * (float(rows[0]["x_nm"]) + float(rows[-1]["x_nm"]))


# ------------------------------------------------------------------------------------ the files
def read_profile(path, coordinate):
    name = os.path.basename(path)
    if not check(os.path.isfile(path), f"{name} written"):
        return None
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not check(bool(rows) and rows[0] == [coordinate, "height_nm"], f"{name} header {coordinate},height_nm"):
        return None
    try:
        table = np.array([[float(v) for v in r] for r in rows[1:]], dtype=float)
    except ValueError as e:
        check(False, f"{name} parses ({e})")
        return None
    if not check(table.ndim == 2 and table.shape[0] >= 2 and table.shape[1] == 2,
                 f"{name}: at least 2 rows of 2 numbers (got shape {table.shape})"):
        return None
    check(bool(np.isfinite(table).all()), f"{name}: every value finite")
    check(bool((np.diff(table[:, 0]) > 0).all()), f"{name}: {coordinate} strictly increasing")
    return table


def check_png(path):
    name = os.path.basename(path)
    if check(os.path.isfile(path), f"{name} written"):
        with open(path, "rb") as f:
            head = f.read(len(PNG_MAGIC))
        check(head == PNG_MAGIC and os.path.getsize(path) > 1000, f"{name} is a PNG ({os.path.getsize(path)} bytes)")


def check_vertices_on_track(along, p, y_axis, tol, half):
    """Every vertex on the track's line is a point of the profile, with its height; on the mirror plane
    of a half model nothing else is (no triangle crosses the plane)."""
    on_line = p[np.abs(p[:, 1] - y_axis) <= tol]
    if half and not check(len(on_line) >= 2, f"{len(on_line)} top-surface vertices on y = {y_axis:g} nm"):
        return
    if len(on_line) == 0:
        print(f"skip no vertex lies on y = {y_axis:g} nm (a full model): the profile is made of crossings only")
        return
    x = along[:, 0]
    k = np.clip(np.searchsorted(x, on_line[:, 0]), 1, len(x) - 1)
    nearest = np.where(np.abs(x[k - 1] - on_line[:, 0]) <= np.abs(x[k] - on_line[:, 0]), k - 1, k)
    dx = float(np.abs(x[nearest] - on_line[:, 0]).max())
    dh = float(np.abs(along[nearest, 1] - on_line[:, 2]).max())
    check(dx <= tol, f"each of the {len(on_line)} vertices on the line is a point of groove_along.csv "
          f"(largest distance in x {dx:.2g} nm, tolerance {tol:.2g})")
    check(dh <= HEIGHT_TOL, f"the profile's heights there are the vertices' z + u_z - z_top "
          f"(largest difference {dh:.2g} nm, tolerance {HEIGHT_TOL:g})")
    if half and abs(y_axis) <= tol:
        distinct = len(np.unique(np.round(on_line[:, 0] / tol)))
        check(len(along) == distinct, f"on the mirror plane the profile is the vertices alone "
              f"({len(along)} points, {distinct} vertices)")


def check_printed(stdout, along, across, p):
    """The line's depth is no deeper than the lowest point on the track's line; its pile-up no higher
    than the surface's highest vertex and no lower than the section across, which it includes. The
    line prints 4 digits."""
    m = re.search(r"groove depth (\S+) nm .*largest pile-up beside it (\S+) nm", stdout)
    if not check(m is not None, f"one line with the groove depth and the pile-up: {stdout.strip().splitlines()[-1:]}"):
        return
    depth, pile = float(m.group(1)), float(m.group(2))
    if not check(np.isfinite(depth) and np.isfinite(pile), f"depth {depth:g} nm and pile-up {pile:g} nm are finite"):
        return
    slack = 1e-3 * max(abs(depth), abs(pile), 1e-6)
    check(-depth >= along[:, 1].min() - slack, f"-depth {-depth:g} >= the lowest height on the track's line "
          f"{along[:, 1].min():g} nm")
    check(across[:, 1].max() - slack <= pile <= p[:, 2].max() + slack,
          f"pile-up {pile:g} nm between the highest point across ({across[:, 1].max():g}) and of the surface "
          f"({p[:, 2].max():g} nm)")


def check_bad_input(script, tmp):
    missing = os.path.join(tmp, "no-such-run")
    res = subprocess.run([sys.executable, script, missing, "--out", os.path.join(tmp, "never")],
                         capture_output=True, text=True)
    lines = res.stderr.strip().splitlines()
    check(res.returncode == 2 and len(lines) == 1 and lines[0].startswith("groove-profile.py: error: ")
          and missing in lines[0], f"a missing run directory: exit {res.returncode}, {lines!r}")
    check(not os.path.exists(os.path.join(tmp, "never")), "and no output directory made")


def main():
    ap = argparse.ArgumentParser(prog="check_groove.py", description=__doc__.split("\n")[0])
    ap.add_argument("--script", required=True, help="scripts/groove-profile.py")
    ap.add_argument("--run", required=True, help="an indent run directory with indent.h5")
    ap.add_argument("--out", help="directory for the script's files (default: a temporary one, removed)")
    args = ap.parse_args()
    if not os.path.isfile(args.script):
        print(f"check_groove.py: --script '{args.script}' does not exist", file=sys.stderr)
        return 2
    if not os.path.isfile(os.path.join(args.run, "indent.h5")):
        print(f"check_groove.py: --run '{args.run}' has no indent.h5", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="check-groove-") as tmp:
        out = args.out or os.path.join(tmp, "out")
        res = subprocess.run([sys.executable, args.script, args.run, "--out", out], capture_output=True, text=True)
        print(res.stdout, end="")
        if not check(res.returncode == 0, f"groove-profile.py exit status {res.returncode}: {res.stderr.strip()}"):
            return 1
        along = read_profile(os.path.join(out, "groove_along.csv"), "x_nm")
        across = read_profile(os.path.join(out, "groove_across.csv"), "y_nm")
        check_png(os.path.join(out, "groove.png"))
        p, tol, half = surface(args.run)
        y_axis, x_mid = track(args.run)
        if along is not None:
            check_vertices_on_track(along, p, y_axis, tol, half)
        if along is not None and across is not None:
            a = float(np.interp(x_mid, along[:, 0], along[:, 1]))
            c = float(np.interp(y_axis, across[:, 0], across[:, 1]))
            check(abs(a - c) <= HEIGHT_TOL, f"where they cross (x = {x_mid:g}, y = {y_axis:g} nm) both profiles give "
                  f"the same height ({a:.12g} and {c:.12g} nm)")
            check_printed(res.stdout, along, across, p)
        check_bad_input(args.script, tmp)
    print("all checks passed" if not failures else f"{len(failures)} check(s) failed")
    return status()


if __name__ == "__main__":
    sys.exit(main())
