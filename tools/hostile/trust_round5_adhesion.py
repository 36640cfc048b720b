"""Hostile sweep over adhesion (issue 42, round 5, trustB): the Maugis-Dugdale
pull-off of several profiles from sigma_0 = 1e-6 to 1e300, the gap of an MD
state at the end of its cohesive zone, and the JKR pull-off of 1 - cos(x)
across the work of adhesion.

Each case runs in its own process under a wall-clock limit and a memory cap;
it counts as ok when it returns a number that passes its check, or ends in a
clear package error (a LineContactError), within the limit.  Not ok: a
timeout (a hang), a crash (GMP abort, memory), a foreign exception, a number
that fails its check (the MD pull-off against the package's JKR pull-off
where lambda is huge, against the rigid Dugdale limit -2 sigma_0 c_r,
f(c_r) = h0, where sigma_0 is tiny, and between P(0+) and 0 otherwise; a
complex gap; a statement of a NoPullOffError contradicted by its own
extrema).

Run (from a worktree; compare two trees by their PYTHONPATH):

    PYTHONPATH=/work/main python tools/hostile/trust_round5_adhesion.py --tag before
    PYTHONPATH=$PWD       python tools/hostile/trust_round5_adhesion.py --tag after

Options: --timeout S (per case, default 40), --only SUBSTRING (cases whose
name contains it).  Prints one line per case and the counts.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

PROFILES = {
    "parabola": ("x**2/(2*R)", {"R": 1}),
    "cosh": ("R*(cosh(x/R) - 1)", {"R": 1}),
    "rounded_punch": ("rounded_punch", {"R": 1, "b": 1}),
    "power3": ("x**3", {}),
    "one_minus_cos": ("1 - cos(x)", {}),
}
SIGMAS = ["1e-6", "1/4", "1000", "10**20", "10**100", "1e300"]

CASE = r'''
import json, resource, sys, mpmath, sympy as sp
resource.setrlimit(resource.RLIMIT_AS, (2500 * 2**20, 2500 * 2**20))
import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError
spec = json.loads(sys.argv[1])
out = {}
try:
    kind = spec["kind"]
    if spec["profile"] == "rounded_punch":
        c = lcs.rounded_punch(verify=False)
    else:
        c = lcs.LineContact(sp.sympify(spec["profile"], locals={"R": sp.Symbol("R", positive=True)}), verify=False)
    vals = dict(spec["values"])
    if kind == "md_pull_off":
        md = c.maugis_dugdale()
        s0 = sp.sympify(spec["sigma0"])
        po = md.pull_off_at(15, E_star=1, gamma=spec["gamma"], sigma_0=s0, **vals)
        out["force"] = float(po.force)
        try:
            pj = c.adhesive().pull_off_at(15, E_star=1, gamma=spec["gamma"], **vals)
            out["jkr"] = float(pj.force)
        except LineContactError:
            out["jkr"] = None
        from linecontact_sym.contacts.adhesion.maugis.check import rigid_limit
        try:
            out["rigid"] = float(rigid_limit(md, 15, E_star=1, gamma=spec["gamma"], sigma_0=s0, **vals))
        except Exception:
            out["rigid"] = None
        out["p0plus"] = float(md.numeric_law(E_star=1, gamma=spec["gamma"], sigma_0=s0, **vals).force_zero_width(15)) \
            if float(s0) < 1e6 else None
    elif kind == "md_gap":
        md = c.maugis_dugdale()
        st = md.state(sp.Rational(1, 2), 20, E_star=1, gamma=spec["gamma"], sigma_0=spec["sigma0"], **vals)
        g = st.gap(st.c_D)
        out["gap_complex"] = isinstance(g, mpmath.mpc)
        out["gap"] = float(mpmath.re(g))
        out["h0"] = float(st.h0)
    elif kind == "jkr_pull_off":
        po = c.adhesive().pull_off_at(15, E_star=1, gamma=spec["gamma"], **vals)
        out["force"] = float(po.force)
        out["minima"] = [(e.kind, float(e.force)) for e in po.minima]
        out["kind"] = po.kind
    out["status"] = "value"
except LineContactError as exc:
    out["status"] = "package_error"
    out["error"] = f"{type(exc).__name__}: {str(exc)[:300]}"
except Exception as exc:
    out["status"] = "foreign"
    out["error"] = f"{type(exc).__name__}: {str(exc)[:300]}"
print("RESULT " + json.dumps(out))
'''


def cases():
    for name, (prof, vals) in PROFILES.items():
        for s0 in SIGMAS:
            yield f"md_pull_off/{name}/sigma0={s0}", dict(kind="md_pull_off", profile=prof, values=vals,
                                                           sigma0=s0, gamma="1/100")
    for name in ("parabola", "cosh", "one_minus_cos"):
        prof, vals = PROFILES[name]
        yield f"md_gap/{name}", dict(kind="md_gap", profile=prof, values=vals, sigma0="1", gamma="1/10")
    for g in ("1/100", "1/2", "1", "2"):
        prof, vals = PROFILES["one_minus_cos"]
        yield f"jkr_pull_off/one_minus_cos/gamma={g}", dict(kind="jkr_pull_off", profile=prof, values=vals,
                                                           gamma=g)


def judge(spec, res):
    """(ok, why) of a finished case."""
    if res["status"] == "foreign":
        return False, "foreign exception: " + res["error"]
    if res["status"] == "package_error":
        err = res["error"]
        if "decreases up to" in err and spec["kind"] == "jkr_pull_off":
            return False, "a statement its extrema may contradict: " + err[:120]
        return True, "package error: " + err[:120]
    if spec["kind"] == "md_gap":
        if res["gap_complex"]:
            return False, "complex gap at c_D"
        return abs(res["gap"] - res["h0"]) < 1e-10 * res["h0"], f"gap {res['gap']} vs h0 {res['h0']}"
    if spec["kind"] == "jkr_pull_off":
        lower = [f for k, f in res["minima"] if k != "end"]
        if lower and res["kind"] == "end":
            return False, "the end taken over a stationary/kink minimum"
        return res["force"] < 0, f"P = {res['force']:.8g} ({res['kind']})"
    P, J, rig, p0 = res["force"], res.get("jkr"), res.get("rigid"), res.get("p0plus")
    s0 = float(eval(spec["sigma0"].replace("^", "**")))
    if not P < 0:
        return False, f"P = {P} not tensile"
    if s0 >= 1e20 and J is not None:
        return abs(P - J) <= 1e-9 * abs(J), f"P = {P:.12g} vs JKR {J:.12g}"
    if s0 <= 1e-6 and rig is not None:
        return abs(P - rig) <= 1e-2 * abs(rig), f"P = {P:.8g} vs rigid {rig:.8g}"
    if p0 is not None and not P <= p0 + 1e-12 * abs(p0):
        return False, f"P = {P} above P(0+) = {p0}"
    return True, f"P = {P:.10g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tag", default="run")
    ap.add_argument("--timeout", type=float, default=40.0)
    ap.add_argument("--only", default="")
    args = ap.parse_args()
    n = ok = 0
    for name, spec in cases():
        if args.only and args.only not in name:
            continue
        n += 1
        t0 = time.time()
        try:
            p = subprocess.run([sys.executable, "-c", CASE, json.dumps(spec)], capture_output=True, text=True,
                               timeout=args.timeout, env=dict(os.environ))
            line = [ln for ln in p.stdout.splitlines() if ln.startswith("RESULT ")]
            if not line:
                good, why = False, f"crash (exit {p.returncode}): {p.stderr.strip().splitlines()[-1:]}"
            else:
                good, why = judge(spec, json.loads(line[-1][7:]))
        except subprocess.TimeoutExpired:
            good, why = False, f"no answer within {args.timeout:g} s"
        ok += bool(good)
        print(f"[{args.tag}] {'ok ' if good else 'BAD'} {name:45s} {time.time() - t0:6.1f} s  {why}", flush=True)
    print(f"[{args.tag}] cases {n}, ok {ok}, not ok {n - ok}")


if __name__ == "__main__":
    main()
