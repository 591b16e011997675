#!/usr/bin/env python3
# rodimpact prove --export: claim X28 (beyond the paper)
# The stick/slide threshold in closed form (mu_f the Coulomb friction coefficient): the contact sticks iff mu_f >= mu_f* = |u_t| k_n/((1+e) u_n k_t), u_t the slip, u_n the approach speed, k_n = 1/m + 1/M + a^2/I and k_t = 1/m + 1/M (+ 2/m for a solid disc); at mu_f = mu_f* sliding and sticking give the same impulse
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
    (vt + (spin * rd)) - ((Vt - (omega * d))),  # sticking: the disc's contact point ends moving with the rod's, along the rod
]
unknowns = [J, Jt, V, Vt, omega, spin, v, vt]
definitions = [
    (d, Integer(0)),  # the rod struck on its axis: the contact point is (d, a) from the centre, d = 0 (a thin rod)
]
filters = [
]

ok = True

# check 1: disc: the sticking impulse over the normal one is u_t k_n/((1+e) v0 k_t), k_t = 3/m + 1/M
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("disc: the sticking impulse over the normal one is u_t k_n/((1+e) v0 k_t), k_t = 3/m + 1/M", "holds", lambda at: EQ(at((((Jt * (Integer(1) + e)) * v0) * ((Integer(3) / m) + (Integer(1) / M)))), at(((J * (v0t + (w * rd))) * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I))))), found) and ok

# check 2: point (rd = 0): the sticking impulse over the normal one is v0t k_n/((1+e) v0 k_t), k_t = 1/m + 1/M
defs = definitions + [(rd, Integer(0))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("point (rd = 0): the sticking impulse over the normal one is v0t k_n/((1+e) v0 k_t), k_t = 1/m + 1/M", "holds", lambda at: EQ(at((((Jt * (Integer(1) + e)) * v0) * ((Integer(1) / m) + (Integer(1) / M)))), at(((J * v0t) * (((Integer(1) / m) + (Integer(1) / M)) + ((a ** 2) / I))))), found) and ok

# check 3: disc, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*
print("left to z3 (not an identity or a check at given values): disc, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*")

# check 4: disc, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J, so slide and stick coincide
print("left to z3 (not an identity or a check at given values): disc, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J, so slide and stick coincide")

# check 5: point, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*
print("left to z3 (not an identity or a check at given values): point, u_t >= 0: the sticking impulse is within the friction cone (|Jt| <= mu_f J) exactly when mu_f >= mu_f*")

# check 6: point, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J
print("left to z3 (not an identity or a check at given values): point, at mu_f = mu_f*: the sticking impulse obeys the sliding law Jt = mu_f J")

# check 7: reading: the disc's moment of inertia taken as m rd^2/4 (k_t = 5/m + 1/M), it sticks once mu_f reaches that lower threshold; refuted
print("left to z3 (not an identity or a check at given values): reading: the disc's moment of inertia taken as m rd^2/4 (k_t = 5/m + 1/M), it sticks once mu_f reaches that lower threshold; refuted")

# check 8: reading: a disc sticks only above the point's threshold (k_t = 1/m + 1/M); refuted
print("left to z3 (not an identity or a check at given values): reading: a disc sticks only above the point's threshold (k_t = 1/m + 1/M); refuted")

sys.exit(0 if ok else 1)
