#!/usr/bin/env python3
"""Copies the mesh and the named fields of an indent HDF5 file into a smaller, compressed reference.

  slim-reference.py RUN.h5 REFERENCE.h5 FIELD [FIELD ...]

scripts/h5compare.py reads the result like any output file; the regression tests compare only the
fields they name, so the reference needs no others.
"""
import sys

import h5py


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    src, dst, fields = sys.argv[1], sys.argv[2], sys.argv[3:]
    with h5py.File(src, "r") as a, h5py.File(dst, "w") as b:
        for name in ["geometry/vertices", "topology/cells"] + [f"fields/{f}" for f in fields]:
            if name not in a:
                print(f"slim-reference.py: '{src}' has no /{name}")
                return 2
            b.create_dataset(name, data=a[name][:], compression="gzip", compression_opts=9, shuffle=True)
        for k, v in a["/"].attrs.items():
            b["/"].attrs[k] = v
    return 0


if __name__ == "__main__":
    sys.exit(main())
