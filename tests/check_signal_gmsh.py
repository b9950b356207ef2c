#!/usr/bin/env python3
"""A stop signal while gmsh meshes ends the job at once with status 75 and one line saying nothing can be continued.

SIGUSR1 goes to mpiexec (which forwards it to the ranks) as soon as gmsh runs: indent ends gmsh (which runs in
a process group of its own, so a signal to indent's group does not kill it unseen), prints one line and exits
75; no gmsh process and no lock are left.

  check_signal_gmsh.py --mpiexec M --indent BIN --workdir D -- <indent options meshing a .geo for seconds>
"""
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def gmsh_for(out):
    """pids of the processes whose command line writes into out's mesh (gmsh and its shell)."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if "gmsh" in cmd and os.path.join(out, "mesh.msh") in cmd:
            found.append(int(pid))
    return found


def main():
    ap, argv, options = indentrun.parser_and_options("check_signal_gmsh.py")
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    out = os.path.join(args.workdir, "run")
    check = indentrun.Checks()
    env = dict(os.environ, OMPI_MCA_orte_execute_quiet="1")
    cmd = [args.mpiexec, "-n", "2", args.indent, *options, "-output_dir", out]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    t0 = time.time()
    while not gmsh_for(out) and proc.poll() is None and time.time() - t0 < 60:
        time.sleep(0.05)
    meshing = bool(gmsh_for(out))
    check(meshing, f"gmsh runs ({time.time() - t0:.1f} s after the start)")
    if meshing:
        proc.send_signal(signal.SIGUSR1)
    try:
        text, _ = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        text, _ = proc.communicate()
    lines = [line for line in text.splitlines() if line.strip()]
    print("\n".join(lines[-3:]))
    check(proc.returncode == 75, f"exit status {proc.returncode} (want 75)")
    check(len(lines) == 1 and "stopped by SIGUSR1 while gmsh meshed" in lines[0] and "nothing to continue" in lines[0],
          "one line: stopped by SIGUSR1 while gmsh meshed ..., nothing to continue from")
    time.sleep(1)
    check(not gmsh_for(out), "no gmsh left")
    check(not os.path.exists(os.path.join(out, "indent.lock")), "no lock left")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
