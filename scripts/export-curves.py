#!/usr/bin/env python3
"""The curve and the residual imprint of an indentation run in the formats analysis tools read.

  /usr/bin/python3 scripts/export-curves.py RUN_DIR [--out DIR] [--segment-seconds S]
                                            [--gsf-pixels N] [--gsf-half-width NM]

Reads RUN_DIR/load_displacement.csv, RUN_DIR/summary.json (or the options stored in indent.h5) and
RUN_DIR/indent.h5, and writes into DIR (default RUN_DIR):

  curve.niget          NIGET's native format: '#NIGET a b c d' (row indices of the contact point, the
                       start of the hold, the start of the unloading and the end), then depth (nm) and
                       force (mN), tab-separated
  curve_hysitron.txt   Hysitron TriboScan text export: a date line, an empty line, 'Number of Points = N',
                       then Depth (nm), Load (uN), Time (s); read by the micromechanics package and NIGET
  imprint.xyz          the top surface at the last step as plain 'x y z' lines, nm: every vertex at its
                       deformed position, height relative to the undeformed surface, half and quarter
                       models mirrored to the full plane (Gwyddion: import as XYZ data); for an
                       axisymmetric section, the pixels of imprint.gsf (its profile revolved)
  imprint.gsf          the same surface interpolated linearly onto a square grid (Gwyddion Simple Field,
                       metres), centred on the indenter axis; a section's profile interpolated at each
                       pixel's distance from the axis

A run without fields (-output_fields 0: no indent.h5) gets its two curves and a line saying what it lacks.
Both curves start with the undeformed state (t = 0, depth 0, load 0), which the CSV does not list, so
that NIGET's contact point (whose depth and force it subtracts from the curve) is the first touch.
The run's pseudo-time t becomes seconds through --segment-seconds (a unit of t: the loading segment).
Exit status 2 on bad input.
"""
import argparse
import datetime
import json
import os
import shlex
import sys

import numpy as np

from heightmap import grid_axis, write_gsf  # this script's folder
from runfiles import InputError, mirror, open_fields, read_curve, top_profile, top_surface

CSV_NAME, SUMMARY_NAME, H5_NAME = "load_displacement.csv", "summary.json", "indent.h5"
# Steps end exactly on the load program's segment ends (src/solvers/loadpath.c); the CSV prints t with 10
# significant digits, so this separates an end from the next step (at least 1/1024 of a segment away).
T_TOL = 1e-8


# ----------------------------------------------------------------------------------------- inputs
def run_options(run_dir, h5):
    """The options string of the run: summary.json's, or indent.h5's for a run without a summary
    (stopped before the end)."""
    path = os.path.join(run_dir, SUMMARY_NAME)
    if os.path.isfile(path):
        try:
            with open(path) as f:
                summary = json.load(f)
        except (OSError, ValueError) as e:
            raise InputError(f"{path}: not JSON ({e})") from None
        return summary.get("options", ""), summary.get("start_time")
    if h5 is not None and "options" in h5.attrs:
        return h5.attrs["options"].decode(), None
    raise InputError(f"{run_dir}: neither {SUMMARY_NAME} nor options in {H5_NAME}")


def option_value(options, name, default):
    words = shlex.split(options)
    for k, w in enumerate(words[:-1]):
        if w == name:
            try:
                return float(words[k + 1])
            except ValueError:
                raise InputError(f"option {name} {words[k + 1]}: not a number") from None
    return default


# ------------------------------------------------------------------------------------------ curves
def with_origin(curve):
    """The curve with the undeformed state prepended (t = 0: lambda = 0, so depth and load are 0)."""
    if curve["t"][0] <= 0:
        return dict(curve)
    return {c: np.r_[0.0, v] for c, v in curve.items()}


def segment_indices(curve, hold):
    """NIGET's four row indices: the contact point (last row without load before the load rises),
    the end of loading (t = 1), the end of the hold (t = 1 + hold) and the last row. A run stopped
    early has its missing segments empty (the indices equal)."""
    t, p = curve["t"], curve["load_uN"]
    last = len(t) - 1
    loaded = np.flatnonzero(p > 0)
    contact = max(int(loaded[0]) - 1, 0) if len(loaded) else 0
    load_end = int(np.flatnonzero(t <= 1 + T_TOL)[-1])
    hold_end = int(np.flatnonzero(t <= 1 + hold + T_TOL)[-1])
    return contact, max(load_end, contact), max(hold_end, contact), last


def write_niget(path, curve, idx):
    with open(path, "w", newline="\n") as f:
        f.write("#NIGET %d %d %d %d\n" % idx)
        for h, p in zip(curve["depth_nm"], curve["load_uN"]):
            f.write(f"{h:.12g}\t{p / 1000.0:.12g}\n")  # force in mN
    print(f"wrote {path}")


def write_hysitron(path, curve, seconds_per_t, start_time):
    """TriboScan's text export as micromechanics (Indentation.loadHysitron) and NIGET read it: line 1
    a date, line 2 empty, line 3 'Number of Points = N', line 4 the column names; latin-1, as the
    instrument writes the micro sign."""
    when = datetime.datetime.now(datetime.timezone.utc)
    if start_time:
        try:
            when = datetime.datetime.strptime(start_time, "%Y-%m-%dT%H:%M:%SZ")
        except ValueError:
            pass
    n = len(curve["t"])
    with open(path, "w", encoding="latin-1", newline="\n") as f:
        f.write(when.strftime("%a %b %d %H:%M:%S %Y") + "\n\n")
        f.write(f"Number of Points = {n}\n")
        f.write("Depth (nm)\tLoad (\u00b5N)\tTime (s)\n")
        for h, p, t in zip(curve["depth_nm"], curve["load_uN"], curve["t"]):
            f.write(f"{h:.12g}\t{p:.12g}\t{t * seconds_per_t:.12g}\n")
    print(f"wrote {path}")


# ----------------------------------------------------------------------------------------- imprint
def write_xyz(path, xy, height):
    order = np.lexsort((xy[:, 1], xy[:, 0]))
    np.savetxt(path, np.column_stack([xy[order], height[order]]), fmt="%.10g", delimiter=" ")
    print(f"wrote {path}")


def node_range(lo, hi, first, step, count):
    """First and last grid node in [lo, hi] (with round-off slack, so that a node on an edge is found)."""
    return max(int(np.ceil((lo - first) / step - 1e-9)), 0), min(int(np.floor((hi - first) / step + 1e-9)), count - 1)


def interpolate(xy, height, tris, gx, gy):
    """Linear interpolation of the triangulated surface at the grid nodes (gx[j], gy[i]); NaN where
    no triangle covers a node."""
    grid = np.full((len(gy), len(gx)), np.nan)
    dx, dy = gx[1] - gx[0], gy[1] - gy[0]
    for a, b, c in tris:  # one small bounding box per triangle, not every node per triangle
        pa, pb, pc = xy[a], xy[b], xy[c]
        lo, hi = np.minimum(np.minimum(pa, pb), pc), np.maximum(np.maximum(pa, pb), pc)
        j0, j1 = node_range(lo[0], hi[0], gx[0], dx, len(gx))
        i0, i1 = node_range(lo[1], hi[1], gy[0], dy, len(gy))
        if j0 > j1 or i0 > i1:
            continue
        X, Y = np.meshgrid(gx[j0:j1 + 1], gy[i0:i1 + 1])
        det = (pb[1] - pc[1]) * (pa[0] - pc[0]) + (pc[0] - pb[0]) * (pa[1] - pc[1])
        if det == 0:
            continue
        la = ((pb[1] - pc[1]) * (X - pc[0]) + (pc[0] - pb[0]) * (Y - pc[1])) / det
        lb = ((pc[1] - pa[1]) * (X - pc[0]) + (pa[0] - pc[0]) * (Y - pc[1])) / det
        lc = 1 - la - lb
        inside = (la >= -1e-9) & (lb >= -1e-9) & (lc >= -1e-9)
        block = grid[i0:i1 + 1, j0:j1 + 1]
        block[inside] = (la * height[a] + lb * height[b] + lc * height[c])[inside]
    return grid


# -------------------------------------------------------------------------------------------- main
def imprint_grid(args, curve, h5, h5_path):
    """The top surface at the last step (xy, height: the mirrored vertices, or a section's pixels), its grid for
    imprint.gsf and the grid's half-width."""
    profile = top_profile(h5, h5_path)
    if profile is None:
        xy, height, tris, axes, tol = top_surface(h5, h5_path)
        xy, tris, source, _ = mirror(xy, tris, axes, tol)
        height = height[source]
        reach = float(min(np.abs(xy[:, 0]).max(), np.abs(xy[:, 1]).max()))
    else:
        reach = float(profile[0].max())
    if args.gsf_half_width is not None:
        half = args.gsf_half_width
    else:
        # Three radii of the largest contact (area times the symmetry factor) hold the imprint and
        # its pile-up; without an area, three depths.
        a_max = float(curve["contact_area_nm2"].max()) if "contact_area_nm2" in curve else 0.0
        radius = float(np.sqrt(a_max / np.pi)) if a_max > 0 else float(curve["depth_nm"].max())
        half = min(3.0 * radius, 0.99 * reach)
    gx = grid_axis(half, args.gsf_pixels)
    if profile is None:
        grid = interpolate(xy, height, tris, gx, gx)
    else:
        # the section revolved: the profile at each pixel's distance from the axis
        X, Y = np.meshgrid(gx, gx)
        grid = np.interp(np.hypot(X, Y), *profile, right=np.nan)
        xy, height = np.column_stack([X.ravel(), Y.ravel()]), grid.ravel()
    if np.isnan(grid).any():
        raise InputError(f"imprint.gsf: {int(np.isnan(grid).sum())} grid nodes lie outside the top surface "
                         f"(half-width {half:.6g} nm): give a smaller --gsf-half-width")
    return xy, height, grid, half


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir", help="output directory of an indent run with an indenter")
    ap.add_argument("--out", help="directory for the files (default RUN_DIR)")
    ap.add_argument("--segment-seconds", type=float, default=10.0,
                    help="seconds per unit of the pseudo-time t (the loading segment), default 10")
    ap.add_argument("--gsf-pixels", type=int, default=257,
                    help="pixels per side of imprint.gsf, default 257 (odd: a pixel centre on the indenter axis)")
    ap.add_argument("--gsf-half-width", type=float,
                    help="half-width of imprint.gsf in nm (default: 3 contact radii at the largest load)")
    args = ap.parse_args(argv)
    try:
        bad_width = args.gsf_half_width is not None and args.gsf_half_width <= 0
        if args.segment_seconds <= 0 or args.gsf_pixels < 2 or bad_width:
            raise InputError("--segment-seconds and --gsf-half-width must be > 0 and --gsf-pixels >= 2")
        if not os.path.isdir(args.run_dir):
            raise InputError(f"{args.run_dir}: no such run directory")
        curve = read_curve(os.path.join(args.run_dir, CSV_NAME), ("t", "depth_nm", "load_uN"))
        if os.path.exists(os.path.join(args.run_dir, H5_NAME)):
            h5, h5_path = open_fields(args.run_dir, H5_NAME, "the imprint needs -output_fields 1")
            with h5:
                options, start_time = run_options(args.run_dir, h5)
                surface = imprint_grid(args, curve, h5, h5_path)
        else:  # a run without fields (-output_fields 0): its curves only
            options, start_time = run_options(args.run_dir, None)
            surface = None
        hold = option_value(options, "-load_hold", 0.0)
    except InputError as e:
        print(f"export-curves: error: {e}", file=sys.stderr)
        return 2
    out = args.out or args.run_dir
    os.makedirs(out, exist_ok=True)
    full = with_origin(curve)
    write_niget(os.path.join(out, "curve.niget"), full, segment_indices(full, hold))
    write_hysitron(os.path.join(out, "curve_hysitron.txt"), full, args.segment_seconds, start_time)
    if surface is None:
        print(f"no imprint.xyz or imprint.gsf: {os.path.join(args.run_dir, H5_NAME)} is absent (the run wrote no "
              "fields: -output_fields 0)")
        return 0
    xy, height, grid, half = surface
    write_xyz(os.path.join(out, "imprint.xyz"), xy, height)
    write_gsf(os.path.join(out, "imprint.gsf"), grid, half, "residual imprint height")
    return 0


if __name__ == "__main__":
    sys.exit(main())
