#!/usr/bin/env python3
"""Parameter sweeps of indent: one run directory per combination of the varied options, run locally
one after another (finished runs skipped, interrupted ones continued from their checkpoint), or one
Slurm or PBS job script per run, and one CSV of every run's summary.json. doc/cluster.md.

  scripts/sweep.py --base "-options_file inputs/berkovich.opts" --vary contact_friction=0,0.1,0.3 \\
      --vary film_yield=0.2,0.3 --out sweeps/friction --np 2 [--run | --slurm | --pbs] [--collect] [--dry-run]
  scripts/sweep.py --out sweeps/friction --run --collect     # the same sweep again (from its sweep.json)
  scripts/sweep.py --base "-options_file inputs/cone_axisymmetric.opts" --vary film_yield=0.2,0.3 --out sweeps/cone \
      --np 2 --run --collect     # a cone on the axisymmetric section: about a minute a run (doc/axisymmetric.md)

--vary NAME=V1,V2,...: the values of option -NAME (separate them with ';' when they hold commas:
--vary "mesh_geo_parameters=h_tip=10,h_far=250;h_tip=6,h_far=250"). The runs are every combination,
the first --vary the slowest, in directories OUT/NAME1=V1,NAME2=V2 that hold indent's output and
sweep-run.json (the run's options). The varied options come after --base on the command line, so
they override an options file's. Relative paths in the options are taken from the directory the
sweep was first made in (recorded in OUT/sweep.json).

--run: runs the unfinished runs one after another with MPIEXEC -n NP INDENT (output in
OUT/RUN/sweep-run.log); a run with checkpoint.h5 continues with -restart, one that stopped without
checkpoint starts again (-output_overwrite). Ctrl-C, SIGTERM or SIGUSR1 make the current run
checkpoint (SIGUSR1 to mpiexec) and stop the sweep with status 75: run the same command to go on.
--slurm, --pbs: write OUT/jobs/RUN.slurm.sh or .pbs.sh from scripts/jobs/*-paper-case.sh (they
checkpoint before the time limit and resubmit themselves); nothing is submitted.
--collect: OUT/summary.csv, one row per run in the order of the varied values: run, the varied
options, status (finished; interrupted: a checkpoint; incomplete: output without summary or
checkpoint; failed: started by --run, no output; not run; or summary.json's own status), then
every scalar of summary.json.
--dry-run: prints the commands (and the CSV) and writes nothing.
A run whose indenter is of revolution (sphere, cone, flat, table) on one of inputs/' parametric 3D meshes runs on the
axisymmetric section of the same parameters (scripts/sectionmodel.py: hundreds of times fewer unknowns), its options
files written out in its recorded options; --3d keeps the 3D model.
"""
import argparse
import csv
import io
import itertools
import json
import os
import re
import shlex
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sectionmodel  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECORD = "sweep-run.json"
SPEC = "sweep.json"
LOG = "sweep-run.log"
EX_TEMPFAIL = 75
# The files by which indent recognises a run in its -output_dir (RunFiles in src/io/rundir.c): a fresh
# run refuses a directory holding any of them unless -output_overwrite is given.
RUN_FILES = ("indent.h5", "indent.xdmf", "indent.xdmf.tmp", "load_displacement.csv", "summary.txt", "summary.json",
             "checkpoint.h5", "checkpoint.h5.tmp", "mesh.msh", "mesh.msh.log", "imprint.csv", "imprint.png",
             "load_displacement.png", "stress_slice.png")
# Keys of summary.json that are not one number or word: left out of the CSV.
CSV_SKIP = {"options", "status"}


def parse_vary(text):
    """NAME=V1,V2 (or V1;V2) -> (NAME, [values])."""
    name, sep, values = text.partition("=")
    name = name.lstrip("-")
    if not sep or not name or not values:
        raise SystemExit(f"--vary {text!r}: expected NAME=V1,V2,... (e.g. contact_friction=0,0.1,0.3)")
    vals = [v.strip() for v in values.split(";" if ";" in values else ",")]
    if any(not v for v in vals):
        raise SystemExit(f"--vary {text!r}: an empty value")
    if len(set(vals)) != len(vals):
        raise SystemExit(f"--vary {text!r}: a value given twice")
    return name, vals


def run_name(combo):
    """Directory name: NAME=VALUE pairs joined by commas; characters unsafe in paths become '_'."""
    return ",".join(f"{k}={re.sub(r'[^A-Za-z0-9._+=,-]', '_', v)}" for k, v in combo)


def make_runs(spec):
    names = [n for n, _ in spec["vary"]]
    if len(set(names)) != len(names):
        raise SystemExit("an option is given to --vary twice")
    runs = []
    for values in itertools.product(*[v for _, v in spec["vary"]]):
        combo = list(zip(names, values))
        args = list(spec["base"])
        for k, v in combo:
            args += [f"-{k}", v]
        run = {"name": run_name(combo), "vary": dict(combo), "args": args}
        if spec.get("section"):
            try:
                tokens, why = sectionmodel.section_of(args, spec["cwd"])
            except (sectionmodel.ModelError, ValueError):
                tokens = None  # options it cannot read are indent's to refuse, naming them, when the run starts
            if tokens:
                run.update(args=tokens, section=why)
        runs.append(run)
    seen = {}
    for r in runs:
        if r["name"] in seen:
            raise SystemExit(f"two runs would share the directory {r['name']!r}: values differ only in "
                             "characters unsafe in file names")
        seen[r["name"]] = r
    return runs


def load_spec(args):
    """The sweep from the command line (and saved to OUT/sweep.json), or from OUT/sweep.json."""
    path = os.path.join(args.out, SPEC)
    old = None
    if os.path.exists(path):
        with open(path) as f:
            old = json.load(f)
    if args.vary or args.base:
        spec = {"base": [a for b in args.base for a in shlex.split(b)],
                "vary": [list(parse_vary(v)) for v in args.vary],
                "cwd": old["cwd"] if old else os.getcwd(),
                "section": not args.three_d}
        if not spec["vary"]:
            raise SystemExit("--vary NAME=V1,V2 is needed (with --base)")
    elif old:
        spec = old
        spec.setdefault("section", False)  # a sweep made before the sections ran its models as given
    else:
        raise SystemExit(f"no {path}: give the sweep with --base and --vary")
    spec["np"] = args.np if args.np is not None else (old or {}).get("np", 1)
    spec["indent"] = os.path.abspath(args.indent) if args.indent else (old or {}).get(
        "indent", os.path.join(REPO, "build", "indent"))
    return spec


def write_json(path, data):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)


def generate(spec, runs, out):
    """Creates OUT/sweep.json and each run's directory with its record; refuses a run directory
    whose recorded options differ (another sweep lives there)."""
    os.makedirs(out, exist_ok=True)
    for r in runs:
        d = os.path.join(out, r["name"])
        rec_path = os.path.join(d, RECORD)
        rec = {"name": r["name"], "vary": r["vary"], "args": r["args"], "cwd": spec["cwd"]}
        if os.path.exists(rec_path):
            with open(rec_path) as f:
                prev = json.load(f)
            if prev.get("args") != r["args"]:
                raise SystemExit(f"{d} was made with other options:\n  {shlex.join(prev.get('args', []))}\n"
                                 f"now:\n  {shlex.join(r['args'])}\nuse another --out")
            continue
        os.makedirs(d, exist_ok=True)
        write_json(rec_path, rec)
    write_json(os.path.join(out, SPEC), spec)


def read_summary(d):
    try:
        with open(os.path.join(d, "summary.json")) as f:
            return json.load(f)
    except FileNotFoundError:
        return None
    except json.JSONDecodeError as e:
        return {"status": f"unreadable summary.json ({e.msg})"}


def run_state(d):
    """finished | interrupted | incomplete | failed | not run, or summary.json's own status."""
    s = read_summary(d)
    if s is not None:
        # A summary without status comes from an indent without checkpoints, which wrote it at the end.
        status = s.get("status", "finished")
        if status == "finished" or not os.path.exists(os.path.join(d, "checkpoint.h5")):
            return status
    if os.path.exists(os.path.join(d, "checkpoint.h5")):
        return "interrupted"
    if any(os.path.exists(os.path.join(d, f)) for f in RUN_FILES):
        return "incomplete"    # failed or killed without checkpoint, or still running
    if os.path.exists(os.path.join(d, LOG)):
        return "failed"        # started by --run, but it wrote nothing
    return "not run"


def command(spec, run, out, args):
    d = os.path.abspath(os.path.join(out, run["name"]))
    state = run_state(d)
    cmd = [args.mpiexec, *shlex.split(args.mpiexec_args), "-n", str(spec["np"]), spec["indent"],
           *run["args"], "-output_dir", d]
    if state == "interrupted":
        cmd += ["-restart", d]
    elif state != "not run":
        cmd += ["-output_overwrite"]
    return d, state, cmd


class Stop:
    """Signals to the sweep become SIGUSR1 to the running mpiexec (indent checkpoints and exits 75)."""

    def __init__(self):
        self.proc = None
        self.requested = False
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGUSR1):
            signal.signal(sig, self.handle)

    def handle(self, signum, frame):
        self.requested = True
        print(f"sweep: {signal.Signals(signum).name}: asking the current run to checkpoint and stop", flush=True)
        if self.proc is not None and self.proc.poll() is None:
            self.proc.send_signal(signal.SIGUSR1)


def summary_line(d):
    s = read_summary(d) or {}
    parts = []
    for key, label, unit in (("P_max_uN", "P_max", "uN"), ("H_GPa", "H", "GPa"), ("E_GPa", "E", "GPa")):
        if isinstance(s.get(key), (int, float)):
            parts.append(f"{label} {s[key]:.6g} {unit}")
    return ", ".join(parts)


def do_run(spec, runs, out, args):
    if args.dry_run:
        for r in runs:
            d, state, cmd = command(spec, r, out, args)
            print(f"# {r['name']}: {state}" + (" (skipped)" if state == "finished" else ""))
            if state != "finished":
                print(f"cd {shlex.quote(spec['cwd'])} && {shlex.join(cmd)}")
        return 0
    stop = Stop()
    failed = []
    for i, r in enumerate(runs, 1):
        if stop.requested:
            print("sweep: stopped", flush=True)
            return EX_TEMPFAIL
        d, state, cmd = command(spec, r, out, args)
        tag = f"[{i}/{len(runs)}] {r['name']}"
        if state == "finished":
            print(f"{tag}: finished, skipped", flush=True)
            continue
        how = {"interrupted": "continuing from its checkpoint", "not run": "running"}.get(
            state, f"{state}: running again")
        print(f"{tag}: {how} (log {os.path.join(d, LOG)})", flush=True)
        t0 = time.time()
        with open(os.path.join(d, LOG), "a") as log:
            log.write(f"# {time.strftime('%Y-%m-%d %H:%M:%S')} in {spec['cwd']}: {shlex.join(cmd)}\n")
            log.flush()
            # Its own session: a Ctrl-C reaches only the sweep, which passes it on as SIGUSR1.
            try:
                stop.proc = subprocess.Popen(cmd, cwd=spec["cwd"], stdout=log, stderr=subprocess.STDOUT,
                                             start_new_session=True)
            except OSError as e:
                raise SystemExit(f"{tag}: cannot start {cmd[0]}: {e}")
            rc = stop.proc.wait()
            stop.proc = None
        secs = time.time() - t0
        ckpt = os.path.join(d, "checkpoint.h5")
        # PETSc's error code 75 (PETSC_ERR_ARG_INCOMP) is also an exit status of 75: only a checkpoint
        # written by this run means that it stopped to be continued.
        fresh = os.path.exists(ckpt) and os.path.getmtime(ckpt) >= t0 - 1
        if rc == 0:
            print(f"{tag}: finished in {secs:.1f} s  {summary_line(d)}", flush=True)
        elif rc == EX_TEMPFAIL and fresh:
            print(f"{tag}: checkpoint written after {secs:.1f} s; run the same command to continue", flush=True)
            return EX_TEMPFAIL
        else:
            print(f"{tag}: failed with exit status {rc} after {secs:.1f} s; the end of its log:", flush=True)
            with open(os.path.join(d, LOG)) as log:
                sys.stdout.write("".join(log.readlines()[-15:]))
            failed.append(r["name"])
    if failed:
        print(f"{len(failed)} run(s) failed: {', '.join(failed)}")
        return 1
    return 0


def job_script(kind, spec, run, out, index, args):
    """One job script for one run from the template in scripts/jobs: its #SBATCH/#PBS lines
    (ranks, name, wall time) and its settings block replaced."""
    template = os.path.join(REPO, "scripts", "jobs", f"{kind}-paper-case.sh")
    with open(template) as f:
        text = f.read()
    jobs = os.path.abspath(os.path.join(out, "jobs"))
    path = os.path.join(jobs, f"{run['name']}.{kind}.sh")
    d = os.path.abspath(os.path.join(out, run["name"]))
    np_ = spec["np"]
    prefix = re.sub(r"[^A-Za-z0-9]", "", os.path.basename(os.path.abspath(out))) or "sweep"
    if not prefix[0].isalpha():
        prefix = "s" + prefix
    jobname = f"{prefix[:10]}{index:03d}"
    q = shlex.quote
    settings = [f"# ---- run settings (begin): written by scripts/sweep.py for the run {run['name']}",
                f"INDENT_REPO={q(REPO)}",
                f"RUN_DIR={q(spec['cwd'])}",
                f"INDENT_EXE={q(spec['indent'])}",
                f"OUTPUT_DIR={q(d)}",
                "INDENT_OPTIONS=(" + " ".join(q(a) for a in run["args"]) + ")"]
    if kind == "slurm":
        settings += ["LAUNCHER=(srun)", "MAX_RESUBMITS=${INDENT_MAX_RESUBMITS:-10}", "RESUBMIT=requeue"]
        subs = [(r"^#SBATCH --ntasks=.*$", f"#SBATCH --ntasks={np_}"),
                (r"^#SBATCH --job-name=.*$", f"#SBATCH --job-name={jobname}"),
                (r"^#SBATCH --output=.*$", f"#SBATCH --output={jobs}/{jobname}-%j.out")]
        if args.walltime:
            subs.append((r"^#SBATCH --time=.*$", f"#SBATCH --time={args.walltime}"))
    else:
        settings += [f"LAUNCHER=(mpiexec -n {np_})", "MAX_RESUBMITS=${INDENT_MAX_RESUBMITS:-10}",
                     "SIGNAL_MARGIN=${INDENT_SIGNAL_MARGIN:-300}"]
        subs = [(r"^#PBS -l select=.*$", f"#PBS -l select=1:ncpus={np_}:mpiprocs={np_}"),
                (r"^# PBS Pro syntax; Torque: .*$", f"# PBS Pro syntax; Torque: #PBS -l nodes=1:ppn={np_}"),
                (r"^#PBS -N .*$", f"#PBS -N {jobname}")]
        if args.walltime:
            subs.append((r"^#PBS -l walltime=.*$", f"#PBS -l walltime={args.walltime}"))
    settings += ["OVERWRITE_PARTIAL=1", f"JOB_SCRIPT={q(path)}", "# ---- run settings (end)"]
    submit = "sbatch" if kind == "slurm" else "qsub"
    header = (f"#!/bin/bash\n# Run {run['name']} of the sweep {os.path.abspath(out)}, written by scripts/sweep.py\n"
              f"# from scripts/jobs/{kind}-paper-case.sh (which explains the checkpoints and resubmission).\n"
              f"# Submit it from anywhere: {submit} {shlex.quote(path)}\n")
    subs.append((r"\A#!/bin/bash\n(#(?!SBATCH|PBS).*\n)*", header))
    for pattern, repl in subs:
        text, n = re.subn(pattern, lambda m: repl, text, count=1, flags=re.M)
        if n != 1:
            raise SystemExit(f"{template}: no line matching {pattern!r} to replace")
    block = re.compile(r"^# ---- run settings \(begin\).*?^# ---- run settings \(end\)$", re.M | re.S)
    text, n = block.subn(lambda m: "\n".join(settings), text)
    if n != 1:
        raise SystemExit(f"{template}: no '# ---- run settings (begin)' ... '(end)' block")
    return path, text


def do_jobs(kind, spec, runs, out, args):
    paths = []
    for i, r in enumerate(runs, 1):
        path, text = job_script(kind, spec, r, out, i, args)
        if args.dry_run:
            print(f"# would write {path}")
        else:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(text)
            os.chmod(path, 0o755)
        paths.append(path)
    submit = "sbatch" if kind == "slurm" else "qsub"
    jobs = os.path.dirname(paths[0])
    if not args.dry_run:
        print(f"wrote {len(paths)} job scripts in {jobs}; submit them with:")
    print(f"  cd {shlex.quote(jobs)} && for f in *.{kind}.sh; do {submit} \"$f\"; done")
    return 0


def numeric_key(v):
    try:
        return (0, float(v), "")
    except (TypeError, ValueError):
        return (1, 0.0, str(v))


def collect(spec, out, args):
    """Every run directory under OUT (those of this sweep and any made before with other values)."""
    records = []
    for entry in sorted(os.listdir(out)) if os.path.isdir(out) else []:
        rec_path = os.path.join(out, entry, RECORD)
        if os.path.isfile(rec_path):
            with open(rec_path) as f:
                records.append(json.load(f))
    if not records:
        raise SystemExit(f"no run directories ({RECORD}) under {out}")
    names = [n for n, _ in spec["vary"]]
    for rec in records:
        names += [k for k in rec["vary"] if k not in names]
    records.sort(key=lambda rec: ([numeric_key(rec["vary"].get(k)) for k in names], rec["name"]))
    rows, keys = [], []
    for rec in records:
        d = os.path.join(out, rec["name"])
        s = read_summary(d) or {}
        row = {"run": rec["name"], **{k: rec["vary"].get(k, "") for k in names}, "status": run_state(d)}
        for k, v in s.items():
            if k in CSV_SKIP or isinstance(v, (dict, list)) or v is None:
                continue
            if k not in keys:
                keys.append(k)
            row[k] = json.dumps(v) if isinstance(v, bool) else v
        rows.append(row)
    clash = [k for k in keys if k in names or k == "run"]
    if clash:
        raise SystemExit(f"summary keys {clash} clash with the varied options' columns")
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=["run", *names, "status", *keys], restval="", lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    path = args.csv or os.path.join(out, "summary.csv")
    if args.dry_run:
        sys.stdout.write(buf.getvalue())
    else:
        with open(path, "w") as f:
            f.write(buf.getvalue())
        done = sum(r["status"] == "finished" for r in rows)
        print(f"{path}: {len(rows)} runs, {done} finished")
        for r in rows:
            if r["status"] != "finished":
                print(f"  {r['run']}: {r['status']}")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    ap.add_argument("--base", action="append", default=[],
                    help="options common to every run, as one string (repeatable); an option without value "
                    "needs the = form: --base=-quiet")
    ap.add_argument("--vary", action="append", default=[], metavar="NAME=V1,V2",
                    help="an option and its values (repeatable: every combination is run)")
    ap.add_argument("--out", required=True, help="the sweep's directory")
    ap.add_argument("--np", type=int, help="MPI ranks per run (default 1, or the sweep's)")
    ap.add_argument("--indent", help="the indent executable (default: build/indent of this checkout)")
    ap.add_argument("--mpiexec", default="mpiexec", help="MPI launcher for --run (default mpiexec)")
    ap.add_argument("--mpiexec-args", default="", help="its extra arguments for --run, e.g. --oversubscribe")
    act = ap.add_mutually_exclusive_group()
    act.add_argument("--run", action="store_true", help="run the unfinished runs here, one after another")
    act.add_argument("--slurm", action="store_true", help="write one Slurm job script per run (not submitted)")
    act.add_argument("--pbs", action="store_true", help="write one PBS job script per run (not submitted)")
    ap.add_argument("--walltime", help="--slurm/--pbs: the jobs' wall time, HH:MM:SS (default: the template's)")
    ap.add_argument("--collect", action="store_true", help="gather every run's summary.json into one CSV")
    ap.add_argument("--csv", help="--collect's file (default OUT/summary.csv)")
    ap.add_argument("--dry-run", action="store_true", help="print the commands, write and run nothing")
    ap.add_argument("--3d", dest="three_d", action="store_true",
                    help="keep a 3D model whose indenter of revolution would run on the axisymmetric section")
    args = ap.parse_args()
    if args.np is not None and args.np < 1:
        ap.error("--np must be >= 1")
    if args.walltime and not re.fullmatch(r"\d+:\d\d:\d\d", args.walltime):
        ap.error("--walltime must be HH:MM:SS")
    args.out = os.path.abspath(args.out)

    spec = load_spec(args)
    runs = make_runs(spec)
    sections = sorted({r["section"] for r in runs if "section" in r})
    for why in sections:
        n = sum(r.get("section") == why for r in runs)
        print(f"sweep: {n} of {len(runs)} runs: {why} (scripts/sectionmodel.py; --3d keeps the 3D model)")
    if not args.dry_run:
        generate(spec, runs, args.out)
    rc = 0
    if args.run:
        rc = do_run(spec, runs, args.out, args)
    elif args.slurm or args.pbs:
        rc = do_jobs("slurm" if args.slurm else "pbs", spec, runs, args.out, args)
    elif not args.collect:
        if not args.dry_run:
            print(f"{args.out}: {len(runs)} run directories; the commands --run would run:")
        do_run(spec, runs, args.out, argparse.Namespace(**{**vars(args), "dry_run": True}))
    if args.collect and rc != EX_TEMPFAIL:
        collect(spec, args.out, args)
    return rc


if __name__ == "__main__":
    sys.exit(main())
