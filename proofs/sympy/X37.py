#!/usr/bin/env python3
# rodimpact prove --export: claim X37 (beyond the paper)
# A frictionless w x h box (h^2 < 2 w^2) falling flat at v > 0 onto both bottom corners while spinning at omega > 0, 0 <= e <= 1: under simultaneous Newton and Poisson the rising corner takes no impulse exactly when omega >= omega_s = (2v/w) ((6 + 2e) w^2 - e h^2)/((2 - 2e) w^2 + (2 + e) h^2), a threshold above the kinematic 2v/w at which that corner starts to rise; for the 2 x 1 box falling at 1 with e = 1/2, omega_s = 55/13
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

a = Symbol("a", positive=True)
b = Symbol("b", positive=True)
c = Symbol("c", positive=True)
cs = Symbol("cs", positive=True)
e = Symbol("e", positive=True)
h2 = Symbol("h2", positive=True)
l1 = Symbol("l1", positive=True)
m = Symbol("m", positive=True)
v = Symbol("v", positive=True)
w2 = Symbol("w2", positive=True)
balance = [
]
unknowns = []
definitions = [
    (a, (((Integer(4) * w2) + h2) / (m * (w2 + h2)))),  # hypothesis of the claim
    (b, ((h2 - (Integer(2) * w2)) / (m * (w2 + h2)))),  # hypothesis of the claim
    (l1, (((Integer(1) + e) * (v + c)) / a)),  # hypothesis of the claim
    (cs, ((v * (((Integer(6) + (Integer(2) * e)) * w2) - (e * h2))) / (((Integer(2) - (Integer(2) * e)) * w2) + ((Integer(2) + e) * h2)))),  # hypothesis of the claim
]
filters = [
]

ok = True

# check 1: the rising corner moving up (c >= v): after the leading corner's impulse it leaves (Newton's condition) iff c >= cs
print("left to z3 (not an identity or a check at given values): the rising corner moving up (c >= v): after the leading corner's impulse it leaves (Newton's condition) iff c >= cs")

# check 2: the rising corner still approaching (c < v): Newton's condition fails, so that corner pushes
print("left to z3 (not an identity or a check at given values): the rising corner still approaching (c < v): Newton's condition fails, so that corner pushes")

# check 3: the threshold is above the kinematic one (c = v)
print("left to z3 (not an identity or a check at given values): the threshold is above the kinematic one (c = v)")

# check 4: Poisson's compression condition (e = 0) is weaker than Newton's
print("left to z3 (not an identity or a check at given values): Poisson's compression condition (e = 0) is weaker than Newton's")

# check 5: the 2 x 1 box at v = 1, e = 1/2: omega_s = cs = 55/13
defs = definitions + [(w2, Integer(4)), (h2, Integer(1)), (v, Integer(1)), (e, (Integer(1) / Integer(2)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("the 2 x 1 box at v = 1, e = 1/2: omega_s = cs = 55/13", "holds", lambda at: EQ(at(cs), at((Integer(55) / Integer(13)))), found) and ok

sys.exit(0 if ok else 1)
