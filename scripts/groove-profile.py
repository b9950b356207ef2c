#!/usr/bin/env python3
"""The groove a scratch test leaves: the height of the top surface along the track and across it.

  /usr/bin/python3 scripts/groove-profile.py RUN_DIR [--at X] [--out DIR]

Reads the last step of RUN_DIR/indent.h5 (after the unloading: the residual groove) and, when there is
one, RUN_DIR/scratch.csv (where the indenter slid), and writes into DIR (default RUN_DIR):

  groove_along.csv    x_nm,height_nm: the section of the top surface by the line y = the indenter axis'
                      y, over the whole modelled length in x
  groove_across.csv   y_nm,height_nm: the section by the line x = X (--at X; default the middle of the
                      scratch, the mean of the first and last x_nm of scratch.csv's rows with
                      distance_nm > 0, or 0 without scratch.csv)
  groove.png          both profiles

and prints one line: the groove depth (the lowest height along the track between its start and its
end), the largest pile-up beside the track (the highest point of the surface with x between the start
and the end, or on the section across) and where they are. The height is z + u_z minus the undeformed
top at the deformed position (x + u_x, y + u_y), linear on the triangles of the top faces; half and
quarter models are mirrored to the full plane. A section holds every vertex on its line and every
crossing of a triangle edge, so with straight lines between its points it is the surface's exact
profile. Without scratch.csv (an indentation) the track is the point x = y = 0. Exit status 2 on bad
input.
"""
import argparse
import csv
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")  # files only, never a window: the script also runs on machines without a display
import matplotlib.pyplot as plt  # noqa: E402  (must come after the backend is chosen)

from runfiles import InputError, mirror, open_fields, read_scratch, top_surface  # noqa: E402  (this script's folder)

H5_NAME, SCRATCH_NAME, CURVE_NAME = "indent.h5", "scratch.csv", "load_displacement.csv"
PROG = "groove-profile.py"


# ------------------------------------------------------------------------------------------ inputs
class Track:
    """Where the indenter slid: x from start to end at y, and the default x of the section across."""

    def __init__(self, start=0.0, end=0.0, y=0.0, middle=0.0):
        self.start, self.end, self.y, self.middle = start, end, y, middle
        self.lo, self.hi = min(start, end), max(start, end)


def read_track(path, tol):
    if not os.path.exists(path):
        return Track()
    s = read_scratch(path, ("distance_nm", "x_nm", "y_nm"))
    moving = s["distance_nm"] > 0
    if not moving.any():  # stopped before the first scratching step: the track is where it indented
        x, y = (s["x_nm"][-1], s["y_nm"][-1]) if len(moving) else (0.0, 0.0)
        return Track(x, x, y, x)
    x, y, d = s["x_nm"][moving], s["y_nm"][moving], s["distance_nm"][moving]
    # The profiles are along x and y, so a track that leaves its line y = const has no profile here.
    if np.ptp(y) > 1e-6 * d.max() + tol:
        raise InputError(f"{path}: the indenter moved from y = {y.min():.6g} to {y.max():.6g} nm: "
                         f"{PROG} profiles a track along x only")
    # The start is where the distance is 0; one row does not tell the direction, and the indentation
    # that starts a scratch is on the z axis, so the start nearer the origin is the one taken.
    sign = np.sign(x[-1] - x[0]) or (1.0 if abs(x[0] - d[0]) <= abs(x[0] + d[0]) else -1.0)
    start = float(np.median(x - sign * d))
    return Track(start, float(x[-1]), float(y[0]), 0.5 * float(x[0] + x[-1]))


def last_load(run_dir):
    """The load of the last step from the curve, or None without a readable curve: only for the title."""
    try:
        with open(os.path.join(run_dir, CURVE_NAME), newline="") as f:
            loads = [float(r["load_uN"]) for r in csv.DictReader(f)]
        return loads[-1], max(loads)
    except (OSError, KeyError, TypeError, ValueError, IndexError):
        return None


# ---------------------------------------------------------------------------------------- sections
def section(xy, height, tris, axis, at, tol):
    """The surface on the line xy[:, axis] = at, as (coordinate along the line, height), sorted: the
    vertices on the line and the crossings of the triangle edges that straddle it."""
    other = 1 - axis
    d = xy[:, axis] - at
    on = np.abs(d) <= tol
    ts, hs, crossing = [xy[on, other]], [height[on]], [np.zeros(on.sum(), bool)]
    for i, j in ((0, 1), (1, 2), (2, 0)):
        a, b = tris[:, i], tris[:, j]
        cut = ~on[a] & ~on[b] & (np.sign(d[a]) != np.sign(d[b]))
        a, b = a[cut], b[cut]
        w = d[a] / (d[a] - d[b])
        ts.append(xy[a, other] + w * (xy[b, other] - xy[a, other]))
        hs.append(height[a] + w * (height[b] - height[a]))
        crossing.append(np.ones(len(a), bool))
    t, h, crossing = np.concatenate(ts), np.concatenate(hs), np.concatenate(crossing)
    # Shared edges and mirrored vertices give each point more than once; a vertex's own value wins.
    order = np.lexsort((crossing, t))
    t, h = t[order], h[order]
    keep = np.r_[True, np.diff(t) > tol] if len(t) else np.zeros(0, bool)
    return t[keep], h[keep]


def deepest(t, h, lo, hi, tol):
    """The lowest point of a section between lo and hi, the ends interpolated so that a track shorter
    than a cell still has one."""
    inside = (t >= lo - tol) & (t <= hi + tol)
    cand_t = np.r_[t[inside], lo, hi]
    cand_h = np.r_[h[inside], np.interp(lo, t, h), np.interp(hi, t, h)]
    k = int(np.argmin(cand_h))
    return cand_t[k], cand_h[k]


def window(t, h, keep):
    """Plot limits that show where the surface moved (by 5% of the largest height or depth), the
    coordinates in keep (the track, the marked points) and as much again on each side, where a
    pile-up lower than 5% of the groove rises; the whole section when nothing moved."""
    moved = np.abs(h) >= 0.05 * np.abs(h).max() if np.abs(h).max() > 0 else np.zeros(len(h), bool)
    a, b = min(np.r_[t[moved], keep]), max(np.r_[t[moved], keep])
    if b <= a:
        return t.min(), t.max()
    return max(a - (b - a), t.min()), min(b + (b - a), t.max())


# ------------------------------------------------------------------------------------------ output
def coordinate(v, tol):
    """A coordinate for the printed line, without the round-off of a vertex on a symmetry plane."""
    return f"{0.0 if abs(v) <= tol else v:.4g}"


def write_profile(path, name, t, h):
    np.savetxt(path, np.column_stack([t, h]), fmt="%.15g", delimiter=",", header=f"{name},height_nm", comments="")
    print(f"wrote {path}")


def plot(path, along, across, track, at, low, pile, what):
    fig, (ax_a, ax_c) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax_a.plot(*along, "-", color="tab:blue", lw=1.2)
    if track.hi > track.lo:
        ax_a.axvspan(track.lo, track.hi, color="0.85", label="track")
    ax_a.axvline(at, ls=":", color="0.3", label=f"section across (x = {at:.4g} nm)")
    ax_a.plot([low[0]], [low[1]], "v", color="tab:red", label=f"deepest {low[1]:.3g} nm")
    ax_a.set_xlim(*window(*along, [track.lo, track.hi, low[0], at]))
    ax_a.set_xlabel("x (nm)")
    ax_a.set_title(f"along the track (y = {track.y:.4g} nm)")
    ax_c.plot(*across, "-", color="tab:blue", lw=1.2)
    ax_c.axvline(track.y, ls=":", color="0.3", label="track")
    ax_c.set_xlim(*window(*across, [track.y] + ([pile[1]] if pile[3] else [])))
    ax_c.set_xlabel("y (nm)")
    ax_c.set_title(f"across the track (x = {at:.4g} nm)")
    if pile[3]:  # the highest point lies on this section: mark it there
        ax_c.plot([pile[1]], [pile[2]], "^", color="tab:green", label=f"largest pile-up {pile[2]:.3g} nm")
    for ax in (ax_a, ax_c):
        ax.axhline(0, color="k", lw=0.6)
        ax.set_ylabel("height (nm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(what)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    print(f"wrote {path}")


# -------------------------------------------------------------------------------------------- main
def main(argv=None):
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir", help="output directory of an indent run")
    ap.add_argument("--at", type=float, metavar="X",
                    help="x (nm) of the section across the track (default: the middle of the scratch)")
    ap.add_argument("--out", help="directory for the files (default RUN_DIR)")
    args = ap.parse_args(argv)
    try:
        if not os.path.isdir(args.run_dir):
            raise InputError(f"{args.run_dir}: no such run directory")
        h5, h5_path = open_fields(args.run_dir, H5_NAME, "the groove needs the field output")
        with h5:
            xy, height, tris, axes, tol = top_surface(h5, h5_path)
        if len(tris) == 0:
            raise InputError(f"{h5_path}: no top surface (no cell face lies in the mesh's highest plane)")
        track = read_track(os.path.join(args.run_dir, SCRATCH_NAME), tol)
        at = track.middle if args.at is None else args.at
        pts, tr, source, _ = mirror(xy, tris, axes, tol)
        val = height[source]
        along = section(pts, val, tr, 1, track.y, tol)
        across = section(pts, val, tr, 0, at, tol)
        for (t, _), line in ((along, f"y = {track.y:.6g} nm (the track)"), (across, f"x = {at:.6g} nm")):
            if len(t) < 2:
                (x0, y0), (x1, y1) = pts.min(axis=0), pts.max(axis=0)
                raise InputError(f"the line {line} misses the top surface (x from {x0:.6g} to {x1:.6g} nm, "
                                 f"y from {y0:.6g} to {y1:.6g} nm)")
    except InputError as e:
        print(f"{PROG}: error: {e}", file=sys.stderr)
        return 2
    low = deepest(*along, track.lo, track.hi, tol)
    # Beside the track: the surface's vertices alongside it, and the section across for a track of
    # no length (an indentation), where that strip holds hardly a vertex.
    strip = np.flatnonzero((pts[:, 0] >= track.lo - tol) & (pts[:, 0] <= track.hi + tol))
    k = strip[np.argmax(val[strip])] if len(strip) else None
    j = int(np.argmax(across[1]))
    on_across = k is None or across[1][j] >= val[k]
    px, py, ph = (at, across[0][j], across[1][j]) if on_across else (pts[k, 0], pts[k, 1], val[k])
    where_y = f"+/-{coordinate(abs(py), tol)}" if 1 in axes and abs(track.y) <= tol else coordinate(py, tol)
    loads = last_load(args.run_dir)
    # Only a run unloaded until the indenter left shows the residual groove: the title must say which.
    if loads is None:
        what = "top surface at the last step"
    elif loads[0] <= 1e-9 * loads[1]:
        what = "residual groove (last step, unloaded)"
    else:
        what = f"top surface at the last step, under P = {loads[0]:.4g} uN"
    out = args.out or args.run_dir
    os.makedirs(out, exist_ok=True)
    write_profile(os.path.join(out, "groove_along.csv"), "x_nm", *along)
    write_profile(os.path.join(out, "groove_across.csv"), "y_nm", *across)
    plot(os.path.join(out, "groove.png"), along, across, track, at, low, (px, py, ph, on_across), what)
    x0, x1, y = (coordinate(v, tol) for v in (track.start, track.end, track.y))
    print(f"groove depth {-low[1]:.4g} nm at x = {coordinate(low[0], tol)} nm (lowest height on the track from "
          f"x = {x0} to {x1} nm, y = {y} nm); largest pile-up beside it {ph:.4g} nm at x = {coordinate(px, tol)}, "
          f"y = {where_y} nm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
