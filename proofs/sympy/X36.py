#!/usr/bin/env python3
# rodimpact prove --export: claim X36 (beyond the paper)
# Projected Gauss-Seidel on Newton's cradle of three equal balls (e = 1): one sweep from zero impulses loses exactly half the energy, and each further sweep shrinks the impulses' error from the simultaneous Newton answer by exactly 1/4
# Re-derived with SymPy from the balance equations (not from rodimpact's solution): solve
# them for the unknowns, substitute, and check each conclusion exactly. Exit status 0 when
# every check is confirmed. Run: python3 FILE
import sys
from sympy import Integer, Symbol, simplify, solve, sqrt


def zero(x):
    return simplify(x) == 0


def sign(x):
    """The exact sign of x, or exit 1 when SymPy cannot decide it."""
    x = simplify(x)
    if x.is_zero:
        return 0
    if x.is_positive:
        return 1
    if x.is_negative:
        return -1
    sys.exit(f"undecided sign: {x}")


def EQ(x, y):
    return zero(x - y)


def NE(x, y):
    return not zero(x - y)


def LT(x, y):
    return sign(y - x) > 0


def LE(x, y):
    return sign(y - x) >= 0


def GT(x, y):
    return sign(x - y) > 0


def GE(x, y):
    return sign(x - y) >= 0


def substitute(x, definitions):
    """x with every definition applied, until none applies (a definition may use another)."""
    for _ in range(len(definitions) + 1):
        for name, value in definitions:
            x = x.subs(name, value)
    return x


def solutions(balance, unknowns, definitions, filters):
    """The solutions of the balance equations after the definitions, those meeting the filters."""
    equations = [substitute(b, definitions) for b in balance]
    found = solve(equations, unknowns, dict=True) if unknowns else [{}]
    kept = [s for s in found if all(f(lambda x: substitute(x, definitions).subs(s)) for f in filters)]
    if not kept:
        sys.exit("the balance equations have no solution")
    return kept


def confirm(what, expect, holds, found):
    results = [holds(lambda x: substitute(x, found[1]).subs(s)) for s in found[0]]
    ok = all(results) if expect == "holds" else (not all(results) if expect == "fails" else any(results))
    print(("confirmed: " if ok else "NOT confirmed: ") + what)
    return ok

a = Symbol("a", positive=True)
b = Symbol("b", positive=True)
d = Symbol("d", positive=True)
m = Symbol("m", positive=True)
v = Symbol("v", positive=True)
balance = [
]
unknowns = []
definitions = [
]
filters = [
]

ok = True

# check 1: from lam = (4mv/3, 2mv/3 + d): one sweep gives (4mv/3 + d/2, 2mv/3 + d/4)
defs = definitions + [(a, ((((Integer(2) * m) * v) + ((((Integer(2) * m) * v) / Integer(3)) + d)) / Integer(2))), (b, (a / Integer(2)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("from lam = (4mv/3, 2mv/3 + d): one sweep gives (4mv/3 + d/2, 2mv/3 + d/4)", "holds", lambda at: all([EQ(at(a), at(((((Integer(4) * m) * v) / Integer(3)) + (d / Integer(2))))), EQ(at(b), at(((((Integer(2) * m) * v) / Integer(3)) + (d / Integer(4)))))]), found) and ok

# check 2: one sweep from zero: lam = (m v, m v/2), the balls at (0, v/2, v/2), energy m v^2/4
defs = definitions + [(a, (m * v)), (b, (a / Integer(2)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("one sweep from zero: lam = (m v, m v/2), the balls at (0, v/2, v/2), energy m v^2/4", "holds", lambda at: EQ(at(((m * ((((v - (a / m)) ** 2) + (((a - b) / m) ** 2)) + ((b / m) ** 2))) / Integer(2))), at(((m * (v ** 2)) / Integer(4)))), found) and ok

sys.exit(0 if ok else 1)
