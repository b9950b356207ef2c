#!/usr/bin/env python3
"""Runs the unit and small component tests of a build under valgrind memcheck (see scripts/valgrind-tests.sh).

  memcheck.py BUILD_DIR [--jobs N] [--regex R]

The tests come from ctest (`ctest --show-only=json-v1`) with their environment and arguments: those
with a label in LABELS but the SLOW ones, and the EXTRA ones. Each runs its executable directly under
valgrind on one rank (a test registered for several rank counts runs once), so that valgrind watches
our program and not mpiexec; TWO_RANKS also runs on 2 ranks, valgrind under mpiexec, for the paths
that communicate. Tests run by a Python or shell driver are left out: valgrind would watch the
interpreter. A run fails on a non-zero exit, a memcheck error or definitely lost bytes that the
suppressions in this directory do not cover. Prints a table and a verdict; exit 1 if any run failed.
"""
import argparse
import concurrent.futures
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SUPPRESSIONS = os.path.join(HERE, "openmpi.supp")
# The unit and component tests, but for those that run for seconds without valgrind (which is 20 to 50
# times slower): the manufactured solutions (three meshes each), the P2 Newton tests, the Newton tests of the
# hardening laws other than Voce (their kernels run under it in unit_plasticity, their table's file in
# plastic_uniaxial_table_np2), all but one state round trip (about 11 s each under valgrind),
# solver_anatomy (3 s alone, 80 s under valgrind; its solves are the runs' own, checked by the others),
# ew_tangent_predictor (43 s under valgrind: PETSc's Eisenstat-Walker with the tangent predictor, whose solve
# runs at the first step of every indentation here) and all but two of the eight run_checks_* (the same
# program deciding other warnings, 7 s each, mostly valgrind's start), three of the four axisymmetric_newton_*
# (48, 16 and 10 s under valgrind; finite_Q1, 14 s, runs the hoop terms of the cell loop and of both kinematics'
# shared helpers), and the second variant of four programs that run in another test already:
# plastic_newton_elastic_tangent (18 s), plastic_cycle_hex_Q2 (17 s), uniaxial_roller_hex_Q2 (9 s) and
# plastic_uniaxial_cutback_hex_Q2 (11 s; plastic_uniaxial_return_cutback rejects steps too), two of the three
# plastic_newton_densifying_* (8 and 11 s; _finite runs the same return map and tangent, unit_densification
# runs them alone) and unit_lagged_smoother (23 s under valgrind, of which our code is one call that resets a
# smoother), unit_rigid_modes_rebuilt (15 s; the program of unit_rigid_modes, which runs), matinsert_tet_P1 (9 s; the
# program of matinsert_hex_Q2, whose P1 kernels run in patch_tet_P1) and all but the P1 variant of disc_layout_*
# (the same loops over other cells). Plus the
# flat-punch contact patch test, which also runs on 2 ranks, a small indentation that writes every
# output file (HDF5 fields, XDMF, curve, summary) and a small scratch (scratch.csv, the sliding contact).
LABELS = {"unit", "component"}
SLOW = re.compile(r"^(mms_|plastic_newton(_finite)?_tet_P2|plastic_newton_(power|swift|table)_|"
                  r"state_roundtrip_(depth_np2|load|fixed_point)|solver_anatomy|ew_tangent_predictor|"
                  r"run_checks_(edge_small|edge_quarter|area|inverted|loading_touches)|"
                  r"axisymmetric_newton_(small_Q1|small_P2|finite_P1)|plastic_newton_elastic_tangent|"
                  r"plastic_cycle_hex_Q2|uniaxial_roller_hex_Q2|plastic_uniaxial_cutback_hex_Q2|"
                  r"plastic_newton_densifying_(small|hardening)|unit_lagged_smoother|unit_rigid_modes_rebuilt|"
                  r"matinsert_tet_P1|disc_layout_(tet_P2|hex_))")
TWO_RANKS = "contact_patch_hex_Q1_np2"
EXTRA = {TWO_RANKS, "xdmf_indent_run", "example_scratch_np2"}
VALGRIND_EXIT = 99  # --error-exitcode: tells memcheck's errors from the test's own failures


def ctest_tests(build):
    """(name, command, properties) of every test, read by ctest from a copy of the build's test files:
    ctest rewrites Testing/Temporary/LastTest.log, which the ctest running this script is writing."""
    with tempfile.TemporaryDirectory() as copy:
        for root, dirs, files in os.walk(build):
            dirs[:] = [d for d in dirs if d not in ("CMakeFiles", "Testing", "valgrind")]
            if "CTestTestfile.cmake" in files:
                os.makedirs(os.path.join(copy, os.path.relpath(root, build)), exist_ok=True)
                shutil.copy(os.path.join(root, "CTestTestfile.cmake"), os.path.join(copy, os.path.relpath(root, build)))
        out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=copy, check=True, stdout=subprocess.PIPE,
                             text=True).stdout
    for t in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        yield t["name"], t.get("command", []), props


def split_command(cmd, build):
    """(ranks, executable, arguments) of a test command, mpiexec stripped; None when the test runs a
    driver script (an interpreter, or a script, rather than a program built in build)."""
    ranks = 1
    if os.path.basename(cmd[0]).startswith("mpiexec") and len(cmd) > 3 and cmd[1] in ("-n", "-np"):
        ranks, cmd = int(cmd[2]), cmd[3:]
    exe = os.path.realpath(cmd[0])
    if not exe.startswith(build + os.sep):
        return None
    with open(exe, "rb") as f:
        if f.read(4) != b"\x7fELF":
            return None
    return ranks, exe, cmd[1:]


def redirect_output(args, workdir):
    """The test's own -output_dir would be shared with ctest's run of it: write into workdir instead."""
    args = list(args)
    if "-output_dir" in args:
        args[args.index("-output_dir") + 1] = os.path.join(workdir, "output")
    return args


def valgrind(logdir):
    return ["valgrind", "--tool=memcheck", "--leak-check=full", "--show-leak-kinds=definite",
            "--errors-for-leak-kinds=definite", f"--error-exitcode={VALGRIND_EXIT}", f"--suppressions={SUPPRESSIONS}",
            "--num-callers=40", f"--log-file={logdir}/valgrind.%p.log"]


def run(build, name, ranks, exe, args, env):
    label = name if ranks == 1 else f"{name} ({ranks} ranks)"
    workdir = os.path.join(build, "valgrind", name + ("" if ranks == 1 else f"_np{ranks}"))
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    cmd = [*valgrind(workdir), exe, *redirect_output(args, workdir)]
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), *cmd]
    start = time.time()
    with open(os.path.join(workdir, "output.txt"), "w") as out:
        out.write("+ " + " ".join(cmd) + "\n")
        out.flush()
        status = subprocess.run(cmd, cwd=workdir, env=env, stdout=out, stderr=subprocess.STDOUT).returncode
    wall = time.time() - start
    errors = lost = summaries = 0
    for log in glob.glob(os.path.join(workdir, "valgrind.*.log")):
        text = open(log).read()
        m = re.search(r"ERROR SUMMARY: ([\d,]+) errors", text)
        if not m:
            continue  # a child Open MPI forked (a singleton's orted) and exec'ed out of valgrind
        summaries += 1
        errors += int(m.group(1).replace(",", ""))
        m = re.search(r"definitely lost: ([\d,]+) bytes", text)
        lost += int(m.group(1).replace(",", "")) if m else 0
    # a rank without a summary: valgrind itself died
    ok = status == 0 and errors == 0 and lost == 0 and summaries >= ranks
    return label, status, errors, lost, wall, ok, workdir


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build")
    ap.add_argument("--jobs", type=int, default=max(1, min(2, os.cpu_count() or 1)))
    ap.add_argument("--regex", help="run only the selected tests whose name matches this")
    args = ap.parse_args()
    build = os.path.realpath(args.build)
    if not shutil.which("valgrind"):
        sys.exit("valgrind-tests: valgrind is not installed (apt-get install valgrind)")

    runs, skipped, bases, found = [], [], set(), set()
    for name, cmd, props in ctest_tests(build):
        found.add(name)
        selected = (LABELS & set(props.get("LABELS", [])) and not SLOW.search(name)) or name in EXTRA
        if not cmd or not selected or (args.regex and not re.search(args.regex, name)):
            continue
        split = split_command(cmd, build)
        if split is None:
            skipped.append(name)
            continue
        ranks, exe, targs = split
        env = dict(os.environ)
        env.update(e.split("=", 1) for e in props.get("ENVIRONMENT", []))
        # valgrind must see the C library's allocations, not PETSc's tracing allocator (-malloc_dump)
        env.pop("PETSC_OPTIONS", None)
        base = re.sub(r"_np\d+$", "", name)
        if base not in bases:  # the same test on more ranks: one single-rank run is enough
            bases.add(base)
            runs.append((base, 1, exe, targs, env))
        if name == TWO_RANKS:
            runs.append((base, 2, exe, targs, env))
    if not runs:
        sys.exit("valgrind-tests: no test selected (is this a configured and built build directory?)")
    missing = EXTRA - found
    if missing and not args.regex:
        sys.exit(f"valgrind-tests: no test {', '.join(sorted(missing))} in ctest (renamed? update EXTRA in {__file__})")

    start = time.time()
    print(f"{len(runs)} runs under valgrind, {args.jobs} at a time", flush=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run, build, *r) for r in runs]
        for k, done in enumerate(concurrent.futures.as_completed(futures), 1):
            label, ok = done.result()[0], done.result()[5]
            print(f"  [{k}/{len(runs)}] {label}: {'ok' if ok else 'FAIL'}", flush=True)
        results = [f.result() for f in futures]
    width = max(len(r[0]) for r in results)
    print(f"{'test':{width}}  {'exit':>4}  {'errors':>6}  {'definitely lost (bytes)':>23}  {'time (s)':>8}")
    for label, status, errors, lost, wall, ok, workdir in results:
        verdict = "" if ok else f"  FAIL: {workdir}"
        print(f"{label:{width}}  {status:4d}  {errors:6d}  {lost:23d}  {wall:8.1f}{verdict}")
    failed = [r for r in results if not r[5]]
    if skipped:
        print(f"not run (script drivers): {', '.join(skipped)}")
    print(f"{len(results)} runs in {time.time() - start:.0f} s: "
          + (f"FAIL: {len(failed)} with errors, leaks or a non-zero exit (valgrind logs in the directories above)"
             if failed else "no memcheck error, no definitely lost bytes"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
