#!/usr/bin/env python3
"""Measured curves in (scripts/measured-curve.py, scripts/indentcurves.py):

  check_measured_curve.py --indent-op BIN --data DIR --workdir D

1. The 9 Berkovich tests of DIR/FS_XP.xls (fused silica, Agilent XP, shared/data/fused-silica-agilent-xp): each is
   read (mN to uN), its segments taken from the file (loading, hold, 26 unloading points), and indent-op analyses it
   with the file's own area function and a diamond tip (E 1141 GPa, nu 0.07; the sample's nu 0.18, as entered in
   the file). E_r and H of each test against the instrument's own values at the same depth: its continuous-stiffness
   channels 'Reduced Modulus' and 'Hardness' over the last 10% of the loading (about 900 to 990 nm): E_r within 5%
   each and 3% on the mean. H comes out 10 to 17% below the instrument's, because the contact depths differ. In
   test 1: 727 nm from the unloading after the 10 s hold (29 nm of creep, and S 300.5 against the continuous
   stiffness's 273 uN/nm) against the instrument's 675 nm at 976 nm during loading. The bounds, 18% each and 15%
   on the mean, keep it where it was measured.
2. Synthetic curves with known values: a CSV in um and mN and a Hysitron .txt in nm and uN, with a hold and a
   thermal-drift hold: units converted, the segments found from the load, and a frame compliance and a drift
   rate removed exactly; the CSV as spreadsheets write it (semicolons and decimal commas with a UTF-8 byte-order
   mark, tab-separated UTF-16, Latin-1 'µN') read alike; a NIGET file (mN, decimal commas, a text line) read with
   the segments of its header.
3. Bad files: a missing file, a curve that never unloads, an unknown unit, a .niget without its header or with
   rows that do not rise: exit 1 and one line naming the file.
4. The tip of test 1's area function as an indenter table (--tip-table): pi r^2 equals A(h) at every row, 3%
   above the ideal Berkovich's at 727 nm; an area function that does not rise, or no --area: exit 1, one line.
Prints ok or FAIL per check; exit 1 on any failure.
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "measured-curve.py")
sys.path.insert(0, os.path.join(HERE, "..", "scripts"))
import indentcurves  # noqa: E402
from checklist import check, status  # noqa: E402  (this folder)



def measured(args, *more):
    """The script, with its own temporary folder (fused_silica checks that nothing is left in it)"""
    tmp = os.path.join(args.workdir, "tmp")
    os.makedirs(tmp, exist_ok=True)
    return subprocess.run([sys.executable, SCRIPT, *more], capture_output=True, text=True,
                          env=dict(os.environ, TMPDIR=tmp))


def fused_silica(args):
    xls = os.path.join(args.data, "FS_XP.xls")
    E, H, Eref, Href = [], [], [], []
    for test in range(1, 10):
        c = indentcurves.read(xls, "agilent", test)
        kinds = [s[0] for s in c["segments"]]
        un = [s for s in c["segments"] if s[0] == "unloading"][0]
        check(kinds == ["loading", "hold", "unloading"] and un[2] - un[1] + 1 == 26,
              f"test {test}: segments {kinds} from the file, {un[2] - un[1] + 1} unloading points")
        pmax = c["load"].max()
        check(111000 < pmax < 114000, f"test {test}: P_max {pmax:.0f} uN (the file: 111.4 to 113.5 mN)")
        run = measured(args, xls, "--test", str(test), "--op", "--indent-op", args.indent_op, "--area", "file",
                       "--", "-op_indenter_modulus", "1141", "-op_indenter_poisson", "0.07", "-op_poisson", "0.18")
        m = re.search(r"H ([0-9.eE+-]+) GPa, E_r ([0-9.eE+-]+) GPa, E ([0-9.eE+-]+) GPa", run.stdout)
        if not check(run.returncode == 0 and m, f"test {test}: indent-op ran ({run.returncode})"):
            print(run.stdout, run.stderr)
            continue
        h, er = float(m.group(1)), float(m.group(2))
        rep = c["reported"]
        href, erref = rep["CSM Hardness at the end of loading"], rep["CSM Reduced Modulus at the end of loading"]
        E.append(er), H.append(h), Eref.append(erref), Href.append(href)
        check(abs(er / erref - 1) <= 0.05 and abs(h / href - 1) <= 0.18,
              f"test {test}: E_r {er:.2f} GPa (instrument {erref:.2f}, {100 * (er / erref - 1):+.1f}%), "
              f"H {h:.3f} GPa (instrument {href:.3f}, {100 * (h / href - 1):+.1f}%)")
    if E:
        me, mh = np.mean(E) / np.mean(Eref) - 1, np.mean(H) / np.mean(Href) - 1
        check(abs(me) <= 0.03 and abs(mh) <= 0.15,
              f"means of {len(E)} tests: E_r {np.mean(E):.2f} +- {np.std(E):.2f} GPa against {np.mean(Eref):.2f} "
              f"({100 * me:+.1f}%), H {np.mean(H):.3f} +- {np.std(H):.3f} GPa against {np.mean(Href):.3f} "
              f"({100 * mh:+.1f}%)")
    left = os.listdir(os.path.join(args.workdir, "tmp"))
    check(not left, f"--op removed its temporary curve files ({len(left)} left)")


def synthetic(args):
    """Loading P = 2 h^1.5, a hold at P_max with 5 nm of creep, unloading to 10%, a thermal-drift hold."""
    h = np.concatenate([np.linspace(0, 100, 41)[1:], 100 + np.linspace(0, 5, 6)[1:], np.linspace(105, 80, 21)[1:],
                        np.full(8, 80.0)])
    P = np.concatenate([2 * np.linspace(0, 100, 41)[1:] ** 1.5, np.full(5, 2000.0), np.linspace(2000, 200, 21)[1:],
                        np.full(8, 200.0)])
    t = np.arange(len(h), dtype=float)
    comp, drift = 0.001, 0.05
    hm = h + comp * P + drift * t  # what an instrument would record
    csv_path = os.path.join(args.workdir, "curve_um_mN.csv")
    with open(csv_path, "w") as f:
        f.write("Time (s),Depth (um),Load (mN)\n")
        for a, b, c in zip(t, hm / 1e3, P / 1e3):
            f.write(f"{a:.17g},{b:.17g},{c:.17g}\n")
    txt_path = os.path.join(args.workdir, "hysitron.txt")
    with open(txt_path, "w", encoding="latin-1") as f:
        f.write("Number of Points = %d\n\nDepth (nm)\tLoad (\xb5N)\tTime (s)\tDepth (V)\tLoad (V)\n" % len(h))
        for a, b, c in zip(hm, P, t):
            f.write(f"{a:.17g}\t{b:.17g}\t{c:.17g}\t0\t0\n")
    # NIGET's format (its file-utils.c): '#NIGET a b c d' (rows of contact, end of loading, end of hold, end of
    # unloading), then depth (nm) and force (mN), here with decimal commas and a line NIGET skips
    niget_path = os.path.join(args.workdir, "curve.niget")
    with open(niget_path, "w") as f:
        f.write("#NIGET 0 39 45 65\n")
        for k, (a, b) in enumerate(zip(hm, P / 1e3)):
            f.write(f"{a:.17g}\t{b:.17g}\n".replace(".", ",") + ("a note NIGET skips\n" if k == 10 else ""))
    c = indentcurves.read(niget_path)
    kinds = [(s[0], s[1], s[2]) for s in c["segments"]]
    check(kinds == [("loading", 0, 39), ("hold", 39, 45), ("unloading", 45, 65)], f"niget: segments {kinds}")
    err = np.max(np.abs(c["depth"] - hm)) + np.max(np.abs(c["load"] - P)) / 2000
    check(err < 1e-9 and len(c["depth"]) == len(hm), f"niget: mN to uN, decimal commas, a text line skipped: {err:.1e}")
    # the same CSV as spreadsheets export it: semicolons and decimal commas (a European locale) in UTF-8 with a
    # byte-order mark; tab-separated UTF-16 ("Unicode text"); Latin-1 with 'µN'
    rows = [(a, b, c) for a, b, c in zip(t, hm / 1e3, P)]
    variants = {"semicolon_comma.csv": ("Time (s);Depth (um);Load (\xb5N)\n", ";", True, "utf-8-sig"),
                "unicode_text.csv": ("Time (s)\tDepth (um)\tLoad (\xb5N)\n", "\t", False, "utf-16"),
                "latin1.csv": ("Time (s),Depth (um),Load (\xb5N)\n", ",", False, "latin-1")}
    ref = indentcurves.read(csv_path, "csv")
    for name, (head, sep, comma, enc) in variants.items():
        path = os.path.join(args.workdir, name)
        with open(path, "w", encoding=enc) as f:
            f.write(head)
            for r in rows:
                cells = [f"{v:.17g}" for v in r]
                f.write(sep.join(c.replace(".", ",") if comma else c for c in cells) + "\n")
        c = indentcurves.read(path, "csv")
        err = max(np.abs(c["depth"] - ref["depth"]).max(), np.abs(c["load"] - ref["load"]).max() / 2000)
        check(err < 1e-12 and c["segments"] == ref["segments"], f"{name} ({enc}): as the plain CSV: {err:.1e}")
    for path, fmt in ((csv_path, "csv"), (txt_path, "hysitron")):
        c = indentcurves.correct(indentcurves.read(path, fmt), comp, drift)
        kinds = [(s[0], s[2] - s[1] + 1) for s in c["segments"]]
        check(kinds == [("loading", 40), ("hold", 6), ("unloading", 21)], f"{fmt}: segments found {kinds}")
        err = max(np.abs(c["depth"] - h).max(), np.abs(c["load"] - P).max() / 2000)
        check(err < 1e-9, f"{fmt}: units, compliance and drift removed: worst {err:.1e}")
        d, p = indentcurves.loading_and_unloading(c)
        check(p.argmax() == 39 and d[p.argmax()] == 105.0 and len(d) == 39 + 21,
              f"{fmt}: the curve for indent-op ends its loading before P_max and starts unloading after the hold")


def bad(args):
    never = os.path.join(args.workdir, "never_unloads.csv")
    with open(never, "w") as f:
        f.write("depth_nm,load_uN\n" + "".join(f"{k},{k * k}\n" for k in range(1, 20)))
    furlong = os.path.join(args.workdir, "furlong.csv")
    with open(furlong, "w") as f:
        f.write("depth (furlong),load (uN)\n1,2\n")
    notniget = os.path.join(args.workdir, "plain.niget")
    with open(notniget, "w") as f:
        f.write("1 2\n3 4\n")
    badrows = os.path.join(args.workdir, "rows.niget")
    with open(badrows, "w") as f:
        f.write("#NIGET 0 5 3 9\n" + "".join(f"{k} {k}\n" for k in range(10)))
    for path, say in ((os.path.join(args.workdir, "nowhere.csv"), "no such file"),
                      (never, "no unloading branch"), (furlong, "unit 'furlong'"),
                      (notniget, "not a NIGET file"), (badrows, "do not rise")):
        run = measured(args, path)
        lines = run.stderr.strip().splitlines()
        check(run.returncode == 1 and len(lines) == 1 and lines[0].startswith("measured-curve.py: error: ")
              and path in lines[0] and say in lines[0], f"{os.path.basename(path)}: one line, '{say}'")


def tip_table(args):
    xls = os.path.join(args.data, "FS_XP.xls")
    path = os.path.join(args.workdir, "tip.csv")
    run = measured(args, xls, "--area", "file", "--tip-table", path)
    if not check(run.returncode == 0 and os.path.exists(path), "--tip-table: the file's tip written"):
        return
    rows = np.loadtxt(path, delimiter=",", comments="#")
    r, h = rows[:, 0], rows[:, 1]
    coef = [24.6954, 395.7700812, -16.13158277]  # the file's 'Area Coefficient' 1 to 3
    area = sum(c * h ** (2.0 / 2 ** k) for k, c in enumerate(coef))
    err = np.max(np.abs(np.pi * r[1:] ** 2 / area[1:] - 1))
    check(r[0] == 0 and h[0] == 0 and np.all(np.diff(r) > 0) and np.all(np.diff(h) > 0) and abs(h[-1] - 3000) < 1e-6,
          f"--tip-table: {len(r)} rows from 0,0 to 3000 nm, r and h rising")
    check(err < 1e-9, f"--tip-table: pi r^2 is the area function at every row ({err:.1e})")
    ratio = np.interp(727.0, h, np.pi * r ** 2) / (24.5 * 727.0 ** 2)
    check(1.02 < ratio < 1.04, f"--tip-table: {ratio:.4f} times the ideal Berkovich's area at 727 nm")
    for more, say in ((["--area=-1,0"], "does not rise"), ([], "needs --area")):
        run = measured(args, xls, *more, "--tip-table", os.path.join(args.workdir, "bad_tip.csv"))
        lines = run.stderr.strip().splitlines()
        check(run.returncode == 1 and len(lines) == 1 and say in lines[0], f"--tip-table {' '.join(more)}: '{say}'")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--indent-op", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--workdir", required=True)
    args = ap.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    fused_silica(args)
    synthetic(args)
    bad(args)
    tip_table(args)
    return status()


if __name__ == "__main__":
    sys.exit(main())
