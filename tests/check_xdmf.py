#!/usr/bin/env python3
"""Checks an indent XDMF index: every HDF5 reference exists with the stated dimensions, hyperslabs
select inside their dataset, and every cell of the topology has positive volume (VTK vertex order)."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def main(path):
    root = ET.parse(path).getroot()
    base = os.path.dirname(path)
    files = {}
    checked = 0
    for item in root.iter("DataItem"):
        if item.get("Format") != "HDF":
            continue
        fname, dset = item.text.strip().split(":")
        f = files.setdefault(fname, h5py.File(os.path.join(base, fname), "r"))
        dims = tuple(int(d) for d in item.get("Dimensions").split())
        if dset.lstrip("/") not in f:
            print(f"FAIL: {dset} referenced by the XDMF is not in {fname}")
            return 1
        shape = f[dset].shape
        if shape != dims:
            print(f"FAIL: {dset} has shape {shape}, the XDMF says {dims}")
            return 1
        checked += 1
    steps = len([g for g in root.iter("Grid") if g.get("GridType") == "Uniform"])
    f = next(iter(files.values()))
    X, C = f["geometry/vertices"][:], f["topology/cells"][:]
    P = X[C]
    if C.shape[1] == 4:
        vol = np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]), P[:, 3] - P[:, 0])
    else:  # VTK hexahedron: corner 0 with its three neighbours 1, 3, 4
        vol = np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 3] - P[:, 0]), P[:, 4] - P[:, 0])
    if (vol <= 0).any():
        print(f"FAIL: {(vol <= 0).sum()} cells with non-positive volume in VTK order")
        return 1
    print(f"ok: {checked} HDF references, {steps} steps, {C.shape[0]} cells with positive volume")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
