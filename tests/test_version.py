"""One version, in pyproject.toml: the package, the CLI and the CHANGELOG's
newest heading say the same."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _pyproject_version() -> str:
    try:
        import tomllib
    except ImportError:
        import tomli as tomllib
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]


def test_package_version_is_pyprojects():
    import linecontact_sym
    assert linecontact_sym.__version__ == _pyproject_version()
    assert re.fullmatch(r"\d+\.\d+\.\d+", linecontact_sym.__version__)


def test_changelog_newest_heading_is_the_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    versions = re.findall(r"^## (\d+\.\d+\.\d+)\b", text, re.M)
    assert versions, "no release heading '## X.Y.Z' in CHANGELOG.md"
    assert versions[0] == _pyproject_version(), (versions[0], _pyproject_version())
    # newest first, no release twice
    key = [tuple(int(p) for p in v.split(".")) for v in versions]
    assert key == sorted(set(key), reverse=True), versions


def test_installed_metadata_is_read_outside_a_source_tree(tmp_path, monkeypatch):
    """A copy of the package without pyproject.toml beside it (an installed
    wheel) reads importlib.metadata; without metadata either, '0+unknown'."""
    from linecontact_sym.core import version
    import importlib.metadata
    fake = tmp_path / "site" / "linecontact_sym" / "core" / "version.py"
    fake.parent.mkdir(parents=True)
    fake.write_text("")
    monkeypatch.setattr(version, "__file__", str(fake))
    monkeypatch.setattr(importlib.metadata, "version", lambda name: "9.8.7" if name == "linecontact_sym" else "")
    version.package_version.cache_clear()
    try:
        assert version.package_version() == "9.8.7"

        def missing(name):
            raise importlib.metadata.PackageNotFoundError(name)
        monkeypatch.setattr(importlib.metadata, "version", missing)
        version.package_version.cache_clear()
        assert version.package_version() == "0+unknown"
    finally:
        version.package_version.cache_clear()


def test_cli_version(capsys):
    import pytest
    from linecontact_sym.cli import build_parser
    with pytest.raises(SystemExit):
        build_parser().parse_args(["--version"])
    assert capsys.readouterr().out.strip() == f"linecontact-sym {_pyproject_version()}"
