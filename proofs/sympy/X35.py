#!/usr/bin/env python3
# rodimpact prove --export: claim X35 (beyond the paper)
# Newton's cradle of three equal balls (e = 1), the first striking the two at rest: simultaneous Newton and Poisson both conserve momentum and energy yet send the first ball back at -v/3 and the others on at 2v/3; sequential impacts, in either order, conserve both too and leave only the last ball moving, at v
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

l1 = Symbol("l1", positive=True)
l2 = Symbol("l2", positive=True)
m = Symbol("m", positive=True)
s1 = Symbol("s1", positive=True)
s2 = Symbol("s2", positive=True)
v = Symbol("v", positive=True)
balance = [
]
unknowns = []
definitions = [
]
filters = [
]

ok = True

# check 1: simultaneous Newton, both contacts pushing (l1, l2 > 0) and leaving at v and 0: the velocities are (-v/3, 2v/3, 2v/3), momentum and energy kept
print("left to z3 (not an identity or a check at given values): simultaneous Newton, both contacts pushing (l1, l2 > 0) and leaving at v and 0: the velocities are (-v/3, 2v/3, 2v/3), momentum and energy kept")

# check 2: sequential, contact 1 then 2: each fires the single-contact impulse (1 + e) |u|/W_ii = m |u|, leaving (0, 0, v)
defs = definitions + [(s1, ((Integer(2) * v) / (Integer(2) / m))), (s2, ((Integer(2) * (s1 / m)) / (Integer(2) / m)))]
found = (solutions(balance, unknowns, defs, filters + [
]), defs)
ok = confirm("sequential, contact 1 then 2: each fires the single-contact impulse (1 + e) |u|/W_ii = m |u|, leaving (0, 0, v)", "holds", lambda at: all([EQ(at((v - (s1 / m))), at(Integer(0))), EQ(at(((s1 / m) - (s2 / m))), at(Integer(0))), EQ(at((s2 / m)), at(v))]), found) and ok

sys.exit(0 if ok else 1)
