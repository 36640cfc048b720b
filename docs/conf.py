"""Sphinx configuration of the linecontact_sym documentation.

Builds offline (no intersphinx, no downloads): ``python -m sphinx -b html docs docs/_build``.
The notebooks in ../notebooks become the tutorials: each is converted here,
at build time, to a Markdown page (its text, its code and the text and image
outputs stored in it) with nbformat; nothing is executed.
"""
import base64
import os
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))

project = "linecontact_sym"
author = "linecontact_sym authors"
release = "0.1.0"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax", "myst_parser"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_enable_extensions = ["dollarmath"]
exclude_patterns = ["_build", "report_page.png"]
html_theme = "alabaster"
autodoc_member_order = "bysource"
autodoc_default_options = {}
suppress_warnings = ["myst.header", "autodoc.import_object"]
nitpicky = False


def _notebook_to_markdown(src: Path, out: Path):
    import nbformat
    nb = nbformat.read(src, as_version=4)
    img_dir = out.parent / "img"
    img_dir.mkdir(parents=True, exist_ok=True)
    lines = [f"<!-- generated from notebooks/{src.name} by docs/conf.py; edit the notebook -->", ""]
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "markdown":
            lines += [cell.source, ""]
        elif cell.cell_type == "code":
            lines += ["```python", cell.source, "```", ""]
            for j, o in enumerate(cell.get("outputs", [])):
                data = o.get("data", {})
                if "image/png" in data:
                    name = f"{src.stem}-{i}-{j}.png"
                    (img_dir / name).write_bytes(base64.b64decode(data["image/png"]))
                    lines += [f"![output](img/{name})", ""]
                elif o.get("output_type") == "stream" or "text/plain" in data:
                    text = o.get("text") or data.get("text/plain", "")
                    lines += ["```text", "".join(text).rstrip(), "```", ""]
    out.write_text("\n".join(lines), encoding="utf-8")


def _generate_tutorials(app):
    gen = DOCS / "tutorials"
    gen.mkdir(exist_ok=True)
    names = []
    for nb in sorted((ROOT / "notebooks").glob("*.ipynb")):
        _notebook_to_markdown(nb, gen / f"{nb.stem}.md")
        names.append(nb.stem)
    toc = ["# Tutorials", "", "The notebooks of `notebooks/`, as stored (run them with Jupyter to see every output).",
           "", "```{toctree}", ":maxdepth: 1", ""] + names + ["```", ""]
    (gen / "index.md").write_text("\n".join(toc), encoding="utf-8")


def _absolute_values(app, what, name, obj, options, lines):
    """Docstrings write |x| for the absolute value; reST would read a substitution."""
    for i, line in enumerate(lines):
        if not line.lstrip().startswith(">>>") and not line.startswith("    "):
            lines[i] = line.replace("|x|", "\\|x\\|")


def setup(app):
    app.connect("builder-inited", _generate_tutorials)
    app.connect("autodoc-process-docstring", _absolute_values)
