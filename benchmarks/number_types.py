"""Hostile sweep: every public numeric entry point x every kind of exact or
foreign number a user may pass (issue 19 item 1).

Each case passes one number type in one slot of one entry point and compares
the result with a reference computed here directly from the textbook formula
of the Hertz line contact (parabola f = x**2/(2R)) with mpmath at 60 digits,
never through the package:

    P(a) = pi E* a^2 / (4R),   p(x) = E*/(2R) sqrt(a^2 - x^2),
    a(P) = sqrt(4 R P / (pi E*)),  c/a = sqrt(1 - Q/(mu P)) (Cattaneo-Mindlin),
    sigma_z(0, z) = -p0 a / sqrt(a^2 + z^2), p0 = E* a / (2R) (McEwen).

A case is ok when it returns without error and agrees with the reference to
the digits the entry point promises (28 for a 40-digit request fed a 31-digit
decimal, ~12 for float64 paths).

    python benchmarks/number_types.py            # table + counts
"""
from __future__ import annotations

import decimal
import fractions
import sys
import time
import traceback

import mpmath
import numpy as np
import sympy as sp

import linecontact_sym as lcs

MP = mpmath.mp.clone() if hasattr(mpmath.mp, "clone") else None
D31 = "0.3333333333333333333333333333333"          # 31 significant digits
F40 = "0.7071067811865475244008443621048490392848"  # 40 digits


def numbers():
    """(label, value, exact value as a 60-digit mpf)"""
    with mpmath.workdps(60):
        return [
            ("sqrt(3)/2", sp.sqrt(3) / 2, mpmath.sqrt(3) / 2),
            ("pi/4", sp.pi / 4, mpmath.pi / 4),
            ("E/4", sp.E / 4, mpmath.e / 4),
            ("exp(-1)", sp.exp(-1), mpmath.exp(-1)),
            ("Rational", sp.Rational(1, 3), mpmath.mpf(1) / 3),
            ("Integer", sp.Integer(1) / 2 * 0 + sp.Rational(1, 2), mpmath.mpf(1) / 2),
            ("Float40", sp.Float(F40, 40), mpmath.mpf(sp.Float(F40, 40))),
            ("Fraction", fractions.Fraction(2, 7), mpmath.mpf(2) / 7),
            ("Decimal31", decimal.Decimal(D31), mpmath.mpf(D31)),
            ("str31", D31, mpmath.mpf(D31)),
            ("np.float64", np.float64(0.3), mpmath.mpf(0.3)),
            ("np.float32", np.float32(0.3), mpmath.mpf(float(np.float32(0.3)))),
            ("np.0d", np.array(0.375), mpmath.mpf("0.375")),
            ("np.int64", np.int64(1), mpmath.mpf(1)),
        ]


def digits(got, ref):
    with mpmath.workdps(60):
        got = mpmath.mpf(got) if not isinstance(got, (mpmath.mpf, np.ndarray)) else \
            mpmath.mpf(float(got)) if isinstance(got, np.ndarray) else got
        if ref == 0:
            return 60 if got == 0 else float(-mpmath.log10(abs(got)))
        err = abs(got - ref) / abs(ref)
        return 60.0 if err == 0 else float(-mpmath.log10(err))


def cases():
    c = lcs.parabola()
    ad = c.adhesive()
    t = c.tangential()
    st = c.stresses()
    pi = mpmath.pi
    E1 = dict(R=1, E_star=1)

    def p_ref(x, a=1, R=1, E=1):
        return E / (2 * R) * mpmath.sqrt(a * a - x * x)

    # entry point: (label, call(v), reference(V), digits needed for a 31-digit input,
    #               digits for float-exact input)
    yield "evaluate_at pressure x", lambda v: c.evaluate_at("pressure", dps=40, x=v, a=1, **E1), \
        lambda V: p_ref(V), 28
    yield "evaluate_at force a", lambda v: c.evaluate_at("force", dps=40, a=v, **E1), \
        lambda V: pi * V**2 / 4, 28
    yield "evaluate_at pressure R", lambda v: c.evaluate_at("pressure", dps=40, x=0, a=1, R=v, E_star=1), \
        lambda V: p_ref(0, 1, V), 28
    yield "evaluate_at half_width P", lambda v: c.evaluate_at("half_width", dps=40, P=v, **E1), \
        lambda V: mpmath.sqrt(4 * V / pi), 28
    yield "half_width(P) method", lambda v: c.half_width(v, **E1), lambda V: mpmath.sqrt(4 * V / pi), 28
    yield "Derivation.evalf force E*", lambda v: c.derivation("force").evalf(dps=40, a=1, R=1, E_star=v), \
        lambda V: pi * V / 4, 28
    yield "evaluate pressure x (auto)", lambda v: c.evaluate("pressure", x=v, a=1, **E1).value, \
        lambda V: p_ref(V), 12
    yield "evaluate pressure x dps=40", lambda v: c.evaluate("pressure", dps=40, x=v, a=1, **E1).value, \
        lambda V: p_ref(V), 28
    yield "evaluate certified pressure x", lambda v: c.evaluate("pressure", certified=True, x=v, a=1, **E1).value, \
        lambda V: p_ref(V), 12
    yield "evaluate certified force a", lambda v: c.evaluate("force", certified=True, rtol=1e-30, a=v, **E1).value, \
        lambda V: pi * V**2 / 4, 28
    yield "to_numeric numpy pressure x", lambda v: c.to_numeric("pressure")(x=v, a=1, **E1), \
        lambda V: p_ref(V), 12
    yield "to_numeric mpmath pressure x", lambda v: c.to_numeric("pressure", backend="mpmath", dps=40)(x=v, a=1, **E1), \
        lambda V: p_ref(V), 28
    yield "to_numeric fixed R", lambda v: c.to_numeric("force", R=v, E_star=1)(a=1), \
        lambda V: pi / (4 * V), 12

    def pull_ref(g, R=1, E=1):
        # 2-D JKR of the parabola: P(a) = pi E a^2/(4R) - sqrt(2 pi g E a); minimum over a
        P = lambda A: pi * E * A**2 / (4 * R) - mpmath.sqrt(2 * pi * g * E * A)
        A = (2 * g * R**2 / (pi * E)) ** (mpmath.mpf(1) / 3)
        return P(A)
    yield "adhesive().at(gamma) closed pull_off_force", \
        lambda v: sp.N(ad.at(gamma=v, **E1).pull_off_force, 45), pull_ref, 28
    yield "pull_off_at force gamma", lambda v: ad.pull_off_at(dps=30, gamma=v, **E1).force, pull_ref, 28
    yield "pull_off_at force R", lambda v: ad.pull_off_at(dps=30, gamma=1, R=v, E_star=1).force, \
        lambda V: pull_ref(1, V), 28

    def ca(Q, mu=2, a=1):
        return mpmath.sqrt(1 - Q / (mu * pi * a * a / 4))
    # the tangential load histories read every value as a parameter (a float
    # is its shortest decimal, tangential.history.to_sympy_number)
    yield "tangential state Q", lambda v: t.state(v, a=1, mu=2, **E1).c, ca, 28, "decimal"
    # mu is a parameter shown in formulas: a float means its shortest decimal
    yield "tangential state mu", lambda v: t.state(sp.Rational(1, 10), a=1, mu=v, **E1).c, \
        lambda V: ca(mpmath.mpf(1) / 10, V), 28, "decimal"
    yield "tangential unload Q", lambda v: t.unload(1, v, a=1, mu=2, **E1).c_r, \
        lambda V: mpmath.sqrt(1 - (1 - V) / (2 * 2 * pi / 4)), 28, "decimal"
    yield "tangential reload Q", lambda v: t.reload(1, v, a=1, mu=2, **E1).c_r, \
        lambda V: mpmath.sqrt(1 - (1 + V) / (2 * 2 * pi / 4)), 28, "decimal"
    yield "tangential cycle Q", lambda v: t.cycle(v, points=3, a=1, mu=2, **E1).c, ca, 12, "decimal"

    def sz(z, a=1):
        return -(a / 2) * a / mpmath.sqrt(a * a + z * z)
    yield "stresses evaluate_at sigma_z z", lambda v: st.evaluate_at("sigma_z", dps=40, x=0, z=v, a=1, **E1), sz, 28
    yield "stresses evaluate_at sigma_z a", lambda v: st.evaluate_at("sigma_z", dps=40, x=0, z=1, a=v, **E1), \
        lambda V: sz(1, V), 28

    def tau_max(a):
        # principal shear on the axis: (sigma_x - sigma_z)/2, p0 = a/2
        p0 = a / 2
        tau = lambda z: p0 * (a / mpmath.sqrt(a * a + z * z) - ((a * a + 2 * z * z) / (a * mpmath.sqrt(a * a + z * z)) - 2 * z / a)) / 2
        zm = mpmath.findroot(lambda z: mpmath.diff(tau, z), 0.78 * a)
        return tau(zm)
    yield "stresses maximum a", lambda v: st.maximum(a=v, **E1).value, tau_max, 6


def cli_cases():
    """(label, argv, reference as a 60-digit mpf or a verdict): the command line
    and a claims file with exact values as text."""
    import os
    import tempfile
    pi = mpmath.pi
    base = ["--set", "R=1", "E_star=1", "--dps", "40", "--json"]
    with mpmath.workdps(60):
        yield "CLI eval pressure x=sqrt(3)/2", ["eval", "x**2/(2*R)", "pressure", "--at", "x=sqrt(3)/2", "a=1"] + base, \
            mpmath.mpf(1) / 4
        yield "CLI eval pressure x=pi/8", ["eval", "x**2/(2*R)", "pressure", "--at", "x=pi/8", "a=1"] + base, \
            mpmath.sqrt(1 - (pi / 8)**2) / 2
        yield "CLI eval force a=<31 digits>", ["eval", "x**2/(2*R)", "force", "--at", "a=" + D31] + base, \
            pi * mpmath.mpf(D31)**2 / 4
        yield "CLI eval half_width P=<31 digits>", ["eval", "x**2/(2*R)", "half_width", "--at", "P=" + D31] + base, \
            mpmath.sqrt(4 * mpmath.mpf(D31) / pi)
        yield "CLI eval force R=E", ["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=E", "E_star=exp(-1)",
                                     "--dps", "40", "--json"], pi / (4 * mpmath.e * mpmath.e)
    claims = os.path.join(tempfile.mkdtemp(), "exact.toml")
    with open(claims, "w") as fh:
        fh.write('[[claims]]\nlabel = "sweep"\ntitle = "Hertz pressure at exact points"\nquantity = "pressure"\n'
                 'profile = "x**2/(2*R)"\nformula = "E_star/(2*R)*sqrt(a**2 - x**2)"\n'
                 'special = { x = ["sqrt(3)/4", "' + D31 + '", "pi/8", "exp(-1)"], '
                 'R = ["E", "1.0000000000000000000000000000001"] }\n')
    yield "claims file special values", ["check", claims, "--json"], "holds"


def run_cli():
    import json
    import os
    import subprocess
    n = ok = 0
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    for label, argv, ref in cli_cases():
        n += 1
        out = subprocess.run([sys.executable, "-m", "linecontact_sym", *argv], capture_output=True, text=True,
                             timeout=600, env=env)
        try:
            data = json.loads(out.stdout)
            if isinstance(ref, str):
                good = data["claims"][0]["status"] == ref
                what = data["claims"][0]["status"]
            else:
                d = digits(mpmath.mpf(data["rows"][0]["value"]), ref)
                good, what = d >= 28, f"{d:.1f} digits"
        except Exception as exc:  # noqa: BLE001
            good, what = False, f"{type(exc).__name__}: {exc}; {out.stderr[-300:]}"
        ok += good
        if not good:
            print(f"{label} | {what}")
    return n, ok


def main():
    rows, fails = [], []
    n = ok = 0
    t0 = time.perf_counter()
    nums = numbers()
    for label, call, ref, need, *floats in cases():
        for tname, v, V in nums:
            if floats and tname in ("np.float64", "np.float32"):
                V = mpmath.mpf(repr(float(v)) if tname == "np.float64" else str(v))
            n += 1
            try:
                got = call(v)
                with mpmath.workdps(60):
                    r = ref(V)
                d = digits(got, r)
                exact31 = tname in ("Decimal31", "str31", "Float40") or not tname.startswith(("np", "str"))
                want = need if exact31 else min(need, 12)
                good = d >= want
            except Exception as exc:  # noqa: BLE001  -- the sweep records every failure
                d, good = None, False
                fails.append((label, tname, f"{type(exc).__name__}: {str(exc)[:160]}"))
            ok += good
            if not good and d is not None:
                fails.append((label, tname, f"{d:.1f} correct digits, want {want}"))
            rows.append((label, tname, d))
    for f in fails:
        print(" | ".join(f))
    print(f"API: cases {n}, ok {ok}, failing {n - ok}  ({time.perf_counter() - t0:.0f} s)")
    cn, cok = run_cli()
    print(f"CLI and claims: cases {cn}, ok {cok}, failing {cn - cok}")
    n, ok = n + cn, ok + cok
    assert mpmath.mp.dps == 15, mpmath.mp.dps
    return 0 if ok == n else 1


if __name__ == "__main__":
    sys.exit(main())
