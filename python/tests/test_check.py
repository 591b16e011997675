"""check(): claims decided against the exact answers."""

import pytest

import rodimpact
from conftest import EXAMPLES


def test_numeric_claims():
    # m = M = 1, hit at the end: omega = 6/5 exactly.
    c = rodimpact.check(m=1, M=1, claims={"omega": "1.2", "v": "3/5"})
    assert c.all_agree
    assert [x.verdict for x in c.claims] == ["agrees", "agrees"]
    assert rodimpact.exact(c["claims"][0]) == rodimpact.solve(m=1, M=1).omega
    wrong = rodimpact.check(m=1, M=1, claims=["omega=1.3"])
    assert not wrong.all_agree
    assert "disagree" in str(wrong) or "0 of 1" in str(wrong)


def test_significant_figures_count():
    # 6/5 = 1.2 to two figures, but 1.20 claims three, and 1.21 is off in the third.
    assert rodimpact.check(m=1, M=1, claims={"omega": "1.20"}).all_agree
    assert not rodimpact.check(m=1, M=1, claims={"omega": "1.21"}).all_agree


def test_symbolic_claim_is_an_identity():
    # Free uniform rod, M = 2m, elastic: omega = 2 v0 a/(a^2 + l^2) (formula's answer above).
    assert rodimpact.check(M="2*m", claims={"omega": "2*v0*a/(a^2 + l^2)"}).all_agree
    assert not rodimpact.check(M="2*m", claims={"omega": "v0*a/(a^2 + l^2)"}).all_agree


def test_problem_file():
    c = rodimpact.check(EXAMPLES / "textbook.toml")
    assert "problems" in c
    assert isinstance(c.all_agree, bool)


def test_bad_claims():
    with pytest.raises(ValueError, match=r"^claim: nothing to check"):
        rodimpact.check(m=1, M=1)
    with pytest.raises(ValueError, match=r"^claim: expected NAME=VALUE, got 'omega'$"):
        rodimpact.check(m=1, M=1, claims=["omega"])
    with pytest.raises(ValueError, match="^omega: the float"):
        rodimpact.check(m=1, M=1, claims={"omega": 1.2})
    with pytest.raises(ValueError, match="not both"):
        rodimpact.check(EXAMPLES / "textbook.toml", m=1)


def test_to_dict_is_the_clis_json(cli_json):
    assert rodimpact.check(m=1, M=1, claims={"omega": "1.2", "v": "3/5"}).to_dict() == cli_json(
        "check", "--m", "1", "--M", "1", "--claim", "omega=1.2", "--claim", "v=3/5", "--json"
    )
    assert rodimpact.check(EXAMPLES / "textbook.toml").to_dict() == cli_json(
        "check", "examples/textbook.toml", "--json"
    )
