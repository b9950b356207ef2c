"""Height maps as AFM software keeps them: Gwyddion Simple Field (.gsf) and plain 'x y z' lines (.xyz).
Shared by export-curves.py (which writes a run's imprint) and the inverse fit (which reads a measured one).

A map here is a HeightMap: flat arrays x, y, z in nm, one entry per pixel or point.
"""
import os
import re

import numpy as np

import textfile

GSF_MAGIC = b"Gwyddion Simple Field 1.0\n"
# Gwyddion keeps base SI units; these are the lengths a map's XYUnits / ZUnits may name, in nm
UNITS_NM = {"m": 1e9, "mm": 1e6, "um": 1e3, "\u00b5m": 1e3, "nm": 1.0, "A": 0.1, "\u00c5": 0.1, "pm": 1e-3}


class MapError(Exception):
    """A missing or malformed height map: reported in one line."""


class HeightMap:
    def __init__(self, x, y, z, path=""):
        self.x, self.y, self.z = (np.asarray(a, float).ravel() for a in (x, y, z))
        self.path = path
        if not (len(self.x) == len(self.y) == len(self.z)):
            raise MapError(f"{path}: x, y and z of different lengths")
        if len(self.z) < 16 or not np.all(np.isfinite(self.z)):
            bad = "fewer than 16 points" if len(self.z) < 16 else "a height that is not a number"
            raise MapError(f"{path}: {bad}")


def grid_axis(half, pixels):
    """Pixel centres of a grid of the given half-width, as Gwyddion places them (XOffset + (j + 1/2) dx)."""
    step = 2 * half / pixels
    return -half + (np.arange(pixels) + 0.5) * step


def write_gsf(path, grid, half, title):
    """Gwyddion Simple Field 1.0 of a square grid (nm) centred on the origin: the magic line, 'name = value'
    lines, 1 to 4 NUL bytes to a multiple of 4, then XRes x YRes little-endian float32 in metres, row by row
    (row i at y = YOffset + (i + 1/2) dy)."""
    m = 1e-9
    header = (f"Gwyddion Simple Field 1.0\nXRes = {grid.shape[1]}\nYRes = {grid.shape[0]}\n"
              f"XReal = {2 * half * m:.10g}\nYReal = {2 * half * m:.10g}\nXOffset = {-half * m:.10g}\n"
              f"YOffset = {-half * m:.10g}\nTitle = {title}\nXYUnits = m\nZUnits = m\n").encode("ascii")
    with open(path, "wb") as f:
        f.write(header + b"\0" * (4 - len(header) % 4))
        f.write((grid * m).astype("<f4").tobytes(order="C"))
    print(f"wrote {path}")


def _unit(header, key, path):
    name = header.get(key, "m")
    if name not in UNITS_NM:
        raise MapError(f"{path}: {key} '{name}' is not a length ({', '.join(UNITS_NM)})")
    return UNITS_NM[name]


def read_gsf(path):
    """A Gwyddion Simple Field file as a HeightMap in nm (pixel centres; NaN pixels, Gwyddion's masked
    ones, left out)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise MapError(f"{path}: {e.strerror}") from None
    if not data.startswith(GSF_MAGIC):
        raise MapError(f"{path}: not a Gwyddion Simple Field file (no 'Gwyddion Simple Field 1.0' line)")
    end = data.find(b"\0")
    if end < 0:
        raise MapError(f"{path}: no NUL byte ends the header")
    header = {}
    for line in data[len(GSF_MAGIC):end].decode("utf-8", "replace").splitlines():
        if "=" in line:
            k, v = line.split("=", 1)
            header[k.strip()] = v.strip()
    try:
        nx, ny = int(header["XRes"]), int(header["YRes"])
        xreal, yreal = float(header.get("XReal", nx)), float(header.get("YReal", ny))
        x0, y0 = float(header.get("XOffset", 0.0)), float(header.get("YOffset", 0.0))
    except KeyError as e:
        raise MapError(f"{path}: the header has no {e.args[0]}") from None
    except ValueError as e:
        raise MapError(f"{path}: a header value is not a number ({e})") from None
    if nx < 1 or ny < 1 or not (xreal > 0 and yreal > 0):
        raise MapError(f"{path}: XRes, YRes, XReal and YReal must be positive")
    start = end + (4 - end % 4)  # 1 to 4 NUL bytes pad the header to a multiple of 4
    if len(data) - start != 4 * nx * ny:
        raise MapError(f"{path}: {len(data) - start} bytes of data for {nx} x {ny} float32 pixels ({4 * nx * ny})")
    xy, zs = _unit(header, "XYUnits", path), _unit(header, "ZUnits", path)
    z = np.frombuffer(data, "<f4", nx * ny, start).astype(float).reshape(ny, nx) * zs
    gx = (x0 + (np.arange(nx) + 0.5) * xreal / nx) * xy
    gy = (y0 + (np.arange(ny) + 0.5) * yreal / ny) * xy
    X, Y = np.meshgrid(gx, gy)
    keep = np.isfinite(z)
    return HeightMap(X[keep], Y[keep], z[keep], path)


def read_xyz(path, unit="nm"):
    """'x y z' lines (spaces, tabs, commas or semicolons; with tabs or semicolons a decimal comma is a point; '#'
    comments; a header line of names is skipped; UTF-8, UTF-16 or Latin-1, textfile.py) in `unit`."""
    if unit not in UNITS_NM:
        raise MapError(f"{path}: unit '{unit}' is not a length ({', '.join(UNITS_NM)})")
    rows = []
    try:
        for k, line in enumerate(textfile.read_text(path).splitlines(), 1):
            line = line.split("#", 1)[0]
            if ";" in line or "\t" in line:  # then a comma is a decimal comma
                line = " ".join(textfile.decimal_points(c) for c in re.split(r"[;\t]", line))
            words = line.replace(",", " ").split()
            if not words:
                continue
            try:
                vals = [float(w) for w in words]
            except ValueError:
                if not rows and k <= 1:
                    continue  # a header of column names
                raise MapError(f"{path}:{k}: not three numbers: {line.strip()[:60]}") from None
            if len(vals) != 3:
                raise MapError(f"{path}:{k}: {len(vals)} numbers, not 3 (x y z)")
            rows.append(vals)
    except OSError as e:
        raise MapError(f"{path}: {e.strerror}") from None
    except textfile.TextError as e:
        raise MapError(str(e)) from None
    if not rows:
        raise MapError(f"{path}: no 'x y z' lines")
    a = np.array(rows) * UNITS_NM[unit]
    return HeightMap(a[:, 0], a[:, 1], a[:, 2], path)


def read_map(path, unit="nm"):
    """A .gsf (its own units) or any other file as 'x y z' lines in `unit`."""
    if os.path.splitext(path)[1].lower() == ".gsf":
        return read_gsf(path)
    return read_xyz(path, unit)
