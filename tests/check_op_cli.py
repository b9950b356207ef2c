#!/usr/bin/env python3
"""indent-op on a synthetic curve (loading P = C h^2, unloading P = alpha (h - h_f)^m) for a sharp
Berkovich, A = 3 sqrt(3) tan^2(65.27 deg) h^2: S, H and E_r must match the closed forms to 1e-6. The same curve as
a spreadsheet saves it (a UTF-8 byte-order mark, semicolons and decimal commas, CRLF; or tabs) and with an empty
column before the depth gives the same numbers in every digit; a cell that is not a number is one error line.

  check_op_cli.py INDENT-OP WORKDIR
"""
import math
import os
import re
import subprocess
import sys


def main():
    exe, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "synthetic.csv")
    hmax, hf, m, pmax = 400.0, 300.0, 1.5, 2000.0
    alpha = pmax / (hmax - hf) ** m
    with open(path, "w") as f:
        f.write("step,depth_nm,load_uN\n")
        k = 0
        for i in range(1, 41):
            h = hmax * i / 40
            k += 1
            f.write(f"{k},{h:.17g},{pmax * (h / hmax) ** 2:.17g}\n")
        for i in range(1, 41):
            h = hmax - (hmax - hf) * i / 40
            k += 1
            f.write(f"{k},{h:.17g},{alpha * (h - hf) ** m:.17g}\n")
    out = run(exe, path)
    print(out, end="")
    S = m * alpha * (hmax - hf) ** (m - 1)
    hc = hmax - 0.75 * pmax / S
    A = 3 * math.sqrt(3) * math.tan(math.radians(65.27)) ** 2 * hc * hc
    H = 1000 * pmax / A
    Er = 1000 * math.sqrt(math.pi) / (2 * 1.034) * S / math.sqrt(A)
    got = {k: float(v) for k, v in re.findall(r"\b(S|H|E_r) ([-+0-9.eE]+)", out)}
    worst = 0.0
    for name, exact in (("S", S), ("H", H), ("E_r", Er)):
        if name not in got:
            print(f"FAIL: no {name} in the output")
            return 1
        worst = max(worst, abs(got[name] / exact - 1))
        print(f"{name}: {got[name]:.10g} vs closed form {exact:.10g}")
    print(f"worst relative error {worst:.2e} (tolerance 1e-6): {'ok' if worst <= 1e-6 else 'FAIL'}")
    bad = worst > 1e-6
    with open(path) as f:
        rows = [line.rstrip("\n").split(",") for line in f]
    forms = {"spreadsheet.csv": (";", True, "utf-8-sig", "\r\n", False),
             "tabs.csv": ("\t", False, "utf-8", "\n", False),
             "empty_column.csv": (",", False, "utf-8", "\n", True)}
    for name, (sep, comma, enc, eol, empty) in forms.items():
        other = os.path.join(work, name)
        with open(other, "w", encoding=enc, newline="") as f:
            for k, r in enumerate(rows):
                cells = ([r[0], "note" if k == 0 else ""] + r[1:]) if empty else r
                f.write(sep.join(c.replace(".", ",") if comma else c for c in cells) + eol)
        same = run(exe, other).splitlines()[1:] == out.splitlines()[1:]  # the first line names the file
        bad |= not same
        print(f"{name}: {'ok, the same output' if same else 'FAIL, another output'}")
    text = os.path.join(work, "text.csv")
    with open(text, "w") as f:
        f.write("depth_nm,load_uN\n1,2\n2,4uN\n")
    err = run(exe, text).strip().splitlines()
    ok = len(err) == 1 and "line 3: '4uN' is not a number" in err[0]
    bad |= not ok
    print(f"text.csv: {'ok' if ok else 'FAIL'}: {err}")
    return 1 if bad else 0


def run(exe, path):
    return subprocess.run([exe, "-op_file", path, "-indenter_type", "berkovich"], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True).stdout


if __name__ == "__main__":
    sys.exit(main())
