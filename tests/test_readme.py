"""The README's Python examples run as written and give what they say."""
import re
from pathlib import Path

import sympy as sp

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_python_blocks_run():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    assert len(blocks) >= 2
    ns: dict = {}
    for block in blocks:
        exec(compile(block, str(README), "exec"), ns)  # the project's own README, not user input
    lcs, R, a = ns["lcs"], ns["R"], ns["a"]
    assert ns["c"].force == sp.pi * lcs.E_star * a**2 / (4 * R)
    roots = ns["ad"].half_width(-0.01, R=1, E_star=1, gamma=0.01)
    assert len(roots) == 2 and roots[0] > roots[1] > 0
    # the wavy surface: Westergaard's load, and Johnson's (1995) pull-off and snap-in recomputed
    # from his printed law P = p* L (sin^2(pi a/L) - alpha sqrt(tan(pi a/L))), alpha^2 = 2 w L/(pi^2 E* h^2)
    import mpmath
    h, L = ns["h"], ns["L"]
    assert sp.simplify(ns["w"].force - sp.pi * lcs.E_star * h * sp.sin(sp.pi * lcs.a / L)**2) == 0
    with mpmath.workdps(30):
        hv, wv = mpmath.mpf(1) / 10, mpmath.mpf(1) / 1000
        ps, alpha = mpmath.pi * hv, mpmath.sqrt(2 * wv / (mpmath.pi**2 * hv**2))
        P = lambda A: ps * (mpmath.sin(mpmath.pi * A)**2 - alpha * mpmath.sqrt(mpmath.tan(mpmath.pi * A)))  # noqa: E731
        a_min = mpmath.findroot(lambda A: mpmath.diff(P, A), 0.035)
        a_max = mpmath.findroot(lambda A: mpmath.diff(P, A), 0.41)
        assert abs(ns["wa"].pull_off_at(**ns["vw"]).force - P(a_min)) < 1e-20
        assert abs(ns["wa"].full_contact_at(**ns["vw"]).force - P(a_max)) < 1e-20
        assert mpmath.nstr(P(a_min), 15) == "-0.0110765175610314"
