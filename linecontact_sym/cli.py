"""The command line ``linecontact-sym``.

Verbs::

    linecontact-sym paper popov2017 [--out DIR]        check a paper, write the reports
    linecontact-sym derive PROFILE [--set R=1 ...] [--adhesion [--law jkr]] [--format text|latex|json]
    linecontact-sym eval PROFILE QUANTITY --at a=0.1,0.2 [x=...] --set R=1 E_star=1 [--dps 50]
    linecontact-sym table power-law --n 1,2,3,4,5,6,10 [--latex]
    linecontact-sym check FILE.toml | --profile PROFILE --force FORMULA ...

Every verb has ``--help`` and ``--json`` (machine-readable output on stdout;
``derive --format json`` is the same).  Progress goes to stderr (a bar on a
terminal, one line per item otherwise; ``--quiet`` silences it); errors go to
stderr.  Exit status (every verb)::

    0  every claim holds (possibly under a condition the report states)
    1  at least one claim does not hold (with --strict: or holds only under a condition)
    2  bad input: a malformed claims file, formula, option or value; nothing was judged
    3  internal error (a bug; LINECONTACT_SYM_DEBUG=1 prints the traceback)
    4  no claim fails but at least one is undecided (the engine could not derive it)

A formula that starts with '-' may be given as it is (``derive -x**2``
works; so does ``--pull-off -pi*gamma``), or after ``--``.  Formulas are
parsed by the whitelisted parser of :mod:`linecontact_sym.parsing`; nothing
typed on the command line is executed as code.
"""
from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import re
import sys
import time
import traceback
from pathlib import Path

from .core.budget import DEFAULT_BUDGET, check_environment, checked_budget
from .core.precision import MAX_DPS
from .claims.results import EXIT_CODES, EXIT_FAILS, EXIT_INPUT, EXIT_INTERNAL, EXIT_OK
from .core import symbols as S
from .core.errors import LineContactError
from .core.parallel import default_jobs, jobs_count
from .core.progress import Progress

#: kept for scripts that imported the old name (1: a claim without a verdict)
EXIT_NO_VERDICT = EXIT_FAILS

EXIT_HELP = "exit status: " + "; ".join(f"{k} {v}" for k, v in EXIT_CODES.items()) + "."


class _Parser(argparse.ArgumentParser):
    """argparse with errors on stderr, exit status 2 (its default)."""


def _dps(text):
    """--dps: an integer number of significant digits, 1 to MAX_DPS (1000)."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer number of digits, got {text!r}") from None
    if not 1 <= v <= MAX_DPS:
        raise argparse.ArgumentTypeError(f"digits must be 1 to {MAX_DPS}, got {v}")
    return v


def _budget(text):
    """--budget: CPU seconds > 0, or 'inf' / 'none' for no limit (the one reader
    of numeric settings, :func:`~linecontact_sym.core.options.read_number`)."""
    try:
        return checked_budget(text, text=True)
    except LineContactError:
        raise argparse.ArgumentTypeError(f"expected seconds > 0 or 'inf', got {text!r}") from None


def _jobs(text):
    """--jobs: a whole number >= 1 (capped at the work by the checker)."""
    try:
        return jobs_count(text)
    except LineContactError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _rtol(text):
    """--rtol: a relative tolerance > 0."""
    from .core.ranges import check_tolerance
    try:
        return check_tolerance(text, "--rtol")
    except LineContactError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _emit_json(obj):
    print(json.dumps(obj, indent=2, default=str))


def _err(msg):
    print(f"linecontact-sym: error: {msg}", file=sys.stderr)


def _cli_hint(msg: str) -> str:
    """Error messages in command-line terms: the claims file's
    ``symbols = ["k"]`` becomes ``--symbols k``."""
    return re.sub(r'symbols = \[((?:"[^"]*"(?:, )?)+)\]',
                  lambda m: "--symbols " + " ".join(re.findall(r'"([^"]*)"', m.group(1))), msg)


# ------------------------------------------------------------------ helpers
def _profile(text, symbols=(), where="PROFILE"):
    from .parsing import parse_expr
    return parse_expr(text, symbols=list(symbols or ()), where=where)


def _settings(items, symbols=()):
    """``--set NAME=VALUE ...``: each value read by the one reader of typed
    numbers (:func:`linecontact_sym.parsing.parse_number`): a plain number
    first (``2.1e11``, ``1/3``), an expression of numbers (``pi/4``), and
    only where the text is neither a number with a unit (``E_star=210GPa``,
    ``R=5 mm``; the ``[units]`` extra, pint's unit parser, nothing
    evaluated), converted to the SI unit declared for NAME
    (:data:`~linecontact_sym.core.symbols.UNITS`); a wrong dimension, or a
    name without a declared unit, is bad input naming the unit."""
    from .parsing import parse_assignments
    return parse_assignments(items or [], where="--set", symbols=list(symbols or ()), units=S.UNITS)


def _has_unit(items) -> bool:
    """Some ``NAME=VALUE`` of ``items`` carries a unit (the result is then said in SI)."""
    from .parsing.numbers import split_unit
    return any("=" in i and split_unit(i.partition("=")[2]) is not None for i in items or [])


def _contact(args, profile, values=None):
    """The frictionless contact of a profile; ``--period L`` (derive, eval): a
    periodic array (its symbols fixed by ``values``, the --set of derive)."""
    from .contacts.normal.contact import LineContact
    period = getattr(args, "period", None)
    if getattr(args, "asymmetric", False):
        if period is not None:
            raise LineContactError("--asymmetric and --period: an asymmetric periodic array is not supported")
        from .core import symbols as S
        return LineContact(profile.xreplace({S.x: S.x_real}), symmetric=False, budget=args.budget)
    if period is None:
        return LineContact(profile, budget=args.budget)
    L = _profile(period, getattr(args, "symbols", None), where="--period")
    return LineContact(profile, budget=args.budget, period=L.xreplace(values or {}))


#: the materials ``--material NAME:K=V,...`` names (:mod:`linecontact_sym.method.material`)
MATERIALS = ("maxwell", "kelvin_voigt", "standard_linear_solid")


def _material(args):
    """The viscoelastic material of ``--material NAME:K=V,...`` or of
    ``--relaxation EXPR`` (E*(t) in t), None without either."""
    from .method import material as M
    from .parsing import parse_assignments
    spec, rel = getattr(args, "material", None), getattr(args, "relaxation", None)
    if spec is None and rel is None:
        return None
    if spec is not None and rel is not None:
        raise LineContactError("give --material or --relaxation, not both")
    if rel is not None:
        return M.Material(_profile(rel, args.symbols, where="--relaxation"))
    name, _, params = spec.partition(":")
    if name.strip() not in MATERIALS:
        raise LineContactError(f"--material {name.strip()}: one of {', '.join(MATERIALS)} (NAME:K=V,...), "
                               "or --relaxation EXPR for any E*(t)")
    vals = parse_assignments(params, where="--material") if params.strip() else {}
    return getattr(M, name.strip())(**{k.name: v for k, v in vals.items()})


#: the contact kinds whose results neglect the two bodies' coupling (--beta, --materials)
FRICTIONAL_KINDS = ("tangential", "rolling")


def _bodies(args) -> dict:
    """The keywords ``beta`` / ``materials`` of ``--beta B`` and
    ``--materials E1,nu1,E2,nu2`` (oo: a rigid body) for the frictional
    layers ({} without either); read by
    :func:`linecontact_sym.core.materials.coupling`."""
    import sympy as sp
    from .core.conversion import plain_number
    from .core.materials import coupling
    beta, mats = getattr(args, "beta", None), getattr(args, "materials", None)
    out = {}
    if beta is not None:
        b = plain_number(beta)
        if b is None:
            raise LineContactError(f"--beta {beta!r}: a number in [-1/2, 1/2] (e.g. -0.2 or -2/7)")
        out["beta"] = b
    if mats is not None:
        parts = [t.strip() for t in mats.split(",")]
        nums = [sp.oo if t.lower() in ("oo", "inf", "rigid") else plain_number(t) for t in parts]
        if len(parts) != 4 or any(v is None for v in nums):
            raise LineContactError(f"--materials {mats!r}: four numbers E1,nu1,E2,nu2 (E = oo: a rigid body), "
                                   f"e.g. 210e9,0.3,70e9,0.33")
        out["materials"] = ((nums[0], nums[1]), (nums[2], nums[3]))
    if out:
        coupling(**out)            # checked here: a wrong beta, materials or a contradiction is a clear error
    return out


def _frictional(kind, c, bodies):
    """The frictional contact of ``kind`` on ``c`` with the two bodies; its
    DomainWarning (beta != 0) not repeated on stderr: the output states the
    coupling (:func:`_coupling_line`)."""
    import warnings
    from .contacts.base import contact_kind
    from .core.errors import DomainWarning
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DomainWarning)
        return contact_kind(kind).from_frictionless(c, **bodies)


def _coupling_line(contact, fixed=None) -> str:
    """The statement of a frictional result on the command line (at the
    friction coefficient of ``fixed`` where it gives one)."""
    return f"coupling: {_coupling_note(contact, fixed)}"


def _coupling_note(contact, fixed=None):
    mu = (fixed or {}).get("mu")
    if mu is not None and not contact.mu.is_number:
        from .parsing import user_value
        return contact.coupling.note(contact.mu.xreplace({S.mu: user_value(mu)}))
    return contact.coupling_note


def _history(args, which):
    """The --history (a(t)) or --load (P(t)) expression in t."""
    text = getattr(args, which, None)
    if text is None:
        raise LineContactError(f"a viscoelastic {'force or pressure' if which == 'history' else 'half-width'} needs "
                               f"--{which} EXPR (a SymPy expression in t, Piecewise for load-then-unload)")
    return _profile(text, args.symbols, where=f"--{which}")


def _viscoelastic_derive(args, c, prof, mat):
    v = c.viscoelastic(mat)
    out = {"profile": str(prof), "material": repr(mat)}
    if getattr(args, "history", None) is not None:
        out["force_history"] = v.force_history(_history(args, "history"), budget=args.budget)
    if getattr(args, "load", None) is not None:
        out["half_width_history"] = v.half_width_history(_history(args, "load"), budget=args.budget)
    if len(out) == 2:
        raise LineContactError("with a material: --history EXPR (a(t): the force history) or --load EXPR "
                               "(P(t): the half-width under creep)")
    if args.json or args.format == "json":
        _emit_json({k: str(v_) for k, v_ in out.items()})
    else:
        for k, v_ in out.items():
            print(f"[{k}]\n{v_}\n")
    return EXIT_OK


def _viscoelastic_eval(c, q, mat, args, values):
    """One value of a viscoelastic quantity (force, pressure, half_width) at t (and x)."""
    if q not in ("force", "pressure", "half_width"):
        raise LineContactError(f"with a material the quantity is force, pressure or half_width, not {q!r}")
    if "t" not in values:
        raise LineContactError(f"{q} of a viscoelastic contact needs the time: --at t=...")
    tv, x = values.pop("t"), values.pop("x", None)
    history = _history(args, "load" if q == "half_width" else "history")
    return c.viscoelastic(mat).evaluate_at(q, tv, history, x=x, dps=args.dps, **values)


def _derivation_dict(d, values=None):
    from .core.printing import to_latex
    expr = d.expr.xreplace(values) if values else d.expr
    rec = d.verification
    return {"quantity": d.quantity, "expr": str(expr), "latex": to_latex(expr),
            "closed_form": bool(d.closed_form), "rule": d.rule, "method": d.method,
            "conditions": [str(c) for c in d.conditions],
            "verified_digits": round(rec.min_digits, 2) if rec is not None else None,
            "seconds": round(d.seconds, 3), "notes": list(d.notes)}


# ------------------------------------------------------------------ paper
def _output_dir(text) -> Path:
    """The output directory of ``paper --out``, checked before any work: no
    part of the path may be a file (``--out report.txt``, ``--out file/sub``),
    and the directory must be creatable and writable; a clear error
    otherwise (exit 2), not a failure after the claims were checked."""
    out = Path(text)
    for part in [out] + list(out.parents):
        if part.exists() or part.is_symlink():
            if not part.is_dir():
                where = "is" if part == out else f"({part}) is"
                raise LineContactError(f"--out {text}: {'it' if part == out else 'a part of the path'} {where} "
                                       f"a file, not a directory; name a directory")
            break
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise LineContactError(f"--out {text}: the directory cannot be created ({exc.strerror})") from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise LineContactError(f"--out {text}: the directory is not writable")
    return out


def cmd_paper(args):
    from .claims.batch import check_and_draw          # the claims and, beside them, the figures
    from .claims.report import text_table, write_paper_outputs
    from .claims.spec import load_paper
    paper = load_paper(args.name)
    out = _output_dir(args.out or f"{paper.key}-report")
    only = set(args.only) if args.only else None
    if only:
        unknown = only - {c.label for c in paper.claims}
        if unknown:
            raise LineContactError(f"no claim(s) {sorted(unknown)} in {paper.source}")
    t0 = time.perf_counter()
    n = len(only) if only else len(paper.claims)
    if not args.quiet:
        print(f"checking {n} claims of {paper.title or paper.key}", file=sys.stderr, flush=True)
    bar = Progress(n, "checking", enabled=not args.quiet)
    result, drawn = check_and_draw(paper, args.jobs, None if args.no_figures else out, args.budget, only=only,
                                   on_start=lambda i, n_, c: bar.start(c.label), progress=lambda i, n_, r: bar.done(
                                       r.label, r.status, r.seconds, f"{r.digits:5.1f} digits"))
    bar.close()
    written = write_paper_outputs(result, out, figures=not args.no_figures, budget=args.budget, drawn=drawn)
    if args.json:
        d = result.to_dict()
        d["written"] = {k: [str(p) for p in v] if isinstance(v, list) else str(v) for k, v in written.items()}
        _emit_json(d)
    else:
        print(text_table(result))
        print()
        print(f"written to {out}/: " + ", ".join(
            Path(p).name for v in written.values() for p in (v if isinstance(v, list) else [v])))
        print(f"total {time.perf_counter() - t0:.0f} s")
    return result.exit_code()


# ------------------------------------------------------------------ derive
def cmd_derive(args):
    from .core.printing import to_latex
    prof = _profile(args.profile, args.symbols)
    values = _settings(args.set, args.symbols)
    unused = sorted(str(k) for k in values if k not in prof.free_symbols)
    if unused:
        raise LineContactError(f"--set {', '.join(unused)}: the profile {prof} has no such parameter")
    prof = prof.xreplace(values)
    c = _contact(args, prof, values)
    if getattr(args, "asymmetric", False):
        return _derive_asymmetric(args, prof, c)
    mat = _material(args)
    if mat is not None:
        return _viscoelastic_derive(args, c, prof, mat)
    quantities = [q.strip() for q in (args.quantities or ",").split(",") if q.strip()] or ["force", "pressure", "gap"]
    if args.quantities is not None and not args.quantities.replace(",", "").strip():   # '' is no choice
        raise LineContactError("--quantities names no quantity (e.g. force,pressure,gap)")
    if args.law is not None and not args.adhesion:
        # a cohesive law named is an adhesive derivation asked for: --law implies --adhesion (said on stderr)
        args.adhesion = True
        if not args.quiet:
            print(f"--law {args.law} implies --adhesion: the adhesive laws of {args.law} follow the "
                  f"frictionless ones", file=sys.stderr)
    args.law = args.law or "jkr"
    known = [n for n, q in type(c).quantities().items() if not q.method]    # a periodic array has more
    adhesive = ("force", "pressure", "adhesion_force", "pull_off_force", "pull_off_half_width")
    for q in (q for q in quantities if q not in known and not (args.adhesion and q in adhesive)):
        raise LineContactError(f"unknown quantity {q!r}; choose from {', '.join(known)} (--adhesion: {adhesive})")
    out = {"profile": str(prof), "profile_latex": to_latex(prof),
           "slope_at_origin": str(c.profile.slope_at_origin), "quantities": {}}
    todo = [(q, c, q) for q in quantities if q in known]
    if args.adhesion:
        from .contacts.adhesion import LAWS
        if args.law not in LAWS:
            raise LineContactError(f"--law {args.law}: unknown cohesive law; one of {', '.join(LAWS)}")
        ad = LAWS[args.law].from_frictionless(c)
        registry = type(ad).quantities()
        todo += [((registry[q].aliases or (q,))[0], ad, q) for q in adhesive   # only as asked (issue 22);
                 if q in quantities or args.quantities is None]     # by default all five, the pull-off P_min too
    bodies = _bodies(args)
    if bodies and not getattr(args, "rolling", False):
        raise LineContactError("--beta/--materials describe the two bodies of a frictional contact: use them "
                               "with --rolling")
    rolling = None
    if getattr(args, "rolling", False):   # steady rolling with traction (Carter for this profile)
        rolling = _frictional("rolling", c, bodies)
        todo += [(f"rolling.{q}", rolling, q) for q in ("tangential_force", "creepage", "stick_half_width")]
        out["coupling"] = str(rolling.coupling_note)
    bar = Progress(len(todo), "deriving", enabled=not args.quiet, min_total=2)
    for key, contact, q in todo:
        bar.start(key)
        t1 = time.perf_counter()
        try:
            out["quantities"][key] = contact.derivation(q)
            status = out["quantities"][key].rule
        except LineContactError as exc:
            if contact is c:
                raise
            out["quantities"][key] = exc
            status = "error"
        bar.done(key, status, time.perf_counter() - t1)
    bar.close()
    if args.json:
        args.format = "json"
    if args.format == "json":      # the rolling derivations carry the coupling note first among their notes
        _emit_json({**out, "quantities": {k: (_derivation_dict(v) if not isinstance(v, Exception)
                                              else {"error": str(v)}) for k, v in out["quantities"].items()}})
    elif args.format == "latex":
        print(r"\begin{align*}")
        lines = [f"f(x) &= {to_latex(prof)}"]
        names = {k: q.latex or k for k, (_, _, q) in _registry().items()}
        for k, v in out["quantities"].items():
            if isinstance(v, Exception):
                continue
            lines.append(f"{names.get(k, k)} &= {to_latex(v.expr)}")
        print(" \\\\\n".join(lines))
        print(r"\end{align*}")
    else:
        print(f"profile f(x) = {prof}    (f'(0+) = {c.profile.slope_at_origin})")
        for k, v in out["quantities"].items():
            print()
            print(f"[{k}]")
            print(str(v) if not isinstance(v, Exception) else f"error: {v}")
        if rolling is not None:
            print()
            print(_coupling_line(rolling))
    return EXIT_OK


def _derive_asymmetric(args, prof, c):
    """``derive --asymmetric``: the contact [e - a, e + a] of f on the whole line: P(e, a),
    the tilt theta(e, a) of the bounded solution, the moments, and the ends where SymPy solves them."""
    import sympy as sp
    core = c.core
    out = {"profile": str(prof), "load P(e, a)": core.force(), "tilt theta(e, a)": core.tilt(),
           "moment about the centre M_c(e, a)": core.moment_centre(), "moment M(e, a)": core.moment()}
    ends = c.ends(budget=args.budget)
    if ends and all(sp.count_ops(d["e"]) + sp.count_ops(d["a"]) < 80 for d in ends):
        out["ends (load P, tilt theta_t)"] = [{k: v for k, v in d.items()} for d in ends]
    elif ends:
        out["ends (load P, tilt theta_t)"] = [f"{len(ends)} branches of SymPy's solution, too long to print "
                                              f"(in Python: LineContact(f, symmetric=False).ends())"]
    if args.json or args.format == "json":
        _emit_json({k: (str(v) if not isinstance(v, list) else
                        [{kk: str(vv) for kk, vv in d.items()} if isinstance(d, dict) else d for d in v])
                    for k, v in out.items()})
    else:
        print(f"profile f(x) = {prof}    on the whole line; contact [e - a, e + a]")
        for k, v in list(out.items())[1:]:
            print()
            print(f"[{k}]")
            print(v if not isinstance(v, list) else "\n".join(str(d) for d in v))
    return EXIT_OK


#: what ``eval --theta/--moment`` evaluates on the contact state
STATE_QUANTITIES = ("left", "right", "e", "a", "theta", "moment", "punch", "pressure", "gap")


def _eval_state(c, q, values, args):
    """``eval --theta T`` / ``--moment M``: the contact state at the load P (given by --set or
    --at), then ``q``: an end, the tilt, the moment, or the pressure or gap at x."""
    if q not in STATE_QUANTITIES:
        raise LineContactError(f"with --theta or --moment the quantity is one of {', '.join(STATE_QUANTITIES)}")
    vals = dict(values)
    if "P" not in vals:
        raise LineContactError("--theta/--moment need the load: --set P=... or --at P=...")
    load = vals.pop("P")
    xv = vals.pop("x", None)
    if q in ("pressure", "gap") and xv is None:
        raise LineContactError(f"{q} needs x: --at x=... or --set x=...")
    state = c.contact_at(load, theta=args.theta, moment=args.moment, dps=args.dps, **vals)
    return getattr(state, q)(xv) if q in ("pressure", "gap") else getattr(state, q)


# ------------------------------------------------------------------ eval
def _registry():
    from .contacts.base import qualified_quantities
    return qualified_quantities()


def _expression_quantities(kind):
    """Registry names of a kind's quantities that are expressions (not methods)."""
    from .contacts.base import contact_kind
    return [n for n, q in contact_kind(kind).quantities().items() if not q.method]


#: the most points one ``eval`` call evaluates (the product of its --at grids)
MAX_EVAL_POINTS = 10000


def cmd_eval(args):
    import mpmath
    from .parsing import parse_number_list
    prof = _profile(args.profile, args.symbols)
    values = _settings(args.set, args.symbols)
    q = args.quantity
    state = args.theta is not None or args.moment is not None
    if args.theta is not None and args.moment is not None:
        raise LineContactError("give --theta or --moment, not both")
    if state and q not in STATE_QUANTITIES:
        raise LineContactError(f"with --theta or --moment the quantity is one of {', '.join(STATE_QUANTITIES)}")
    if not state and getattr(args, "asymmetric", False):
        raise LineContactError("--asymmetric in eval needs --theta or --moment (the contact state)")
    mat = _material(args)
    if state and mat is not None:
        raise LineContactError("--theta/--moment and a viscoelastic material together are not supported")
    c = _contact(args, prof)
    own = {} if state else _own_quantities(c)   # the contact's own (a periodic array: nominal_pressure, ...) first
    if not state and q not in own and q not in _registry() and mat is None:
        raise LineContactError(f"unknown quantity {q!r}; choose one of {', '.join(dict.fromkeys([*own, *_registry()]))}")
    grids = {}
    for item in args.at or []:
        if "=" not in item:
            raise LineContactError(f"--at expects NAME=V1,V2,..., got {item!r}")
        name, vs = item.split("=", 1)
        grids[name.strip()] = parse_number_list(vs, where=f"--at {name.strip()}", name=name.strip(), units=S.UNITS)
    total = math.prod(len(v) for v in grids.values())
    if total > MAX_EVAL_POINTS:
        raise LineContactError(f"--at spans {total} points (the product of the grids); at most "
                               f"{MAX_EVAL_POINTS} per call")
    names = list(grids)
    fixed = {k.name: v for k, v in values.items()}
    bodies = _bodies(args)
    frictional = None              # the frictional contact whose results neglect the bodies' coupling (said)
    if not state and mat is None and q not in own and _registry()[q][0] in FRICTIONAL_KINDS:
        frictional = _frictional(_registry()[q][0], c, bodies)
    elif bodies:
        raise LineContactError("--beta/--materials describe the two bodies of a frictional contact: use them "
                               "with a tangential.* or rolling.* quantity")
    rows = []
    for combo in itertools.product(*[grids[nm] for nm in names]):
        point = dict(zip(names, combo))
        allv = {**fixed, **point}
        try:
            v = (_eval_state(c, q, allv, args) if state else
                 _eval_one(c, q, allv, args.dps, frictional) if mat is None else
                 _viscoelastic_eval(c, q, mat, args, allv))
            rows.append({**{k: str(vv) for k, vv in point.items()}, "value": mpmath.nstr(v, args.dps)})
        except LineContactError as exc:
            rows.append({**{k: str(vv) for k, vv in point.items()}, "value": None, "error": str(exc)})
            at = ", ".join(f"{k} = {vv}" for k, vv in point.items())
            _err(f"{q}{' at ' + at if at else ''}: {_cli_hint(str(exc))}")   # on stderr too, not only in the table
    if args.json:
        _emit_json({"profile": str(prof), "quantity": q, "set": {k: str(v) for k, v in fixed.items()},
                    "dps": args.dps, "rows": rows,
                    **({"coupling": str(_coupling_note(frictional, fixed))} if frictional is not None else {})})
    else:
        head = "  ".join(f"{n:>12}" for n in names) + f"  {q}"
        if _has_unit(list(args.set or []) + list(args.at or [])):
            quantity = type(c).quantities()[own[q]] if q in own else _registry().get(q, (None, None, None))[2]
            unit = getattr(quantity, "unit", None)      # values with units: the result in SI, said
            head += f" [{unit or 'SI'}]"
        print(head)
        for r in rows:
            print("  ".join(f"{r[n]:>12}" for n in names) + "  " + (r["value"] or f"error: {r['error']}"))
        if frictional is not None:
            print(_coupling_line(frictional, fixed))
    return EXIT_OK if all(r.get("value") is not None for r in rows) else EXIT_INPUT


def _own_quantities(c) -> dict:
    """Name (and alias) -> registry name of the frictionless contact's own
    quantities: those of its class (a periodic array's nominal_pressure,
    full_contact_force, ...), which the registry of kinds does not list."""
    out = {}
    for name, quantity in type(c).quantities().items():
        out[name] = name
        for al in quantity.aliases:
            out.setdefault(al, name)
    return out


def _eval_one(c, q, values, dps, frictional=None):
    from .contacts.base import contact_kind
    own = _own_quantities(c)
    if q in own:                       # the contact's own quantity, on the contact itself
        contact, name = c, own[q]
        quantity = type(c).quantities()[name]
    else:
        kind, name, quantity = _registry()[q]
        contact = frictional if frictional is not None else contact_kind(kind).from_frictionless(c)
    if quantity.method:  # a(P), c_s(Q): the load is the last argument, passed first
        load_name = quantity.arguments[-1]
        if load_name not in values:
            raise LineContactError(f"{q} needs {load_name}: --at {load_name}=... or --set {load_name}=...")
        load = values.pop(load_name)
        out = getattr(contact, name)(load, **values)
        return out[0] if isinstance(out, tuple) else out
    return contact.evaluate_at(name, dps=dps, **values)


# ------------------------------------------------------------------ model
def cmd_model(args):
    """Which adhesion model a tolerance needs: JKR or Maugis-Dugdale."""
    import mpmath
    prof = _profile(args.profile, args.symbols)
    values = {k.name: v for k, v in _settings(args.set, args.symbols).items()}
    md = _contact(args, prof).maugis_dugdale()
    missing = [s.name for s in md.variables if s.name not in values]
    if missing:
        raise LineContactError(f"model needs values for {', '.join(missing)} (--set NAME=VALUE)")
    ch, po = md.model_choice(rtol=args.rtol, dps=args.dps, **values), md.pull_off_at(args.dps, **values)
    out = {"profile": str(prof), "set": {k: str(v) for k, v in values.items()}, "model": ch.model,
           "maugis_parameter": mpmath.nstr(ch.maugis_parameter, args.dps),
           "pull_off_jkr": mpmath.nstr(ch.jkr, args.dps), "pull_off_md": mpmath.nstr(ch.md, args.dps),
           "relative_difference": mpmath.nstr(ch.relative_difference, 6), "rtol": args.rtol,
           "md_pull_off_kind": po.kind, "md_pull_off_half_width": mpmath.nstr(po.half_width, args.dps),
           "note": po.note, "displacement_control": "not defined for line contacts"}
    if args.json:
        _emit_json(out)
    else:
        print(f"profile f(x) = {prof}")
        print(f"model: {ch.model}   (JKR suffices when its pull-off is within rtol = {args.rtol} of MD's)")
        print(f"Maugis parameter lambda = {out['maugis_parameter']}")
        print(f"pull-off (load control): JKR {out['pull_off_jkr']}, MD {out['pull_off_md']} "
              f"(relative difference {out['relative_difference']}); MD minimum: {po.kind} at a = "
              f"{out['md_pull_off_half_width']}")
        print("displacement control: not defined for line contacts (the indentation depth of a half-plane is not)")
    return EXIT_OK


# ------------------------------------------------------------------ table
def cmd_table(args):
    from .parsing import parse_number_list
    from .claims.report import power_law_latex, power_law_rows, power_law_text
    if args.kind != "power-law":
        raise LineContactError(f"unknown table {args.kind!r}; available: power-law")
    ns = parse_number_list(args.n, where="--n")
    rows, Zsym, d = power_law_rows(ns, budget=args.budget)
    if args.json:
        _emit_json({"Z_n": str(Zsym), "force_law": str(d.expr), "method": d.method,
                    "rows": [{"n": str(r["n"]), "Z_n": str(r["Z"]), "Z_n_float": r["Z_float"],
                              "force": str(r["force"])} for r in rows]})
    elif args.latex:
        print(power_law_latex(rows))
    else:
        print(f"f(x) = c x**n:  P(a) = E* c Z_n a**n,  Z_n = {Zsym}   (derived: {d.rule})")
        print(power_law_text(rows))
    return EXIT_OK


# ------------------------------------------------------------------ check
_CLI_QUANTITIES = {"force": "force", "pressure": "pressure", "gap": "gap",
                   "adhesive_force": "adhesive_force", "adhesion_force": "adhesion_force",
                   "pull_off": "pull_off_force", "Z_n": "Z_n"}


def cmd_check(args):
    from .claims.batch import check_paper
    from .claims.spec import Paper, claim_from_cli, load_paper
    from .claims.report import text_table
    formulas = [(q, getattr(args, q)) for q in _CLI_QUANTITIES if getattr(args, q, None)]
    if args.quantity or args.formula:
        if not (args.quantity and args.formula):
            raise LineContactError("--quantity and --formula go together")
        formulas.append(("__generic__", args.formula))
    if args.file:
        if formulas or args.profile:
            raise LineContactError("give either a claims FILE or --profile with formulas, not both")
        paper = load_paper(args.file)
    else:
        if not formulas:
            raise LineContactError("nothing to check: give a claims FILE, or --profile with --force/--pressure/"
                                   "--gap/--adhesive-force/--adhesion-force/--pull-off/--Z-n or --quantity Q --formula F")
        ranges = {}
        for item in args.range or []:
            name, _, span = item.partition("=")
            lo, _, hi = span.partition(":")
            if not (name and lo and hi):
                raise LineContactError(f"--range expects NAME=LOW:HIGH, got {item!r}")
            ranges[name.strip()] = [lo, hi]
        claims = []
        for q, formula in formulas:
            quantity = args.quantity if q == "__generic__" else _CLI_QUANTITIES[q]
            claims.append(claim_from_cli(quantity, formula, args.profile, label=f"{quantity} (command line)",
                                         assumptions=args.assume or (), ranges=ranges, symbols=args.symbols or (),
                                         force_law=args.force_law))
        paper = Paper("command-line", "claims from the command line", "", claims, {}, "command line")
    bar = Progress(len(paper.claims), "checking", enabled=not args.quiet, min_total=2)
    result = check_paper(paper, budget=args.budget, jobs=args.jobs, on_start=lambda i, n, c: bar.start(c.label),
                         progress=lambda i, n, r: bar.done(r.label, r.status, r.seconds))
    bar.close()
    if args.json:
        d = result.to_dict()
        d["exit_status"] = result.exit_code(args.strict)
        _emit_json(d)
    else:
        from .claims.report import claim_details_text
        print(text_table(result, notes=False))
        print()
        print(claim_details_text(result))
    return result.exit_code(args.strict)


# ------------------------------------------------------------------ parser
def bodies_options(sp_):
    """--beta, --materials (derive --rolling; eval of tangential.* and rolling.*): the keywords of
    :data:`linecontact_sym.core.materials.COUPLING_KEYWORDS`."""
    from .core.materials import COUPLING_KEYWORDS
    sp_.add_argument("--beta", default=None, metavar="B", help="with tangential/rolling results: "
                     + COUPLING_KEYWORDS["beta"] + " (without --beta or --materials: beta = 0 assumed, said)")
    sp_.add_argument("--materials", default=None, metavar="E1,nu1,E2,nu2", help="with tangential/rolling "
                     "results, the two elastic bodies (oo: rigid; not --material, the viscoelastic one): "
                     + COUPLING_KEYWORDS["materials"].split(": ", 1)[1])


def viscoelastic_options(sp_):
    """--material, --relaxation, --history, --load (derive and eval)."""
    sp_.add_argument("--material", metavar="NAME:K=V,...", help="a viscoelastic half-plane: "
                     + ", ".join(MATERIALS) + " with its parameters, e.g. maxwell:E0=2,tau=1 (reduced modulus E*(t))")
    sp_.add_argument("--relaxation", metavar="EXPR", help="any reduced relaxation modulus E*(t) in t, e.g. "
                     "'1 + 2*exp(-t)' (a Prony series)")
    sp_.add_argument("--history", metavar="EXPR", help="with a material: the half-width a(t), e.g. "
                     "'Piecewise((t/10, t <= 1), ((2 - t)/10, t <= 2), (0, True))'")
    sp_.add_argument("--load", metavar="EXPR", help="with a material: the load P(t) (creep; quantity half_width)")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="linecontact-sym",
                description="Closed-form line (2-D) contact laws by Popov's (2017) flat-punch superposition: "
                            "derive, evaluate, tabulate, and check published formulas.",
                epilog=EXIT_HELP + " A formula starting with '-' may be typed as it is (or after --).")
    from .core.version import package_version
    p.add_argument("--version", action="version", version=f"%(prog)s {package_version()}")
    sub = p.add_subparsers(dest="verb", metavar="VERB")
    sub.required = True

    def common(sp_, quiet=False):
        sp_.add_argument("--budget", type=_budget, default=DEFAULT_BUDGET, metavar="S",
                         help=f"CPU seconds allowed to each symbolic derivation, rules, tidying and "
                              f"verification together (default "
                              f"{'no limit' if DEFAULT_BUDGET is None else format(DEFAULT_BUDGET, 'g')}; "
                              f"'inf' for no limit)")
        sp_.add_argument("--json", action="store_true", help="machine-readable JSON on stdout")
        sp_.add_argument("--no-cache", dest="no_cache", action="store_true",
                         help="neither read nor write the on-disk derivation cache (default: "
                              "$LINECONTACT_SYM_CACHE, else ~/.cache/linecontact_sym; 'off' disables it)")
        if quiet:
            sp_.add_argument("--quiet", action="store_true",
                             help="no progress on stderr (a bar on a terminal, one line per item otherwise)")

    sym_help = "extra symbol names used by the formulas (created positive)"

    pp = sub.add_parser("paper", help="check every claim of a paper and write the reports",
                        description="Derive and check every claim of a paper (a shipped name such as "
                                    "popov2017, or a claims TOML file); print a report table and write a "
                                    "Markdown and a LaTeX report, the LaTeX Table 1, the paper's figures (its [[figures]], PNG and PDF) "
                                    "and results.json into DIR.",
                        epilog=EXIT_HELP)
    pp.add_argument("name", help="shipped paper (popov2017) or path to a claims .toml file")
    pp.add_argument("--out", metavar="DIR", help="output directory (default: ./<key>-report)")
    pp.add_argument("--only", nargs="+", metavar="LABEL", help="check only these claims, e.g. --only 'Eq. (10)'")
    pp.add_argument("--no-figures", action="store_true", help="do not draw the figures")
    _add_jobs(pp)
    common(pp, quiet=True)
    pp.set_defaults(func=cmd_paper)

    pd = sub.add_parser("derive", help="derive the force law, pressure and gap of a profile",
                        description="Derive P(a), p(x; a) and the gap of a profile f(x) (x >= 0, mirrored), "
                                    "e.g. linecontact-sym derive 'x**2/(2*R)'.",
                        epilog="exit status: 0 derived (a quantity without a closed form is given as an "
                               "integral, evaluated numerically); 2 bad input; 3 internal error.")
    pd.add_argument("profile", help="the profile f(x) in SymPy syntax, e.g. 'x**2/(2*R)'")
    pd.add_argument("--set", nargs="+", action="extend", metavar="NAME=VALUE", help="fix parameters, e.g. R=1")
    pd.add_argument("--symbols", nargs="+", action="extend", metavar="NAME", help=sym_help)
    pd.add_argument("--quantities", default=None, help="comma-separated, from: " + ", ".join(_expression_quantities(
        "frictionless")) + " (default force,pressure,gap); --adhesion: also adhesion_force, pull_off_force, ...")
    pd.add_argument("--adhesion", action="store_true", help="also the adhesive laws (default: JKR, Eqs. 29-36): "
                    "force, pressure, the pull-off P_min and P_adh = -P_min, a at pull-off, or those of --quantities")
    pd.add_argument("--rolling", action="store_true", help="also steady rolling with traction (rolling in +x, "
                    "the stick zone [a - 2 c_s, a] at the leading edge): the tangential force Q(a, c_s), the "
                    "creepage xi(a, c_s) and the stick half-width c_s(Q) (Carter for the cylinder)")
    bodies_options(pd)
    viscoelastic_options(pd)
    pd.add_argument("--law", default=None, help="the cohesive law of --adhesion (registered: jkr, maugis_dugdale; "
                    "default jkr); naming one implies --adhesion")
    pd.add_argument("--period", default=None, metavar="L", help="a periodic array of period L (a number or a "
                    "symbol; the profile given on 0 <= x <= L/2): also nominal_pressure, full_contact_force, "
                    "full_contact_pressure")
    pd.add_argument("--asymmetric", action="store_true", help="f is given on the whole line (not mirrored): "
                    "the load P(e, a), tilt theta(e, a) and moments of the contact [e - a, e + a]")
    pd.add_argument("--format", choices=("text", "latex", "json"), default="text",
                    help="text (default: SymPy syntax), latex (an align* block in the paper's notation; "
                         "K(k), E(k) with the modulus k) or json (same as --json)")
    common(pd, quiet=True)
    pd.set_defaults(func=cmd_derive)

    pe = sub.add_parser("eval", help="evaluate a derived quantity at points, to any precision",
                        description="Evaluate a quantity on the grid of --at values (all combinations), with "
                                    "--set fixing the rest, e.g. linecontact-sym eval 'x**2/(2*R)' pressure "
                                    "--at a=1 x=0.1,0.5 --set R=1 E_star=1 --dps 50.",
                        epilog="exit status: 0 every point evaluated; 2 bad input or a point outside the "
                               "quantity's domain (its row says why); 3 internal error.")
    pe.add_argument("profile", help="the profile f(x) in SymPy syntax")
    pe.add_argument("quantity", help="one of: " + ", ".join(_registry()) + " (adhesive quantities "
                                     "take gamma; a(P) quantities take P, the stable branch first)")
    pe.add_argument("--at", nargs="+", action="extend", metavar="NAME=V1,V2",
                    help="grid values, e.g. a=0.1,0.2 x=0:1:5 (LOW:HIGH:COUNT)")
    pe.add_argument("--set", nargs="+", action="extend", metavar="NAME=VALUE", help="fixed values, e.g. R=1 E_star=1")
    pe.add_argument("--symbols", nargs="+", action="extend", metavar="NAME", help=sym_help)
    pe.add_argument("--dps", type=_dps, default=30, help="significant digits, 1 to 1000 (default 30)")
    bodies_options(pe)
    viscoelastic_options(pe)
    pe.add_argument("--period", default=None, metavar="L", help="a periodic array of period L (the profile given "
                    "on 0 <= x <= L/2; L a number or a symbol given by --set)")
    pe.add_argument("--theta", default=None, metavar="T", help="the contact state at the load P with the tilt T "
                    "(gap f(x) - T x - d); quantity one of " + ", ".join(STATE_QUANTITIES))
    pe.add_argument("--moment", default=None, metavar="M", help="the contact state at the load P under the moment "
                    "M = int x p dx (free rotation)")
    pe.add_argument("--asymmetric", action="store_true", help="f is given on the whole line (not mirrored)")
    common(pe)
    pe.set_defaults(func=cmd_eval)

    pm = sub.add_parser("model", help="which adhesion model a tolerance needs: JKR or Maugis-Dugdale",
                        description="Given the profile, E_star, the work of adhesion gamma, the Dugdale stress "
                                    "sigma_0 and the profile's parameters, compare the load-control pull-off of "
                                    "the JKR and the Maugis-Dugdale laws and print the Maugis parameter, e.g. "
                                    "linecontact-sym model 'x**2/(2*R)' --set R=1 E_star=1 gamma=1 sigma_0=0.5.",
                        epilog="exit status: 0 done; 2 bad input; 3 internal error.")
    pm.add_argument("profile", help="the profile f(x) in SymPy syntax")
    pm.add_argument("--set", nargs="+", action="extend", metavar="NAME=VALUE",
                    help="values: E_star, gamma, sigma_0 and the profile's parameters")
    pm.add_argument("--rtol", type=_rtol, default=0.05, help="relative tolerance on the pull-off (default 0.05)")
    pm.add_argument("--symbols", nargs="+", action="extend", metavar="NAME", help=sym_help)
    pm.add_argument("--dps", type=_dps, default=15, help="significant digits (default 15)")
    common(pm)
    pm.set_defaults(func=cmd_model)

    pt = sub.add_parser("table", help="tables of derived laws (power-law Z_n)",
                        description="Z_n and the force law P(a) = E* c Z_n a^n of the power-law profile c x^n "
                                    "for a list of exponents, as text, LaTeX (booktabs) or JSON.",
                        epilog="exit status: 0 done; 2 bad input (e.g. an exponent <= 0); 3 internal error.")
    pt.add_argument("kind", choices=("power-law",), help="the table (power-law)")
    pt.add_argument("--n", default="1,2,3,4,5,6,10", help="exponents, comma-separated (default 1,2,3,4,5,6,10)")
    pt.add_argument("--latex", action="store_true", help="LaTeX booktabs table")
    common(pt)
    pt.set_defaults(func=cmd_table)

    pc = sub.add_parser("check", help="check claims: a claims file, or one formula typed here",
                        description="Check a claims TOML file, or a formula for a profile, e.g. "
                                    "linecontact-sym check --profile 'x**2/(2*R)' --force 'pi*E_star*a**2/(4*R)'. "
                                    "Verdicts: holds / holds under a condition / does not hold (with the "
                                    "derived formula, a counterexample and, for a common mistake such as "
                                    "the elliptic modulus k passed for the parameter m = k**2, a diagnosis) "
                                    "/ undecided.",
                        epilog=EXIT_HELP)
    pc.add_argument("file", nargs="?", help="claims .toml file (or a shipped paper name)")
    pc.add_argument("--profile", help="the profile f(x)")
    pc.add_argument("--force", help="the claimed force law P(a)")
    pc.add_argument("--pressure", help="the claimed pressure p(x; a), 0 < x < a")
    pc.add_argument("--gap", help="the claimed gap g(x; a), x > a")
    pc.add_argument("--adhesive-force", dest="adhesive_force", help="the claimed JKR force law P(a)")
    pc.add_argument("--adhesion-force", dest="adhesion_force",
                    help="the claimed adhesion force P_adh = -min_a P(a) > 0 (e.g. Eqs. 34-36)")
    pc.add_argument("--pull-off", dest="pull_off",
                    help="the claimed pull-off load P_min = min_a P(a) < 0 (negative: a tensile load; "
                         "write --pull-off='-...' for a leading minus; for the positive P_adh use "
                         "--adhesion-force)")
    pc.add_argument("--Z-n", dest="Z_n", help="the claimed Z_n of a power law c*x**n")
    pc.add_argument("--quantity", help="any checker quantity (with --formula): " + ", ".join(_check_quantities()))
    pc.add_argument("--formula", help="the claimed formula for --quantity")
    pc.add_argument("--force-law", dest="force_law", help="force law for --quantity inverse_profile")
    pc.add_argument("--assume", nargs="+", action="extend", metavar="REL", help="assumptions, e.g. 'a < R'")
    pc.add_argument("--range", nargs="+", action="extend", metavar="NAME=LOW:HIGH",
                    help="sampling ranges, e.g. n=0.3:6")
    pc.add_argument("--symbols", nargs="+", action="extend", metavar="NAME", help=sym_help)
    pc.add_argument("--strict", action="store_true", help="exit 1 unless every claim holds unconditionally")
    _add_jobs(pc)
    common(pc, quiet=True)
    pc.set_defaults(func=cmd_check)
    return p


def _check_quantities():
    from .claims.spec import QUANTITIES
    return sorted(QUANTITIES)


def _option_strings(parser) -> set:
    out = set()
    for act in parser._actions:
        out.update(act.option_strings)
        if isinstance(act, argparse._SubParsersAction):
            for sp_ in act.choices.values():
                out |= _option_strings(sp_)
    return out


def protect_formulas(argv, options) -> list:
    """Let formulas start with '-': an argument such as ``-x**2`` (one dash,
    not an option of the parser) gets a leading space, which argparse does
    not read as an option and the formula parser ignores.  Arguments after
    ``--`` are left alone.

    >>> protect_formulas(["derive", "-x**2", "-h"], {"-h", "--help"})
    ['derive', ' -x**2', '-h']
    """
    out, rest = [], False
    for tok in argv:
        if not rest and tok == "--":
            rest = True
        elif not rest and len(tok) > 1 and tok[0] == "-" and tok[1] != "-" and tok not in options:
            tok = " " + tok
        out.append(tok)
    return out


def _add_jobs(parser) -> None:
    """``--jobs N`` (default: the cores), read by :func:`_jobs`."""
    parser.add_argument("--jobs", "-j", type=_jobs, default=default_jobs(), metavar="N",
                        help=f"check the claims in N worker processes (default: the cores, here {default_jobs()}; "
                             f"never more than the claims); the results are those of --jobs 1, in the same order")


def main(argv=None) -> int:
    try:
        check_environment()          # LINECONTACT_SYM_BUDGET: bad input (exit 2), not "a claim fails"
    except LineContactError as exc:
        _err(str(exc))
        return EXIT_INPUT
    parser = build_parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    args = parser.parse_args(protect_formulas(argv, _option_strings(parser)))
    if getattr(args, "no_cache", False):
        from .method import store
        store.set_enabled(False)
    try:
        return args.func(args)
    except LineContactError as exc:
        _err(_cli_hint(str(exc)))
        return EXIT_INPUT
    except KeyboardInterrupt:
        _err("interrupted")
        return 130
    except BrokenPipeError:          # output piped into head & co.
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return EXIT_OK
    except Exception as exc:  # noqa: BLE001
        _err(f"internal error: {type(exc).__name__}: {exc}")
        if os.environ.get("LINECONTACT_SYM_DEBUG"):
            traceback.print_exc()
        return EXIT_INTERNAL


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
