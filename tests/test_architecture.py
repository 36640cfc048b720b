"""The package's shape, checked on its source (no import is executed):

* imports flow one way through the layers
  (core < parsing < method < numeric < views < contacts < claims < cli);
* no import cycle between modules, function-level imports included (a cycle
  hidden in a function body is still a cycle: the two modules cannot be
  understood, tested or moved apart);
* no module imports another module's private ``_name`` (a name shared
  between modules is public; otherwise the logic belongs where it lives);
* every subpackage of ``contacts/`` says in its docstring what physics it
  holds and which equations of which paper.

Each check is a function of the package directory, so that the tests at the
end run it on a synthetic package with a planted defect and see it fail.
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "linecontact_sym"

#: the layers, bottom to top; a module may import its own layer and the ones below
LAYERS = ["core", "parsing", "method", "numeric", "views", "contacts", "claims", "cli"]
LAYER_OF = {name: i for i, name in enumerate(LAYERS)}
LAYER_OF["__main__"] = LAYER_OF["cli"]


# ---------------------------------------------------------------- the import graph
def modules(root: Path) -> dict:
    """dotted module name -> path, for every .py file under the package ``root``
    (a package is named by its directory, its ``__init__`` by the package's name)."""
    out = {}
    for path in sorted(root.rglob("*.py")):
        parts = [root.name, *path.relative_to(root).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def imports(name: str, path: Path, mods: dict):
    """(line, imported module, imported names, function-level) for every import
    of the package in the module ``name`` (function-level imports included).
    ``from pkg import sub`` where ``sub`` is a module is an import of ``pkg.sub``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    is_pkg = path.name == "__init__.py"
    here = name.split(".") if is_pkg else name.split(".")[:-1]
    top = name.split(".")[0]
    funcs = [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]
    inner = {id(n) for f in funcs for n in ast.walk(f) if n is not f}
    for node in ast.walk(tree):
        local = id(node) in inner
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[:len(here) - node.level + 1]
                full = base + (node.module.split(".") if node.module else [])
            else:
                full = node.module.split(".") if node.module else []
            if not full or full[0] != top:
                continue
            target = ".".join(full)
            plain = []
            for alias in node.names:
                sub = f"{target}.{alias.name}"
                if sub in mods:
                    yield node.lineno, sub, (), local
                else:
                    plain.append(alias.name)
            if plain:
                yield node.lineno, target, tuple(plain), local
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == top:
                    yield node.lineno, alias.name, (), local


def graph(root: Path) -> dict:
    """module -> {imported module: first line}, every import of the package."""
    mods = modules(root)
    out = {}
    for name, path in mods.items():
        edges = out.setdefault(name, {})
        for line, target, _, _ in imports(name, path, mods):
            if target in mods and target != name:
                edges.setdefault(target, line)
    return out


# ---------------------------------------------------------------- the checks
def upward_imports(root: Path) -> list:
    """Imports against the layers, as 'module:line imports target'."""
    bad = []
    g = graph(root)
    for name, edges in g.items():
        parts = name.split(".")
        if len(parts) == 1:
            continue   # the package's front door re-exports from every layer
        mine = LAYER_OF.get(parts[1])
        for target, line in edges.items():
            t = target.split(".")
            if len(t) > 1 and mine is not None and LAYER_OF.get(t[1], -1) > mine:
                bad.append(f"{name}:{line} imports {target} (layer {t[1]} above {parts[1]})")
    return bad


def import_cycles(root: Path) -> list:
    """Every cycle of the module import graph (function-level imports
    included; a package's ``__init__`` re-exporting its own modules is an
    edge like any other, an implicit parent-package import is none), as
    lists of modules: the strongly connected components with more than one
    module (Tarjan)."""
    g = graph(root)
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in g.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))
    for v in sorted(g):
        if v not in index:
            visit(v)
    return out


def private_imports(root: Path) -> list:
    """Imports of another module's private name (``from m import _x``, or
    ``m._x`` on an imported module ``m``), as 'module:line name'."""
    mods = modules(root)
    bad = []
    for name, path in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        aliases = {}
        for line, target, names, _ in imports(name, path, mods):
            for n in names:
                if n.startswith("_") and not n.startswith("__"):
                    bad.append(f"{name}:{line} imports {target}.{n}")
        for node in ast.walk(tree):   # modules bound to a local name
            if isinstance(node, ast.ImportFrom):
                for alias in node.names:
                    aliases[alias.asname or alias.name] = alias.name
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.asname:
                        aliases[alias.asname] = alias.name
        mod_names = {local for local, orig in aliases.items()
                     if any(m.endswith("." + orig) or m == orig for m in mods)}
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                    and node.value.id in mod_names and node.attr.startswith("_") \
                    and not node.attr.startswith("__"):
                bad.append(f"{name}:{node.lineno} uses {node.value.id}.{node.attr}")
    return bad


#: a docstring that cites equations (Eq./Eqs.) of a paper (author, year)
_CITES = re.compile(r"Eqs?\.\s*\(?\d", re.S)
_PAPER = re.compile(r"\b(1[89]|20)\d\d\b")


def undocumented_subpackages(root: Path) -> list:
    """Subpackages of ``contacts`` whose ``__init__`` docstring does not say
    what it holds and cite equations of a paper (author and year)."""
    bad = []
    for init in sorted((root / "contacts").glob("*/__init__.py")):
        doc = ast.get_docstring(ast.parse(init.read_text(encoding="utf-8"))) or ""
        if len(doc.split()) < 15 or not _CITES.search(doc) or not _PAPER.search(doc):
            bad.append(f"contacts/{init.parent.name}: docstring missing, too short or without "
                       f"the paper and its equations")
    return bad


# ---------------------------------------------------------------- the package
def test_every_module_belongs_to_a_layer():
    for name in modules(PKG):
        parts = name.split(".")
        assert len(parts) == 1 or parts[1] in LAYER_OF, f"{name} is in no layer of {LAYERS}"


def test_imports_run_down_the_layers():
    bad = upward_imports(PKG)
    assert not bad, "imports against the flow:\n" + "\n".join(bad)


def test_no_import_cycle_even_through_function_level_imports():
    cycles = import_cycles(PKG)
    assert not cycles, "import cycles:\n" + "\n".join(" <-> ".join(c) for c in cycles)


def test_no_import_of_another_modules_private_name():
    bad = private_imports(PKG)
    assert not bad, "private names used across modules:\n" + "\n".join(bad)


def test_every_contacts_subpackage_is_documented():
    subs = [p.parent.name for p in (PKG / "contacts").glob("*/__init__.py")]
    assert {"normal", "adhesion", "tangential", "stresses"} <= set(subs)
    bad = undocumented_subpackages(PKG)
    assert not bad, "\n".join(bad)


# ---------------------------------------------------------------- the checks can fail
def _package(tmp_path, files: dict) -> Path:
    root = tmp_path / "linecontact_sym"
    for rel, text in {"__init__.py": "", "core/__init__.py": "", "method/__init__.py": "",
                      "contacts/__init__.py": "", **files}.items():
        p = root / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    return root


def test_the_checks_see_an_upward_import(tmp_path):
    root = _package(tmp_path, {"method/a.py": "def f():\n    from ..contacts.b import g\n",
                               "contacts/b.py": "def g(): pass\n"})
    assert upward_imports(root) == ["linecontact_sym.method.a:2 imports linecontact_sym.contacts.b "
                                    "(layer contacts above method)"]


def test_the_checks_see_a_cycle_hidden_in_a_function(tmp_path):
    root = _package(tmp_path, {"core/a.py": "from .b import g\n",
                               "core/b.py": "def g():\n    from . import a\n    return a\n",
                               "core/c.py": "from .a import g\n"})
    assert import_cycles(root) == [["linecontact_sym.core.a", "linecontact_sym.core.b"]]
    root = _package(tmp_path / "x", {"core/a.py": "from . import b\n", "core/b.py": "x = 1\n"})
    assert import_cycles(root) == []


def test_the_checks_see_a_private_import(tmp_path):
    root = _package(tmp_path, {"core/a.py": "_hidden = 1\n__version__ = 2\n",
                               "core/b.py": "from .a import _hidden, __version__\n",
                               "core/c.py": "from . import a\n\ndef f():\n    return a._hidden\n"})
    assert private_imports(root) == ["linecontact_sym.core.b:1 imports linecontact_sym.core.a._hidden",
                                     "linecontact_sym.core.c:4 uses a._hidden"]


def test_the_checks_see_an_undocumented_subpackage(tmp_path):
    root = _package(tmp_path, {"contacts/good/__init__.py": '"""The frictionless line contact of Popov (2017), '
                                                             'Eqs. (9)-(12): force law, pressure, gap, the '
                                                             'inverse map and the admissible range."""\n',
                               "contacts/bare/__init__.py": '"""Things."""\n'})
    assert undocumented_subpackages(root) == ["contacts/bare: docstring missing, too short or without the paper "
                                              "and its equations"]


@pytest.mark.parametrize("check", [upward_imports, import_cycles, private_imports, undocumented_subpackages])
def test_the_checks_pass_on_an_empty_package(tmp_path, check):
    assert check(_package(tmp_path, {})) == []
