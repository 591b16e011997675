#!/usr/bin/env python3
# rodimpact prove --export: claim X12 (beyond the paper)
# v = v0 (m - e M_eff)/(m + M_eff) with M_eff = M r_G^2/(r_G^2 + a^2): the projectile bounces back iff m < e M_eff, stops iff m = e M_eff, goes on iff m > e M_eff. Uniform rod, e = 1: M_eff runs over [M/4, M] and the projectile stops at a0 = l sqrt((M - m)/(3m)), which lies on the rod for m <= M <= 4m. It always goes on for e = 0, and at a* for e = 1
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
Me = Symbol("Me", positive=True)
V = Symbol("V", real=True)
V_s = Symbol("V_s", real=True)
a = Symbol("a", positive=True)
e = Symbol("e", positive=True)
l = Symbol("l", positive=True)
m = Symbol("m", positive=True)
omega = Symbol("omega", real=True)
omega_s = Symbol("omega_s", real=True)
r = Symbol("r", positive=True)
s = Symbol("s", positive=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
v_s = Symbol("v_s", real=True)
balance = [
    (m * v0) - (((m * v) + (M * V))),  # linear momentum
    ((m * v0) * a) - ((((m * v) * a) + (I * omega))),  # angular momentum about the fixed point at the rod's centre
    ((V + (omega * a)) - v) - ((e * v0)),  # Newton's law, restitution e
    (m * v0) - (((m * v_s) + (M * V_s))),  # linear momentum (impact s, at s)
    ((m * v0) * s) - ((((m * v_s) * s) + (I * omega_s))),  # angular momentum about the fixed point at the rod's centre (impact s, at s)
    ((V_s + (omega_s * s)) - v_s) - ((e * v0)),  # Newton's law, restitution e (impact s, at s)
]
unknowns = [V, V_s, omega, omega_s, v, v_s]
definitions = [
    (I, (M * (r ** 2))),  # moment of inertia about the centre
    (Me, ((M * (r ** 2)) / ((r ** 2) + (a ** 2)))),  # hypothesis of the claim
    (s, sqrt((((M + m) * (r ** 2)) / m))),  # hypothesis of the claim
]
filters = [
]

ok = True

# check 1: v = v0 (m - e M_eff)/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)
defs = definitions + []
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("v = v0 (m - e M_eff)/(m + M_eff), M_eff = M r_G^2/(r_G^2 + a^2)", "holds", lambda at: EQ(at(v), at(((v0 * (m - (e * Me))) / (m + Me)))), found) and ok

# check 2: bounces back iff m < e M_eff, stops iff m = e M_eff
print("left to z3 (not an identity or a check at given values): bounces back iff m < e M_eff, stops iff m = e M_eff")

# check 3: uniform rod: M_eff in [M/4, M] on the rod
print("left to z3 (not an identity or a check at given values): uniform rod: M_eff in [M/4, M] on the rod")

# check 4: uniform rod, e = 1: the projectile stops at a0 = l sqrt((M - m)/(3m)), on the rod iff M <= 4m
print("left to z3 (not an identity or a check at given values): uniform rod, e = 1: the projectile stops at a0 = l sqrt((M - m)/(3m)), on the rod iff M <= 4m")

# check 5: e = 0: it always goes on
print("left to z3 (not an identity or a check at given values): e = 0: it always goes on")

# check 6: e = 1 at a*: it goes on
print("left to z3 (not an identity or a check at given values): e = 1 at a*: it goes on")

sys.exit(0 if ok else 1)
