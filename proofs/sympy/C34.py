#!/usr/bin/env python3
# rodimpact prove --export: claim C34 (§intuition ¶1)
# The impulse depends on a
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
J_1 = Symbol("J_1", real=True)
J_2 = Symbol("J_2", real=True)
M = Symbol("M", positive=True)
V_1 = Symbol("V_1", real=True)
V_2 = Symbol("V_2", real=True)
a1 = Symbol("a1", positive=True)
a2 = Symbol("a2", positive=True)
l = Symbol("l", positive=True)
m = Symbol("m", positive=True)
omega_1 = Symbol("omega_1", real=True)
omega_2 = Symbol("omega_2", real=True)
v0 = Symbol("v0", positive=True)
v_1 = Symbol("v_1", real=True)
v_2 = Symbol("v_2", real=True)
balance = [
    ((m * v_1) - (m * v0)) - ((-J_1)),  # projectile: impulse -J (impact 1, at a1)
    (M * V_1) - (J_1),  # rod, linear: impulse J (impact 1, at a1)
    (I * omega_1) - ((J_1 * a1)),  # rod, angular: moment of J (impact 1, at a1)
    ((V_1 + (omega_1 * a1)) - v_1) - (v0),  # Newton's law, e = 1 (impact 1, at a1)
    ((m * v_2) - (m * v0)) - ((-J_2)),  # projectile: impulse -J (impact 2, at a2)
    (M * V_2) - (J_2),  # rod, linear: impulse J (impact 2, at a2)
    (I * omega_2) - ((J_2 * a2)),  # rod, angular: moment of J (impact 2, at a2)
    ((V_2 + (omega_2 * a2)) - v_2) - (v0),  # Newton's law, e = 1 (impact 2, at a2)
]
unknowns = [J_1, J_2, V_1, V_2, omega_1, omega_2, v_1, v_2]
definitions = [
    (I, ((M * (l ** 2)) / Integer(3))),  # uniform rod of length 2l
]
filters = [
]

ok = True

# check 1: the impulse differs between a = 0 and a = l (M = m = l = v0 = 1)
defs = definitions + [(m, Integer(1)), (M, Integer(1)), (l, Integer(1)), (v0, Integer(1)), (a1, Integer(0)), (a2, Integer(1))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("the impulse differs between a = 0 and a = l (M = m = l = v0 = 1)", "exists", lambda at: NE(at(J_1), at(J_2)), found) and ok

sys.exit(0 if ok else 1)
