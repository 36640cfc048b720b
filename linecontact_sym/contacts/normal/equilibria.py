"""Stationary points, minima and equilibria of a :class:`~.force_law.ForceLaw`:
the one scan / bracket / root / minimum toolkit of the contacts layer.

Load control.  A contact at load P sits at a half-width a with P(a) = P; it
is stable where dP/da > 0.  **Pull-off**: a contact pulled from one larger
than every local minimum of P(a) follows the stable branch down to the
largest-a local minimum; there it jumps, at the same load, to a stable
equilibrium at smaller a if one exists (and follows that branch on), and
separates when there is none.  Every jump lands on a branch whose minimum
is lower, so the contact separates at the **global minimum of P over the
admissible range** 0 < a <= a*: that minimum is the pull-off load.
Minima are of three kinds: 'stationary' (dP/da = 0), 'kink' (a profile
breakpoint where dP/da jumps from negative to positive) and 'end' (the end
a* of the admissible range with dP/da < 0 there).  At an 'end' minimum the
frictionless solution stops holding (beyond a* the pressure at the edges
of the non-adhesive contact turns tensile, or the profile is not defined):
the contact is not followed further, and a pull-off of kind 'end' is the
lowest load the model describes, not a separation it can prove.  The end
lies on a falling branch (unstable under load control), so a contact
unloaded from a stable branch separates at a stationary or kink minimum
(or the infimum) first: the end is the pull-off only where there is none,
and a lower end beside one is reported in the note, not taken.

The admissible range (:func:`admissible_range`): a* is the first a where
the non-adhesive slope dP0/da turns negative (the edge pressure is
p ~ dP0/da sqrt(a - |x|)/pi, tensile beyond) or the end of the real domain
of the law (the exact cylinder at a = R), whichever comes first; without
either, the search runs up to 4**40 times the law's length scale.  Where
dP0/da >= 0 is proven from the profile (P0 convex, or
:func:`~.force_law.rising_profile`: h' = f' + t f'' >= 0 on every piece, no
falling slope jump) there is no a* to search for.

**None missed** (:func:`landscape`).  Every sign change of dP/da on
[4**-20 s, a*] (s the length scale, :data:`SPAN`) is found by subdivision in ln a, split
at the profile's breakpoints:

* closed-form law (python-flint, a core dependency): dP/da (and d2P/da2) evaluated in ball
  arithmetic on each interval; an interval whose ball excludes 0 holds no
  stationary point, one with dP/da of opposite signs at its ends and a ball
  of d2P/da2 that excludes 0 holds exactly one.  This is a proof, up to the
  widths below.
* quadrature law (or a function without a ball translation; the landscape's ``method`` and ``notes`` say which): an
  interval is excluded when the values of dP/da at its ends, log-quartiles
  and log-midpoint have one sign and each is more than twice the largest
  change between neighbours (the error bound assumes dP/da varies by at most
  twice its sampled change between neighbouring samples).  With three
  samples (ends and midpoint) a narrow dip below zero between the midpoint
  and an end went unseen (a minimum missed: a law with stationary points at
  a = 1.811 and 1.935 next to one at 0.26).

An interval is not split below a relative width of 1e-10; one that is
neither excluded nor holds a sign change there is listed in ``notes`` as a
possible touching zero.  Within 1e-12 (relative) of a breakpoint the sign
of dP/da is the one at that distance (the slope jump term
J b**2/sqrt(a**2 - b**2) dominates there).

Equilibria at a load (:func:`equilibria`): between two neighbouring extrema
P is monotone, so each such segment holds at most one root of P(a) = load;
stable where P increases.
"""
from __future__ import annotations

import contextlib
import contextvars
from dataclasses import dataclass

import flint
import mpmath

from ...core.budget import Deadline
from ...core.conversion import to_mpf
from ...core.errors import BudgetExceeded, DomainError, InadmissibleProfileError, NoPullOffError, VerificationError
from ...core.roots import UNDEFINED, domain_end, root_in_log
from .force_law import GUARD, PullOff
from ...core.precision import workdps

#: relative width below which an interval is not split
MIN_WIDTH = mpmath.mpf("1e-10")
#: relative distance from a breakpoint where the one-sided signs are read
KINK_GAP = mpmath.mpf("1e-12")
#: the search covers 4**-20 (about 1e-12) .. 4**40 (about 1e24) times the
#: law's length scale (below, the closed forms of the catalogue cancel to
#: nothing at 20 digits and the adhesive term dominates every pull-off)
SPAN = (mpmath.mpf(4)**-20, mpmath.mpf(4)**40)
#: relative width (in ln a) below which an inconclusive ball (the dependency
#: problem of interval arithmetic) hands the interval to the sampled bound
BALL_GIVEUP = mpmath.mpf("1e-3")
#: intervals examined per search before it gives up
MAX_INTERVALS = 20000
#: bits of the ball arithmetic
BALL_PREC = 192


#: the default wall-clock budget (seconds) of one numeric search at numbers
#: (a pull-off, a half-width): generous, since a search is correct however long
#: it takes; a budget passed by the caller is the deadline
SEARCH_BUDGET = 120.0

#: the deadline of the numeric searches running in this context (None: none)
_DEADLINE = contextvars.ContextVar("linecontact_sym_search_deadline", default=None)


@contextlib.contextmanager
def searching_until(budget):
    """Run the numeric searches of this module (scans, subdivisions, roots)
    under a ``budget`` of CPU seconds (None: no limit; :class:`~linecontact_sym.core.budget.Deadline`): they check it
    between evaluations and raise :class:`BudgetExceeded` when it is spent.
    In-process and cheap (no fork): a search is a loop of mpmath or ball
    evaluations, each short, so the check between them is a deadline."""
    token = _DEADLINE.set(Deadline(budget) if budget is not None else None)
    try:
        yield
    finally:
        _DEADLINE.reset(token)


def within_search_budget():
    """:func:`searching_until` the default :data:`SEARCH_BUDGET` where no search deadline is running
    (a numeric quantity evaluated through its Derivation's reference: a claims file, ``evaluate``),
    else nothing: every search at numbers ends in :class:`BudgetExceeded`, never a wait."""
    if _DEADLINE.get() is not None:
        return contextlib.nullcontext()
    return searching_until(SEARCH_BUDGET)


def check_deadline(what):
    """Raise :class:`BudgetExceeded` naming ``what`` when the running search deadline is spent."""
    d = _DEADLINE.get()
    if d is not None and d.expired():
        raise BudgetExceeded(f"{what} did not finish within its budget of {d.budget:g} CPU s")


@dataclass(frozen=True)
class Extremum:
    """A local extremum of P(a): half-width, force, kind ('stationary',
    'kink', 'end') and whether it is a minimum."""

    half_width: mpmath.mpf
    force: mpmath.mpf
    kind: str
    minimum: bool = True
    bracket: tuple = ()


@dataclass
class Landscape:
    """Every extremum of P(a) over the searched range [lo, hi] (see the module
    docstring).  ``end`` says why the range stops at hi: 'admissible' (dP0/da
    turns negative), 'domain' (the law stops being real) or 'search' (the
    search limit); ``rising_at_end`` whether dP/da > 0 just below hi."""

    lo: mpmath.mpf
    hi: mpmath.mpf
    end: str
    extrema: tuple
    method: str
    notes: tuple = ()
    rising_at_end: bool = True

    @property
    def minima(self):
        return tuple(e for e in self.extrema if e.minimum)

    def describe(self) -> str:
        end = {"admissible": "the end of the admissible range (dP0/da turns negative there)",
               "domain": "the end of the law's real domain", "search": "the search limit"}[self.end]
        how = {"convex": "the convexity of P0 (dP/da increasing: one sign change at most)",
               "ball": "ball arithmetic on dP/da (python-flint): no stationary point missed",
               "ball+adaptive": "ball arithmetic on dP/da, with the sampled bound where the balls were "
                                "inconclusive",
               "scan": "the law's log grid of dP/da (its ScanHint)"}.get(self.method, "adaptive subdivision of dP/da with a sampled "
                                                                 "error bound")
        return (f"searched a in [{mpmath.nstr(self.lo, 4)}, {mpmath.nstr(self.hi, 8)}] up to {end}, by {how}; "
                f"{len(self.minima)} local minimum(s): "
                + ", ".join(f"{e.kind} at a = {mpmath.nstr(e.half_width, 8)} (P = {mpmath.nstr(e.force, 8)})"
                            for e in self.minima))


# ---------------------------------------------------------------- sign changes
class _Balls:
    """dP/da and d2P/da2 of a closed-form law in ball arithmetic, or the
    reason there are none."""

    def __init__(self, law, which="dP"):
        self.reason = None
        self.gave_up = 0
        self.f = self.df = None
        expr = law.expr
        if expr is None:
            self.reason = "no closed form (quadrature law)"
            return
        try:
            from ...numeric.certified import compile_arb
            import sympy as sp
            from ...core import symbols as S
            d1 = sp.diff(expr, S.a)
            self.f = compile_arb(d1, [S.a])
            self.df = compile_arb(sp.diff(d1, S.a), [S.a])
            self.flint = flint
        except Exception as exc:  # CertificationError (no ball translation): the numeric method
            self.reason = f"{type(exc).__name__}: {str(exc).splitlines()[0]}"
            self.f = None
        self.ok = None
        if law.conditions:
            import sympy as sp
            from ...core import symbols as S
            self.ok = sp.lambdify(S.a, sp.And(*law.conditions), "mpmath")

    def __call__(self, fn, lo, hi):
        """The ball of fn over [lo, hi], or None (not finite, not available,
        the closed form's conditions fail at an end)."""
        if self.f is None:
            return None
        try:
            if self.ok is not None and not (bool(self.ok(lo)) and bool(self.ok(hi))):
                return None
        except Exception:
            return None
        from ...numeric.certified import to_arb
        flint = self.flint
        try:
            with flint.ctx.workprec(BALL_PREC):
                A = to_arb(lo).union(to_arb(hi))
                y = fn(A)
                return y if y.is_finite() else None
        except Exception:
            return None


def reliable(fn):
    """``fn`` (a closed-form law's P or dP) evaluated at 20 digits, raising the
    precision (40, 80, ... 640) until two levels agree to 10 digits: closed
    forms such as K(m) - E(m) cancel at small a."""
    def g(A):
        v, k = None, 20
        while k <= 640:
            with workdps(k):
                w = fn(A)
            if v is not None and abs(w - v) <= abs(w) * mpmath.mpf(10)**-10:
                return +w
            v, k = w, 2 * k
        return +v
    return g


def _excludes_zero(y):
    return y is not None and (y > 0 or y < 0 or y.is_zero())


def crossings(g, lo, hi, balls=None, notes=None, first=False):
    """Sign changes of g on [lo, hi] (0 < lo < hi) by subdivision in ln a
    (module docstring): a list of brackets (l, r), ascending, with g(l) and
    g(r) of opposite signs (zero counts as positive).  ``balls``: a
    :class:`_Balls` of g (rigorous exclusion); else the sampled bound.
    Possible touching zeros are appended to ``notes``.  ``first``: stop at
    the first (lowest) sign change (intervals are examined left to right)."""
    vals = {}

    def G(A):
        if A not in vals:
            vals[A] = g(A)
        return vals[A]
    out, stack, count, touching = [], [(lo, hi)], 0, []
    rigorous = balls is not None and balls.f is not None
    while stack:
        l, r = stack.pop()
        count += 1
        check_deadline("the search for stationary points of P(a)")
        if count > MAX_INTERVALS:
            raise VerificationError(f"the search for stationary points of P(a) on [{mpmath.nstr(lo, 6)}, "
                                    f"{mpmath.nstr(hi, 6)}] needed more than {MAX_INTERVALS} intervals")
        gl, gr = G(l), G(r)
        change = (gl < 0) != (gr < 0)
        m = mpmath.sqrt(l * r)
        y = balls(balls.f, l, r) if rigorous else None
        if y is not None:
            if _excludes_zero(y):
                continue
            d = balls(balls.df, l, r)
            if d is not None and (d > 0 or d < 0):
                if change:
                    out.append((l, r))
                    if first:
                        break
                continue
            if mpmath.log(r / l) < BALL_GIVEUP:
                y = None
                balls.gave_up += 1
        vs = None
        if y is None:   # no ball here (not available, not finite, outside the closed form's conditions)
            # five samples in ln a (ends, quartiles, midpoint: the halves' midpoints are the quartiles,
            # so a split costs no new sample); three let a dip hide between the midpoint and an end
            vs = [gl, G(mpmath.sqrt(l * m)), G(m), G(mpmath.sqrt(m * r)), gr]
            same = len({v < 0 for v in vs}) == 1
            if same and min(abs(v) for v in vs) > 2 * max(abs(v - u) for u, v in zip(vs, vs[1:])):
                continue
        if mpmath.log(r / l) < MIN_WIDTH:
            if change:
                out.append((l, r))
                if first:
                    break
            else:
                touching.append((m, _unresolved(l, r, lo, hi, vs)))
            continue
        stack.append((m, r))
        stack.append((l, m))
    if notes is not None:
        # an unresolved neighbour of a sign change found is that sign change, not a second zero
        near = [(cl * (1 - 4 * MIN_WIDTH), cr * (1 + 4 * MIN_WIDTH)) for cl, cr in out]
        for m, note in sorted(touching, key=lambda t: t[0]):
            if not any(lo_ <= m <= hi_ for lo_, hi_ in near):
                notes.append(note)
    return sorted(out)


def _unresolved(l, r, lo, hi, vs):
    """The note of an interval [l, r] of the search on [lo, hi] that reached
    the search resolution neither excluded nor holding a sign change; ``vs``
    its five samples of dP/da (None: its ball of dP/da contains 0).

    The note says what was seen: a ball containing 0 or samples that come
    near 0 is a possible touching zero; samples of one sign whose size
    grows monotonically toward an end of [lo, hi] that the interval
    touches (the circular-corner punch's dP/da ~ 1/sqrt(a_end - a) at the
    end of its domain, about 1e10 there) are no evidence of a zero: the
    sampled bound cannot exclude such an end at any width, and the note
    says so instead of calling it near 0."""
    seen = "its ball there contains 0"
    if vs is not None:
        mags = [abs(v) for v in vs]
        seen = f"sampled between {mpmath.nstr(min(vs), 4)} and {mpmath.nstr(max(vs), 4)}"
        for end, seq in ((hi, mags), (lo, mags[::-1])):
            touches = r == hi if end is hi else l == lo
            if touches and all(u < v for u, v in zip(seq, seq[1:])) and seq[-1] > 2 * seq[0]:
                return (f"dP/da is unresolved next to the end a = {mpmath.nstr(end, 12)} of a searched segment: "
                        f"one sign there ({seen} over the last relative {mpmath.nstr(mpmath.log(r / l), 2)} "
                        f"of a), its size rising monotonically toward the end, away from 0 (a singular end "
                        f"of dP/da, which the sampled bound cannot exclude at any width); no sign change, "
                        f"treated as none")
    return (f"dP/da comes within the search resolution of 0 near a = {mpmath.nstr(mpmath.sqrt(l * r), 12)} "
            f"without changing sign ({seen}: a possible touching zero, treated as none)")


def _on_flat(law, r) -> bool:
    """Does the segment ending at ``r`` lie on the profile's flat (P0 = 0
    there, :func:`~.force_law.flat_end`)?  dP/da has no sign change on it
    (0, or -B1/(2 sqrt(a)) with adhesion), and the sampled bound, which
    cannot exclude an interval where the slope is 0, need not look."""
    flat = getattr(law.base, "flat", None)
    if flat is None or not (law is law.base or law.monotone_term):
        return False
    return r <= flat * (1 + KINK_GAP / 2)   # the segment [., b(1 - KINK_GAP)]


def _segments(law, lo, hi):
    """[lo, hi] cut at the breakpoints (KINK_GAP around each)."""
    return _segments_raw(law, lo, hi)


def _segments_raw(law, lo, hi):
    edges, kinks = [lo], []
    for b in law.breaks():
        if lo < b * (1 - KINK_GAP) and b * (1 + KINK_GAP) < hi:
            edges += [b * (1 - KINK_GAP), b * (1 + KINK_GAP)]
            kinks.append(b)
    edges.append(hi)
    return list(zip(edges[0::2], edges[1::2])), kinks


# ---------------------------------------------------------------- ranges
def real_range(law):
    """(lo, hi, end): where the law is real, on a factor-4 grid from
    SPAN[0] to SPAN[1] times its scale, the end bisected ('domain') or the
    grid's end ('search')."""
    with workdps(20):
        grid = [law.scale * mpmath.mpf(4)**j for j in range(-20, 41)]
        first = good = None
        for A in grid:
            check_deadline("the scan for the real domain of P(a)")
            try:
                law.P(A)
                law.dP(A)
            except UNDEFINED:
                if good is None:
                    continue
                return first, domain_end(lambda v: (check_deadline("the search for the end of the law's domain"),
                                                    law.P(v), law.dP(v)), good, A), "domain"
            first = A if first is None else first
            good = A
        if good is None:
            raise DomainError("the force law could not be evaluated at any half-width")
        return first, good, "search"


def _falling(base, l, r, balls, notes):
    """The first sign change of dP0/da from >= 0 to < 0 on [l, r] (as a
    one-element list), or []."""
    g = reliable(base.dP) if base.expr is not None else base.dP
    while l < r:
        got = crossings(g, l, r, balls, notes, first=True)
        if not got:
            return []
        cl, cr = got[0]
        if g(cr) < 0:
            return [(cl, cr)]
        l = cr
    return []


def admissible_range(law):
    """(lo, hi, end, note): the half-widths where the frictionless solution
    under ``law`` holds (module docstring): dP0/da >= 0 for the non-adhesive
    law P0 = ``law.base``, within the real domain.  Raises
    :class:`InadmissibleProfileError` when dP0/da < 0 from the start."""
    cache = getattr(law.base, "_admissible", None)
    if cache is not None:
        return cache
    base = law.base
    lo, hi, end = real_range(base)
    with workdps(20):
        balls = _Balls(base)
        notes = []
        first_neg = None
        segs, kinks = _segments(base, lo, hi)
        # a closed form cancels next to a breakpoint (the rounded punch's
        # P0 ~ (a - b)**(3/2) from terms of size a**2): its slope is read at
        # the precision that resolves it, as everywhere in the scan
        dP0 = reliable(base.dP) if base.expr is not None else base.dP
        if dP0(lo) < 0:
            raise InadmissibleProfileError(f"dP0/da < 0 already at a = {mpmath.nstr(lo, 6)}: no admissible "
                                           f"half-width (tensile edge pressure)")
        if base.rising and not base.convex:
            notes.append("dP0/da >= 0 for every a, proven from the profile (h' = f' + t f'' >= 0 on each piece, "
                         "no falling slope jump: force_law.rising_profile): the admissible range is not searched")
        for (l, r), b in zip(segs, kinks + [None]) if not (base.convex or base.rising) else ():
            # (a convex P0 has dP0/da nondecreasing: >= 0 at lo, >= 0 everywhere; a rising one, >= 0 proven)
            for cl, cr in (_falling(base, l, r, balls, notes) if not _on_flat(base, r) else ()):
                first_neg = root_in_log(base.dP, cl, cr)
                break
            if first_neg is not None:
                break
            if b is not None and dP0(b * (1 + KINK_GAP)) < 0:
                first_neg = b
                break
        note = ""
        if first_neg is not None:
            hi, end = first_neg, "admissible"
            note = (f"admissible for a <= a* = {mpmath.nstr(hi, 12)}: dP0/da turns negative there (tensile "
                    f"pressure at the edges of the non-adhesive contact beyond)")
    res = (lo, hi, end, note)
    # the scan itself, for the landscape of P0 (the same search: see landscape)
    law.base._admissible_scan = (balls, tuple(notes))
    law.base._admissible = res
    return res


# ---------------------------------------------------------------- landscape
def landscape(law) -> Landscape:
    """Every local extremum of P(a) over the admissible range (module
    docstring), at 20 digits; cached on the law."""
    if law._landscape is not None:
        return law._landscape
    if law.expr is None and getattr(law, "scan", None) is not None:
        # the law's own grid reads dP0/da at its points too: no search of the whole range first
        law._landscape = _scanned_landscape(law, *_scan_range(law))
        return law._landscape
    lo, hi, end, note = admissible_range(law)
    notes = [note] if note else []
    if law.base.convex and (law is law.base or law.monotone_term):
        law._landscape = _convex_landscape(law, lo, hi, end, notes)
        return law._landscape
    # the non-adhesive law itself: dP0/da >= 0 up to a* is what admissible_range
    # just searched for, on the same segments with the same balls; it found no
    # sign change below a* (the first one, falling, is a*), so P0 has no
    # stationary point there and the search is not run a second time (the
    # circular-corner punch: two subdivisions to MIN_WIDTH at its domain end)
    read_off = law is law.base and getattr(law, "_admissible_scan", None) is not None
    with workdps(20):
        balls = law._admissible_scan[0] if read_off else _Balls(law)
        if read_off:
            notes += law._admissible_scan[1]
        method = "ball" if balls.f is not None else "adaptive"
        if balls.f is None and law.expr is not None:
            notes.append(f"ball arithmetic unavailable ({balls.reason}): adaptive subdivision instead")
        hi_eval = hi * (1 - KINK_GAP) if end != "search" else hi
        segs, kinks = _segments(law, lo, hi_eval)
        ext = []
        g = reliable(law.dP) if law.expr is not None else law.dP
        for (l, r), b in zip(segs, kinks + [None]):
            for cl, cr in (crossings(g, l, r, balls, notes) if not (read_off or _on_flat(law, r)) else ()):
                A = root_in_log(g, cl, cr)
                ext.append(Extremum(A, law.P(A), "stationary", g(cl) < 0, (cl, cr)))
            if b is not None:
                left, right = g(b * (1 - KINK_GAP)), g(b * (1 + KINK_GAP))
                if (left < 0) != (right < 0):
                    ext.append(Extremum(b, law.P(b), "kink", left < 0, (b * (1 - KINK_GAP), b * (1 + KINK_GAP))))
        rising = g(hi_eval) >= 0
        if not rising and end != "search":
            ext.append(Extremum(hi_eval, law.P(hi_eval), "end", True, (hi_eval, hi_eval)))
        if balls.gave_up:
            method = "ball+adaptive"
            notes.append(f"ball arithmetic was inconclusive on {balls.gave_up} interval(s) (the dependency "
                         f"problem); the sampled bound decided there")
    law._landscape = Landscape(lo, hi_eval, end, tuple(ext), method, tuple(notes), rising)
    return law._landscape


def _convex_landscape(law, lo, hi, end, notes) -> Landscape:
    """The landscape where P0 is proven convex (:func:`~.force_law.convex_profile`):
    dP/da = dP0/da - B1/(2 sqrt(a)) is then increasing on (0, oo), so it
    changes sign at most once, from - to + (a minimum): found by walking a
    factor-4 grid up from lo to the first a with dP/da >= 0, then the root.
    No subdivision of the whole range (an exponentially growing P0 such as
    that of cosh(x) - 1 left the subdivision no interval it could exclude)."""
    with workdps(20):
        g = reliable(law.dP) if law.expr is not None else law.dP
        hi_eval = hi * (1 - KINK_GAP) if end != "search" else hi
        ext = []
        A_prev, A = None, lo
        while True:
            check_deadline("the search for the stationary point of P(a)")
            if g(A) >= 0:
                break
            if A >= hi_eval:
                A = None
                break
            A_prev, A = A, min(4 * A, hi_eval)
        rising = A is not None
        if A is not None and A_prev is not None:
            r = root_in_log(g, A_prev, A)
            ext.append(Extremum(r, law.P(r), "stationary", True, (A_prev, A)))
        if not rising and end != "search":
            ext.append(Extremum(hi_eval, law.P(hi_eval), "end", True, (hi_eval, hi_eval)))
        how = ("P0 convex on (0, oo) (h2 = 2 f2 + t f3 >= 0 for t > 0, proven by the assumptions of SymPy): "
               "dP/da increasing, one sign change at most, bracketed on a factor-4 grid")
    return Landscape(lo, hi_eval, end, tuple(ext), "convex", tuple(notes) + (how,), rising)


def _scan_range(law):
    """(lo, hi, end, notes) for :func:`_scanned_landscape`: the admissible range
    where it is known (cached on the base law), else the search span, the scan
    reading dP0/da >= 0 at its own grid points (``admissible`` there)."""
    cached = getattr(law.base, "_admissible", None)
    if cached is not None:
        lo, hi, end, note = cached
        return lo, hi, end, [note] if note else []
    return law.scale * SPAN[0], law.scale * SPAN[1], "search", []


def _scanned_landscape(law, lo, hi, end, notes) -> Landscape:
    """The landscape of a law without closed form that supplies a
    :class:`~.force_law.ScanHint` (``law.scan``): dP/da on the law's log grid
    from ``scan.start()`` up (the breakpoints' one-sided points included,
    never bracketed across), each sign change between neighbours refined by
    :func:`~linecontact_sym.core.roots.root_in_log`; the walk stops where
    P > 0 and dP/da > 0 beyond every breakpoint (end 'scan'), at the end of
    the admissible range, or where the law stops being real (its own domain,
    bisected: end 'domain').  One inner solve per grid point, instead of the
    subdivision's thousands."""
    hint = law.scan
    with workdps(20):
        start = max(to_mpf(hint.start()), lo)
        step = mpmath.mpf(10)**(mpmath.mpf(1) / hint.per_decade)
        hi_eval = hi * (1 - KINK_GAP) if end != "search" else hi
        kinks = [b for b in law.breaks() if start < b * (1 - KINK_GAP) and b * (1 + KINK_GAP) < hi_eval]
        last_kink = max(kinks, default=mpmath.mpf(0))
        cache = {}

        def PdP(A):
            if A not in cache:
                cache[A] = (law.P(A), law.dP(A))
            return cache[A]
        pts, A, top_end = [], start, None
        check_base = getattr(law.base, "_admissible", None) is None   # the range is not known: read dP0/da
        base_dP = reliable(law.base.dP) if law.base.expr is not None else law.base.dP
        if check_base and base_dP(start) < 0:
            raise InadmissibleProfileError(f"dP0/da < 0 already at a = {mpmath.nstr(start, 6)}: no admissible "
                                           f"half-width (tensile edge pressure)")
        pending = sorted([b * (1 - KINK_GAP) for b in kinks] + [b * (1 + KINK_GAP) for b in kinks])
        while True:
            check_deadline("the scan of dP/da on the law's grid")
            while pending and pending[0] <= A:
                X = pending.pop(0)
                try:
                    pts.append((X,) + PdP(X))
                except UNDEFINED:
                    break
            try:
                P, d = PdP(A)
            except UNDEFINED:
                if not pts:
                    raise DomainError(f"the force law is not real at the start of its scan, a = {mpmath.nstr(A, 8)}")
                good = domain_end(lambda v: PdP(v), pts[-1][0], A, iters=40)
                if good > pts[-1][0]:
                    pts.append((good,) + PdP(good))
                top_end = "domain"
                notes.append(f"P(a) is real up to a = {mpmath.nstr(good, 10)} (the law's own domain ends there)")
                break
            if check_base and pts and base_dP(A) < 0:
                # dP0/da turns negative between the last point and A: the admissible range ends there
                a_star = root_in_log(base_dP, pts[-1][0], A)
                notes.append(f"admissible for a <= a* = {mpmath.nstr(a_star, 12)}: dP0/da turns negative there "
                             f"(read on the law's grid; tensile pressure at the edges of the non-adhesive "
                             f"contact beyond)")
                A = a_star * (1 - KINK_GAP)
                P, d = PdP(A)
                pts.append((A, P, d))
                top_end = "admissible"
                break
            pts.append((A, P, d))
            if A >= hi_eval:
                top_end = end
                break
            if P > 0 and d > 0 and A > last_kink * (1 + KINK_GAP):
                top_end = "scan"
                break
            A = min(A * step, hi_eval)
        ext = []
        for (A0, P0_, d0), (A1, P1_, d1) in zip(pts, pts[1:]):
            across = any(A0 < b < A1 for b in kinks)
            if not across and (d0 < 0) != (d1 < 0):
                r = root_in_log(law.dP, A0, A1)
                ext.append(Extremum(r, law.P(r), "stationary", d0 < 0, (A0, A1)))
        for b in kinks:
            try:
                left, right = PdP(b * (1 - KINK_GAP))[1], PdP(b * (1 + KINK_GAP))[1]
            except (UNDEFINED + (KeyError,)):
                continue
            if (left < 0) != (right < 0):
                ext.append(Extremum(b, law.P(b), "kink", left < 0, (b * (1 - KINK_GAP), b * (1 + KINK_GAP))))
        top, d_top = pts[-1][0], pts[-1][2]
        rising = d_top >= 0
        if not rising and top_end in ("admissible", "domain"):
            ext.append(Extremum(top, pts[-1][1], "end", True, (top, top)))
        how = (f"dP/da on the law's log grid ({hint.per_decade} per decade) from a = {mpmath.nstr(start, 4)} "
               f"to {mpmath.nstr(top, 6)} ({len(pts)} points)"
               + ("; P > 0 and rising there" if top_end == "scan" else "")
               + (f": {hint.why}" if hint.why else ""))
    ext.sort(key=lambda e: e.half_width)
    return Landscape(start, top, "search" if top_end == "scan" else top_end, tuple(ext), "scan",
                     tuple(notes) + (how,), rising)


# ---------------------------------------------------------------- below the search range
#: decades followed below the landscape's lower end before a -> 0+ is declared (at most)
MAX_DECADES = 400


def descent(law, lo, dps: int, scale=None):
    """Below the landscape's lower end ``lo``, for a law whose limit P(0+) is
    not 0 (``law.P_zero``, Maugis-Dugdale's -2 sigma_0 c0): follow dP/da down
    in quarter decades; a sign change - (below) to + (above) brackets a
    minimum; stop where a |dP/da| < 10**-(dps + 6) |P(0+)| (what P can still
    change below).  Returns (brackets, infimum, a_end): ``infimum`` when dP/da
    is still positive there (P decreases to P(0+) as a -> 0+, approached, not
    attained).  ``scale``: the load that sets the tolerance in place of
    |P(0+)| (a law with P(0+) = 0, already negative and rising at ``lo``: its
    minimum lies below).  The scale of a 'decade' search is the law's own: no minimum
    hides between grid points below a quarter decade, since the minima of a
    law on top of a smooth P0 are separated by more (a law with finer
    structure near a = 0 needs a finer step)."""
    with workdps(20):
        Pz = abs(law.P_zero()) if scale is None else abs(scale)
        step = mpmath.mpf(10)**(-mpmath.mpf(1) / 4)
        tol = Pz * mpmath.mpf(10)**-(dps + 6)
        prev = (lo, law.dP(lo))
        brackets = []
        for _ in range(4 * MAX_DECADES):
            check_deadline("the descent of dP/da towards a -> 0+")
            A = prev[0] * step
            d = law.dP(A)
            if d < 0 < prev[1]:
                brackets.append((A, prev[0]))
            prev = (A, d)
            if A * abs(d) <= tol:
                return brackets, d > 0, A
        return brackets, False, prev[0]


def _negative_below(law, lo):
    """(A, P(A)) with P(A) < 0 < dP/da(A) at or below the scan's start ``lo``
    of a law with P(0+) = 0 whose P rises there, or (lo, None): followed down
    in quarter decades while P >= 0 and rising (at most :data:`MAX_DECADES`).
    An adhesive term ~ sqrt(a) outgrows P0 ~ a^2 as a -> 0+: a weak adhesion
    (JKR at gamma = 1e-40 on a sinusoid array) has its negative minimum far
    below the scan's start, where P is already positive."""
    with workdps(20):
        A = to_mpf(lo)
        P, d = law.P(A), law.dP(A)
        if not d > 0 or getattr(law, "inactive", False):
            return lo, None
        step = mpmath.mpf(10)**(-mpmath.mpf(1) / 4)
        for _ in range(4 * MAX_DECADES):
            if P < 0:
                return A, P
            if not d > 0:
                return lo, None
            check_deadline("the search for a negative P(a) below the scan")
            A = A * step
            P, d = law.P(A), law.dP(A)
        return lo, None


# ---------------------------------------------------------------- minimum (method A)
def _refine(law, e, dps):
    """An extremum at the working precision (dps + GUARD)."""
    if e.kind == "stationary":
        lo, hi = e.bracket
        A = root_in_log(law.dP, to_mpf(lo), to_mpf(hi), approx=to_mpf(e.half_width))
    elif e.kind == "kink":
        A = [b for b in law.breaks() if abs(b - e.half_width) <= abs(e.half_width) * mpmath.mpf("1e-15")][0]
    else:
        A = to_mpf(e.half_width)
    return Extremum(+A, law.P(A), e.kind, e.minimum, e.bracket)


def minimum(law, dps: int, scan_law=None) -> PullOff:
    """The pull-off (module docstring): the global minimum of P(a) over the
    admissible range from ``law``'s own values, with every local minimum
    listed; the extrema are located on ``scan_law`` (default ``law``).
    Raises :class:`NoPullOffError` where P has no finite negative minimum."""
    scan_law = scan_law or law
    if law.inactive:
        raise NoPullOffError(f"{law.inactive if isinstance(law.inactive, str) else 'no adhesion'}: "
                             f"P(a) = P0(a) >= 0, no tensile pull-off")
    land = landscape(scan_law)
    if not land.rising_at_end and land.end == "search":
        raise NoPullOffError(
            f"P(a) is still decreasing at a = {mpmath.nstr(land.hi, 6)} (the end of the search range): P(a) "
            f"has no finite minimum, no finite pull-off (the profile grows no faster than sqrt(x) there, "
            f"so the adhesive term dominates)")
    below = None
    if getattr(scan_law, "P_zero", None) is not None:
        brackets, infimum, a_end = descent(scan_law, land.lo, dps)
        below = ([Extremum(mpmath.sqrt(l * r), None, "stationary", True, (l, r)) for l, r in brackets],
                 infimum, a_end)
    else:
        A_lo, P_lo = _negative_below(scan_law, land.lo)
        if P_lo is not None:
            # P(0+) = 0 and P negative and rising at A_lo: P fell below it, a minimum lies below the
            # scan's range (a weak adhesion: JKR's moves to a ~ gamma^(1/3))
            brackets, _, a_end = descent(scan_law, A_lo, dps, scale=P_lo)
            below = ([Extremum(mpmath.sqrt(l * r), None, "stationary", True, (l, r)) for l, r in brackets],
                     False, a_end)
    with workdps(dps + GUARD):
        mins = [_refine(law, e, dps) for e in land.minima + (tuple(below[0]) if below else ())]
        if below is not None and below[1]:
            mins.append(Extremum(mpmath.mpf(0), +law.P_zero(), "infimum", True, ()))
        neg = [e for e in mins if e.force < 0]
        if law.geometry.closes_at_end:      # a periodic array: the end is full contact, not a separation
            return _first_minimum(law, land, mins)
        if not neg:
            raise NoPullOffError(
                "P(a) has no negative minimum: no tensile load is sustained (the infimum 0 is "
                "reached only as a -> 0); no finite pull-off")
        # the end of the admissible range (dP/da < 0 there) lies on a falling branch, unstable under
        # load control: unloading from a stable branch separates at a stationary or kink minimum (or the
        # infimum) first, and reaches the end only where there is none
        inner = [e for e in neg if e.kind != "end"]
        best = min(inner or neg, key=lambda e: e.force)
        note = land.describe()
        note += _end_not_reached(land, best, neg)
        if below is not None:
            note += (f"; dP/da followed down in quarter decades below a = {mpmath.nstr(land.lo, 4)} to a = "
                     f"{mpmath.nstr(below[2], 3)}, where a |dP/da| < 1e-{dps + 6} |P(0+)|"
                     + (": P(a) decreases to its limit P(0+) as a -> 0+ there" if below[1] else ""))
        if best.kind == "infimum":
            note += "; the pull-off is the infimum P(0+) (approached as a -> 0+, not attained)"
        if best.kind == "end":
            note += ("; the global minimum is at the end of the admissible range: the lowest load the "
                     "frictionless adhesive solution describes, not a proven separation load")
        return PullOff(+best.force, -best.force, +best.half_width, best.kind, None, tuple(mins), note)


def _end_not_reached(land, best, neg) -> str:
    """The note on a lower end of the admissible range that the pull-off ``best`` is not: its value and
    the local maximum between them (from the extrema found), or ''."""
    ends = [e for e in neg if e.kind == "end" and e.force < best.force]
    if not ends or best.kind == "end":
        return ""
    end = ends[0]
    maxima = [e for e in land.extrema if not e.minimum and best.half_width < e.half_width < end.half_width]
    top = max(maxima, key=lambda e: e.force, default=None)
    over = (f"beyond the local maximum at a = {mpmath.nstr(top.half_width, 8)} (P = {mpmath.nstr(top.force, 8)}), "
            if top is not None else "")
    return (f"; the end of the admissible range a* = {mpmath.nstr(end.half_width, 8)} has the lower "
            f"P = {mpmath.nstr(end.force, 8)}, but it lies {over}on a branch where P falls towards a* "
            f"(dP/da < 0: unstable under load control): unloading from the stable branch separates at the "
            f"{best.kind} minimum a = {mpmath.nstr(best.half_width, 8)} first and does not reach it")


def _first_minimum(law, land, mins) -> PullOff:
    """The pull-off of a partial contact where the end of the range closes
    the contact (:attr:`~linecontact_sym.method.geometry.Geometry.closes_at_end`,
    a periodic array): pulled from a partial contact, the contact follows its
    stable branch down to the first local minimum of P(a) from small a and
    separates there; the fall of P(a) towards the end is the unstable branch
    beyond the snap into full contact, which in JKR holds any tension."""
    inner = sorted((e for e in mins if e.kind != "end"), key=lambda e: e.half_width)
    if not inner or inner[0].force >= 0:
        raise NoPullOffError(
            "P(a) has no negative local minimum before full contact: from any partial contact the array snaps "
            "into full contact (a = L/2), which in JKR holds any tension: no pull-off of a partial contact")
    first = inner[0]
    note = land.describe() + ("; the first local minimum from small a (the end a -> L/2 is full contact: "
                              "in JKR it holds any tension)")
    return PullOff(+first.force, -first.force, +first.half_width, first.kind, None, tuple(mins), note)


def first_maximum_after(law, A, dps: int):
    """The first local maximum of P(a) beyond the half-width A (stationary or
    kink) at ``dps`` digits, or None: the load of the snap into full contact
    of a periodic array (every extremum from :func:`landscape`)."""
    land = landscape(law)
    with workdps(dps + GUARD):
        for e in sorted(land.extrema, key=lambda e: e.half_width):
            if not e.minimum and e.half_width > A and e.kind != "end":
                return _refine(law, e, dps)
    return None


# ---------------------------------------------------------------- equilibria
@dataclass(frozen=True)
class Equilibrium:
    """A half-width with P(a) = load; stable where dP/da > 0."""

    half_width: mpmath.mpf
    stable: bool


def equilibria_at(law, load, dps: int, scan_law=None):
    """Every equilibrium at ``load`` over the admissible range (module
    docstring): :class:`Equilibrium` s, stable first, then by decreasing a."""
    sl = scan_law or law
    land = landscape(sl)
    with workdps(20):
        L20 = to_mpf(load)
        nodes = [land.lo] + [e.half_width for e in sorted(land.extrema, key=lambda e: e.half_width)
                             if e.kind != "end"] + [land.hi]
        vals = [sl.P(A) for A in nodes]
        # below lo: P(0+) (0, or the law's P_zero) and P is monotone there
        a0, p0 = nodes[0], vals[0]
        Pz = sl.P_zero() if getattr(sl, "P_zero", None) is not None else 0
        k = 0
        while L20 != Pz and (p0 - L20 > 0) != (Pz - L20 > 0) and k < 200:
            a0 = a0 / 16
            p0 = sl.P(a0)
            k += 1
        nodes[0], vals[0] = a0, p0
        if land.end == "search":  # beyond the search range, while P keeps moving towards the load
            k = 0
            while k < 200 and ((land.rising_at_end and vals[-1] < L20) or (not land.rising_at_end and vals[-1] > L20)):
                try:
                    A = nodes[-1] * 16
                    vals[-1] = sl.P(A)
                    nodes[-1] = A
                except UNDEFINED:
                    break
                k += 1
        brackets = [(n0, n1, v1 > v0) for (n0, v0), (n1, v1) in zip(zip(nodes, vals), zip(nodes[1:], vals[1:]))
                    if (v0 - L20) * (v1 - L20) < 0]
    with workdps(dps + GUARD):
        L = to_mpf(load)
        out = [Equilibrium(+root_in_log(lambda A: law.P(A) - L, to_mpf(n0), to_mpf(n1)), st)
               for n0, n1, st in brackets]
    out.sort(key=lambda e: (not e.stable, -e.half_width))
    return out


def equilibria(law, load, dps: int, scan_law=None):
    """All half-widths with P(a) = load over the admissible range:
    list of (a, stable), stable first (then by decreasing a)."""
    return [(e.half_width, e.stable) for e in equilibria_at(law, load, dps, scan_law)]


def half_width_at(law, load, dps: int = 30):
    """The half-width of a non-adhesive law at a positive load: the stable
    equilibrium within the admissible range; :class:`DomainError` when the
    load is not reached there."""
    roots = [a for a, st in equilibria(law, load, dps) if st]
    if not roots:
        lo, hi, end, note = admissible_range(law)
        with workdps(dps + 10):
            top = law.P(hi)
            # a range that ends where the geometry closes the contact (a periodic array at a = L/2:
            # full contact) holds its end load, and every load beyond it, at that end: the load
            # evaluate_at(a=L/2) returns answers L/2 (the roots above are interior crossings)
            top_a = law.geometry.mp_a_max(getattr(law, "geometry_values", {})) if law.geometry.closes_at_end \
                else mpmath.inf
            # (the range ends there as the law's domain, or where dP0/da = 0 rounds negative at the crest)
            if mpmath.isfinite(top_a) and hi >= top_a * (1 - mpmath.mpf(10)**-12):
                try:
                    full = law.P(top_a)           # the load of full contact, at the end itself
                except (ValueError, ZeroDivisionError):
                    full = top
                if mpmath.isfinite(full) and to_mpf(load) >= full * (1 - mpmath.mpf(10)**(-dps + 3)):
                    return +top_a
        raise DomainError(f"no half-width found for load {load}: the largest load of the admissible range "
                          f"is P({mpmath.nstr(hi, 8)}) = {mpmath.nstr(top, 8)}"
                          + (f" ({note})" if note else f" ({'domain end' if end == 'domain' else 'search end'})"))
    return roots[0]


__all__ = ["first_maximum_after", "Extremum", "Landscape", "Equilibrium", "searching_until", "SEARCH_BUDGET",
           "within_search_budget", "check_deadline", "crossings",
           "real_range", "admissible_range", "landscape",
           "minimum", "equilibria", "equilibria_at", "half_width_at", "descent", "MAX_DECADES",
           "MIN_WIDTH", "KINK_GAP", "SPAN"]
