"""A whitelisted parser for formulas typed by people: claims files, the
command line, notebooks.

No string is ever compiled, evaluated or handed to ``sympify``.  Each string
is parsed by Python's own ``ast`` module (syntax only) and every node is
checked against a whitelist: numbers, the arithmetic operators, comparisons
and boolean connectives (for ``Piecewise`` conditions), tuples (for the
arguments of ``Piecewise``, ``Integral`` and ``hyper``), known names, and
calls of known functions by their bare name.  Anything else -- attribute
access, subscripts, dunder names, lambdas, comprehensions, keyword arguments,
strings, calls of unknown names -- is rejected with a
:class:`~linecontact_sym.core.errors.ClaimError` that names where the string
came from (file, claim, field) and what is wrong.  Sizes are bounded before
anything is built (so nothing can hang or exhaust memory): at most
:data:`MAX_LENGTH` characters, :data:`MAX_NODES` syntax nodes,
:data:`MAX_DEPTH` levels of nesting (a flat sum or product of many terms is
not nesting), constant exponents up to :data:`MAX_CONST_EXPONENT`,
``gamma``/``binomial``/``beta`` of constants up to :data:`MAX_EXACT_ARGUMENT`,
derivative orders up to :data:`MAX_DERIVATIVE_ORDER`.  Only then is the
SymPy object built node by node from the whitelisted objects.

Names
-----
* the standard symbols ``x, a, P, E_star, gamma, R, b, n, c, theta`` (with the
  assumptions of :mod:`linecontact_sym.core.symbols`) and the integration
  variables ``t`` and ``s`` (the paper's a-tilde);
* symbols the caller declares (``symbols=["k", "h"]``, created positive);
* named definitions (``definitions={"Z_n": expr}``), e.g. Popov's Z_n;
* placeholders for functional claims (``placeholders={"f": ...}``);
* constants ``pi``, ``E`` (Euler's number), ``I``, ``oo``;
* functions: see :data:`FUNCTIONS`.

``gamma`` is both the work of adhesion (a symbol, the paper's gamma_12) and
Euler's Gamma function: ``gamma(n/2)`` is the function, a bare ``gamma`` the
symbol.  ``^`` means power.  Decimal literals are exact (``0.1`` is 1/10).
"""
from __future__ import annotations

import ast
import math

import sympy as sp

from ..core import symbols as S
from ..core.conversion import exact_number, to_basic
from ..core.errors import ClaimError, DomainError, LineContactError

#: integration variables of formulas people write (the paper's a-tilde); the
#: engine's own are Dummies (:mod:`linecontact_sym.method.transforms`), so a
#: parameter named t or s in a profile never meets them
t = S.t     # the time symbol too (core.symbols): a bound variable never meets it
s = sp.Symbol("s", positive=True)

#: the standard symbols every formula may use
SYMBOLS = {sym.name: sym for sym in (S.x, S.a, S.P, S.E_star, S.gamma, S.R, S.b, S.n, S.c, S.theta,
                                     S.mu, S.Q, S.c_s, S.c_r, S.sigma_0, S.c_D, t, s)}

#: constants
CONSTANTS = {"pi": sp.pi, "E": sp.E, "I": sp.I, "oo": sp.oo, "True": sp.true, "False": sp.false}

#: functions that may be called, by name
FUNCTIONS = {
    "sqrt": sp.sqrt, "cbrt": sp.cbrt, "root": sp.root, "exp": sp.exp, "log": sp.log, "ln": sp.log,
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec, "csc": sp.csc,
    "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "acot": sp.acot, "atan2": sp.atan2,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "coth": sp.coth,
    "asinh": sp.asinh, "acosh": sp.acosh, "atanh": sp.atanh, "acoth": sp.acoth,
    "gamma": sp.gamma, "loggamma": sp.loggamma, "beta": sp.beta, "binomial": sp.binomial,
    "elliptic_k": sp.elliptic_k, "elliptic_e": sp.elliptic_e, "elliptic_f": sp.elliptic_f,
    "elliptic_pi": sp.elliptic_pi, "hyper": sp.hyper,
    "besselj": sp.besselj, "bessely": sp.bessely, "besseli": sp.besseli, "besselk": sp.besselk,
    "erf": sp.erf, "erfc": sp.erfc,
    "Piecewise": sp.Piecewise, "Abs": sp.Abs, "sign": sp.sign, "Min": sp.Min, "Max": sp.Max,
    "Rational": sp.Rational, "Integral": sp.Integral, "Derivative": sp.Derivative,
    "Eq": sp.Eq, "Ne": sp.Ne, "Lt": sp.Lt, "Le": sp.Le, "Gt": sp.Gt, "Ge": sp.Ge,
    "And": sp.And, "Or": sp.Or, "Not": sp.Not,
}

#: helpful words for names people often try
_HINTS = {
    "K": "for the complete elliptic integral K(k) write elliptic_k(k**2) (SymPy takes the parameter m = k**2)",
    "E": "E is Euler's number; for the elliptic integral E(k) write elliptic_e(k**2) "
         "(parameter m = k**2); the modulus is E_star",
    "Gamma": "write gamma(...) for Euler's Gamma function",
    "arcsin": "write asin", "arccos": "write acos", "arctan": "write atan",
    "arcsinh": "write asinh", "arccosh": "write acosh", "arctanh": "write atanh",
    "Estar": "the reduced modulus is E_star", "E_s": "the reduced modulus is E_star",
    "eval": "strings are never evaluated as code", "exec": "strings are never evaluated as code",
    "import": "strings are never evaluated as code", "open": "strings are never evaluated as code",
}

MAX_LENGTH = 2000
MAX_NODES = 800
MAX_DIGITS = 100         # longest numeric literal (characters)
MAX_CONST_EXPONENT = 1000
MAX_DEPTH = 60           # nesting of the syntax tree
MAX_EXACT_ARGUMENT = 1000  # |n| of gamma(n), binomial(n, k), beta(...) with constant arguments
MAX_DERIVATIVE_ORDER = 20
#: functions whose exact value at a large constant argument is astronomically long
_FACTORIAL_LIKE = {"gamma", "binomial", "beta"}

_ALLOWED_BINOPS = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow, ast.BitXor, ast.BitAnd, ast.BitOr)
_ALLOWED_UNARY = (ast.UAdd, ast.USub, ast.Invert, ast.Not)
_ALLOWED_CMP = (ast.Lt, ast.LtE, ast.Gt, ast.GtE, ast.Eq, ast.NotEq)



def where_prefix(where: str) -> str:
    return f"{where}: " if where else ""


class _Validator(ast.NodeVisitor):
    def __init__(self, text, where, names, callables):
        self.text = text
        self.where = where
        self.names = names
        self.callables = callables
        self.count = 0
        self.source = text

    def fail(self, problem, node=None):
        pos = f" (at column {node.col_offset + 1})" if node is not None and hasattr(node, "col_offset") else ""
        raise ClaimError(f"{where_prefix(self.where)}{problem}{pos} in {self.text!r}")

    depth = 0

    def visit(self, node):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(f"formula nested too deeply (more than {MAX_DEPTH} levels)")
        try:
            return super().visit(node)
        finally:
            self.depth -= 1

    def generic_visit(self, node):
        self.count += 1
        if self.count > MAX_NODES:
            self.fail(f"formula too large (more than {MAX_NODES} syntax nodes)")
        super().generic_visit(node)

    # -- allowed nodes -------------------------------------------------------
    def visit_Expression(self, node):
        self.generic_visit(node)

    def visit_Constant(self, node):
        self.count += 1
        v = node.value
        if isinstance(v, bool):
            return
        if isinstance(v, (int, float)):
            if len(ast.get_source_segment(self.source, node) or repr(v)) > MAX_DIGITS:
                self.fail(f"numeric literal with more than {MAX_DIGITS} characters", node)
            return
        if isinstance(v, str):
            self.fail("strings are not allowed", node)
        self.fail(f"constant {v!r} is not allowed", node)

    def visit_Name(self, node):
        self.count += 1
        name = node.id
        if name.startswith("_") or "__" in name:
            self.fail(f"name {name!r} is not allowed (no private or dunder names)", node)
        if name not in self.names and name not in self.callables:
            hint = _HINTS.get(name)
            known = ", ".join(sorted(n for n in self.names if n not in ("True", "False")))
            self.fail(f"unknown name {name!r}" + (f" ({hint})" if hint else
                      f"; declare it as a symbol (symbols = [\"{name}\"]) or use one of: {known}"), node)
        if name in self.callables and name not in self.names:
            self.fail(f"{name!r} is a function; call it, e.g. {name}(x)", node)

    def visit_BinOp(self, node):
        # a chain a + b + c + ... nests to the left in the syntax tree but is
        # flat in the formula: walk it iteratively, its links are no nesting
        links, cur = [], node
        while isinstance(cur, ast.BinOp) and (not links or type(cur.op) is type(links[-1].op)):
            links.append(cur)
            cur = cur.left
        for link in links:
            self._check_binop(link)
        self.visit(cur)
        for link in reversed(links):
            self.visit(link.right)

    def _check_binop(self, node):
        if not isinstance(node.op, _ALLOWED_BINOPS):
            self.fail(f"operator {type(node.op).__name__} is not allowed", node)
        if isinstance(node.op, (ast.Pow, ast.BitXor)) and _is_constant(node.right):
            try:
                e = _const_value(node.right)
            except OverflowError:
                self.fail("constant exponent too large", node)
            if isinstance(e, (int, float)) and abs(e) > MAX_CONST_EXPONENT:
                self.fail(f"power with the exponent {e:g} is too large (at most {MAX_CONST_EXPONENT} "
                          f"in magnitude)", node)
        if isinstance(node.op, (ast.Pow, ast.BitXor)) and _is_constant(node.left) and _is_constant(node.right):
            try:
                _const_value(node)
            except OverflowError:
                self.fail("constant power too large", node)
        self.count += 1
        if self.count > MAX_NODES:
            self.fail(f"formula too large (more than {MAX_NODES} syntax nodes)")

    def visit_UnaryOp(self, node):
        if not isinstance(node.op, _ALLOWED_UNARY):
            self.fail(f"operator {type(node.op).__name__} is not allowed", node)
        self.generic_visit(node)

    def visit_Compare(self, node):
        for op in node.ops:
            if not isinstance(op, _ALLOWED_CMP):
                self.fail(f"comparison {type(op).__name__} is not allowed", node)
        if len(node.ops) > 1:
            self.fail("chained comparisons (a < x < b) are ambiguous here; write (a < x) & (x < b)", node)
        self.generic_visit(node)

    def visit_BoolOp(self, node):
        self.fail("use & and | (or And(...), Or(...)) for conditions instead of 'and'/'or'", node)

    def visit_Tuple(self, node):
        self.generic_visit(node)

    def visit_Call(self, node):
        if not isinstance(node.func, ast.Name):
            if isinstance(node.func, ast.Attribute):
                self.fail("attribute access (obj.name) not allowed; call whitelisted functions by "
                          "their bare name", node)
            self.fail("only calls of whitelisted functions by their bare name are allowed", node)
        name = node.func.id
        if name.startswith("_") or "__" in name:
            self.fail(f"name {name!r} is not allowed (no private or dunder names)", node)
        if name not in self.callables:
            hint = _HINTS.get(name)
            self.fail(f"call of {name!r} is not allowed" + (f" ({hint})" if hint else
                      "; allowed functions: " + ", ".join(sorted(self.callables))), node)
        if node.keywords:
            self.fail(f"keyword arguments are not allowed (in the call of {name})", node)
        if name in _FACTORIAL_LIKE:
            for arg in node.args:
                inner = [n.func.id for n in ast.walk(arg) if isinstance(n, ast.Call)
                         and isinstance(n.func, ast.Name) and n.func.id in _FACTORIAL_LIKE]
                if inner and _is_constant(arg):   # gamma(gamma(20)) = gamma(19!): not bounded by 20
                    self.fail(f"{name}(...) of a constant containing {inner[0]}(...) would be "
                              f"astronomically long in exact arithmetic; use loggamma or a float", node)
                if _is_constant(arg) and _magnitude(arg) > MAX_EXACT_ARGUMENT:
                    self.fail(f"{name}(...) of a constant larger than {MAX_EXACT_ARGUMENT} would be "
                              f"astronomically long in exact arithmetic; use loggamma or a float", node)
        if name == "Derivative":
            for arg in node.args[1:]:
                # Derivative(f, (x, n)) and Derivative(f, x, n): every order bounded
                orders = arg.elts[1:] if isinstance(arg, ast.Tuple) else [] if isinstance(arg, ast.Name) else [arg]
                for o in orders:
                    if not _is_constant(o) or _magnitude(o) > MAX_DERIVATIVE_ORDER:
                        self.fail(f"derivative order must be a number <= {MAX_DERIVATIVE_ORDER}", node)
        self.count += 1
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                self.fail("*args are not allowed", arg)
            self.visit(arg)

    # -- everything else is refused -----------------------------------------
    def _refuse(self, node):
        what = {ast.Attribute: "attribute access", ast.Subscript: "subscripts",
                ast.Lambda: "lambda", ast.IfExp: "conditional expressions (use Piecewise)",
                ast.ListComp: "comprehensions", ast.GeneratorExp: "comprehensions",
                ast.DictComp: "comprehensions", ast.SetComp: "comprehensions",
                ast.List: "lists (use tuples)", ast.Dict: "dicts", ast.Set: "sets",
                ast.NamedExpr: "assignment expressions", ast.JoinedStr: "f-strings",
                ast.Starred: "starred expressions", ast.Slice: "slices",
                ast.Await: "await", ast.Yield: "yield", ast.YieldFrom: "yield"}.get(type(node))
        self.fail(f"{what or type(node).__name__} not allowed", node)

    visit_Attribute = visit_Subscript = visit_Lambda = visit_IfExp = _refuse
    visit_ListComp = visit_GeneratorExp = visit_DictComp = visit_SetComp = _refuse
    visit_List = visit_Dict = visit_Set = visit_NamedExpr = visit_JoinedStr = _refuse
    visit_Starred = visit_Slice = visit_Await = visit_Yield = visit_YieldFrom = _refuse
    visit_FormattedValue = _refuse


def _is_constant(node) -> bool:
    """No symbol in the subtree (calls of functions of constants count as constant)."""
    funcs = {id(n.func) for n in ast.walk(node) if isinstance(n, ast.Call)}
    return all(not isinstance(n, ast.Name) or id(n) in funcs for n in ast.walk(node))


def _magnitude(node) -> float:
    """|value| of a constant subtree (calls count as their largest argument,
    a bound for sqrt, roots and the like); inf when astronomically large."""
    try:
        return abs(_const_value(node))
    except (OverflowError, ValueError, TypeError):
        return math.inf


def _const_value(node):
    """Float value of a constant arithmetic subtree, raising OverflowError when
    it is astronomically large (so that SymPy is never asked to build it)."""
    if isinstance(node, ast.Constant):
        return node.value
    if isinstance(node, ast.UnaryOp):
        v = _const_value(node.operand)
        return -v if isinstance(node.op, ast.USub) else v
    if isinstance(node, ast.BinOp):
        lv, rv = _const_value(node.left), _const_value(node.right)
        lf, rf = float(lv), float(rv)
        if isinstance(node.op, (ast.Pow, ast.BitXor)):
            if abs(rf) > MAX_CONST_EXPONENT and abs(lf) not in (0.0, 1.0):
                raise OverflowError
            if lf != 0 and abs(rf * math.log10(abs(lf))) > 10000:
                raise OverflowError
            try:
                return lf ** rf if not (lf < 0 and rf != int(rf)) else abs(lf) ** rf
            except ZeroDivisionError:
                return math.inf
        if isinstance(node.op, ast.Add):
            return lf + rf
        if isinstance(node.op, ast.Sub):
            return lf - rf
        if isinstance(node.op, ast.Mult):
            return lf * rf
        if isinstance(node.op, ast.Div):
            return lf / rf if rf else math.inf
        return 0.0
    if isinstance(node, ast.Call):
        vals = [abs(float(_const_value(a_))) for a_ in node.args]
        return max(vals, default=0.0)
    if isinstance(node, ast.Tuple):
        return 0.0
    return 0.0


_BINOPS = {ast.Add: sp.Add, ast.Mult: sp.Mul}
_RELATIONS = {ast.Lt: sp.Lt, ast.LtE: sp.Le, ast.Gt: sp.Gt, ast.GtE: sp.Ge, ast.Eq: sp.Eq, ast.NotEq: sp.Ne}


class _Builder:
    """Builds the SymPy object of a *validated* syntax tree node by node: no
    text is ever compiled or evaluated.  Decimal literals are exact
    (``0.1`` is 1/10), ``^`` is a power, ``&``/``|``/``~`` are And/Or/Not;
    ``gamma(...)`` is Euler's Gamma function while the bare name ``gamma``
    is the work of adhesion."""

    def __init__(self, names, callables, source=""):
        self.names, self.callables, self.source = names, callables, source

    def build(self, node):
        if isinstance(node, ast.Constant):
            v = node.value
            if isinstance(v, bool):
                return sp.true if v else sp.false
            if isinstance(v, int):
                return sp.Integer(v)
            # the literal's own digits, exactly (a 31-digit decimal keeps all 31;
            # never read through a Python float)
            lit = ast.get_source_segment(self.source, node) if self.source else None
            return sp.Rational(lit.replace("_", "")) if lit else sp.Rational(repr(v))
        if isinstance(node, ast.Name):
            return {"True": sp.true, "False": sp.false}.get(node.id) or self.names[node.id]
        if isinstance(node, ast.Tuple):
            return tuple(self.build(e) for e in node.elts)
        if isinstance(node, ast.UnaryOp):
            v = self.build(node.operand)
            if isinstance(node.op, ast.USub):
                return -v
            if isinstance(node.op, ast.UAdd):
                return v
            return sp.Not(v)
        if isinstance(node, ast.Compare):
            return _RELATIONS[type(node.ops[0])](self.build(node.left), self.build(node.comparators[0]))
        if isinstance(node, ast.Call):
            fn = sp.gamma if node.func.id == "gamma" else self.callables[node.func.id]
            return fn(*[self.build(a_) for a_ in node.args])
        if isinstance(node, ast.BinOp):
            return self._binop(node)
        raise ClaimError(f"cannot build {type(node).__name__}")  # not reached after validation

    def _binop(self, node):
        # a chain a + b + c ... (left-nested) is built iteratively
        links, cur = [], node
        while isinstance(cur, ast.BinOp) and (not links or type(cur.op) is type(links[-1].op)):
            links.append(cur)
            cur = cur.left
        op = type(node.op)
        operands = [self.build(cur)] + [self.build(link.right) for link in reversed(links)]
        if op in _BINOPS:
            return _BINOPS[op](*operands)
        if op is ast.Sub:
            return sp.Add(operands[0], *[-v for v in operands[1:]])
        out = operands[0]
        for v in operands[1:]:
            if op is ast.Div:
                out = out / v
            elif op in (ast.Pow, ast.BitXor):
                out = out**v
            elif op is ast.BitAnd:
                out = sp.And(out, v)
            else:
                out = sp.Or(out, v)
        return out


def declare_symbols(names, where: str = "") -> dict:
    """Positive SymPy symbols for user-declared names (validated identifiers)."""
    out = {}
    for name in names or ():
        if not isinstance(name, str) or not name.isidentifier() or name.startswith("_"):
            raise ClaimError(f"{where_prefix(where)}symbol name {name!r} is not a plain identifier")
        if name in FUNCTIONS or name in CONSTANTS:
            raise ClaimError(f"{where_prefix(where)}symbol name {name!r} clashes with a function or constant")
        out[name] = SYMBOLS.get(name) or sp.Symbol(name, positive=True)
    return out


def parse_expr(text, *, symbols=None, definitions=None, placeholders=None, where: str = "",
               allow_relational: bool = False) -> sp.Expr:
    """Parse a formula string safely into a SymPy expression.

    Parameters
    ----------
    text : str
        The formula in SymPy (Python) syntax, e.g. ``"pi*E_star*a**2/(4*R)"``.
    symbols : iterable of str or dict, optional
        Extra symbol names the formula may use (created ``positive=True``), or
        a dict name -> Symbol.
    definitions : dict, optional
        Named sub-expressions (name -> SymPy expression) substituted for the name.
    placeholders : dict, optional
        Extra names (name -> SymPy object: a symbol, or an undefined Function
        for names used as calls) for functional claims.
    where : str
        Where the string comes from (file, claim, field), used in errors.
    allow_relational : bool
        Accept a relation (``"a < R"``) as the result (for assumptions).

    Raises
    ------
    ClaimError
        If the string is not valid syntax, uses a name or construct outside
        the whitelist, or is not an expression.

    Examples
    --------
    >>> parse_expr("pi*E_star*a**2/(4*R)")
    pi*E_star*a**2/(4*R)
    >>> parse_expr("(n-1)*sqrt(pi)*gamma(n/2 - 1/2)/(2*gamma(n/2))")
    sqrt(pi)*(n - 1)*gamma(n/2 - 1/2)/(2*gamma(n/2))
    >>> parse_expr("__import__('os')")
    Traceback (most recent call last):
    ...
    linecontact_sym.core.errors.ClaimError: name '__import__' is not allowed (no private or dunder names) (at column 1) in "__import__('os')"
    """
    if not isinstance(text, str):
        if isinstance(text, (int, float)) and not isinstance(text, bool):
            text = repr(text)
        else:
            raise ClaimError(f"{where_prefix(where)}expected a formula string, got {type(text).__name__}: {text!r}")
    if not text.strip():
        raise ClaimError(f"{where_prefix(where)}empty formula")
    if len(text) > MAX_LENGTH:
        raise ClaimError(f"{where_prefix(where)}formula longer than {MAX_LENGTH} characters")
    try:
        # "^" means power with the precedence of "**" (token level, like SymPy's convert_xor)
        source = text.strip().replace("^", "**")
        tree = ast.parse(source, mode="eval")
    except SyntaxError as exc:
        raise ClaimError(f"{where_prefix(where)}not a valid formula ({exc.msg}) in {text!r}") from None
    except (RecursionError, MemoryError, ValueError):
        raise ClaimError(f"{where_prefix(where)}formula nested too deeply: {text[:60]!r}...") from None

    sym_table = dict(SYMBOLS)
    if isinstance(symbols, dict):
        sym_table.update(symbols)
    else:
        sym_table.update(declare_symbols(symbols, where))
    defs = dict(definitions or {})
    ph = dict(placeholders or {})
    names = {**sym_table, **CONSTANTS, **defs}
    callables = dict(FUNCTIONS)
    for k, v in ph.items():
        if isinstance(v, sp.FunctionClass) or callable(v) and not isinstance(v, sp.Basic):
            callables[k] = v
        else:
            names[k] = v
    try:
        checker = _Validator(text, where, names, callables)
        checker.source = source
        checker.visit(tree)
    except RecursionError:
        raise ClaimError(f"{where_prefix(where)}formula nested too deeply: {text[:60]!r}...") from None

    local = dict(names)
    local.pop("True", None)
    local.pop("False", None)
    try:
        expr = _Builder(local, callables, source).build(tree.body)
    except ClaimError:
        raise
    except RecursionError:
        raise ClaimError(f"{where_prefix(where)}formula nested too deeply: {text[:60]!r}...") from None
    except Exception as exc:
        raise ClaimError(f"{where_prefix(where)}cannot build the formula {text!r}: {type(exc).__name__}: {exc}") from None
    if isinstance(expr, tuple):
        raise ClaimError(f"{where_prefix(where)}expected one expression, got a tuple: {text!r}")
    if not isinstance(expr, sp.Basic):
        expr = sp.sympify(expr, strict=True)  # safe: parser output, never a string
    is_relation = isinstance(expr, (sp.logic.boolalg.Boolean, sp.Rel)) and not isinstance(expr, sp.Expr)
    if is_relation and not allow_relational:
        raise ClaimError(f"{where_prefix(where)}expected an expression, got the relation {text!r}")
    if allow_relational and not is_relation:
        raise ClaimError(f"{where_prefix(where)}expected a relation such as 'a < R', got {text!r}")
    if expr.has(sp.zoo, sp.nan) and not expr.is_Relational:
        raise ClaimError(f"{where_prefix(where)}the formula {text!r} is undefined (division by zero?)")
    return expr



def to_sympy(value, where: str = "") -> sp.Basic:
    """A value given to the API as a SymPy object: strings go through the
    whitelisted :func:`parse_expr`, never through ``eval``; everything else
    through the strict :func:`linecontact_sym.core.conversion.to_basic`.  Use
    this instead of ``sympy.sympify``, which evaluates strings."""
    if isinstance(value, str):
        return parse_expr(value, where=where)
    if isinstance(value, float) and not math.isfinite(value):
        raise ClaimError(f"{where + ': ' if where else ''}{value} is not a finite number")
    try:
        return to_basic(value)
    except LineContactError as exc:
        raise ClaimError(f"{where + ': ' if where else ''}{exc}") from None


def user_value(value, where: str = ""):
    """A parameter value as a user gives it (mu, nu, gamma, a stick
    half-width): a float means its shortest decimal (0.3 -> 3/10), text goes
    through the whitelisted :func:`parse_expr`, anything else through
    :func:`to_sympy`'s strict conversion."""
    if isinstance(value, str):
        return to_sympy(value, where)
    try:                                # NaN and inf: DomainError
        return exact_number(value)      # the one converter, floats as their shortest decimal
    except DomainError:
        raise
    except LineContactError as exc:
        raise ClaimError(f"{where + ': ' if where else ''}{exc}") from None

