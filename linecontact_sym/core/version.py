"""The package's version: pyproject.toml holds it (the one place); this reads it.

In a source tree (a checkout, or an editable install of one) the
``pyproject.toml`` beside the package is read: an editable install's
metadata keeps the version it was installed with, however the file moved on
since.  Elsewhere (an installed wheel) the installed distribution's metadata
(:mod:`importlib.metadata`).  ``linecontact_sym.__version__`` is this value,
read on first use; the CHANGELOG's newest heading names it (a test checks)."""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

DISTRIBUTION = "linecontact_sym"


@lru_cache(maxsize=1)
def package_version() -> str:
    pyproject = Path(__file__).resolve().parents[2] / "pyproject.toml"
    if pyproject.is_file():
        try:
            import tomllib
        except ImportError:             # Python 3.10 (tomli: a dependency there)
            import tomli as tomllib
        try:
            project = tomllib.loads(pyproject.read_text(encoding="utf-8")).get("project", {})
        except (OSError, ValueError):
            project = {}
        if project.get("name") == DISTRIBUTION and project.get("version"):
            return str(project["version"])
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version(DISTRIBUTION)
    except PackageNotFoundError:        # neither installed nor a source tree (a copied folder)
        return "0+unknown"
