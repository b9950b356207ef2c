#!/usr/bin/env python3
"""The fields of an axisymmetric run (a 2D section in (r, z)) revolved into 3D, for ParaView.

  /usr/bin/python3 scripts/revolve.py RUN_DIR [--segments 36] [--angle 360] [--out DIR]

Reads RUN_DIR/indent.h5 (and the steps' times from load_displacement.csv) of a run on a section (indent writes it
in the plane y = 0, x the radius, z the axis) and writes DIR/revolved.h5 and DIR/revolved.xdmf (DIR: RUN_DIR by
default): every step of the section's fields on the solid swept by turning the section about z through --angle
degrees in --segments equal segments. Triangles become wedges and quadrilaterals hexahedra (cells on the axis
have a degenerate edge there). Values are the section's, in the 3D frame: a vertex's displacement (u_r, 0, u_z) becomes
(u_r cos t, u_r sin t, u_z) at angle t; a cell's stress and strain (Voigt xx, yy, zz, xy, yz, xz, with yy the
hoop component and strain shears engineering) are turned by the segment's middle angle; scalars are
copied. The revolved solid's straight edges make its volume sin(d)/d times the ring's, d = angle / segments.
Exit status 2 on bad input.
"""
import argparse
import math
import os
import sys

import numpy as np

from runfiles import (REL_TOL, InputError, curve_rows, dataset, field_steps, is_section, open_fields,  # this folder
                      read_curve)

H5_NAME = "indent.h5"
OUT_H5, OUT_XDMF = "revolved.h5", "revolved.xdmf"


def parse(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--segments", type=int, default=36, help="segments round the axis (36)")
    ap.add_argument("--angle", type=float, default=360.0, help="degrees swept, in (0, 360] (360)")
    ap.add_argument("--out", help="directory of revolved.h5 and revolved.xdmf (RUN_DIR)")
    args = ap.parse_args(argv)
    if args.segments < 1:
        ap.error(f"--segments must be >= 1, got {args.segments}")
    if not 0 < args.angle <= 360:
        ap.error(f"--angle must lie in (0, 360] degrees, got {args.angle:g}")
    if args.angle == 360 and args.segments < 3:
        ap.error("--segments must be >= 3 for a full turn")
    return args


def revolve_mesh(x, cells, angles, full):
    """Vertices turned to each angle (copy k of vertex v is k n + v) and the cells between consecutive
    copies, ordered as VTK and XDMF expect: a wedge's first triangle faces away from its second, a
    hexahedron's first quadrilateral towards its second."""
    n, nseg = len(x), len(angles) - 1
    r, z = x[:, 0], x[:, 2]
    ncopy = nseg if full else nseg + 1
    pts = np.concatenate([np.column_stack([r * math.cos(t), r * math.sin(t), z]) for t in angles[:ncopy]])
    # orientation of each section cell in the (r, z) plane: its normal along +y (the turning direction)
    # when (x1 - x0) x (x2 - x0) has a positive y component, i.e. (z1 - z0)(r2 - r0) - (r1 - r0)(z2 - z0) > 0
    a, b, c = cells[:, 0], cells[:, 1], cells[:, 2]
    ny = (z[b] - z[a]) * (r[c] - r[a]) - (r[b] - r[a]) * (z[c] - z[a])
    base = cells.copy()
    wedge = cells.shape[1] == 3
    flip = ny > 0 if wedge else ny < 0
    base[flip] = base[flip][:, ::-1]
    out = []
    for k in range(nseg):
        k1 = (k + 1) % ncopy
        out.append(np.hstack([base + k * n, base + k1 * n]))
    return pts, np.concatenate(out)


def rotate_vectors(u, angles, ncopy):
    """(u_r, u_theta, u_z) of every vertex, turned to each copy's angle, stacked like revolve_mesh's points."""
    parts = []
    for t in angles[:ncopy]:
        c, s = math.cos(t), math.sin(t)
        parts.append(np.column_stack([c * u[:, 0] - s * u[:, 1], s * u[:, 0] + c * u[:, 1], u[:, 2]]))
    return np.concatenate(parts)


def rotate_voigt(v, t, engineering):
    """Voigt (xx, yy, zz, xy, yz, xz) tensors turned by t about z; engineering: shears are doubled."""
    f = 0.5 if engineering else 1.0
    T = np.empty((len(v), 3, 3))
    T[:, 0, 0], T[:, 1, 1], T[:, 2, 2] = v[:, 0], v[:, 1], v[:, 2]
    T[:, 0, 1] = T[:, 1, 0] = f * v[:, 3]
    T[:, 1, 2] = T[:, 2, 1] = f * v[:, 4]
    T[:, 0, 2] = T[:, 2, 0] = f * v[:, 5]
    c, s = math.cos(t), math.sin(t)
    Q = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    R = np.einsum("ij,njk,lk->nil", Q, T, Q)
    return np.column_stack([R[:, 0, 0], R[:, 1, 1], R[:, 2, 2], R[:, 0, 1] / f, R[:, 1, 2] / f, R[:, 0, 2] / f])


def revolve_field(name, values, on_vertices, angles, ncopy):
    """One step's field on the revolved mesh."""
    nseg = len(angles) - 1
    if on_vertices:
        if values.shape[1] == 3:
            return rotate_vectors(values, angles, ncopy)
        return np.concatenate([values] * ncopy)
    if values.shape[1] == 6:
        mids = [0.5 * (angles[k] + angles[k + 1]) for k in range(nseg)]
        return np.concatenate([rotate_voigt(values, t, name == "strain") for t in mids])
    return np.concatenate([values] * nseg)


def xdmf_text(names, shapes, centres, nverts, ncells, cell_type, per_cell, steps, times):
    kinds = {1: "Scalar", 3: "Vector", 6: "Matrix"}
    out = ['<?xml version="1.0" ?>', '<Xdmf Version="3.0">', "<Domain>",
           '<Grid Name="steps" GridType="Collection" CollectionType="Temporal">']
    for i, (step, t) in enumerate(zip(steps, times)):
        out += [f'<Grid Name="output {i}" GridType="Uniform">', f'<Time Value="{t:.15g}"/>',
                f'<Information Name="step" Value="{int(step)}"/>',
                f'<Topology TopologyType="{cell_type}" NumberOfElements="{ncells}">',
                f'<DataItem Format="HDF" NumberType="Int" Precision="8" Dimensions="{ncells} {per_cell}">'
                f"{OUT_H5}:/topology/cells</DataItem>", "</Topology>", '<Geometry GeometryType="XYZ">',
                f'<DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{nverts} 3">'
                f"{OUT_H5}:/geometry/vertices</DataItem>", "</Geometry>"]
        for name, comps, centre in zip(names, shapes, centres):
            rows = nverts if centre == "Node" else ncells
            out += [f'<Attribute Name="{name}" AttributeType="{kinds.get(comps, "Scalar")}" Center="{centre}">',
                    f'<DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{rows} {comps}">'
                    f"{OUT_H5}:/xdmf/{i}/{name}</DataItem>", "</Attribute>"]
        out.append("</Grid>")
    out += ["</Grid>", "</Domain>", "</Xdmf>", ""]
    return "\n".join(out)


def main(argv):
    args = parse(argv)
    import h5py
    try:
        h5, path = open_fields(args.run_dir, H5_NAME, "the section's fields to revolve")
        with h5:
            x = dataset(h5, "geometry/vertices", path)[:]
            cells = dataset(h5, "topology/cells", path)[:].astype(np.int64)
            tol = REL_TOL * float(np.max(x.max(axis=0) - x.min(axis=0))) if len(x) else 0.0
            if x.ndim != 2 or x.shape[1] != 3 or not is_section(x, cells, tol):
                raise InputError(f"{path}: not an axisymmetric section (a 2D mesh in the plane y = 0): a 3D run "
                                 "needs no revolving")
            if np.any(x[:, 0] < -tol):
                raise InputError(f"{path}: vertices at r < 0: not a section indent wrote")
            fields = {k: h5["fields"][k] for k in dataset(h5, "fields", path) if k != "step"}
            steps = field_steps(h5, path)
            # the load program's pseudo-time of each step, as indent's own XDMF gives it
            curve = read_curve(os.path.join(args.run_dir, "load_displacement.csv"), need=("t", "step"))
            times = curve["t"][curve_rows(curve, steps, path)]
            full = args.angle >= 360.0
            angles = np.linspace(0.0, math.radians(args.angle), args.segments + 1)
            ncopy = args.segments if full else args.segments + 1
            pts, rcells = revolve_mesh(x, cells, angles, full)
            names, comps, centres = [], [], []
            out_dir = args.out or args.run_dir
            os.makedirs(out_dir, exist_ok=True)
            tmp = os.path.join(out_dir, OUT_H5 + ".tmp")
            with h5py.File(tmp, "w") as o:
                o["geometry/vertices"] = pts
                o["topology/cells"] = rcells
                o["fields/step"] = np.asarray(steps)
                for name, d in fields.items():
                    if d.ndim != 3 or d.shape[1] not in (len(x), len(cells)):
                        continue
                    on_vertices = d.shape[1] == len(x)
                    names.append(name)
                    comps.append(d.shape[2])
                    centres.append("Node" if on_vertices else "Cell")
                    for i in range(d.shape[0]):
                        o[f"xdmf/{i}/{name}"] = revolve_field(name, d[i], on_vertices, angles, ncopy)
            os.replace(tmp, os.path.join(out_dir, OUT_H5))
    except InputError as e:
        print(f"revolve.py: {e}", file=sys.stderr)
        return 2
    cell_type = "Wedge" if cells.shape[1] == 3 else "Hexahedron"
    text = xdmf_text(names, comps, centres, len(pts), len(rcells), cell_type, rcells.shape[1], steps, times)
    tmp = os.path.join(out_dir, OUT_XDMF + ".tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out_dir, OUT_XDMF))
    print(f"revolve.py: {len(steps)} steps of {len(names)} fields on {len(rcells)} {cell_type.lower()} cells and "
          f"{len(pts)} vertices ({args.segments} segments through {args.angle:g} deg) in "
          f"{os.path.join(out_dir, OUT_XDMF)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
