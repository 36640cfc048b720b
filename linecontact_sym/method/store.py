"""Derivations remembered, so that nothing waits twice for the same answer.

Two levels, one key:

* **in this process** a dict: a quantity derived once (closed form or not)
  is not derived again, in particular a quantity that failed to close is not
  retried (unless with a larger time budget than the one it failed under);
* **across processes** one file per derivation in the user's cache
  directory: ``$LINECONTACT_SYM_CACHE`` if set (a directory, or ``off`` to
  disable), else ``$XDG_CACHE_HOME/linecontact_sym``, else
  ``~/.cache/linecontact_sym``.  ``linecontact-sym --no-cache`` (or
  :func:`set_enabled`) switches the disk off for the process.

The key is a SHA-256 of the profile and force law (``srepr``, so the symbols'
assumptions are part of it; the engine's Dummy integration variables by
their order of appearance, not their per-process index), the quantity, the
verification settings and the *code version*: the package version, the
versions of SymPy, mpmath and python-flint, and a hash of **every** source
file of the package (a rule, a reference quadrature, a sampler or a contact
that builds a problem can all shape a derivation), so a changed package never
meets an entry written by its predecessor.

**The cache is data, never code.**  A file holds a magic line, the SHA-256
of its payload and the payload, JSON: plain values, and SymPy objects as
their ``srepr`` text, which is read back by :func:`from_srepr`, a parser
that accepts only calls of SymPy's own classes with literal arguments
(nothing is evaluated, no attribute is looked up, no other name is
callable).  An entry whose checksum, format, code version or key does not
match, or that holds anything else, is ignored (and replaced by the fresh
derivation).  A checksum only detects damage: it does not say who wrote the
file, so the directory must be the user's own -- a cache directory (or file)
owned by another user, or writable by group or others (``/tmp``), is not
used: a warning says so once and the process runs without the disk cache.
Files are written atomically (a temporary file renamed) with owner-only
permissions.  The reference quadrature of a derivation is a closure and is
not stored: the caller rebuilds it.
"""
from __future__ import annotations

import ast
import hashlib
import json
import os
import re
import stat
import tempfile
import warnings
from pathlib import Path

__all__ = ["cache_dir", "set_enabled", "enabled", "code_version", "make_key", "get", "put", "clear_memory",
           "CACHE_ENV", "from_srepr", "encode", "decode", "UntrustedCacheWarning"]

#: environment variable: a cache directory, or ``off``
CACHE_ENV = "LINECONTACT_SYM_CACHE"
_MAGIC = b"linecontact_sym-derivation-cache 2 json\n"
_SUFFIX = ".json"
_memory: dict = {}
_state = {"enabled": True, "version": None, "refused": set()}


class UntrustedCacheWarning(UserWarning):
    """The cache directory is not the user's own (it is not used), or a
    record in it is not what this package writes (it is ignored and derived
    afresh)."""


def set_enabled(on: bool) -> None:
    """Switch the on-disk cache on or off for this process (the in-process
    memory stays: within one process nothing is derived twice)."""
    _state["enabled"] = bool(on)


def enabled() -> bool:
    return _state["enabled"] and cache_dir() is not None


def cache_dir() -> Path | None:
    """The cache directory (see the module docstring), or None when disabled."""
    env = os.environ.get(CACHE_ENV)
    if env is not None:
        if env.strip().lower() in ("off", "0", "no", "false", ""):
            return None
        return Path(env).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "linecontact_sym"


# ------------------------------------------------------------------ who may have written it
def _foreign(st) -> str | None:
    """Why a file or directory with this ``lstat`` is not the user's own, or None."""
    if not hasattr(os, "getuid"):          # pragma: no cover - no POSIX owners (Windows)
        return None
    if st.st_uid != os.getuid():
        return f"owned by uid {st.st_uid}, not by this user (uid {os.getuid()})"
    if st.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
        return "writable by group or others"
    return None


def _trusted_dir(d: Path, create: bool) -> bool:
    """Is ``d`` a directory only this user can write (created owner-only
    when missing and ``create``)?  A refusal warns once per directory."""
    try:
        st = os.lstat(d)
    except FileNotFoundError:
        if not create:
            return False
        try:
            d.mkdir(parents=True, exist_ok=True, mode=0o700)
            st = os.lstat(d)
        except OSError:
            return False
    except OSError:
        return False
    why = "not a directory (a link or a file)" if not stat.S_ISDIR(st.st_mode) else _foreign(st)
    if why is None:
        return True
    if str(d) not in _state["refused"]:
        _state["refused"].add(str(d))
        warnings.warn(f"linecontact_sym: the derivation cache {d} is {why}; anyone who can write there could "
                      f"plant results, so it is not used (derivations are computed afresh). Use a directory "
                      f"of your own ({CACHE_ENV}=/path) or {CACHE_ENV}=off", UntrustedCacheWarning, stacklevel=3)
    return False


# ------------------------------------------------------------------ the key
def code_version() -> str:
    """The package version, the versions of the libraries results depend
    on, and a hash of every source file of the package."""
    if _state["version"] is None:
        import mpmath
        import sympy
        import flint      # a core dependency: its version is part of the key
        flint_version = getattr(flint, "__version__", "present")
        from ..core.version import package_version
        pkg = Path(__file__).resolve().parent.parent
        version = package_version()
        h = hashlib.sha256(f"{version}|sympy {sympy.__version__}|mpmath {mpmath.__version__}|"
                           f"flint {flint_version}".encode())
        for path in sorted(pkg.rglob("*.py")):
            h.update(path.relative_to(pkg).as_posix().encode())
            h.update(path.read_bytes())
        _state["version"] = f"{version}+{h.hexdigest()[:16]}"
    return _state["version"]


_DUMMY_INDEX = re.compile(r"dummy_index=\d+")


#: the key text of recent SymPy objects, by identity (the object kept, so that its id is not
#: reused while it is here): SymPy objects are immutable, and the claims checker keys every
#: point of a form by the same derived expression, profile and conditions
_TEXTS: dict = {}
_TEXTS_MAX = 512


def _part(p):
    import sympy as sp
    if isinstance(p, sp.Basic):
        hit = _TEXTS.get(id(p))
        if hit is not None and hit[0] is p:
            return hit[1]
        text, seen = sp.srepr(p), {}
        # a Dummy's index differs between processes: number them by appearance
        text = _DUMMY_INDEX.sub(lambda m: f"dummy_index=#{seen.setdefault(m.group(0), len(seen))}", text)
        if len(_TEXTS) >= _TEXTS_MAX:
            _TEXTS.clear()
        _TEXTS[id(p)] = (p, text)
        return text
    if isinstance(p, (list, tuple)):
        return "(" + ",".join(_part(q) for q in p) + ")"
    if isinstance(p, dict):
        return "{" + ",".join(f"{_part(k)}:{_part(v)}" for k, v in sorted(p.items(), key=lambda kv: str(kv[0]))) + "}"
    return repr(p)


def make_key(*parts) -> str:
    """A key for the given parts (SymPy objects by ``srepr``) and the code version."""
    text = code_version() + "|" + "|".join(_part(p) for p in parts)
    return hashlib.sha256(text.encode()).hexdigest()


# ------------------------------------------------------------------ data, never code
_CLASSES: dict = {}


class UntrustedRecord(ValueError):
    """A stored record holds something that is not plain data."""


#: the limits of what a record may hold, checked on the text before anything is built
MAX_TEXT = 2_000_000            # characters of one srepr text
MAX_DIGITS = 1000               # digits of an Integer / Rational literal
MAX_NAME = 200                  # characters of a Symbol's name
MAX_FLOAT_BITS = 40_000         # precision of a Float literal (bits)
MAX_POW_DIGITS = 10_000         # digits of a power of a number the reader would compute
MAX_EXPONENT = 1000             # |p|, q of a rational exponent of a number
MAX_FUNCTION_ARG = 10_000       # |p|, q of an exact number a function is applied to (factorial(10**7) ...)

#: classes whose constructors compute (roots of polynomials, matrices, new
#: functions, substitutions): never in a derivation record
_DENIED = {"Function", "Lambda", "Subs", "WildFunction", "CRootOf", "ComplexRootOf", "RootOf", "RootSum", "Poly",
           "PurePoly", "ImageSet", "ConditionSet", "ComplexRegion"}
#: arithmetic and structure: their arguments' sizes are bounded by the literals and by Pow's rule
_ARITHMETIC = {"Add", "Mul", "Pow", "Tuple", "ExprCondPair", "Piecewise", "Equality", "Unequality",
               "StrictLessThan", "LessThan", "StrictGreaterThan", "GreaterThan", "And", "Or", "Not",
               "Integer", "Rational", "Float", "Symbol", "Dummy", "Str", "Integral", "Interval"}
_FLOAT_TEXT = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d{1,6})?|[+-]?inf|nan")
_BOOL_KW = {"Symbol", "Dummy"}


def _sympy_names():
    """name -> SymPy class (a subclass of Basic defined in SymPy) or SymPy
    singleton (pi, E, oo, true, ...): everything :func:`from_srepr` accepts."""
    if not _CLASSES:
        import sympy as sp
        stack = [sp.Basic]
        while stack:
            k = stack.pop()
            stack.extend(type.__subclasses__(k))
            if (getattr(k, "__module__", None) or "").startswith("sympy.") and not k.__name__.startswith("_"):
                _CLASSES.setdefault(k.__name__, k)
        for name in dir(sp):
            v = getattr(sp, name)
            if isinstance(v, type) and issubclass(v, sp.Basic):
                _CLASSES[name] = v           # the public class wins a name clash
            elif isinstance(v, sp.Basic) and not name.startswith("_"):
                _CLASSES[name] = v           # pi, E, I, oo, zoo, nan, true, false, EulerGamma, ...
        for name in list(_CLASSES):
            v = _CLASSES[name]
            if name in _DENIED or (isinstance(v, type) and issubclass(v, sp.MatrixBase if hasattr(sp, "MatrixBase")
                                                                        else ())):
                _CLASSES.pop(name)           # constructors that compute, or make new functions
    return _CLASSES


def _digits(n: int) -> int:
    return len(str(abs(n))) if abs(n) < 10 ** 50 else int(abs(n).bit_length() * 0.30103) + 1


def from_srepr(text: str):
    """The SymPy object of an ``srepr`` text, read by a whitelist over
    Python's ``ast`` of the text (nothing is evaluated by ``eval`` or
    ``sympify``; no string reaches either):

    * node types: calls of a *name*, names, literals, unary minus of a number;
    * names: SymPy's classes (subclasses of ``Basic`` defined in SymPy; not
      those whose constructors compute or create functions: ``Function``,
      ``Lambda``, ``Subs``, ``RootOf``, ``Poly``, matrices, ...) and SymPy's
      singletons (``pi``, ``oo``, ``true`` ...);
    * argument kinds by class: a string only as the name of a ``Symbol`` /
      ``Dummy`` / ``Str`` (kept as a name) and as the digits of a ``Float``
      (matched as a decimal number first); a Python int only in
      ``Integer``, ``Rational`` and the keywords ``precision`` (of a Float)
      and ``dummy_index``; keywords only ``Symbol``'s / ``Dummy``'s boolean
      assumptions; every other argument is a SymPy object built the same way;
    * sizes, checked before anything is built: the text, the digits of every
      integer literal, a Float's precision, a power of a number (the digits
      it would have, its exponent), and an exact number given to a function
      (``factorial(10**7)``), so that no record can make the reader hang.

    Anything else raises :class:`UntrustedRecord`.  Dummies keep their name
    and assumptions; the engine's integration variables (``_t``, ``_s`` of
    :mod:`~linecontact_sym.method.transforms`) come back as themselves.

    >>> import sympy as sp
    >>> R = sp.Symbol("R", positive=True)
    >>> from_srepr(sp.srepr(sp.pi * R / 4)) == sp.pi * R / 4
    True
    >>> from_srepr("__import__('os').system('true')")
    Traceback (most recent call last):
    ...
    linecontact_sym.method.store.UntrustedRecord: not SymPy data: a call of __import__('os').system
    >>> from_srepr("sin('1+1')")
    Traceback (most recent call last):
    ...
    linecontact_sym.method.store.UntrustedRecord: not SymPy data: a string given to sin
    >>> from_srepr("Pow(Integer(10), Integer(1000000000))")
    Traceback (most recent call last):
    ...
    linecontact_sym.method.store.UntrustedRecord: not SymPy data: a power of a number with the exponent 1000000000
    """
    import sympy as sp
    if not isinstance(text, str) or len(text) > MAX_TEXT:
        raise UntrustedRecord("not an srepr text (not a string, or longer than a record may be)")
    names = _sympy_names()
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        raise UntrustedRecord(f"not an srepr text: {exc}") from None
    dummies: dict = {}
    from . import transforms as T
    engine = {(d.name, tuple(sorted(d.assumptions0.items()))): d for d in (T.t, T.s)}

    def refuse(why):
        raise UntrustedRecord(f"not SymPy data: {why}")

    def py_int(node, where):
        """A Python int literal (unary minus allowed), its size bounded."""
        sign = 1
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            sign, node = -1, node.operand
        if not (isinstance(node, ast.Constant) and type(node.value) is int):
            refuse(f"{where} takes an integer literal")
        if _digits(node.value) > MAX_DIGITS:
            refuse(f"an integer of more than {MAX_DIGITS} digits in {where}")
        return sign * node.value

    def py_str(node, where, limit=MAX_NAME):
        if not (isinstance(node, ast.Constant) and type(node.value) is str):
            refuse(f"{where} takes a string literal")
        if len(node.value) > limit:
            refuse(f"a string of more than {limit} characters in {where}")
        return node.value

    def small(v, bound):
        return not (isinstance(v, sp.Rational) and (abs(v.p) > bound or v.q > bound))

    def check_pow(base, exp):
        if not base.is_number or not isinstance(exp, sp.Rational):
            return
        if abs(exp.p) > MAX_EXPONENT or exp.q > MAX_EXPONENT:
            refuse(f"a power of a number with the exponent {exp}")
        if isinstance(base, sp.Rational) and max(_digits(base.p), _digits(base.q)) * abs(exp.p) > MAX_POW_DIGITS:
            refuse(f"a power of a number with more than {MAX_POW_DIGITS} digits")

    def call(node):
        if not isinstance(node.func, ast.Name):
            refuse(f"a call of {ast.unparse(node.func)}")
        name = node.func.id
        cls = names.get(name)
        if not isinstance(cls, type):
            refuse(name)
        if any(isinstance(a, ast.Starred) for a in node.args):
            refuse(f"starred arguments of {name}")
        if name == "Integer":
            if len(node.args) != 1 or node.keywords:
                refuse("Integer takes one integer literal")
            return sp.Integer(py_int(node.args[0], name))
        if name == "Rational":
            if len(node.args) != 2 or node.keywords:
                refuse("Rational takes two integer literals")
            p, q = (py_int(a, name) for a in node.args)
            if q == 0:
                refuse("a Rational with denominator 0")
            return sp.Rational(p, q)
        if name == "Float":
            kw = {k.arg: k.value for k in node.keywords}
            if len(node.args) != 1 or set(kw) - {"precision"}:
                refuse("Float takes its digits as a string and a precision")
            digits = py_str(node.args[0], name, limit=MAX_FLOAT_BITS)
            if not _FLOAT_TEXT.fullmatch(digits):
                refuse(f"Float digits {digits[:40]!r} are not a decimal number")
            prec = py_int(kw["precision"], "Float's precision") if "precision" in kw else 53
            if not 1 <= prec <= MAX_FLOAT_BITS:
                refuse(f"a Float of precision {prec} bits")
            return sp.Float(digits, precision=prec)
        if name in ("Symbol", "Dummy", "Str"):
            if len(node.args) != 1:
                refuse(f"{name} takes one name")
            label = py_str(node.args[0], name)
            kw = {}
            for k in node.keywords:
                if name == "Dummy" and k.arg == "dummy_index":
                    kw[k.arg] = py_int(k.value, "dummy_index")
                elif name in _BOOL_KW and k.arg is not None and k.arg.isidentifier() and \
                        isinstance(k.value, ast.Constant) and type(k.value.value) is bool:
                    kw[k.arg] = k.value.value
                else:
                    refuse(f"a keyword of {name} that is not a boolean assumption")
            if name == "Str":
                if kw:
                    refuse("Str takes no keywords")
                return sp.core.symbol.Str(label)
            if name == "Dummy":
                index = kw.pop("dummy_index", None)
                if index not in dummies:
                    same = engine.get((label, tuple(sorted(sp.Dummy(label, **kw).assumptions0.items()))))
                    dummies[index] = same if same is not None else sp.Dummy(label, **kw)
                return dummies[index]
            return sp.Symbol(label, **kw)
        if node.keywords:
            refuse(f"keyword arguments of {name}")
        args = []
        for a in node.args:
            if isinstance(a, ast.Constant):
                refuse(f"a {type(a.value).__name__} given to {name}" if not isinstance(a.value, str)
                       else f"a string given to {name}")
            args.append(conv(a))
        if name == "Pow":
            if len(args) != 2:
                refuse("Pow takes two arguments")
            check_pow(*args)
        elif name not in _ARITHMETIC and not all(small(v, MAX_FUNCTION_ARG) for v in args):
            refuse(f"an exact number above {MAX_FUNCTION_ARG} given to {name}")
        return cls(*args)

    def conv(node):
        if isinstance(node, ast.Call):
            return call(node)
        if isinstance(node, ast.Name):
            v = names.get(node.id)
            if v is None or isinstance(v, type):
                refuse(node.id)
            return v
        refuse(type(node).__name__ if not isinstance(node, ast.Constant) else f"a bare {type(node.value).__name__}")
    try:
        return conv(tree.body)
    except UntrustedRecord:
        raise
    except RecursionError:
        raise UntrustedRecord("not SymPy data: nested too deeply") from None
    except Exception as exc:              # a SymPy class refusing its arguments
        raise UntrustedRecord(f"could not rebuild {text[:80]!r}: {type(exc).__name__}: {exc}") from None


def encode(obj):
    """A record as JSON-able plain data (SymPy objects by ``srepr``); a type
    this store does not know raises TypeError (the record stays in memory)."""
    import sympy as sp
    from .rulebase import Step
    from .verification import VerificationRecord
    if obj is None or isinstance(obj, (bool, int, float, str)):
        return obj
    if isinstance(obj, sp.Basic):
        return {"sympy": sp.srepr(obj)}
    if isinstance(obj, tuple):
        return {"tuple": [encode(v) for v in obj]}
    if isinstance(obj, list):
        return {"list": [encode(v) for v in obj]}
    if isinstance(obj, dict):
        return {"dict": [[encode(k), encode(v)] for k, v in obj.items()]}
    if isinstance(obj, Step):
        return {"Step": [encode(obj.rule), encode(obj.expr), encode(tuple(obj.conditions)), encode(tuple(obj.notes))]}
    if isinstance(obj, VerificationRecord):
        return {"VerificationRecord": [encode(obj.points), encode(obj.digits), obj.dps, obj.reference, obj.required,
                                       encode(obj.guaranteed), obj.outside]}
    raise TypeError(f"the derivation store does not keep {type(obj).__name__}")


def decode(data):
    """The inverse of :func:`encode`, through :func:`from_srepr` for SymPy
    objects; anything unexpected raises :class:`UntrustedRecord`."""
    from .rulebase import Step
    from .verification import VerificationRecord
    if data is None or isinstance(data, (bool, int, float, str)):
        return data
    if isinstance(data, dict) and len(data) == 1:
        (tag, val), = data.items()
        if tag == "sympy" and isinstance(val, str):
            return from_srepr(val)
        if tag in ("tuple", "list") and isinstance(val, list):
            out = [decode(v) for v in val]
            return tuple(out) if tag == "tuple" else out
        if tag == "dict" and isinstance(val, list) and all(isinstance(p, list) and len(p) == 2 for p in val):
            return {decode(k): decode(v) for k, v in val}
        if tag == "Step" and isinstance(val, list) and len(val) == 4:
            rule, expr, conds, notes = (decode(v) for v in val)
            if isinstance(rule, str) and isinstance(conds, tuple) and isinstance(notes, tuple):
                return Step(rule, expr, conds, notes)
        if tag == "VerificationRecord" and isinstance(val, list) and len(val) == 7:
            points, digits, guaranteed = decode(val[0]), decode(val[1]), decode(val[5])
            if isinstance(points, tuple) and isinstance(digits, tuple) and isinstance(val[2], int) \
                    and isinstance(val[3], str) and isinstance(val[4], int) and isinstance(guaranteed, tuple) \
                    and all(isinstance(g, float) for g in guaranteed) and isinstance(val[6], int):
                return VerificationRecord(points, digits, val[2], val[3], val[4], guaranteed, val[6])
    raise UntrustedRecord(f"not a record of this store: {str(data)[:80]}")


# ------------------------------------------------------------------ files
def _path(key):
    d = cache_dir()
    return None if d is None else d / key[:2] / f"{key}{_SUFFIX}"


def get(key: str):
    """The record stored under ``key`` (in memory, else on disk), or None;
    its ``source`` says which."""
    if key in _memory:
        return dict(_memory[key], source="memory")
    if not enabled():
        return None
    path = _path(key)
    if not (_trusted_dir(path.parent.parent, create=False) and _trusted_dir(path.parent, create=False)):
        return None
    try:
        # O_NONBLOCK: a FIFO at the path opens at once (and is refused below as not a regular
        # file) instead of blocking until a writer comes; a regular file reads as ever
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode) or _foreign(st) is not None:
            return None
        with os.fdopen(fd, "rb") as fh:
            fd = None
            data = fh.read()
    except OSError:
        return None
    finally:
        if fd is not None:
            os.close(fd)
    rec = _decode(data, key)
    if rec is None:
        return None
    _memory[key] = rec
    return dict(rec, source="disk")


def _decode(data: bytes, key: str):
    if not data.startswith(_MAGIC):
        return None
    body = data[len(_MAGIC):]
    digest, payload = body[:64], body[65:]
    if hashlib.sha256(payload).hexdigest().encode() != digest:
        return None                                    # corrupt: recomputed, never trusted
    try:
        rec = decode(json.loads(payload.decode("utf-8")))
    except UntrustedRecord as exc:
        warnings.warn(f"linecontact_sym: a derivation cache record ({key[:16]}...) holds something that is not "
                      f"plain data ({str(exc)[:160]}); it is ignored and derived afresh", UntrustedCacheWarning,
                      stacklevel=4)
        return None
    except Exception:   # noqa: BLE001 -- whatever is wrong with a file, it is derived afresh
        return None
    if not isinstance(rec, dict) or rec.get("key") != key or rec.get("version") != code_version():
        return None                                    # stale or misplaced
    return rec


def put(key: str, record: dict) -> None:
    """Remember ``record`` under ``key``: in memory, and on disk if enabled
    (silently skipped when the directory cannot be written or is not the
    user's own)."""
    record = dict(record, key=key, version=code_version())
    _memory[key] = record
    if not enabled():
        return
    path = _path(key)
    try:
        payload = json.dumps(encode(record), separators=(",", ":")).encode("utf-8")
    except (TypeError, ValueError):
        return                                         # not plain data: memory only
    data = _MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload
    if not (_trusted_dir(path.parent.parent, create=True) and _trusted_dir(path.parent, create=True)):
        return
    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-")
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, 0o600)
        os.replace(tmp, path)
    except OSError:
        pass


def clear_memory() -> None:
    """Forget the in-process records (the disk cache is untouched)."""
    _memory.clear()
