#!/usr/bin/env python3
# rodimpact prove --export: claim X34 (beyond the paper)
# Newton's law with Coulomb friction never gains energy in one planar contact
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
c = Symbol("c", positive=True)
dK = Symbol("dK", positive=True)
e = Symbol("e", positive=True)
lam_s = Symbol("lam_s", positive=True)
lf = Symbol("lf", positive=True)
mu = Symbol("mu", positive=True)
tf = Symbol("tf", positive=True)
ut = Symbol("ut", positive=True)
vn = Symbol("vn", positive=True)
balance = [
]
unknowns = []
definitions = [
]
filters = [
]

ok = True

# check 1: a tilted rod (length 2, mass 1, axis (3, 4)/5) landing on its end at 1 while sliding at 1 on a floor with mu = 1, e = 1: the slip stops before the impact ends, sticks, and the kinetic energy rises by 1/10
defs = definitions + [(a, (Integer(52) / Integer(25))), (b, (Integer(36) / Integer(25))), (c, (Integer(73) / Integer(25))), (vn, Integer(1)), (ut, (-Integer(1))), (e, Integer(1)), (mu, Integer(1)), (lam_s, ((-ut) / (b + (mu * c)))), (lf, ((((c * (Integer(1) + e)) * vn) + (b * ut)) / ((a * c) - (b ** 2)))), (tf, (((((-b) * (Integer(1) + e)) * vn) - (a * ut)) / ((a * c) - (b ** 2)))), (dK, ((((lf * (e - Integer(1))) * vn) + (tf * ut)) / Integer(2)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("a tilted rod (length 2, mass 1, axis (3, 4)/5) landing on its end at 1 while sliding at 1 on a floor with mu = 1, e = 1: the slip stops before the impact ends, sticks, and the kinetic energy rises by 1/10", "exists", lambda at: all([LT(at(lam_s), at(lf)), GE(at((mu * c)), at(b)), EQ(at(dK), at((Integer(1) / Integer(10)))), GT(at(dK), at(Integer(0)))]), found) and ok

sys.exit(0 if ok else 1)
