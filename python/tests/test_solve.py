"""solve(): exact values against an independent derivation, and the CLI's JSON."""

import random
import subprocess
import sys
from fractions import Fraction as F

import pytest

import rodimpact
from rodimpact import Surd


def derived(m, M, l=F(1), a=None, v0=F(1), e=F(1), inertia=None, pivot=None):
    """The answer derived here, independently of the library: Newton's restitution at the
    contact with the impulse J on the rod.

    Free rod: linear momentum m v0 = m v + M V, angular momentum about the centre
    m v0 a = m v a + I omega, restitution (V + omega a) - v = e v0. Eliminating gives
    J = m (v0 - v) = (1 + e) v0 / (1/m + 1/M + a^2/I), V = J/M, omega = J a/I.
    On a pivot at p: the rod turns about p with I_p = I + M p^2, the lever arm is a - p,
    J = (1 + e) v0 / (1/m + (a - p)^2/I_p), omega = J (a - p)/I_p, V = -omega p.
    """
    a = l if a is None else a
    I = M * l * l / 3 if inertia is None else inertia
    if pivot is None:
        J = (1 + e) * v0 / (1 / m + 1 / M + a * a / I)
        V, omega = J / M, J * a / I
    else:
        Ip = I + M * pivot * pivot
        J = (1 + e) * v0 / (1 / m + (a - pivot) ** 2 / Ip)
        omega = J * (a - pivot) / Ip
        V = -omega * pivot
    v = v0 - J / m
    return v, V, omega, I


def test_the_issue_example_prints_the_exact_answer():
    # The issue's "done when": a fresh interpreter prints the exact answer. m = M = l = v0 = 1,
    # a = 1/2: J = 2/(1 + 1 + 3/4) = 8/11, omega = J a/I = (8/11)(1/2)(3) = 12/11.
    out = subprocess.run(
        [sys.executable, "-c", "import rodimpact; print(rodimpact.solve(m=1, M=1, a='1/2').omega)"],
        capture_output=True, text=True, check=True,
    ).stdout
    assert out == "12/11\n"


def test_the_papers_scene_exactly():
    s = rodimpact.solve(m=1, M=1, a="1/2")
    assert (s.v, s.V, s.omega) == (F(3, 11), F(8, 11), F(12, 11))
    assert isinstance(s.omega, F)
    assert s.energy.before == s.energy.after == F(1, 2)
    assert s.energy.lost == 0
    assert s.laws_hold


def test_random_scenes_match_the_derivation():
    rng = random.Random(29)
    for _ in range(60):
        m = F(rng.randint(1, 50), rng.randint(1, 50))
        M = F(rng.randint(1, 50), rng.randint(1, 50))
        l = F(rng.randint(1, 20), rng.randint(1, 10))
        a = l * F(rng.randint(-100, 100), 100)
        v0 = F(rng.randint(1, 30), rng.randint(1, 7))
        e = F(rng.randint(0, 10), 10)
        kind = rng.choice(["uniform", "dumbbell", "rg"])
        if kind == "uniform":
            rod, inertia = None, None
        elif kind == "dumbbell":
            rod, inertia = "dumbbell", M * l * l
        else:
            r = l * F(rng.randint(1, 10), 10)
            rod, inertia = f"rg={r}", M * r * r
        pivot = None if rng.random() < 0.6 else l * F(rng.randint(-10, 10), 10)
        if pivot is not None and a == pivot:
            continue  # a hit on the pivot itself moves nothing; covered by the library's tests
        s = rodimpact.solve(m=m, M=M, l=l, a=a, v0=v0, e=e, rod=rod, pivot=pivot)
        v, V, omega, I = derived(m, M, l, a, v0, e, inertia, pivot)
        assert (s.v, s.V, s.omega) == (v, V, omega), (m, M, l, a, v0, e, kind, pivot)
        # Energies from the derived state: K = m v^2/2 + M V^2/2 + I omega^2/2.
        before = m * v0 * v0 / 2
        after = m * v * v / 2 + M * V * V / 2 + I * omega * omega / 2
        assert s.energy.before == before
        assert s.energy.after == after
        assert s.energy.lost == before - after
        if e == 1:
            assert s.energy.lost == 0


def test_the_optimum_is_a_surd():
    # a*^2 = (M + m) I/(m M) with I = M l^2/3: at m = M = l = 1, a*^2 = 2/3, a* = sqrt(6)/3.
    s = rodimpact.solve(m=1, M=1)
    star = s.a_star
    assert isinstance(star, Surd)
    assert star.squared == F(2, 3)
    assert star.exact == "sqrt(6)/3"
    assert float(star) == pytest.approx((2 / 3) ** 0.5, rel=1e-15)
    assert star == Surd("sqrt(6)/3", "0.8")  # equality is the canonical form's
    assert star != F(4, 5)
    assert s["a_star"]["within_rod"] is True
    # omega_max = (1 + e) v0/(2 a*) = 1/sqrt(2/3) = sqrt(6)/2
    assert s.omega_max.exact == "sqrt(6)/2"
    sympy = pytest.importorskip("sympy")
    assert sympy.simplify(star.sympy() - sympy.sqrt(sympy.Rational(2, 3))) == 0
    assert sympy.simplify(s.omega_max.sympy() - 1 / sympy.sqrt(sympy.Rational(2, 3))) == 0


def test_a_rational_optimum_is_a_fraction():
    # m = 1, M = 3, dumbbell I = M l^2 = 3: a*^2 = (M + m) I/(m M) = 4 * 3/3 = 4, a* = 2,
    # beyond the rod (l = 1): the end gives the fastest spin.
    s = rodimpact.solve(m=1, M=3, rod="dumbbell")
    assert s.a_star == F(2)
    assert s["a_star"]["within_rod"] is False
    assert s.argmax == "end"


def test_decimals_and_digits():
    s = rodimpact.solve(m=1, M=1, a="1/2", digits=40)
    assert s["omega"]["decimal"].startswith("1.0909090909090909090909090909090909090")
    with pytest.raises(ValueError, match=r"^digits: must be a whole number from 1 to 10000, got '0'$"):
        rodimpact.solve(m=1, M=1, digits=0)


def test_text_report_and_laws():
    s = rodimpact.solve(m=1, M=1, a=1)
    assert "6/5 rad/s" in str(s)
    assert s.laws_hold


def test_oblique_scene_keys():
    s = rodimpact.solve(m=1, M=1, a="1/2", v0t="1/2", mu="1/4")
    assert s["contact"] in ("stick", "slide")
    assert isinstance(s.vt, F)


def test_to_dict_is_the_clis_json(cli_json):
    cases = [
        dict(m=1, M=1, a="1/2"),
        dict(m="0.25", M="3/4", length="2", from_end="1/2", e="1/2"),
        dict(m=2, M=1, pivot="-1/2", rod="rg=1/2"),
        dict(m=1, M=1, a="1/2", v0t="1/2", mu="1/4"),
        dict(m="100 g", M="1.5kg", v0="36 km/h"),
    ]
    for case in cases:
        flags = []
        for key, value in case.items():
            flags += [f"--{key.replace('_', '-')}", str(value)]
        assert rodimpact.solve(**case).to_dict() == cli_json("solve", *flags, "--json"), case


def test_the_impulse_is_in_the_answer():
    # NEWCOMER m18: J = m (v0 - v), as the text report, check and formula name it.
    s = rodimpact.solve(m=1, M=1, a="1/2")
    assert s.impulse == F(8, 11) == 1 * (1 - s.v)
