"""Maugis-Dugdale line contacts (issue 21): time and correct digits per profile.

    python benchmarks/maugis_dugdale.py [--json PATH]

For the parabola, the power law n = 3, the wedge and the worn cylinder
(E* = w = 1, lambda = 1 via sigma0_for; R = 1, c = 1, theta = 0.3, b = 1):

* derivation: the two conditions and the pressure (force, cohesive_gap,
  pressure), cold (the on-disk derivation store off), with and without the
  independent verification;
* state at 30 digits: median time of ``md.state(a, 30)`` over a = 0.05 ... 3
  (law compiled once), digits of P and c_D against the state at 60 digits;
* pull-off at 30 digits: time (law compiled once), digits against 50 digits,
  its kind and half-width.

Prints a Markdown table; writes JSON (default: benchmarks/maugis_dugdale_results.json).
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time

import mpmath

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
import linecontact_sym as lcs  # noqa: E402
from linecontact_sym.method import store  # noqa: E402
from linecontact_sym.method.verification import digits_agreeing  # noqa: E402

PROFILES = {
    "parabola": (lcs.parabola, dict(R=1)),
    "power law n=3": (lcs.power_law, dict(c=1, n=3)),
    "wedge": (lcs.wedge, dict(theta="3/10")),
    "worn cylinder": (lcs.worn_cylinder, dict(R=1, b=1)),
}
A_VALUES = ("0.05", "0.2", "0.5", "1", "1.7", "3")


def derivation_time(mk, verify):
    md = mk(verify=verify).maugis_dugdale()
    t0 = time.perf_counter()
    for q in ("zone_force", "cohesive_gap", "pressure"):
        md.derivation(q)
    return time.perf_counter() - t0


def row(name, mk, params):
    base = dict(E_star=1, gamma=1, **params)
    t_ver = derivation_time(mk, True)
    t_nover = derivation_time(mk, False)
    md = mk().maugis_dugdale()
    s0 = md.sigma0_for(1, **base)
    vals = dict(base, sigma_0=s0)
    md.state("0.7", 30, **vals)          # compile the law once
    times, dP, dc = [], [], []
    for a in A_VALUES:
        t0 = time.perf_counter()
        st = md.state(a, 30, **vals)
        times.append(time.perf_counter() - t0)
        ref = md.state(a, 60, **vals)
        with mpmath.workdps(70):
            dP.append(digits_agreeing(st.force, ref.force))
            dc.append(digits_agreeing(st.c_D, ref.c_D))
    t0 = time.perf_counter()
    po = md.pull_off_at(30, **vals)
    t_po = time.perf_counter() - t0
    po50 = md.pull_off_at(50, **vals)
    with mpmath.workdps(60):
        d_po = digits_agreeing(po.force, po50.force)
    return {"profile": name, "derive_verified_s": round(t_ver, 2), "derive_s": round(t_nover, 2),
            "state30_median_ms": round(1e3 * statistics.median(times), 2),
            "state30_max_ms": round(1e3 * max(times), 2),
            "state30_digits_P": round(min(dP), 1), "state30_digits_c": round(min(dc), 1),
            "pull_off30_s": round(t_po, 2), "pull_off30_digits": round(d_po, 1),
            "pull_off": mpmath.nstr(po.force, 20), "kind": po.kind, "half_width": mpmath.nstr(po.half_width, 10)}


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=os.path.join(os.path.dirname(__file__), "maugis_dugdale_results.json"))
    args = ap.parse_args(argv)
    store.set_enabled(False)
    rows = [row(name, mk, p) for name, (mk, p) in PROFILES.items()]
    print("| profile | derive (verified) s | derive s | state@30 median / max ms | digits P / c_D | "
          "pull-off@30 s | digits | P_min (lambda = 1) | kind |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['profile']} | {r['derive_verified_s']} | {r['derive_s']} | {r['state30_median_ms']} / "
              f"{r['state30_max_ms']} | {r['state30_digits_P']} / {r['state30_digits_c']} | {r['pull_off30_s']} | "
              f"{r['pull_off30_digits']} | {r['pull_off']} | {r['kind']} |")
    meta = {"machine": platform.platform(), "python": platform.python_version(), "cpus": os.cpu_count(),
            "load": os.getloadavg(), "when": time.strftime("%Y-%m-%d %H:%M")}
    with open(args.json, "w") as fh:
        json.dump({"meta": meta, "rows": rows}, fh, indent=1)


if __name__ == "__main__":
    main()
