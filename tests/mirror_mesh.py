#!/usr/bin/env python3
"""Mirrors a gmsh half model (format 2.2, ASCII, all nodes at y >= 0) across the plane y = 0.

  mirror_mesh.py HALF.msh FULL.msh --drop symmetry

Every element gets a mirrored copy with its orientation restored (two nodes swapped), nodes on the
plane are shared, and the elements of the named physical groups (the mirror plane itself) are left
out of the full model. The two halves of the result are exact mirror images, so a half-model run
with a symmetry condition must reproduce the full model's load to solver tolerance. Exit 2 on bad
input.
"""
import argparse
import sys

# gmsh element types: nodes per element, and which two local nodes to swap to undo the reflection
SWAP = {1: (2, (0, 1)), 2: (3, (1, 2)), 3: (4, (1, 3)), 4: (4, (1, 2)), 15: (1, None)}


def sections(lines):
    out, name, body = {}, None, []
    for line in lines:
        s = line.strip()
        if s.startswith("$End"):
            out[name] = body
            name, body = None, []
        elif s.startswith("$"):
            name = s[1:]
        elif name is not None:
            body.append(s)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("half")
    ap.add_argument("full")
    ap.add_argument("--drop", action="append", default=[], help="physical name whose elements are left out")
    a = ap.parse_args()
    try:
        with open(a.half) as f:
            sec = sections(f.readlines())
    except OSError as e:
        print(f"mirror_mesh.py: cannot read {a.half}: {e}")
        return 2
    if sec.get("MeshFormat", [""])[0].split()[:2] != ["2.2", "0"]:
        print(f"mirror_mesh.py: {a.half} is not an ASCII gmsh 2.2 file (mesh it with -format msh22)")
        return 2
    names = sec.get("PhysicalNames", ["0"])[1:]
    drop = {int(n.split()[1]) for n in names if n.split()[2].strip('"') in a.drop}
    if len(drop) != len(a.drop):
        print(f"mirror_mesh.py: {a.half} lacks some of the physical names {a.drop}")
        return 2
    nodes = {}
    for line in sec["Nodes"][1:]:
        t = line.split()
        nodes[int(t[0])] = [float(v) for v in t[1:4]]
    size = max(max(abs(c) for c in x) for x in nodes.values())
    if min(x[1] for x in nodes.values()) < -1e-9 * size:
        print(f"mirror_mesh.py: {a.half} has nodes at y < 0: not a half model on y >= 0")
        return 2
    image, next_id = {}, max(nodes) + 1
    for i, x in sorted(nodes.items()):
        if abs(x[1]) <= 1e-9 * size:
            image[i] = i
        else:
            image[i] = next_id
            next_id += 1
    elements = []
    for line in sec["Elements"][1:]:
        t = [int(v) for v in line.split()]
        etype, ntags = t[1], t[2]
        if etype not in SWAP:
            print(f"mirror_mesh.py: element type {etype} is not supported")
            return 2
        tags, conn = t[3:3 + ntags], t[3 + ntags:]
        if ntags and tags[0] in drop:
            continue
        elements.append((etype, tags, conn))
        mirrored = [image[n] for n in conn]
        swap = SWAP[etype][1]
        if swap:
            i, j = swap
            mirrored[i], mirrored[j] = mirrored[j], mirrored[i]
        elements.append((etype, tags, mirrored))
    with open(a.full, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$PhysicalNames\n%d\n" % len(names) + "".join(n + "\n" for n in names) + "$EndPhysicalNames\n")
        f.write("$Nodes\n%d\n" % (next_id - 1))
        for i, x in sorted(nodes.items()):
            f.write("%d %.17g %.17g %.17g\n" % (i, x[0], x[1], x[2]))
        for i, x in sorted(nodes.items()):
            if image[i] != i:
                f.write("%d %.17g %.17g %.17g\n" % (image[i], x[0], -x[1], x[2]))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for k, (etype, tags, conn) in enumerate(elements, 1):
            f.write(" ".join(str(v) for v in [k, etype, len(tags)] + tags + conn) + "\n")
        f.write("$EndElements\n")
    print(f"mirror_mesh.py: {len(nodes)} -> {next_id - 1} nodes, {len(elements)} elements in {a.full}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
