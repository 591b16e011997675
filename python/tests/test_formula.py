"""formula(): SymPy expressions equal to an independent symbolic derivation."""

import sys

import pytest

import rodimpact

sympy = pytest.importorskip("sympy")
m, M, l, a, v0, e = sympy.symbols("m M l a v0 e")


def derived_omega(inertia):
    """omega = J a/I with J = (1 + e) v0/(1/m + 1/M + a^2/I) (free rod, Newton's law)."""
    J = (1 + e) * v0 / (1 / m + 1 / M + a**2 / inertia)
    return J * a / inertia, J


def test_uniform_rod_formulas_are_the_derivation():
    f = rodimpact.formula(e="e")
    omega, J = derived_omega(M * l**2 / 3)
    assert sympy.simplify(f.omega - omega) == 0
    assert sympy.simplify(f.impulse - J) == 0
    assert sympy.simplify(f.V - J / M) == 0
    assert sympy.simplify(f.v - (v0 - J / m)) == 0
    # a*^2 = (M + m) I/(m M)
    assert sympy.simplify(f.a_star_squared - (M + m) * (M * l**2 / 3) / (m * M)) == 0
    assert f.free_symbols == ["m", "M", "l", "a", "v0", "e"]


def test_given_values_and_expressions():
    f = rodimpact.formula(M="2*m", e="e")
    omega, _ = derived_omega(2 * m * l**2 / 3)
    assert sympy.simplify(f.omega - omega.subs(M, 2 * m)) == 0
    assert f.text("omega") == "(a*e*v0 + a*v0)/(a^2 + l^2)"
    # A SymPy expression as an input, and numbers: the formula then evaluates to solve's value.
    g = rodimpact.formula(M=2 * m, a=sympy.Rational(1, 2), l=1, v0=1)
    assert g.omega.subs(m, 7) == rodimpact.solve(m=7, M=14, a="1/2").omega


def test_formulas_agree_with_solve_numbers():
    f = rodimpact.formula()
    values = {m: 3, M: 5, l: 2, a: sympy.Rational(3, 4), v0: 7}
    s = rodimpact.solve(m=3, M=5, l=2, a="3/4", v0=7)
    for key in ("v", "V", "omega"):
        assert sympy.Rational(getattr(f, key).subs(values)) == getattr(s, key), key


def test_to_dict_is_the_clis_json(cli_json):
    assert rodimpact.formula(M="2*m", e="e").to_dict() == cli_json(
        "formula", "--M", "2*m", "--e", "e", "--format", "json"
    )


def test_bad_formula_input():
    with pytest.raises(ValueError, match=r"^M: "):
        rodimpact.formula(M="2*")


def test_strings_without_sympy(monkeypatch):
    monkeypatch.setitem(sys.modules, "sympy", None)  # import sympy now fails
    f = rodimpact.formula(M="2*m", e="e")
    assert f.omega == "(a*e*v0 + a*v0)/(a^2 + l^2)"


def test_latex_display():
    f = rodimpact.formula()
    latex = f._repr_latex_()
    assert latex.startswith("$$\\begin{aligned}") and "\\omega &=" in latex
