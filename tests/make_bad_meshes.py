#!/usr/bin/env python3
"""Broken gmsh files for the bad-input tests, made from good ones at build time.

make_bad_meshes.py CUBE41 CUBE22 OUTDIR writes into OUTDIR:
  truncated.msh  the first 60% of CUBE41 (format 4.1): a file cut short, with no $End... line at its end
  corrupt.msh    the first half of CUBE41 closed by a stray $EndElements line: it looks whole, the reader
                 fails inside
  ghost.msh      CUBE22 (format 2.2) with a physical volume "ghost" that has no elements
  lid.msh        CUBE22 with a physical surface "lid" that has no elements
"""
import os
import sys


def with_physical(text, lines):
    head = "$PhysicalNames\n"
    i = text.index(head) + len(head)
    j = text.index("\n", i)
    n = int(text[i:j])
    return text[:i] + "%d\n" % (n + len(lines)) + "".join(l + "\n" for l in lines) + text[j + 1:]


def main():
    cube41, cube22, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    data = open(cube41, "rb").read()
    open(os.path.join(out, "truncated.msh"), "wb").write(data[: int(0.6 * len(data))])
    open(os.path.join(out, "corrupt.msh"), "wb").write(data[: len(data) // 2] + b"\n$EndElements\n")
    text = open(cube22).read()
    open(os.path.join(out, "ghost.msh"), "w").write(with_physical(text, ['3 9 "ghost"']))
    open(os.path.join(out, "lid.msh"), "w").write(with_physical(text, ['2 19 "lid"']))


if __name__ == "__main__":
    main()
