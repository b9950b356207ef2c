#!/usr/bin/env python3
"""Oliver-Pharr results only where the contact resolves them:

  check_op_withheld.py --mpiexec M --indent BIN --workdir D [--np N] --shallow DEPTH -- <indent options>

runs the case DEPTH nm deep (a contact of a few nodes): summary.json must hold H_GPa, E_r_GPa, E_GPa,
H_true_GPa and E_r_true_GPa as null with op_withheld naming -op_min_contact_nodes, summary.txt must say
"no Oliver-Pharr analysis", and the run must print the reason once as 'indent: warning: H and E_r
withheld ...' (it runs with -quiet); the same run with -op_min_contact_nodes 0 must report numbers and no
op_withheld. Prints ok or FAIL per check; exit 1 on a failed check.
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

KEYS = ("H_GPa", "E_r_GPa", "E_GPa", "H_true_GPa", "E_r_true_GPa")
check = indentrun.Checks()


def main():
    ap, mine, options = indentrun.parser_and_options("check_op_withheld.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--shallow", required=True)
    args = ap.parse_args(mine)
    os.makedirs(args.workdir, exist_ok=True)
    out = os.path.join(args.workdir, "withheld")
    cmd = [args.mpiexec, "-n", str(args.np), args.indent, *options, "-load_depth", args.shallow, "-output_dir", out,
           "-output_overwrite"]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout, end="")
    if check(proc.returncode == 0, f"the {args.shallow} nm run finished (exit {proc.returncode})"):
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        for k in KEYS:
            check(k in s and s[k] is None, f"summary.json: {k} is null (got {s.get(k, 'no key')!r})")
        check("-op_min_contact_nodes" in s.get("op_withheld", ""),
              "summary.json: op_withheld names -op_min_contact_nodes")
        with open(os.path.join(out, "summary.txt")) as f:
            check("no Oliver-Pharr analysis: H and E_r withheld" in f.read(), "summary.txt says why")
        lines = [l for l in proc.stdout.splitlines() if l.startswith("indent: warning: H and E_r withheld")]
        check(len(lines) == 1, f"one warning line printed (got {len(lines)})")
    out = os.path.join(args.workdir, "forced")
    if check(indentrun.run(args, args.np, [*options, "-load_depth", args.shallow, "-op_min_contact_nodes", "0"], out,
                           "the run with -op_min_contact_nodes 0"), "the run with -op_min_contact_nodes 0"):
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        check(all(isinstance(s.get(k), float) for k in KEYS) and "op_withheld" not in s,
              "with -op_min_contact_nodes 0: H and E_r reported")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
