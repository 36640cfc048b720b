"""Check published formulas against what the engine derives.

A paper is a *claims file* (TOML, no code): each claim names the quantity,
the profile (or a list of test profiles for a general formula), the formula
*as printed* in SymPy syntax, and the assumptions on its symbols.  The
checker derives the quantity with the engine (or, for the flat punch and the
critical punch force, from first principles), compares it with the printed
formula symbolically and at random points with mpmath (45 working digits,
>= 30 agreeing digits required), and reports per claim one of

* ``holds`` -- at every point (and, where SymPy can show it, identically);
* ``holds under a condition`` -- it says which: a range of a parameter found by
  bisection (``n > 1``), a property of the profile (``only where f'(0+) = 0``),
  or an excluded point where the printed form is undefined (``n != 1``);
* ``does not hold`` -- with a counterexample point and both values;
* ``undecided`` -- an internal failure (the engine could not derive the
  quantity); the CLI exits non-zero then.

File format
-----------
::

    key = "popov2017"
    title = "..."
    reference = "..."

    [definitions]                 # named sub-formulas used by the claims
    Z_n = "(n-1)*sqrt(pi)*gamma(n/2 - 1/2)/(2*gamma(n/2))"

    [ranges]                      # default sampling ranges (file-wide)
    R = [0.5, 2.5]

    [[claims]]
    label = "Eq. (13)"
    quantity = "force"            # see QUANTITIES
    profile = "x**2/(2*R)"        # or, for a general formula, test profiles:
                                  # profiles = ["x**2/(2*R)", "x*tan(theta)"]
                                  # profile_names = ["parabola", "wedge"]
    formula = "pi*E_star*a**2/(4*R)"
    forms = ["E_star*a**2/(2*R)*Integral(1/sqrt(a**2 - t**2), (t, 0, a))"]   # other printed forms
    assumptions = ["a < R"]       # where the printed formula is meant to hold
    ranges = { n = [0.3, 6.0] }   # sampling ranges (exact rationals are drawn)
    special = { n = ["1"] }       # exact values always tested
    symbols = ["k"]               # extra symbol names (positive)
    points = 6                    # random points (plus range ends and special values)
    note = "..."                  # remark shown in the report
    reading = "..."               # how the transcription was read

Formulas may use, besides the standard symbols, ``t`` and ``s`` (integration
variables), ``Integral`` and ``Derivative``, the definitions, and the
placeholders of general (functional) claims: ``f(...)`` the profile,
``force(...)`` the non-adhesive force law P_0 and ``p0`` the non-adhesive
pressure.  Every string is parsed by :mod:`linecontact_sym.parsing`
(whitelist; no code runs).
"""
from __future__ import annotations

import math
import random
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef

from ..parsing import to_sympy
from ..core import symbols as S
from ..core.budget import run_with_budget
from ..core.errors import BudgetExceeded, ClaimError, DomainError, LineContactError
from ..parsing import declare_symbols, parse_expr, t as T_VAR

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

#: working precision of the comparisons, and the digits a claim must reproduce
DPS = 45
REQUIRED_DIGITS = 30

HOLDS = "holds"
HOLDS_IF = "holds under a condition"
FAILS = "does not hold"
UNDECIDED = "undecided"

#: what the checker can derive, with a description
QUANTITIES = {
    "force": "non-adhesive force law P(a), Eq. (10*) (engine)",
    "pressure": "non-adhesive pressure p(x; a), 0 < x < a, Eq. (12) (engine) + Flamant check",
    "gap": "surface separation g(x; a), x > a, Eqs. (3)/(5) (engine)",
    "profile_at_a": "the profile at the contact edge f(a), for the inverse map Eq. (9)",
    "inverse_profile": "profile f(x) from a given force law (claim field force_law), Eq. (9) (engine)",
    "half_width": "half-width a at load P (inverse of the force law) (engine)",
    "Z_n": "Popov's coefficient Z_n = P(a)/(E* c a^n) of a power law c*x**n (engine)",
    "adhesive_force": "JKR force law P(a), Eq. (33) (engine, adhesion)",
    "adhesive_pressure": "JKR pressure, Eq. (29) (engine, adhesion) + Flamant check",
    "pull_off_force": "pull-off force P_adh = -min_a P(a) > 0, Eqs. (34)-(36) (engine, adhesion) "
                      "+ independent numeric minimum",
    "pull_off_half_width": "half-width at pull-off (engine, adhesion)",
    "flat_punch_pressure": "pressure under a flat punch, Eq. (1): checked from first principles "
                           "(resultant and flat surface under the punch, Flamant kernel)",
    "flat_punch_displacement": "d - u_z(x) outside a flat punch, Eq. (3), from the Flamant kernel",
    "punch_adhesion_force": "critical force of a pulled flat punch, Eq. (31), from the energy-release "
                            "rate (Griffith) and the stress-intensity factor",
}

#: placeholders of general claims (replaced per test profile)
PLACEHOLDER_F = sp.Function("f")
PLACEHOLDER_FORCE = sp.Function("force")
PLACEHOLDER_P0 = sp.Symbol("p0")
PLACEHOLDERS = {"f": PLACEHOLDER_F, "force": PLACEHOLDER_FORCE, "p0": PLACEHOLDER_P0}

#: default sampling ranges (overridden by the file's and the claim's ranges)
DEFAULT_RANGES = {"a": (0.1, 2.0), "x": (0.1, 2.0), "P": (0.1, 3.0), "E_star": (0.5, 3.0), "gamma": (0.01, 0.5),
                  "R": (0.5, 2.5), "b": (0.1, 0.5), "c": (0.5, 2.5), "n": (0.3, 6.0),
                  "theta": (0.05, 1.2)}
#: x relative to a, by quantity
X_RANGES = {"pressure": (0.02, 0.98), "adhesive_pressure": (0.02, 0.98),
            "flat_punch_pressure": (0.02, 0.98), "gap": (1.05, 3.0),
            "flat_punch_displacement": (1.05, 3.0)}

_CLAIM_KEYS = {"label", "title", "description", "quantity", "profile", "profiles", "profile_names", "formula", "forms",
               "assumptions", "ranges", "special", "symbols", "force_law", "values", "labels", "note",
               "points", "reading"}


# =====================================================================  data
@dataclass
class Form:
    """One printed form of a claim: its text, the expression as printed (with
    definitions as symbols, for display) and as evaluated."""

    text: str
    shown: sp.Expr
    expr: sp.Expr


@dataclass
class Claim:
    label: str
    quantity: str
    forms: list            # [Form]; the last is the final printed formula
    profiles: list         # [(text, expr)]; empty for profile-free quantities
    general: bool = False  # a general formula checked on test profiles
    assumptions: tuple = ()
    ranges: dict = field(default_factory=dict)        # the claim's own sampling ranges
    special: dict = field(default_factory=dict)
    symbols: dict = field(default_factory=dict)
    force_law: sp.Expr | None = None
    values: list = field(default_factory=list)     # Table claims: [(text, expr)]
    labels: dict = field(default_factory=dict)     # Table claims: value text -> printed n
    title: str = ""
    note: str = ""
    reading: str = ""
    points: int = 6
    source: str = "<claims>"
    file_ranges: dict = field(default_factory=dict)   # the file's default ranges

    @property
    def formula(self) -> Form:
        return self.forms[-1]


@dataclass
class Paper:
    key: str
    title: str
    reference: str
    claims: list
    definitions: dict
    source: str


# =====================================================================  loading
def _w(source, label=None, fld=None):
    out = str(source)
    if label:
        out += f": claim {label!r}"
    if fld:
        out += f": {fld}"
    return out


def _parse_range(val, where):
    if not (isinstance(val, (list, tuple)) and len(val) == 2):
        raise ClaimError(f"{where}: a range is [low, high], got {val!r}")
    lo, hi = (float(_num(v, where)) for v in val)
    if not lo < hi:
        raise ClaimError(f"{where}: empty range [{lo}, {hi}]")
    return (lo, hi)


def _num(v, where):
    if isinstance(v, bool):
        raise ClaimError(f"{where}: expected a number, got {v!r}")
    if isinstance(v, (int, float)):
        return sp.nsimplify(v, rational=True) if isinstance(v, float) else sp.Integer(v)
    e = parse_expr(str(v), where=where)
    if e.free_symbols:
        raise ClaimError(f"{where}: expected a number, got {v!r}")
    return e


def load_paper(source) -> Paper:
    """Load a claims file: a path, or the name of a shipped paper (``popov2017``)."""
    path = resolve_paper(source)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ClaimError(f"{path}: not valid TOML: {exc}") from None
    return paper_from_dict(data, str(path))


def resolve_paper(source) -> Path:
    p = Path(source)
    if p.suffix == ".toml" and p.exists():
        return p
    shipped = Path(__file__).with_name("data") / f"{source}.toml"
    if shipped.exists():
        return shipped
    if p.exists():
        return p
    names = sorted(q.stem for q in (Path(__file__).with_name("data")).glob("*.toml"))
    raise ClaimError(f"no claims file {source!r} (neither a path nor a shipped paper; shipped: {names})")


def paper_from_dict(data: dict, source: str = "<claims>") -> Paper:
    """Validate and parse a claims document (the TOML as a dict)."""
    if not isinstance(data, dict):
        raise ClaimError(f"{source}: the claims document must be a table")
    unknown = set(data) - {"key", "title", "reference", "definitions", "ranges", "claims", "source", "symbols"}
    if unknown:
        raise ClaimError(f"{source}: unknown top-level field(s) {sorted(unknown)}")
    file_syms = declare_symbols(data.get("symbols", []), _w(source, fld="symbols"))
    defs_show, defs = {}, {}
    for name, text in (data.get("definitions") or {}).items():
        where = _w(source, fld=f"definitions.{name}")
        if not name.isidentifier() or name.startswith("_"):
            raise ClaimError(f"{where}: {name!r} is not a plain name")
        defs[name] = parse_expr(text, symbols=file_syms, definitions=defs, where=where)
        defs_show[name] = sp.Symbol(name, positive=True)
    ranges = {k: _parse_range(v, _w(source, fld=f"ranges.{k}")) for k, v in (data.get("ranges") or {}).items()}
    claims_data = data.get("claims")
    if not isinstance(claims_data, list) or not claims_data:
        raise ClaimError(f"{source}: no [[claims]] in the file")
    claims = []
    seen = set()
    for i, cd in enumerate(claims_data):
        claim = claim_from_dict(cd, source, defs, defs_show, ranges, file_syms, index=i)
        if claim.label in seen:
            raise ClaimError(f"{_w(source, claim.label)}: duplicate label")
        seen.add(claim.label)
        claims.append(claim)
    return Paper(str(data.get("key", Path(source).stem)), str(data.get("title", "")),
                 str(data.get("reference", "")), claims, defs, source)


def claim_from_dict(cd: dict, source="<claims>", definitions=None, definitions_shown=None,
                    file_ranges=None, file_symbols=None, index=0) -> Claim:
    if not isinstance(cd, dict):
        raise ClaimError(f"{source}: claim #{index + 1} is not a table")
    label = cd.get("label")
    if not isinstance(label, str) or not label.strip():
        raise ClaimError(f"{source}: claim #{index + 1} has no label")
    W = lambda fld=None: _w(source, label, fld)  # noqa: E731
    unknown = set(cd) - _CLAIM_KEYS
    if unknown:
        raise ClaimError(f"{W()}: unknown field(s) {sorted(unknown)}; allowed: {sorted(_CLAIM_KEYS)}")
    quantity = cd.get("quantity")
    if quantity not in QUANTITIES:
        raise ClaimError(f"{W('quantity')}: unknown quantity {quantity!r}; choose one of {sorted(QUANTITIES)}")
    syms = dict(file_symbols or {})
    syms.update(declare_symbols(cd.get("symbols", []), W("symbols")))
    defs = dict(definitions or {})
    shown = dict(definitions_shown or {})
    general = "profiles" in cd
    if "profile" in cd and general:
        raise ClaimError(f"{W()}: give either profile or profiles, not both")
    ph = PLACEHOLDERS if general else {}

    def parse(text, fld, **kw):
        return parse_expr(text, symbols=syms, definitions=defs, placeholders=kw.pop("placeholders", ph),
                          where=W(fld), **kw)

    profiles = []
    if general:
        plist = cd["profiles"]
        if not isinstance(plist, list) or not plist:
            raise ClaimError(f"{W('profiles')}: expected a non-empty list of profile formulas")
        names = cd.get("profile_names", [])
        if names and (not isinstance(names, list) or len(names) != len(plist)):
            raise ClaimError(f"{W('profile_names')}: expected one name per profile ({len(plist)})")
        for j, ptxt in enumerate(plist):
            display = f"{names[j]} ({ptxt})" if names else str(ptxt)
            profiles.append((display, parse(ptxt, f"profiles[{j}]", placeholders={})))
    elif "profile" in cd:
        profiles.append((str(cd["profile"]), parse(cd["profile"], "profile", placeholders={})))
    needs_profile = quantity not in ("flat_punch_pressure", "flat_punch_displacement",
                                     "punch_adhesion_force", "inverse_profile")
    if needs_profile and not profiles:
        raise ClaimError(f"{W()}: quantity {quantity!r} needs a profile (profile = \"...\")")
    for txt, e in profiles:
        if S.x not in e.free_symbols:
            raise ClaimError(f"{W('profile')}: the profile {txt!r} does not depend on x")
    force_law = None
    if quantity == "inverse_profile":
        if "force_law" not in cd:
            raise ClaimError(f"{W()}: quantity 'inverse_profile' needs force_law = \"...\"")
        force_law = parse(cd["force_law"], "force_law")
    values, labels = [], {}
    texts = []
    if "values" in cd:
        if quantity != "Z_n":
            raise ClaimError(f"{W('values')}: a table of values is supported for quantity 'Z_n' only")
        for j, vt in enumerate(cd["values"]):
            v = parse(str(vt), f"values[{j}]")
            if v.free_symbols:
                raise ClaimError(f"{W(f'values[{j}]')}: expected a number, got {vt!r}")
            values.append((str(vt), v))
        for k, v in (cd.get("labels") or {}).items():
            if k not in [vt for vt, _ in values]:
                raise ClaimError(f"{W('labels')}: {k!r} is not one of the values")
            labels[k] = _num(v, W(f"labels.{k}"))
    else:
        if "formula" not in cd:
            raise ClaimError(f"{W()}: no formula")
        forms_raw = cd.get("forms", [])
        if not isinstance(forms_raw, list):
            raise ClaimError(f"{W('forms')}: expected a list of formulas")
        texts = [str(f) for f in forms_raw] + [str(cd["formula"])]
    forms = []
    for j, text in enumerate(texts):
        fld = "formula" if j == len(texts) - 1 else f"forms[{j}]"
        expr = parse(text, fld)
        shown_expr = parse_expr(text, symbols=syms, definitions=shown, placeholders=ph, where=W(fld))
        forms.append(Form(text, shown_expr, expr))
    assumptions = tuple(parse_expr(str(r), symbols=syms, where=W(f"assumptions[{j}]"), allow_relational=True)
                        for j, r in enumerate(cd.get("assumptions", [])))
    table = {}
    for k, v in (cd.get("ranges") or {}).items():
        table[k] = _parse_range(v, W(f"ranges.{k}"))
    special = {}
    for k, vals in (cd.get("special") or {}).items():
        if not isinstance(vals, list):
            vals = [vals]
        special[k] = [_num(v, W(f"special.{k}")) for v in vals]
    pts = cd.get("points", 6)
    if not isinstance(pts, int) or not 1 <= pts <= 50:
        raise ClaimError(f"{W('points')}: expected an integer 1..50")
    return Claim(label.strip(), quantity, forms, profiles, general, assumptions, table, special,
                 {**syms}, force_law, values, labels, str(cd.get("title", cd.get("description", ""))),
                 str(cd.get("note", "")), str(cd.get("reading", "")), pts, str(source),
                 dict(file_ranges or {}))


def claim_from_cli(quantity: str, formula: str, profile: str | None = None, *, label="command line",
                   assumptions=(), ranges=None, symbols=(), force_law=None, special=None) -> Claim:
    """A claim typed on the command line (``check --profile ... --force ...``)."""
    d = {"label": label, "quantity": quantity, "formula": formula}
    if profile is not None:
        d["profile"] = profile
    if force_law is not None:
        d["force_law"] = force_law
    if assumptions:
        d["assumptions"] = list(assumptions)
    if ranges:
        d["ranges"] = ranges
    if symbols:
        d["symbols"] = list(symbols)
    if special:
        d["special"] = special
    return claim_from_dict(d, "command line")


# =====================================================================  numerics
class Undefined(Exception):
    """The quantity or the printed formula has no (real, finite) value here."""


class Divergent(Undefined):
    """An integral in the printed formula diverges here."""


class DerivedUndefined(Undefined):
    """The derived quantity does not exist here (outside its conditions, no
    pull-off, ...)."""


def _finite_real(v, what, dps, exc=Undefined):
    """mpf of a SymPy number, or ``exc`` (an Undefined)."""
    if v.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise exc(f"{what} is undefined here ({v})")
    try:
        re, im = v.as_real_imag()
        re, im = sp.N(re, dps), sp.N(im, dps)
    except Exception as err:  # noqa: BLE001
        raise exc(f"{what} cannot be evaluated here: {err}")
    if not (re.is_number and im.is_number) or not re.is_finite:
        raise exc(f"{what} cannot be evaluated here: {v}")
    if im != 0 and abs(im) > max(abs(re), sp.Float(1e-300)) * sp.Float(10) ** (-(dps - 8)):
        raise exc(f"{what} is complex here ({sp.N(v, 8)})")
    return mpmath.mpf(str(re))


def _mpf(v, dps):
    with mpmath.workdps(dps + 20):
        return _mp(v)


def _breakpoints(f, var, lo, hi, dps):
    bps = set()
    for rel in f.atoms(sp.Rel):
        d = rel.lhs - rel.rhs
        if var not in d.free_symbols:
            continue
        try:
            poly = sp.Poly(d, var)
            if poly.degree() == 1:
                c1, c0 = poly.all_coeffs()
                roots = [-c0 / c1]        # keeps the full precision of Float coefficients
            else:
                roots = sp.solve(sp.Eq(d, 0), var, rational=False)
        except Exception:  # noqa: BLE001
            continue
        for r in roots:
            try:
                rv = _mp(r)
            except (TypeError, ValueError):
                continue
            if lo < rv < hi:
                bps.add(rv)
    return sorted(bps)


def _endpoint_exponent(g, e, direction, span):
    """Local power of g at an endpoint: |g(e + dir*h)| ~ h**alpha."""
    h1, h2 = span * mpmath.mpf(10) ** -12, span * mpmath.mpf(10) ** -24
    try:
        v1, v2 = abs(g(e + direction * h1)), abs(g(e + direction * h2))
    except (ZeroDivisionError, ValueError, TypeError):
        return None
    if isinstance(v1, mpmath.mpc) or isinstance(v2, mpmath.mpc):
        v1, v2 = abs(v1), abs(v2)
    if v1 == 0 and v2 == 0:
        return math.inf
    if v1 == 0 or v2 == 0 or not (mpmath.isfinite(v1) and mpmath.isfinite(v2)):
        return None if v2 == 0 else -math.inf
    return float(mpmath.log(v2 / v1) / mpmath.log(h2 / h1))


def _quad_dps(dps):
    """Working precision of the quadratures: tanh-sinh nodes crowd an endpoint
    closer than the working precision resolves, so an integrand with a
    cancelling factor such as sqrt(a**2 - t**2) there is good to about half the
    working digits; twice the target plus a margin keeps >= dps digits."""
    return 2 * dps + 10


class _Integrand:
    """Wrap an integrand for tanh-sinh near the ends of [lo, hi].

    * Precision grows with the closeness of a node to an end (one digit per
      decade, up to twice the working precision): forms such as
      (R - sqrt(R**2 - t**2))/t**2 cancel catastrophically as t -> 0, and the
      nodes crowd there.
    * Imaginary parts from rounding at the very ends (sqrt of -1 ulp at t = a)
      are dropped; a significant imaginary part elsewhere is remembered.
    * A non-finite value at a node closer to an end than the precision
      resolves (atanh(1.0)) counts as 0: its weight is negligible.
    """

    def __init__(self, g, lo, hi):
        self.g, self.lo, self.hi = g, lo, hi
        self.span = hi - lo
        self.tol = mpmath.mpf(10) ** (-(mpmath.mp.dps // 2))
        self.cap = mpmath.mp.dps
        self.complex_at = None

    def near_end(self, tv):
        return min(abs(tv - self.lo), abs(tv - self.hi)) <= self.tol * self.span

    def _eval(self, tv):
        dist = min(abs(tv - self.lo), abs(tv - self.hi))
        extra = 0
        if dist < self.span * mpmath.mpf(10) ** -5:
            extra = self.cap if dist == 0 else min(self.cap, int(-mpmath.log10(dist / self.span)))
        if extra:
            with mpmath.extradps(extra):
                return self.g(tv)
        return self.g(tv)

    def __call__(self, tv):
        try:
            v = self._eval(tv)
        except ZeroDivisionError:
            if self.near_end(tv):
                return mpmath.mpf(0)
            raise
        if not mpmath.isfinite(v) and self.near_end(tv):
            return mpmath.mpf(0)
        if isinstance(v, mpmath.mpc):
            if v.imag and abs(v.imag) > abs(v.real) * mpmath.mpf(10) ** (-mpmath.mp.dps + 10):
                if not self.near_end(tv) and self.complex_at is None:
                    self.complex_at = tv
            return +v.real
        return +v


def quad_integral(I: sp.Integral, dps: int = DPS):
    """Numeric value of a one-dimensional definite Integral with numeric limits,
    with a divergence test at both endpoints (local power <= -1 -> Divergent)."""
    if len(I.limits) != 1 or len(I.limits[0]) != 3:
        raise Undefined(f"only one-dimensional definite integrals are evaluated: {I}")
    var, lo, hi = I.limits[0]
    f = I.function
    if f.free_symbols - {var}:
        raise Undefined(f"the integrand has free symbols {sorted(map(str, f.free_symbols - {var}))}")
    with mpmath.workdps(_quad_dps(dps)):
        lo_v, hi_v = _mp(lo), _mp(hi)
        if lo_v == hi_v:
            return mpmath.mpf(0)
        sign = 1
        if hi_v < lo_v:
            lo_v, hi_v, sign = hi_v, lo_v, -1
        g = _Integrand(sp.lambdify(var, f, "mpmath"), lo_v, hi_v)
        span = hi_v - lo_v
        alphas = []
        for e, d in ((lo_v, 1), (hi_v, -1)):
            alpha = _endpoint_exponent(g, e, d, span)
            if alpha is not None and alpha <= -1 + 1e-3:
                raise Divergent(f"the integral {I} diverges at {var} = {sp.N(e, 6)} "
                                f"(integrand ~ |{var} - {sp.N(e, 6)}|^{alpha:.3g})")
            alphas.append(alpha)
        pts = [lo_v] + _breakpoints(f, var, lo_v, hi_v, dps) + [hi_v]
        try:
            v = _quad_segments(g, pts, alphas)
        except (ZeroDivisionError, ValueError) as exc:
            raise Undefined(f"the integral {I} cannot be evaluated: {exc}")
        if g.complex_at is not None:
            raise Undefined(f"the integrand of {I} is complex at {var} = {mpmath.nstr(g.complex_at, 8)}")
        return sign * v


def _quad_segments(g, pts, alphas):
    """Tanh-sinh over the segments.  A strong power singularity |t - e|^alpha
    (-1 < alpha < -1/2) at an end of the interval is first smoothed by
    t = e + (t1 - e) u**m, m = ceil(2/(1 + alpha)): tanh-sinh alone cannot
    place nodes closer to the end than the working precision, and the missing
    piece of such an integrand is of the order of that distance**(1 + alpha)."""
    total = mpmath.mpf(0)
    segs = list(zip(pts[:-1], pts[1:]))
    for i, (l, h) in enumerate(segs):
        a_lo = alphas[0] if i == 0 else None
        a_hi = alphas[1] if i == len(segs) - 1 else None
        if a_lo is not None and -1 < a_lo < -0.5:
            m = min(int(math.ceil(2 / (1 + a_lo))), 2000)
            mid = (l + h) / 2
            total += mpmath.quad(lambda u: g(l + (mid - l) * u**m) * (mid - l) * m * u**(m - 1), [0, 1],
                                 maxdegree=10)
            l = mid
        if a_hi is not None and -1 < a_hi < -0.5:
            m = min(int(math.ceil(2 / (1 + a_hi))), 2000)
            mid = (l + h) / 2
            total += mpmath.quad(lambda u: g(h - (h - mid) * u**m) * (h - mid) * m * u**(m - 1), [0, 1],
                                 maxdegree=10)
            h = mid
        total += mpmath.quad(g, [l, h], maxdegree=10)
    return total


def _mp(v):
    """mpf of an exact SymPy number at the current working precision (rationals
    divided in mpmath, so that they round exactly like lambdified code)."""
    v = to_sympy(v)
    if v.is_Rational:
        return mpmath.mpf(int(v.p)) / int(v.q)
    return mpmath.mpf(str(sp.N(v, mpmath.mp.dps + 5)))


def num_eval(expr: sp.Expr, vals: dict, dps: int = DPS, what: str = "the printed formula", exc=Undefined):
    """mpf value of an expression at a point; integrals by :func:`quad_integral`.

    See :func:`_numeric_values` for how the values are substituted."""
    e = expr.xreplace(_numeric_values(expr, vals, dps))
    if e.has(sp.Derivative):
        e = e.replace(lambda z: isinstance(z, sp.Derivative), lambda z: z.doit())
    if e.has(sp.Integral):
        e = e.replace(lambda z: isinstance(z, sp.Integral),
                      lambda z: sp.Float(quad_integral(z, dps), dps + 10))
    with mpmath.workdps(dps + 10):
        return _finite_real(sp.N(e, dps + 10), what, dps, exc)


def _numeric_values(expr, vals, dps):
    """Values to substitute: exact rationals, except for symbols that appear
    in exponents (a**n), which become Floats of 2*dps + 30 digits -- SymPy
    would factor large integers for an exact rational power.  Bases stay
    exact so that cancellations such as R - sqrt(R**2 - t**2) at t -> 0 are
    resolved by the working precision."""
    in_exponent = set()
    for pw in expr.atoms(sp.Pow):
        in_exponent |= pw.exp.free_symbols
    out = {}
    for k, v in vals.items():
        v = to_sympy(v)
        if k in in_exponent and v.is_Rational and (v.q > 12 or abs(v.p) > 10**4):
            v = sp.Float(v, _quad_dps(dps) + 20)
        out[k] = v
    return out


def flamant_relative_displacement(p, a, xv, E, dps=DPS):
    """u_z(0) - u_z(x) of the half-plane under the even pressure p(s) on |s| < a
    (Flamant/Boussinesq kernel; reference-free)::

        u_z(0) - u_z(x) = (2/(pi E*)) int_0^a p(s) ln|x^2/s^2 - 1| ds

    For a rigid indenter in contact on |x| < a this equals the profile f(x);
    outside it is d - u_z(x), the quantity of Eq. (3).  Evaluated with
    s = a sin(phi) (removes the inverse-square-root edge singularity of
    flat-punch-like pressures), split at the logarithmic point s = x."""
    with mpmath.workdps(_quad_dps(dps)):
        a, xv, E = _mp(a), _mp(xv), _mp(E)
        pr = _Integrand(p, mpmath.mpf(0), a)

        def h(ph):
            sv = a * mpmath.sin(ph)
            return pr(sv) * mpmath.log(abs(xv**2 / sv**2 - 1)) * a * mpmath.cos(ph)
        pts = [mpmath.mpf(0), mpmath.asin(xv / a), mpmath.pi / 2] if xv < a else [mpmath.mpf(0), mpmath.pi / 2]
        val = mpmath.quad(h, pts, maxdegree=10)
        return +(2 * val / (mpmath.pi * E))


def flamant_resultant(p, a, dps=DPS):
    """int_{-a}^{a} p(s) ds for an even pressure (s = a sin(phi))."""
    with mpmath.workdps(_quad_dps(dps)):
        a = _mp(a)
        pr = _Integrand(p, mpmath.mpf(0), a)
        return +(2 * mpmath.quad(lambda ph: pr(a * mpmath.sin(ph)) * a * mpmath.cos(ph),
                                 [0, mpmath.pi / 2], maxdegree=10))


def numeric_minimum(P, dP, scale, dps=DPS):
    """(a*, P(a*)) of the smallest local minimum of P(a) for a > 0, located
    from the sign change of dP/da (- to +) on a logarithmic grid; None when
    P has no minimum (the pull-off does not exist)."""
    with mpmath.workdps(dps + 10):
        # quarter decades from 1e-300 to 1e300: near an existence bound (n -> 1/2
        # for a power law) the minimum moves out to astronomically small or large a
        grid = [mpmath.mpf(scale) * mpmath.mpf(10) ** (k / mpmath.mpf(4)) for k in range(-1200, 1201)]
        prev = None
        for av in grid:
            try:
                d = dP(av)
            except (ZeroDivisionError, ValueError):
                prev = None
                continue
            if isinstance(d, mpmath.mpc):
                prev = None
                continue
            if prev is not None and prev[1] < 0 <= d:
                root = mpmath.findroot(dP, (prev[0], av), solver="anderson")
                return root, P(root)
            prev = (av, d)
    return None


# =====================================================================  derived quantities
@dataclass
class Comparison:
    what: str
    printed: object          # mpf
    target: object           # mpf
    scale: object = None     # mpf; default |target|

    @property
    def digits(self) -> float:
        with mpmath.workdps(2 * DPS):     # never at mpmath's default 15 digits
            err = abs(self.printed - self.target)
            scale = self.scale if self.scale is not None else abs(self.target)
            if err == 0:
                return float(DPS)
            if scale == 0:
                scale = abs(self.printed)
                if scale == 0:
                    return float(DPS)
            return max(0.0, min(float(DPS), float(-mpmath.log10(err / scale))))


@dataclass
class Derived:
    """What the checker compares a printed formula with, for one profile."""

    expr: sp.Expr | None
    method: str
    conditions: tuple = ()
    closed_form: bool = True
    notes: tuple = ()
    seconds: float = 0.0
    verified_digits: float | None = None
    evaluator: Callable | None = None    # (vals, dps) -> mpf
    comparer: Callable | None = None     # (vals, printed_expr, dps) -> [Comparison]
    physics: Callable | None = None      # (vals, printed_expr, dps) -> [Comparison]
    profile: sp.Expr | None = None
    slope: sp.Expr | None = None         # f'(0+)
    variables: frozenset = frozenset()   # symbols the evaluation needs besides those of expr

    def value(self, vals, dps=DPS):
        with mpmath.workdps(dps + 10):   # arithmetic on the values must not round to 15 digits
            return self._value(vals, dps)

    def _value(self, vals, dps):
        for c in self.conditions:
            try:
                ok = c.xreplace(vals)
                ok = bool(ok) if ok in (sp.true, sp.false) else bool(sp.simplify(ok))
            except TypeError:
                ok = False
            if not ok:
                raise DerivedUndefined(f"outside the derived result's conditions ({c})")
        if self.evaluator is not None:
            return self.evaluator(vals, dps)
        return num_eval(self.expr, vals, dps, what="the derived quantity", exc=DerivedUndefined)

    def compare(self, vals, printed_expr, dps=DPS, physics=False):
        with mpmath.workdps(dps + 10):   # arithmetic on the values must not round to 15 digits
            return self._compare(vals, printed_expr, dps, physics)

    def _compare(self, vals, printed_expr, dps, physics):
        if self.comparer is not None:
            comps = self.comparer(vals, printed_expr, dps)
        else:
            target = self.value(vals, dps)
            printed = num_eval(printed_expr, vals, dps)
            comps = [Comparison("value", printed, target)]
        if physics and self.physics is not None and not printed_expr.has(sp.Integral):
            comps += self.physics(vals, printed_expr, dps)
        return comps


class _Context:
    """Caches engine objects across the claims of one run."""

    def __init__(self, budget):
        self.budget = budget
        self.contacts = {}
        self.adhesives = {}

    def contact(self, profile, claim):
        from ..contacts.frictionless import LineContact
        params = {}
        for sym in sorted(profile.free_symbols - {S.x}, key=lambda z: z.name):
            params[sym] = _range_of(sym, claim)
        key = (profile, tuple(sorted((k.name, v) for k, v in params.items())))
        if key not in self.contacts:
            self.contacts[key] = LineContact(profile, params=params or None, budget=self.budget)
        return self.contacts[key]

    def adhesive(self, profile, claim):
        c = self.contact(profile, claim)
        if id(c) not in self.adhesives:
            self.adhesives[id(c)] = c.adhesive(S.gamma)
        return self.adhesives[id(c)]


def _from_derivation(d, profile=None, slope=None, physics=None) -> Derived:
    rec = d.verification
    return Derived(d.expr, d.method, tuple(d.conditions), d.closed_form, tuple(d.notes), d.seconds,
                   rec.min_digits if rec is not None else None,
                   evaluator=(None if d.closed_form else (lambda vals, dps, d=d: _ref_eval(d, vals, dps))),
                   physics=physics, profile=profile, slope=slope)


def _ref_eval(d, vals, dps):
    try:
        return d.reference(vals, dps)
    except (DomainError, ValueError, ZeroDivisionError) as exc:
        raise DerivedUndefined(f"the derived quantity cannot be evaluated here: {exc}")


def _pressure_physics(profile, force_fn):
    """Flamant checks of a pressure: it reproduces the profile under the contact
    and its resultant is the load."""
    def physics(vals, printed_expr, dps):
        fixed = {k: v for k, v in vals.items() if k != S.x}
        p = sp.lambdify(S.x, printed_expr.xreplace(fixed), "mpmath")
        E, av, xv = vals[S.E_star], vals[S.a], vals[S.x]
        with mpmath.workdps(dps + 10):
            D = flamant_relative_displacement(p, av, xv, E, dps)
            fx = num_eval(profile, {**vals}, dps, what="the profile", exc=DerivedUndefined)
            res = flamant_resultant(p, av, dps)
            Pa = force_fn(vals, dps)
        return [Comparison("Flamant: u_z(0) - u_z(x) = f(x) under the contact", D, fx),
                Comparison("Flamant: resultant = P(a)", res, Pa)]
    return physics


def derive(claim: Claim, profile, ctx: _Context) -> Derived:
    """The derived counterpart of ``claim.quantity`` for one profile."""
    q = claim.quantity
    if q in ("force", "pressure", "gap", "Z_n", "profile_at_a", "half_width"):
        c = ctx.contact(profile, claim)
        slope = c.profile.slope_at_origin
        if q == "profile_at_a":
            return Derived(profile.xreplace({S.x: S.a}), "the profile itself, f(a)", profile=profile,
                           slope=slope)
        if q == "Z_n":
            d = c.derivation("force")
            if not d.closed_form:
                raise ClaimError(f"{_w(claim.source, claim.label)}: the engine found no closed force law")
            Z = sp.simplify(sp.gammasimp(d.expr / (S.E_star * S.c * S.a**S.n)))
            if Z.free_symbols - {S.n}:
                raise ClaimError(f"{_w(claim.source, claim.label)}: Z_n needs a power-law profile c*x**n; "
                                 f"P/(E* c a^n) = {Z} depends on {sorted(map(str, Z.free_symbols))}")
            return Derived(Z, f"P(a)/(E* c a^n) of the engine's force law ({d.method})", d.conditions,
                           True, tuple(d.notes), d.seconds,
                           d.verification.min_digits if d.verification else None, profile=profile, slope=slope)
        if q == "half_width":
            return _from_derivation(c.half_width(S.P), profile, slope)
        d = c.derivation(q)
        physics = None
        if q == "pressure":
            fd = c.derivation("force")
            physics = _pressure_physics(profile, lambda vals, dps: _from_derivation(fd).value(vals, dps))
        return _from_derivation(d, profile, slope, physics)
    if q in ("adhesive_force", "adhesive_pressure", "pull_off_force", "pull_off_half_width"):
        return _derive_adhesive(claim, profile, ctx)
    if q == "inverse_profile":
        from ..contacts.inverse import profile_from_force
        t0 = time.perf_counter()
        d = profile_from_force(claim.force_law, budget=ctx.budget)
        out = _from_derivation(d)
        out.seconds = time.perf_counter() - t0
        return out
    if q == "flat_punch_pressure":
        return _flat_punch_pressure()
    if q == "flat_punch_displacement":
        return _flat_punch_displacement()
    if q == "punch_adhesion_force":
        return _punch_adhesion_force(ctx)
    raise ClaimError(f"{_w(claim.source, claim.label)}: quantity {q!r} is not implemented")


def _adhesion_item(ad, name):
    if hasattr(ad, "derivation"):
        try:
            return ad.derivation(name)
        except (KeyError, ValueError, AttributeError, TypeError):
            pass
    return getattr(ad, name)


def _as_derived(obj, method) -> Derived:
    from ..method.derivation import Derivation
    if isinstance(obj, Derivation):
        return _from_derivation(obj)
    return Derived(to_sympy(obj), method)


def _derive_adhesive(claim, profile, ctx) -> Derived:
    t0 = time.perf_counter()
    q = claim.quantity
    ad = ctx.adhesive(profile, claim)
    c = ctx.contact(profile, claim)
    slope = c.profile.slope_at_origin
    force = _as_derived(_adhesion_item(ad, "force"), "adhesive force law (engine, Eq. 33)")
    if q == "adhesive_force":
        force.profile, force.slope = profile, slope
        force.seconds = time.perf_counter() - t0
        return force
    if q == "adhesive_pressure":
        out = _as_derived(_adhesion_item(ad, "pressure"), "adhesive pressure (engine, Eq. 29)")
        out.physics = _pressure_physics(profile, force.value)
        out.profile, out.slope = profile, slope
        out.seconds = time.perf_counter() - t0
        return out
    if q == "pull_off_half_width":
        out = _as_derived(_adhesion_item(ad, "pull_off_half_width"), "half-width at pull-off (engine)")
        out.profile, out.slope = profile, slope
        out.seconds = time.perf_counter() - t0
        return out
    # pull-off: the engine's closed form (sign normalised to P_adh > 0) and an
    # independent numeric minimum of the engine's force law over a
    try:
        engine = _as_derived(_adhesion_item(ad, "adhesion_force"), "adhesion force P_adh (engine)")
        sign = [1]
    except AttributeError:
        engine = _as_derived(_adhesion_item(ad, "pull_off_force"), "pull-off force (engine)")
        sign = [None]
    Pexpr = force.expr
    dPexpr = sp.diff(Pexpr, S.a)

    def minimum(vals, dps):
        fixed = {k: v for k, v in vals.items() if k != S.a}
        Pf = sp.lambdify(S.a, Pexpr.xreplace(fixed), "mpmath")
        dPf = sp.lambdify(S.a, dPexpr.xreplace(fixed), "mpmath")
        scale = 1
        m = numeric_minimum(Pf, dPf, scale, dps)
        if m is None:
            raise DerivedUndefined("P(a) of Eq. (33) has no minimum over a > 0: no pull-off force exists")
        return -m[1]

    def comparer(vals, printed_expr, dps):
        printed = num_eval(printed_expr, vals, dps)
        indep = minimum(vals, dps)
        comps = [Comparison("-min_a P(a), numeric (independent)", printed, indep)]
        try:
            ev = engine.value(vals, dps)
        except (Undefined, LineContactError) as exc:
            raise DerivedUndefined(f"the engine's pull-off is undefined here: {exc}")
        if sign[0] is None:
            sign[0] = -1 if ev < 0 else 1
        comps.insert(0, Comparison("engine pull_off_force", printed, sign[0] * ev))
        return comps

    def evaluator(vals, dps):
        return minimum(vals, dps)
    note = ("the engine's pull_off_force is compared after normalising its sign to P_adh = -P_min > 0; "
            "the minimum of the engine's Eq. (33) over a is also located numerically")
    expr = engine.expr
    return Derived(expr, engine.method + "; independent: numeric minimum of Eq. (33)", engine.conditions,
                   engine.closed_form, tuple(engine.notes) + (note,), time.perf_counter() - t0,
                   engine.verified_digits, evaluator=evaluator, comparer=comparer, profile=profile, slope=slope,
                   variables=frozenset(Pexpr.free_symbols - {S.a}))


# ---------------------------------------------------------------- first principles
def _flat_punch_pressure() -> Derived:
    """Eq. (1) is checked, not compared: the printed pressure must carry the load
    (resultant P) and leave the surface flat under the punch (Flamant)."""
    def comparer(vals, printed_expr, dps):
        fixed = {k: v for k, v in vals.items() if k != S.x}
        p = sp.lambdify(S.x, printed_expr.xreplace(fixed), "mpmath")
        av, xv, E, Pv = (vals[s] for s in (S.a, S.x, S.E_star, S.P))
        with mpmath.workdps(dps + 10):
            res = flamant_resultant(p, av, dps)
            Pv, E = _mp(Pv), _mp(E)
            D = flamant_relative_displacement(p, av, xv, E, dps)
            scale = 2 * Pv / (mpmath.pi * E)
        return [Comparison("resultant int p dx = P", res, Pv),
                Comparison("flat base: u_z(0) - u_z(x) = 0 under the punch (Flamant)", D, mpmath.mpf(0), scale)]
    return Derived(None, "first principles: resultant and Flamant displacement of the printed pressure",
                   comparer=comparer)


def _flat_punch_displacement() -> Derived:
    """d - u_z(x) outside the punch from the Flamant kernel applied to the
    flat-punch pressure P/(pi sqrt(a^2 - x^2)) (whose correctness is claim Eq. (1))."""
    def evaluator(vals, dps):
        av, xv, E, Pv = (vals[s] for s in (S.a, S.x, S.E_star, S.P))

        def p(sv):
            A = _mp(av)
            return _mp(Pv) / (mpmath.pi * mpmath.sqrt(A**2 - sv**2))
        return flamant_relative_displacement(p, av, xv, E, dps)
    return Derived(None, "Flamant kernel applied to the flat-punch pressure P/(pi sqrt(a^2 - x^2))",
                   closed_form=False, evaluator=evaluator)


def _griffith():
    Ph, L, xx = sp.symbols("Phat L xi", positive=True)
    a, E, g = S.a, S.E_star, S.gamma
    # route 1: compliance from Eq. (3) at a far point L, energy balance at fixed d
    C = 2 / (sp.pi * E) * sp.acosh(L / a)
    dCda = sp.limit(sp.diff(C, a), L, sp.oo)
    G_energy = sp.simplify(Ph**2 / 2 * (-dCda) / 2)          # per contact edge
    sol1 = sp.solve(sp.Eq(G_energy, g), Ph)
    # route 2: stress intensity of the pulled punch, G = K^2/(2E*)
    p = Ph / (sp.pi * sp.sqrt(a**2 - xx**2))
    K = sp.limit(sp.sqrt(2 * sp.pi * (a - xx)) * p, xx, a, "-")
    sol2 = sp.solve(sp.Eq(K**2 / (2 * E), g), Ph)
    return sol1, sol2, G_energy, K


def _punch_adhesion_force(ctx) -> Derived:
    t0 = time.perf_counter()
    sol1, sol2, G, K = run_with_budget(_griffith, seconds=max(ctx.budget, 30))
    if len(sol1) != 1 or len(sol2) != 1 or sp.simplify(sol1[0] - sol2[0]) != 0:
        raise ClaimError(f"Griffith derivation of Eq. (31) inconclusive: {sol1} vs {sol2}")
    note = (f"energy route: G = Phat^2/(2 pi a E*) from the compliance of Eq. (3); stress-intensity route: "
            f"K_I = {K}, G = K_I^2/(2E*); both give Phat = {sol1[0]}")
    return Derived(sol1[0], "energy-release rate of the pulled flat punch (Griffith), two routes",
                   notes=(note,), seconds=time.perf_counter() - t0)


# =====================================================================  sampling
def _rat(v):
    return sp.Rational(round(v * 10**6), 10**6)


def _range_of(sym, claim):
    return claim.ranges.get(sym.name) or claim.file_ranges.get(sym.name) or DEFAULT_RANGES.get(sym.name, (0.5, 2.5))


def _holds_at(rels, vals):
    for r in rels:
        v = r.xreplace(vals)
        if getattr(v, "free_symbols", None):
            continue          # an assumption on symbols this point does not involve
        try:
            if v in (sp.true, sp.false):
                ok = bool(v)
            else:
                ok = bool(sp.N(v.lhs - v.rhs, 30) < 0) if isinstance(v, (sp.StrictLessThan, sp.LessThan)) \
                    else bool(sp.simplify(v))
        except TypeError:
            return False
        if not ok:
            return False
    return True


def sample_points(claim: Claim, symbols, k: int, seed: int = 2017):
    """Latin-hypercube points (exact rationals) over the sampling ranges, with
    the claim's assumptions enforced (rejection), plus one point near each end
    of every range the claim declares, plus the claim's special values."""
    rng = random.Random(seed)
    syms = sorted((s for s in symbols if s not in (S.x, T_VAR)), key=lambda z: z.name)
    has_x = S.x in symbols or claim.quantity in X_RANGES
    xr = X_RANGES.get(claim.quantity, (0.02, 0.98))
    perms = {s: rng.sample(range(k), k) for s in syms}
    xperm = rng.sample(range(k), k)
    out = []

    def draw(u_of):
        vals = {}
        for s in syms:
            lo, hi = _range_of(s, claim)
            vals[s] = _rat(lo + (hi - lo) * u_of(s))
        if has_x and S.a in vals:
            vals[S.x] = _rat(float(vals[S.a]) * (xr[0] + (xr[1] - xr[0]) * u_of(S.x)))
        elif has_x:
            lo, hi = _range_of(S.x, claim)
            vals[S.x] = _rat(lo + (hi - lo) * u_of(S.x))
        return vals

    def accept(vals):
        return _holds_at(claim.assumptions, vals)

    for i in range(k):
        for attempt in range(60):
            if attempt == 0:
                u_of = lambda s, i=i: (  # noqa: E731
                    ((perms[s][i] if s in perms else xperm[i]) + rng.uniform(0.15, 0.85)) / k)
            else:
                u_of = lambda s: rng.uniform(0.02, 0.98)  # noqa: E731
            vals = draw(u_of)
            if accept(vals):
                out.append(("random", vals))
                break
    base = out[0][1] if out else None
    for s in syms:
        if s.name in claim.ranges and base is not None:
            lo, hi = claim.ranges[s.name]
            for v in (lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo)):
                vals = dict(base)
                vals[s] = _rat(v)
                if has_x and S.a in vals and s == S.a:
                    vals[S.x] = _rat(float(vals[S.a]) * (xr[0] + xr[1]) / 2)
                if accept(vals):
                    out.append((f"end of the range of {s}", vals))
        for v in claim.special.get(s.name, []):
            if base is None:
                continue
            vals = dict(base)
            vals[s] = v
            if accept(vals):
                out.append((f"special value {s} = {v}", vals))
    return out


# =====================================================================  checking
@dataclass
class PointResult:
    values: dict
    kind: str                 # 'random', 'end of the range ...', 'special value ...', 'bisection'
    status: str               # 'pass', 'fail', 'printed_undefined', 'diverges', 'derived_undefined', 'both_undefined'
    digits: float = 0.0
    comparisons: list = field(default_factory=list)
    reason: str = ""

    @property
    def ok(self):
        return self.status in ("pass", "both_undefined")

    def describe(self) -> str:
        pt = ", ".join(f"{k} = {_fmt_num(v)}" for k, v in sorted(self.values.items(), key=lambda kv: kv[0].name))
        if self.status == "fail":
            worst = min(self.comparisons, key=lambda c: c.digits)
            return (f"at {pt}: {worst.what}: printed {_fmt_mp(worst.printed)}, derived {_fmt_mp(worst.target)} "
                    f"({worst.digits:.1f} digits agree)")
        return f"at {pt}: {self.reason}"

    def to_dict(self):
        return {"point": {k.name: str(v) for k, v in self.values.items()}, "kind": self.kind,
                "status": self.status, "digits": round(self.digits, 2), "reason": self.reason,
                "comparisons": [{"what": c.what, "printed": _fmt_mp(c.printed, 25), "derived": _fmt_mp(c.target, 25),
                                 "digits": round(c.digits, 2)} for c in self.comparisons]}


def _fmt_num(v):
    v = to_sympy(v)
    if v.is_Rational and v.q > 1000:
        return str(sp.N(v, 8))
    return str(v)


def _fmt_mp(v, digits=20):
    if v is None:
        return "-"
    return mpmath.nstr(v, digits) if not isinstance(v, str) else v


def evaluate_point(derived: Derived, printed_expr, vals, kind="random", dps=DPS, physics=False) -> PointResult:
    """Compare at one point; classify what is undefined where."""
    try:
        comps = derived.compare(vals, printed_expr, dps, physics=physics)
    except Divergent as exc:
        return PointResult(vals, kind, "diverges", reason=str(exc))
    except DerivedUndefined as exc:
        try:
            num_eval(printed_expr, vals, dps)
        except Undefined:
            return PointResult(vals, kind, "both_undefined", reason=f"both undefined: {exc}")
        return PointResult(vals, kind, "derived_undefined", reason=str(exc))
    except Undefined as exc:
        return PointResult(vals, kind, "printed_undefined", reason=str(exc))
    except (LineContactError, ZeroDivisionError, ValueError, TypeError, OverflowError) as exc:
        return PointResult(vals, kind, "derived_undefined", reason=f"{type(exc).__name__}: {exc}")
    d = min(c.digits for c in comps)
    return PointResult(vals, kind, "pass" if d >= REQUIRED_DIGITS else "fail", d, comps)


@dataclass
class FormResult:
    form: Form
    status: str
    condition: str = ""
    digits: float = 0.0
    points: list = field(default_factory=list)
    counterexample: PointResult | None = None
    symbolic: str = ""
    note: str = ""

    def to_dict(self):
        return {"formula": self.form.text, "status": self.status, "condition": self.condition,
                "digits": round(self.digits, 2), "symbolic": self.symbolic, "note": self.note,
                "counterexample": self.counterexample.describe() if self.counterexample else None,
                "points": [p.to_dict() for p in self.points]}


@dataclass
class TargetResult:
    profile_text: str
    derived: Derived | None
    forms: list
    status: str
    condition: str = ""
    error: str = ""

    def to_dict(self):
        d = self.derived
        return {"profile": self.profile_text, "status": self.status, "condition": self.condition,
                "error": self.error,
                "derived": str(d.expr) if d is not None and d.expr is not None else None,
                "method": d.method if d is not None else None,
                "conditions": [str(c) for c in d.conditions] if d is not None else [],
                "notes": list(d.notes) if d is not None else [],
                "forms": [f.to_dict() for f in self.forms]}


@dataclass
class ClaimResult:
    claim: Claim
    status: str
    verdict: str                 # one line: status + condition/counterexample
    digits: float
    seconds: float
    targets: list = field(default_factory=list)
    details: list = field(default_factory=list)   # extra lines (table mapping etc.)

    @property
    def label(self):
        return self.claim.label

    def _repr_markdown_(self):
        from ..views.latex import to_latex
        c = self.claim
        lines = [f"**{c.label}** ({c.title or c.quantity}): **{self.status}**"]
        if c.forms:
            lines.append(f"$$ {to_latex(c.formula.shown)} $$")
        lines.append(self.verdict)
        for t in self.targets:
            if t.derived is not None and t.derived.expr is not None and not c.values:
                lines.append(f"- derived{' for ' + t.profile_text if c.general else ''}: "
                             f"${to_latex(t.derived.expr)}$")
        return "\n\n".join(lines)

    def to_dict(self):
        c = self.claim
        return {"label": c.label, "title": c.title, "quantity": c.quantity, "status": self.status,
                "verdict": self.verdict, "digits": round(self.digits, 2), "seconds": round(self.seconds, 3),
                "formula": c.formula.text if c.forms else None,
                "forms": [f.text for f in c.forms], "profiles": [p for p, _ in c.profiles],
                "assumptions": [str(r) for r in c.assumptions], "note": c.note, "reading": c.reading,
                "details": self.details, "targets": [t.to_dict() for t in self.targets]}


def _substitute(expr, profile, derived_force=None, derived_pressure=None):
    """Replace the placeholders f(.), force(.), p0 of a general formula."""
    if profile is not None and expr.has(PLACEHOLDER_F):
        expr = expr.replace(lambda e: isinstance(e, AppliedUndef) and e.func == PLACEHOLDER_F,
                            lambda e: profile.xreplace({S.x: e.args[0]}))
    if expr.has(PLACEHOLDER_FORCE):
        if derived_force is None:
            raise ClaimError("force(...) is used but the engine found no closed-form force law")
        expr = expr.replace(lambda e: isinstance(e, AppliedUndef) and e.func == PLACEHOLDER_FORCE,
                            lambda e: derived_force.xreplace({S.a: e.args[0]}))
    if expr.has(PLACEHOLDER_P0):
        if derived_pressure is None:
            raise ClaimError("p0 is used but the engine found no closed-form pressure")
        expr = expr.xreplace({PLACEHOLDER_P0: derived_pressure})
    return expr


def _symbolic(printed, derived: Derived, vals, budget) -> str:
    if derived.expr is None or not derived.closed_form:
        return ""
    dex = derived.expr
    if isinstance(dex, sp.Piecewise) and vals is not None:
        for e, cnd in dex.args:
            v = cnd.xreplace(vals)
            if v == sp.true or (v != sp.false and _holds_at([v], {})):
                dex = e
                break

    def work(p, d):
        if p.has(sp.Integral):
            p = p.doit()
            if p.has(sp.Integral):
                return "not decided (SymPy leaves the printed integral unevaluated)"
            p = sp.piecewise_fold(p)
            if isinstance(p, sp.Piecewise):
                for e, cnd in p.args:
                    if cnd == sp.true or (vals is not None and cnd.xreplace(vals) == sp.true):
                        p = e
                        break
        diff = sp.simplify(sp.gammasimp(p - d))
        if diff == 0:
            return "identical (SymPy simplifies the difference to 0)"
        if diff.has(sp.gamma) and sp.simplify(sp.gammasimp(sp.expand_func(diff))) == 0:
            return "identical (0 after expanding the Gamma functions)"
        diff2 = sp.simplify(sp.expand_log(sp.expand(diff.rewrite(sp.log)), force=True))
        if diff2 == 0:
            return "identical (difference is 0 after rewriting in logarithms)"
        if not diff.free_symbols:
            return f"differs by the constant {diff}"
        return "not decided by simplify"
    try:
        return run_with_budget(work, printed, dex, seconds=budget)
    except BudgetExceeded:
        return f"not decided within {budget:g} s"
    except Exception as exc:  # noqa: BLE001
        return f"not decided ({type(exc).__name__})"


def _status_ok_loose(pr: PointResult) -> bool:
    return pr.status in ("pass", "both_undefined") or (pr.status == "fail" and pr.digits >= 8)


def _bisect_boundary(derived, printed, sym, v_fail, v_pass, base_vals, dps, iters=24):
    """Locate the boundary between failing and passing values of one parameter."""
    lo, hi = mpmath.mpf(v_fail), mpmath.mpf(v_pass)
    for _ in range(iters):
        mid = (lo + hi) / 2
        vals = dict(base_vals)
        vals[sym] = sp.Rational(str(mpmath.nstr(mid, 20)))
        pr = evaluate_point(derived, printed, vals, "bisection", dps=30)
        if _status_ok_loose(pr):
            hi = mid
        else:
            lo = mid
        if abs(hi - lo) < mpmath.mpf(10) ** -7 * max(1, abs(hi)):
            break
    return (lo + hi) / 2


def _nice(value):
    """A simple rational near a located boundary (denominator <= 12)."""
    best = None
    for q in range(1, 13):
        p = round(float(value) * q)
        cand = sp.Rational(p, q)
        err = abs(float(cand) - float(value))
        if err < 2e-2 * max(1.0, abs(float(value))) and (best is None or err < best[1] - 1e-12):
            best = (cand, err)
    return best[0] if best else sp.Float(float(value), 6)


def _infer_parameter_condition(derived, printed, points, dps):
    """A one-parameter range (p > v or p < v) separating the points where the
    printed form holds from those where it fails; refined by bisection."""
    rand = [p for p in points if p.kind != "bisection" and not p.kind.startswith("special")]
    good = [p for p in rand if p.ok]
    bad = [p for p in rand if not p.ok]
    if not good or not bad:
        return None
    for sym in sorted(good[0].values, key=lambda z: z.name):
        if sym in (S.x,):
            continue
        gv = [float(p.values[sym]) for p in good]
        bv = [float(p.values[sym]) for p in bad]
        if max(bv) < min(gv):
            direction = ">"
            fail_v, pass_v = max(bv), min(gv)
        elif min(bv) > max(gv):
            direction = "<"
            fail_v, pass_v = min(bv), max(gv)
        else:
            continue
        base = next(p for p in good if float(p.values[sym]) == pass_v).values
        b = _bisect_boundary(derived, printed, sym, fail_v, pass_v, base, dps)
        nice = _nice(b)
        # at the boundary itself
        vals = dict(base)
        vals[sym] = nice if nice.is_Rational else sp.Rational(str(b))
        at = evaluate_point(derived, printed, vals, "boundary", dps=dps)
        op = {(">", True): ">=", (">", False): ">", ("<", True): "<=", ("<", False): "<"}[(direction, at.ok)]
        what = {"fail": "fails", "diverges": "the printed integral diverges",
                "printed_undefined": "the printed form is undefined",
                "derived_undefined": "the derived quantity does not exist"}
        reasons = sorted({what.get(p.status, p.status) for p in bad})
        return (f"{sym} {op} {nice}", sym, nice, at, reasons)
    return None


def check_form(claim: Claim, form: Form, derived: Derived, printed, *, dps=DPS, budget=10.0,
               seed=2017, physics_points=2, symbolic=True) -> FormResult:
    """Check one printed form against the derived quantity."""
    free = set(printed.free_symbols) - {T_VAR}
    if derived.expr is not None:
        free |= derived.expr.free_symbols
    if derived.profile is not None:
        free |= derived.profile.free_symbols - {S.x}
    free |= set(derived.variables)
    if claim.quantity in X_RANGES:
        free |= {S.x, S.a}
    if claim.quantity in ("flat_punch_pressure", "flat_punch_displacement", "pressure", "adhesive_pressure"):
        free |= {S.E_star}
    if claim.quantity in ("flat_punch_pressure", "flat_punch_displacement"):
        free |= {S.P}
    pts = sample_points(claim, free, claim.points, seed=seed)
    results = []
    nphys = 0
    for kind, vals in pts:
        phys = derived.physics is not None and nphys < physics_points
        pr = evaluate_point(derived, printed, vals, kind, dps, physics=phys)
        if phys and pr.status == "pass":
            nphys += 1
        results.append(pr)
    sym_note = ""
    if symbolic and derived.expr is not None and not printed.has(AppliedUndef):
        sym_note = _symbolic(printed, derived, pts[0][1] if pts else None,
                             min(budget, 4.0) if printed.has(sp.Integral) else budget)
    ok = [p for p in results if p.ok]
    bad = [p for p in results if not p.ok]
    digits = min((p.digits for p in ok if p.status == "pass"), default=0.0)
    if not bad:
        return FormResult(form, HOLDS, "", digits, results, None, sym_note)
    if not ok:
        return FormResult(form, FAILS, "", max((p.digits for p in bad), default=0.0), results, bad[0], sym_note)
    # a condition: excluded special points, or a parameter range
    special_bad = [p for p in bad if p.kind.startswith("special")]
    other_bad = [p for p in bad if not p.kind.startswith("special")]
    conds = []
    notes = []
    for p in special_bad:
        spec = p.kind.replace("special value ", "")
        if p.status == "printed_undefined":
            sym = next(s for s in p.values if spec.startswith(s.name + " "))
            lim = _limit_note(derived, printed, p.values, sym, dps)
            conds.append(f"{spec.replace('=', '!=')}")
            notes.append(f"at {spec} the printed form is undefined ({p.reason}); {lim}")
        else:
            conds.append(f"not at {spec}")
            notes.append(p.describe())
    cex = bad[0]
    if other_bad:
        inf = _infer_parameter_condition(derived, printed, results, dps)
        if inf is not None:
            text, sym, nice, at, reasons = inf
            # special values outside the range found need no separate mention
            keep = [i for i, p in enumerate(special_bad) if _in_range(text, sym, nice, p.values.get(sym))]
            conds = [conds[i] for i in keep]
            notes = [notes[i] for i in keep]
            conds.insert(0, text)
            notes.insert(0, f"outside {text}: " + "; ".join(reasons) + f" (e.g. {other_bad[0].describe()})")
        else:
            conds.insert(0, "only at some of the points")
            notes.insert(0, other_bad[0].describe())
        cex = other_bad[0]
    return FormResult(form, HOLDS_IF, " and ".join(conds), digits, results, cex, sym_note, "; ".join(notes))


def _in_range(text, sym, bound, value):
    if value is None:
        return True
    op = text.split()[1]
    return bool({">": value > bound, ">=": value >= bound, "<": value < bound, "<=": value <= bound}[op])


def _limit_note(derived, printed, vals, sym, dps):
    """Does the printed form tend to the derived value at a removable point?"""
    try:
        target = derived.value(vals, dps)
    except Undefined:
        return "the derived quantity is undefined there too"
    eps = sp.Rational(1, 10**20)
    out = []
    with mpmath.workdps(dps + 30):
        for side in (1, -1):
            v2 = dict(vals)
            v2[sym] = vals[sym] + side * eps
            try:
                pv = num_eval(printed, v2, dps + 30)
            except Undefined:
                return "its limit could not be evaluated"
            out.append(float(-mpmath.log10(abs(pv - target) / max(abs(target), mpmath.mpf(10) ** -30) + 10**-40)))
    if min(out) > 15:
        return f"its limit there equals the derived value {_fmt_mp(target, 15)} (removable singularity)"
    return f"its limit there differs from the derived value {_fmt_mp(target, 15)}"


# ---------------------------------------------------------------- per claim
def _verdict_line(status, condition, cex: PointResult | None, extra=""):
    if status == HOLDS:
        return HOLDS + (f" ({extra})" if extra else "")
    if status == HOLDS_IF:
        return f"{HOLDS_IF}: {condition}" + (f" ({extra})" if extra else "")
    if status == FAILS:
        return f"{FAILS}: " + (cex.describe() if cex else extra)
    return f"{UNDECIDED}: {extra}"


def check_claim(claim: Claim, ctx: _Context | None = None, *, budget: float = 20.0, dps: int = DPS,
                symbolic: bool = True) -> ClaimResult:
    """Derive, compare and judge one claim."""
    ctx = ctx or _Context(budget)
    t0 = time.perf_counter()
    if claim.values:
        return _check_table(claim, ctx, t0)
    targets = []
    profiles = claim.profiles or [(None, None)]
    for ptxt, prof in profiles:
        try:
            derived = derive(claim, prof, ctx)
        except ImportError as exc:
            targets.append(TargetResult(ptxt, None, [], UNDECIDED, error=f"engine module missing: {exc}"))
            continue
        except (LineContactError, BudgetExceeded) as exc:
            targets.append(TargetResult(ptxt, None, [], UNDECIDED, error=f"{type(exc).__name__}: {exc}"))
            continue
        except Exception as exc:  # noqa: BLE001 -- an engine bug must not stop the other claims
            targets.append(TargetResult(ptxt, None, [], UNDECIDED,
                                        error=f"internal error in the engine: {type(exc).__name__}: {exc}"))
            continue
        dforce = dpress = None
        if claim.general:
            c = ctx.contact(prof, claim)
            if any(f.expr.has(PLACEHOLDER_FORCE) for f in claim.forms):
                fd = c.derivation("force")
                dforce = fd.expr if fd.closed_form else None
            if any(f.expr.has(PLACEHOLDER_P0) for f in claim.forms):
                pd = c.derivation("pressure")
                dpress = pd.expr if pd.closed_form else None
        frs = []
        try:
            for form in claim.forms:
                printed = _substitute(form.expr, prof, dforce, dpress)
                frs.append(check_form(claim, form, derived, printed, dps=dps, budget=min(budget, 10.0),
                                      symbolic=symbolic))
        except ClaimError as exc:
            targets.append(TargetResult(ptxt, derived, frs, UNDECIDED, error=str(exc)))
            continue
        st, cond = _combine_forms(frs)
        targets.append(TargetResult(ptxt, derived, frs, st, cond))
    status, verdict, digits = _combine_targets(claim, targets)
    return ClaimResult(claim, status, verdict, digits, time.perf_counter() - t0, targets)


def _combine_forms(frs):
    sts = [f.status for f in frs]
    if all(s == HOLDS for s in sts):
        return HOLDS, ""
    if all(s == FAILS for s in sts):
        return FAILS, ""
    parts = []
    multi = len(frs) > 1
    for i, f in enumerate(frs):
        name = ("final form" if i == len(frs) - 1 else f"form {i + 1}") if multi else ""
        if f.status == HOLDS_IF:
            parts.append((f"{name}: " if name else "") + f.condition)
        elif f.status == FAILS:
            parts.append((f"{name}: " if name else "") + "does not hold")
        elif f.status == UNDECIDED:
            parts.append((f"{name}: " if name else "") + "undecided")
    return HOLDS_IF, "; ".join(parts)


def _combine_targets(claim, targets):
    if any(t.status == UNDECIDED for t in targets):
        errs = "; ".join(f"{t.profile_text or claim.quantity}: {t.error}" for t in targets if t.status == UNDECIDED)
        return UNDECIDED, f"{UNDECIDED}: {errs}", 0.0
    digits = min((f.digits for t in targets for f in t.forms if f.status != FAILS), default=0.0)
    sts = [t.status for t in targets]
    if all(s == HOLDS for s in sts):
        sym = [f.symbolic for t in targets for f in t.forms if f.symbolic.startswith("identical")]
        extra = "symbolically identical" if sym and len(sym) == sum(len(t.forms) for t in targets) else ""
        return HOLDS, _verdict_line(HOLDS, "", None, extra), digits
    if not claim.general:
        t = targets[0]
        if t.status == FAILS:
            f = next(f for f in t.forms if f.status == FAILS)
            return FAILS, _verdict_line(FAILS, "", f.counterexample), max(f.digits for f in t.forms)
        return HOLDS_IF, _verdict_line(HOLDS_IF, t.condition, None), digits
    # general claims: is the split explained by f'(0+) = 0 ?
    prop = _slope_hypothesis(targets)
    per = []
    for t in targets:
        if t.status == HOLDS:
            continue
        if t.status == FAILS:
            f = next(f for f in t.forms if f.status == FAILS)
            per.append(f"fails for {t.profile_text} ({f.counterexample.describe()})")
        else:
            per.append(f"{t.profile_text}: {t.condition}")
    if all(s == FAILS for s in sts):
        return FAILS, f"{FAILS}: " + "; ".join(per), 0.0
    held = [t.profile_text for t in targets if t.status == HOLDS]
    head = "only where f'(0+) = 0" if prop else "for some of the test profiles only"
    if prop and claim.quantity == "force" and _misses_boundary_term(targets):
        head += " (where it fails with finite values, derived - printed = E*·a·f'(0+) exactly: the printed " \
                "form drops the boundary term of the integration by parts)"
    cond = head + ("; holds for " + ", ".join(held) if held else "") + "; " + "; ".join(per)
    return HOLDS_IF, f"{HOLDS_IF}: {cond}", digits


def _misses_boundary_term(targets) -> bool:
    """At every failing point with finite values: derived - printed = E* a f'(0+)?"""
    seen = False
    for t in targets:
        d = t.derived
        if d is None or d.slope is None:
            continue
        for f in t.forms:
            for p in f.points:
                if p.status != "fail":
                    continue
                c = p.comparisons[0]
                try:
                    term = num_eval(S.E_star * S.a * d.slope, p.values, DPS)
                except Undefined:
                    return False
                with mpmath.workdps(DPS + 10):
                    if Comparison("boundary term", c.target - c.printed, term).digits < 20:
                        return False
                seen = True
    return seen


def _slope_hypothesis(targets) -> bool:
    """True when the printed form holds exactly at the points where f'(0+) = 0."""
    seen_zero = seen_nonzero = False
    for t in targets:
        d = t.derived
        if d is None or d.slope is None:
            return False
        for f in t.forms:
            for p in f.points:
                if p.kind in ("bisection", "boundary"):
                    continue
                try:
                    sv = d.slope.xreplace(p.values)
                    sv = sp.N(sv) if not isinstance(sv, sp.Piecewise) else sp.N(sv.doit())
                    zero = sv == 0
                except Exception:  # noqa: BLE001
                    return False
                seen_zero |= zero
                seen_nonzero |= not zero
                if zero != p.ok:
                    # a form that fails where f'(0+) = 0 (or holds elsewhere) breaks the hypothesis
                    if f is t.forms[-1] or not zero:
                        return False
    return seen_zero and seen_nonzero


# ---------------------------------------------------------------- Table 1
def _check_table(claim: Claim, ctx: _Context, t0) -> ClaimResult:
    """Each printed Z value belongs to which n?  Z_n increases with n, so each
    value has one n; it is located by root finding and identified exactly."""
    prof_txt, prof = claim.profiles[0]
    try:
        derived = derive(claim, prof, ctx)
    except (LineContactError, ImportError) as exc:
        return ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: {exc}", 0.0, time.perf_counter() - t0)
    Z = derived.expr
    Zf = sp.lambdify(S.n, Z, "mpmath")
    rows, problems, digits = [], [], []
    found = []
    for text, val in claim.values:
        with mpmath.workdps(DPS):
            target = _mpf(val, DPS)
            try:
                nroot = mpmath.findroot(lambda nv: Zf(nv) - target, (mpmath.mpf("0.01"), mpmath.mpf(200)),
                                        solver="anderson")
            except (ValueError, ZeroDivisionError):
                problems.append(f"{text}: no n > 0 with Z_n = {text}")
                continue
        nn = sp.nsimplify(float(nroot), rational=True, tolerance=1e-9)
        exact = sp.simplify(sp.gammasimp(Z.subs(S.n, nn) - val)) == 0 if nn.is_Rational else False
        with mpmath.workdps(DPS):
            dg = Comparison("Z", _mpf(Z.subs(S.n, nn), DPS), target).digits
        digits.append(dg)
        found.append(nn)
        lab = claim.labels.get(text)
        if lab is not None:
            if lab != nn:
                problems.append(f"{text} is printed for n = {lab} but Z_{lab} = {Z.subs(S.n, lab)}")
        rows.append({"value": text, "n": str(nn), "exact": bool(exact), "digits": round(dg, 1),
                     "label": (f"{lab} ({'agrees' if lab == nn else 'DISAGREES'})" if lab is not None else None)})
        if not (nn.is_Integer and exact):
            problems.append(f"{text}: Z_n = {text} at n = {sp.N(nroot, 12)}, not an integer")
    ints = [int(v) for v in found if v.is_Integer]
    gaps = [k for k in range(1, max(ints) + 1) if k not in ints] if ints else []
    mapping = ", ".join(f"{r['value']} -> n = {r['n']}" for r in rows)
    details = [f"{r['value']}: n = {r['n']}" + (" (exact)" if r["exact"] else "") +
               (f", printed label n = {r['label']}" if r["label"] else "") for r in rows]
    gap_note = ""
    if gaps:
        gap_note = "; no value printed (or legible) for " + ", ".join(
            f"n = {k} (Z_{k} = {sp.nsimplify(Z.subs(S.n, k))})" for k in gaps)
    details.append(f"Z_n from the engine: {Z}; Z_1 = {sp.nsimplify(Z.subs(S.n, 1))}")
    seconds = time.perf_counter() - t0
    tr = TargetResult(prof_txt, derived, [], HOLDS if not problems else FAILS)
    if problems:
        return ClaimResult(claim, FAILS, f"{FAILS}: " + "; ".join(problems), min(digits, default=0), seconds,
                           [tr], details)
    return ClaimResult(claim, HOLDS, f"{HOLDS}: {mapping}{gap_note}", min(digits, default=0), seconds,
                       [tr], details)


# =====================================================================  papers
@dataclass
class PaperResult:
    paper: Paper
    results: list
    seconds: float

    @property
    def ok(self) -> bool:
        return all(r.status != UNDECIDED for r in self.results)

    def _repr_markdown_(self):
        from .report import markdown_summary
        return markdown_summary(self)

    def to_dict(self):
        return {"key": self.paper.key, "title": self.paper.title, "reference": self.paper.reference,
                "source": self.paper.source, "seconds": round(self.seconds, 2),
                "counts": {s: sum(r.status == s for r in self.results) for s in (HOLDS, HOLDS_IF, FAILS, UNDECIDED)},
                "claims": [r.to_dict() for r in self.results]}


def check_paper(paper, *, budget: float = 20.0, progress: Callable | None = None, only=None,
                dps: int = DPS, symbolic: bool = True) -> PaperResult:
    """Check every claim of a paper (a :class:`Paper`, a path, or a shipped name).

    ``progress(i, n, result)`` is called after each claim; ``only`` limits the
    run to the given labels."""
    if not isinstance(paper, Paper):
        paper = load_paper(paper)
    ctx = _Context(budget)
    t0 = time.perf_counter()
    claims = [c for c in paper.claims if only is None or c.label in only]
    results = []
    for i, claim in enumerate(claims):
        try:
            r = check_claim(claim, ctx, budget=budget, dps=dps, symbolic=symbolic)
        except ClaimError as exc:
            r = ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: {exc}", 0.0, 0.0)
        except Exception as exc:  # noqa: BLE001 -- report, and go on with the next claim
            r = ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: internal error {type(exc).__name__}: {exc}", 0.0, 0.0)
        results.append(r)
        if progress is not None:
            progress(i, len(claims), r)
    return PaperResult(paper, results, time.perf_counter() - t0)


def check_file(path, **kw) -> PaperResult:
    return check_paper(load_paper(path), **kw)


__all__ = ["Claim", "Paper", "Form", "ClaimResult", "PaperResult", "load_paper", "paper_from_dict",
           "claim_from_dict", "claim_from_cli", "check_claim", "check_paper", "check_file", "num_eval",
           "quad_integral", "flamant_relative_displacement", "flamant_resultant", "QUANTITIES",
           "HOLDS", "HOLDS_IF", "FAILS", "UNDECIDED", "REQUIRED_DIGITS", "DPS"]
