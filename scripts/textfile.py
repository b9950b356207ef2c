"""Text files as spreadsheets and instruments save them, for the readers of measured data (indentcurves.py,
heightmap.py): the encoding told by the byte-order mark, and decimal commas where the cells are not comma-separated.
"""
import re


class TextError(Exception):
    """A file that cannot be read as text: the message names it."""


def read_text(path):
    """A text file's contents: UTF-16 when its byte-order mark says so, else UTF-8 (with or without a mark), else
    Latin-1 (Windows' 'µ' as one byte)."""
    with open(path, "rb") as f:
        raw = f.read()
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        try:
            return raw.decode("utf-16")
        except UnicodeDecodeError:
            raise TextError(f"{path}: marked as UTF-16 but not UTF-16 text") from None
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def decimal_points(cell):
    """A decimal comma (a European locale's '0,35') made a point; only for cells that commas do not separate."""
    return re.sub(r"^(\s*[-+]?\d*),(\d)", r"\1.\2", cell)
