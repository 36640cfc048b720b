"""The command line `linecontact-sym`: every verb, --help, JSON output,
errors on stderr with a non-zero exit status."""
import json
import os
import re
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import mpmath
import pytest

from independent_refs import close
from linecontact_sym import cli

ROOT = Path(__file__).resolve().parents[1]


def run(capsys, *argv):
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("verb", [None, "paper", "derive", "eval", "table", "check", "model"])
def test_help(capsys, verb):
    with pytest.raises(SystemExit) as info:
        cli.main(([verb] if verb else []) + ["--help"])
    assert info.value.code == 0
    out = capsys.readouterr().out
    assert "usage: linecontact-sym" in out


def test_module_entry_point_runs():
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    proc = subprocess.run([sys.executable, "-m", "linecontact_sym", "table", "power-law", "--n", "2"],
                          capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "pi/2" in proc.stdout


def test_importing_the_main_module_runs_nothing(monkeypatch):
    """Sphinx's autosummary imports every module to list it: an import of
    linecontact_sym.__main__ that ran the CLI parsed the build's arguments
    and ended the docs build in CI."""
    import importlib
    monkeypatch.setattr(sys, "argv", ["sphinx", "-q", "-E", "-b", "html"])
    sys.modules.pop("linecontact_sym.__main__", None)
    module = importlib.import_module("linecontact_sym.__main__")
    assert callable(module.main)


def test_entry_point_is_declared():
    text = (ROOT / "pyproject.toml").read_text()
    assert 'linecontact-sym = "linecontact_sym.cli:main"' in text


# ------------------------------------------------------------------ check
def test_check_command_line_claim_holds(capsys):
    code, out, err = run(capsys, "check", "--profile", "x**2/(2*R)", "--force", "pi*E_star*a**2/(4*R)",
                         "--budget", "5")
    assert code == 0 and "holds" in out and err == ""


def test_check_wrong_claim_counterexample_and_strict(capsys):
    argv = ["check", "--profile", "x*tan(theta)", "--force", "pi*E_star*a*tan(theta)/2", "--budget", "5"]
    code, out, _ = run(capsys, *argv)
    assert code == 1 and "does not hold" in out and "printed" in out and "derived" in out
    # the derived formula, a counterexample and the diagnosis of the failing claim
    assert "derived:        E_star*a*tan(theta)" in out and "counterexample: at " in out
    assert "diagnosis:      holds up to a constant factor: the formula is pi/2 times" in out
    code, _, _ = run(capsys, *argv, "--strict")
    assert code == 1


def test_check_json(capsys):
    code, out, _ = run(capsys, "check", "--profile", "c*x**n", "--Z-n",
                       "(n - 1)*sqrt(pi)*gamma(n/2 - 1/2)/(2*gamma(n/2))", "--range", "n=0.5:3", "--json",
                       "--budget", "5")
    d = json.loads(out)
    assert code == 0 and d["claims"][0]["status"] in ("holds", "holds under a condition")


def test_check_adhesion_force_and_pull_off_signs(capsys):
    """--adhesion-force is P_adh > 0, --pull-off is P_min < 0 (wedge, Eq. 36)."""
    base = ["check", "--profile", "x*tan(theta)", "--budget", "5", "--json"]
    code, out, _ = run(capsys, *base, "--adhesion-force", "pi*gamma/(2*tan(theta))",
                       "--pull-off=-pi*gamma/(2*tan(theta))")
    d = json.loads(out)
    assert code == 0
    assert [(c["quantity"], c["status"]) for c in d["claims"]] == [("adhesion_force", "holds"),
                                                                   ("pull_off_force", "holds")]
    code, out, _ = run(capsys, *base, "--pull-off", "pi*gamma/(2*tan(theta))")
    d = json.loads(out)["claims"][0]
    assert code == 1 and d["status"] == "does not hold"
    assert "opposite sign" in d["diagnoses"][0] and "P_min < 0" in d["diagnoses"][0]
    # a formula starting with '-' needs neither '=' nor '--'
    code, out, _ = run(capsys, *base, "--pull-off", "-pi*gamma/(2*tan(theta))")
    assert code == 0 and json.loads(out)["claims"][0]["status"] == "holds"
    with pytest.raises(SystemExit):
        cli.main(["check", "--help"])
    assert "P_min = min_a P(a) < 0" in " ".join(capsys.readouterr().out.split())


def test_check_refuses_unsafe_input(capsys):
    code, out, err = run(capsys, "check", "--profile", "x**2", "--force", "__import__('os').getcwd()")
    assert code == 2 and out == ""
    assert "error" in err and "not allowed" in err and "command line" in err


def test_check_file(tmp_path, capsys):
    p = tmp_path / "mine.toml"
    p.write_text(textwrap.dedent('''
        title = "my notes"
        [[claims]]
        label = "Hertz"
        quantity = "force"
        profile = "x**2/(2*R)"
        formula = "pi*E_star*a**2/(4*R)"
        [[claims]]
        label = "wedge, wrong"
        quantity = "force"
        profile = "x*tan(theta)"
        formula = "E_star*a*theta"
        points = 2
    '''))
    code, out, err = run(capsys, "check", str(p), "--json", "--budget", "5")
    d = json.loads(out)
    assert code == 1 and d["exit_status"] == 1
    assert [c["status"] for c in d["claims"]] == ["holds", "does not hold"]
    assert "[ 1/2] Hertz" in err and "[ 2/2] wedge, wrong" in err       # progress: one line per claim
    code, out, err = run(capsys, "check", str(p), "--quiet", "--budget", "5")
    assert code == 1 and err == "" and "Hertz: holds" in out
    assert d["claims"][1]["targets"][0]["forms"][0]["counterexample"]


def test_check_malformed_file(tmp_path, capsys):
    p = tmp_path / "bad.toml"
    p.write_text('[[claims]]\nlabel = "Eq. (7)"\nquantity = "force"\nprofile = "x**2"\nformula = "a.b"\n')
    code, out, err = run(capsys, "check", str(p))
    assert code == 2 and out == ""
    assert "bad.toml" in err and "Eq. (7)" in err and "attribute" in err


def test_nothing_to_check(capsys):
    code, _, err = run(capsys, "check", "--profile", "x**2")
    assert code == 2 and "nothing to check" in err


# ------------------------------------------------------------------ derive / eval / table
def test_derive_formats(capsys):
    code, out, _ = run(capsys, "derive", "x**2/(2*R)", "--quantities", "force,pressure", "--format", "json",
                       "--budget", "5")
    d = json.loads(out)
    assert code == 0 and d["quantities"]["force"]["expr"] == "pi*E_star*a**2/(4*R)"
    assert d["quantities"]["force"]["verified_digits"] >= 30
    code, out, _ = run(capsys, "derive", "x*tan(theta)", "--quantities", "force", "--format", "latex")
    assert code == 0 and r"\begin{align*}" in out and "E^{*}" in out
    code, out, _ = run(capsys, "derive", "k*x**2", "--symbols", "k", "--set", "k=1/2", "--quantities", "force")
    assert code == 0 and "pi*E_star*a**2/4" in out


def test_derive_adhesion(capsys):
    code, out, _ = run(capsys, "derive", "x**2/(2*R)", "--quantities", "force,adhesion_force", "--adhesion",
                       "--format", "json", "--budget", "5")
    d = json.loads(out)
    assert code == 0 and "adhesion_force" in d["quantities"]
    # only what is asked (issue 22: --quantities force derived all five quantities)
    code, out, _ = run(capsys, "derive", "x**2/(2*R)", "--quantities", "force", "--adhesion", "--format", "json")
    d = json.loads(out)
    assert code == 0 and sorted(d["quantities"]) == ["adhesive_force", "force"]
    assert d["quantities"]["adhesive_force"]["expr"].replace(" ", "") == \
        "-sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma)+pi*E_star*a**2/(4*R)"
    code, _, err = run(capsys, "derive", "x**2/(2*R)", "--quantities", "adhesion_force")
    assert code == 2 and "--adhesion" in err


def test_eval_grid_and_precision(capsys):
    code, out, _ = run(capsys, "eval", "x**2/(2*R)", "pressure", "--at", "a=1", "x=0,0.5", "--set", "R=1",
                       "E_star=1", "--dps", "40", "--json")
    d = json.loads(out)
    assert code == 0 and len(d["rows"]) == 2
    assert d["rows"][0]["value"].startswith("0.5")
    assert d["rows"][1]["value"].startswith("0.4330127018922193233818615853764680")


def test_eval_outside_domain(capsys):
    code, out, _ = run(capsys, "eval", "x**2/(2*R)", "pressure", "--at", "a=1", "x=2", "--set", "R=1", "E_star=1")
    assert code == 2 and "outside the contact" in out


def test_eval_unknown_quantity(capsys):
    code, _, err = run(capsys, "eval", "x**2", "torque", "--at", "a=1")
    assert code == 2 and "unknown quantity" in err


def test_table(capsys):
    code, out, _ = run(capsys, "table", "power-law", "--n", "1,2,3,4,5,6,10")
    assert code == 0
    for v in ("pi/2", "3*pi/4", "8/3", "15*pi/16", "315*pi/256"):
        assert v in out
    code, out, _ = run(capsys, "table", "power-law", "--n", "1,2", "--latex")
    assert r"\toprule" in out and r"\bottomrule" in out
    code, out, _ = run(capsys, "table", "power-law", "--n", "3", "--json")
    assert json.loads(out)["rows"][0]["Z_n"] == "2"
    code, _, err = run(capsys, "table", "power-law", "--n", "-1")
    assert code == 2 and "positive" in err


# ------------------------------------------------------------------ paper
def test_paper_job_writes_report_table_and_figures(tmp_path, capsys):
    p = tmp_path / "demo.toml"
    p.write_text(textwrap.dedent('''
        key = "demo"
        title = "demo paper"
        [[claims]]
        label = "Eq. (13)"
        title = "parabola"
        quantity = "force"
        profile = "x**2/(2*R)"
        formula = "pi*E_star*a**2/(4*R)"
        [[claims]]
        label = "Table 1"
        quantity = "Z_n"
        profile = "c*x**n"
        values = ["1", "pi/2", "3*pi/4"]
        [[figures]]
        file = "fig4_worn_cylinder"
        caption = "A worn cylinder against the parabola."
        x = "a/b"
        y = "2*R*P/(E_star*b**2)"
        x_range = [0, 4]
        points = 41
        values = { b = 1, R = 1, E_star = 1 }
        [[figures.curves]]
        profile = "Piecewise((0, x < b), ((x**2 - b**2)/(2*R), True))"
        [[figures.curves]]
        profile = "x**2/(2*R)"
        style = "--"
        [[figures]]
        file = "fig5_exact_cylinder"
        caption = "The exact cylinder against Hertz, and their ratio."
        x = "a/R"
        y = "P/(E_star*R)"
        x_range = [0, 0.99]
        points = 41
        values = { R = 1, E_star = 1 }
        ratio = ["exact", "hertz"]
        [[figures.curves]]
        name = "exact"
        profile = "R - sqrt(R**2 - x**2)"
        [[figures.curves]]
        name = "hertz"
        profile = "x**2/(2*R)"
    '''))
    out_dir = tmp_path / "out"
    code, out, err = run(capsys, "paper", str(p), "--out", str(out_dir), "--budget", "10")
    assert code == 0, err
    assert "[ 1/2] Eq. (13)" in err and "[ 2/2] Table 1" in err          # progress lines
    assert "Eq. (13)" in out and "holds" in out
    for name in ("report.md", "report.tex", "table1.tex", "results.json", "fig4_worn_cylinder.png",
                 "fig4_worn_cylinder.pdf", "fig5_exact_cylinder.png", "fig5_exact_cylinder.pdf"):
        assert (out_dir / name).stat().st_size > 0, name
    assert r"\toprule" in (out_dir / "table1.tex").read_text()
    assert json.loads((out_dir / "results.json").read_text())["counts"]["holds"] == 2
    assert r"\caption{The exact cylinder against Hertz, and their ratio.}" in (out_dir / "report.tex").read_text()


def test_paper_shipped_subset_json(tmp_path, capsys):
    code, out, _ = run(capsys, "paper", "popov2017", "--only", "Eq. (19)", "Eq. (17)", "--no-figures",
                       "--quiet", "--json", "--out", str(tmp_path), "--budget", "5")
    d = json.loads(out)
    assert code == 0
    status = {c["label"]: c["status"] for c in d["claims"]}
    assert status == {"Eq. (17)": "holds under a condition", "Eq. (19)": "holds"}


def test_paper_unknown_label_and_internal_error(tmp_path, capsys, monkeypatch):
    code, _, err = run(capsys, "paper", "popov2017", "--only", "Eq. (99)", "--out", str(tmp_path))
    assert code == 2 and "Eq. (99)" in err

    import linecontact_sym.claims.batch as B

    def boom(*a, **k):
        raise RuntimeError("kaboom")
    monkeypatch.setattr(B, "check_paper", boom)
    code, _, err = run(capsys, "paper", "popov2017", "--out", str(tmp_path), "--no-figures")
    assert code == 3 and "internal error" in err and "kaboom" in err


# ------------------------------------------------------------------ exit codes, hints, help
def test_exit_codes_undecided_and_internal(capsys, monkeypatch):
    import linecontact_sym.claims.check as C
    from linecontact_sym.core.errors import BudgetExceeded
    argv = ["check", "--profile", "x**2/(2*R)", "--force", "pi*E_star*a**2/(4*R)", "--json"]

    def slow(*a, **k):
        raise BudgetExceeded("the derivation took longer than 0.1 s")
    monkeypatch.setattr(C, "derive", slow)
    code, out, _ = run(capsys, *argv)
    assert code == 4 and json.loads(out)["claims"][0]["status"] == "undecided"

    def bug(*a, **k):
        raise ZeroDivisionError("oops")
    monkeypatch.setattr(C, "derive", bug)
    code, out, _ = run(capsys, *argv)
    assert code == 3 and "internal error" in json.loads(out)["claims"][0]["verdict"]


def test_exit_codes_are_documented(capsys):
    for verb in ("check", "paper"):
        with pytest.raises(SystemExit):
            cli.main([verb, "--help"])
        text = " ".join(capsys.readouterr().out.split())
        for code in ("0 every claim holds", "1 at least one claim does not hold", "2 bad input",
                     "3 internal error", "4 no claim fails but at least one is undecided"):
            assert code in text, (verb, code)


def test_help_lists_the_values(capsys):
    with pytest.raises(SystemExit):
        cli.main(["derive", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "{text,latex,json}" in text and "mean_pressure" in text and "stiffness" in text
    with pytest.raises(SystemExit):
        cli.main(["check", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "adhesive_pressure" in text and "flat_punch_pressure" in text


def test_unknown_symbol_hint_uses_command_line_syntax(capsys):
    code, _, err = run(capsys, "derive", "k*x**2", "--quantities", "force")
    assert code == 2 and "--symbols k" in err and "symbols = [" not in err


def test_profile_starting_with_a_minus(capsys):
    code, out, _ = run(capsys, "derive", "-x**2/(2*R) + x**2/R", "--quantities", "force", "--json",
                       "--budget", "5")
    assert code == 0 and json.loads(out)["quantities"]["force"]["expr"] == "pi*E_star*a**2/(4*R)"
    code, out, _ = run(capsys, "derive", "--quantities", "force", "--format", "json", "--",
                       "-x**2/(2*R) + x**2/R")
    assert code == 0 and json.loads(out)["profile"] == "x**2/(2*R)"


def test_model_maugis_dugdale(capsys):
    """JKR or MD for an rtol, with the Maugis parameter (Baney & Hui's for the parabola)."""
    code, out, _ = run(capsys, "model", "x**2/(2*R)", "--set", "R=1", "E_star=1", "gamma=1", "sigma_0=0.5", "--json")
    assert code == 0
    d = json.loads(out)
    assert d["model"] == "MD" and abs(float(d["maugis_parameter"]) - 0.932388154070823) < 1e-12
    code, out, _ = run(capsys, "model", "x**2/(2*R)", "--set", "R=1", "E_star=1", "gamma=1", "sigma_0=30",
                       "--rtol", "0.01", "--json")
    assert code == 0 and json.loads(out)["model"] == "JKR"


@pytest.mark.slow
def test_rolling_mode_of_derive_and_eval(capsys):
    """derive --rolling gives Carter's creepage; eval evaluates it at carter2d (stick half-width 0.6)."""
    code, out, _ = run(capsys, "derive", "x**2/(2*R)", "--rolling", "--quantities", "force", "--json", "--quiet")
    assert code == 0
    got = json.loads(out)["quantities"]
    assert got["rolling.creepage"]["expr"] == "mu*(a - c_s)/R"
    assert json.loads(out)["coupling"].startswith("beta = 0 assumed (elastically similar bodies)")
    assert got["rolling.creepage"]["notes"][0] == json.loads(out)["coupling"]
    code, out, _ = run(capsys, "eval", "x**2/(2*R)", "rolling.creepage", "--at", "c_s=0.6", "--set", "a=1", "R=500",
                       "E_star=113888.9", "mu=0.3", "--json")
    assert code == 0 and float(json.loads(out)["rows"][0]["value"]) == pytest.approx(2.4e-4, rel=1e-25)


@pytest.mark.parametrize("argv,match", [
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "--dps", "0"], "digits must be"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=oo", "--set", "R=1", "E_star=1"], "finite real"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "Q=3"], "'Q'"),
    (["derive", "x**2/(2*R)", "--set", "Q=3", "--quantities", "force"], "no such parameter"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=-1", "E_star=1"], "R must be positive"),
])
def test_cli_refuses_bad_values(capsys, argv, match):
    from linecontact_sym import cli
    try:
        code = cli.main(argv)
    except SystemExit as exc:   # argparse type errors
        code = exc.code
    out, err = capsys.readouterr()
    assert code != 0 and re.search(match, out + err), (code, out, err)


@pytest.mark.parametrize("argv, words", [
    (["eval", "x**2/(2*R)", "pressure", "--at", "a=0.1:1:10000", "x=0.1:1:10000"], "points"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=", "--set", "R=1", "E_star=1"], "no value"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1:2:abc"], "not an integer"),
    (["derive", "x**2/(2*R)", "--quantities", ""], "names no quantity"),
    (["check", "--profile", "x**2/(2*R)", "--force", "pi*E_star*a**2/(4*R)", "--range", "R=-1:1"], "positive"),
])
def test_cli_refusals_exit_2(argv, words, capsys):
    from linecontact_sym.cli import main
    assert main(argv) == 2
    assert words in capsys.readouterr().err


def test_cli_budget_refused(capsys):
    from linecontact_sym.cli import main
    with pytest.raises(SystemExit):
        main(["derive", "x**2/(2*R)", "--budget", "-3"])
    assert "expected seconds > 0" in capsys.readouterr().err


def test_cli_edges_are_input_errors(tmp_path, capsys):
    afile = tmp_path / "a-file"
    afile.write_text("x")
    t0 = time.perf_counter()
    assert cli.main(["paper", "popov2017", "--out", str(afile), "--quiet"]) == cli.EXIT_INPUT
    assert cli.main(["paper", "popov2017", "--out", str(afile / "sub"), "--quiet"]) == cli.EXIT_INPUT
    assert time.perf_counter() - t0 < 20          # refused before any claim is checked
    assert "is a file" in capsys.readouterr().err
    for n in ("1e400", "1e-400", "2,1e400", "-1", "0", "oo", "nan", "I"):
        assert cli.main(["table", "power-law", f"--n={n}"]) == cli.EXIT_INPUT, n
    # an irrational exponent is an exponent: Z_n = n int_0^{pi/2} sin^n(phi) dphi (Eq. 10* of c x^n)
    capsys.readouterr()
    assert cli.main(["table", "power-law", "--n=sqrt(2)", "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    n = mpmath.sqrt(2)
    assert close(row["Z_n_float"], float(n * mpmath.quad(lambda p: mpmath.sin(p)**n, [0, mpmath.pi / 2])), 1e-14)


def _cli(args, **env):
    return subprocess.run([sys.executable, "-m", "linecontact_sym"] + args, capture_output=True, text=True,
                          timeout=300, env={**os.environ, "PYTHONPATH": str(ROOT), **env})


@pytest.mark.slow
def test_budget_environment_on_the_cli():
    args = ["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "--dps", "12"]
    r = _cli(args, LINECONTACT_SYM_BUDGET="abc")
    assert r.returncode == 2 and "LINECONTACT_SYM_BUDGET" in r.stderr and "Traceback" not in r.stderr
    r = _cli(args, LINECONTACT_SYM_BUDGET="inf")        # the README's "no limit"
    assert r.returncode == 0 and "0.785398163397" in r.stdout
    r = _cli(["paper", "popov2017", "--jobs", "abc"])
    assert r.returncode == 2 and "--jobs" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.slow
def test_paper_jobs_are_capped_at_the_work(monkeypatch, tmp_path):
    from linecontact_sym import cli
    from linecontact_sym.claims import batch
    seen = []
    real = batch.process_pool
    monkeypatch.setattr(batch, "process_pool", lambda jobs=None: seen.append(jobs) or real(jobs))
    code = cli.main(["paper", "popov2017", "--jobs", "1000", "--only", "Eq. (13)", "--no-figures", "--quiet",
                     "--out", str(tmp_path)])
    assert code == 0 and all(j <= 2 for j in seen)


def test_cli_eval_bad_value_on_stderr():
    import contextlib
    import io
    from linecontact_sym import cli
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = cli.main(["eval", "x**2/(2*R)", "force", "--at", "a=-1", "--set", "R=1", "E_star=1"])
    assert code == 2 and "a = -1" in err.getvalue() and "positive" in err.getvalue()


# ------------------------------------------------------------------ issue 42 (trust, round 5)
def test_derive_law_implies_adhesion(capsys):
    """--law without --adhesion printed the non-adhesive laws alone; a cohesive law named is an
    adhesive derivation asked for (said on stderr)."""
    code, out, err = run(capsys, "derive", "x**2/(2*R)", "--law", "jkr", "--quantities", "force", "--json")
    assert code == 0 and "implies --adhesion" in err
    q = json.loads(out)["quantities"]
    assert q["force"]["expr"] == "pi*E_star*a**2/(4*R)"
    assert q["adhesive_force"]["expr"] == "-sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma) + pi*E_star*a**2/(4*R)"


def test_maugis_dugdale_on_an_array_is_refused_as_by_the_api(capsys, tmp_path):
    """derive exited 3 (an internal error); a claims file got 'holds' at 45 digits."""
    code, _, err = run(capsys, "derive", "h*(1 - cos(2*pi*x/L))", "--symbols", "h", "L", "--period", "L",
                       "--adhesion", "--law", "maugis_dugdale")
    assert code == 2 and "maugis_dugdale law on a periodic array is not derived yet" in err
    f = tmp_path / "md.toml"
    f.write_text(textwrap.dedent('''
        key = "t"
        symbols = ["h", "L"]
        [[claims]]
        label = "md zone"
        quantity = "maugis_dugdale.zone_force"
        profile = "h*(1 - cos(2*pi*x/L))"
        period = "L"
        formula = "2*sigma_0*sqrt(c_D**2 - a**2)"
        '''))
    code, out, _ = run(capsys, "check", str(f), "--json")
    r = json.loads(out)["claims"][0]
    assert code == 4 and r["status"] == "undecided" and "periodic array is not derived yet" in json.dumps(r)


def test_claims_period_zero_is_bad_input(capsys, tmp_path):
    f = tmp_path / "p.toml"
    f.write_text('key = "t"\nsymbols = ["h"]\n[[claims]]\nlabel = "p0"\nquantity = "force"\n'
                 'profile = "h*(1 - cos(2*pi*x))"\nperiod = "0"\nformula = "h"\n')
    code, _, err = run(capsys, "check", str(f))
    assert code == 2 and "period" in err and "must be positive" in err


def test_claims_file_ranges_are_read_and_checked_at_load(capsys, tmp_path):
    """The file's [ranges] as a claim's own: numbers in any notation, a negative range of a positive
    symbol bad input (exit 2; was an undecided claim), a unit refused (a claims file takes SI)."""
    claim = ('[[claims]]\nlabel = "hertz"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
             'formula = "pi*E_star*a**2/(4*R)"\n')
    for rng, expected in (('["-1", "1"]', 2), ('["1mm", "2mm"]', 2)):
        f = tmp_path / "r.toml"
        f.write_text(f'key = "t"\n[ranges]\nR = {rng}\n' + claim)
        code, _, err = run(capsys, "check", str(f))
        assert code == expected and "ranges.R" in err, (rng, err)


def test_eval_takes_the_arrays_own_quantities(capsys):
    """eval --period ... nominal_pressure was refused as unknown."""
    code, out, err = run(capsys, "eval", "h*(1 - cos(2*pi*x/L))", "nominal_pressure", "--symbols", "h", "L",
                         "--period", "L", "--at", "a=0.1", "--set", "h=1", "L=1", "E_star=1", "--dps", "20")
    assert code == 0, err
    import mpmath
    # Westergaard: pbar = pi E* h sin(pi a/L)**2 / L, computed here
    with mpmath.workdps(30):
        assert mpmath.nstr(mpmath.pi * mpmath.sin(mpmath.pi / 10)**2, 20) in out


@pytest.mark.slow
def test_derive_adhesion_prints_the_wedges_pull_off(capsys):
    """The pull-off P_min = -pi gamma/(2 tan theta) is among the default adhesive quantities."""
    code, out, _ = run(capsys, "derive", "x*tan(theta)", "--adhesion", "--json")
    q = json.loads(out)["quantities"]
    assert code == 0 and q["pull_off_force"]["expr"] == "-pi*gamma/(2*tan(theta))"
    assert q["adhesion_force"]["expr"] == "pi*gamma/(2*tan(theta))"


def test_tangential_and_rolling_output_states_the_coupling(capsys):
    """eval of a tangential quantity prints the coupling (beta = 0 assumed; with
    --materials the size |beta| mu at the --set mu, E_star filled from the
    materials); derive --rolling ends with it; --beta beside a frictionless
    quantity is refused."""
    code, out, _ = run(capsys, "eval", "x**2/(2*R)", "tangential.tangential_force", "--at", "c_s=0.5",
                       "--set", "a=1", "R=1", "mu=0.3", "E_star=1")
    assert code == 0 and "coupling: beta = 0 assumed (elastically similar bodies)" in out
    code, out, err = run(capsys, "eval", "x**2/(2*R)", "tangential.tangential_force", "--at", "c_s=0.5",
                         "--set", "a=1", "R=1", "mu=0.3", "--materials", "oo,0,0.91,0.3", "--json")
    got = json.loads(out)
    # a rigid cylinder on nu = 0.3: E* = 0.91/(1 - 0.09) = 1, |beta| = 0.4/1.4 = 2/7; Q = 0.3 pi (1 - 1/4)/4
    assert code == 0 and float(got["rows"][0]["value"]) == pytest.approx(0.3 * mpmath.pi * 0.75 / 4, rel=1e-25)
    assert "|beta| mu = 0.0857" in got["coupling"] and "Warning" not in err
    code, out, _ = run(capsys, "eval", "x**2/(2*R)", "tangential.tangential_force", "--at", "c_s=0.5",
                       "--set", "a=1", "R=1", "mu=0.3", "E_star=2", "--materials", "oo,0,0.91,0.3")
    assert code == 2 and "contradicts the materials" in out
    code, _, err = run(capsys, "eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1",
                       "--beta", "0.1")
    assert code == 2 and "frictional" in err
