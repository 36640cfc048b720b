"""The package's shape: imports flow one way through the layers, and no
module or class grows past the size one person can hold in their head."""
import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "linecontact_sym"

#: the layers, bottom to top; a module may import its own layer and the ones below
LAYERS = ["core", "parsing", "method", "numeric", "views", "contacts", "claims", "cli"]
LAYER_OF = {name: i for i, name in enumerate(LAYERS)}
LAYER_OF["__main__"] = LAYER_OF["cli"]

MAX_MODULE_LINES = 600
MAX_CLASS_LINES = 300


def _modules():
    for path in sorted(PKG.rglob("*.py")):
        rel = path.relative_to(PKG)
        yield path, rel


def _top(rel: Path) -> str:
    return rel.parts[0][:-3] if len(rel.parts) == 1 else rel.parts[0]


def _imports(path: Path, rel: Path):
    """(line, top-level package part) of every import of linecontact_sym in the
    file, function-level imports included."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    pkg_parts = ["linecontact_sym", *rel.parts[:-1]]
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = pkg_parts[:len(pkg_parts) - node.level + 1]
                full = base + (node.module.split(".") if node.module else [])
            else:
                full = node.module.split(".") if node.module else []
            if not full or full[0] != "linecontact_sym":
                continue
            if len(full) == 1:  # from linecontact_sym import x / from . import x
                for alias in node.names:
                    yield node.lineno, alias.name
            else:
                yield node.lineno, full[1]
        elif isinstance(node, ast.Import):
            for alias in node.names:
                parts = alias.name.split(".")
                if parts[0] == "linecontact_sym" and len(parts) > 1:
                    yield node.lineno, parts[1]


def test_every_module_belongs_to_a_layer():
    for path, rel in _modules():
        top = _top(rel)
        assert top == "__init__" or top in LAYER_OF, f"{rel} is in no layer of {LAYERS}"


def test_imports_run_down_the_layers():
    upward = []
    for path, rel in _modules():
        top = _top(rel)
        if top == "__init__":
            continue  # the package's front door re-exports from every layer
        mine = LAYER_OF[top]
        for line, target in _imports(path, rel):
            if target == "__init__" or target not in LAYER_OF:
                continue
            if LAYER_OF[target] > mine:
                upward.append(f"{rel}:{line} imports {target} (layer {LAYER_OF[target]} > {mine})")
    assert not upward, "imports against the flow:\n" + "\n".join(upward)


def test_the_layer_check_sees_an_upward_import(tmp_path):
    """The check above can fail: an upward import in a synthetic module is found."""
    mod = PKG / "method" / "profile.py"
    fake = tmp_path / "method" / "fake.py"
    fake.parent.mkdir()
    fake.write_text("from ..contacts.frictionless import LineContact\n")
    found = list(_imports(fake, Path("method/fake.py")))
    assert found == [(1, "contacts")] and LAYER_OF["contacts"] > LAYER_OF["method"]
    assert mod.exists()


@pytest.mark.parametrize("path,rel", list(_modules()), ids=lambda v: str(v) if isinstance(v, Path) else "")
def test_module_and_class_sizes(path, rel):
    text = path.read_text(encoding="utf-8")
    n = text.count("\n")
    assert n <= MAX_MODULE_LINES, f"{rel} has {n} lines (at most {MAX_MODULE_LINES})"
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.ClassDef):
            size = node.end_lineno - node.lineno + 1
            assert size <= MAX_CLASS_LINES, f"{rel}: class {node.name} has {size} lines"
