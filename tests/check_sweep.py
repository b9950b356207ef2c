#!/usr/bin/env python3
"""Tests of scripts/sweep.py.

  check_sweep.py dry-run --sweep scripts/sweep.py --workdir DIR
  check_sweep.py collect --sweep scripts/sweep.py --workdir DIR
  check_sweep.py run --sweep scripts/sweep.py --workdir DIR --indent BIN --mpiexec MPIEXEC [-- tiny case options]

dry-run: a 2x2 sweep with --dry-run writes nothing and prints one command per run, named and
ordered as expected; generated for real, each directory records its options; finished, interrupted
and stopped runs get no command, -restart and -output_overwrite; --slurm and --pbs scripts carry
the ranks and the options (read back through bash); values holding commas; a changed --base is
refused. collect: fabricated summary.json files (finished, another status, a checkpoint only, no
output) become one CSV, rows in numeric order of the varied values, the same on a second call.
run: a real sweep of two tiny runs (-load_steps 2 and 3), then the same command again, which must
start no indent; then a third value (-load_steps 12), interrupted by SIGUSR1 to the sweep after its
second step (checkpoint, status 75) and continued by the next --run with -restart.
"""
import argparse
import csv
import io
import json
import os
import shlex
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import indentrun  # noqa: E402

FAILURES = []


def check(cond, what):
    print(("ok: " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        FAILURES.append(what)
    return cond


def sweep(args, cwd, ok=True, env=None):
    cmd = [sys.executable, ARGS.sweep, *args]
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env=env)
    if ok and p.returncode != 0:
        print(f"command failed ({p.returncode}): {shlex.join(cmd)}\n{p.stdout}{p.stderr}")
        sys.exit(1)
    return p


def parse_dry_run(text):
    """[(name, state, command or None)] from the '# NAME: STATE' and 'cd DIR && COMMAND' lines."""
    runs = []
    for line in text.splitlines():
        if line.startswith("# "):
            name, _, state = line[2:].rpartition(": ")
            runs.append([name, state, None])
        elif line.startswith("cd "):
            runs[-1][2] = shlex.split(line.split(" && ", 1)[1])
    return runs


def test_dry_run(work):
    base = "-options_file inputs/berkovich.opts -quiet"
    out = os.path.join(work, "sw")
    common = ["--base", base, "--vary", "contact_friction=0,0.3", "--vary", "film_yield=0.2,0.3", "--out", out,
              "--np", "2", "--indent", "/opt/fake/indent"]
    p = sweep([*common, "--run", "--dry-run"], work)
    check(not os.path.exists(out), "--dry-run writes nothing")
    runs = parse_dry_run(p.stdout)
    names = ["contact_friction=0,film_yield=0.2", "contact_friction=0,film_yield=0.3",
             "contact_friction=0.3,film_yield=0.2", "contact_friction=0.3,film_yield=0.3"]
    check([r[0] for r in runs] == names, f"four runs named and ordered as NAME=VALUE,...: {[r[0] for r in runs]}")
    check(all(r[1] == "not run" for r in runs), "all four not run yet")
    ok = True
    for (name, _, cmd), (mu, y) in zip(runs, [("0", "0.2"), ("0", "0.3"), ("0.3", "0.2"), ("0.3", "0.3")]):
        want = ["mpiexec", "-n", "2", "/opt/fake/indent", "-options_file", "inputs/berkovich.opts", "-quiet",
                "-contact_friction", mu, "-film_yield", y, "-output_dir", os.path.join(out, name)]
        ok &= check(cmd == want, f"command of {name}: {shlex.join(cmd or [])}")
    check(f"cd {shlex.quote(work)} &&" in p.stdout, "commands run in the directory the sweep was made in")

    # Generated: directories with their records and the sweep's own record.
    p = sweep(common, work)
    for name in names:
        rec_path = os.path.join(out, name, "sweep-run.json")
        if check(os.path.isfile(rec_path), f"{name}/sweep-run.json written"):
            with open(rec_path) as f:
                rec = json.load(f)
            mu, y = name.split(",")[0].split("=")[1], name.split(",")[1].split("=")[1]
            check(rec["args"] == ["-options_file", "inputs/berkovich.opts", "-quiet", "-contact_friction", mu,
                                  "-film_yield", y] and rec["vary"] == {"contact_friction": mu, "film_yield": y},
                  f"{name}: recorded options {rec['args']}")
    check(os.path.isfile(os.path.join(out, "sweep.json")), "sweep.json written")

    # States: finished (skipped), interrupted (-restart), stopped (-output_overwrite), not run.
    with open(os.path.join(out, names[0], "summary.json"), "w") as f:
        json.dump({"P_max_uN": 1.0, "status": "finished"}, f)
    with open(os.path.join(out, names[1], "checkpoint.h5"), "w") as f:
        f.write("x")
    with open(os.path.join(out, names[2], "load_displacement.csv"), "w") as f:
        f.write("step,t\n")
    p = sweep(["--out", out, "--run", "--dry-run"], work)   # the sweep read back from sweep.json
    runs = {r[0]: r for r in parse_dry_run(p.stdout)}
    check(runs[names[0]][1] == "finished (skipped)" and runs[names[0]][2] is None, "finished run: no command")
    d1 = os.path.join(out, names[1])
    c1 = runs[names[1]][2] or []
    check(runs[names[1]][1] == "interrupted" and c1[-2:] == ["-restart", d1] and "-output_overwrite" not in c1,
          f"checkpoint: -restart {d1}")
    c2 = runs[names[2]][2] or []
    check(runs[names[2]][1] == "incomplete" and c2[-1] == "-output_overwrite" and "-restart" not in c2,
          "output without checkpoint: -output_overwrite")
    c3 = runs[names[3]][2] or []
    check(c3[-2:] == ["-output_dir", os.path.join(out, names[3])], "not run: a plain command")
    check("-n" in c1 and c1[c1.index("-n") + 1] == "2", "--np read back from sweep.json")

    # Job scripts: the ranks, the run's output directory and options, as bash reads them.
    for kind in ("slurm", "pbs"):
        p = sweep(["--out", out, f"--{kind}", "--walltime", "02:30:00"], work)
        path = os.path.join(out, "jobs", f"{names[3]}.{kind}.sh")
        if not check(os.path.isfile(path), f"--{kind} wrote {path}"):
            continue
        check(len([f for f in os.listdir(os.path.join(out, "jobs")) if f.endswith(f".{kind}.sh")]) == 4,
              f"--{kind}: one script per run")
        check(subprocess.run(["bash", "-n", path]).returncode == 0, f"--{kind} script passes bash -n")
        text = open(path).read()
        if kind == "slurm":
            check("#SBATCH --ntasks=2\n" in text and "#SBATCH --time=02:30:00\n" in text, "#SBATCH ranks and time")
            check("#SBATCH --signal=B:USR1@300\n" in text, "the signal line kept")
        else:
            check("#PBS -l select=1:ncpus=2:mpiprocs=2\n" in text and "#PBS -l walltime=02:30:00\n" in text,
                  "#PBS ranks and wall time")
        show = ('eval "$(sed -n "/^# ---- run settings (begin)/,/^# ---- run settings (end)/p" "$1")"; '
                'printf "%s\\n" "$OUTPUT_DIR" "$JOB_SCRIPT" "${LAUNCHER[*]}" "${INDENT_OPTIONS[@]}"')
        got = subprocess.run(["bash", "-c", show, "x", path], capture_output=True, text=True).stdout.splitlines()
        want = [os.path.join(out, names[3]), path, "srun" if kind == "slurm" else "mpiexec -n 2",
                "-options_file", "inputs/berkovich.opts", "-quiet", "-contact_friction", "0.3", "-film_yield", "0.3"]
        check(got == want, f"--{kind} settings read by bash: {got}")

    # Values holding commas, separated by ';'.
    p = sweep(["--base", base, "--vary", "mesh_geo_parameters=h_tip=10,h_far=250;h_tip=6,h_far=250",
               "--out", os.path.join(work, "geo"), "--dry-run"], work)
    runs = parse_dry_run(p.stdout)
    check([r[0] for r in runs] == ["mesh_geo_parameters=h_tip=10,h_far=250", "mesh_geo_parameters=h_tip=6,h_far=250"]
          and runs[1][2][runs[1][2].index("-mesh_geo_parameters") + 1] == "h_tip=6,h_far=250",
          "';' separates values that hold commas")

    # Another --base over existing run directories is refused.
    p = sweep(["--base", "-options_file inputs/sphere.opts", "--vary", "contact_friction=0,0.3",
               "--vary", "film_yield=0.2,0.3", "--out", out], work, ok=False)
    check(p.returncode != 0 and "made with other options" in p.stderr, "changed --base refused")


def summary(P, H, E, status="finished", ranks=2):
    """A summary.json as indent writes it (keys from src/analysis/summary.c and the provenance keys)."""
    return {"indenter": "berkovich", "op_fraction": 0.5, "op_epsilon": 0.75, "op_beta": 1.034,
            "P_max_uN": P, "h_max_nm": 60, "final_depth_nm": 21.5, "final_load_uN": 0, "H_GPa": H,
            "E_r_GPa": E * 1.1, "E_GPa": E, "steps": 224, "cutbacks": 0, "newton": 1200,
            "wall_time_s": 401.25, "options": "-contact_friction 0.1 -film_yield 0.3 -load_depth 60",
            "indent_version": "0.1.0", "git_commit": "0a00f5a", "petsc_version": "Petsc Release Version 3.18.5",
            "ranks": ranks, "start_time": "2026-11-23T17:00:00", "wall_seconds": 401.3, "status": status}


def test_collect(work):
    out = os.path.join(work, "sw")
    # Values given out of order, one pair (6 < 12) sorting otherwise as text.
    sweep(["--base", "-options_file inputs/berkovich.opts", "--vary", "contact_friction=0.3,0.1",
           "--vary", "load_steps=12,6", "--out", out], work)
    files = {"contact_friction=0.1,load_steps=6": summary(187.6, 2.01, 71.2),
             "contact_friction=0.1,load_steps=12": summary(188.92, 2.023, 70.5, ranks=4),
             "contact_friction=0.3,load_steps=6": summary(150.5, 1.95, 69.0, status="failed")}
    for name, s in files.items():
        with open(os.path.join(out, name, "summary.json"), "w") as f:
            json.dump(s, f, indent=2)
    with open(os.path.join(out, "contact_friction=0.3,load_steps=12", "checkpoint.h5"), "w") as f:
        f.write("x")
    sweep(["--out", out, "--collect"], work)
    path = os.path.join(out, "summary.csv")
    if not check(os.path.isfile(path), "summary.csv written"):
        return
    text = open(path).read()
    rows = list(csv.reader(io.StringIO(text)))
    header = rows[0]
    keys = [k for k in summary(0, 0, 0) if k not in ("options", "status")]
    check(header == ["run", "contact_friction", "load_steps", "status", *keys],
          f"header: run, the varied options, status, the summary's scalars in its order: {header}")
    check("options" not in header, "the options string is not a column")
    order = [r[0] for r in rows[1:]]
    check(order == ["contact_friction=0.1,load_steps=6", "contact_friction=0.1,load_steps=12",
                    "contact_friction=0.3,load_steps=6", "contact_friction=0.3,load_steps=12"],
          f"rows in numeric order of the varied values: {order}")
    byrun = {r[0]: dict(zip(header, r)) for r in rows[1:]}
    r = byrun["contact_friction=0.1,load_steps=6"]
    check(r["status"] == "finished" and r["contact_friction"] == "0.1" and r["load_steps"] == "6",
          "a finished run's status and varied values")
    check(r["P_max_uN"] == "187.6" and r["H_GPa"] == "2.01" and r["steps"] == "224" and r["indenter"] == "berkovich",
          "its summary values as written")
    check(byrun["contact_friction=0.1,load_steps=12"]["ranks"] == "4", "per-run values kept apart")
    check(byrun["contact_friction=0.3,load_steps=6"]["status"] == "failed", "a summary's own status")
    r = byrun["contact_friction=0.3,load_steps=12"]
    check(r["status"] == "interrupted" and r["P_max_uN"] == "", "a run with only a checkpoint: interrupted, no values")
    sweep(["--out", out, "--collect"], work)
    check(open(path).read() == text, "a second --collect writes the same file")
    p = sweep(["--out", out, "--collect", "--dry-run"], work)
    check(p.stdout == text, "--collect --dry-run prints the CSV")
    # A new value: the new runs are listed in their place, one not run, one that --run started and
    # that wrote nothing (only the sweep's log).
    sweep(["--base", "-options_file inputs/berkovich.opts", "--vary", "contact_friction=0.3,0.1,0.2",
           "--vary", "load_steps=12,6", "--out", out], work)
    with open(os.path.join(out, "contact_friction=0.2,load_steps=12", "sweep-run.log"), "w") as f:
        f.write("# mpiexec ...\nindent: error: -film_yield must be > 0\n")
    sweep(["--out", out, "--collect"], work)
    rows = list(csv.reader(open(path)))
    check([r[0] for r in rows[1:]][2:4] == ["contact_friction=0.2,load_steps=6", "contact_friction=0.2,load_steps=12"]
          and rows[3][3] == "not run" and rows[4][3] == "failed",
          f"runs added later sorted in, not run or failed: {[r[3] for r in rows[3:5]]}")


def read_json(path):
    with open(path) as f:
        return json.load(f)


def test_run(work):
    help_text = subprocess.run([ARGS.indent, *ARGS.options, "-help", "-output_dir", os.path.join(work, "help")],
                               capture_output=True, text=True).stdout
    if not check("checkpoint_every" in help_text, "indent -help lists -checkpoint_every"):
        return
    out = os.path.join(work, "sw")
    base = ["--base", shlex.join(ARGS.options), "--out", out, "--np", "2", "--indent", ARGS.indent,
            "--mpiexec", ARGS.mpiexec]
    vary2 = ["--vary", "load_steps=2,3"]
    t0 = time.time()
    p = sweep([*base, *vary2, "--run", "--collect"], work, ok=False)
    print(p.stdout + p.stderr)
    check(p.returncode == 0, f"first --run exits 0 ({time.time() - t0:.1f} s)")
    names = ["load_steps=2", "load_steps=3"]
    mtimes = {}
    for name in names:
        sj = os.path.join(out, name, "summary.json")
        if check(os.path.isfile(sj), f"{name}: summary.json"):
            check(read_json(sj).get("status") == "finished", f"{name}: status finished")
            mtimes[name] = os.stat(sj).st_mtime_ns
    t0 = time.time()
    p = sweep([*base, *vary2, "--run"], work, ok=False)
    print(p.stdout + p.stderr)
    check(p.returncode == 0 and p.stdout.count("finished, skipped") == 2,
          f"second --run skips both finished runs ({time.time() - t0:.1f} s)")
    for name in names:
        sj = os.path.join(out, name, "summary.json")
        check(os.path.isfile(sj) and os.stat(sj).st_mtime_ns == mtimes.get(name), f"{name}: not run again")
        log = open(os.path.join(out, name, "sweep-run.log")).read()
        check(sum(line.startswith("# ") for line in log.splitlines()) == 1, f"{name}: indent started once")

    # A third value with more steps, interrupted after its first ones and continued.
    vary3 = ["--vary", "load_steps=2,3,12"]
    new = os.path.join(out, "load_steps=12")
    proc = subprocess.Popen([sys.executable, ARGS.sweep, *base, *vary3, "--run"], cwd=work,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    curve = os.path.join(new, "load_displacement.csv")
    deadline = time.time() + 120
    while time.time() < deadline and proc.poll() is None:
        if os.path.exists(curve) and len(open(curve).read().splitlines()) >= 3:
            break
        time.sleep(0.05)
    check(len(indentrun.signal_mid_run(proc, signal.SIGUSR1)) == 2, "SIGUSR1 sent while the run's 2 ranks ran")
    text, _ = proc.communicate(timeout=300)
    print(text)
    check(proc.returncode == 75, f"SIGUSR1 to the sweep: status 75 (got {proc.returncode})")
    check(os.path.isfile(os.path.join(new, "checkpoint.h5")), "the interrupted run left checkpoint.h5")
    s = os.path.join(new, "summary.json")
    check(not os.path.exists(s) or read_json(s).get("status") != "finished", "the interrupted run is not finished")
    p = sweep([*base, *vary3, "--run", "--collect"], work, ok=False)
    print(p.stdout + p.stderr)
    check(p.returncode == 0 and "continuing from its checkpoint" in p.stdout, "the next --run continues it")
    log = open(os.path.join(new, "sweep-run.log")).read()
    starts = [line for line in log.splitlines() if line.startswith("# ")]
    check(len(starts) == 2 and f"-restart {shlex.quote(new)}" in starts[1] and "-restart" not in starts[0],
          "its second start has -restart")
    check(os.path.isfile(s) and read_json(s).get("status") == "finished", "the continued run finished")
    rows = list(csv.reader(open(os.path.join(out, "summary.csv"))))
    check([r[0] for r in rows[1:]] == ["load_steps=2", "load_steps=3", "load_steps=12"]
          and all(r[2] == "finished" for r in rows[1:]), "summary.csv: three finished runs")


def main():
    global ARGS
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=["dry-run", "collect", "run"])
    ap.add_argument("--sweep", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--indent")
    ap.add_argument("--mpiexec", default="mpiexec")
    argv = sys.argv[1:]
    cut = argv.index("--") if "--" in argv else len(argv)
    ARGS = ap.parse_args(argv[:cut])
    ARGS.options = argv[cut + 1:]   # run: the tiny case's options
    ARGS.sweep = os.path.abspath(ARGS.sweep)
    work = os.path.abspath(ARGS.workdir)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"dry-run": test_dry_run, "collect": test_collect, "run": test_run}[ARGS.test](work)
    if FAILURES:
        print(f"{len(FAILURES)} check(s) failed")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
