"""Times rodimpact.audit against `rodimpact batch` on the same file of 10^6 rows.

    python3 python/bench/audit_vs_cli.py PATH/TO/rodimpact [ROWS]

The file is the 10,000 rows of tests/data/bench-1e6.csv (scenes with exact claimed v, V,
omega) repeated to ROWS rows (default 10^6) in a temporary directory. Runs alternate, five of
each; both use the default options and every core: the CLI writes its rows to a file
(`--out`), audit() returns them as a pandas DataFrame. Prints the best and the median of each
and their ratio. Also times audit() fed the same rows as a DataFrame of text columns.
"""

import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import rodimpact

REPO = pathlib.Path(__file__).resolve().parents[2]


def main() -> None:
    cli = sys.argv[1]
    rows = int(sys.argv[2]) if len(sys.argv) > 2 else 1_000_000
    lines = (REPO / "tests" / "data" / "bench-1e6.csv").read_text().splitlines(True)
    header, data = lines[0], lines[1:]
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "rows.csv"
        with open(path, "w") as f:
            f.write(header)
            for k in range(rows):
                f.write(data[k % len(data)])
        out = pathlib.Path(tmp) / "out.csv"
        times = {"cli": [], "audit(path)": []}
        for _ in range(5):
            t = time.perf_counter()
            subprocess.run([cli, "batch", str(path), "--out", str(out)], check=True,
                           stderr=subprocess.DEVNULL)
            times["cli"].append(time.perf_counter() - t)
            out.unlink()
            t = time.perf_counter()
            frame = rodimpact.audit(path)
            times["audit(path)"].append(time.perf_counter() - t)
            assert len(frame) == rows and frame.attrs["summary"].ok
            del frame
        try:
            import pandas as pd

            source = pd.read_csv(path, dtype=str)
            times["audit(DataFrame)"] = []
            for _ in range(3):
                t = time.perf_counter()
                frame = rodimpact.audit(source)
                times["audit(DataFrame)"].append(time.perf_counter() - t)
                del frame
        except ImportError:
            pass
    best_cli = min(times["cli"])
    print(f"{rows} rows")
    for name, runs in times.items():
        print(f"{name:18} best {min(runs):6.2f} s  median {statistics.median(runs):6.2f} s  "
              f"best/CLI best {min(runs) / best_cli:5.2f}")


if __name__ == "__main__":
    main()
