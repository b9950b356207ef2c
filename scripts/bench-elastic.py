#!/usr/bin/env python3
"""Benchmark: elastic Q2 (or Q1) block (default ~207k dofs) with the default solver (CG + GAMG) on 1 and 2 ranks.
Prints a table of setup/solve times from -log_view stages and peak resident memory per rank.
A measurement, not a test: it never fails on a time.

  scripts/bench-elastic.py [--cells 20] [--ranks 1,2] [--build build] [-- extra indent options]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def stage_times(log):
    times = {}
    for m in re.finditer(r"^\s*\d+:\s+(\S+):\s+([0-9.e+-]+)", log, re.M):
        times[m.group(1)] = float(m.group(2))
    return times


def main():
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[:argv.index("--")] if "--" in argv else argv
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=int, default=20, help="hexahedra per side (Q2: 3 (2n+1)^3 dofs, Q1: 3 (n+1)^3)")
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--degree", type=int, default=2)
    ap.add_argument("--build", default=os.path.join(top, "build"))
    args = ap.parse_args(argv)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OPENBLAS_NUM_THREADS="1", HWLOC_HIDE_ERRORS="2")
    n = args.cells
    print(f"{'ranks':>5} {'dofs':>9} {'setup s':>8} {'solve s':>8} {'KSP its':>7} {'peak RSS/rank MB':>17}")
    for np_ in [int(r) for r in args.ranks.split(",")]:
        with tempfile.TemporaryDirectory() as tmp:
            cmd = ["mpiexec", "-n", str(np_), "/usr/bin/time", "-f", "maxrss_kb %M", os.path.join(args.build, "indent"),
                   "-dm_plex_box_faces", f"{n},{n},{n}", "-disc_degree", str(args.degree), "-domain_young", "100", "-domain_poisson", "0.3",
                   "-bc_fixed", "bottom", "-bc_displacement", "top:z=-0.01", "-output_fields", "0", "-log_view", *extra]
            run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
            if run.returncode:
                print(run.stdout[-3000:])
                return 1
            out = run.stdout
            dofs = int(re.search(r"(\d+) dofs", out).group(1))
            its = int(re.search(r"linear\s+(\d+)", out).group(1))
            rss = max(int(x) for x in re.findall(r"maxrss_kb (\d+)", out)) / 1024
            t = stage_times(out)
            print(f"{np_:>5} {dofs:>9} {t.get('IndSetup', float('nan')):>8.2f} {t.get('IndSolve', float('nan')):>8.2f} {its:>7} {rss:>17.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
