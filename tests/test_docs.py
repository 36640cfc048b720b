"""The documentation agrees with the tool: the claims-file page names every
field the parser accepts, the CLI page every exit status, and the Sphinx site
builds offline without warnings (where Sphinx is installed: the [docs] extra)."""
import subprocess
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


def test_sphinx_site_builds_offline(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-E", "-b", "html", str(DOCS), str(tmp_path)],
                          capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert proc.returncode == 0, proc.stderr[-3000:]
    problems = [ln for ln in proc.stderr.splitlines() if "WARNING" in ln or "ERROR" in ln]
    assert not problems, "\n".join(problems[:20])
    for page in ("index", "conventions", "cli", "claims-format", "outputs", "api", "tutorials/quickstart"):
        assert (tmp_path / f"{page}.html").exists(), page
    api = (tmp_path / "api.html").read_text(encoding="utf-8")
    assert "parabola" in api and "check_paper" in api and "plot_contact" in api
    # issue 23: every module has a page generated from its docstrings
    import pkgutil
    import linecontact_sym
    modules = [m.name for m in pkgutil.walk_packages(linecontact_sym.__path__, "linecontact_sym.")
               if not m.name.endswith("__main__")]
    missing = [m for m in modules if not (tmp_path / "reference" / f"{m}.html").exists()]
    assert not missing, missing
    units = (tmp_path / "reference" / "linecontact_sym.core.units.html").read_text(encoding="utf-8")
    assert "split_units" in units and "dimension" in units
    # every notebook is a tutorial page; the gallery shows every figure of docs/gallery.py with its code
    for nb in (ROOT / "notebooks").glob("*.ipynb"):
        assert (tmp_path / "tutorials" / f"{nb.stem}.html").exists(), nb.stem
    gallery = (tmp_path / "gallery.html").read_text(encoding="utf-8")
    pngs = sorted((DOCS / "gallery").glob("*.png"))
    assert len(pngs) >= 6
    for png in pngs:
        assert f"_images/{png.name}" in gallery and (tmp_path / "_images" / png.name).exists(), png.name
    import html
    import re
    code = html.unescape(re.sub(r"<[^>]+>", "", gallery))   # the highlighted code as text (Pygments' markup varies)
    assert 'plot("pressure"' in code
