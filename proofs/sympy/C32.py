#!/usr/bin/env python3
# rodimpact prove --export: claim C32 (§intuition ¶1)
# About a fixed axis (doors, levers), the farther from the axis one strikes, the bigger the angular velocity (decide it in this paper's setting: a projectile of mass m, speed v0, striking a rod on a fixed pivot)
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

Ip = Symbol("Ip", positive=True)
M = Symbol("M", positive=True)
d1 = Symbol("d1", positive=True)
d2 = Symbol("d2", positive=True)
ds = Symbol("ds", positive=True)
e = Symbol("e", positive=True)
m = Symbol("m", positive=True)
omega_1 = Symbol("omega_1", real=True)
omega_2 = Symbol("omega_2", real=True)
v0 = Symbol("v0", positive=True)
v_1 = Symbol("v_1", real=True)
v_2 = Symbol("v_2", real=True)
balance = [
    ((m * v0) * d1) - ((((m * v_1) * d1) + (Ip * omega_1))),  # angular momentum about the pivot (impact 1, at d1)
    ((omega_1 * d1) - v_1) - ((e * v0)),  # Newton's law, restitution e (impact 1, at d1)
    ((m * v0) * d2) - ((((m * v_2) * d2) + (Ip * omega_2))),  # angular momentum about the pivot (impact 2, at d2)
    ((omega_2 * d2) - v_2) - ((e * v0)),  # Newton's law, restitution e (impact 2, at d2)
]
unknowns = [omega_1, omega_2, v_1, v_2]
definitions = [
]
filters = [
]

ok = True

# check 1: reading: omega grows with the arm d; refuted for a door (Ip = M (2l)^2/3) with M = m = l = v0 = 1, e = 1 between d1 = 1 and d2 = 2
defs = definitions + [(m, Integer(1)), (M, Integer(1)), (Ip, (Integer(4) / Integer(3))), (v0, Integer(1)), (e, Integer(1)), (d1, Integer(1)), (d2, Integer(2))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("reading: omega grows with the arm d; refuted for a door (Ip = M (2l)^2/3) with M = m = l = v0 = 1, e = 1 between d1 = 1 and d2 = 2", "fails", lambda at: ((not all([LT(at(Integer(0)), at(d1)), LT(at(d1), at(d2))])) or LT(at(omega_1), at(omega_2))), found) and ok

# check 2: qualified: it grows on every arm up to d* = sqrt(Ip/m)
print("left to z3 (not an identity or a check at given values): qualified: it grows on every arm up to d* = sqrt(Ip/m)")

sys.exit(0 if ok else 1)
