#!/usr/bin/env python3
"""Checks the last step of an indent output for a plastic film (z > ZFILM) on an elastic substrate:
every substrate cell has zero plastic strain and never yielded, and the film has yielded.

  check_regions.py indent.h5 ZFILM
"""
import sys

import h5py
import numpy as np


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, zfilm = sys.argv[1], float(sys.argv[2])
    with h5py.File(path, "r") as f:
        x = f["geometry/vertices"][:]
        cells = f["topology/cells"][:]
        p = f["fields/plastic_strain"][-1, :, 0]
        y = f["fields/yielding"][-1, :, 0]
    zc = x[cells][:, :, 2].mean(axis=1)
    sub, film = zc < zfilm, zc > zfilm
    print(f"substrate: {sub.sum()} cells, max plastic strain {p[sub].max():.3e}, max yielding {y[sub].max():.3e}")
    print(f"film: {film.sum()} cells, max plastic strain {p[film].max():.3e}, yielding cells {(y[film] > 0).sum()}")
    ok = sub.sum() > 0 and film.sum() > 0 and p[sub].max() == 0 and y[sub].max() == 0 and p[film].max() > 0
    print("ok" if ok else "FAIL: the elastic substrate yielded or the plastic film did not")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
