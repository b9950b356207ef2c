#!/usr/bin/env python3
"""The fault matrix: every probe of a fault or an odd input (ctest label `faults`: bad inputs, damaged
checkpoints, a live run's directory, kills, signals, results withheld, reproducibility) run, and printed
as a table of what each probe does, what it expects and what it got.

  scripts/fault-matrix.py [--build build] [-j 2] [--label faults] [--no-run] [--out FILE.md]

Runs `ctest -L <label>` in the build directory (unless --no-run: the last results of those tests, from
ctest's Testing/Temporary/LastTest.log), then prints one Markdown row per test: the probe (the test's
name), what it expects (for a bad input, the start of the one line it must print; for a scripted check,
the first line of its checker's description; for a test with a pass expression, that expression) and
what it got (passed, or FAILED with the error line it printed). Exit status 0 when every probe passed,
1 otherwise, 2 on bad arguments.
"""
import argparse
import json
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def tests(build, label):
    """name -> (command list, properties dict) of the tests with the label."""
    out = subprocess.run(["ctest", "-L", label, "--show-only=json-v1"], cwd=build, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, check=True).stdout
    found = {}
    for t in json.loads(out).get("tests", []):
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        found[t["name"]] = (t.get("command", []), props)
    return found


def expectation(command, props):
    """What the test expects, in a few words."""
    for k, word in enumerate(command):
        if word.endswith("expect_error.sh"):
            args = command[k + 1:]
            while args and args[0].startswith("--"):
                args = args[1 if args[0] == "--after-output" else 2:]
            if args:
                return "error: " + args[0].replace("\\", "")
    for word in command:
        if word.endswith(".py") and os.path.exists(word):
            with open(word) as f:
                text = f.read()
            doc = re.search(r'"""(.*?)(\n|""")', text, re.S)
            if doc:
                return doc.group(1).strip()
    if "PASS_REGULAR_EXPRESSION" in props:
        value = props["PASS_REGULAR_EXPRESSION"]
        return "prints: " + (value[0] if isinstance(value, list) else value).replace("\\", "")
    return "exit 0"


def results(build):
    """name -> (passed, output) from ctest's last log."""
    path = os.path.join(build, "Testing", "Temporary", "LastTest.log")
    out = {}
    if not os.path.exists(path):
        return out
    with open(path, errors="replace") as f:
        text = f.read()
    starts = [(m.start(), m.group(1)) for m in re.finditer(r"^\d+/\d+ Testing: (\S+)", text, re.M)]
    for k, (at, name) in enumerate(starts):
        block = text[at:starts[k + 1][0] if k + 1 < len(starts) else len(text)]
        if re.search(r"^(Test Passed\.|Test Pass Reason:)", block, re.M):
            out[name] = (True, block)
        elif re.search(r"^Test Failed\.", block, re.M):
            out[name] = (False, block)
    return out


def got(passed, output):
    if passed:
        return "passed"
    line = next((l for l in output.splitlines() if ": error: " in l or l.startswith("FAIL")), "")
    return "FAILED" + (": " + line.strip() if line else "")


def cell(text, width=140):
    text = " ".join(text.split()).replace("|", "\\|")
    return text if len(text) <= width else text[:width - 3] + "..."


def main():
    ap = argparse.ArgumentParser(prog="fault-matrix.py", description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("-j", type=int, default=2, help="tests run at once")
    ap.add_argument("--label", default="faults")
    ap.add_argument("--no-run", action="store_true", help="report the last results instead of running")
    ap.add_argument("--out", help="also write the table to this Markdown file")
    args = ap.parse_args()
    if not os.path.isdir(args.build):
        print(f"fault-matrix.py: error: no build directory '{args.build}' (scripts/build.sh makes it)", file=sys.stderr)
        return 2
    last = results(args.build) if args.no_run else {}  # listing the tests below rewrites ctest's log
    found = tests(args.build, args.label)
    if not found:
        print(f"fault-matrix.py: error: no test has the label '{args.label}'", file=sys.stderr)
        return 2
    if not args.no_run:
        subprocess.run(["ctest", "-L", args.label, "-j", str(args.j)], cwd=args.build, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        last = results(args.build)
    rows = ["| probe | expected | got |", "|---|---|---|"]
    bad = 0
    for name in sorted(found):
        command, props = found[name]
        passed, output = last.get(name, (False, "not run"))
        bad += not passed
        outcome = got(passed, output) if name in last else "not run"
        rows.append(f"| `{name}` | {cell(expectation(command, props))} | {cell(outcome)} |")
    table = "\n".join(rows)
    print(table)
    print(f"\n{len(found) - bad} of {len(found)} probes as expected")
    if args.out:
        with open(args.out, "w") as f:
            f.write(table + "\n")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
