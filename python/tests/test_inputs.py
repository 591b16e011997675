"""Bad inputs: ValueError with the command line's one-line message, never a crash."""

import decimal
from fractions import Fraction as F

import pytest

import rodimpact

CASES = [
    (dict(m=-1, M=1), "m: must be > 0, got -1", ["--m", "-1", "--M", "1"]),
    (dict(m=1, M=0), "M: must be > 0, got 0", ["--m", "1", "--M", "0"]),
    (dict(m="abc", M=1), "m: not a number: unexpected character 'a' at position 1 in \"abc\"",
     ["--m", "abc", "--M", "1"]),
    (dict(m=1, M=1, a=2), "a: must lie on the rod, |a| <= l = 1, got 2", ["--m", "1", "--M", "1", "--a", "2"]),
    (dict(m=1, M=1, e="3/2"), "e: coefficient of restitution must lie in [0, 1], got 3/2",
     ["--m", "1", "--M", "1", "--e", "3/2"]),
    (dict(m="1/0", M=1), "m: division by zero", ["--m", "1/0", "--M", "1"]),
    (dict(M=1), "m: required, but not given", None),
    (dict(m="1" * 1_000_000, M=1), "m: more than 10000 digits (limit on digits per number)",
     ["--m", "1" * 20_000, "--M", "1"]),
    (dict(m=1, M=1, rod="wood"), "rod: expected uniform, dumbbell, rg=<radius> or I=<inertia>, got 'wood'",
     ["--m", "1", "--M", "1", "--rod", "wood"]),
    (dict(m=1, M=1, l=1, length=2), "length: give either --l or --length, not both",
     ["--m", "1", "--M", "1", "--l", "1", "--length", "2"]),
]


@pytest.mark.parametrize("kwargs,message,flags", CASES)
def test_bad_input_is_a_value_error_with_the_message(kwargs, message, flags):
    with pytest.raises(ValueError) as caught:
        rodimpact.solve(**kwargs)
    assert str(caught.value) == message


@pytest.mark.parametrize("kwargs,message,flags", [c for c in CASES if c[2]])
def test_the_message_is_the_clis(kwargs, message, flags, cli):
    code, out, err = cli("solve", *flags)
    assert code == 2
    assert err.strip() == "error: " + message


def test_a_float_is_refused_not_rounded():
    with pytest.raises(ValueError, match=r"^m: the float 0\.1 is not exact .*pass the number as a string \('0\.1'\)"):
        rodimpact.solve(m=0.1, M=1)
    with pytest.raises(ValueError, match="^a: the float"):
        rodimpact.solve(m=1, M=1, a=0.5)


def test_exact_inputs_of_every_kind():
    want = rodimpact.solve(m="1/4", M="3/4", a="1/2").to_dict()
    assert rodimpact.solve(m=F(1, 4), M=F(3, 4), a=F(1, 2)).to_dict() == want
    assert rodimpact.solve(m="0.25", M="0.75", a="0.5").to_dict() == want
    assert rodimpact.solve(m=decimal.Decimal("0.25"), M="75e-2", a="5/10").to_dict() == want
    assert rodimpact.solve(m="250 g", M="0.75 kg", a="50 cm").to_dict() == want


def test_bools_and_objects_are_refused():
    with pytest.raises(ValueError, match="^m: expected a number, got the bool True$"):
        rodimpact.solve(m=True, M=1)
    with pytest.raises(ValueError, match="^M: expected a number"):
        rodimpact.solve(m=1, M=[1])


def test_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'mass'"):
        rodimpact.solve(m=1, M=1, mass=2)


def test_hostile_strings_do_not_crash():
    for text in ["", " ", "1e999999999", "1/1e-999999", "\x00", "😀", "-", "1/", "nan", "inf", "1e-10001"]:
        try:
            rodimpact.solve(m=text, M=1)
        except ValueError as e:
            assert str(e).startswith("m: "), (text, str(e))


def test_numbers_up_to_the_librarys_limit_not_pythons():
    # CPython refuses str() of ints past 4,300 digits; the library takes 10,000 (RELIABILITY H12).
    big = 10**5000
    assert rodimpact.solve(m=big, M=1).to_dict() == rodimpact.solve(m="1e5000", M=1).to_dict()
    small = rodimpact.solve(m=F(1, big), M=1).to_dict()
    assert small == rodimpact.solve(m="1e-5000", M=1).to_dict()
    for value in (10**20000, F(1, 10**20000)):
        with pytest.raises(ValueError, match=r"^m: more than 10000 digits \(limit"):
            rodimpact.solve(m=value, M=1)
    # A Decimal as its own text: a huge exponent is refused at once, not expanded.
    with pytest.raises(ValueError, match=r"^m: exponent beyond \+-10000"):
        rodimpact.solve(m=decimal.Decimal("1e999999999"), M=1)
    assert rodimpact.solve(m=decimal.Decimal("1E+5"), M=1).to_dict() == rodimpact.solve(
        m=100000, M=1
    ).to_dict()


def test_errors_of_the_right_kind_naming_the_argument():
    # RELIABILITY H13: a lone surrogate named by its field; audit of a non-table a TypeError.
    with pytest.raises(ValueError, match=r"^m: not text the library can read"):
        rodimpact.solve(m="1\ud800", M=1)
    with pytest.raises(TypeError, match=r"^audit: expected a path, a pandas DataFrame"):
        rodimpact.audit(5)
    with pytest.raises(TypeError, match=r"^audit: expected a path"):
        rodimpact.audit([{"m": 1}])
