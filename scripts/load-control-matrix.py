#!/usr/bin/env python3
"""Load control against depth control on the paper's case: for each mesh, formulation, rank count and
prescribed force, a load-controlled run (-load_force F) and a depth-controlled run to the depth at which
the first reached F; prints a table: whether the run ended, the largest load's error, the load at the
end, Newton iterations per step under load and depth control (mean and largest), the ratio of their
Krylov iterations, and the wall time of each.

  scripts/load-control-matrix.py                               # coarse mesh, 20/150/300 uN, both formulations, 1-3 ranks
  scripts/load-control-matrix.py --mesh h_tip=10,h_far=250 --np 2 --force 20,300

Not a test: it asserts nothing; doc/load-control.md quotes its table.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(np_, opts, out):
    cmd = ["mpiexec", "-n", str(np_), os.path.join(TOP, "build", "indent"), "-options_file",
           os.path.join(TOP, "inputs", "berkovich.opts"), "-mesh_file", os.path.join(TOP, "inputs", "berkovich_half.geo"),
           "-output_fields", "0", "-quiet", "-output_dir", out, "-output_overwrite"] + opts
    t0 = time.time()
    p = subprocess.run(cmd, cwd=TOP, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.time() - t0
    rows = []
    curve = os.path.join(out, "load_displacement.csv")
    if os.path.exists(curve):
        with open(curve) as f:
            rows = list(csv.DictReader(f))
    return p.returncode, rows, seconds, p.stdout.strip().splitlines()[-1:] if p.returncode else []


def newton(rows):
    n = [int(r["newton"]) for r in rows]
    return (sum(n) / len(n), max(n)) if n else (0, 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh", default="h_tip=15,h_far=300", help="-mesh_geo_parameters")
    ap.add_argument("--force", default="20,150,300", help="forces, uN")
    ap.add_argument("--formulation", default="small,finite")
    ap.add_argument("--np", default="1,2,3")
    ap.add_argument("--limit", default="90", help="-load_depth, nm: the largest depth load control may reach")
    args = ap.parse_args()
    env_ok = shutil.which("mpiexec")
    if not env_ok:
        sys.exit("mpiexec not found: source scripts/mpi-env.sh")
    work = tempfile.mkdtemp(prefix="indent-lcm-")
    print(f"mesh {args.mesh}; -load_depth {args.limit} nm for load control; default steps (24 loading, unloading "
          "to zero force)")
    head = ("| formulation | ranks | F (uN) | ended | P_max - F (uN) | end load (uN) | steps | Newton/step load "
            "(mean, max) | Newton/step depth (mean, max) | Krylov load/depth | time load, depth (s) |")
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for form in args.formulation.split(","):
        for np_ in [int(x) for x in args.np.split(",")]:
            for force in [float(x) for x in args.force.split(",")]:
                base = ["-mesh_geo_parameters", args.mesh, "-formulation", form]
                out = os.path.join(work, "force")
                rc, rows, t_load, last = run(np_, base + ["-load_force", repr(force), "-load_depth", args.limit], out)
                if rc or not rows:
                    print(f"| {form} | {np_} | {force:g} | no (exit {rc}: {' '.join(last)[:80]}) | | | | | | | |")
                    continue
                loads = [float(r["load_uN"]) for r in rows]
                top = max(range(len(rows)), key=lambda i: loads[i])
                hmax = float(rows[top]["depth_nm"])
                rc_d, rows_d, t_depth, _ = run(np_, base + ["-load_depth", repr(hmax)], os.path.join(work, "depth"))
                nl, nd = newton(rows), newton(rows_d)
                kl = sum(int(r["linear"]) for r in rows)
                kd = sum(int(r["linear"]) for r in rows_d) if rows_d else 0
                print(f"| {form} | {np_} | {force:g} | yes | {loads[top] - force:.2e} | {loads[-1]:.2e} | {len(rows)} | "
                      f"{nl[0]:.2f}, {nl[1]} | {nd[0]:.2f}, {nd[1]} | {kl / kd if kd else float('nan'):.2f} | "
                      f"{t_load:.1f}, {t_depth:.1f} |", flush=True)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
