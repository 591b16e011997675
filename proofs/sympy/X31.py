#!/usr/bin/env python3
# rodimpact prove --export: claim X31 (beyond the paper)
# The paper's a* is unchanged by the projectile's slide along the rod, by friction, by a disc's spin and by the rod's drift: omega(a) = (1+e) u_n a/(a*^2 + a^2) with the paper's a*^2 = I (M + m)/(m M) in every contact case
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
V0 = Symbol("V0", positive=True)
Vt = Symbol("Vt", real=True)
Vt0 = Symbol("Vt0", positive=True)
a = Symbol("a", positive=True)
d = Symbol("d", positive=True)
e = Symbol("e", positive=True)
m = Symbol("m", positive=True)
omega = Symbol("omega", real=True)
rd = Symbol("rd", positive=True)
s = Symbol("s", positive=True)
spin = Symbol("spin", real=True)
v = Symbol("v", real=True)
v0 = Symbol("v0", positive=True)
v0t = Symbol("v0t", positive=True)
vt = Symbol("vt", real=True)
w = Symbol("w", positive=True)
balance = [
    ((m * v) - (m * v0)) - ((-J)),  # projectile: impulse -J
    (M * (V - V0)) - (J),  # rod, linear: impulse J
    (I * omega) - (((a * J) - (d * Jt))),  # rod, angular: moment of (J, Jt) applied at (d, a)
    ((V + (omega * a)) - v) - ((e * (v0 - V0))),  # Newton's law, restitution e
    ((m * vt) - (m * v0t)) - ((-Jt)),  # projectile, along the rod: impulse -Jt
    (M * (Vt - Vt0)) - (Jt),  # rod, along its axis: impulse Jt
    ((m * (rd ** 2)) * (spin - w)) - ((((-Integer(2)) * rd) * Jt)),  # disc, angular about its centre: moment of -Jt at its rim
]
unknowns = [J, Jt, V, Vt, omega, spin, v, vt]
definitions = [
    (d, Integer(0)),  # the rod struck on its axis: the contact point is (d, a) from the centre, d = 0 (a thin rod)
]
filters = [
]

ok = True

# check 1: whatever the tangential impulse: omega (a*^2 + a^2) = (1+e) (v0 - V0) a with the paper's a*^2 = I (M + m)/(m M)
defs = definitions + [(s, sqrt((((M + m) * I) / (m * M))))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("whatever the tangential impulse: omega (a*^2 + a^2) = (1+e) (v0 - V0) a with the paper's a*^2 = I (M + m)/(m M)", "holds", lambda at: EQ(at((omega * ((s ** 2) + (a ** 2)))), at((((Integer(1) + e) * (v0 - V0)) * a))), found) and ok

sys.exit(0 if ok else 1)
