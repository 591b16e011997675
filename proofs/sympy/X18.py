#!/usr/bin/env python3
# rodimpact prove --export: claim X18 (beyond the paper)
# Pivoted rod (fixed axis): omega = (1+e) m d v0/(I_p + m d^2), maximal at d* = sqrt(I_p/m) (inside a door iff M < 3m). The pivot impulse vanishes at d = I_p/(M h), the centre of percussion (2L/3 for a door)
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
J = Symbol("J", real=True)
J_s = Symbol("J_s", real=True)
L = Symbol("L", positive=True)
M = Symbol("M", positive=True)
P = Symbol("P", real=True)
P_s = Symbol("P_s", real=True)
d = Symbol("d", positive=True)
ds = Symbol("ds", positive=True)
e = Symbol("e", positive=True)
h = Symbol("h", positive=True)
m = Symbol("m", positive=True)
omega = Symbol("omega", real=True)
omega_s = Symbol("omega_s", real=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
v_s = Symbol("v_s", real=True)
balance = [
    ((m * v) - (m * v0)) - ((-J)),  # projectile: impulse -J
    ((M * h) * omega) - ((J + P)),  # rod, linear: impulses J and the pivot's P
    (Ip * omega) - ((J * d)),  # rod, angular: moment of J
    ((omega * d) - v) - ((e * v0)),  # Newton's law, restitution e
    ((m * v_s) - (m * v0)) - ((-J_s)),  # projectile: impulse -J (impact s, at ds)
    ((M * h) * omega_s) - ((J_s + P_s)),  # rod, linear: impulses J and the pivot's P (impact s, at ds)
    (Ip * omega_s) - ((J_s * ds)),  # rod, angular: moment of J (impact s, at ds)
    ((omega_s * ds) - v_s) - ((e * v0)),  # Newton's law, restitution e (impact s, at ds)
]
unknowns = [J, J_s, P, P_s, omega, omega_s, v, v_s]
definitions = [
    (ds, sqrt((Ip / m))),  # hypothesis of the claim
]
filters = [
]

ok = True

# check 1: omega = (1+e) m d v0/(I_p + m d^2)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("omega = (1+e) m d v0/(I_p + m d^2)", "holds", lambda at: EQ(at(omega), at((((((Integer(1) + e) * m) * d) * v0) / (Ip + (m * (d ** 2)))))), found) and ok

# check 2: the unique maximum over d >= 0 is at d* = sqrt(I_p/m)
print("left to z3 (not an identity or a check at given values): the unique maximum over d >= 0 is at d* = sqrt(I_p/m)")

# check 3: door (I_p = M L^2/3): d* < L iff M < 3m
print("left to z3 (not an identity or a check at given values): door (I_p = M L^2/3): d* < L iff M < 3m")

# check 4: the pivot's impulse vanishes iff d = I_p/(M h), the centre of percussion
print("left to z3 (not an identity or a check at given values): the pivot's impulse vanishes iff d = I_p/(M h), the centre of percussion")

# check 5: reading: a wrong centre of percussion, d = I_p/(2 M h), where the impulse would vanish; refuted
print("left to z3 (not an identity or a check at given values): reading: a wrong centre of percussion, d = I_p/(2 M h), where the impulse would vanish; refuted")

# check 6: reading: the impulse vanishes only at d = I_p/(2 M h); refuted
print("left to z3 (not an identity or a check at given values): reading: the impulse vanishes only at d = I_p/(2 M h); refuted")

# check 7: door: at 2L/3 from the hinge
defs = definitions + [(Ip, ((M * (L ** 2)) / Integer(3))), (h, (L / Integer(2))), (d, ((Integer(2) * L) / Integer(3)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("door: at 2L/3 from the hinge", "holds", lambda at: EQ(at(P), at(Integer(0))), found) and ok

sys.exit(0 if ok else 1)
