#!/usr/bin/env python3
"""The scorecard of docs/engines.md from `rodimpact batch` audits of engine output.

Usage:
    rodimpact batch tests/data/engines/rapier2d-0.36.1-f32.csv --ulps 16 --float f32 --out a.csv
    python3 engines/scorecard.py a.csv [b.csv ...] > table.md

Reads audited CSVs (an engine log with the columns `rodimpact batch` appends) and prints one
Markdown row per engine, version, float and scene class: the number of runs, the range of the
energy change (claimed kinetic energy minus the exact energy after the impact, over the energy
before) and the count of each diagnosis. Every number comes from rodimpact's exact audit; this
script only groups and counts. Standard library only.
"""

import csv
import sys
from collections import defaultdict

ORDER = ["energy-gain", "energy-loss", "restitution-ignored", "no-contact", "momentum",
         "angular-momentum", "above-omega-max", "off", "ok"]


def signed(x):
    return f"{x:+.2g}" if x is not None else "-"


def main():
    groups = defaultdict(lambda: {"runs": 0, "low": None, "high": None,
                                  "diagnoses": defaultdict(int)})
    for path in sys.argv[1:]:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                key = (row["engine"], row["version"], row["float"], row["class"])
                g = groups[key]
                g["runs"] += 1
                try:
                    change = float(row["energy_change"])
                except ValueError:
                    change = None
                if change is not None:
                    g["low"] = change if g["low"] is None else min(g["low"], change)
                    g["high"] = change if g["high"] is None else max(g["high"], change)
                for d in row["diagnosis"].split(";"):
                    g["diagnoses"][d] += 1
    print("| engine | version | float | class | runs | energy change | diagnoses |")
    print("|---|---|---|---|---:|---|---|")
    for key in sorted(groups):
        g = groups[key]
        found = ", ".join(f"{d} {g['diagnoses'][d]}" for d in ORDER if g["diagnoses"][d])
        span = f"{signed(g['low'])} .. {signed(g['high'])}"
        print(f"| {' | '.join(key)} | {g['runs']} | {span} | {found} |")


if __name__ == "__main__":
    main()
