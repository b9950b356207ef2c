#!/usr/bin/env python3
"""The axisymmetric model against the 3D one on its section's mesh revolved (scripts/revolve-mesh.py):

  check_revolved_vs_section.py --indent BIN --mesh SECTION.geo|.msh --workdir DIR [--np 2] [--segments 12]
      [--tol 0.01] [--from 5] [--tol-all 0.035] [--geo-parameters k=v,...] [--options "..."]

indent runs the section (a .geo meshed with --geo-parameters; its mesh written to DIR/section/mesh.msh),
scripts/revolve-mesh.py turns that mesh through 90 degrees in --segments segments, and indent runs the same case
on the quarter solid (-bc_symmetry front,left).
Both have the same nodes in (r, z) on every meridian, so the loads differ by what the models do, not by their
meshes. Checked: the same depths, no step cut back in either (the load paths are the same), and at every depth
the 3D load within --tol-all of the section's, and within --tol from depth --from (nm) on. Exit 1 on a failed
check, 2 on bad arguments.
"""
import csv
import os
import subprocess
import sys

import meshcheck  # this folder

PROG = "check_revolved_vs_section.py"
HERE = os.path.dirname(os.path.abspath(__file__))
REVOLVE = os.path.join(HERE, "..", "scripts", "revolve-mesh.py")


def parse():
    ap = meshcheck.parser(PROG, __doc__, "the section's .geo (indent meshes it) or .msh")
    ap.add_argument("--segments", type=int, default=12, help="segments of the quarter turn (12)")
    ap.add_argument("--tol", type=float, default=0.01, help="relative load difference from --from on (0.01)")
    ap.add_argument("--from", dest="from_depth", type=float, default=5.0, help="depth from which --tol holds, nm (5)")
    ap.add_argument("--tol-all", type=float, default=0.035, help="relative load difference at every depth (0.035)")
    ap.add_argument("--geo-parameters", default="", help="the section .geo's -mesh_geo_parameters")
    ap.add_argument("--options", default="", help="the case's indent options, shared by both runs")
    args = ap.parse_args()
    meshcheck.check_common(PROG, args)
    if args.segments < 1 or not args.tol > 0 or not args.tol_all > 0:
        meshcheck.bad_input(PROG, "--segments must be >= 1 and --tol, --tol-all > 0")
    return args


def curve(out):
    with open(os.path.join(out, "load_displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    return ([float(r["depth_nm"]) for r in rows], [float(r["load_uN"]) for r in rows],
            sum(int(r["cutbacks"]) for r in rows))


def main():
    args = parse()
    options = args.options.split()
    sec_out, rev_out = os.path.join(args.workdir, "section"), os.path.join(args.workdir, "revolved")
    os.makedirs(args.workdir, exist_ok=True)
    geo = ["-mesh_geo_parameters", args.geo_parameters] if args.geo_parameters else []
    if meshcheck.run_indent(PROG, args, options + geo, sec_out) is None:
        return 1
    mesh3d = os.path.join(args.workdir, "revolved.msh")
    run = subprocess.run([sys.executable, REVOLVE, os.path.join(sec_out, "mesh.msh"), mesh3d,
                          "--segments", str(args.segments), "--angle", "90"], capture_output=True, text=True)
    print(run.stdout, end="")
    if run.returncode:
        print(run.stderr, end="")
        print("FAIL: revolve-mesh.py")
        return 1
    args.mesh = mesh3d
    if meshcheck.run_indent(PROG, args, options + ["-bc_symmetry", "front,left"], rev_out) is None:
        return 1
    hs, ps, cut_s = curve(sec_out)
    h3, p3, cut_3 = curve(rev_out)
    if hs != h3 or cut_s or cut_3:
        print(f"FAIL: the load paths differ: {len(hs)} and {len(h3)} steps, {cut_s} and {cut_3} cut back")
        return 1
    worst_all = worst_from = 0.0
    for h, a, b in zip(hs, ps, p3):
        if h <= 0 or a <= 0:
            continue
        d = b / a - 1
        print(f"depth {h:8.3f} nm: section {a:12.6g} uN, 3D {b:12.6g} uN, {100 * d:+7.3f}%")
        worst_all = max(worst_all, abs(d))
        if h >= args.from_depth - 1e-9:
            worst_from = max(worst_from, abs(d))
    ok_all, ok_from = worst_all <= args.tol_all, worst_from <= args.tol
    print(f"{'ok' if ok_all else 'FAIL'}: at every depth within {100 * worst_all:.3f}% "
          f"(tolerance {100 * args.tol_all:g}%)")
    print(f"{'ok' if ok_from else 'FAIL'}: from {args.from_depth:g} nm within {100 * worst_from:.3f}% "
          f"(tolerance {100 * args.tol:g}%)")
    return 0 if ok_all and ok_from else 1


if __name__ == "__main__":
    sys.exit(main())
