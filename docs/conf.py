"""Sphinx configuration of the linecontact_sym documentation.

Builds offline (no intersphinx, no downloads): ``python -m sphinx -b html docs docs/_build``.
The notebooks in ../notebooks become the tutorials: each is converted here,
at build time, to a Markdown page (its text, its code and the text and image
outputs stored in it) with nbformat; nothing is executed.
"""
import base64
import os
import shutil
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))

project = "linecontact_sym"
author = "linecontact_sym authors"
release = "0.1.0"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.autosummary", "sphinx.ext.napoleon", "sphinx.ext.mathjax",
              "myst_parser"]
# the API reference: one page per module of the package, generated from the docstrings at build time
autosummary_generate = True
# autosummary writes a page per module but never removes one: a renamed module
# (maugis_check.py -> maugis/check.py) left its old page behind, an import
# warning in every later build of that checkout; the folder is generated
# (git-ignored), so every build starts it afresh
shutil.rmtree(DOCS / "reference", ignore_errors=True)
autosummary_imported_members = False
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_enable_extensions = ["dollarmath"]
exclude_patterns = ["_build", "gallery.py"]
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


def _notebook_to_markdown(src: Path, out: Path) -> list:
    """Write the notebook as a Markdown page; return its figures as
    ``(image path relative to docs/, caption)``: the caption is the first
    sentence of the Markdown cell before the figure's code cell."""
    import nbformat
    nb = nbformat.read(src, as_version=4)
    img_dir = out.parent / "img"
    img_dir.mkdir(parents=True, exist_ok=True)
    lines = [f"<!-- generated from notebooks/{src.name} by docs/conf.py; edit the notebook -->", ""]
    figures, said = [], ""
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "markdown":
            lines += [cell.source, ""]
            said = _first_sentence(cell.source)
        elif cell.cell_type == "code":
            lines += ["```python", cell.source, "```", ""]
            for j, o in enumerate(cell.get("outputs", [])):
                data = o.get("data", {})
                if "image/png" in data:
                    name = f"{src.stem}-{i}-{j}.png"
                    (img_dir / name).write_bytes(base64.b64decode(data["image/png"]))
                    lines += [f"![output](img/{name})", ""]
                    figures.append((f"tutorials/img/{name}", said))
                elif o.get("output_type") == "stream" or "text/plain" in data:
                    text = o.get("text") or data.get("text/plain", "")
                    lines += ["```text", "".join(text).rstrip(), "```", ""]
    out.write_text("\n".join(lines), encoding="utf-8")
    return figures


def _first_sentence(md: str) -> str:
    text = " ".join(ln.strip().lstrip("#").strip() for ln in md.splitlines() if ln.strip())
    for stop in (". ", ": "):
        if stop in text:
            text = text[:text.index(stop) + 1]
    return text[:160]


def _generate_tutorials(app):
    gen = DOCS / "tutorials"
    gen.mkdir(exist_ok=True)
    names, figures = [], []
    for nb in sorted((ROOT / "notebooks").glob("*.ipynb")):
        figures += [(path, cap, nb.stem) for path, cap in _notebook_to_markdown(nb, gen / f"{nb.stem}.md")]
        names.append(nb.stem)
    toc = ["# Tutorials", "", "The notebooks of `notebooks/`, as stored (run them with Jupyter to see every output).",
           "", "```{toctree}", ":maxdepth: 1", ""] + names + ["```", ""]
    (gen / "index.md").write_text("\n".join(toc), encoding="utf-8")
    _generate_gallery(figures)


def _generate_gallery(figures):
    """docs/gallery.md: every figure of the notebooks (as stored) and of the
    documentation pages, each with its caption and where it comes from."""
    out = ["<!-- generated by docs/conf.py -->", "# Gallery", "",
           "The figures the package draws, each with the code that draws it (``python docs/gallery.py`` "
           "draws them again), the figures stored in the tutorials' outputs, and those of these pages.", ""]
    for path, cap, stem in figures:
        out += [f"## {stem.replace('_', ' ')}: {cap}" if cap else f"## {stem.replace('_', ' ')}", "",
                f"![{cap or stem}]({path})", "", f"From the tutorial [{stem}](tutorials/{stem}.md).", ""]
    sys.path.insert(0, str(DOCS))
    import gallery                      # the captions and code only: nothing is drawn here
    for stem, cap, code in gallery.entries():
        if (DOCS / "gallery" / f"{stem}.png").exists():
            out += [f"## {cap.split(': ')[0].split(' (')[0]}", "", f"![{stem}](gallery/{stem}.png)", "",
                    cap, "", "```python", "import linecontact_sym as lcs", code, "```", ""]
    for png in sorted(DOCS.glob("*.png")):
        # the pages that show it (not this gallery's own page: its copy from an earlier build
        # named every figure, so a second build said "Shown in gallery", a first did not)
        used = [md.stem for md in sorted(DOCS.glob("*.md"))
                if md.name != "gallery.md" and png.name in md.read_text(encoding="utf-8")]
        out += [f"## {png.stem.replace('_', ' ')}", "", f"![{png.stem}]({png.name})", ""]
        if used:
            out += ["Shown in " + ", ".join(f"[{u}]({u}.md)" for u in used) + ".", ""]
    (DOCS / "gallery.md").write_text("\n".join(out), encoding="utf-8")


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
    app.connect("builder-inited", _generate_tutorials)
    app.connect("autodoc-process-docstring", _absolute_values)
