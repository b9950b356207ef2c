#!/usr/bin/env python3
"""Pictures of an indentation run: the load-displacement curve, the residual imprint (table and
contour map) and a vertical slice through the indenter axis with the von Mises stress at the largest
load and the plastic strain at the last step (after unloading, for a complete run).

  /usr/bin/python3 scripts/plot-indent.py RUN_DIR [--out DIR]

Reads RUN_DIR/load_displacement.csv and RUN_DIR/indent.h5 and writes into DIR (default RUN_DIR):
load_displacement.png, imprint.csv, imprint.png, stress_slice.png, and with RUN_DIR/csm.csv (-csm_every)
csm.png: H and E_r against depth (against h/t with --film-thickness t), with the reduced moduli of the
film and the substrate drawn when the run's summary.json names them; with RUN_DIR/scratch.csv (a
scratch test) scratch.png: the normal and lateral forces against the sliding distance and the apparent
friction coefficient lateral / normal while sliding, with the Coulomb coefficient of the run's
summary.json. Half (y >= 0) and quarter (x, y >= 0) models are mirrored for the pictures. An axisymmetric
section (a 2D mesh, doc/axisymmetric.md) gives its imprint as a profile (imprint.csv with y = 0, imprint.png
the height against r) and its slice is the section itself, mirrored about the axis. A run without fields
(-output_fields 0: no indent.h5) gets its curve (and csm.png, scratch.png) and a line saying what it lacks.
Exit status 2 on bad input.
"""
import argparse
import json
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")  # files only, never a window: the script also runs on machines without a display
import matplotlib.pyplot as plt  # noqa: E402  (must come after the backend is chosen)
from matplotlib import colors, ticker, tri as mtri  # noqa: E402

from runfiles import (InputError, curve_rows, field_steps, is_section, mirror, plane_faces,  # noqa: E402
                      read_curve, read_scratch)  # (this script's folder)

CSV_NAME = "load_displacement.csv"
H5_NAME = "indent.h5"
SCRATCH_NAME = "scratch.csv"
SCRATCH_COLUMNS = ("distance_nm", "normal_uN", "lateral_uN", "side_uN", "friction")
# Coordinates on a plane of the mesh (top surface, symmetry plane) are exact up to round-off, so a
# tolerance relative to the mesh size separates them safely from the next layer of vertices.
REL_TOL = 1e-9


# ----------------------------------------------------------------------------------------- input
class Run:
    """The mesh of indent.h5, with its fields read one step at a time (a step of ~100k cells is
    a few MB, the whole history can be GBs)."""

    def __init__(self, path):
        if not os.path.isfile(path):
            raise InputError(f"{path}: no such file")
        try:
            self.h5 = h5py.File(path, "r")
        except OSError as e:
            raise InputError(f"{path}: cannot open as HDF5 ({e})") from None
        self.path = path
        self.x = self.dataset("geometry/vertices")[:]
        self.cells = self.dataset("topology/cells")[:].astype(np.int64)
        if self.x.ndim != 2 or self.x.shape[1] != 3 or self.cells.ndim != 2 or self.cells.shape[1] not in (3, 4, 8):
            raise InputError(f"{path}: expected vertices (N, 3) and cells (C, 3, 4 or 8), got {self.x.shape} and "
                             f"{self.cells.shape}")
        lo, hi = self.x.min(axis=0), self.x.max(axis=0)
        self.tol = REL_TOL * float(np.max(hi - lo))
        self.section = is_section(self.x, self.cells, self.tol)  # axisymmetric: x = r, z the axis
        if self.cells.shape[1] == 3 and not self.section:
            raise InputError(f"{path}: triangles outside the plane y = 0: not a mesh indent writes")
        self.lo, self.hi = lo, hi
        self.z_top = hi[2]
        self.nsteps = self.dataset("fields/displacement").shape[0]
        self.steps = field_steps(self.h5, path)  # the accepted step of each written one
        self.rows = None  # the curve's row of each written step, set by load_inputs
        # A symmetry plane x = 0 or y = 0 is a boundary of the model with the body on its positive side.
        self.mirror_axes = [a for a in (0, 1) if abs(lo[a]) <= self.tol and hi[a] > self.tol]

    def dataset(self, name):
        if name not in self.h5:
            raise InputError(f"{self.path}: dataset /{name} missing")
        return self.h5[name]

    def field(self, name, step):
        """One step of a field, flattened to (N,) when it has a single component."""
        data = self.dataset(f"fields/{name}")[step]
        return data[:, 0] if data.shape[1] == 1 else data

    def optional_field(self, name, step):
        """A field that older files lack (contact_status, contact_pressure): None when absent."""
        return self.field(name, step) if f"fields/{name}" in self.h5 else None


# -------------------------------------------------------------------------------------- geometry
def triangle_area(p, tris):
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    return 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


# ------------------------------------------------------------------------------------------ curve
def branches(depth):
    """Index ranges of loading, hold and unloading: up to the first maximum depth, at it, after it."""
    top = np.flatnonzero(depth >= depth.max())
    return slice(0, top[0] + 1), slice(top[0], top[-1] + 1), slice(top[-1], len(depth))


def plot_load_displacement(curve, path):
    h, p = curve["depth_nm"], curve["load_uN"]
    load, hold, unload = branches(h)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    # The curve starts at the origin, which is not a step of the CSV.
    ax.plot(np.r_[0, h[load]], np.r_[0, p[load]], "o-", color="tab:blue", ms=4, label="loading")
    if hold.stop - hold.start > 1:
        ax.plot(h[hold], p[hold], "s-", color="tab:green", ms=4, label="hold")
    if unload.stop - unload.start > 1:
        ax.plot(h[unload], p[unload], "v-", color="tab:red", ms=4, label="unloading")
    ax.set_xlabel("depth h (nm)")
    ax.set_ylabel("load P (uN)")
    ax.set_title(f"P_max = {p.max():.4g} uN, h_max = {h.max():.4g} nm")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()
    save(fig, path)


def option_value(options, name):
    """The value of -name in the options string of summary.json, or None."""
    words = options.split()
    return words[words.index(name) + 1] if name in words[:-1] else None


def summary_options(run_dir):
    """The options string of the run's summary.json; empty for a run without one (stopped early)."""
    summary = os.path.join(run_dir, "summary.json")
    return json.load(open(summary)).get("options", "") if os.path.exists(summary) else ""


def plot_csm(run_dir, thickness, path):
    """H and E_r against depth from the unloading stiffness (csm.csv), with E* of film and substrate."""
    c = np.atleast_1d(np.genfromtxt(os.path.join(run_dir, "csm.csv"), delimiter=",", names=True))
    x = c["depth_nm"] / thickness if thickness else c["depth_nm"]
    fig, (ax_h, ax_e) = plt.subplots(1, 2, figsize=(10, 4.2))
    ax_h.plot(x, c["H_GPa"], "o-", color="tab:blue", ms=4)
    ax_e.plot(x, c["E_r_GPa"], "o-", color="tab:red", ms=4, label="E_r from S")
    options = summary_options(run_dir)
    for region, style in (("film", "--"), ("substrate", ":")):
        young, nu = option_value(options, f"-{region}_young"), option_value(options, f"-{region}_poisson")
        if young and nu:
            estar = float(young) / (1 - float(nu) ** 2)
            ax_e.axhline(estar, ls=style, color="0.4", label=f"{region}: E/(1-nu^2) = {estar:.4g} GPa")
    xlabel = "h / t" if thickness else "depth h (nm)"
    for ax, label in ((ax_h, "hardness H (GPa)"), (ax_e, "reduced modulus E_r (GPa)")):
        ax.set_xlabel(xlabel)
        ax.set_ylabel(label)
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
    ax_e.legend(fontsize=8)
    fig.suptitle("from the unloading stiffness at each depth (-csm_every)")
    save(fig, path)


def plot_scratch(scratch, mu, path):
    """The forces against the sliding distance, every row: the loading stands at distance 0 and the
    unloading at the end. lateral / normal only while sliding (the distance grows): under the loading
    and the unloading it is no friction coefficient, and it diverges as the normal load goes to 0."""
    d = scratch["distance_nm"]
    sliding = (d > 0) & (d > np.r_[-np.inf, d[:-1]])
    fig, (ax_f, ax_m) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    ax_f.plot(d, scratch["normal_uN"], "o-", color="tab:blue", ms=3, label="normal P")
    ax_f.plot(d, scratch["lateral_uN"], "s-", color="tab:red", ms=3, label="lateral (along the scratch)")
    if np.any(scratch["side_uN"] != 0):
        ax_f.plot(d, scratch["side_uN"], "^-", color="tab:green", ms=3, label="side (across it)")
    ax_f.set_ylabel("force (uN)")
    ax_f.set_title(f"largest normal load {scratch['normal_uN'].max():.4g} uN, "
                   f"largest lateral force {np.abs(scratch['lateral_uN']).max():.4g} uN")
    ax_f.legend(fontsize=8)
    ratio = scratch["friction"][sliding]
    ax_m.plot(d[sliding], ratio, "o-", color="tab:purple", ms=3, label="lateral / normal")
    if mu is not None:
        ax_m.axhline(mu, ls="--", color="0.4", label=f"Coulomb friction of the contact: {mu:.4g}")
    if len(ratio):
        ax_m.set_title(f"apparent friction coefficient while sliding: {ratio.min():.4g} to {ratio.max():.4g}, "
                       f"last {ratio[-1]:.4g}", fontsize=10)
    ax_m.set_xlabel("sliding distance (nm)")
    ax_m.set_ylabel("lateral / normal")
    ax_m.legend(fontsize=8)
    for ax in (ax_f, ax_m):
        ax.grid(alpha=0.3)
    save(fig, path)


# ---------------------------------------------------------------------------------------- imprint
def top_surface(run):
    """Top-surface vertex numbers (sorted by x then y) and its triangles in those local numbers."""
    on_top = np.abs(run.x[:, 2] - run.z_top) <= run.tol
    tris, _ = plane_faces(run.cells, on_top)
    verts = np.flatnonzero(on_top)
    verts = verts[np.lexsort((run.x[verts, 1], run.x[verts, 0]))]
    local = np.full(len(run.x), -1)
    local[verts] = np.arange(len(verts))
    return verts, local[tris]


def write_imprint(path, xy, height):
    table = np.column_stack([xy, height])
    np.savetxt(path, table, fmt="%.10g", delimiter=",", header="x_nm,y_nm,height_nm", comments="")
    print(f"wrote {path}")


def plot_profile(r, height, contact, what, path):
    """The imprint of an axisymmetric section: the top surface's height against the radius, mirrored
    about the axis; contact (vertex status at P_max, or None) marks the contact's edge."""
    fig, ax = plt.subplots(figsize=(6.5, 4))
    hmin = height.min()
    reach = 3 * r[height < 0.05 * hmin].max() if hmin < 0 and (height < 0.05 * hmin).any() else r.max()
    ax.plot(np.r_[-r[::-1], r], np.r_[height[::-1], height], "-", color="tab:blue")
    ax.axhline(0, color="k", lw=0.6)
    if contact is not None and (contact > 0).any():
        edge = r[contact > 0].max()
        for s in (-1, 1):
            ax.axvline(s * edge, color="tab:green", ls="--", lw=1)
        ax.plot([], [], "--", color="tab:green", label="contact edge at P_max")
        ax.legend(loc="lower right", fontsize=8)
    ax.set_xlim(-reach, reach)
    ax.set_xlabel("r (nm)")
    ax.set_ylabel("height (nm)")
    pileup = max(height.max(), 0)
    ax.set_title(f"{what}: min {hmin:.3g} nm, pile-up {pileup:.3g} nm\n(black line: original surface level)",
                 fontsize=10)
    save(fig, path)


def imprint(run, curve, out):
    """imprint.csv and imprint.png: the top surface at the last step, relative to its original level."""
    load = curve["load_uN"]
    what = "residual imprint" if load[-1] <= 1e-9 * load.max() else f"surface under P = {load[-1]:.4g} uN"
    contact = run.optional_field("contact_status", peak_step(run, curve))
    if run.section:
        verts = np.flatnonzero(np.abs(run.x[:, 2] - run.z_top) <= run.tol)
        verts = verts[np.argsort(run.x[verts, 0])]
        u = run.field("displacement", run.nsteps - 1)[verts]
        r, height = run.x[verts, 0] + u[:, 0], run.x[verts, 2] + u[:, 2] - run.z_top
        write_imprint(os.path.join(out, "imprint.csv"), np.column_stack([r, np.zeros_like(r)]), height)
        plot_profile(r, height, None if contact is None else contact[verts], what, os.path.join(out, "imprint.png"))
        return
    verts, tris = top_surface(run)
    xy = run.x[verts, :2]
    height = run.x[verts, 2] + run.field("displacement", run.nsteps - 1)[verts, 2] - run.z_top
    write_imprint(os.path.join(out, "imprint.csv"), xy, height)
    # Only a run unloaded until the indenter left shows a residual imprint (what); otherwise the picture
    # is the surface under the last load, and the title must not claim otherwise.
    plot_imprint(run, xy, tris, height, None if contact is None else contact[verts], what, os.path.join(out, "imprint.png"))


def zoom_square(points, inside, bounds):
    """Square of side 3x the extent of the points flagged inside, centred on them and clipped to
    bounds ((xmin, xmax), (ymin, ymax)); the whole bounds when nothing is flagged."""
    if not inside.any():
        return bounds
    lo, hi = points[inside].min(axis=0), points[inside].max(axis=0)
    centre, half = 0.5 * (lo + hi), 1.5 * float(np.max(hi - lo))
    return tuple((max(centre[a] - half, bounds[a][0]), min(centre[a] + half, bounds[a][1])) for a in (0, 1))


def height_levels(vmin, vmax):
    """Contour levels and a norm centred on 0: the pile-up is typically ten times shallower than
    the print, so each side gets its own scale, otherwise it would be a single pale band."""
    vmin = min(vmin, -1e-9)
    vmax = max(vmax, 0.01 * abs(vmin))  # no pile-up at all: still a valid two-sided scale
    levels = np.r_[np.linspace(vmin, 0, 11), np.linspace(0, vmax, 9)[1:]]
    return levels, colors.TwoSlopeNorm(vcenter=0, vmin=vmin, vmax=vmax)


def plot_imprint(run, xy, tris, height, contact, what, path):
    """Filled contours of the top-surface height; contact (vertex status at P_max, or None) adds
    the edge of the contact zone, to compare the imprint with the area that carried the load."""
    pts, tr, psrc, _ = mirror(xy, tris, run.mirror_axes, run.tol)
    val = height[psrc]
    bounds = tuple((pts[:, a].min(), pts[:, a].max()) for a in (0, 1))
    hmin = val.min()
    # The print is where the surface is down by 5% of the deepest point; 1% would reach far out
    # under load, where the elastic sink-in decays only as 1/r.
    (x0, x1), (y0, y1) = zoom_square(pts, val < 0.05 * hmin if hmin < 0 else np.zeros(len(val), bool), bounds)
    window = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    pileup = max(val[window].max(), 0.0)
    levels, norm = height_levels(hmin, pileup)
    triang = mtri.Triangulation(pts[:, 0], pts[:, 1], tr)
    fig, ax = plt.subplots(figsize=(6.5, 5.5))
    cs = ax.tricontourf(triang, val, levels=levels, norm=norm, cmap="RdBu_r", extend="both")
    if val.min() < 0 < val.max():
        ax.tricontour(triang, val, levels=[0], colors="k", linewidths=0.6)
    if contact is not None and (contact > 0).any() and not (contact > 0).all():
        ax.tricontour(triang, (contact[psrc] > 0).astype(float), levels=[0.5], colors="tab:green", linestyles="--", linewidths=1)
        ax.plot([], [], "--", color="tab:green", label="contact edge at P_max")
        ax.legend(loc="upper right", fontsize=8)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_xlabel("x (nm)")
    ax.set_ylabel("y (nm)")
    ax.set_title(f"{what}: min {hmin:.3g} nm, pile-up {pileup:.3g} nm\n(black line: original surface level)",
                 fontsize=10)
    fig.colorbar(cs, ax=ax, label="height (nm)", ticks=levels[::2])
    save(fig, path)


# ----------------------------------------------------------------------------------- stress slice
def contact_radius(curve, step):
    """Radius of the disc with the projected contact area of the CSV (already times the symmetry
    factor): the same measure whether or not the file has contact fields, and for a Berkovich print
    between the in- and circumradius of the triangle."""
    area = curve["contact_area_nm2"][step] if "contact_area_nm2" in curve else 0.0
    return float(np.sqrt(area / np.pi)) if area > 0 else 3.0 * float(curve["depth_nm"].max())


def section_y0(run):
    """The plane y = 0 as (points (x, z), triangles, cell of each triangle or point). Cell faces
    lying on the plane when they cover it (half model, or a full mesh with an internal surface
    there); otherwise the centroids of the cells cut by the plane, with triangles None."""
    on_plane = np.abs(run.x[:, 1]) <= run.tol
    if run.section:  # the section is the slice, mirrored about its axis
        tris, owners = plane_faces(run.cells, on_plane, section=True)
        xz, tris, _, tsrc = mirror(run.x[:, [0, 2]], tris, [0], run.tol)
        return xz, tris, owners[tsrc]
    if on_plane.any():
        tris, owners = plane_faces(run.cells, on_plane)
        xz = run.x[:, [0, 2]]
        section = (run.hi[0] - run.lo[0]) * (run.hi[2] - run.lo[2])
        # A few stray faces on the plane (along box edges of a full mesh) are not a slice.
        if len(tris) and triangle_area(xz, tris).sum() >= 0.5 * section:
            if 0 in run.mirror_axes:  # a quarter model is also cut by x = 0
                xz, tris, _, tsrc = mirror(xz, tris, [0], run.tol)
                owners = owners[tsrc]
            return xz, tris, owners
    y = run.x[run.cells, 1]
    cut = np.flatnonzero((y.min(axis=1) <= 0) & (y.max(axis=1) >= 0))
    return run.x[run.cells[cut]].mean(axis=1)[:, [0, 2]], None, cut


def draw_slice(ax, fig, section, window, values, label, unit, title):
    """One panel: cell values on the section, coloured up to the 99th percentile of what the window
    shows, because the cells at a sharp tip reach values far above the rest of the plastic zone."""
    (x0, x1), (z0, z1) = window
    pts, tris, owners = section
    val = values[owners]
    where = pts[tris].mean(axis=1) if tris is not None else pts
    shown = val[(where[:, 0] >= x0) & (where[:, 0] <= x1) & (where[:, 1] >= z0)]
    vmax = max(float(np.percentile(shown, 99)) if len(shown) else val.max(), 1e-12)
    if tris is not None:
        im = ax.tripcolor(mtri.Triangulation(pts[:, 0], pts[:, 1], tris), facecolors=val, cmap="viridis",
                          vmin=0, vmax=vmax)  # default: no edges, no antialiasing seams
    else:
        levels = ticker.MaxNLocator(14).tick_values(0, vmax)
        im = ax.tricontourf(mtri.Triangulation(pts[:, 0], pts[:, 1]), val, levels=levels, cmap="viridis", extend="max")
    ax.set_xlim(x0, x1)
    ax.set_ylim(z0, z1)
    ax.set_aspect("equal")
    ax.set_xlabel("x (nm)")
    ax.set_ylabel("z (nm)")
    peak = shown.max() if len(shown) else val.max()
    ax.set_title(f"{title}\nlargest in view {peak:.3g} {unit}".rstrip())
    fig.colorbar(im, ax=ax, label=f"{label} ({unit or '-'})", shrink=0.9, extend="max")


def peak_step(run, curve):
    """The written step with the largest load (the end of loading, which is always written, in depth control)."""
    return int(np.argmax(curve["load_uN"][run.rows]))


def slice_reach(run, curve):
    """Half-width of the stress slice: 3 contact radii at the written step of P_max cover the plastic zone
    and the stress bulb under it; the film of the paper (300 nm under a 60 nm indent with a ~170 nm contact
    radius) fits with some substrate."""
    return 3.0 * contact_radius(curve, int(run.rows[peak_step(run, curve)]))  # that step's row of the curve


def plot_stress_slice(run, curve, path):
    # the fields' steps, with the depth and load of their own rows of the curve
    depth, load = curve["depth_nm"][run.rows], curve["load_uN"][run.rows]
    peak, last = peak_step(run, curve), run.nsteps - 1
    reach = slice_reach(run, curve)
    xmin = -run.hi[0] if 0 in run.mirror_axes else run.lo[0]
    window = ((max(-reach, xmin), min(reach, run.hi[0])), (max(run.z_top - reach, run.lo[2]), run.z_top))
    section = section_y0(run)
    compaction = run.optional_field("compaction", last)  # a densifying material's (a glass)
    fig, axes = plt.subplots(2 if compaction is None else 3, 1, figsize=(7.5, 8 if compaction is None else 12))
    draw_slice(axes[0], fig, section, window, run.field("von_mises", peak), "von Mises stress", "GPa",
               f"von Mises stress at P_max = {load[peak]:.4g} uN (h = {depth[peak]:.4g} nm)")
    draw_slice(axes[1], fig, section, window, run.field("plastic_strain", last), "equivalent plastic strain", "",
               f"equivalent plastic strain at the last step (h = {depth[last]:.4g} nm)")
    if compaction is not None:
        draw_slice(axes[2], fig, section, window, compaction, "plastic compaction -tr(eps_p)", "",
                   f"plastic compaction (densification) at the last step (h = {depth[last]:.4g} nm)")
    save(fig, path)


# ------------------------------------------------------------------------------------------- main
def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    print(f"wrote {path}")


def load_inputs(run_dir):
    """The curve, the HDF5 file and the scratch table (None without one) of a run, checked to agree,
    so that bad input fails before any output is written."""
    if not os.path.isdir(run_dir):
        raise InputError(f"{run_dir}: no such run directory")
    curve = read_curve(os.path.join(run_dir, CSV_NAME))
    path = os.path.join(run_dir, SCRATCH_NAME)
    scratch = read_scratch(path, SCRATCH_COLUMNS) if os.path.exists(path) else None
    if not os.path.exists(os.path.join(run_dir, H5_NAME)):
        return curve, None, scratch  # a run without fields: its curves only
    run = Run(os.path.join(run_dir, H5_NAME))
    run.rows = curve_rows(curve, run.steps, run.path)
    if run.rows[-1] != len(curve["depth_nm"]) - 1:
        raise InputError(f"{run.path}: its last fields are of step {run.steps[-1]}, the curve goes on to row "
                         f"{len(curve['depth_nm'])} (a run still being written?)")
    for name in ("von_mises", "plastic_strain"):
        if run.dataset(f"fields/{name}").shape[0] != run.nsteps:
            raise InputError(f"{run.path}: /fields/{name} and /fields/displacement have different step counts")
    return curve, run, scratch


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir", help="output directory of an indent run")
    ap.add_argument("--out", help="directory for the pictures and imprint.csv (default RUN_DIR)")
    ap.add_argument("--film-thickness", type=float, help="film thickness t (nm): csm.png against h / t")
    args = ap.parse_args(argv)
    try:
        curve, run, scratch = load_inputs(args.run_dir)
    except InputError as e:
        print(f"plot-indent: error: {e}", file=sys.stderr)
        return 2
    out = args.out or args.run_dir
    os.makedirs(out, exist_ok=True)
    plot_load_displacement(curve, os.path.join(out, "load_displacement.png"))
    if run is None:
        print(f"no imprint.csv, imprint.png or stress_slice.png: {os.path.join(args.run_dir, H5_NAME)} is absent "
              "(the run wrote no fields: -output_fields 0)")
    else:
        with run.h5:
            imprint(run, curve, out)
            plot_stress_slice(run, curve, os.path.join(out, "stress_slice.png"))
    if os.path.exists(os.path.join(args.run_dir, "csm.csv")):
        plot_csm(args.run_dir, args.film_thickness, os.path.join(out, "csm.png"))
    if scratch is not None and len(scratch["distance_nm"]):
        mu = option_value(summary_options(args.run_dir), "-contact_friction")
        plot_scratch(scratch, None if mu is None else float(mu), os.path.join(out, "scratch.png"))
    elif scratch is not None:
        print(f"no scratch.png: {SCRATCH_NAME} has no rows yet")
    return 0


if __name__ == "__main__":
    sys.exit(main())
