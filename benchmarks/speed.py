"""Where a user waits (issues 22, 26): one table of wall-clock times, with the machine.

    python benchmarks/speed.py [--jobs N] [--no-paper] [--no-suite] [--full-suite] [--quick]

Rows (each in a fresh process where a user would start one; "cold" = an empty
derivation cache in a temporary directory, "warm" = the same cache again):

* ``import linecontact_sym`` (the best of 5 fresh interpreters; target <= 1 s);
* the 18 seed derivations: force, pressure and gap of the parabola, the power
  law (symbolic n), the wedge, the worn and the exact cylinder and the flat
  punch with rounded corners, cold, each certified (target <= 4 s);
* the Maugis-Dugdale derivation of the parabola (zone force, cohesive gap,
  pressure) with its checks and without (target <= 2 s with them);

* the paper job ``linecontact-sym paper popov2017 --jobs N`` cold and warm
  (targets <= 60 s and <= 10 s on 2 cores);
* the fast test loop ``pytest -m "not slow"`` (target <= 60 s; the whole
  suite, <= 5 min, is left to ``--full-suite``: it takes minutes);
* ``parabola().tangential().stick_half_width()``, cold and warm;
* the pressure of smooth profiles whose force law is not elementary
  (cosh(x) - 1, 1 - cos(x), a Gaussian bump): how long until an answer, and
  whether it is a closed form;
* the 10^6-point pressure export of the elliptic (exact cylinder) and
  piecewise (worn cylinder) laws against their force law (target <= 30x);
* scalar calls of the float64 export on Python floats against the same
  formula written by hand with NumPy/scipy.special (target <= 5x), and
  ``evaluate(rtol=1e-12)`` (target <= 25x);
* adhesive pull-offs (c x^4, the exact cylinder).

Every row states the machine: nproc, CPU model, the load average before and
after (this machine is shared: a load above the core count stretches every
wall-clock time), the mpmath backend, and whether the package's bytecode is
current (before the run, and at the seed row: the fast loop's notebook test
writes it).  Times are wall clock unless marked CPU.
"""
from __future__ import annotations

import argparse
import math
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
import timeit

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)


def machine() -> dict:
    model = "unknown"
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    import mpmath.libmp
    return {"nproc": os.cpu_count(), "cpu": model, "python": platform.python_version(),
            "mpmath backend": mpmath.libmp.BACKEND, "load": os.getloadavg(), "bytecode": bytecode()}


def bytecode() -> str:
    """Whether the package's modules have current bytecode (``__pycache__``):
    without it every fresh interpreter compiles the sources it imports
    (about 0.4 CPU s for the whole package), as on a machine with
    PYTHONDONTWRITEBYTECODE set that never ran anything that writes it."""
    import importlib.util
    srcs = [os.path.join(d, f) for d, _, fs in os.walk(os.path.join(ROOT, "linecontact_sym")) for f in fs
            if f.endswith(".py")]
    current = sum(1 for f in srcs if os.path.exists(importlib.util.cache_from_source(f))
                  and os.path.getmtime(importlib.util.cache_from_source(f)) >= os.path.getmtime(f))
    return f"package bytecode current for {current} of {len(srcs)} modules" + \
        (f" (PYTHONDONTWRITEBYTECODE={os.environ['PYTHONDONTWRITEBYTECODE']})"
         if os.environ.get("PYTHONDONTWRITEBYTECODE") else "")


def fresh(code: str, cache: str, timeout=900) -> tuple:
    """Run ``code`` in a fresh interpreter with the derivation cache in
    ``cache``; it prints ``T <seconds>`` (the time of the work, imports
    excluded) and maybe ``R <result>``.  Returns (seconds, result text)."""
    env = dict(os.environ, LINECONTACT_SYM_CACHE=cache, PYTHONPATH=ROOT)
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True,
                         timeout=timeout)
    secs, res = math.nan, out.stderr.strip().splitlines()[-1:] or [""]
    for line in out.stdout.splitlines():
        if line.startswith("T "):
            secs = float(line[2:])
        elif line.startswith("R "):
            res = [line[2:]]
    return secs, res[0][:90]


def timed(stmt: str, setup: str = "") -> str:
    return (f"import time\n{setup}\nt0 = time.perf_counter()\n{stmt}\n"
            f"print('T', time.perf_counter() - t0)\n")


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cli(args, cache) -> tuple:
    """(wall seconds, CPU seconds of the process and its workers, exit status)."""
    env = dict(os.environ, LINECONTACT_SYM_CACHE=cache, PYTHONPATH=ROOT)
    t0, c0 = time.perf_counter(), _children_cpu()
    r = subprocess.run([sys.executable, "-m", "linecontact_sym", *args], cwd=ROOT, env=env, capture_output=True,
                       timeout=3600)
    return time.perf_counter() - t0, _children_cpu() - c0, r.returncode


def per_call(f, n=3000) -> float:
    """CPU seconds per call (process time: on a shared machine the wall clock
    of a microsecond call measures the other sessions)."""
    f()
    return min(timeit.repeat(f, number=n, repeat=5, timer=time.process_time)) / n


def per_call_interleaved(fns, n=3000, rounds=15) -> list:
    """CPU seconds per call of each of ``fns`` ((callable, calls per round)
    pairs), the best of ``rounds`` rounds that time every callable in turn:
    a ratio of two rows then compares them in the same state of the machine
    (on this VM the speed of a microsecond call drifts by up to 2x over
    seconds; timed one after the other, a ratio drifted with it)."""
    best = [math.inf] * len(fns)
    for f, _ in fns:
        f()
    for _ in range(rounds):
        for i, (f, k) in enumerate(fns):
            t = timeit.timeit(f, number=k, timer=time.process_time) / k
            best[i] = min(best[i], t)
    return best


def in_process_rows(rows):
    import numpy as np
    import scipy.special as sc
    import linecontact_sym as lcs

    # 1e6-point pressure vs force
    for law, par in (("exact_cylinder", {"R": 1.0}), ("worn_cylinder", {"R": 1.0, "b": 0.2})):
        c = getattr(lcs, law)()
        P, p = c.to_numeric("force"), c.to_numeric("pressure")
        a = np.linspace(0.3, 0.9, 10**6)
        x = np.linspace(-0.5, 0.5, 10**6)
        P(a=a[:10], E_star=1.0, **par)
        p(a=0.5, x=x[:10], E_star=1.0, **par)
        tf = min(timeit.repeat(lambda: P(a=a, E_star=1.0, **par), number=1, repeat=3, timer=time.process_time))
        tp = min(timeit.repeat(lambda: p(a=0.5, x=x, E_star=1.0, **par), number=1, repeat=3,
                               timer=time.process_time))
        rows.append((f"pressure at 1e6 points, {law.replace('_', ' ')}", f"{tp:.3f} s CPU",
                     f"{tp / tf:.1f}x the force law ({tf:.3f} s); target <= 30x"))

    # scalar calls
    hand = {
        "exact_cylinder": lambda a, E, R: E * a**2 * sc.elliprd(0, (R - a) * (R + a) / R**2, 1) / (3 * R),
        "parabola": lambda a, E, R: np.pi * E * a**2 / (4 * R),
    }
    for law, h in hand.items():
        c = getattr(lcs, law)()
        f = c.to_numeric("force")
        fn = c.to_numeric("force", check=False)
        it = iter(range(10**9))
        th, te, tn, tv, tev = per_call_interleaved([
            (lambda: h(0.3, 1.7, 1.0), 3000),
            (lambda: f(a=0.3, E_star=1.7, R=1.0), 3000),
            (lambda: fn(a=0.3, E_star=1.7, R=1.0), 3000),
            (lambda: f(a=0.3 + 1e-9 * next(it), E_star=1.7, R=1.0), 300),
            (lambda: c.evaluate("force", rtol=1e-12, a=0.3, E_star=1.7, R=1.0), 1000)])
        name = law.replace("_", " ")
        rows.append((f"scalar force call, {name}: by hand", f"{th * 1e6:.2f} us",
                     "NumPy/scipy.special, no checks; CPU time per call, as the rows below"))
        rows.append((f"  export (checked)", f"{te * 1e6:.2f} us",
                     f"{te / th:.1f}x; a new a at every call {tv * 1e6:.1f} us ({tv / th:.1f}x); target <= 5x"))
        rows.append((f"  export, check=False", f"{tn * 1e6:.2f} us", f"{tn / th:.1f}x"))
        rows.append((f"  evaluate(rtol=1e-12)", f"{tev * 1e6:.1f} us", f"{tev / th:.0f}x; target <= 10x"))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--no-paper", action="store_true", help="skip the paper job (cold: minutes)")
    ap.add_argument("--no-suite", action="store_true", help="skip the fast test loop")
    ap.add_argument("--full-suite", action="store_true", help="also time the whole suite (minutes)")
    ap.add_argument("--quick", action="store_true", help="only the in-process rows")
    ap.add_argument("--report", metavar="DIR", help="keep the paper job's reports (of the warm run) in DIR")
    args = ap.parse_args(argv)
    m0 = machine()
    rows = []
    t_start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="lcs-bench-") as tmp:
        cache = os.path.join(tmp, "cache")
        if not (args.no_paper or args.quick):
            out = args.report or os.path.join(tmp, "report")
            for what, target in (("cold", "empty cache; target <= 20 s"), ("warm", "same cache; target <= 3 s")):
                wall, cpu, code = run_cli(["paper", "popov2017", "--jobs", str(args.jobs), "--out", out, "--quiet"],
                                          cache)
                rows.append((f"paper popov2017 --jobs {args.jobs}, {what}", f"{wall:.1f} s",
                             f"{target}; CPU {cpu:.0f} s in all processes; exit {code}"))
        if not (args.no_suite or args.quick):
            t0 = time.perf_counter()
            r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-m", "not slow"],
                               cwd=ROOT, capture_output=True, text=True, timeout=3600)
            tail = (r.stdout.strip().splitlines() or [""])[-1]
            rows.append(("pytest -m 'not slow'", f"{time.perf_counter() - t0:.1f} s", f"{tail}; target <= 30 s"))
            if args.full_suite:
                t0 = time.perf_counter()
                r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"], cwd=ROOT,
                                   capture_output=True, text=True, timeout=3600)
                tail = (r.stdout.strip().splitlines() or [""])[-1]
                rows.append(("pytest (whole suite)", f"{time.perf_counter() - t0:.1f} s", f"{tail}; target <= 180 s"))
        if not args.quick:
            imp = []
            for _ in range(5):
                t0 = time.perf_counter()
                subprocess.run([sys.executable, "-c", "import linecontact_sym"], cwd=ROOT, check=True,
                               env=dict(os.environ, PYTHONPATH=ROOT))
                imp.append(time.perf_counter() - t0)
            rows.append(("import linecontact_sym", f"{min(imp):.2f} s",
                         f"best of 5 fresh interpreters (median {sorted(imp)[2]:.2f} s); target <= 1 s"))
            seeds = timed("n = cert = pts = 0\n"
                          "for mk in (lcs.parabola, lcs.power_law, lcs.wedge, lcs.worn_cylinder, lcs.exact_cylinder,\n"
                          "           lcs.rounded_punch):\n"
                          "    c = mk()\n"
                          "    for q in ('force', 'pressure', 'gap'):\n"
                          "        d = c.derivation(q); v = d.verification\n"
                          "        n += d.closed_form and v.passed; cert += v.certified_points; pts += len(v.points)",
                          "import linecontact_sym as lcs") + "print('R', f'{n} of 18 closed and verified; Arb " \
                "certified {cert} of {pts} points')\n"
            secs, res = fresh(seeds, cache + "-seeds")
            rows.append(("18 seed derivations, cold", f"{secs:.1f} s", f"{res}; target <= 4 s; {bytecode()}"))
            for verify in (True, False):
                code = timed("md = lcs.LineContact(lcs.x**2 / (2 * lcs.R), verify=%s).maugis_dugdale()\n"
                             "for q in ('zone_force', 'cohesive_gap', 'pressure'):\n"
                             "    md.derivation(q)" % verify, "import linecontact_sym as lcs")
                secs, res = fresh(code, cache + f"-md-{verify}")
                rows.append((f"Maugis-Dugdale derivation, parabola, {'with' if verify else 'without'} checks",
                             f"{secs:.1f} s", "cold; target <= 2 s with checks" if verify else "cold"))
            st = timed("c = lcs.parabola().tangential().stick_half_width()\nprint('R', c.expr if hasattr(c, 'expr') "
                       "else c)", "import linecontact_sym as lcs")
            cold = fresh(st, cache + "-stick")
            warm = fresh(st, cache + "-stick")
            rows.append(("parabola().tangential().stick_half_width()", f"{cold[0]:.1f} s",
                         f"warm {warm[0]:.1f} s (new process, same cache)"))
            for name, prof in (("cosh(x) - 1", "sp.cosh(lcs.x) - 1"), ("1 - cos(x)", "1 - sp.cos(lcs.x)"),
                               ("Gaussian bump 1 - exp(-x**2)", "1 - sp.exp(-lcs.x**2)")):
                code = timed("d = lcs.LineContact(%s).derivation('pressure')\n"
                             "print('R', 'closed form' if d.closed_form else 'no closed form (integral + number)')"
                             % prof, "import sympy as sp\nimport linecontact_sym as lcs")
                secs, res = fresh(code, cache + "-smooth")
                rows.append((f"pressure of {name}", f"{secs:.1f} s", res))
            for name, prof in (("c*x**4", "lcs.c * lcs.x**4"), ("exact cylinder", "lcs.exact_cylinder().profile.expr")):
                code = timed("d = lcs.LineContact(%s).adhesive(lcs.gamma).derivation('pull_off_force')\n"
                             "print('R', 'closed form' if d.closed_form else 'no closed form')" % prof,
                             "import linecontact_sym as lcs")
                secs, res = fresh(code, cache + "-pull")
                rows.append((f"pull-off force of {name}", f"{secs:.1f} s", res))
        in_process_rows(rows)
    m1 = machine()
    print(f"machine: {m0['nproc']} cores, {m0['cpu']}, Python {m0['python']}, mpmath backend {m0['mpmath backend']}")
    print(m0["bytecode"], "(before the run)")
    print(f"load average (1/5/15 min) before {'/'.join(f'{v:.1f}' for v in m0['load'])}, "
          f"after {'/'.join(f'{v:.1f}' for v in m1['load'])}; benchmark took {time.perf_counter() - t_start:.0f} s")
    w = max(len(r[0]) for r in rows)
    print(f"| {'what':<{w}} | {'time':>10} | notes |")
    print(f"|{'-' * (w + 2)}|{'-' * 12}|-------|")
    for what, t, note in rows:
        print(f"| {what:<{w}} | {t:>10} | {note} |")


if __name__ == "__main__":
    main()
