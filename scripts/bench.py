#!/usr/bin/env python3
"""Benchmark suite: runs named cases of indent and prints (and saves as CSV and a Markdown table) per
case: dofs, ranks, load steps, Newton, outer and Krylov iterations (totals, per step, per Newton
iteration; the totals include the attempts cut back, whose share is given apart), wall time per step, the split of the run from -log_view (residual, Jacobian with the
return map, contact, preconditioner setup, Krylov, output) and the peak memory per rank and per dof.

  scripts/bench.py                       # the default set (fits a 2-core machine in ~10 min)
  scripts/bench.py --list                # every case with its size
  scripts/bench.py paper_h6 sphere_100k  # chosen cases
  scripts/bench.py --np 16 paper_h3      # a large case with more ranks (on a cluster node)
  scripts/bench.py --extra "-ksp_type bcgs" paper_h15   # a variant: extra options for every case

Not a test: it asserts nothing; doc/performance.md quotes its tables.
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PAPER = ["-options_file", "inputs/berkovich.opts"]
SPHERE_BLOCK = ["-domain_young", "100", "-domain_poisson", "0.3", "-domain_model", "plastic", "-domain_hardening", "linear",
                "-domain_yield", "1", "-domain_hardening_slope", "5", "-bc_fixed", "bottom", "-indenter_type", "sphere",
                "-load_steps", "1", "-load_unload", "0", "-output_fields", "0"]


def box(n, size=1000):
    return ["-dm_plex_box_faces", f"{n},{n},{n}", "-dm_plex_box_lower", f"0,0,{-size}",
            "-dm_plex_box_upper", f"{size},{size},0"]


def sphere(n):
    # A quarter of a sphere of radius 500 nm on the corner x = y = 0, 30 nm deep: symmetry planes
    return box(n) + SPHERE_BLOCK + ["-indenter_radius", "500", "-load_depth", "30", "-bc_symmetry", "left,front"]


def cube(n):
    # The plastic cube of the solver's scaling study: sphere_* at small strain (doc/performance.md)
    return sphere(n) + ["-formulation", "small"]


def weak(ranks):
    """The plastic cube with the same cells of 31.25 nm and the same dofs per rank (107,811) on 1, 2, 4,
    ... ranks: the block grows by 33 nodes in z, x, y in turn (doubling its nodes each time); the
    quarter sphere presses its corner as in cube_32."""
    assert ranks & (ranks - 1) == 0, "a power of 2"
    nodes = [33, 33, 33]
    k, axis = 1, 2
    while k < ranks:
        nodes[axis] *= 2
        axis = (axis + 1) % 3
        k *= 2
    faces = [m - 1 for m in nodes]
    size = [31.25 * f for f in faces]
    return (["-dm_plex_box_faces", ",".join(map(str, faces)), "-dm_plex_box_lower", f"0,0,{-size[2]:g}",
             "-dm_plex_box_upper", f"{size[0]:g},{size[1]:g},0"] + SPHERE_BLOCK +
            ["-indenter_radius", "500", "-load_depth", "30", "-bc_symmetry", "left,front", "-formulation", "small"])


def paper(h_tip, *extra):
    return PAPER + ["-mesh_geo_parameters", f"h_tip={h_tip},h_far={max(250, 20 * h_tip)}"] + list(extra)


def elastic(n):
    return box(n) + ["-domain_young", "100", "-domain_poisson", "0.3", "-bc_fixed", "bottom",
                     "-bc_displacement", "top:z=-10", "-output_fields", "0"]


# name: (options, default ranks, in the default set, what it is)
CASES = {
    "elastic_20": (elastic(20), 2, True, "elastic Q1 box, one solve"),
    "elastic_40": (elastic(40), 2, True, "elastic Q1 box, one solve"),
    "elastic_64": (elastic(64), 2, False, "elastic Q1 box, one solve"),
    "sphere_100k": (sphere(31), 1, True, "frictionless sphere into a plastic Q1 box, one load step"),
    "sphere_800k": (sphere(63), 2, False, "frictionless sphere into a plastic Q1 box, one load step"),
    "cube_32": (cube(32), 1, False, "sphere into a plastic Q1 cube, small strain, one load step (108k dofs)"),
    "cube_48": (cube(48), 1, False, "the same cube (353k dofs)"),
    "cube_64": (cube(64), 1, False, "the same cube (824k dofs)"),
    "weak_1": (weak(1), 1, False, "weak scaling: the cube at 108k dofs per rank, 1 rank"),
    "weak_2": (weak(2), 2, False, "weak scaling: 2 ranks, the block twice as deep"),
    "weak_4": (weak(4), 4, False, "weak scaling: 4 ranks"),
    "weak_8": (weak(8), 8, False, "weak scaling: 8 ranks"),
    "weak_16": (weak(16), 16, False, "weak scaling: 16 ranks"),
    "weak_32": (weak(32), 32, False, "weak scaling: 32 ranks"),
    "weak_64": (weak(64), 64, False, "weak scaling: 64 ranks"),
    "paper_h15": (paper(15), 2, True, "paper case, load and unload (h_tip 15)"),
    "paper_h10": (paper(10), 2, True, "paper case, load and unload"),
    "paper_h6": (paper(6), 2, False, "paper case, load and unload"),
    "paper_h4": (paper(4), 2, False, "paper case, load and unload"),
    "paper_h3": (paper(3), 2, False, "paper case, load and unload"),
    "sharp_h15": (paper(15, "-indenter_radius", "0"), 2, True, "paper case, sharp Berkovich"),
    "cube_corner_h15": (paper(15, "-indenter_type", "cube_corner", "-indenter_radius", "0", "-load_depth", "40"), 2, False,
                        "paper film, sharp cube corner, 40 nm"),
    "mu0_h15": (paper(15, "-contact_friction", "0"), 2, True, "paper case, frictionless"),
    "mu05_h15": (paper(15, "-contact_friction", "0.5"), 2, True, "paper case, friction 0.5"),
    "mu1_h15": (paper(15, "-contact_friction", "1"), 2, False, "paper case, friction 1.0"),
    # the axisymmetric model (doc/axisymmetric.md): 2D sections, a direct solve of the free rows
    "axi_sphere_h10": (["-options_file", "inputs/fit-sphere.opts"], 2, True,
                       "section: the fit's sphere model (h_tip 10, within 0.26% of h_tip 2.5)"),
    "axi_cone_h5": (["-options_file", "inputs/cone_axisymmetric.opts"], 2, False,
                    "section: the paper's film under the 70.3 deg cone, 5 nm cells, steps that follow them"),
}

# The split of the run from -log_view's nested (flame graph) output of rank 0: a column's time is
# the self time of every stack through any of its frames, so nested events count once.
SPLIT = {
    "residual": (["IndResidual"], []),
    "jacobian": (["IndJacobian"], []),
    "contact": (["IndContact"], []),
    "pc_setup": (["PCSetUp"], []),
    "krylov": (["KSPSolve"], ["PCSetUp"]),
    "output": (["IndOutputWrite"], []),
    "solve": (["SNESSolve"], []),
}


def log_split(path):
    stacks = []
    with open(path) as f:
        for line in f:
            parts = line.rsplit(" ", 1)
            if len(parts) == 2 and parts[1].strip().isdigit():
                stacks.append((parts[0].split(";"), int(parts[1]) * 1e-6))
    split = {}
    for col, (incl, excl) in SPLIT.items():
        split[col] = sum(t for frames, t in stacks
                         if any(e in frames for e in incl) and not any(e in frames for e in excl))
    return split


def run_case(name, opts, np, build, workdir, extra):
    out = os.path.join(workdir, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    logv = os.path.join(out, "log_view.txt")
    # each rank's peak resident memory (kB), from the kernel's accounting of the finished process
    rss = 'exec /usr/bin/time -f %M -o "$0/rss_rank$OMPI_COMM_WORLD_RANK.txt" "$@"'
    cmd = ["mpiexec", "-n", str(np), "sh", "-c", rss, out,
           os.path.join(build, "indent")] + opts + extra + ["-output_dir", out, "-output_overwrite", "-log_view", ":" + logv + ":ascii_flamegraph"]
    t0 = time.time()
    proc = subprocess.run(cmd, cwd=TOP, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    with open(os.path.join(out, "stdout.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n" + proc.stdout)
    row = {"case": name, "ranks": np, "ok": proc.returncode == 0, "wall_s": wall}
    m = re.search(r"(\d+) dofs", proc.stdout)
    row["dofs"] = int(m.group(1)) if m else 0
    steps = re.findall(r"^step\s+\d+.*$", proc.stdout, re.M)
    row["steps"] = len(steps)
    row["cutbacks"] = len(re.findall(r"rejected", proc.stdout))
    tot = {"newton": 0, "outer": 0, "linear": 0}
    for s in steps:
        for key, pat in (("newton", r"newton\s+(\d+)"), ("outer", r"uzawa\s+(\d+)"), ("linear", r"linear\s+(\d+)")):
            mm = re.search(pat, s)
            if mm:
                tot[key] += int(mm.group(1))
    if not tot["outer"]:
        tot["outer"] = row["steps"]
    # the attempts cut back cost iterations too: counted apart, and in the totals that the rates divide
    rej = {"newton": 0, "linear": 0}
    for s in re.findall(r"rejected after newton (\d+) linear (\d+)", proc.stdout):
        rej["newton"] += int(s[0])
        rej["linear"] += int(s[1])
    row["newton_rejected"], row["linear_rejected"] = rej["newton"], rej["linear"]
    tot["newton"] += rej["newton"]
    tot["linear"] += rej["linear"]
    row.update(tot)
    split = log_split(logv) if os.path.exists(logv) else {}
    for col in SPLIT:
        row[col + "_s"] = split.get(col, 0.0)
    # the answer, to compare variants and meshes
    row["P_max_uN"] = row["H_GPa"] = row["E_r_GPa"] = float("nan")
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summ = json.load(f)
        row["P_max_uN"] = summ.get("P_max_uN", float("nan"))
        # withheld (null) or absent: not a number
        row["H_GPa"] = summ.get("H_GPa") if summ.get("H_GPa") is not None else float("nan")
        row["E_r_GPa"] = summ.get("E_r_GPa") if summ.get("E_r_GPa") is not None else float("nan")
    except (OSError, ValueError):
        pass
    rss = []
    for r in range(np):
        p = os.path.join(out, f"rss_rank{r}.txt")
        if os.path.exists(p):
            with open(p) as f:
                vals = [int(x) for x in f.read().split() if x.isdigit()]
                if vals:
                    rss.append(vals[-1])
    row["peak_rss_mb"] = max(rss) / 1024 if rss else 0
    row["bytes_per_dof"] = sum(rss) * 1024 / row["dofs"] if rss and row["dofs"] else 0
    n = max(row["steps"], 1)
    row["newton_per_step"] = row["newton"] / n
    row["outer_per_step"] = row["outer"] / n
    row["krylov_per_newton"] = row["linear"] / max(row["newton"], 1)
    row["s_per_step"] = wall / n
    row["s_per_newton"] = row["solve_s"] / max(row["newton"], 1)
    row["jacobian_per_newton_ms"] = 1e3 * row["jacobian_s"] / max(row["newton"], 1)
    row["linear_per_newton_ms"] = 1e3 * (row["pc_setup_s"] + row["krylov_s"]) / max(row["newton"], 1)
    return row


COLUMNS = [("case", "case", "{}"), ("dofs", "dofs", "{:,}"), ("ranks", "ranks", "{}"), ("steps", "steps", "{}"),
           ("cutbacks", "cut", "{}"), ("newton", "Newton", "{}"), ("newton_rejected", "in cut", "{}"),
           ("newton_per_step", "/step", "{:.1f}"), ("outer", "outer", "{}"), ("outer_per_step", "/step", "{:.2f}"),
           ("linear", "Krylov", "{}"), ("linear_rejected", "in cut", "{}"),
           ("krylov_per_newton", "/Newton", "{:.1f}"), ("wall_s", "wall s", "{:.1f}"), ("s_per_step", "s/step", "{:.2f}"),
           ("solve_s", "solve s", "{:.1f}"), ("residual_s", "resid s", "{:.2f}"), ("jacobian_s", "Jac s", "{:.2f}"),
           ("contact_s", "contact s", "{:.2f}"),
           ("pc_setup_s", "PC setup s", "{:.1f}"), ("krylov_s", "Krylov s", "{:.1f}"), ("output_s", "output s", "{:.1f}"),
           ("jacobian_per_newton_ms", "Jac ms/Newton", "{:.1f}"), ("linear_per_newton_ms", "solve ms/Newton", "{:.1f}"),
           ("peak_rss_mb", "MB/rank", "{:.0f}"), ("bytes_per_dof", "B/dof", "{:.0f}"),
           ("P_max_uN", "P_max uN", "{:.2f}"), ("H_GPa", "H GPa", "{:.4f}"), ("E_r_GPa", "E_r GPa", "{:.2f}"), ("ok", "ok", "{}")]


def markdown(rows):
    lines = ["| " + " | ".join(c[1] for c in COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    for r in rows:
        lines.append("| " + " | ".join(fmt.format(r[key]) for key, _, fmt in COLUMNS) + " |")
    return "\n".join(lines)


def growth(rows):
    """Per family of cases (the name before its last '_': cube, sphere, paper, weak), how Krylov
    iterations per Newton iteration and the time per Newton iteration grow with the dofs against
    the family's smallest case: the ratio, and the exponent a of time per Newton ~ dofs^a."""
    import math
    families = {}
    for r in rows:
        families.setdefault(r["case"].rsplit("_", 1)[0], []).append(r)
    lines = []
    for fam, rs in families.items():
        rs = sorted((r for r in rs if r["ok"] and r["newton"]), key=lambda r: (r["dofs"], r["ranks"]))
        if len(rs) < 2:
            continue
        base = rs[0]
        for r in rs:
            kr = r["krylov_per_newton"] / base["krylov_per_newton"]
            a = (math.log(r["s_per_newton"] / base["s_per_newton"]) / math.log(r["dofs"] / base["dofs"])
                 if r["dofs"] != base["dofs"] and r["s_per_newton"] > 0 and base["s_per_newton"] > 0 else float("nan"))
            lines.append(f"| {r['case']} | {r['dofs']:,} | {r['ranks']} | {r['dofs'] // r['ranks']:,} | "
                         f"{r['krylov_per_newton']:.1f} | {kr:.2f} | {r['s_per_newton']:.3f} | {a:.2f} |")
    if not lines:
        return ""
    head = ["| case | dofs | ranks | dofs/rank | Krylov/Newton | vs smallest | solve s/Newton | exponent |",
            "|---|---|---|---|---|---|---|---|"]
    return "\n".join(head + lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", help="case names (default: the default set)")
    ap.add_argument("--list", action="store_true", help="list the cases")
    ap.add_argument("--np", type=int, help="ranks for every case (default: each case's own)")
    ap.add_argument("--build", default=os.path.join(TOP, "build"), help="build directory with indent")
    ap.add_argument("--extra", default="", help="extra indent options for every case")
    ap.add_argument("--out", default=os.path.join(TOP, "bench-results"), help="directory for the CSV and Markdown table")
    ap.add_argument("--keep", action="store_true", help="keep each run's output directory")
    args = ap.parse_args()
    if args.list:
        for k, (o, np, dflt, what) in CASES.items():
            print(f"{k:16s} {'default' if dflt else '       '}  {np} rank(s)  {what}")
        return 0
    names = args.cases or [k for k, v in CASES.items() if v[2]]
    for n in names:
        if n not in CASES:
            sys.exit(f"bench.py: unknown case '{n}' (see --list)")
    os.environ.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
                       "OMPI_MCA_rmaps_base_oversubscribe": "1", "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"})
    os.makedirs(args.out, exist_ok=True)
    workdir = tempfile.mkdtemp(prefix="indent-bench-")
    rows = []
    for n in names:
        opts, np, _, what = CASES[n]
        row = run_case(n, opts, args.np or np, args.build, workdir, args.extra.split())
        rows.append(row)
        print(markdown([row]).splitlines()[-1] if len(rows) > 1 else markdown([row]), flush=True)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    with open(os.path.join(args.out, f"bench-{stamp}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    grow = growth(rows)
    if grow:
        print("\nGrowth with the dofs (time per Newton iteration ~ dofs^exponent, against each family's smallest):")
        print(grow)
    with open(os.path.join(args.out, f"bench-{stamp}.md"), "w") as f:
        f.write(markdown(rows) + "\n" + ("\n" + grow + "\n" if grow else ""))
    print(f"\nsaved {args.out}/bench-{stamp}.csv and .md" + ("" if args.keep else ""))
    if args.keep:
        print(f"run directories in {workdir}")
    else:
        shutil.rmtree(workdir, ignore_errors=True)
    return 0 if all(r["ok"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
