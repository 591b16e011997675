#!/usr/bin/env python3
# rodimpact prove --export: claim X30 (beyond the paper)
# The frictional energy loss: the kinetic energy lost is (1 - e^2) u_n^2/(2 k_n) to restitution plus u_t^2/(2 k_t) when the contact sticks or mu_f J (|u_t| - mu_f J k_t/2) when it slides; the sliding loss is positive
# Not stated here: the sticking loss u_t^2/(2 k_t) is certified by rodimpact only: one scene per exported statement
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
Jt = Symbol("Jt", real=True)
M = Symbol("M", positive=True)
V = Symbol("V", real=True)
Vt = Symbol("Vt", real=True)
a = Symbol("a", positive=True)
d = Symbol("d", positive=True)
e = Symbol("e", positive=True)
m = Symbol("m", positive=True)
mu_f = Symbol("mu_f", positive=True)
omega = Symbol("omega", real=True)
rd = Symbol("rd", positive=True)
spin = Symbol("spin", real=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
v0t = Symbol("v0t", positive=True)
vt = Symbol("vt", real=True)
w = Symbol("w", positive=True)
balance = [
    ((m * v) - (m * v0)) - ((-J)),  # projectile: impulse -J
    (M * V) - (J),  # rod, linear: impulse J
    (I * omega) - (((a * J) - (d * Jt))),  # rod, angular: moment of (J, Jt) applied at (d, a)
    ((V + (omega * a)) - v) - ((e * v0)),  # Newton's law, restitution e
    ((m * vt) - (m * v0t)) - ((-Jt)),  # projectile, along the rod: impulse -Jt
    (M * Vt) - (Jt),  # rod, along its axis: impulse Jt
    ((m * (rd ** 2)) * (spin - w)) - ((((-Integer(2)) * rd) * Jt)),  # disc, angular about its centre: moment of -Jt at its rim
    Jt - ((mu_f * J)),  # sliding forward: Coulomb's law, Jt = mu_f J
]
unknowns = [J, Jt, V, Vt, omega, spin, v, vt]
definitions = [
    (d, Integer(0)),  # the rod struck on its axis: the contact point is (d, a) from the centre, d = 0 (a thin rod)
]
filters = [
]

ok = True

# check 1: the normal impulse: J k_n = (1 + e) v0, k_n = 1/m + 1/M + a^2/I
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("the normal impulse: J k_n = (1 + e) v0, k_n = 1/m + 1/M + a^2/I", "holds", lambda at: EQ(at((J * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I)))), at(((Integer(1) + e) * v0))), found) and ok

# check 2: sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (u_t - mu_f J k_t/2), u_t = v0t + w rd, k_t = 3/m + 1/M
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (u_t - mu_f J k_t/2), u_t = v0t + w rd, k_t = 3/m + 1/M", "holds", lambda at: EQ(at(((((m * ((v0 ** 2) + (v0t ** 2))) / Integer(2)) + (((m * (rd ** 2)) * (w ** 2)) / Integer(4))) - (((((m * ((v ** 2) + (vt ** 2))) / Integer(2)) + ((M * ((V ** 2) + (Vt ** 2))) / Integer(2))) + ((I * (omega ** 2)) / Integer(2))) + (((m * (rd ** 2)) * (spin ** 2)) / Integer(4))))), at(((((Integer(1) - (e ** 2)) * (v0 ** 2)) / (Integer(2) * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I)))) + ((mu_f * J) * ((v0t + (w * rd)) - (((mu_f * J) * ((Integer(3) / m) + (Integer(1) / M))) / Integer(2))))))), found) and ok

# check 3: the normal motion's part of the loss: (1 - e^2) v0^2/(2 k_n)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("the normal motion's part of the loss: (1 - e^2) v0^2/(2 k_n)", "holds", lambda at: EQ(at((((m * (v0 ** 2)) / Integer(2)) - ((((m * (v ** 2)) / Integer(2)) + ((M * (V ** 2)) / Integer(2))) + ((I * (omega ** 2)) / Integer(2))))), at((((Integer(1) - (e ** 2)) * (v0 ** 2)) / (Integer(2) * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I)))))), found) and ok

# check 4: the translation along the rod's part: Jt (v0t - Jt (1/m + 1/M)/2)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("the translation along the rod's part: Jt (v0t - Jt (1/m + 1/M)/2)", "holds", lambda at: EQ(at((((m * (v0t ** 2)) / Integer(2)) - (((m * (vt ** 2)) / Integer(2)) + ((M * (Vt ** 2)) / Integer(2))))), at((Jt * (v0t - ((Jt * ((Integer(1) / m) + (Integer(1) / M))) / Integer(2)))))), found) and ok

# check 5: point (rd = 0), sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (v0t - mu_f J k_t/2), k_t = 1/m + 1/M
defs = definitions + [(rd, Integer(0))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("point (rd = 0), sliding: energy lost = (1 - e^2) v0^2/(2 k_n) + mu_f J (v0t - mu_f J k_t/2), k_t = 1/m + 1/M", "holds", lambda at: EQ(at((((m * ((v0 ** 2) + (v0t ** 2))) / Integer(2)) - ((((m * ((v ** 2) + (vt ** 2))) / Integer(2)) + ((M * ((V ** 2) + (Vt ** 2))) / Integer(2))) + ((I * (omega ** 2)) / Integer(2))))), at(((((Integer(1) - (e ** 2)) * (v0 ** 2)) / (Integer(2) * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I)))) + ((mu_f * J) * (v0t - (((mu_f * J) * ((Integer(1) / m) + (Integer(1) / M))) / Integer(2))))))), found) and ok

# check 6: point, still sliding at the end (v0t > mu_f J k_t): the frictional loss is positive
print("left to z3 (not an identity or a check at given values): point, still sliding at the end (v0t > mu_f J k_t): the frictional loss is positive")

# check 7: disc, still sliding at the end (u_t > mu_f J k_t): the frictional loss is positive
print("left to z3 (not an identity or a check at given values): disc, still sliding at the end (u_t > mu_f J k_t): the frictional loss is positive")

sys.exit(0 if ok else 1)
