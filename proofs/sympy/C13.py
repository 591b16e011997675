#!/usr/bin/env python3
# rodimpact prove --export: claim C13 (Eq. (v))
# v = -(1 - m/M - ma^2/I)/D v0, with D > 0
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

I = Symbol("I", positive=True)
M = Symbol("M", positive=True)
V = Symbol("V", real=True)
a = Symbol("a", positive=True)
m = Symbol("m", positive=True)
omega = Symbol("omega", real=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
balance = [
    (m * v0) - (((m * v) + (M * V))),  # linear momentum
    ((m * v0) * a) - ((((m * v) * a) + (I * omega))),  # angular momentum about the fixed point at the rod's centre
    ((V + (omega * a)) - v) - (v0),  # Newton's law, e = 1
]
unknowns = [V, omega, v]
definitions = [
]
filters = [
]

ok = True

# check 1: Eq. (v)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("Eq. (v)", "holds", lambda at: EQ(at(v), at((((-((Integer(1) - (m / M)) - ((m * (a ** 2)) / I))) / ((Integer(1) + (m / M)) + ((m * (a ** 2)) / I))) * v0))), found) and ok

# check 2: D > 0
print("left to z3 (not an identity or a check at given values): D > 0")

sys.exit(0 if ok else 1)
