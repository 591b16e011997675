#!/usr/bin/env python3
# rodimpact prove --export: claim X10 (beyond the paper)
# General e, at a*: v - V = (1-e) v0/2, V = (1+e) m v0/(2(M+m)), K_rot = ((1+e)/2)^2 mu v0^2/2
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
V_s = Symbol("V_s", real=True)
e = Symbol("e", positive=True)
m = Symbol("m", positive=True)
omega_s = Symbol("omega_s", real=True)
s = Symbol("s", positive=True)
v0 = Symbol("v0", positive=True)
v_s = Symbol("v_s", real=True)
balance = [
    (m * v0) - (((m * v_s) + (M * V_s))),  # linear momentum (impact s, at s)
    ((m * v0) * s) - ((((m * v_s) * s) + (I * omega_s))),  # angular momentum about the fixed point at the rod's centre (impact s, at s)
    ((V_s + (omega_s * s)) - v_s) - ((e * v0)),  # Newton's law, restitution e (impact s, at s)
]
unknowns = [V_s, omega_s, v_s]
definitions = [
    (s, sqrt((((M + m) * I) / (m * M)))),  # hypothesis of the claim
]
filters = [
]

ok = True

# check 1: at a*: v - V, V and the rotational energy
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("at a*: v - V, V and the rotational energy", "holds", lambda at: all([EQ(at((v_s - V_s)), at((((Integer(1) - e) * v0) / Integer(2)))), EQ(at(V_s), at(((((Integer(1) + e) * m) * v0) / (Integer(2) * (M + m))))), EQ(at((I * (omega_s ** 2))), at((((((Integer(1) + e) / Integer(2)) ** 2) * ((m * M) / (M + m))) * (v0 ** 2))))]), found) and ok

sys.exit(0 if ok else 1)
