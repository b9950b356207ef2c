#!/usr/bin/env python3
"""The same command twice gives the same answer, bit for bit:

  check_reproducible.py --mpiexec M --indent BIN --workdir D [--np N] -- <indent options>

runs the command twice on N ranks and compares: load_displacement.csv cell by cell as text (but the
wall-time column), every dataset of indent.h5 with numpy's array_equal (NaN equal to NaN), and every
value of summary.json (but the wall time and the start time). Prints ok or FAIL per check; exit 1 on
a failed check.
"""
import csv
import json
import os
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

TIMES_CSV = {"seconds"}
TIMES_JSON = {"wall_time_s", "wall_seconds", "start_time", "options"}
check = indentrun.Checks()


def rows(d):
    with open(os.path.join(d, "load_displacement.csv"), newline="") as f:
        return [{k: v for k, v in r.items() if k not in TIMES_CSV} for r in csv.DictReader(f)]


def datasets(d):
    out = {}
    with h5py.File(os.path.join(d, "indent.h5"), "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out


def main():
    ap, mine, options = indentrun.parser_and_options("check_reproducible.py")
    ap.add_argument("--np", type=int, default=2)
    args = ap.parse_args(mine)
    dirs = [os.path.join(args.workdir, f"run{k}") for k in (1, 2)]
    for d in dirs:
        if not check(indentrun.run(args, args.np, options, d, d), f"run into {d}"):
            return 1
    a, b = rows(dirs[0]), rows(dirs[1])
    differ = [i + 1 for i, (x, y) in enumerate(zip(a, b)) if x != y]
    check(len(a) == len(b) and not differ,
          f"load_displacement.csv: {len(a)} and {len(b)} rows, differing rows {differ[:5]}")
    da, db = datasets(dirs[0]), datasets(dirs[1])
    check(da.keys() == db.keys(), f"indent.h5: the same {len(da)} datasets")
    bad = [n for n in da if n in db and not (da[n].shape == db[n].shape and
           (np.array_equal(da[n], db[n], equal_nan=True) if da[n].dtype.kind == "f" else np.array_equal(da[n], db[n])))]
    check(not bad, f"indent.h5: every dataset bitwise equal (differing: {bad[:5]})")
    sa, sb = (json.load(open(os.path.join(d, "summary.json"))) for d in dirs)
    diff = [k for k in sa if k not in TIMES_JSON and sa.get(k) != sb.get(k)]
    check(not diff, f"summary.json: every value equal but the times (differing: {diff[:5]})")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
