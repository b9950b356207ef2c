"""Measured load-depth curves in: readers, units, segments, corrections (scripts/measured-curve.py uses them).

A curve is a dict of numpy arrays: depth (nm), load (uN), time (s, NaN when the file has none), and
'segments': a list of (name, first, last) index ranges, each one of 'loading', 'hold', 'unloading'.

Readers:
  - Agilent / Keysight / KLA NanoSuite exports, .xls (and .xlsx through the same library): one sheet per
    test ('Test 001', ...), channels 'Displacement Into Surface' (nm), 'Load On Sample' (mN), 'Time On Sample'
    (s), the segments named in the first column. Read with xlrd (Debian's python3-xlrd).
  - Hysitron TriboScan .txt exports: a header, then the columns 'Depth (nm)', 'Load (uN)' ('µN'), 'Time (s)'.
  - CSV with a header naming a depth and a load column, each with its unit in brackets or after an underscore
    (depth_nm, "Depth (um)", load_uN, "Load (mN)"...), optionally a time column. Commas, semicolons or tabs
    separate the cells (the header's most frequent of them); with semicolons or tabs a decimal comma is read as a
    point (a spreadsheet's export in a European locale). UTF-8 with or without a byte-order mark, UTF-16 with one
    (a spreadsheet's "Unicode text"), or else Latin-1 (Windows' 'µ').
  - NIGET's own format (.niget; as NIGET's file-utils.c reads it): a first line '#NIGET a b c d', the 0-based
    rows of the contact point, of the end of loading, of the end of the hold and of the end of unloading, then
    one 'depth force' pair per line, depth in nm and force in mN, blank-separated (a decimal comma is read as a
    point; lines that are not two numbers are skipped, as NIGET does). The segments are those rows.
"""
import csv
import math
import os
import re

import numpy as np

import textfile

DEPTH_UNITS = {"nm": 1.0, "um": 1e3, "µm": 1e3, "mm": 1e6, "m": 1e9}
LOAD_UNITS = {"un": 1.0, "µn": 1.0, "mn": 1e3, "n": 1e6, "nn": 1e-3}


class CurveError(Exception):
    """A file that is not a curve indent can read: the message names the file and what is wrong."""


def _unit(name, table, what, path):
    """The factor of the unit in a column name: 'Depth (um)', 'load_mN', 'Load [µN]'."""
    m = re.search(r"[\(\[]\s*([^\)\]]+?)\s*[\)\]]\s*$", name) or re.search(r"_([A-Za-zµ]+)\s*$", name)
    if not m:
        raise CurveError(f"{path}: column '{name}' gives no unit for the {what} (e.g. '{what} (nm)')")
    unit = m.group(1).strip().lower()
    if unit not in table:
        raise CurveError(f"{path}: unit '{m.group(1)}' of column '{name}' is not one of {', '.join(table)}")
    return table[unit]


def _columns(header, path):
    """Indices of the depth, load and time columns of a header."""
    idx = {}
    for k, name in enumerate(header):
        low = name.strip().lower()
        for key, words in (("depth", ("depth", "displacement")), ("load", ("load", "force")), ("time", ("time",))):
            if key not in idx and any(low.startswith(w) for w in words):
                idx[key] = k
    for key in ("depth", "load"):
        if key not in idx:
            raise CurveError(f"{path}: no {key} column in the header {header}")
    return idx


def _table(rows, header, path, first_line):
    idx = _columns(header, path)
    fd = _unit(header[idx["depth"]], DEPTH_UNITS, "depth", path)
    fl = _unit(header[idx["load"]], LOAD_UNITS, "load", path)
    depth, load, time = [], [], []
    for n, row in enumerate(rows, start=first_line):
        if not row or not "".join(row).strip():
            continue
        try:
            depth.append(float(row[idx["depth"]]) * fd)
            load.append(float(row[idx["load"]]) * fl)
            time.append(float(row[idx["time"]]) if "time" in idx else math.nan)
        except (ValueError, IndexError):
            raise CurveError(f"{path}, line {n}: {row} holds no number in the depth or load column") from None
    return _curve(np.array(depth), np.array(load), np.array(time), None, path)


def _text(path):
    try:
        return textfile.read_text(path)
    except textfile.TextError as e:
        raise CurveError(str(e)) from None


def read_csv(path):
    lines = [l for l in _text(path).splitlines() if l.strip() and not l.lstrip().startswith("#")]
    if len(lines) < 2:
        raise CurveError(f"{path}: no header and data")
    sep = max(("\t", ";", ","), key=lines[0].count)
    rows = list(csv.reader(lines, delimiter=sep))
    if sep != ",":  # a decimal comma can only be told apart from the separator when the separator is not one
        rows = [rows[0]] + [[textfile.decimal_points(c) for c in r] for r in rows[1:]]
    return _table(rows[1:], rows[0], path, 2)


def read_hysitron(path):
    """TriboScan's export: free text, then a tab-separated header with 'Depth (nm)' and 'Load (µN)'."""
    lines = _text(path).splitlines()
    for k, line in enumerate(lines):
        cells = [c.strip() for c in line.split("\t")]
        low = [c.lower() for c in cells]
        if any(c.startswith("depth") for c in low) and any(c.startswith("load") for c in low):
            cells = [c.replace("\xb5", "u").replace("Âu", "u") for c in cells]
            return _table([l.split("\t") for l in lines[k + 1:]], cells, path, k + 2)
    raise CurveError(f"{path}: no 'Depth (nm)' / 'Load (uN)' header: not a Hysitron TriboScan export")


def read_niget(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    head = lines[0].split() if lines else []
    try:
        if len(head) != 5 or head[0] != "#NIGET":
            raise ValueError
        idx = [int(x) for x in head[1:]]
    except ValueError:
        raise CurveError(f"{path}: the first line is not '#NIGET a b c d' (four row numbers): not a NIGET file") \
            from None
    depth, load = [], []
    for line in lines[1:]:
        cells = line.replace(",", ".").split()
        try:
            d, p = float(cells[0]), float(cells[1])
        except (ValueError, IndexError):
            continue
        depth.append(d)
        load.append(p * 1e3)  # mN to uN
    n = len(depth)
    if not (0 <= idx[0] <= idx[1] <= idx[2] <= idx[3] < n):
        raise CurveError(f"{path}: rows {' '.join(map(str, idx))} of the header do not rise within the {n} rows of "
                         "data (contact, end of loading, end of hold, end of unloading)")
    segments = [("loading", idx[0], idx[1])]
    if idx[2] > idx[1]:
        segments.append(("hold", idx[1], idx[2]))
    if idx[3] > idx[2]:
        segments.append(("unloading", idx[2], idx[3]))
    return _curve(np.array(depth), np.array(load), np.full(n, math.nan), segments, path)


def read_agilent(path, test=1):
    """Test `test` (1-based) of a NanoSuite export; also the instrument's own results for it, when present."""
    try:
        import xlrd
    except ImportError:
        raise CurveError("reading .xls needs python3-xlrd (Debian): apt-get install python3-xlrd") from None
    try:
        book = xlrd.open_workbook(path)
    except Exception as e:  # xlrd raises several kinds for a file that is not a workbook
        raise CurveError(f"{path}: not an Excel workbook ({e})") from None
    name = f"Test {test:03d}"
    if name not in book.sheet_names():
        tests = [s for s in book.sheet_names() if s.startswith("Test ")]
        raise CurveError(f"{path}: no sheet '{name}' (the file has {len(tests)} tests)")
    sh = book.sheet_by_name(name)
    head, units = sh.row_values(0), sh.row_values(1)
    try:
        cd, cl, ct = (head.index(c) for c in ("Displacement Into Surface", "Load On Sample", "Time On Sample"))
    except ValueError:
        raise CurveError(f"{path}, sheet '{name}': no 'Displacement Into Surface' / 'Load On Sample' channels") \
            from None
    fd = DEPTH_UNITS.get(str(units[cd]).lower())
    fl = LOAD_UNITS.get(str(units[cl]).lower())
    if fd is None or fl is None:
        raise CurveError(f"{path}, sheet '{name}': units '{units[cd]}', '{units[cl]}' not known")
    depth, load, time, marks = [], [], [], []
    for r in range(2, sh.nrows):
        label = str(sh.cell_value(r, 0)).lower()
        if label == "end":
            break
        if label:
            marks.append((label, len(depth)))
        v = [sh.cell_value(r, c) for c in (cd, cl, ct)]
        if not all(isinstance(x, float) for x in v) or any(abs(x) > 1e300 for x in v):
            continue
        depth.append(v[0] * fd)
        load.append(v[1] * fl)
        time.append(v[2])
    segments = []
    for k, (label, start) in enumerate(marks):
        end = (marks[k + 1][1] if k + 1 < len(marks) else len(depth)) - 1
        kind = ("unloading" if "unload" in label else "hold" if "hold" in label and "drift" not in label
                else "loading" if label.startswith("load") else None)
        if kind and end > start:
            segments.append((kind, start, end))
    c = _curve(np.array(depth), np.array(load), np.array(time), segments or None, path)
    c["reported"] = _agilent_results(book, test)
    c["reported"].update(_agilent_csm_end(sh, head, cd))
    return c


def _agilent_csm_end(sh, head, cd):
    """The instrument's continuous-stiffness values at the end of loading: the means of its channels 'Hardness',
    'Modulus' and 'Reduced Modulus' over the loading points deeper than 90% of the loading's largest depth."""
    cols = {k: head.index(k) for k in ("Hardness", "Modulus", "Reduced Modulus") if k in head}
    rows = []
    for r in range(2, sh.nrows):
        if str(sh.cell_value(r, 0)).lower() not in ("", "load segment type"):
            break
        rows.append(r)
    depth = [sh.cell_value(r, cd) for r in rows]
    deepest = max(d for d in depth if isinstance(d, float) and d < 1e300)
    out = {}
    for name, k in cols.items():
        v = [sh.cell_value(r, k) for r, d in zip(rows, depth)
             if isinstance(d, float) and 0.9 * deepest <= d < 1e300 and isinstance(sh.cell_value(r, k), float)
             and 0 < sh.cell_value(r, k) < 1e300]
        if v:
            out[f"CSM {name} at the end of loading"] = float(np.mean(v))
    return out


def _agilent_results(book, test):
    """The instrument's E and H of the test from the sheet 'Results' (GPa), with the columns' names."""
    if "Results" not in book.sheet_names():
        return {}
    sh = book.sheet_by_name("Results")
    head = sh.row_values(0)
    for r in range(2, sh.nrows):
        if str(sh.cell_value(r, 0)).strip() in (str(test), f"{test}.0"):
            return {h: sh.cell_value(r, k) for k, h in enumerate(head) if isinstance(sh.cell_value(r, k), float)}
    return {}


def _curve(depth, load, time, segments, path):
    if len(depth) < 5:
        raise CurveError(f"{path}: {len(depth)} points; a curve needs a loading and an unloading branch")
    c = {"depth": depth, "load": load, "time": time, "path": path}
    c["segments"] = segments or find_segments(load)
    if not any(s[0] == "unloading" for s in c["segments"]):
        raise CurveError(f"{path}: no unloading branch (the load never falls from its maximum)")
    return c


def find_segments(load, hold_tol=0.01):
    """Loading up to the first point within hold_tol of the largest load, a hold while the load stays there,
    unloading while it then falls (it ends where the load stops falling: a thermal-drift hold or the end)."""
    pmax = load.max()
    top = int(np.argmax(load >= (1 - hold_tol) * pmax))
    last = top
    while last + 1 < len(load) and load[last + 1] >= (1 - hold_tol) * pmax:
        last += 1
    imax = top + int(np.argmax(load[top:last + 1]))
    end = max(last, imax)
    stop = end
    while stop + 1 < len(load) and load[stop + 1] < load[stop]:
        stop += 1
    seg = [("loading", 0, top)]
    if end > top:
        seg.append(("hold", top, end))
    if stop > end:
        seg.append(("unloading", end, stop))
    return seg


def read(path, fmt="auto", test=1):
    ext = os.path.splitext(path)[1].lower()
    if not os.path.isfile(path):
        raise CurveError(f"{path}: no such file")
    if fmt == "auto":
        fmt = {".xls": "agilent", ".xlsx": "agilent", ".txt": "hysitron", ".csv": "csv", ".niget": "niget"}.get(ext)
        if fmt is None:
            raise CurveError(f"{path}: cannot tell the format from '{ext}': give --format")
    readers = {"agilent": lambda: read_agilent(path, test), "hysitron": lambda: read_hysitron(path),
               "csv": lambda: read_csv(path), "niget": lambda: read_niget(path)}
    if fmt not in readers:
        raise CurveError(f"--format {fmt}: not one of {', '.join(readers)}")
    return readers[fmt]()


def correct(curve, compliance=0.0, drift=0.0):
    """Frame compliance (nm/uN: h -= C P) and thermal drift (nm/s: h -= rate t, t from the first point)."""
    h = curve["depth"] - compliance * curve["load"]
    if drift:
        t = curve["time"]
        if np.isnan(t).any():
            raise CurveError(f"{curve['path']}: a drift correction needs the time of every point")
        h = h - drift * (t - t[0])
    out = dict(curve)
    out["depth"] = h
    return out


def loading_and_unloading(curve):
    """The loading from first contact (load > 0 and depth > 0) and the unloading, as indent-op reads them: its
    largest load is the unloading's first point, so that h_max is the depth after the hold's creep."""
    seg = {kind: (a, b) for kind, a, b in curve["segments"]}
    ua, ub = seg["unloading"]
    la, lb = seg.get("loading", (0, -1))
    top = curve["load"][ua]
    keep = [i for i in range(la, lb + 1) if curve["load"][i] < top] + list(range(ua, ub + 1))
    keep = [i for i in keep if curve["load"][i] > 0 and curve["depth"][i] > 0]
    return curve["depth"][keep], curve["load"][keep]


def write_csv(path, depth, load):
    with open(path, "w") as f:
        f.write("depth_nm,load_uN\n")
        for h, p in zip(depth, load):
            f.write(f"{h:.10g},{p:.10g}\n")
