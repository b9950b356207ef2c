#!/usr/bin/env python3
"""Rank-count invariance: the same run on several rank counts gives load-displacement curves that agree
to a relative tolerance (of P_max) and identical contact-node counts at every step.

  check_rank_invariance.py --mpiexec M --indent BIN --workdir D --np 1,2,3,4 [--rtol 1e-8] -- <indent options>
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def main():
    ap, argv, options = indentrun.parser_and_options("check_rank_invariance.py")
    ap.add_argument("--np", default="1,2,3,4")
    ap.add_argument("--rtol", type=float, default=1e-8)
    args = ap.parse_args(argv)
    curves = {}
    for n in [int(x) for x in args.np.split(",")]:
        out = os.path.join(args.workdir, f"np{n}")
        if not indentrun.run(args, n, options, out, f"indent on {n} ranks"):
            return 1
        curves[n] = np.genfromtxt(os.path.join(out, "load_displacement.csv"), delimiter=",", names=True)
    ranks = sorted(curves)
    ref = curves[ranks[0]]
    failed = 0
    print(f"{'ranks':>5} {'points':>6} {'max |dP|/P_max':>15} {'max |dh| nm':>12} {'contact nodes':>14}")
    for n in ranks:
        c = curves[n]
        if len(c) != len(ref):
            print(f"{n:>5} {len(c):>6}  FAIL: {len(ref)} points on {ranks[0]} rank(s)")
            failed += 1
            continue
        dp = np.max(np.abs(c["load_uN"] - ref["load_uN"])) / np.max(np.abs(ref["load_uN"]))
        dh = np.max(np.abs(c["depth_nm"] - ref["depth_nm"]))
        same = bool(np.all(c["contact_nodes"] == ref["contact_nodes"]))
        bad = dp > args.rtol or dh > args.rtol * np.max(ref["depth_nm"]) or not same
        failed += bad
        print(f"{n:>5} {len(c):>6} {dp:>15.3e} {dh:>12.3e} {'identical' if same else 'DIFFER':>14}{'  FAIL' if bad else ''}")
    print("the curves agree on every rank count" if not failed else f"FAIL: {failed} rank count(s) differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
