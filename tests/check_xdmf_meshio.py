#!/usr/bin/env python3
"""Reads each indent XDMF index given with meshio's XdmfTimeSeriesReader (Debian python3-meshio) and checks,
against indent.h5 read with h5py: the mesh, the number of steps, every step's time value and every
field of every step. Exit 77 (skipped) only when meshio cannot be imported."""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_xdmf import XdmfError, read_index  # noqa: E402

SKIP = 77


def main(path):
    try:
        import meshio
    except ImportError as e:
        print(f"SKIP: meshio is not importable ({e}); install the Debian package python3-meshio")
        return SKIP
    try:
        steps = read_index(path)
    except XdmfError as e:
        print(f"FAIL: {path}: {e}")
        return 1
    h5 = h5py.File(os.path.join(os.path.dirname(path), "indent.h5"), "r")
    X, C = h5["geometry/vertices"][()], h5["topology/cells"][()]
    section = C.shape[1] in (3, 4) and bool(np.all(X[:, 1] == 0))  # an axisymmetric section, in y = 0
    kind = ({3: "triangle", 4: "quad"} if section else {4: "tetra", 8: "hexahedron"})[C.shape[1]]
    compared = 0
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        points, cells = reader.read_points_cells()
        if not np.array_equal(points, X):
            print("FAIL: meshio's points differ from /geometry/vertices")
            return 1
        if len(cells) != 1 or cells[0].type != kind or not np.array_equal(cells[0].data, C):
            blocks = [(b.type, b.data.shape) for b in cells]
            print(f"FAIL: meshio's cells {blocks} differ from /topology/cells ({kind})")
            return 1
        if reader.num_steps != len(steps):
            print(f"FAIL: meshio sees {reader.num_steps} steps, the index has {len(steps)}")
            return 1
        for k in range(reader.num_steps):
            t, point_data, cell_data = reader.read_data(k)
            if t != steps[k]["time"]:
                print(f"FAIL: step {k}: meshio's time {t}, the index says {steps[k]['time']}")
                return 1
            fields = {**point_data, **{name: blocks[0] for name, blocks in cell_data.items()}}
            if set(fields) != set(steps[k]["attributes"]):
                print(f"FAIL: step {k}: meshio reads {sorted(fields)}, the index has {sorted(steps[k]['attributes'])}")
                return 1
            for name, values in fields.items():
                if not np.array_equal(values, h5["fields/" + name][k]):
                    print(f"FAIL: step {k}: meshio's {name} differs from /fields/{name}[{k}]")
                    return 1
                compared += 1
    names = sorted(steps[0]["attributes"])
    print(f"ok: meshio {meshio.__version__} read {len(steps)} steps ({kind}, {len(X)} points), "
          f"times {steps[0]['time']:g} .. "
          f"{steps[-1]['time']:g}; {compared} fields equal to indent.h5: {', '.join(names)}")
    return 0


if __name__ == "__main__":
    codes = [main(path) for path in sys.argv[1:]]
    sys.exit(1 if 1 in codes else max(codes))
