#!/bin/sh
# Compare every user-visible output of two rodimpact binaries over the corpus.
#   bench/compare/run.sh OLD_BIN NEW_BIN [--quick] [--jobs N] [--seed S] [--filter RE] [...]
# Exit 0 when every command is identical, 1 when any differs, 2 on bad usage.
# Runs under `nice -n 10` (COMPARE_NICE=0 to run at normal priority). See README.md.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
if [ "$#" -lt 2 ]; then
    echo "usage: $0 OLD_BIN NEW_BIN [--quick] [--jobs N] [--seed S] [--filter REGEX] [--no-fuzz] [--report FILE] [--keep] [--list]" >&2
    exit 2
fi
exec nice -n "${COMPARE_NICE:-10}" python3 "$here/compare.py" "$@"
