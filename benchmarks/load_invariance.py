"""Results that do not depend on the machine's load (issue 26): the same cold
derivations, pull-offs and the paper's verdicts, quiet and with three busy
loops per core.

    python benchmarks/load_invariance.py [--no-paper]

Each side runs in fresh processes with an empty derivation cache and the
default budget (CPU seconds).  Prints, per item, the result's fingerprint
(closed or not, the srepr's hash, the verdict) quiet and loaded, the wall
times, and whether they are identical; exits 1 if any differs.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

ITEMS = """
import hashlib, json, sys, time
import sympy as sp
import linecontact_sym as lcs
def fp(d):
    return ("closed" if d.closed_form else "integral") + ":" + hashlib.sha256(sp.srepr(d.expr).encode()).hexdigest()[:12]
out = {}
def item(name, fn):
    t0 = time.monotonic()
    out[name] = [fn(), round(time.monotonic() - t0, 1)]
for prof in ("worn_cylinder", "exact_cylinder"):
    for q in ("pressure", "gap"):
        item(f"{prof} {q}", lambda: fp(getattr(lcs, prof)().derivation(q)))
item("power law pressure (symbolic n)", lambda: fp(lcs.power_law().derivation("pressure")))
item("rounded punch pressure", lambda: fp(lcs.rounded_punch().derivation("pressure")))
item("MD conditions, parabola", lambda: hashlib.sha256(sp.srepr(lcs.parabola().maugis_dugdale().conditions).encode()).hexdigest()[:12])
item("JKR pull-off of c x^4", lambda: fp(lcs.LineContact(lcs.c * lcs.x**4).adhesive(lcs.gamma).derivation("pull_off_force")))
print(json.dumps(out))
"""


def run_items(cache):
    env = dict(os.environ, LINECONTACT_SYM_CACHE=cache, PYTHONPATH=ROOT)
    env.pop("LINECONTACT_SYM_BUDGET", None)
    r = subprocess.run([sys.executable, "-c", ITEMS], env=env, capture_output=True, text=True, timeout=3600)
    if r.returncode:
        raise SystemExit(r.stderr[-3000:])
    return json.loads(r.stdout.strip().splitlines()[-1])


def run_paper(cache, out):
    env = dict(os.environ, LINECONTACT_SYM_CACHE=cache, PYTHONPATH=ROOT)
    env.pop("LINECONTACT_SYM_BUDGET", None)
    t0 = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "linecontact_sym", "paper", "popov2017", "--no-figures", "--quiet",
                        "--out", out], env=env, capture_output=True, text=True, timeout=7200)
    wall = time.monotonic() - t0
    try:
        with open(os.path.join(out, "results.json")) as fh:
            verdicts = {c["label"]: c["verdict"] for c in json.load(fh)["claims"]}
    except (OSError, ValueError, KeyError):
        verdicts = {"exit": r.returncode, "stderr": hashlib.sha256(r.stderr.encode()).hexdigest()[:12]}
    return verdicts, wall


def side(loaded: bool, paper: bool):
    loops = []
    if loaded:
        code = "import time\nt = time.monotonic() + 3600\nwhile time.monotonic() < t:\n    pass\n"
        loops = [subprocess.Popen([sys.executable, "-c", code]) for _ in range(3 * (os.cpu_count() or 1))]
    try:
        with tempfile.TemporaryDirectory(prefix="lcs-load-") as tmp:
            items = run_items(os.path.join(tmp, "c1"))
            verdicts, wall = run_paper(os.path.join(tmp, "c2"), os.path.join(tmp, "out")) if paper else ({}, 0.0)
    finally:
        for p in loops:
            p.kill()
            p.wait()
    return items, verdicts, wall


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-paper", action="store_true")
    args = ap.parse_args(argv)
    quiet = side(False, not args.no_paper)
    loaded = side(True, not args.no_paper)
    same = True
    print(f"machine: {os.cpu_count()} cores; busy loops while loaded: {3 * (os.cpu_count() or 1)}")
    print("| item | quiet | loaded | wall quiet / loaded [s] | identical |")
    print("|---|---|---|---|---|")
    for k in quiet[0]:
        q, lo = quiet[0][k], loaded[0][k]
        ok = q[0] == lo[0]
        same &= ok
        print(f"| {k} | {q[0]} | {lo[0]} | {q[1]} / {lo[1]} | {'yes' if ok else 'NO'} |")
    if not args.no_paper:
        ok = quiet[1] == loaded[1]
        same &= ok
        print(f"| paper popov2017 verdicts ({len(quiet[1])} claims) | "
              f"{sum(v == 'holds' for v in quiet[1].values())} hold | "
              f"{sum(v == 'holds' for v in loaded[1].values())} hold | {quiet[2]:.0f} / {loaded[2]:.0f} | "
              f"{'yes' if ok else 'NO'} |")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
