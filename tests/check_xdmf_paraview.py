#!/usr/bin/env python3
"""Reads each indent XDMF index given with ParaView's three XDMF readers (XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT)
and checks, against the index and indent.h5 read with h5py: the time values, and at every step the
mesh size and cell type, the arrays with their component counts (stress and strain: 6) and the values
of every field. Runs with /usr/bin/python3 when Debian's python3-paraview is installed, or with pvpython.
Exit 77 (skipped) only when ParaView's Python modules cannot be imported."""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_xdmf import XdmfError, read_index  # noqa: E402

SKIP = 77
VTK_TRIANGLE, VTK_QUAD, VTK_TETRA, VTK_HEXAHEDRON = 5, 9, 10, 12


def fetch(reader, t):
    from paraview import servermanager

    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    while data.IsA("vtkMultiBlockDataSet"):
        if data.GetNumberOfBlocks() != 1:
            raise RuntimeError(f"{data.GetNumberOfBlocks()} blocks")
        data = data.GetBlock(0)
    return data


def check_reader(label, reader, steps, h5):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    C = h5["topology/cells"]
    nvert, (ncell, corners) = h5["geometry/vertices"].shape[0], C.shape
    section = corners in (3, 4) and not np.any(h5["geometry/vertices"][:, 1])  # an axisymmetric section, in y = 0
    cell_type = ({3: VTK_TRIANGLE, 4: VTK_QUAD} if section else {4: VTK_TETRA, 8: VTK_HEXAHEDRON})[corners]
    times = np.array([s["time"] for s in steps])
    reader.UpdatePipelineInformation()
    seen = np.array(reader.TimestepValues, dtype=float).ravel()
    if seen.shape != times.shape or not np.allclose(seen, times, rtol=1e-12, atol=0):
        return f"{label}: time values {seen.tolist()}, the index has {times.tolist()}"
    compared = 0
    for k, t in enumerate(times):
        d = fetch(reader, t)
        if d.GetNumberOfPoints() != nvert or d.GetNumberOfCells() != ncell:
            return (f"{label}: step {k}: {d.GetNumberOfPoints()} points, {d.GetNumberOfCells()} cells; "
                    f"indent.h5 has {nvert}, {ncell}")
        if d.GetCellType(0) != cell_type:
            return f"{label}: step {k}: VTK cell type {d.GetCellType(0)}, expected {cell_type}"
        for name, (center, _) in steps[k]["attributes"].items():
            arrays = d.GetPointData() if center == "Node" else d.GetCellData()
            a = arrays.GetArray(name)
            ref = h5["fields/" + name][k]
            if a is None:
                return f"{label}: step {k}: no {center} array {name}"
            if a.GetNumberOfComponents() != ref.shape[1]:
                return f"{label}: step {k}: {name} has {a.GetNumberOfComponents()} components, indent.h5 {ref.shape[1]}"
            if not np.array_equal(vtk_to_numpy(a).reshape(ref.shape), ref):
                return f"{label}: step {k}: {name} differs from /fields/{name}[{k}]"
            compared += 1
    print(f"ok: {label}: {len(times)} time values {times[0]:g} .. {times[-1]:g}, {compared} arrays equal to indent.h5")
    return None


def main(path):
    try:
        from paraview import simple
    except ImportError as e:
        print(f"SKIP: ParaView's Python modules are not importable ({e}); install the Debian package python3-paraview")
        return SKIP
    import paraview

    print(f"ParaView {paraview.__version__}")
    try:
        steps = read_index(path)
    except XdmfError as e:
        print(f"FAIL: {path}: {e}")
        return 1
    h5 = h5py.File(os.path.join(os.path.dirname(path), "indent.h5"), "r")
    readers = [("XDMFReader", lambda: simple.XDMFReader(FileNames=[path])),
               ("Xdmf3ReaderS", lambda: simple.Xdmf3ReaderS(FileName=[path])),
               ("Xdmf3ReaderT", lambda: simple.Xdmf3ReaderT(FileName=[path]))]
    failed = 0
    for label, make in readers:
        reader = make()
        error = check_reader(label, reader, steps, h5)
        simple.Delete(reader)
        if error:
            print("FAIL: " + error)
            failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    codes = [main(os.path.abspath(path)) for path in sys.argv[1:]]
    sys.exit(1 if 1 in codes else max(codes))
