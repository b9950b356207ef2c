#!/usr/bin/env python3
"""A 3D tetrahedral mesh made by turning an axisymmetric section's triangle mesh about its axis.

  /usr/bin/python3 scripts/revolve-mesh.py SECTION.msh OUT.msh [--segments 24] [--angle 90]

SECTION.msh is the gmsh mesh of a section (gmsh's x the radius r >= 0, y the axis z), as the axisymmetric
model reads it: the mesh indent writes to its output directory (mesh.msh) or gmsh's own. OUT.msh (gmsh 2.2) is
the solid swept through --angle degrees (90: a quarter, 180: a half, 360: the whole) in --segments equal
segments about the axis, z up as the 3D model has it: each triangle sweeps a prism cut into three tetrahedra
(two, or one, where it touches the axis), every quadrilateral face cut along the diagonal through its vertex
of least number, so that neighbours share their faces. The 3D model on it has the section's nodes in (r, z)
on every meridian: the two models then differ by what they model, not by their meshes. Names carry over:
a physical surface of the section becomes the volume of that name, a physical curve the surface swept by it
('axis' sweeps nothing); the meridian at angle 0 (the plane y = 0) is 'front', the one at 90 degrees (x = 0)
'left' (a half model ends on 'front' again). Exit status 2 on bad input.
"""
import argparse
import os
import sys

import numpy as np

import meshio


class InputError(Exception):
    pass


def parse(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("section")
    ap.add_argument("out")
    ap.add_argument("--segments", type=int, default=24, help="segments round the axis (24)")
    ap.add_argument("--angle", type=float, default=90.0, help="degrees swept: 90, 180 or 360 (90)")
    args = ap.parse_args(argv)
    if args.angle not in (90.0, 180.0, 360.0):
        ap.error(f"--angle must be 90, 180 or 360 degrees, got {args.angle:g}")
    if args.segments < (3 if args.angle == 360 else 1):
        ap.error(f"--segments must be >= {3 if args.angle == 360 else 1}, got {args.segments}")
    return args


def prism_tets(v):
    """Three tetrahedra of the prism v[0:3] (bottom) and v[3:6] (top, v[i + 3] above v[i]) whose quadrilateral
    faces are cut through their vertices of least number (Dompierre et al. 1999: never a cycle)."""
    m = int(np.argmin(v))
    if m >= 3:  # the least vertex on the bottom: swap the triangles
        v = [v[3], v[4], v[5], v[0], v[1], v[2]]
        m -= 3
    b = [v[(m + i) % 3] for i in range(3)]
    t = [v[3 + (m + i) % 3] for i in range(3)]
    v0, v1, v2, v3, v4, v5 = b[0], b[1], b[2], t[0], t[1], t[2]
    if min(v1, v5) < min(v2, v4):
        return [(v0, v1, v2, v5), (v0, v1, v5, v4), (v0, v4, v5, v3)]
    return [(v0, v1, v2, v4), (v0, v4, v2, v5), (v0, v4, v5, v3)]


def quad_tris(p0, q0, q1, p1):
    """The quadrilateral p0 q0 q1 p1 (p1 above p0) cut through its vertex of least number."""
    if min(p0, q1) < min(q0, p1):
        return [(p0, q0, q1), (p0, q1, p1)]
    return [(p0, q0, p1), (q0, q1, p1)]


def section_cells(mesh):
    """Triangles and boundary lines of the section, each with its physical tag."""
    tris, tri_tags, lines, line_tags = [], [], [], []
    phys = mesh.cell_data.get("gmsh:physical")
    if phys is None:
        raise InputError("the section has no physical groups (gmsh:physical)")
    for block, tags in zip(mesh.cells, phys):
        if block.type == "triangle":
            tris.append(block.data)
            tri_tags.append(tags)
        elif block.type == "line":
            lines.append(block.data)
            line_tags.append(tags)
        elif block.type in ("quad", "triangle6", "quad9", "quad8"):
            raise InputError(f"the section has {block.type} cells: only linear triangles are revolved")
    if not tris:
        raise InputError("the section has no triangles")
    lines = np.concatenate(lines) if lines else np.zeros((0, 2), int)
    line_tags = np.concatenate(line_tags) if line_tags else np.zeros(0, int)
    return np.concatenate(tris), np.concatenate(tri_tags), lines, line_tags


def revolve(mesh, segments, angle):
    x = np.asarray(mesh.points, float)
    if np.any(np.abs(x[:, 2]) > 0) or x[:, 0].min() < -1e-9 * np.ptp(x[:, 0]):
        raise InputError("not a section: its points must lie in the plane z = 0 with x (the radius) >= 0")
    tris, tri_tags, lines, line_tags = section_cells(mesh)
    # the output's physical tags, numbered afresh: a section curve's tag may repeat a surface's
    groups = {(int(d), int(t)): n for n, (t, d) in mesh.field_data.items() if int(d) in (1, 2) and n != "axis"}
    new_tag = {key: i + 1 for i, key in enumerate(sorted(groups))}
    taken = sorted({"front", "left"} & set(groups.values()))
    if taken and angle != 360:
        raise InputError(f"the section already names {' and '.join(taken)}, the names of the sweep's end planes")
    tri_tags = [new_tag.get((2, int(t)), 0) for t in tri_tags]
    line_tags = [new_tag.get((1, int(t)), 0) for t in line_tags]
    if 0 in tri_tags:
        raise InputError("a triangle of the section is in no named physical surface")
    used = np.unique(tris)
    r, z = x[:, 0].copy(), x[:, 1].copy()
    on_axis = r <= 1e-9 * np.ptp(r)
    r[on_axis] = 0.0
    full = angle == 360.0
    ncopy = segments if full else segments + 1
    theta = np.radians(angle) * np.arange(ncopy) / segments
    cos, sin = np.cos(theta), np.sin(theta)
    # the meridians of the symmetry planes exactly in them
    for k, t in enumerate(np.arange(ncopy) * angle / segments):
        if t % 90 == 0:
            cos[k], sin[k] = [(1, 0), (0, 1), (-1, 0), (0, -1)][int(t // 90) % 4]
    # numbering: the axis nodes once, then each meridian's off-axis nodes
    axis_nodes = used[on_axis[used]]
    ring_nodes = used[~on_axis[used]]
    nid = np.full((len(x), ncopy), -1, int)
    nid[axis_nodes, :] = np.arange(len(axis_nodes))[:, None]
    for k in range(ncopy):
        nid[ring_nodes, k] = len(axis_nodes) + k * len(ring_nodes) + np.arange(len(ring_nodes))
    pts = np.zeros((len(axis_nodes) + ncopy * len(ring_nodes), 3))
    pts[: len(axis_nodes), 2] = z[axis_nodes]
    for k in range(ncopy):
        s = slice(len(axis_nodes) + k * len(ring_nodes), len(axis_nodes) + (k + 1) * len(ring_nodes))
        pts[s] = np.column_stack([r[ring_nodes] * cos[k], r[ring_nodes] * sin[k], z[ring_nodes]])

    tets, tet_tags = [], []
    for tri, tag in zip(tris, tri_tags):
        ax = [bool(on_axis[v]) for v in tri]
        if sum(ax) == 3:
            raise InputError("a triangle of the section lies on the axis")
        i = ax.index(True) if sum(ax) == 1 else (ax.index(False) if sum(ax) == 2 else 0)
        a, b, c = tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]  # a: the lone vertex on (or off) the axis
        for k in range(segments):
            k1 = (k + 1) % ncopy
            if sum(ax) == 0:
                cells = prism_tets([nid[a, k], nid[b, k], nid[c, k], nid[a, k1], nid[b, k1], nid[c, k1]])
            elif sum(ax) == 1:  # a pyramid: apex a on the axis, base b c swept
                cells = [(nid[a, k],) + t for t in quad_tris(nid[b, k], nid[c, k], nid[c, k1], nid[b, k1])]
            else:  # b and c on the axis: one tetrahedron
                cells = [(nid[b, k], nid[c, k], nid[a, k], nid[a, k1])]
            tets.extend(cells)
            tet_tags.extend([tag] * len(cells))
    tets = np.array(tets, int)
    e1, e2, e3 = (pts[tets[:, i]] - pts[tets[:, 0]] for i in (1, 2, 3))
    vol = np.einsum("ij,ij->i", np.cross(e1, e2), e3)
    tets[vol < 0] = tets[vol < 0][:, [0, 2, 1, 3]]
    if np.any(np.abs(vol) <= 1e-14 * np.abs(vol).max()):
        raise InputError("the sweep made a flat tetrahedron: is a triangle's edge along the axis cut?")

    tris3, tri3_tags = [], []
    for (p, q), tag in zip(lines, line_tags):
        if not tag or (on_axis[p] and on_axis[q]):
            continue  # the axis sweeps nothing
        if on_axis[q]:
            p, q = q, p
        for k in range(segments):
            k1 = (k + 1) % ncopy
            if on_axis[p]:
                faces = [(nid[p, k], nid[q, k], nid[q, k1])]
            else:
                faces = quad_tris(nid[p, k], nid[q, k], nid[q, k1], nid[p, k1])
            tris3.extend(faces)
            tri3_tags.extend([tag] * len(faces))
    next_tag = len(new_tag) + 1
    plane_tags = {}
    for k, name in [(0, "front"), (segments, "left" if angle == 90 else "front")]:
        if full:
            break
        if name not in plane_tags:
            plane_tags[name] = next_tag
            next_tag += 1
        for tri in tris:
            tris3.append(tuple(nid[v, k] for v in tri))
            tri3_tags.append(plane_tags[name])

    field_data = {name: np.array([new_tag[(d, t)], d + 1]) for (d, t), name in groups.items()}
    for name, tag in plane_tags.items():
        field_data[name] = np.array([tag, 2])
    tri3_tags = np.array(tri3_tags, int)
    cells = [("tetra", tets)]
    phys = [np.asarray(tet_tags, int)]
    if len(tris3):
        cells.append(("triangle", np.array(tris3, int)))
        phys.append(tri3_tags)
    out = meshio.Mesh(pts, cells, cell_data={"gmsh:physical": phys, "gmsh:geometrical": phys},
                      field_data=field_data)
    return out, len(axis_nodes), len(ring_nodes)


def main(argv):
    args = parse(argv)
    try:
        try:
            mesh = meshio.read(args.section)
        except Exception as e:  # meshio raises several types for unreadable files
            raise InputError(f"cannot read the section '{args.section}': {e}")
        out, naxis, nring = revolve(mesh, args.segments, args.angle)
    except InputError as e:
        print(f"revolve-mesh: error: {args.section}: {e}", file=sys.stderr)
        return 2
    tmp = args.out + ".tmp"  # an earlier OUT.msh stays whole until the new one is
    meshio.write(tmp, out, file_format="gmsh22", binary=False)
    os.replace(tmp, args.out)
    print(f"revolve-mesh: {args.out}: {len(out.points)} nodes ({naxis} on the axis, {nring} on each of "
          f"{args.segments + (0 if args.angle == 360 else 1)} meridians), {len(out.cells[0].data)} tetrahedra, "
          f"{args.angle:g} degrees in {args.segments} segments")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
