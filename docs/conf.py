"""Sphinx configuration of the linecontact_sym documentation.

Builds offline (no intersphinx, no downloads; MathJax is served from the
build's own ``_static``): ``python -m sphinx -b html docs docs/_build/html``.
The notebooks in ../notebooks are the tutorials: MyST-NB executes each at
build time and shows its outputs (formulas as LaTeX, tables, figures); the
executed notebooks are kept in a jupyter-cache (``docs/_build/.jupyter_cache``,
or the folder ``LINECONTACT_SYM_DOCS_CACHE`` names), so a rebuild of unchanged
notebooks executes nothing.  A cell that raises fails the build.  The gallery
(docs/gallery.py) is a page of the same kind, executed the same way.
"""
import os
import shutil
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))

project = "linecontact_sym"
author = "linecontact_sym authors"
# the version pyproject.toml holds (the one place of it; linecontact_sym.__version__ reads it so too)
from linecontact_sym.core.version import package_version  # noqa: E402

release = version = package_version()
extensions = ["sphinx.ext.autodoc", "sphinx.ext.autosummary", "sphinx.ext.napoleon", "sphinx.ext.mathjax",
              "myst_nb"]
try:
    # MathJax 3 shipped in a Python package and copied into the build's _static:
    # the pages render their formulas without a network (sphinx.ext.mathjax alone
    # loads MathJax from a CDN)
    import importlib.util
    if importlib.util.find_spec("sphinx-mathjax-offline") is not None:
        extensions.append("sphinx-mathjax-offline")
except (ImportError, ValueError):
    pass
# the API reference: one page per module of the package, generated from the docstrings at build time
autosummary_generate = True
# autosummary writes a page per module but never removes one: a renamed module
# (maugis_check.py -> maugis/check.py) left its old page behind, an import
# warning in every later build of that checkout; the folder is generated
# (git-ignored), so every build starts it afresh
shutil.rmtree(DOCS / "reference", ignore_errors=True)
autosummary_imported_members = False
myst_enable_extensions = ["dollarmath"]
exclude_patterns = ["_build", "gallery.py", "**.ipynb_checkpoints"]

# ---- the notebooks (MyST-NB): executed at build time, outputs cached (jupyter-cache)
nb_execution_mode = "cache"
nb_execution_cache_path = os.environ.get("LINECONTACT_SYM_DOCS_CACHE") or str(DOCS / "_build" / ".jupyter_cache")
nb_execution_raise_on_error = True      # a cell that raises fails the build
nb_execution_show_tb = True
nb_execution_timeout = 240              # seconds a cell
# the kernels import this tree's package (not another installed copy), and the
# notebooks take their quick path (LINECONTACT_SYM_NOTEBOOK_QUICK: the Popov
# reproduction checks the claims of a second or less; the full check is the CLI's paper job)
if os.environ.get("PYTHONPATH", "").split(os.pathsep)[0] != str(ROOT):
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), os.environ.get("PYTHONPATH")) if p)
os.environ.setdefault("LINECONTACT_SYM_NOTEBOOK_QUICK", "1")
templates_path = ["_templates"]
html_theme = "alabaster"
autodoc_member_order = "bysource"
autodoc_default_options = {}
# the package writes annotations, never "# type:" comments: autodoc need not read
# every function's source again (inspect + ast) to look for them (Sphinx >= 8.2;
# the same pages, 3 of the build's 22 CPU s)
autodoc_use_type_comments = False
suppress_warnings = ["myst.header", "autodoc.import_object"]
nitpicky = False


def _definitions_on_demand():
    """Sphinx's module analyser (``sphinx.pycode``) reads a module twice when
    first asked about it: an ast walk (the ``#:`` comments of attributes and
    the order of definitions, which autosummary and autodoc's 'bysource' use)
    and a token-by-token scan for the line ranges of definitions, which only
    ``find_tags`` (viewcode, literalinclude's ``:pyobject:``: neither is used
    here) reads.  The scan, a sixth of the build's CPU time, is done when
    ``find_tags`` asks for it: the same site.  Where Sphinx's analyser is not
    made as assumed, nothing is changed."""
    try:
        from sphinx.pycode import ModuleAnalyzer
        from sphinx.pycode.parser import Parser
    except ImportError:
        return
    if not (callable(getattr(Parser, "parse_comments", None)) and callable(getattr(Parser, "parse_definition", None))
            and callable(getattr(ModuleAnalyzer, "find_tags", None)) and callable(getattr(ModuleAnalyzer, "analyze", None))):
        return

    def parse(self):
        self.parse_comments()

    def find_tags(self):
        self.analyze()
        if not getattr(self, "_definitions_scanned", False):
            parser = Parser(self.code)
            parser.parse_definition()
            self.tags = parser.definitions
            self._definitions_scanned = True
        return self.tags
    Parser.parse = parse
    ModuleAnalyzer.find_tags = find_tags


def _copy_if_changed(src: Path, dst: Path) -> None:
    """Copy with the source's time stamp, and only when the contents differ:
    Sphinx rereads (and MyST-NB asks its cache about) only what changed."""
    if not dst.exists() or dst.read_bytes() != src.read_bytes():
        shutil.copy2(src, dst)


def _generate_pages(app):
    """docs/tutorials/: every notebook of notebooks/ (copied; git-ignored) and
    an index whose toctree globs them, so a new notebook needs no edit here;
    docs/gallery.md: the gallery page, a MyST notebook written from docs/gallery.py."""
    gen = DOCS / "tutorials"
    gen.mkdir(exist_ok=True)
    notebooks = sorted((ROOT / "notebooks").glob("*.ipynb"))
    for nb in notebooks:
        _copy_if_changed(nb, gen / nb.name)
    for old in gen.glob("*.ipynb"):         # a notebook removed from notebooks/
        if not (ROOT / "notebooks" / old.name).exists():
            old.unlink()
    for old in gen.glob("*.md"):            # pages of the former notebook-to-Markdown conversion
        if old.name != "index.md":
            old.unlink()
    index = "\n".join(["# Tutorials", "",
                       "The notebooks of `notebooks/`, executed when these pages were built: every output "
                       "below is the notebook's own (the quick path, `LINECONTACT_SYM_NOTEBOOK_QUICK=1`).",
                       "", "```{toctree}", ":maxdepth: 1", ":glob:", "", "*", "```", ""])
    if not (gen / "index.md").exists() or (gen / "index.md").read_text(encoding="utf-8") != index:
        (gen / "index.md").write_text(index, encoding="utf-8")
    sys.path.insert(0, str(DOCS))
    import gallery
    page = gallery.page()
    out = DOCS / "gallery.md"
    if not out.exists() or out.read_text(encoding="utf-8") != page:
        out.write_text(page, encoding="utf-8")


def _absolute_values(app, what, name, obj, options, lines):
    """Docstrings write |x| for the absolute value (and |Q| < mu P ...); reST
    would read a substitution: every | outside code (``...``, doctests,
    literal blocks after ::) is escaped."""
    literal = False
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        if literal and stripped and len(line) - len(stripped) <= literal_indent:
            literal = False
        if not literal and not stripped.startswith(">>>") and "|" in line:
            parts = line.split("``")
            lines[i] = "``".join(p if k % 2 else p.replace("|", "\\|") for k, p in enumerate(parts))
        if line.rstrip().endswith("::") and not literal:
            literal, literal_indent = True, len(line) - len(stripped)


class _PlainTextDocstrings:
    """A logging filter: the package's docstrings are plain text with formulas
    (tables of ``name  meaning``, |x|, int_0^a ...), not reST; where docutils
    reads one as markup it cannot parse, the generated page shows that text
    as it is.  Those docutils messages from docstrings (and the generated
    module pages) are not build errors; every other warning is."""

    def filter(self, record):
        where = str(getattr(record, "location", "") or "")
        text = record.getMessage()
        from_docstring = "docstring of" in where or "/reference/" in where or "<autosummary>" in where
        return not (from_docstring and record.levelname in ("WARNING", "ERROR") and (
            "[docutils]" in text or getattr(record, "type", "") == "docutils" or "docutils" in where
            or any(m in text for m in _DOCUTILS_MESSAGES)))


#: docutils' messages about plain text read as reST markup
_DOCUTILS_MESSAGES = ("Definition list ends without a blank line", "Unexpected indentation",
                      "Block quote ends without a blank line", "Inline literal start-string",
                      "Unknown target name", "Undefined substitution", "Inline emphasis start-string",
                      "Inline strong start-string", "Inline interpreted text")


def _relative_modules(app, what, name, obj, options, lines):
    """``:mod:`.sibling``` in a docstring means the module next to the one
    documented (Python's reading); Sphinx would search every module of that
    name.  Rewritten to the absolute name where that module exists."""
    import importlib.util
    import re
    mod = name if what == "module" else getattr(obj, "__module__", "") or ""
    is_package = what == "module" and hasattr(obj, "__path__")
    package = mod if is_package or "." not in mod else mod.rsplit(".", 1)[0]
    if not package:
        return

    def absolute(m):
        target = f"{package}.{m.group(1)}"
        try:
            found = importlib.util.find_spec(target) is not None
        except (ImportError, ValueError):
            found = False
        return f":mod:`~{target}`" if found else m.group(0)
    for i, line in enumerate(lines):
        if ":mod:`." in line:
            lines[i] = re.sub(r":mod:`\.([A-Za-z_][A-Za-z0-9_.]*)`", absolute, line)


def setup(app):
    _definitions_on_demand()
    app.connect("autodoc-process-docstring", _relative_modules)
    import logging
    logging.getLogger("sphinx").addFilter(_PlainTextDocstrings())
    for h in logging.getLogger("sphinx").handlers:
        h.addFilter(_PlainTextDocstrings())
    app.connect("builder-inited", _generate_pages)
    app.connect("autodoc-process-docstring", _absolute_values)
