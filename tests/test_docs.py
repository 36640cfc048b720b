"""The documentation agrees with the tool: the claims-file page names every
field the parser accepts, the CLI page every exit status, and the Sphinx site
builds offline without warnings (where Sphinx and MyST-NB are installed: the
[docs] extra), executing every notebook once (tests/docs_site.py), and shows
their outputs."""
import re
import sys
from pathlib import Path

import pytest

from linecontact_sym.claims import spec
from linecontact_sym.claims.results import EXIT_CODES

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def test_claims_format_page_names_every_field_and_quantity():
    text = (DOCS / "claims-format.md").read_text(encoding="utf-8")
    for key in spec._TOP_KEYS | spec._CLAIM_KEYS | spec._FIGURE_KEYS | spec._CURVE_KEYS:
        if key in ("source", "description"):        # internal / legacy alias
            continue
        assert f"{key} =" in text or f"[[{key}]]" in text or f"[{key}]" in text or f".{key}]]" in text, key
    for q in spec.QUANTITIES:
        assert f"`{q}`" in text, q


def test_cli_page_and_readme_state_every_exit_status():
    for page in (DOCS / "cli.md", ROOT / "README.md"):
        text = page.read_text(encoding="utf-8")
        for code in EXIT_CODES:
            assert f"| {code} |" in text, (page.name, code)


def test_catalogue_constructors_have_docstrings():
    import linecontact_sym as lcs
    for f in (lcs.parabola, lcs.power_law, lcs.wedge, lcs.worn_cylinder, lcs.exact_cylinder):
        assert f.__doc__ and "Eq" in f.__doc__ and ">>>" in f.__doc__, f.__name__


@pytest.mark.xdist_group("docs")
def test_sphinx_site_builds_offline(docs_site):
    out, proc = docs_site
    html_dir = out / "html"
    problems = [ln for ln in proc.stderr.splitlines() if "WARNING" in ln or "ERROR" in ln]
    problems = [ln for ln in problems if "Kernel is running over TCP" not in ln]   # ipykernel's, not the build's
    assert not problems, "\n".join(problems[:20])
    for page in ("index", "conventions", "cli", "claims-format", "outputs", "api", "tutorials/quickstart"):
        assert (html_dir / f"{page}.html").exists(), page
    api = (html_dir / "api.html").read_text(encoding="utf-8")
    assert "parabola" in api and "check_paper" in api and "plot_contact" in api
    # issue 23: every module has a page generated from its docstrings
    import pkgutil
    import linecontact_sym
    modules = [m.name for m in pkgutil.walk_packages(linecontact_sym.__path__, "linecontact_sym.")
               if not m.name.endswith("__main__")]
    missing = [m for m in modules if not (html_dir / "reference" / f"{m}.html").exists()]
    assert not missing, missing
    units = (html_dir / "reference" / "linecontact_sym.core.units.html").read_text(encoding="utf-8")
    assert "split_units" in units and "dimension" in units
    # every notebook of notebooks/ is a tutorial page (found by the toctree's glob)
    for nb in (ROOT / "notebooks").glob("*.ipynb"):
        assert (html_dir / "tutorials" / f"{nb.stem}.html").exists(), nb.stem
    # offline: MathJax is the build's own copy, no page loads a script from the network
    for page in html_dir.rglob("*.html"):
        text = page.read_text(encoding="utf-8")
        assert not re.search(r"<script[^>]+src=\"(https?:)?//", text), page.name
    assert (html_dir / "_static" / "mathjax" / "tex-chtml.js").exists()


def _outputs(page: str) -> list:
    """The HTML of each cell output of a built notebook page."""
    return re.findall(r'<div class="cell_output docutils container">(.*?)</div>\s*</div>\s*</div>', page, re.S)


@pytest.mark.xdist_group("docs")
def test_a_tutorial_shows_its_formulas_and_figures(docs_site):
    """Issue 43: the tutorial of adhesion shows the outputs of its cells: the
    derived force law as a formula for MathJax (SymPy's LaTeX in \\[ \\]) and
    the force-law figure as an image the build wrote."""
    out, _ = docs_site
    page = (out / "html" / "tutorials" / "adhesion.html").read_text(encoding="utf-8")
    outputs = _outputs(page)
    formulas = [o for o in outputs if "math notranslate" in o]
    assert formulas and any("\\sqrt" in f and "\\gamma" in f and "E^{*}" in f for f in formulas), outputs[:3]
    assert '<script' in page and "_static/mathjax/tex-chtml.js" in page
    images = [src for o in outputs for src in re.findall(r'<img[^>]+src="([^"]+)"', o)]
    assert images
    for src in images:
        png = (out / "html" / "tutorials" / src).resolve()
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", src
    assert "&lt;Figure size" not in page


@pytest.mark.xdist_group("docs")
def test_a_rebuild_executes_nothing(docs_site):
    """Every executed notebook is in the build's jupyter-cache, found by the
    match MyST-NB makes before it executes (a rebuild without changes runs no kernel)."""
    from jupyter_cache import get_cache
    import nbformat
    out, _ = docs_site
    cache = get_cache(str(out / "jupyter_cache"))
    pages = sorted((DOCS / "tutorials").glob("*.ipynb")) + [DOCS / "gallery.md"]
    assert len(cache.list_cache_records()) == len(pages)
    for nb in (ROOT / "notebooks").glob("*.ipynb"):
        assert cache.match_cache_notebook(nbformat.read(nb, as_version=4)) is not None, nb.name


@pytest.mark.xdist_group("docs")
def test_gallery_draws_every_entry_with_its_code(docs_site):
    """One figure per entry of docs/gallery.py, drawn by the build (no stored
    image), each under its heading and beside the code that draws it."""
    sys.path.insert(0, str(DOCS))
    import gallery
    entries = gallery.entries()
    assert len(entries) >= 6
    assert not list(DOCS.glob("gallery/*.png"))
    out, _ = docs_site
    page = (out / "html" / "gallery.html").read_text(encoding="utf-8")
    sections = re.split(r'<section id="', page)[1:]
    import html
    for name, heading, caption, code in entries:
        section = next((s for s in sections if re.search(rf"<h2>{re.escape(html.escape(heading))}<", s)), None)
        assert section is not None, heading
        images = re.findall(r'<img[^>]+src="([^"]+)"', section)
        assert len(images) == 1, (name, images)
        assert (out / "html" / images[0]).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        text = html.unescape(re.sub(r"<[^>]+>", "", section))   # the highlighted code as text
        assert code.splitlines()[-1] in text, name
