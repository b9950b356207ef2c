"""Shared by the scripts that read an indent run's files (plot-indent.py, export-curves.py): the cells'
faces, the input error they report in one line, and the triangulation of a plane of the mesh with its
mirror images (half and quarter models)."""
import numpy as np

# Local faces of the supported cells as cyclic vertex lists (VTK order for the hexahedron), so that
# a quadrilateral splits into the triangles (0, 1, 2) and (0, 2, 3).
CELL_FACES = {
    4: [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)],
    8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}


class InputError(Exception):
    """A missing or malformed input file: reported in one line, exit status 2."""


def plane_faces(cells, on_plane):
    """Triangles of the cell faces whose vertices all lie on a plane (on_plane: vertex mask), with
    the cell owning each triangle."""
    flags = on_plane[cells]
    tris, owners = [], []
    for face in CELL_FACES[cells.shape[1]]:  # a loop over the 4 or 6 local faces, not over cells
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
