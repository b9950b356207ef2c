#!/usr/bin/env python3
"""Oliver-Pharr results only where the run supports them:

  check_op_withheld.py --mpiexec M --indent BIN --workdir D [--np N] --depth DEPTH --reason TEXT [--forced]
      -- <indent options>

runs the case DEPTH nm deep (a contact of a few nodes, or an indenter wider than the block): summary.json must
hold H_GPa, E_r_GPa, E_GPa, H_true_GPa and E_r_true_GPa as null with op_withheld containing TEXT, summary.txt must
say "no Oliver-Pharr analysis", and the run must print the reason once as 'indent: warning: H and E_r
withheld ...' (it runs with -quiet). With --forced, the same run with -op_min_contact_nodes 0 must report numbers
and no op_withheld. Prints ok or FAIL per check; exit 1 on a failed check.
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
    ap.add_argument("--depth", required=True)
    ap.add_argument("--reason", required=True)
    ap.add_argument("--forced", action="store_true")
    args = ap.parse_args(mine)
    os.makedirs(args.workdir, exist_ok=True)
    out = os.path.join(args.workdir, "withheld")
    cmd = [args.mpiexec, "-n", str(args.np), args.indent, *options, "-load_depth", args.depth, "-output_dir", out,
           "-output_overwrite"]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout, end="")
    if check(proc.returncode == 0, f"the {args.depth} nm run finished (exit {proc.returncode})"):
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        for k in KEYS:
            check(k in s and s[k] is None, f"summary.json: {k} is null (got {s.get(k, 'no key')!r})")
        check(args.reason in s.get("op_withheld", ""), f"summary.json: op_withheld says '{args.reason}'")
        with open(os.path.join(out, "summary.txt")) as f:
            check("no Oliver-Pharr analysis: H and E_r withheld" in f.read(), "summary.txt says why")
        lines = [l for l in proc.stdout.splitlines() if l.startswith("indent: warning: H and E_r withheld")]
        check(len(lines) == 1, f"one warning line printed (got {len(lines)})")
    if not args.forced:
        return check.status()
    out = os.path.join(args.workdir, "forced")
    if check(indentrun.run(args, args.np, [*options, "-load_depth", args.depth, "-op_min_contact_nodes", "0"], out,
                           "the run with -op_min_contact_nodes 0"), "the run with -op_min_contact_nodes 0"):
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        check(all(isinstance(s.get(k), float) for k in KEYS) and "op_withheld" not in s,
              "with -op_min_contact_nodes 0: H and E_r reported")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
