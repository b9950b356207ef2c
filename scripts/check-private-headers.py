#!/usr/bin/env python3
"""The objects' insides stay in their group, and the headers form no cycle:

  check-private-headers.py [ROOT]

1. A header in src/<group>/ (a private header: an object's fields, a group's helpers) is included only by the
   files of that group, and by the white-box tests listed in WHITE_BOX (each with the group it opens and why).
2. No public header (include/**) defines an object's struct (struct _p_...): handles are opaque.
3. The includes among the headers (public and private) form no cycle.
Prints one line per violation and exits 1 on any; prints a summary line and exits 0 otherwise.
"""
import os
import re
import sys

# tests that open one group's private headers on purpose: file -> {group: why}
WHITE_BOX = {
    "tests/test_contact_newton.c": {"contact": "unit test of one contact node, built by hand"},
    "tests/test_bordered.c": {"solvers": "unit test of the bordered solve, a private object of the solvers"},
    "tests/test_matinsert.c": {"physics": "switches the assembly's cached insertion off to compare"},
    "tests/test_cell_stiffness.c": {"physics": "unit test of the kinematics' point stiffness and the cell completion"},
    "tests/bench_point_kernels.c": {"physics": "benchmark of the kinematics' point kernels, called one by one"},
    "tests/test_kept_jacobian.c": {"physics": "unit test: both Jacobians through the assembly's own matrix"},
    "tests/test_held_lu.c": {"solvers": "reads the size of the free block the section's direct solve factors"},
    "tests/test_linesearch.c": {"solvers": "unit test of depth control's line search, private to the solvers"},
    "tests/test_pcreuse.c": {"solvers": "unit test of the rule that rebuilds the multigrid, private to the solvers"},
    "tests/test_box.c": {"mesh": "unit test of the grid of ranks the box built in blocks chooses, private to the mesh"},
    "tests/solver_anatomy.c": {"contact": "diagnostic that takes the Jacobian apart",
                               "solvers": "diagnostic that takes the Jacobian apart",
                               "physics": "diagnostic that takes the Jacobian apart"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
STRUCT = re.compile(r'^\s*struct\s+_p_\w+\s*\{', re.M)


def sources(root, top):
    for d, _, files in os.walk(os.path.join(root, top)):
        for f in files:
            if f.endswith((".c", ".h", ".h.in")):
                yield os.path.relpath(os.path.join(d, f), root)


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    bad = []
    private = {}  # header name -> group
    for p in sources(root, "src"):
        parts = p.split(os.sep)
        if p.endswith(".h") and len(parts) == 3:
            private[parts[2]] = parts[1]
    files = list(sources(root, "src")) + list(sources(root, "tests")) + list(sources(root, "include"))
    graph = {}
    for p in files:
        with open(os.path.join(root, p), encoding="utf-8", errors="replace") as f:
            text = f.read()
        included = INCLUDE.findall(text)
        parts = p.split(os.sep)
        group = parts[1] if parts[0] == "src" and len(parts) == 3 else None
        for h in included:
            owner = private.get(os.path.basename(h))
            if owner is None or owner == group:
                continue
            why = WHITE_BOX.get(p, {}).get(owner)
            if not why:
                bad.append(f"{p}: includes {h}, private to src/{owner}/")
        if p.startswith("include") and STRUCT.search(text):
            bad.append(f"{p}: defines an object's struct in a public header")
        if p.endswith((".h", ".h.in")):
            graph[os.path.basename(p)] = [os.path.basename(h) for h in included]
    # cycles among headers
    state = {}

    def visit(h, path):
        state[h] = 1
        for n in graph.get(h, []):
            if n not in graph:
                continue
            if state.get(n) == 1:
                cycle = path[path.index(n):] + [n] if n in path else [h, n]
                bad.append("include cycle: " + " -> ".join(cycle))
            elif not state.get(n):
                visit(n, path + [n])
        state[h] = 2

    for h in sorted(graph):
        if not state.get(h):
            visit(h, [h])
    for line in bad:
        print(line)
    if bad:
        return 1
    groups = sorted(set(private.values()))
    print(f"ok: {len(private)} private headers in {len(groups)} groups ({', '.join(groups)}) stay in their group; "
          f"{len(WHITE_BOX)} white-box tests; no public struct; {len(graph)} headers, no include cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
