"""Claims files (claims/spec.py): a field of the wrong type, a file that is
not text or too large, a negative special value, a TOML nested too deep are
refused with a ClaimError naming the problem; a printed float keeps the
digits it was printed with.  Moved from tests/test_trust_round3.py (issue 19,
item 9) and tests/test_hardening.py (issue 10)."""
from __future__ import annotations

import time

import pytest

import linecontact_sym as lcs
from linecontact_sym.core.errors import ClaimError


def test_printed_digits_of_a_toml_float(tmp_path):
    """before: formula = -0.08090 was read as the float -0.0809 (four
    digits): its interval was ten times too wide."""
    from linecontact_sym.claims.spec import load_paper, printed_spread, printed_variants
    f = tmp_path / "t.toml"
    f.write_text('key = "t"\ntitle = "t"\n[[claims]]\nlabel = "c2"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
                 'formula = -0.08090\nrounding = "printed"\nranges = { a = [0.5, 1.5] }\n')
    paper = load_paper(str(f))
    form = paper.claims[0].forms[-1]
    assert form.text == "-0.08090"
    ends = sorted(float(v) for v in form.variants)
    assert ends == [-0.080905, -0.080895]
    # every constant is varied, not the first six
    text = "+".join(f"0.{k}1*x**{k}" for k in range(1, 9))
    vs = printed_variants(text)
    assert printed_spread(text) == "sum" and len(vs) == 17
    for k in range(1, 9):
        assert any(f"0.{k}05*x**{k}" in v for v in vs) and any(f"0.{k}15*x**{k}" in v for v in vs)


def _paper(tmp_path, body):
    p = tmp_path / "c.toml"
    p.write_text(body, encoding="utf-8")
    return p


BASE = 'label = "L"\nquantity = "force"\nprofile = "x**2/(2*R)"\nformula = "pi*E_star*a**2/(4*R)"\n'


@pytest.mark.parametrize("extra,match", [
    ('symbols = "k"\n', "symbols must be a list"),
    ("points = true\n", "points must be"),
    ("assumptions = \"a < R\"\n", "assumptions must be a list"),
    ("ranges = [1, 2]\n", "ranges must be a table"),
    ("note = 3\n", "note must be a string"),
])
def test_claims_fields_of_the_wrong_type(tmp_path, extra, match):
    from linecontact_sym.claims import load_paper
    with pytest.raises(ClaimError, match=match):
        load_paper(_paper(tmp_path, "[[claims]]\n" + BASE + extra))


def test_claims_file_that_is_not_a_text_file(tmp_path):
    from linecontact_sym.claims import load_paper
    bad = tmp_path / "bin.toml"
    bad.write_bytes(b"\xff\xfe\x00[claims]")
    with pytest.raises(ClaimError, match="UTF-8"):
        load_paper(bad)
    with pytest.raises(ClaimError, match="regular file"):
        load_paper(tmp_path)
    t0 = time.perf_counter()
    with pytest.raises(ClaimError, match="regular file"):
        load_paper("/dev/zero")
    big = tmp_path / "big.toml"
    big.write_bytes(b"#" * 2_000_000)
    with pytest.raises(ClaimError, match="larger than"):
        load_paper(big)
    assert time.perf_counter() - t0 < 2


def test_claims_file_refusals(tmp_path):
    from linecontact_sym.claims import load_paper
    p = tmp_path / "neg.toml"
    p.write_text('[[claims]]\nlabel = "x"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
                 'formula = "pi*E_star*a**2/(4*R)"\nspecial = { R = ["-1"] }\n')
    with pytest.raises(lcs.ClaimError, match="positive"):
        load_paper(str(p))
    deep = tmp_path / "deep.toml"
    deep.write_text("a = " + "[" * 3000 + "]" * 3000 + "\n")
    with pytest.raises(lcs.ClaimError, match="TOML"):
        load_paper(str(deep))
