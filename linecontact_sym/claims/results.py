"""The records of a check: verdicts per point, per printed form, per test
profile, per claim and per paper, with their one-line descriptions and JSON
forms.  Built by :mod:`.check`, shown by :mod:`.report`."""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import sympy as sp

from ..core.conversion import to_basic

HOLDS = "holds"
HOLDS_IF = "holds under a condition"
FAILS = "does not hold"
UNDECIDED = "undecided"
STATUSES = (HOLDS, HOLDS_IF, FAILS, UNDECIDED)

#: exit statuses of the command line (``check``, ``paper`` and the other verbs)
EXIT_OK, EXIT_FAILS, EXIT_INPUT, EXIT_INTERNAL, EXIT_UNDECIDED = 0, 1, 2, 3, 4
EXIT_CODES = {
    EXIT_OK: "every claim holds (possibly under a condition that the report states)",
    EXIT_FAILS: "at least one claim does not hold (with --strict: or holds only under a condition)",
    EXIT_INPUT: "bad input: a malformed claims file, formula, option or value; nothing was judged",
    EXIT_INTERNAL: "internal error (a bug in linecontact_sym; LINECONTACT_SYM_DEBUG=1 prints the traceback)",
    EXIT_UNDECIDED: "no claim fails but at least one is undecided: the engine could not derive the "
                    "quantity (e.g. within --budget)",
}


def fmt_num(v) -> str:
    """A sample value for a message: exact unless its denominator is large.

    >>> fmt_num(sp.Rational(1, 3)), fmt_num(sp.Rational(123457, 1000000))
    ('1/3', '0.12345700')
    """
    v = to_basic(v)
    if v.is_Rational and v.q > 1000:
        return str(sp.N(v, 8))
    return str(v)


def fmt_mp(v, digits: int = 20) -> str:
    """An mpf for a message (``-`` for None)."""
    if v is None:
        return "-"
    return mpmath.nstr(v, digits) if not isinstance(v, str) else v


@dataclass
class PointResult:
    """The comparison at one sample point."""

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
        pt = ", ".join(f"{k} = {fmt_num(v)}" for k, v in sorted(self.values.items(), key=lambda kv: kv[0].name))
        if self.status == "fail":
            worst = min(self.comparisons, key=lambda c: c.digits)
            return (f"at {pt}: {worst.what}: printed {fmt_mp(worst.printed)}, derived {fmt_mp(worst.target)} "
                    f"({worst.digits:.1f} digits agree)")
        return f"at {pt}: {self.reason}"

    def to_dict(self):
        return {"point": {k.name: str(v) for k, v in self.values.items()}, "kind": self.kind,
                "status": self.status, "digits": round(self.digits, 2), "reason": self.reason,
                "comparisons": [{"what": c.what, "printed": fmt_mp(c.printed, 25), "derived": fmt_mp(c.target, 25),
                                 "digits": round(c.digits, 2)} for c in self.comparisons]}


@dataclass
class FormResult:
    """The verdict on one printed form for one profile."""

    form: object              # spec.Form
    status: str
    condition: str = ""
    digits: float = 0.0
    points: list = field(default_factory=list)
    counterexample: PointResult | None = None
    symbolic: str = ""
    note: str = ""
    diagnosis: object = None  # diagnosis.Diagnosis: a known mistake that explains a failure

    def to_dict(self):
        dg = self.diagnosis
        return {"formula": self.form.text, "status": self.status, "condition": self.condition,
                "digits": round(self.digits, 2), "symbolic": self.symbolic, "note": self.note,
                "diagnosis": dg.message if dg is not None else None,
                "diagnosis_rule": dg.rule if dg is not None else None,
                "corrected_formula": dg.formula if dg is not None and dg.formula else None,
                "counterexample": self.counterexample.describe() if self.counterexample else None,
                "points": [p.to_dict() for p in self.points]}


@dataclass
class TargetResult:
    """The verdict of a claim for one (test) profile."""

    profile_text: str
    derived: object           # derive.Derived or None
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
    """The verdict on one claim."""

    claim: object             # spec.Claim
    status: str
    verdict: str                 # one line: status + condition/counterexample
    digits: float
    seconds: float
    targets: list = field(default_factory=list)
    details: list = field(default_factory=list)   # extra lines (table mapping etc.)

    @property
    def label(self):
        return self.claim.label

    @property
    def diagnoses(self) -> list:
        """The diagnoses of the failing forms (one sentence each, no repeats)."""
        out = []
        for t in self.targets:
            for f in t.forms:
                if f.diagnosis is not None and f.diagnosis.message not in out:
                    out.append(f.diagnosis.message)
        return out

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
                "details": self.details, "diagnoses": self.diagnoses,
                "targets": [t.to_dict() for t in self.targets]}


@dataclass
class PaperResult:
    """The verdicts on every (selected) claim of a paper."""

    paper: object             # spec.Paper
    results: list
    seconds: float

    @property
    def ok(self) -> bool:
        """Every claim has a verdict (none is undecided)."""
        return all(r.status != UNDECIDED for r in self.results)

    def exit_code(self, strict: bool = False) -> int:
        """The command line's exit status for this result (see :data:`EXIT_CODES`):
        3 when a claim is undecided by an internal error, else 1 when a claim
        does not hold (``strict``: or holds only under a condition), else 4
        when a claim is undecided, else 0."""
        sts = [r.status for r in self.results]
        if any(r.status == UNDECIDED and "internal error" in r.verdict for r in self.results):
            return EXIT_INTERNAL
        if FAILS in sts or (strict and HOLDS_IF in sts):
            return EXIT_FAILS
        if UNDECIDED in sts:
            return EXIT_UNDECIDED
        return EXIT_OK

    def _repr_markdown_(self):
        return markdown_summary(self)

    def to_dict(self):
        return {"key": self.paper.key, "title": self.paper.title, "reference": self.paper.reference,
                "source": self.paper.source, "seconds": round(self.seconds, 2),
                "counts": {s: sum(r.status == s for r in self.results) for s in STATUSES},
                "claims": [r.to_dict() for r in self.results]}


def verdict_line(status, condition, cex: PointResult | None, extra="") -> str:
    """The one-line verdict: status, then the condition or the counterexample."""
    if status == HOLDS:
        return HOLDS + (f" ({extra})" if extra else "")
    if status == HOLDS_IF:
        return f"{HOLDS_IF}: {condition}" + (f" ({extra})" if extra else "")
    if status == FAILS:
        return f"{FAILS}: " + (cex.describe() if cex else extra)
    return f"{UNDECIDED}: {extra}"


# ---------------------------------------------------------------- the claims table in Markdown
#: the status as the tables print it
SHORT = {HOLDS: "holds", HOLDS_IF: "holds if", FAILS: "DOES NOT HOLD", UNDECIDED: "UNDECIDED"}


def digits_text(r):
    """The agreeing digits of a claim result as the tables print them ('-' where none)."""
    return f"{r.digits:.1f}" if r.status in (HOLDS, HOLDS_IF) or r.digits else "-"


def md_escape(text):
    """Text for a Markdown table cell (pipes escaped, one line)."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def markdown_summary(result) -> str:
    """The claims table alone, in Markdown (notebooks display a PaperResult so)."""
    res = result.results
    out = ["| claim | result | status | digits | time | verdict |", "|---|---|---|---:|---:|---|"]
    for r in res:
        verdict = r.verdict.split(": ", 1)[1] if ": " in r.verdict and r.status != HOLDS else ""
        out.append(f"| {r.label} | {md_escape(r.claim.title)} | {SHORT[r.status]} | {digits_text(r)} | "
                   f"{r.seconds:.1f} s | {md_escape(verdict[:300])} |")
    return "\n".join(out)


__all__ = ["HOLDS", "HOLDS_IF", "FAILS", "UNDECIDED", "STATUSES", "EXIT_CODES", "EXIT_OK", "EXIT_FAILS",
           "EXIT_INPUT", "EXIT_INTERNAL", "EXIT_UNDECIDED", "PointResult", "FormResult", "TargetResult",
           "ClaimResult", "PaperResult", "verdict_line", "fmt_num", "fmt_mp", "SHORT", "digits_text", "md_escape", "markdown_summary"]
