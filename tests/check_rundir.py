#!/usr/bin/env python3
"""The output-directory rule: a fresh run refuses a directory holding a run (files untouched), replaces
it with -output_overwrite (only indent's files go), and -restart is refused without a checkpoint, with
-output_overwrite, or with a checkpoint outside -output_dir.

  check_rundir.py --mpiexec M --indent BIN --workdir D -- <options of a short indentation>
"""
import hashlib
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def snapshot(d):
    return {n: hashlib.sha256(open(os.path.join(d, n), "rb").read()).hexdigest() for n in sorted(os.listdir(d))}


def main():
    ap, argv, options = indentrun.parser_and_options("check_rundir.py")
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    run = os.path.join(args.workdir, "run")
    failed = 0

    def indent(*extra):
        cmd = [args.indent, *options, *extra]  # a singleton: mpiexec adds its own banner to a non-zero exit
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        indentrun.pass_on_unfreed(proc.stdout)
        return proc.returncode, [l for l in proc.stdout.splitlines() if l.strip()]

    def expect_refusal(label, text, *extra):
        nonlocal failed
        before = snapshot(run)
        code, lines = indent(*extra)
        ok = code != 0 and len(lines) == 1 and text in lines[0] and snapshot(run) == before
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {label}: exit {code}, {'untouched' if snapshot(run) == before else 'CHANGED'}: "
              f"{lines[0] if lines else '(nothing)'}{'' if len(lines) <= 1 else f' (+{len(lines) - 1} lines)'}")

    code, lines = indent("-output_dir", run)
    if code != 0:
        print("\n".join(lines))
        print("FAIL: the first run failed")
        return 1
    with open(os.path.join(run, "notes.txt"), "w") as fp:
        fp.write("the user's own file\n")
    expect_refusal("a second run into the directory", "already holds a run", "-output_dir", run)
    expect_refusal("-restart without a checkpoint", "no checkpoint", "-output_dir", run, "-restart", run)
    expect_refusal("-restart with -output_overwrite", "give one", "-output_dir", run, "-restart", run, "-output_overwrite")
    other = os.path.join(args.workdir, "other")
    os.makedirs(other)
    shutil.copy(os.path.join(HERE, "check_rundir.py"), os.path.join(other, "checkpoint.h5"))
    expect_refusal("-restart of a checkpoint outside -output_dir", "must lie in -output_dir", "-output_dir", run, "-restart", other)

    before = snapshot(run)
    os.utime(os.path.join(run, "summary.json"), (0, 0))
    code, lines = indent("-output_dir", run, "-output_overwrite")
    after = snapshot(run)
    ok = code == 0 and after.get("notes.txt") == before["notes.txt"] and set(after) == set(before) \
        and os.path.getmtime(os.path.join(run, "summary.json")) > 0
    failed += not ok
    print(f"{'ok  ' if ok else 'FAIL'} -output_overwrite: exit {code}, the user's file kept, the run's files rewritten")
    print("the output directory rule holds" if not failed else f"FAIL: {failed} check(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
