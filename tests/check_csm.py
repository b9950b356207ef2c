#!/usr/bin/env python3
"""Hardness and modulus against depth (-csm_every): the unloading stiffness S of csm.csv.

  --hertz ESTAR: on an elastic half-space S at the last depth equals the slope of the computed load-depth
  curve there (central difference of two more runs at D -/+ 0.1 nm), E_r at every depth is E*, and S is
  2 E* a with a from the contact nodes (a quantised by the mesh);
  --film ESTAR: on a film on a stiffer substrate E_r starts near the film's E* and rises with depth.
H and E_r of a contact too few nodes wide (-op_min_contact_nodes) are empty cells: they must be the shallowest
rows only, with at least 3 rows resolved; the checks above are made on the resolved rows. With --expect-withheld
at least one row must be withheld.

  check_csm.py --mpiexec M --indent BIN --workdir D --depth D [--hertz ESTAR] [--film ESTAR] [--expect-withheld]
               -- <indent options>
"""
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def table(d, name):
    return np.atleast_1d(np.genfromtxt(os.path.join(d, name), delimiter=",", names=True))


def main():
    ap, argv, options = indentrun.parser_and_options("check_csm.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--depth", type=float, required=True)
    ap.add_argument("--hertz", type=float)
    ap.add_argument("--film", type=float)
    ap.add_argument("--expect-withheld", action="store_true")
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    run = os.path.join(args.workdir, "csm")
    if not indentrun.run(args, args.np, options + ["-load_depth", repr(args.depth), "-csm_every", "1"], run, "indent"):
        return 1
    c = table(run, "csm.csv")
    print(f"{'depth nm':>9} {'P uN':>10} {'S uN/nm':>10} {'h_c nm':>8} {'H GPa':>7} {'E_r GPa':>8} {'a nm':>7}")
    for r in c:
        print(f"{r['depth_nm']:9.3f} {r['load_uN']:10.4f} {r['S_uN_per_nm']:10.5f} {r['h_c_nm']:8.3f} "
              f"{r['H_GPa']:7.3f} "
              f"{r['E_r_GPa']:8.3f} {r['contact_radius_nm']:7.2f}")
    failed = 0
    resolved = np.isfinite(c["E_r_GPa"]) & np.isfinite(c["H_GPa"])
    withheld = int((~resolved).sum())
    print(f"H and E_r withheld at {withheld} of {len(c)} depths")
    if withheld and resolved[:withheld].any() or resolved.sum() < 3 or (args.expect_withheld and not withheld):
        print("FAIL: withheld rows are not the shallowest, fewer than 3 rows resolved, or none withheld where expected")
        return 1
    c = c[resolved]
    if args.hertz:
        loads = []
        # An elastic body pressed without friction has one equilibrium at each depth, whatever the path: one step
        # each (options later on the command line win)
        for dd in (-0.1, 0.1):
            out = os.path.join(args.workdir, f"depth{dd:+g}")
            if not indentrun.run(args, args.np, options + ["-load_depth", repr(args.depth + dd), "-load_steps", "1"],
                                 out, "indent"):
                return 1
            loads.append(table(out, "load_displacement.csv")["load_uN"][-1])
        slope = (loads[1] - loads[0]) / 0.2
        s = c["S_uN_per_nm"][-1]
        er = np.max(np.abs(c["E_r_GPa"] / args.hertz - 1))
        twoea = np.max(np.abs(c["S_uN_per_nm"] / (2e-3 * args.hertz * c["contact_radius_nm"]) - 1))
        print(f"S at {args.depth:g} nm: {s:.6g} uN/nm; slope of the load-depth curve there {slope:.6g}: "
              f"relative {s / slope - 1:+.2e}")
        print(f"E_r vs E* {args.hertz:g} GPa: largest relative difference {er:.3f}; S vs 2 E* a: largest {twoea:.3f}")
        failed += abs(s / slope - 1) > 5e-3
        failed += er > 0.06
        failed += twoea > 0.12
    if args.film:
        first, last = c["E_r_GPa"][0], c["E_r_GPa"][-1]
        print(f"E_r from {first:.1f} GPa (film's E* {args.film:g}) to {last:.1f} GPa at {c['depth_nm'][-1]:g} nm")
        failed += abs(first / args.film - 1) > 0.15
        failed += last < 1.25 * first
    print("the unloading stiffness checks out" if not failed else f"FAIL: {failed} check(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
