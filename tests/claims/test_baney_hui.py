"""The shipped claims file of Baney & Hui (1997): Eq. (23) in their
normalisation (derived from the parabola's Maugis-Dugdale conditions) and the
normalised pull-off table (computed here; no copy of the paper's table)."""
from linecontact_sym.claims.batch import check_paper
from linecontact_sym.claims.spec import load_paper


def test_baney_hui_claims_hold():
    paper = load_paper("baney_hui1997")
    result = check_paper(paper, budget=120)
    status = {r.label: r.status for r in result.results}
    assert status["Eq. (23), load"] == "holds" and status["Eq. (23), cohesive zone"] == "holds"
    assert all(s == "holds" for s in status.values()), status
    assert len(status) == 8


def test_baney_hui_wrong_table_entry_fails(tmp_path):
    """A table entry off in its 4th digit does not hold (the check can fail)."""
    text = load_paper("baney_hui1997").source
    body = open(text).read().replace("-1.09902*F_BH", "-1.09952*F_BH")
    p = tmp_path / "bh.toml"
    p.write_text(body)
    result = check_paper(load_paper(str(p)), budget=120, only={"Pull-off, lambda = 0.932"})
    assert [r.status for r in result.results] == ["does not hold"]
