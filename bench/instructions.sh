#!/usr/bin/env bash
# Instructions per batch row, counted by callgrind (valgrind), which does not vary with the
# machine's load the way wall time does: the whole process on FILE minus the whole process on
# FILE's header alone, divided by the rows. One thread (RAYON_NUM_THREADS=1). Not a test.
#
#   bench/instructions.sh [FILE.csv] [--backend exact|f64]
#       (default tests/data/bench-1e6.csv, exact; needs valgrind: apt-get install valgrind)
set -euo pipefail
cd "$(dirname "$0")/.."
file="${1:-tests/data/bench-1e6.csv}"
shift || true
command -v valgrind >/dev/null || { echo "error: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
cargo build --release --quiet
bin="target/release/rodimpact"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
head -n 1 "$file" > "$tmp/header.csv"
# batch exits 1 when a claim is wrong (an engine log's usual verdict): counted all the same.
count() {
  { RAYON_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    "$bin" batch "$1" "${@:2}" --out "$tmp/out.csv" 2>&1 || true; } | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
rows=$(( $(wc -l < "$file") - 1 ))
base=$(count "$tmp/header.csv" "$@")
total=$(count "$file" "$@")
echo "$file: $rows rows, $(( (total - base) / rows )) instructions per row (batch ${*:-(exact)}; one thread, callgrind)"
