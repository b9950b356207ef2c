#!/usr/bin/env python3
"""Checks scripts/plot-indent.py on an indent run directory:

  /usr/bin/python3 tests/check_plots.py RUN_DIR

runs it with --out in a fresh temporary directory, then checks that the three PNGs are PNGs, that
imprint.csv has one finite row per top-surface vertex with heights equal to z + u_z - z_top of the
last step (recomputed here from indent.h5), that the deepest point is below the surface and near the
axis, that the written steps' fields are read beside their own rows of the curve (P_max's among them),
that a missing run directory is an error, and that the run's curve alone (indent.h5 left out: a run
without fields) gives load_displacement.png, exit 0 and a line naming what it lacks. Prints ok or FAIL: ...,
exit status 0 or 1."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "plot-indent.py")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
PNGS = ("load_displacement.png", "imprint.png", "stress_slice.png")


class Failure(Exception):
    pass


def require(condition, message):
    if not condition:
        raise Failure(message)


def plot(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


def check_pngs(out):
    for name in PNGS:
        path = os.path.join(out, name)
        require(os.path.isfile(path), f"{name} was not written")
        with open(path, "rb") as f:
            head = f.read(len(PNG_MAGIC))
        require(head == PNG_MAGIC, f"{name} is not a PNG (starts with {head!r})")
        require(os.path.getsize(path) > 1000, f"{name} is only {os.path.getsize(path)} bytes")


def read_imprint(path):
    require(os.path.isfile(path), "imprint.csv was not written")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    require(rows and rows[0] == ["x_nm", "y_nm", "height_nm"], f"imprint.csv header is {rows[0] if rows else 'missing'}")
    try:
        table = np.array([[float(v) for v in r] for r in rows[1:]], ndmin=2)
    except ValueError as e:
        raise Failure(f"imprint.csv: {e}") from None
    require(table.shape[1:] == (3,), f"imprint.csv rows have {table.shape[1:]} columns, expected 3")
    return table


def expected_imprint(h5_path):
    """Top-surface (x, y, height) of the last step, computed from the file without the script's code."""
    with h5py.File(h5_path, "r") as f:
        x = f["geometry/vertices"][:]
        uz = f["fields/displacement"][-1, :, 2]
    size = float(np.ptp(x, axis=0).max())
    top = np.flatnonzero(np.abs(x[:, 2] - x[:, 2].max()) <= 1e-9 * size)
    return np.column_stack([x[top, 0], x[top, 1], x[top, 2] + uz[top] - x[:, 2].max()]), size


def by_position(table, size):
    """Rows ordered by position, on coordinates rounded to 1e-6 of the mesh size, so that the CSV's
    rounding of the digits cannot change the order."""
    key = np.round(table[:, :2] / (1e-6 * size)).astype(np.int64)
    order = np.lexsort((key[:, 1], key[:, 0]))
    return table[order], key[order]


def check_imprint(out, run_dir):
    got = read_imprint(os.path.join(out, "imprint.csv"))
    want, size = expected_imprint(os.path.join(run_dir, "indent.h5"))
    require(len(got) == len(want), f"imprint.csv has {len(got)} rows, the top surface {len(want)} vertices")
    require(np.isfinite(got).all(), "imprint.csv has non-finite values")
    require((np.diff(got[:, 0]) >= -1e-9 * size).all(), "imprint.csv is not sorted by x")
    h = got[:, 2]
    deepest = int(np.argmin(h))
    require(h[deepest] < -1e-6, f"the imprint is not below the surface: min height {h[deepest]:g} nm")
    width = float(np.ptp(want[:, 0]))
    r = float(np.hypot(*got[deepest, :2]))
    require(r < 0.5 * width, f"the deepest point is {r:g} nm from the axis, the top surface is {width:g} nm wide")
    got, gkey = by_position(got, size)
    want, wkey = by_position(want, size)
    require((gkey == wkey).all(), "imprint.csv positions differ from the top-surface vertices of indent.h5")
    diff = float(np.abs(got[:, 2] - want[:, 2]).max())
    require(diff < 1e-6, f"imprint.csv heights differ from indent.h5 by up to {diff:g} nm")
    return len(got), h[deepest], float(h.max()), diff


def check_field_rows(run_dir):
    """plot-indent's match of the written steps to the curve's rows (fields are written at some steps only,
    -output_fields_every): each written step's row holds its step, P_max's row is written (the end of loading)
    and the stress slice's width comes from that row's contact radius."""
    import importlib.util
    scripts = os.path.dirname(SCRIPT)
    sys.path.insert(0, scripts)
    spec = importlib.util.spec_from_file_location("plot_indent", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    curve, run, _ = mod.load_inputs(run_dir)
    with run.h5:
        steps = curve["step"][run.rows].astype(int)
        require(list(steps) == [int(k) for k in run.steps], f"written steps {list(run.steps)} read at rows of steps "
                f"{list(steps)}")
        top = int(np.argmax(curve["load_uN"]))
        peak = int(run.rows[mod.peak_step(run, curve)])
        require(peak == top, f"the slice's P_max is the curve's row {peak}, the largest load is at row {top}")
        reach = mod.slice_reach(run, curve)
        want = 3.0 * mod.contact_radius(curve, top)
        require(abs(reach - want) <= 1e-12 * want,
                f"the slice reaches {reach:g} nm, 3 contact radii at P_max are {want:g}")
    return len(run.steps), len(curve["step"])


def check_missing_dir(tmp):
    missing = os.path.join(tmp, "no-such-run")
    res = plot(missing, "--out", os.path.join(tmp, "never"))
    require(res.returncode != 0, "a missing run directory gave exit status 0")
    require(missing in res.stderr, f"the error for a missing run directory does not name it: {res.stderr.strip()!r}")


def check_without_fields(tmp, run_dir):
    bare = os.path.join(tmp, "bare")
    os.makedirs(bare)
    shutil.copy(os.path.join(run_dir, "load_displacement.csv"), bare)
    out = os.path.join(tmp, "bare-out")
    res = plot(bare, "--out", out)
    require(res.returncode == 0, f"a run without fields: exit {res.returncode}: {res.stderr.strip()}")
    require(os.path.isfile(os.path.join(out, "load_displacement.png")), "a run without fields: no curve drawn")
    require(not os.path.exists(os.path.join(out, "imprint.csv")), "a run without fields: an imprint.csv written")
    require("-output_fields 0" in res.stdout, f"a run without fields: no line says why ({res.stdout.strip()!r})")


def main(run_dir):
    with tempfile.TemporaryDirectory(prefix="check-plots-") as tmp:
        out = os.path.join(tmp, "out")
        res = plot(run_dir, "--out", out)
        require(res.returncode == 0, f"plot-indent.py exited with {res.returncode}: {res.stderr.strip()}")
        check_pngs(out)
        rows, hmin, hmax, diff = check_imprint(out, run_dir)
        written, steps = check_field_rows(run_dir)
        check_missing_dir(tmp)
        check_without_fields(tmp, run_dir)
    print(f"ok: 3 PNGs, imprint.csv {rows} rows, height {hmin:.4g} .. {hmax:.4g} nm, largest difference from "
          f"indent.h5 {diff:.2g} nm; fields of {written} of {steps} steps matched to their rows")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    try:
        main(sys.argv[1])
    except Failure as e:
        print(f"FAIL: {e}")
        sys.exit(1)
