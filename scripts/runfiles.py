"""Shared by the scripts that read an indent run's files (plot-indent.py, export-curves.py,
groove-profile.py): the cells' faces, the input error they report in one line, the triangulation of a
plane of the mesh with its mirror images (half and quarter models), the deformed top surface of the last
step, the curve's rows of the steps whose fields were written, and the scratch test's table."""
import csv
import os

import numpy as np

# Local faces of the supported cells as cyclic vertex lists (VTK order for the hexahedron), so that
# a quadrilateral splits into the triangles (0, 1, 2) and (0, 2, 3).
CELL_FACES = {
    4: [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)],
    8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}


# Vertices on a plane of the mesh are exact up to round-off: relative to the model size.
REL_TOL = 1e-9


class InputError(Exception):
    """A missing or malformed input file: reported in one line, exit status 2."""


def is_section(x, cells, tol):
    """An axisymmetric section (a 2D mesh, which indent writes in the plane y = 0 with x the radius and z
    the axis): triangles, or quadrilaterals whose vertices all lie on y = 0 (a tetrahedron's four cannot)."""
    return cells.ndim == 2 and cells.shape[1] in (3, 4) and bool(np.all(np.abs(x[:, 1]) <= tol))


def plane_faces(cells, on_plane, section=False):
    """Triangles of the cell faces whose vertices all lie on a plane (on_plane: vertex mask), with
    the cell owning each triangle; on a section (is_section) the faces are the cells themselves."""
    flags = on_plane[cells]
    tris, owners = [], []
    faces = [tuple(range(cells.shape[1]))] if section else CELL_FACES[cells.shape[1]]
    for face in faces:  # a loop over the 4 or 6 local faces, not over cells
        owner = np.flatnonzero(flags[:, face].all(axis=1))
        v = cells[owner][:, face]
        for k in range(1, len(face) - 1):  # fan of the face: 1 triangle, or 2 for a quadrilateral
            tris.append(v[:, [0, k, k + 1]])
            owners.append(owner)
    return np.concatenate(tris), np.concatenate(owners)


def mirror(points, tris, axes, tol):
    """Reflects a 2D triangulation across the lines points[:, a] = 0 for a in axes. Returns the new
    points and triangles, and for each new point / triangle the index of its original, so values
    come along by indexing. Points on a mirror line are shared, so the picture has no seam."""
    pts, tr = points, tris
    psrc, tsrc = np.arange(len(points)), np.arange(len(tris))
    for a in axes:
        on_line = np.abs(pts[:, a]) <= tol
        image = np.where(on_line, np.arange(len(pts)), len(pts) + np.cumsum(~on_line) - 1)
        flipped = pts[~on_line].copy()
        flipped[:, a] *= -1
        pts = np.vstack([pts, flipped])
        tr = np.vstack([tr, image[tr][:, ::-1]])  # reversed to keep the orientation
        psrc = np.concatenate([psrc, psrc[~on_line]])
        tsrc = np.concatenate([tsrc, tsrc])
    return pts, tr, psrc, tsrc


def dataset(h5, name, path):
    if name not in h5:
        raise InputError(f"{path}: dataset /{name} missing")
    return h5[name]


def _last_top(h5, path):
    """Vertices, cells, the last step's displacement, the top plane's level and the tolerance of a plane."""
    x = dataset(h5, "geometry/vertices", path)[:]
    cells = dataset(h5, "topology/cells", path)[:].astype(np.int64)
    disp = dataset(h5, "fields/displacement", path)
    if x.ndim != 2 or x.shape[1] != 3 or cells.ndim != 2 or cells.shape[1] not in (3, 4, 8) or disp.shape[0] == 0:
        raise InputError(f"{path}: expected vertices (N, 3), cells (C, 3, 4 or 8) and a displacement step")
    u = disp[disp.shape[0] - 1]
    lo, hi = x.min(axis=0), x.max(axis=0)
    tol = REL_TOL * float(np.max(hi - lo))
    return x, cells, u, lo, hi, tol


def top_surface(h5, path):
    """Top-surface vertices of the last step: deformed (x, y), height of the deformed surface above
    the undeformed one, the triangles of the top faces in local numbers, the mirror axes and the
    tolerance of a plane."""
    x, cells, u, lo, hi, tol = _last_top(h5, path)
    if is_section(x, cells, tol):
        raise InputError(f"{path}: an axisymmetric section, whose top surface is a profile, not a map: its imprint "
                         "is imprint.csv of scripts/plot-indent.py")
    on_top = np.abs(x[:, 2] - hi[2]) <= tol
    tris, _ = plane_faces(cells, on_top)
    verts = np.flatnonzero(on_top)
    local = np.full(len(x), -1)
    local[verts] = np.arange(len(verts))
    xy = x[verts, :2] + u[verts, :2]
    height = x[verts, 2] + u[verts, 2] - hi[2]
    # A symmetry plane x = 0 or y = 0 bounds the model with the body on its positive side.
    axes = [a for a in (0, 1) if abs(lo[a]) <= tol and hi[a] > tol]
    return xy, height, local[tris], axes, tol


def top_profile(h5, path):
    """The top surface of an axisymmetric section at the last step: deformed radius and height above the
    undeformed surface of its vertices, by radius; None for a 3D model."""
    x, cells, u, lo, hi, tol = _last_top(h5, path)
    if not is_section(x, cells, tol):
        return None
    verts = np.flatnonzero(np.abs(x[:, 2] - hi[2]) <= tol)
    r, height = x[verts, 0] + u[verts, 0], x[verts, 2] + u[verts, 2] - hi[2]
    order = np.argsort(r)
    return r[order], height[order]


def read_scratch(path, need):
    """scratch.csv as a dict of float arrays, one per column; the arrays are empty when the file has
    its header only (a run stopped before its first scratching step)."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})") from None
    missing = [c for c in need if not rows or c not in rows[0]]
    if missing:
        raise InputError(f"{path}: no header or missing the columns {', '.join(missing)}")
    head, body = rows[0], [r for r in rows[1:] if r]
    for k, r in enumerate(body, 2):
        if len(r) != len(head):
            raise InputError(f"{path}: line {k} has {len(r)} values under a header of {len(head)} columns")
    try:
        table = np.array([[float(v) for v in r] for r in body], dtype=float).reshape(len(body), len(head))
    except ValueError as e:
        raise InputError(f"{path}: unreadable number ({e})") from None
    return {c: table[:, k] for k, c in enumerate(head)}


def open_fields(run_dir, h5_name, what):
    """The run's field file, open for reading; InputError naming it when it is missing (what: why the
    caller needs it) or not HDF5."""
    import h5py  # only the scripts that read fields need it
    path = os.path.join(run_dir, h5_name)
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file ({what})")
    try:
        return h5py.File(path, "r"), path
    except OSError as e:
        raise InputError(f"{path}: cannot open as HDF5 ({e})") from None


def read_curve(path, need=("depth_nm", "load_uN")):
    """The load-displacement CSV as a dict of float arrays, one per column; InputError naming the file
    when it is missing, has no rows or lacks a column of need."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file (a run with an indenter writes it)")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or any(c not in rows[0] for c in need):
        raise InputError(f"{path}: no data rows or missing one of the columns {', '.join(need)}")
    try:
        return {c: np.array([float(r[c]) for r in rows]) for c in rows[0]}
    except (TypeError, ValueError) as e:
        raise InputError(f"{path}: unreadable number ({e})") from None


def field_steps(h5, path):
    """The accepted step of each step in /fields (-output_fields_every writes only some): /fields/step, or
    1, 2, ... for a file written before it existed, when every step was written."""
    n = dataset(h5, "fields/displacement", path).shape[0]
    if "fields/step" not in h5:
        return np.arange(1, n + 1)
    steps = h5["fields/step"][:].reshape(-1).astype(np.int64)
    if len(steps) != n:
        raise InputError(f"{path}: /fields/step has {len(steps)} entries for {n} steps of fields")
    return steps


def curve_rows(curve, steps, path):
    """The rows of the curve (its step column) holding each written field step; InputError when one is
    missing, as in a run still being written."""
    where = {int(s): i for i, s in enumerate(curve["step"])} if "step" in curve else \
        {i + 1: i for i in range(len(curve["load_uN"]))}
    missing = [int(s) for s in steps if int(s) not in where]
    if missing:
        raise InputError(f"{path}: fields of step {missing[0]}, which the curve does not have (a run still being "
                         "written?)")
    return np.array([where[int(s)] for s in steps], dtype=np.int64)
