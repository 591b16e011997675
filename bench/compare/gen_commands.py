#!/usr/bin/env python3
"""Write bench/compare/commands.txt, the fixed corpus of the comparison harness.

    python3 bench/compare/gen_commands.py [OUT]      (default: commands.txt beside this script)

One command line per line, starting with `rodimpact`. `{R}` stands for the repository's root
(absolute). A leading `[q]` puts the line in the --quick subset; `[setup: SH]` runs the shell
snippet SH in the (fresh, empty) working directory before the command; `< FILE` feeds FILE on
standard input. Output files are named relative to the working directory, which the harness
snapshots after the run. The corpus is deterministic: the same script writes the same file.
Python 3.11 standard library only.
"""

from __future__ import annotations

import itertools
import shlex
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent

lines: list[str] = []
quick_count = 0


def q(s: str) -> str:
    """Quote one argument for the corpus (shlex)."""
    return shlex.quote(s)


def add(cmd: str, quick: bool = False, setup: str | None = None) -> None:
    tags = ""
    if quick:
        tags += "[q] "
    if setup:
        tags += f"[setup: {setup}] "
    lines.append(tags + ("rodimpact " + cmd).rstrip())


def section(title: str) -> None:
    lines.append("")
    lines.append(f"# --- {title}")


def every(n: int):
    """A predicate that is true for every n-th call (to pick a spread quick subset)."""
    state = {"i": 0}

    def f() -> bool:
        state["i"] += 1
        return state["i"] % n == 1

    return f


SUBCOMMANDS = [
    "solve", "prove", "paper", "table", "plot", "impact", "check", "formula", "explore",
    "handout", "stability", "batch", "scenes", "simulate",
]
CLAIMS = [f"C{i}" for i in range(1, 47)] + [f"X{i}" for i in range(1, 39)]

# ---------------------------------------------------------------------------------- meta
section("program: help, version, usage errors")
for c in ["", "--help", "-h", "--version", "-V", "help", "nosuch", "--nosuch", "solve --nosuch 1"]:
    add(c, quick=c in ("", "--help", "--version", "nosuch"))
for s in SUBCOMMANDS:
    add(f"{s} --help", quick=s in ("solve", "batch"))
    add(f"{s} -h")
    add(f"help {s}")

# ---------------------------------------------------------------------------------- paper
section("paper")
add("paper", quick=True)
add("paper --format text")
add("paper --out rep", quick=True)
add("paper --format text --out rep/sub")
add("paper --format html", quick=True)
add("paper --format html --out paper.html", quick=True)
add("paper --format html --summary")
add("paper --format html --summary --out summary.html", quick=True)
add("paper --summary")
add("paper --summary --out rep")
add("paper --format html --out rep")
add("paper --format pdf")
add("paper --out rep", setup="mkdir rep && chmod 700 rep && echo mine > rep/notes.txt && echo old > rep/C1.md && chmod 600 rep/C1.md")
add("paper --out rep", setup="touch rep")
add("paper --out rep", setup="mkdir -p rep/report.md")
add("paper --format html --out paper.html", setup="echo old > paper.html && chmod 640 paper.html")
add("paper --format html --out missing/dir/paper.html")
add("paper --out /dev/null")
add("paper --format html --out /dev/null")

# ---------------------------------------------------------------------------------- prove
section("prove")
add("prove", quick=True)
add("prove --json", quick=True)
pick = every(7)
for cid in CLAIMS:
    add(f"prove {cid}", quick=pick())
    add(f"prove --json {cid}")
add("prove C1 C15 C27 C31 X19", quick=True)
add("prove X35 X36 X37 X38")
add("prove --json X35 X36 X37 X38")
add("prove C15 C1 C15")
add("prove C47")
add("prove X39")
add("prove c1")
add("prove C0")
add("prove ''")
add("prove --write certs", quick=True)
add("prove --write certs --json")
add("prove C15 X19 --write certs")
add("prove --write certs", setup="mkdir certs && chmod 750 certs && echo keep > certs/mine.txt && echo old > certs/C2.md")
add("prove --write certs", setup="mkdir -p certs/C3.md")
add("prove --write certs", setup="echo x > certs")
add("prove --export smt2 smt", quick=True)
add("prove --export sympy py", quick=True)
add("prove X35 X38 --export smt2 smt")
add("prove C1 C2 C3 --export sympy py")
add("prove --export smt2 smt --write certs --json")
add("prove --export z3 out")
add("prove --export smt2")
add("prove C1 --write")

# ---------------------------------------------------------------------------------- table
section("table")
TABLE_ONLY = ["T1", "T2", "T3", "T4", "T5", "T6", "T1,T2,T3,T4,T5,T6", "T6,T1", "T2,T5", "T3,T3"]
pick = every(5)
for fmt in ["md", "latex", "csv"]:
    add(f"table --format {fmt}", quick=True)
    for only in TABLE_ONLY:
        add(f"table --format {fmt} --only {only}", quick=pick())
add("table", quick=True)
add("table --out t.md", quick=True)
add("table --format csv --out t.csv")
add("table --format latex --only T6 --out t.tex")
add("table --format csv --only T1 --out /dev/stdout")
for ratios in ["1,2,3", "1/100,1/10,1,10,100", "0.5,1.5e0,2", "7/3", "1/1000000,1000000", "3,2,1,2"]:
    add(f"table --ratios {ratios}")
    add(f"table --ratios {ratios} --format csv --only T1,T5")
for ratio in ["2", "1/3", "10", "0.75"]:
    add(f"table --ratio {ratio}")
    add(f"table --ratio {ratio} --only T6 --format csv")
for rod in ["dumbbell", "rg=1/2", "I=1/2", "rg=1", "I=1"]:
    add(f"table --rod {rod}")
    add(f"table --rod {rod} --only T6 --format latex")
for e in ["0", "1/2", "0.9"]:
    add(f"table --e {e}")
    add(f"table --e {e} --only T1,T2,T5,T6 --format csv")
for pivot in ["0", "-1", "1/2", "1"]:
    add(f"table --pivot {pivot} --only T1")
    add(f"table --pivot {pivot} --only T1 --format csv")
add("table --only T6 --v0t 2 --a 1/2 --mu-nope 1")
for extra in ["--v0t 2", "--v0t 1/3 --a 1/2", "--a -1/2", "--radius 1/4", "--radius 1/4 --spin 8",
              "--radius 1/2 --spin -3 --v0t 0", "--v0t 0", "--a 0"]:
    add(f"table --only T6 {extra}")
    add(f"table --only T6 {extra} --format csv")
add("table --only T6 --pivot 1")
add("table --only T1 --v0t 2")
add("table --only T4 --rod dumbbell")
add("table --only T4 --e 1/2")
add("table --spin 2 --only T6")
add("table --only T7")
add("table --only ''")
add("table --format html")
add("table --ratios 1,-2")
add("table --ratios 1,x")
add("table --ratio 0")
add("table --e 2")
add("table --rod rg=2")
add("table --a 2 --only T6")
add("table --out nodir/t.md")

# ---------------------------------------------------------------------------------- stability
section("stability")
add("stability", quick=True)
add("stability --format md")
add("stability --format json", quick=True)
add("stability --plot s.svg", quick=True)
add("stability --format json --plot s.svg")
add("stability --format csv")

# ---------------------------------------------------------------------------------- scenes
section("scenes")
add("scenes --suite engines", quick=True)
add("scenes --suite engines --out suite.csv", quick=True)
add("scenes")
add("scenes --suite nope")

# ---------------------------------------------------------------------------------- plot
section("plot")
KINDS = ["omega", "optimum", "figure1", "velocities", "quantities", "energy"]
SAMPLED = {"omega", "optimum", "quantities", "energy"}
PLOT_SCENES = [
    "",
    "--m 1 --M 1",
    "--m 1 --M 3 --a 1/2",
    "--m 2 --M 1 --a -1/3 --e 1/2",
    "--m 1 --M 1 --pivot -1 --a 1/2",
    "--m 1 --M 2 --rod dumbbell --inelastic",
    "--m 1 --M 1 --rod rg=1/2 --pivot 0 --a 1",
    "--m 100g --M 1.5kg --length 120cm --v0 '36 km/h' --from-end 10cm",
    "--m 1 --M 4 --rod I=1/2 --l 2 --a 3/2 --e 0.3",
]
pick = every(4)
for kind in KINDS:
    for scene in PLOT_SCENES:
        data = f" --data {kind}.csv" if kind in SAMPLED else ""
        add(f"plot {kind} --out {kind}.svg{data} {scene}".rstrip(), quick=pick())
    add(f"plot {kind} --out {kind}.png --m 1 --M 2 --a 1/2", quick=kind == "omega")
    add(f"plot {kind} --out {kind}.svg --data {kind}.csv --m 1 --M 1")
for ratios in ["1,2", "1/10,1,10,100", "5"]:
    add(f"plot omega --out o.svg --data o.csv --ratios {ratios}")
    add(f"plot omega --out o.svg --ratios {ratios} --e 1/2 --pivot 0")
add("plot omega --out o.svg --data o.csv --ratios 1,2 --m 1 --M 1")
add("plot nosuch --out x.svg")
add("plot omega")
add("plot omega --out x.pdf")
add("plot omega --out x.svg --m 1")
add("plot figure1 --out x.svg --m 1 --M 1 --a 2")
add("plot optimum --out x.svg --rod I=1e-300")
add("plot optimum --out x.svg --M 1e400 --m 1")
add("plot velocities --out x.svg --m 1 --M 1 --l 1e-10000 --a 1e-10000")
add("plot omega --out x.svg --m 1 --M 1 --pivot 1e-9000")
add("plot omega --out nodir/x.svg")
add("plot omega --out x.svg --data nodir/x.csv")
add("plot omega --out x.svg", setup="ln -s target.svg x.svg")

# ---------------------------------------------------------------------------------- simulate
section("simulate")
SIM = [
    "--m 1 --M 1 --a 1/2 --stiffness 1e6",
    "--m 1 --M 1 --a 1/2 --pivot 0 --stiffness 1e8 --integrator event-rk4",
    "--m 1 --M 2 --a 1/3 --e 1/2 --stiffness 1e5",
    "--m 1 --M 2 --a 1/3 --inelastic --stiffness 1e5",
    "--m 1 --M 1 --a 1 --stiffness 1e6 --geometry frozen",
    "--m 1 --M 1 --a 1/2 --stiffness 1e4 --geometry frozen --integrator verlet --steps 50",
    "--m 2 --M 1 --a -1/2 --stiffness 1e4 --integrator midpoint --dt 1/100000",
    "--m 1 --M 3 --a 1/2 --stiffness 1e4 --integrator backward-euler",
    "--m 1 --M 3 --a 1/2 --stiffness 1e4 --integrator rk4 --rod dumbbell",
    "--m 1 --M 1 --a 1/2 --sweep-k",
    "--m 1 --M 1 --a 1/2 --sweep-k --e 1/2",
]
for i, s in enumerate(SIM):
    add(f"simulate {s}", quick=i in (0, 9))
    add(f"simulate {s} --json", quick=i == 1)
add("simulate --m 1 --M 1 --a 1 --stiffness 1e6")
add("simulate --m 1 --M 1 --a 1/2")
add("simulate --m 1 --M 1 --a 1/2 --stiffness 0")
add("simulate --m 1 --M 1 --a 1/2 --stiffness 1e6 --steps 0")
add("simulate --m 1 --M 1 --a 1/2 --stiffness 1e6 --dt 1")
add("simulate --m 1 --M 1 --a 1/2 --stiffness 1e30 --integrator backward-euler --steps 1000000")

# ---------------------------------------------------------------------------------- handout
section("handout")
HANDOUTS = [
    "",
    "--m 1 --M 1",
    "--m 1 --M 1 --a 1/2",
    "--m 1 --M 3 --a 1 --pivot 0 --inelastic",
    "--m 2 --M 1 --a -1/2 --e 1/2 --rod dumbbell",
    "--m 1 --M 1 --rod rg=1/2 --pivot -1",
    "--m 50g --M 2kg --length 1.2m --v0 30 --inelastic",
    "--m 1 --M 1 --rod I=1/4 --l 2 --a 0",
]
for i, h in enumerate(HANDOUTS):
    add(f"handout {h}".rstrip(), quick=i == 2)
    add(f"handout {h} --out handout.html".replace("  ", " "), quick=i == 3)
add("handout --m 1 --M 1 --a 5 --out handout.html")
add("handout --m -1 --M 1")
add("handout --m 1 --M 1 --out nodir/h.html")

# ---------------------------------------------------------------------------------- explore
section("explore")
EXPLORE = [
    "",
    "--M 1/2 --a 1 --rod dumbbell --no-predict --frame lab",
    "--m 1 --M 2 --e 1/2 --pivot -1",
    "--rod I=1/2",
    "--predict --frame centre-of-mass",
    "--m 2kg --M 3kg --length 2m --from-end 0.5m",
    "--scene paper --v0t 1 --mu 1/2",
    "--scene tilted-rod",
    "--scene tilted-rod --tilt 1/4 --slip -1/2 --mu 1/2 --e 1/2",
    "--scene tilted-rod --tilt 3/4 --slip 0 --mu 0",
]
for i, x in enumerate(EXPLORE):
    add(f"explore {x}".rstrip(), quick=i in (0, 7))
    add(f"explore {x} --out x.html".replace("  ", " "), quick=i in (1, 8))
for bad in ["--M -1", "--a 2", "--scene tilted-rod --tilt 1", "--scene tilted-rod --tilt 0",
            "--scene nope", "--frame side", "--e 3/2", "--scene tilted-rod --mu -1"]:
    add(f"explore {bad}")
add("explore --out nodir/x.html")

# ---------------------------------------------------------------------------------- solve
section("solve: the grid (free and pivoted, e, rod kinds, impact points)")
MASSES = ["--m 1 --M 1", "--m 1 --M 3", "--m 2 --M 1", "--m 3/7 --M 5/2"]
RODS = ["", "--rod uniform", "--rod dumbbell", "--rod rg=1/2", "--rod I=2/5"]
ES = ["", "--e 0", "--e 1/2", "--inelastic", "--elastic --e 1"]
AS = ["", "--a 0", "--a 1", "--a -1", "--a 1/3", "--a -3/4", "--a 0.9"]
PIVOTS = ["", "--pivot 0", "--pivot -1", "--pivot 1/2", "--pivot 1"]
pick = every(37)
k = 0
for rod, e, a, pivot in itertools.product(RODS, ES[:4], AS, PIVOTS):
    m = MASSES[k % len(MASSES)]
    k += 1
    base = " ".join(x for x in ["solve", m, rod, e, a, pivot] if x)
    add(base, quick=pick())
    if k % 3 == 0:
        add(base + " --json")
section("solve: JSON, digits, backends, explain")
SCENES = [
    "--m 1 --M 1 --a 1",
    "--m 1 --M 3 --a 1/2",
    "--m 1 --M 3 --a 1 --pivot 0 --inelastic",
    "--m 4/7 --M 1 --l 1 --a 1/2",
    "--m 1 --M 1 --a 0",
    "--m 2 --M 1 --a -1/2 --e 1/2 --rod dumbbell",
    "--m 1 --M 1 --rod rg=1/2 --pivot -1 --a 1/2",
    "--m 0.100kg --M 1.50 --length 2.00 --from-end 0 --v0 12.0 --inelastic",
    "--m 100g --M 1.5kg --length 120cm --v0 '36 km/h' --a 10cm",
    "--m 1lb --M 2lb --length 3ft --v0 '10 mph' --from-end 1ft",
    "--m 1e-30 --M 1e30 --a 1/2",
    "--m 123456789012345678901234567890 --M 987654321098765432109876543211 --a 1/7",
    "--m 1 --M 1 --a 7.9e-343",
    "--m 1 --M 1 --pivot 1e-622",
    "--m 1 --M 1 --a 1 --e 0.999999",
]
pick = every(3)
for s in SCENES:
    add(f"solve {s}", quick=pick())
    add(f"solve {s} --json")
    add(f"solve {s} --json --digits 50")
    add(f"solve {s} --digits 5")
    add(f"solve {s} --digits 1")
    for b in ["exact", "f64", "f32", "interval"]:
        add(f"solve {s} --backend {b}")
    add(f"solve {s} --backend f64 --json", quick=s == SCENES[0])
    add(f"solve {s} --backend interval --json")
    add(f"solve {s} --explain", quick=s == SCENES[1])
    for fmt in ["text", "markdown", "latex"]:
        add(f"solve {s} --explain {fmt}")
    add(f"solve {s} --explain latex --standalone")
add("solve --m 1 --M 1 --digits 100")
add("solve --m 1 --M 1 --digits 1000 --json")
add("solve --m 1 --M 1 --backend f64 --a 1e-300")
add("solve --m 1 --M 1 --backend f32 --a 1e-40")
add("solve --m 1 --M 1 --backend f32 --M 1e39")
add("solve --m 1 --M 1 --explain markdown --standalone")
add("solve --m 1 --M 1 --explain html")

section("solve: oblique, friction, discs, moving rods")
OBL = [
    "--m 1 --M 2 --a 1/2 --v0 3 --v0t 2 --e 1/2 --mu 1/5 --digits 6",
    "--m 1 --M 3 --a 1/2 --v0 2 --mu 1/2 --radius 1/4 --spin 8",
    "--m 1 --M 3 --a 1/2 --v0 2 --mu 1/2 --radius 1/4 --spin 8 --json",
    "--m 1 --M 1 --v0t 1",
    "--m 1 --M 1 --v0t 1 --mu 1",
    "--m 1 --M 1 --v0t -1 --mu 1/10",
    "--m 1 --M 1 --v0t 1 --mu 1 --pivot 0",
    "--m 1 --M 1 --v0t 1 --mu 1/3 --pivot -1 --a 1/2 --e 0",
    "--m 1 --M 2 --radius 1/2",
    "--m 1 --M 2 --radius 1/2 --spin -4 --mu 1",
    "--m 1 --M 2 --rod-v 1/2",
    "--m 1 --M 2 --rod-v -1 --rod-vt 1 --mu 1/2",
    "--m 1 --M 2 --rod-omega 1 --a 1/2",
    "--m 1 --M 2 --rod-omega -1/2 --a -1/2 --rod-v 1/4 --rod-vt -1/4 --v0t 1/2 --mu 1/4 --radius 1/10 --spin 3",
    "--m 1 --M 2 --rod dumbbell --v0t 2 --mu 1/2 --e 1/2",
    "--m 1 --M 2 --rod rg=1/2 --v0t 2 --mu 0",
    "--m 1 --M 2 --rod I=1/2 --v0t 2 --mu 1e-3 --a 0",
    "--m 1 --M 1 --v0t 1 --mu 1 --backend f64",
    "--m 1 --M 1 --v0t 1 --mu 1 --explain",
    "--m 1 --M 1 --v0t 1 --mu 1 --radius 1/2 --spin 2 --explain latex",
    "--m 1 --M 1 --v0t 1 --mu 1/10 --explain markdown",
    "--m 1 --M 1 --rod-omega 2 --a 1 --explain",
]
for i, s in enumerate(OBL):
    add(f"solve {s}", quick=i in (0, 1, 13))
    if "--json" not in s and "--explain" not in s:
        add(f"solve {s} --json")
section("solve: textbook flags")
for s in ["--length 2", "--length 4 --from-end 1", "--length 1.20 --from-end 0",
          "--from-end 1/2", "--from-end 0 --pivot -1", "--l 3 --a 2", "--length 2m --from-end 25cm",
          "--l 2 --a 2 --v0 5", "--length 0.8 --from-end 0 --pivot -0.4 --inelastic"]:
    add(f"solve --m 1 --M 1 {s}", quick=s == "--length 4 --from-end 1")
    add(f"solve --m 1 --M 1 {s} --json")
section("solve: refused inputs (exit 2)")
BAD = [
    "", "--m 1", "--M 1", "--m -1 --M 1", "--m 0 --M 1", "--m 1/0 --M 1", "--m 1 --M 1 --a 2",
    "--m 1 --M 1 --a -1.0001", "--m 1 --M 1 --e 2", "--m 1 --M 1 --e -1/2", "--m 1 --M 1 --pivot 2",
    "--m 1 --M 1 --pivot 1 --a 1", "--m 1 --M 1 --rod nope", "--m 1 --M 1 --rod rg=-1",
    "--m 1 --M 1 --rod I=0", "--m x --M 1", "--m 1kg --M 1m", "--m 1 --M 1 --v0 0",
    "--m 1 --M 1 --v0 -1", "--m 1 --M 1 --l 0", "--m 1 --M 1 --length 2 --l 1",
    "--m 1 --M 1 --a 1 --from-end 0", "--m 1 --M 1 --from-end 3", "--m 1 --M 1 --elastic --inelastic",
    "--m 1 --M 1 --e 1/2 --inelastic", "--m 1 --M 1 --mu -1", "--m 1 --M 1 --spin 1",
    "--m 1 --M 1 --radius -1", "--m 1 --M 1 --rod-v 2", "--m 1 --M 1 --rod-v 1",
    "--m 1 --M 1 --digits 0", "--m 1 --M 1 --digits 10001", "--m 1 --M 1 --backend f16",
    "--m 1 --M 1 --backend f64 --v0t 1", "--m 1 --M 1 --standalone", "--m 1e10001 --M 1",
    "--m 1e-10001 --M 1", "--m '1 2' --M 1", "--m '' --M 1", "--m 1/ --M 1", "--m 0x10 --M 1",
    "--m 1.5.5 --M 1", "--m '1 ; 2' --M 1", "--m '\u00e9' --M 1", "--m 1 --M 1 --m 2",
    "--m 1 --M 1 --explain latex --json",
]
for i, b in enumerate(BAD):
    add(f"solve {b}".rstrip(), quick=i % 6 == 0)

# ---------------------------------------------------------------------------------- check
section("check: numbers, fractions, formulas")
CHECKS = [
    "--m 0.100kg --M 1.50 --length 2.00 --from-end 0 --v0 12.0 --inelastic --claim omega=1.89 --claim omega=0.947 --claim 'omega=18.1 rpm'",
    "--m 1 --M 1 --a 1/2 --claim omega=0.343",
    "--m 1 --M 1 --a 'a*' --claim omega=1.22 --claim v=1/2 --claim V=0.5",
    "--m 1 --M 1 --a '-a*' --claim omega=-1.22",
    "--m 1 --M 1 --claim v=3/5 --claim V=2/5 --claim omega=6/5 --claim impulse=2/5",
    "--m 1 --M 1 --claim v=0.6 --claim V=0.4 --claim omega=1.2 --claim energy_before=0.5 --claim energy_after=0.5 --claim energy_lost=0",
    "--m 1 --M 1 --claim v=0.61 --claim V=2/5 --claim omega=1.3",
    "--m 1 --M 1 --claim a_star=0.816 --claim omega_max=1.22",
    "--m 1 --M 3 --a 1 --pivot 0 --inelastic --claim pivot_impulse=-1/2 --claim omega=1/2",
    "--m 1 --M 1 --claim 'omega=1.2 rad/s' --claim 'omega=68.75 deg/s' --claim 'omega=11.5 rpm' --claim 'omega=0.191 rev/s'",
    "--m 1 --M 1 --claim 'impulse=0.4 N*s' --claim 'energy_before=0.5 J' --claim 'energy_before=0.0005 kJ'",
    "--m 1 --M 1 --claim V_cm=0.2",
    "--m 1 --M 1 --sig 2 --claim omega=1.2",
    "--m 1 --M 1 --sig 5 --claim omega=1.2",
    "--m 1 --M 1 --claim omega=1.21",
    "--m 1 --M 1 --claim omega=2.4",
    "--m 1 --M 1 --claim omega=-1.2",
    "--m 1 --M 2 --a 1/2 --v0 3 --v0t 2 --e 1/2 --mu 1/5 --claim vt=38/25 --claim Vt=0.24 --claim tangential_impulse=12/25",
    "--m 1 --M 3 --a 1/2 --v0 2 --mu 1/2 --radius 1/4 --spin 8 --claim spin=16/5 --claim vt=-0.6",
    "--M 2*m --claim 'omega=(a*v0+a*v0)/(a^2+l^2)'",
    "--M m --claim 'omega_max=sqrt(6)/2*v0/l'",
    "--M 3*m --claim 'omega_max=3/4*v0/l'",
    "--claim 'a_star=sqrt((M+m)/(3*m))*l'",
    "--rod I=I --claim 'a_star=sqrt((M+m)*I/(m*M))'",
    "--rod I=I --claim 'v=-(1-m/M-m*a^2/I)/(1+m/M+m*a^2/I)*v0' --claim 'V=2*m/M*v0/(1+m/M+m*a^2/I)'",
    "--rod rg=r --claim 'a_star=sqrt((M+m)/m)*r'",
    "--rod rg=r --a r --claim 'omega=2*m*v0*r/(M*r^2+m*r^2+M*r^2)'",
    "--length L --a L/2 --elastic --claim 'omega=12*m*v0/((M+4*m)*L)' --claim 'omega=6*m*v0/((M+4*m)*L)'",
    "--M m --a l --v0t v0t --mu mu --claim 'tangential_impulse=2/5*mu*m*v0' --claim 'vt=v0t/3'",
    "--M 4*m --a L/4 --length L --claim 'omega=3*v0/(4*L)'",
    "--e e --claim 'omega=(1+e)*3*m*a*v0/(M*l^2+3*m*a^2+m*l^2)'",
    "--pivot p --claim 'omega=x'",
    "--a 2*l --claim v=0",
    "--M -m --claim v=0",
    "--m 1 --M 1 --claim nope=1",
    "--m 1 --M 1 --claim omega",
    "--m 1 --M 1 --claim 'omega=(('",
    "--m 1 --M 1 --claim 'omega=1/0'",
    "--m 1 --M 1 --claim 'omega=1.2 kg'",
    "--m 1 --M 1",
    "--m 1 --M 1 --sig 0 --claim omega=1.2",
    "--m 1e9000 --M 1 --claim a_star=1",
    "--M 'm*(l+123456789012*v0)^16/(l+987654321098*v0)^16' --claim v=1",
]
pick = every(4)
for c in CHECKS:
    add(f"check {c}", quick=pick() or c == "--m 1 --M 1 --a 1/2 --claim omega=0.343")
    add(f"check {c} --json")
section("check: problem files")
for f in ["examples/textbook.toml", "examples/oblique.toml"]:
    add(f"check {{R}}/{f}", quick=True)
    add(f"check {{R}}/{f} --json", quick=True)
    add(f"check {{R}}/{f} --sig 2")
    add(f"check {{R}}/{f} --sig 4 --json")
add("check {R}/examples/textbook.toml --m 1")
add("check {R}/nosuch.toml")
add("check {R}/examples/impacts/box-corner.toml")
add("check {R}/README.md")
add("check /dev/null")
add("check /dev/stdin < {R}/examples/oblique.toml")

# ---------------------------------------------------------------------------------- formula
section("formula")
FORMULAS = [
    "",
    "--M 2*m --e e",
    "--M m",
    "--M 3*m",
    "--m 1 --M 1",
    "--m 1 --M 1 --a 1/2 --e 1/2",
    "--pivot p",
    "--pivot -l --a a",
    "--rod dumbbell",
    "--rod rg=r",
    "--rod I=I",
    "--rod rg=r --a r",
    "--length L --a L/2",
    "--length L --from-end d",
    "--e e --pivot 0",
    "--inelastic",
    "--M 4*m --a L/4 --length L",
    "--M m --a l --v0t v0t --mu mu",
    "--M m --a l --v0t v0t",
    "--v0t v0t --mu mu --e e",
    "--v0t v0t --mu 1/2 --M m",
    "--m 1 --M 1 --v0t 1 --mu mu",
    "--M m --radius rd --spin w --mu mu",
    "--M m --radius rd --mu mu --v0t v0t",
    "--M m --rod-v V0",
    "--M m --rod-v V0 --rod-vt Vt0 --mu mu --v0t v0t",
    "--M m --rod-omega omega0",
    "--pivot p --v0t v0t --mu mu",
    "--M m --rod-v 2*v0",
    "--M -m",
    "--a 2*l",
    "--v0t v0t --mu -mu",
    "--radius -rd",
    "--v0 -v0",
    "--M 'm*(l+123456789012*v0)^16/(l+987654321098*v0)^16'",
    "--m '(('",
]
pick = every(4)
for f in FORMULAS:
    for fmt in ["", "--format text", "--format latex", "--format markdown", "--format json",
                "--format md", "--format tex", "--format txt", "--format latex --standalone"]:
        if fmt and f in ("--M -m", "--a 2*l", "--v0 -v0", "--m '(('", "--radius -rd", "--v0t v0t --mu -mu",
                         "--M 'm*(l+123456789012*v0)^16/(l+987654321098*v0)^16'", "--M m --rod-v 2*v0"):
            continue
        add(f"formula {f} {fmt}".strip().replace("  ", " "), quick=pick() and fmt in ("", "--format json"))
add("formula --format html")
add("formula --standalone")

# ---------------------------------------------------------------------------------- impact
section("impact: every example under every law, model and format")
IMPACT_FILES = sorted(p.relative_to(REPO).as_posix() for p in (REPO / "examples/impacts").glob("*.toml"))
IMPACT_FILES += sorted(p.relative_to(REPO).as_posix() for p in (REPO / "examples/impacts/published").glob("*.toml"))
MODELS = ["simultaneous-newton", "simultaneous-poisson", "sequential", "pgs:1", "pgs:10", "all", "pgs:4"]
for f in IMPACT_FILES:
    text = (REPO / f).read_text(encoding="utf-8")
    ncontacts = text.count("[[contact]]")
    path = "{R}/" + f
    add(f"impact {path}", quick=True)
    for law in ["newton", "poisson", "energetic", "all"]:
        for fmt in ["text", "json"]:
            add(f"impact {path} --law {law} --format {fmt}")
    add(f"impact {path} --digits 50")
    add(f"impact {path} --format json --digits 50")
    add(f"impact {path} --digits 1")
    if ncontacts > 1:
        for model in MODELS:
            for fmt in ["text", "json"]:
                add(f"impact {path} --model {model} --format {fmt}", quick=model == "pgs:1" and fmt == "text")
        order = ",".join(str(i) for i in range(ncontacts, 0, -1))
        add(f"impact {path} --model sequential:{order}")
        add(f"impact {path} --model sequential:{order} --format json --digits 40")
        add(f"impact {path} --model sequential:1")
        add(f"impact {path} --law newton --model simultaneous-newton")
    else:
        add(f"impact {path} --model pgs:1")
add("impact")
add("impact {R}/nosuch.toml")
add("impact {R}/examples/textbook.toml")
add("impact {R}/examples/impacts/box-corner.toml --law nope")
add("impact {R}/examples/impacts/cradle-3.toml --model pgs:0")
add("impact {R}/examples/impacts/cradle-3.toml --model sequential:1,1")
add("impact {R}/examples/impacts/cradle-3.toml --model sequential:3,1")
add("impact {R}/examples/impacts/cradle-3.toml --model nope")
add("impact {R}/examples/impacts/box-corner.toml --digits 0")
add("impact {R}/examples/impacts/box-corner.toml --format yaml")
add("impact /dev/stdin < {R}/examples/impacts/box-corner.toml")
section("impact --batch")
JSONL = ["engines/impacts.jsonl"] + sorted(
    p.relative_to(REPO).as_posix() for p in (REPO / "tests/data/engines/impacts").glob("*.jsonl"))
for f in JSONL:
    path = "{R}/" + f
    add(f"impact --batch {path}", quick=True)
    add(f"impact --batch {path} --rtol 1e-3", quick=True)
    add(f"impact --batch {path} --rtol 1e-2")
    add(f"impact --batch {path} --rtol 0")
    add(f"impact --batch {path} --rtol 1")
    add(f"impact --batch {path} --format text")
    add(f"impact --batch {path} --format json --rtol 1e-3")
    add(f"impact --batch {path} --law newton")
    add(f"impact --batch {path} --digits 40")
add("impact --batch {R}/engines/impacts.jsonl --rtol 2")
add("impact --batch {R}/engines/impacts.jsonl --rtol -1")
add("impact --batch {R}/engines/impacts.jsonl --rtol x")
add("impact --batch {R}/nosuch.jsonl")
add("impact --batch {R}/engines/suite.csv")
add("impact --batch {R}/engines/impacts.jsonl {R}/examples/impacts/box-corner.toml")
add("impact --batch /dev/stdin < {R}/tests/data/engines/impacts/box2d-2.3.10.jsonl")
add("impact {R}/examples/impacts/box-corner.toml --rtol 1e-3")

# ---------------------------------------------------------------------------------- batch
section("batch: every CSV of tests/data and tests/data/engines in four modes, to stdout and --out")
CSVS = sorted(p.relative_to(REPO).as_posix() for p in (REPO / "tests/data").glob("*.csv"))
CSVS += sorted(p.relative_to(REPO).as_posix() for p in (REPO / "tests/data/engines").glob("*.csv"))
CSVS += ["engines/suite.csv"]
MODES = ["", "--backend f64", "--ulps 16", "--rtol 1e-6"]
for f in CSVS:
    path = "{R}/" + f
    small = (REPO / f).stat().st_size < 200_000
    for mode in MODES:
        add(f"batch {path} {mode}".rstrip(), quick=small and mode in ("", "--ulps 16"))
        add(f"batch {path} {mode} --out out.csv".replace("  ", " "), quick=small and mode == "--rtol 1e-6")
    add(f"batch {path} --summary-json s.json --out out.csv")
    add(f"batch {path} --ulps 16 --summary-json s.json")
    add(f"batch {path} --jobs 1 --ulps 16")
    add(f"batch {path} --jobs 3 --backend f64")
    if "f32" in f:
        add(f"batch {path} --ulps 16 --float f32", quick=small)
        add(f"batch {path} --ulps 16 --float f32 --out out.csv --summary-json s.json")
    add(f"batch {path} --rtol 1e-6 --atol 1e-12")
    add(f"batch {path} --ulps 16 --atol 1e-12")
section("batch: the documented audits and their flags")
D = "{R}/tests/data/engines"
add(f"batch {D}/pymunk-7.3.1-f64.csv --ulps 16 --atol 1e-12 --expect {D}/pymunk-7.3.1-f64-expected.csv --summary-json summary.json --out audited.csv", quick=True)
add(f"batch {D}/pymunk-7.3.1-f64.csv --ulps 16 --expect {D}/pymunk-7.3.1-f64-expected.csv")
add(f"batch {D}/pymunk-7.3.1-f64.csv --expect {D}/pymunk-7.3.1-f64-expected.csv")
add(f"batch {D}/pymunk-7.3.1-f64.csv --rtol 1e-6 --expect {D}/pymunk-7.3.1-f64-expected.csv --summary-json s.json")
add(f"batch {D}/rapier2d-0.36.1-f64.csv --ulps 16 --expect {D}/pymunk-7.3.1-f64-expected.csv")
add(f"batch {D}/tolerance-classes.csv --tolerance pivot=rtol:1e-6 --tolerance free=ulps:2 --out audited.csv", quick=True)
add(f"batch {D}/tolerance-classes.csv --tolerance pivot=rtol:1e-6 --tolerance free=ulps:2")
add(f"batch {D}/tolerance-classes.csv --tolerance 'id:piv-*=exact' --tolerance free=rtol:1e-3")
add(f"batch {D}/tolerance-classes.csv --tolerance oblique=ulps:4 --ulps 1")
add(f"batch {D}/rapier2d-0.36.1-f32.csv --tolerance pivot=rtol:1e-3 --tolerance free=ulps:16 --float f32 --atol 1e-6")
add(f"batch {D}/rapier2d-0.36.1-f64-oblique.csv --tolerance oblique=rtol:1e-9 --summary-json s.json")
add(f"batch {D}/tolerance-classes.csv --tolerance nope=rtol:1")
add(f"batch {D}/tolerance-classes.csv --tolerance pivot=fuzzy:1")
add(f"batch {D}/tolerance-classes.csv --rtol 2")
add(f"batch {D}/tolerance-classes.csv --rtol 1e-10000")
add(f"batch {D}/tolerance-classes.csv --rtol 1/3")
add(f"batch {D}/tolerance-classes.csv --rtol 0.000001")
add(f"batch {D}/tolerance-classes.csv --ulps -1")
add(f"batch {D}/tolerance-classes.csv --ulps 16 --backend f64")
add(f"batch {D}/tolerance-classes.csv --ulps 16 --rtol 1e-6")
add(f"batch {D}/tolerance-classes.csv --atol 2")
add(f"batch {D}/tolerance-classes.csv --jobs 0")
add(f"batch {D}/tolerance-classes.csv --float f16")
add(f"batch {D}/tolerance-classes.csv --expect {{R}}/nosuch.csv")
add(f"batch {D}/tolerance-classes.csv --expect {D}/pymunk-7.3.1-f64-expected.csv")
add(f"batch {{R}}/tests/data/sweep-decimals.csv --expect {D}/pymunk-7.3.1-f64-expected.csv")
add(f"batch {D}/tolerance-classes.csv --out nodir/out.csv")
add(f"batch {D}/tolerance-classes.csv --out out.csv", setup="echo old > out.csv && chmod 604 out.csv")
add(f"batch {D}/tolerance-classes.csv --out out.csv", setup="mkdir out.csv")
add(f"batch {D}/tolerance-classes.csv --out link.csv", setup="ln -s real.csv link.csv")
add(f"batch {D}/tolerance-classes.csv --out /dev/stdout")
add("batch /dev/stdin < {R}/tests/data/sweep-fractions.csv")
add("batch /dev/stdin --backend f64 < {R}/tests/data/sweep-decimals.csv")
add("batch")
add("batch {R}/nosuch.csv")
add("batch {R}/README.md")
add("batch /dev/null")
add("batch {R}/engines/impacts.jsonl")


def main() -> None:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE / "commands.txt"
    header = [
        "# The fixed corpus of bench/compare (written by gen_commands.py: edit that, then rerun it).",
        "# One command line per line; {R} is the repository's root.",
        "# [q]: in the --quick subset. [setup: SH]: SH runs first in the empty working directory.",
        "# `< FILE`: FILE on standard input. Output files go to the working directory.",
    ]
    n = sum(1 for x in lines if x and not x.startswith("#"))
    nq = sum(1 for x in lines if x.startswith("[q]"))
    header.append(f"# {n} command lines, {nq} in the quick subset.")
    out.write_text("\n".join(header + lines) + "\n", encoding="utf-8")
    print(f"{out}: {n} command lines, {nq} quick", file=sys.stderr)


if __name__ == "__main__":
    main()
