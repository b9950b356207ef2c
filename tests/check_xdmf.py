#!/usr/bin/env python3
"""Checks an indent XDMF index (doc/output.md, "XDMF index"):
- XDMF 3, one Temporal collection of Uniform grids (one per output step), each with its own Topology
  and Geometry;
- every HDF5 reference exists with the stated dimensions, and the attributes of output step k are the
  views /xdmf/<k>/<field> holding exactly the slab k of /fields/<field>;
- the time values strictly increase; every step has its load step and load factor as Information, and,
  with an indenter (contact fields), its depth and load; with load_displacement.csv beside the index,
  they equal the curve's row of that step;
- every cell of the topology has positive volume in VTK vertex order.
Also imported by check_xdmf_meshio.py and check_xdmf_paraview.py for read_index()."""
import csv
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


class XdmfError(Exception):
    pass


def hdf_item(parent):
    """(file, dataset, dims) of the one HDF DataItem in parent (meshio reads exactly one, whole)."""
    items = list(parent)
    if len(items) != 1 or items[0].tag != "DataItem":
        raise XdmfError(f"<{parent.tag} {parent.attrib}> must hold exactly one DataItem")
    item = items[0]
    if item.get("Format") != "HDF":
        raise XdmfError(f"DataItem {item.attrib} is not Format=\"HDF\"")
    fname, dset = item.text.strip().split(":")
    return fname, dset, tuple(int(d) for d in item.get("Dimensions").split())


def read_index(path):
    """The steps of the index, each {"name", "time", "info": {name: value}, "topology": (type, item),
    "geometry": item, "attributes": {name: (center, item)}}, where item is (file, dataset, dims)."""
    root = ET.parse(path).getroot()
    if root.tag != "Xdmf" or root.get("Version", "").split(".")[0] != "3":
        raise XdmfError(f"root is <{root.tag} Version={root.get('Version')!r}>, not XDMF 3")
    domains = list(root)
    if len(domains) != 1 or domains[0].tag != "Domain":
        raise XdmfError("the root must hold exactly one Domain (meshio)")
    grids = [g for g in domains[0] if g.tag == "Grid"]
    if len(grids) != 1 or grids[0].get("GridType") != "Collection" or grids[0].get("CollectionType") != "Temporal":
        raise XdmfError("the Domain must hold exactly one Grid, a Temporal collection")
    steps = []
    for g in grids[0]:
        if g.tag != "Grid" or g.get("GridType") != "Uniform":
            raise XdmfError(f"<{g.tag} {g.attrib}> in the collection: only Uniform grids "
                            "(meshio counts every child as a step)")
        step = {"name": g.get("Name"), "time": None, "info": {}, "attributes": {}}
        for c in g:
            if c.tag == "Time":
                step["time"] = float(c.get("Value"))
            elif c.tag == "Information":
                step["info"][c.get("Name")] = float(c.get("Value"))
            elif c.tag == "Topology":
                step["topology"] = (c.get("TopologyType"), hdf_item(c))
            elif c.tag == "Geometry":
                step["geometry"] = hdf_item(c)
            elif c.tag == "Attribute":
                if c.get("Center") not in ("Node", "Cell"):
                    raise XdmfError(f"attribute {c.get('Name')} has Center={c.get('Center')!r} "
                                    "(meshio reads Node and Cell only)")
                step["attributes"][c.get("Name")] = (c.get("Center"), hdf_item(c))
            else:
                raise XdmfError(f"unexpected <{c.tag}> in step {step['name']}")
        for key in ("topology", "geometry"):
            if key not in step:
                raise XdmfError(f"step {step['name']} has no {key}")
        if step["time"] is None:
            raise XdmfError(f"step {step['name']} has no time value")
        steps.append(step)
    if not steps:
        raise XdmfError("no steps")
    return steps


def read_curve(path):
    with open(path) as f:
        return {int(r["step"]): r for r in csv.DictReader(f)}


def check(path):
    base = os.path.dirname(path)
    steps = read_index(path)
    files = {}

    def dataset(item):
        fname, dset, dims = item
        f = files.setdefault(fname, h5py.File(os.path.join(base, fname), "r"))
        if dset.lstrip("/") not in f:
            raise XdmfError(f"{dset} referenced by the XDMF is not in {fname}")
        if f[dset].shape != dims:
            raise XdmfError(f"{dset} has shape {f[dset].shape}, the XDMF says {dims}")
        return f, f[dset]

    checked = 0
    for k, s in enumerate(steps):
        dataset(s["topology"][1])
        dataset(s["geometry"])
        checked += 2
        for name, (center, item) in s["attributes"].items():
            f, view = dataset(item)
            if item[1] != f"/xdmf/{k}/{name}":
                raise XdmfError(f"step {k}: attribute {name} points at {item[1]}, not /xdmf/{k}/{name}")
            whole = f["fields/" + name]
            if whole.shape[0] <= k or not np.array_equal(view[()], whole[k]):
                raise XdmfError(f"/xdmf/{k}/{name} is not the slab {k} of /fields/{name}")
            checked += 1

    times = np.array([s["time"] for s in steps])
    if len(times) > 1 and not (np.diff(times) > 0).all():
        k = int(np.argmax(np.diff(times) <= 0))
        raise XdmfError(f"time values do not increase: step {k + 1} has {times[k + 1]} after {times[k]}")
    indenter = "contact_pressure" in steps[0]["attributes"]
    wanted = ["step", "load_factor"] + (["depth_nm", "load_uN"] if indenter else [])
    for s in steps:
        missing = [w for w in wanted if w not in s["info"]]
        if missing:
            raise XdmfError(f"step {s['name']} lacks the Information {missing}")

    curve_path = os.path.join(base, "load_displacement.csv")
    compared = 0
    if indenter and os.path.exists(curve_path):
        curve = read_curve(curve_path)
        for s in steps:
            row = curve.get(int(s["info"]["step"]))
            if row is None:
                raise XdmfError(f"step {s['name']}: load step {s['info']['step']:g} is not in {curve_path}")
            pairs = [(s["time"], float(row["t"])), (s["info"]["depth_nm"], float(row["depth_nm"])),
                     (s["info"]["load_uN"], float(row["load_uN"]))]
            if not all(np.isclose(a, b, rtol=1e-9, atol=1e-9) for a, b in pairs):
                raise XdmfError(f"step {s['name']}: (t, depth, load) = {[a for a, _ in pairs]}, "
                                f"the curve has {[b for _, b in pairs]}")
            compared += 1

    f, cells = dataset(steps[0]["topology"][1])
    _, vertices = dataset(steps[0]["geometry"])
    if "fields/step" in f:  # the file's own record of which accepted step each output step is
        saved = [int(v) for v in f["fields/step"][:].reshape(-1)]
        listed = [int(s["info"]["step"]) for s in steps]
        if saved != listed:
            raise XdmfError(f"/fields/step {saved} differs from the index's steps {listed}")
    X, C = vertices[()], cells[()]
    # an axisymmetric section (a 2D mesh) lies in the plane y = 0: triangles, or quadrilaterals
    section = C.shape[1] in (3, 4) and bool(np.all(X[:, 1] == 0))
    expected = ({3: "Triangle", 4: "Quadrilateral"} if section else {4: "Tetrahedron", 8: "Hexahedron"}).get(C.shape[1])
    if steps[0]["topology"][0] != expected:
        raise XdmfError(f"TopologyType {steps[0]['topology'][0]} for cells of {C.shape[1]} vertices")
    P = X[C]
    if section:  # a section's cells may be drawn either way round: only a degenerate one is wrong
        xz = P[:, :, [0, 2]]
        vol = np.abs(np.cross(xz[:, 1] - xz[:, 0], xz[:, 2] - xz[:, 0]))
    elif C.shape[1] == 4:
        vol = np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]), P[:, 3] - P[:, 0])
    else:  # VTK hexahedron: corner 0 with its three neighbours 1, 3, 4
        vol = np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 3] - P[:, 0]), P[:, 4] - P[:, 0])
    if (vol <= 0).any():
        raise XdmfError(f"{(vol <= 0).sum()} cells with non-positive volume in VTK order")
    print(f"ok: {checked} HDF references, {len(steps)} steps at times {times[0]:g} .. {times[-1]:g} increasing, "
          f"Information {wanted}, {compared} steps equal to the curve, {C.shape[0]} cells with positive "
          f"{'area' if section else 'volume'}")


def main(path):
    try:
        check(path)
    except XdmfError as e:
        print(f"FAIL: {path}: {e}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
