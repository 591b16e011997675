#!/usr/bin/env bash
# Whole process against whole process: `rodimpact batch` against Python `fractions` and gmpy2
# evaluating the same closed form (uniform rod, elastic), checking the same three laws and the
# file's claimed v, V, omega, and writing the same rows. Not part of the tests.
#
#   bench/compare.sh [FILE.csv] [ROUNDS]     (default tests/data/bench-1e6.csv, 3 rounds)
#
# Prints the median wall time of each and the ratios. A missing Python module is skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
file="${1:-tests/data/bench-1e6.csv}"
rounds="${2:-3}"
cargo build --release --quiet
bin="target/release/rodimpact"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

cat > "$tmp/closed_form.py" <<'PY'
import sys
backend, path, out = sys.argv[1], sys.argv[2], sys.argv[3]
if backend == "fractions":
    from fractions import Fraction as Q
else:
    from gmpy2 import mpq as Q
wrong = 0
with open(path) as f, open(out, "w") as w:
    header = f.readline().strip()
    w.write(header + ",v_exact,V_exact,omega_exact,laws_held\n")
    for line in f:
        cells = line.strip().split(",")
        m, M, l, a, v0 = (Q(c) for c in cells[:5])
        I = M * l * l / 3
        r, ma_i = m / M, m * a / I
        q = r + ma_i * a
        d = 1 + q
        v, V, w_ = (q - 1) / d * v0, 2 * r / d * v0, 2 * ma_i / d * v0
        laws = (m * v + M * V == m * v0 and m * a * v + I * w_ == m * a * v0
                and m * v * v + M * V * V + I * w_ * w_ == m * v0 * v0)
        claims = [Q(c) for c in cells[5:8]]
        wrong += sum(c != x for c, x in zip(claims, (v, V, w_)))
        w.write(f"{line.strip()},{v},{V},{w_},{'true' if laws else 'false'}\n")
print(f"{backend}: {wrong} wrong", file=sys.stderr)
PY

seconds() { # median wall time of "$@" over $rounds runs
  local times=()
  for _ in $(seq "$rounds"); do
    local start end
    start=$(date +%s.%N)
    "$@" > /dev/null 2>&1
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc -l)")
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n "$(( (rounds + 1) / 2 ))p"
}

rows=$(( $(wc -l < "$file") - 1 ))
echo "file: $file ($rows rows), median of $rounds runs, whole process"
# Standard output into a file, as the Python scripts write theirs: `--out` also syncs the file
# to the disk before renaming it into place (all or nothing), which Python's `open` does not.
ours=$(seconds sh -c '"$0" batch "$1" > "$2"' "$bin" "$file" "$tmp/ours.csv")
printf '%-22s %8.3f s\n' "rodimpact batch" "$ours"
synced=$(seconds "$bin" batch "$file" --out "$tmp/synced.csv")
printf '%-22s %8.3f s   (with --out: written, synced, renamed)\n' "rodimpact batch --out" "$synced"
for backend in fractions gmpy2; do
  module=$([ "$backend" = gmpy2 ] && echo gmpy2 || echo fractions)
  if ! python3 -c "import $module" 2>/dev/null; then
    echo "$backend: python3 module '$module' not available, skipped"
    continue
  fi
  t=$(seconds python3 "$tmp/closed_form.py" "$backend" "$file" "$tmp/$backend.csv")
  printf '%-22s %8.3f s   rodimpact is %5.1fx faster\n' "python $backend" "$t" \
    "$(echo "$t / $ours" | bc -l)"
done
