#!/usr/bin/env python3
# rodimpact prove --export: claim X5 (beyond the paper)
# omega_e = (1+e) v0 a/(a*^2 + a^2): a* does not depend on e or v0. At a* the rotational compliance a^2/I equals the translational compliance 1/m + 1/M, and J(a*) = J(0)/2
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
J = Symbol("J", real=True)
J_0 = Symbol("J_0", real=True)
J_s = Symbol("J_s", real=True)
M = Symbol("M", positive=True)
V = Symbol("V", real=True)
V_0 = Symbol("V_0", real=True)
V_s = Symbol("V_s", real=True)
a = Symbol("a", positive=True)
e = Symbol("e", positive=True)
m = Symbol("m", positive=True)
omega = Symbol("omega", real=True)
omega_0 = Symbol("omega_0", real=True)
omega_s = Symbol("omega_s", real=True)
s = Symbol("s", positive=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
v_0 = Symbol("v_0", real=True)
v_s = Symbol("v_s", real=True)
balance = [
    ((m * v) - (m * v0)) - ((-J)),  # projectile: impulse -J
    (M * V) - (J),  # rod, linear: impulse J
    (I * omega) - ((J * a)),  # rod, angular: moment of J
    ((V + (omega * a)) - v) - ((e * v0)),  # Newton's law, restitution e
    ((m * v_s) - (m * v0)) - ((-J_s)),  # projectile: impulse -J (impact s, at s)
    (M * V_s) - (J_s),  # rod, linear: impulse J (impact s, at s)
    (I * omega_s) - ((J_s * s)),  # rod, angular: moment of J (impact s, at s)
    ((V_s + (omega_s * s)) - v_s) - ((e * v0)),  # Newton's law, restitution e (impact s, at s)
    ((m * v_0) - (m * v0)) - ((-J_0)),  # projectile: impulse -J (impact 0, at 0)
    (M * V_0) - (J_0),  # rod, linear: impulse J (impact 0, at 0)
    (I * omega_0) - ((J_0 * Integer(0))),  # rod, angular: moment of J (impact 0, at 0)
    ((V_0 + (omega_0 * Integer(0))) - v_0) - ((e * v0)),  # Newton's law, restitution e (impact 0, at 0)
]
unknowns = [J, J_0, J_s, V, V_0, V_s, omega, omega_0, omega_s, v, v_0, v_s]
definitions = [
    (s, sqrt((((M + m) * I) / (m * M)))),  # hypothesis of the claim
]
filters = [
]

ok = True

# check 1: omega_e = (1+e) v0 a/(a*^2 + a^2)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("omega_e = (1+e) v0 a/(a*^2 + a^2)", "holds", lambda at: EQ(at(omega), at(((((Integer(1) + e) * v0) * a) / ((s ** 2) + (a ** 2))))), found) and ok

# check 2: a* maximises omega_e over a >= 0 for every e and v0
print("left to z3 (not an identity or a check at given values): a* maximises omega_e over a >= 0 for every e and v0")

# check 3: at a* the rotational compliance equals the translational one
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("at a* the rotational compliance equals the translational one", "holds", lambda at: EQ(at(((s ** 2) / I)), at(((Integer(1) / m) + (Integer(1) / M)))), found) and ok

# check 4: J(a*) = J(0)/2
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("J(a*) = J(0)/2", "holds", lambda at: EQ(at(J_s), at((J_0 / Integer(2)))), found) and ok

sys.exit(0 if ok else 1)
