#!/usr/bin/env python3
"""A section's mesh turned into a 3D one (scripts/revolve-mesh.py):

  check_revolve_mesh.py --workdir D

A small section written here (triangles with none, one and two vertices on the axis; physical surfaces 'film' and
'substrate', curves 'top', 'bottom', 'sides' and 'axis') is revolved through 90, 180 and 360 degrees:
- the tetrahedra: three, two and one per triangle and segment, every one of positive volume, and their volume
  sin(d) / d times the ring's (d the segment's angle: the sweep's straight chords), to 1e-12;
- the faces: every face of a tetrahedron shared by two of them or on the boundary, and the boundary exactly the
  named surfaces ('top', 'bottom', 'sides', and 'front' (y = 0) and 'left' (x = 0) where the sweep stops), each
  triangle of them a face of one tetrahedron, with the volumes named as the section's surfaces;
- every node on a meridian of a section node, at its radius and height;
- bad sections (quadrilaterals, a 3D mesh, no physical groups): exit 2 and one line.
Prints ok or FAIL per check; exit 1 on any failure.
"""
import argparse
import math
import os
import subprocess
import sys
from collections import Counter

import numpy as np

import meshio

from checklist import check, status  # this folder

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "revolve-mesh.py")


def section(path):
    """A 3 x 2 grid of squares in r in [0, 3], z in [-2, 0], each cut in two; film above z = -1."""
    nr, nz = 4, 3
    pts = np.array([[1.0 * i, -1.0 * j, 0.0] for j in range(nz) for i in range(nr)])
    pts[5, :2] += [0.2, 0.1]  # an interior node off the grid
    tris, tags = [], []
    for j in range(nz - 1):
        for i in range(nr - 1):
            a, b, c, d = j * nr + i, j * nr + i + 1, (j + 1) * nr + i + 1, (j + 1) * nr + i
            tris += [(a, d, b), (b, d, c)] if (i + j) % 2 else [(a, c, b), (a, d, c)]
            tags += [1, 1] if j == 0 else [2, 2]
    lines, ltags = [], []
    for i in range(nr - 1):
        lines += [(i, i + 1), ((nz - 1) * nr + i, (nz - 1) * nr + i + 1)]
        ltags += [3, 4]
    for j in range(nz - 1):
        lines += [(j * nr, (j + 1) * nr), (j * nr + nr - 1, (j + 1) * nr + nr - 1)]
        ltags += [5, 6]
    cells = [("triangle", np.array(tris)), ("line", np.array(lines))]
    phys = [np.array(tags), np.array(ltags)]
    field = {"film": np.array([1, 2]), "substrate": np.array([2, 2]), "top": np.array([3, 1]),
             "bottom": np.array([4, 1]), "axis": np.array([5, 1]), "sides": np.array([6, 1])}
    meshio.write(path, meshio.Mesh(pts, cells, cell_data={"gmsh:physical": phys, "gmsh:geometrical": phys},
                                   field_data=field), file_format="gmsh22", binary=False)
    return pts, np.array(tris), np.array(tags)


def tet_volumes(p, t):
    e1, e2, e3 = (p[t[:, i]] - p[t[:, 0]] for i in (1, 2, 3))
    return np.einsum("ij,ij->i", np.cross(e1, e2), e3) / 6


def revolved(args, sec, angle, segments):
    pts, tris, tags = sec
    out = os.path.join(args.workdir, f"revolved_{angle}.msh")
    run = subprocess.run([sys.executable, SCRIPT, os.path.join(args.workdir, "section.msh"), out,
                          "--angle", str(angle), "--segments", str(segments)], capture_output=True, text=True)
    if not check(run.returncode == 0, f"{angle} degrees: revolved ({run.stdout.strip() or run.stderr.strip()})"):
        return
    m = meshio.read(out)
    p = m.points
    tets = np.concatenate([c.data for c in m.cells if c.type == "tetra"])
    names = {int(t): n for n, (t, d) in m.field_data.items()}
    faces = {}
    for c, tg in zip(m.cells, m.cell_data["gmsh:physical"]):
        if c.type == "triangle":
            for f, g in zip(c.data, tg):
                faces.setdefault(names[int(g)], []).append(tuple(sorted(f)))
    vol_names = sorted({names[int(g)] for c, tg in zip(m.cells, m.cell_data["gmsh:physical"]) if c.type == "tetra"
                        for g in tg})
    r = pts[:, 0]
    naxis = np.array([np.sum(r[t] == 0) for t in tris])
    expect = segments * int(np.sum(np.where(naxis == 0, 3, np.where(naxis == 1, 2, 1))))
    check(len(tets) == expect, f"{angle} degrees: {len(tets)} tetrahedra (3, 2 or 1 a triangle and segment)")
    vol = tet_volumes(p, tets)
    d = math.radians(angle) / segments
    area = 0.5 * np.abs((pts[tris[:, 1], 0] - pts[tris[:, 0], 0]) * (pts[tris[:, 2], 1] - pts[tris[:, 0], 1]) -
                        (pts[tris[:, 2], 0] - pts[tris[:, 0], 0]) * (pts[tris[:, 1], 1] - pts[tris[:, 0], 1]))
    ring = segments * math.sin(d) * np.sum(area * pts[tris, 0].mean(axis=1))
    check(vol.min() > 0 and abs(vol.sum() / ring - 1) < 1e-12,
          f"{angle} degrees: volumes positive, {vol.sum():.12g} against sin(d)/d of the ring's {ring:.12g}")
    count = Counter(tuple(sorted(f)) for t in tets for f in ((t[0], t[1], t[2]), (t[0], t[1], t[3]),
                                                              (t[0], t[2], t[3]), (t[1], t[2], t[3])))
    boundary = {f for f, n in count.items() if n == 1}
    named = set().union(*[set(v) for v in faces.values()]) if faces else set()
    want = {"top", "bottom", "sides"} | ({"front", "left"} if angle == 90 else {"front"} if angle == 180 else set())
    check(max(count.values()) == 2 and boundary == named and set(faces) == want
          and all(len(v) == len(set(v)) for v in faces.values()),
          f"{angle} degrees: faces shared by two tetrahedra or on the boundary, which is {sorted(faces)}")
    check(vol_names == ["film", "substrate"], f"{angle} degrees: the volumes {vol_names}")
    if "front" in faces:
        check(all(p[list(f), 1].max() == 0 and p[list(f), 1].min() == 0 for f in faces["front"]), f"{angle} degrees: "
              "'front' in the plane y = 0")
    if "left" in faces:
        check(all(np.all(p[list(f), 0] == 0) for f in faces["left"]), f"{angle} degrees: 'left' in the plane x = 0")
    rz = np.column_stack([np.hypot(p[:, 0], p[:, 1]), p[:, 2]])
    dist = np.min(np.hypot(rz[:, None, 0] - pts[None, :, 0], rz[:, None, 1] - pts[None, :, 1]), axis=1)
    check(dist.max() < 1e-12, f"{angle} degrees: every node at a section node's radius and height ({dist.max():.1e})")


def bad(args):
    quads = os.path.join(args.workdir, "quads.msh")
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, -1, 0], [0, -1, 0]], float)
    meshio.write(quads, meshio.Mesh(pts, [("quad", np.array([[0, 3, 2, 1]]))],
                                    cell_data={"gmsh:physical": [np.array([1])], "gmsh:geometrical": [np.array([1])]},
                                    field_data={"domain": np.array([1, 2])}), file_format="gmsh22", binary=False)
    solid = os.path.join(args.workdir, "solid.msh")
    pts3 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    meshio.write(solid, meshio.Mesh(pts3, [("tetra", np.array([[0, 1, 2, 3]]))],
                                    cell_data={"gmsh:physical": [np.array([1])], "gmsh:geometrical": [np.array([1])]},
                                    field_data={"domain": np.array([1, 3])}), file_format="gmsh22", binary=False)
    bare = os.path.join(args.workdir, "bare.msh")
    meshio.write(bare, meshio.Mesh(pts, [("triangle", np.array([[0, 2, 1]]))]), file_format="gmsh22", binary=False)
    for path, say in ((quads, "quad"), (solid, "not a section"), (bare, "physical"),
                      (os.path.join(args.workdir, "nowhere.msh"), "cannot read")):
        run = subprocess.run([sys.executable, SCRIPT, path, os.path.join(args.workdir, "out.msh")],
                             capture_output=True, text=True)
        lines = run.stderr.strip().splitlines()
        check(run.returncode == 2 and len(lines) == 1 and say in lines[0] and path in lines[0],
              f"{os.path.basename(path)}: exit 2, one line naming it, '{say}'")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--workdir", required=True)
    args = ap.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    sec = section(os.path.join(args.workdir, "section.msh"))
    for angle, segments in ((90, 4), (180, 5), (360, 7)):
        revolved(args, sec, angle, segments)
    bad(args)
    return status()


if __name__ == "__main__":
    sys.exit(main())
