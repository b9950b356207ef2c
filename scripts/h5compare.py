#!/usr/bin/env python3
"""Compare two indent HDF5 files field by field, independent of the rank count that wrote them.

Vertices are matched by coordinates and cells by centroids, so files written on different numbers of
ranks (different vertex orders) compare exactly. Steps are matched by their accepted step (/fields/step;
a file without it has every step): each of the run's steps must be one of the reference's, and both
must end on the same step (a reference may hold more, e.g. one written with -output_fields_every 1).
A field passes where |a - b| <= atol + rtol |b| everywhere (b: the reference). Exit status 0 when every
field passes, 1 otherwise, 2 on bad input.

  h5compare.py RUN.h5 REFERENCE.h5 [--field NAME:ATOL:RTOL ...] [--step N]
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from runfiles import InputError, field_steps  # noqa: E402  (this script's folder)



# Fields on the mesh vertices; all others are on the cells.
VERTEX_FIELDS = ("displacement", "contact_pressure", "contact_status")


def bad_input(message):
    print(f"h5compare: {message}", file=sys.stderr)
    sys.exit(2)


def matching_order(points, scale):
    """A permutation sorting points lexicographically after rounding to a tolerance of the mesh size."""
    key = np.round(points / scale, 7)
    return np.lexsort(key.T[::-1])


def load(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        bad_input(f"cannot open '{path}': {e}")
    for need in ("geometry/vertices", "topology/cells"):
        if need not in f:
            bad_input(f"'{path}' has no /{need}: not an indent output file")
    return f


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("reference")
    ap.add_argument("--field", action="append", help="NAME:ATOL:RTOL (repeatable); default: every field with 1e-10:1e-8")
    ap.add_argument("--step", type=int, default=None, help="output step to compare (default: every step)")
    args = ap.parse_args()

    a, b = load(args.run), load(args.reference)
    xa, xb = a["geometry/vertices"][:], b["geometry/vertices"][:]
    if xa.shape != xb.shape:
        print(f"FAIL mesh: {xa.shape[0]} vertices vs {xb.shape[0]} in the reference")
        return 1
    scale = max(np.ptp(xb, axis=0).max(), 1e-300)
    va, vb = matching_order(xa, scale), matching_order(xb, scale)
    geom = np.abs(xa[va] - xb[vb]).max() / scale
    if geom > 1e-9:
        print(f"FAIL mesh: vertex coordinates differ by {geom:.3e} (relative)")
        return 1
    ca, cb = a["topology/cells"][:], b["topology/cells"][:]
    if ca.shape != cb.shape:
        print(f"FAIL mesh: {ca.shape[0]} cells vs {cb.shape[0]} in the reference")
        return 1
    cena, cenb = xa[ca].mean(axis=1), xb[cb].mean(axis=1)
    oa, ob = matching_order(cena, scale), matching_order(cenb, scale)
    if np.abs(cena[oa] - cenb[ob]).max() / scale > 1e-9:
        print("FAIL mesh: cell centroids do not match")
        return 1

    try:
        sa, sb = field_steps(a, args.run), field_steps(b, args.reference)
    except InputError as e:
        bad_input(str(e))
    where = {int(k): i for i, k in enumerate(sb)}
    if any(int(k) not in where for k in sa) or (len(sa) and len(sb) and sa[-1] != sb[-1]):
        print(f"FAIL steps: the run's field steps {list(sa)} are not among the reference's {list(sb)} with the same last")
        return 1
    specs = args.field or [f"{name}:1e-10:1e-8" for name in b["fields"].keys() if name != "step"]
    failed = 0
    for spec in specs:
        try:
            name, atol, rtol = spec.split(":")
            atol, rtol = float(atol), float(rtol)
        except ValueError:
            bad_input(f"bad --field '{spec}' (want NAME:ATOL:RTOL)")
        if f"fields/{name}" not in b or f"fields/{name}" not in a:
            print(f"FAIL {name}: missing in {'reference' if f'fields/{name}' not in b else 'run'}")
            failed += 1
            continue
        fa, fb = a[f"fields/{name}"][:], b[f"fields/{name}"][:]
        if fa.shape[0] != len(sa) or fb.shape[0] != len(sb) or fa.shape[1:] != fb.shape[1:]:
            print(f"FAIL {name}: shape {fa.shape} vs {fb.shape} in the reference (field steps {len(sa)}, {len(sb)})")
            failed += 1
            continue
        steps = range(fa.shape[0]) if args.step is None else [args.step]
        for s in steps:
            pa, pb = (va, vb) if name in VERTEX_FIELDS else (oa, ob)
            da, db = fa[s][pa], fb[where[int(sa[s])]][pb]
            err = np.abs(da - db)
            bad = err > atol + rtol * np.abs(db)
            rel = err.max() / max(np.abs(db).max(), 1e-300)
            status = "FAIL" if bad.any() else "ok"
            print(f"{status} {name} step {int(sa[s])}: max abs diff {err.max():.3e}, relative to max {rel:.3e} (atol {atol:g}, rtol {rtol:g})")
            failed += bool(bad.any())
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
