#!/usr/bin/env python3
"""The contact fields of indent.h5 tell the state the curve reports:

  /usr/bin/python3 tests/check_contact_fields.py --mpiexec M --indent I --workdir W --np 1,2 -- <indent options>

runs indent on each rank count (fields of every step written) and checks, at every written step, that
the vertices with contact_status 1 (stick) and 2 (slip) are as many as load_displacement.csv's stick
and slip columns of that step, that contact_status holds only 0, 1 and 2, that contact_pressure is
positive exactly where the status is not open (and zero elsewhere), and that the run had steps with
both sticking and slipping nodes (so that a field that called every node sticking cannot pass).
Prints ok or FAIL per check; exit status 0, 1 on a failed check.
"""
import csv
import os
import sys

import h5py
import numpy as np

import indentrun

check = indentrun.Checks()


def compare(out, label):
    with open(os.path.join(out, "load_displacement.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with h5py.File(os.path.join(out, "indent.h5"), "r") as f:
        status = f["fields/contact_status"][:, :, 0]
        pressure = f["fields/contact_pressure"][:, :, 0]
        steps = f["fields/step"][:].reshape(-1).astype(int)
    # each written step against its own row of the curve (-output_fields_every writes only some)
    by_step = {int(r["step"]): r for r in rows}
    if not check(len(steps) == status.shape[0] and all(s in by_step for s in steps),
                 f"{label}: field steps {list(steps)} are steps of the curve"):
        return
    check(set(np.unique(status)) <= {0.0, 1.0, 2.0}, f"{label}: contact_status only 0, 1, 2")
    mixed = 0
    for k, row in enumerate(by_step[s] for s in steps):
        stick, slip = int(np.sum(status[k] == 1)), int(np.sum(status[k] == 2))
        want = (int(row["stick"]), int(row["slip"]))
        check((stick, slip) == want, f"{label} step {row['step']}: field stick/slip {stick}/{slip}, "
              f"curve {want[0]}/{want[1]}")
        touching = status[k] > 0
        check(bool(np.all(pressure[k][touching] > 0)) and bool(np.all(pressure[k][~touching] == 0)),
              f"{label} step {row['step']}: pressure positive exactly at the {int(np.sum(touching))} nodes in contact")
        mixed += stick > 0 and slip > 0
    check(mixed > 0, f"{label}: {mixed} steps with both sticking and slipping nodes")


def main():
    ap, mine, options = indentrun.parser_and_options("check_contact_fields.py")
    ap.add_argument("--np", default="1,2")
    args = ap.parse_args(mine)
    for n in [int(v) for v in args.np.split(",")]:
        out = os.path.join(args.workdir, f"np{n}")
        os.makedirs(args.workdir, exist_ok=True)
        if check(indentrun.run(args, n, options, out, f"{n} rank(s)"), f"run on {n} rank(s)"):
            compare(out, f"{n} rank(s)")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
