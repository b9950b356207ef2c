#!/usr/bin/env python3
"""Validation of the contact against Hertz (sphere) and Sneddon (70.3 deg cone), for a series of
graded quarter-block meshes: prints, per mesh, the largest relative error of P(h) over
h/R = 0.02 .. 0.1 (sphere R = 1000 nm) and h = 20 .. 100 nm (cone), with both gap definitions.
A table of figures, not a test: run it after changing the contact or the elements.

  /usr/bin/python3 scripts/validate-contact.py [--build build] [--np 2] [--quick]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

E, NU, R = 100.0, 0.3, 1000.0
ES = E / (1 - NU * NU)
ALPHA = math.radians(70.3)


def run(args, mesh, degree, indenter, gap, out):
    cmd = ["mpiexec", "-n", str(args.np), os.path.join(args.build, "indent"), "-mesh_file", mesh, "-disc_degree", str(degree),
           "-domain_young", str(E), "-domain_poisson", str(NU), "-bc_symmetry", "left,front", "-bc_fixed", "bottom",
           "-load_depth", "100", "-load_steps", "5", "-load_unload", "0", "-contact_gap", gap, "-quiet", "-output_fields", "0",
           "-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps", "-output_dir", out, "-output_overwrite"] + indenter
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
    worst = 0.0
    with open(os.path.join(out, "load_displacement.csv")) as f:
        for r in csv.DictReader(f):
            h, p = float(r["depth_nm"]), float(r["load_uN"]) * 1e3
            exact = 4 / 3 * ES * math.sqrt(R) * h ** 1.5 if indenter[1] == "sphere" else 2 / math.pi * ES * math.tan(ALPHA) * h * h
            worst = max(worst, abs(p / exact - 1))
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="only the two coarsest meshes of each degree")
    args = ap.parse_args()
    geo = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "meshes", "hertz_block.geo")
    # (degree, cells per edge, progression): L = 20 R throughout
    series = [(1, 14, 1.55), (1, 18, 1.45), (1, 24, 1.32), (2, 8, 2.05), (2, 10, 1.8), (2, 13, 1.55)]
    if args.quick:
        series = [s for s in series if s[1] in (14, 18, 8, 10)]
    tmp = tempfile.mkdtemp(prefix="indent-validate-")
    print(f"{'elements':>9} {'N':>3} {'ratio':>6} {'smallest nm':>11} {'dofs':>7} | {'Hertz ref':>9} {'Hertz cur':>9} | {'Sneddon ref':>11} {'Sneddon cur':>11}")
    for degree, n, ratio in series:
        L = 20 * R
        mesh = os.path.join(tmp, f"block_{n}_{ratio}.msh")
        subprocess.run(["gmsh", "-3", geo, "-setnumber", "L", str(L), "-setnumber", "N", str(n), "-setnumber", "r", str(ratio), "-format", "msh41", "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
        h1 = L * (ratio - 1) / (ratio ** n - 1)
        dofs = 3 * (degree * n + 1) ** 3
        errs = []
        for ind in (["-indenter_type", "sphere", "-indenter_radius", str(R)], ["-indenter_type", "cone"]):
            for gap in ("reference", "current"):
                errs.append(100 * run(args, mesh, degree, ind, gap, os.path.join(tmp, "out")))
        print(f"{'Q%d hex' % degree:>9} {n:>3} {ratio:>6} {h1:>11.1f} {dofs:>7} | {errs[0]:>8.2f}% {errs[1]:>8.2f}% | {errs[2]:>10.2f}% {errs[3]:>10.2f}%", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
