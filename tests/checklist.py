"""The ok/FAIL lines of the check scripts: check(ok, what) prints one and counts it; status() is the scripts' exit
status, 1 after any failure."""
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)
    return ok


def status():
    return 1 if failures else 0
