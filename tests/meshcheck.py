"""Shared by the validation drivers that run indent on a given mesh (check_sphere_op.py,
check_kick.py): their common arguments, checked, and one checked run."""
import argparse
import os
import re
import shlex
import subprocess
import sys
import time

# a block PETSc's -malloc_dump reports unfreed at PetscFinalize: "[ 0] 1008 bytes IndFoo() at src/foo.c:12"
UNFREED = re.compile(r"^\[ *\d+\] ?\d+ bytes \S+\(\) (at|line) ")


def bad_input(prog, msg):
    print(f"{prog}: {msg}", file=sys.stderr)
    sys.exit(2)


def parser(prog, doc, mesh_help):
    """An ArgumentParser with --indent, --mesh, --workdir, --np, --mpiexec, --mpiexec-args."""
    ap = argparse.ArgumentParser(prog=prog, description=doc.split("\n")[0])
    ap.add_argument("--indent", required=True, help="the indent executable")
    ap.add_argument("--mesh", required=True, help=mesh_help)
    ap.add_argument("--workdir", required=True, help="output directory (created)")
    ap.add_argument("--np", type=int, default=2, help="MPI ranks (2)")
    ap.add_argument("--mpiexec", default=os.environ.get("MPIEXEC", "mpiexec"))
    ap.add_argument("--mpiexec-args", default="--oversubscribe", help='extra mpiexec arguments ("--oversubscribe"; "" for none)')
    return ap


def check_common(prog, args):
    """Exit 2 on a bad common argument; splits --mpiexec-args into a list."""
    if not (os.path.isfile(args.indent) and os.access(args.indent, os.X_OK)):
        bad_input(prog, f"--indent '{args.indent}' is not an executable file")
    if not os.path.isfile(args.mesh):
        bad_input(prog, f"--mesh '{args.mesh}' does not exist")
    if args.np < 1:
        bad_input(prog, f"--np must be >= 1, got {args.np}")
    try:
        args.mpiexec_args = shlex.split(args.mpiexec_args)
    except ValueError as e:
        bad_input(prog, f"--mpiexec-args: {e}")


def run_indent(prog, args, options, out):
    """Runs indent on --mesh with options into out; its wall time, or None (with a message) if it
    failed or left an option unused."""
    cmd = [args.mpiexec, *args.mpiexec_args, "-n", str(args.np), args.indent, "-mesh_file", args.mesh, *options,
           "-output_dir", out, "-output_overwrite", "-options_left"]
    print("+", " ".join(shlex.quote(c) for c in cmd), flush=True)
    start = time.time()
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    except OSError as e:
        bad_input(prog, f"cannot run {args.mpiexec}: {e}")
    wall = time.time() - start
    # the output is shown only on failure; PETSc's -malloc_dump report (exit 0) is for ctest to judge
    print("".join(line + "\n" for line in proc.stdout.splitlines() if UNFREED.search(line)), end="")
    unused = "WARNING! There are" in proc.stdout
    if proc.returncode != 0 or unused:
        print(proc.stdout, end="")
        print(f"FAIL: indent exited with {proc.returncode}" + (" (unused options)" if unused else ""))
        return None
    return wall
