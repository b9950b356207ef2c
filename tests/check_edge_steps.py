#!/usr/bin/env python3
"""Load steps that follow the mesh (-load_edge_steps K): with K the contact's edge moves at most 1/K of the surface's
node spacing in a loading step (the summary's edge_advance_max), where the same run with uniform steps moved it
further; the steps end exactly at the largest depth; and they are the same on 1 and on --np ranks.

  check_edge_steps.py --mpiexec M --indent BIN --workdir D [--np 2] [--edge-steps 4] -- <indent options>
"""
import json
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def loading(d):
    c = np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)
    return c[c["t"] <= 1.0 + 1e-12]


def summary(d):
    with open(os.path.join(d, "summary.json")) as f:
        return json.load(f)


def main():
    ap, argv, options = indentrun.parser_and_options("check_edge_steps.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--edge-steps", type=float, default=4)
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    runs = {"uniform": (args.np, ["-load_edge_steps", "0"]),
            "limited": (args.np, ["-load_edge_steps", str(args.edge_steps)]),
            "limited_1rank": (1, ["-load_edge_steps", str(args.edge_steps)])}
    for name, (nranks, extra) in runs.items():
        if not indentrun.run(args, nranks, options + extra, os.path.join(args.workdir, name), name):
            return 1
    ok = True
    uni, lim = summary(os.path.join(args.workdir, "uniform")), summary(os.path.join(args.workdir, "limited"))
    bound = 1.0 / args.edge_steps
    print(f"edge advance per loading step: uniform {uni['edge_advance_max']:.4g}, limited {lim['edge_advance_max']:.4g}"
          f" node spacings (bound {bound:.4g}); P_max {uni['P_max_uN']:.6g} and {lim['P_max_uN']:.6g} uN")
    if not uni["edge_advance_max"] > bound:
        print("FAIL: the uniform steps already keep within the bound: the test checks nothing")
        ok = False
    if not lim["edge_advance_max"] <= bound * (1 + 1e-9):
        print("FAIL: the limited run's edge moved further than the bound")
        ok = False
    a, b = loading(os.path.join(args.workdir, "limited")), loading(os.path.join(args.workdir, "limited_1rank"))
    depth_max = float(options[options.index("-load_depth") + 1])
    print(f"loading steps: uniform {len(loading(os.path.join(args.workdir, 'uniform')))}, limited {len(a)}"
          f" ({args.np} ranks) and {len(b)} (1 rank)")
    if not (np.all(np.diff(a["depth_nm"]) > 0) and abs(a["depth_nm"][-1] - depth_max) <= 1e-12 * depth_max):
        print("FAIL: the limited steps do not rise to exactly -load_depth")
        ok = False
    if len(a) != len(b) or np.max(np.abs(a["depth_nm"] - b["depth_nm"])) > 1e-12 * depth_max:
        print(f"FAIL: the limited steps differ between {args.np} ranks and 1")
        ok = False
    print("ok" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
