#!/usr/bin/env python3
# rodimpact prove --export: claim X33 (beyond the paper)
# Stronge's energetic law never gains energy in one planar contact with Coulomb friction, whatever the slip does; neither does Poisson's law while the slip keeps its mode through the impact
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

Wc = Symbol("Wc", positive=True)
Wf = Symbol("Wf", positive=True)
Wr = Symbol("Wr", positive=True)
e = Symbol("e", positive=True)
k = Symbol("k", positive=True)
lc = Symbol("lc", positive=True)
vn = Symbol("vn", positive=True)
balance = [
]
unknowns = []
definitions = [
]
filters = [
]

ok = True

# check 1: energetic: Wr = -e^2 Wc, so the energy change Wc + Wr + Wf <= 0
print("left to z3 (not an identity or a check at given values): energetic: Wr = -e^2 Wc, so the energy change Wc + Wr + Wf <= 0")

# check 2: Poisson with one slope k through the impact: Wc = -vn^2/(2k), Wr = k (e lam_c)^2/2 = -e^2 Wc
defs = definitions + [(lc, (vn / k)), (Wc, (((-vn) * lc) + ((k * (lc ** 2)) / Integer(2)))), (Wr, ((k * ((e * lc) ** 2)) / Integer(2)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("Poisson with one slope k through the impact: Wc = -vn^2/(2k), Wr = k (e lam_c)^2/2 = -e^2 Wc", "holds", lambda at: EQ(at(Wr), at(((-(e ** 2)) * Wc))), found) and ok

sys.exit(0 if ok else 1)
