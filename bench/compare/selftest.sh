#!/bin/bash
# Self-test of the harness: does it catch a one-byte difference, and only that?
#
#   bench/compare/selftest.sh [BASELINE_BIN] [run.sh options, e.g. --quick]
#
# Builds a wrapper around BASELINE_BIN (default /work/baseline/rodimpact-193b69f) that behaves
# exactly like it, except that for ONE command line it alters ONE byte: of standard output
# (MODE=stdout, the default), of a file the command writes (MODE=file), or the exit status
# (MODE=exit). Then runs run.sh BASELINE WRAPPER and checks that exactly that one command is
# reported, and that the summary says 1 differ. Exit 0 when the harness passed the test.
set -u
here=$(cd "$(dirname "$0")" && pwd)
base=${1:-/work/baseline/rodimpact-193b69f}
[ "$#" -gt 0 ] && shift
mode=${MODE:-stdout}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rodimpact-selftest.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

case $mode in
    stdout) target='solve --m 1 --M 1' ;;                 # a [q] line of commands.txt
    file) target='table --out t.md' ;;                    # a [q] line that writes t.md
    exit) target='check --m 1 --M 1 --a 1/2 --claim omega=0.343' ;;   # a [q] line too
    *) echo "selftest: MODE must be stdout, file or exit" >&2; exit 2 ;;
esac

cat > "$tmp/wrapper" <<EOF
#!/bin/bash
# rodimpact, except for one command line: $target ($mode)
base='$base'
if [ "\$*" != '$target' ]; then
    exec -a rodimpact "\$base" "\$@"
fi
out=\$(mktemp)
(exec -a rodimpact "\$base" "\$@") > "\$out"
rc=\$?
flip() { python3 -c 'import sys; p = sys.argv[1]; b = bytearray(open(p, "rb").read()); b[min(10, len(b) - 1)] ^= 0x01; open(p, "wb").write(bytes(b))' "\$1"; }
case '$mode' in
    stdout) flip "\$out" ;;
    file) flip t.md ;;
    exit) rc=\$((rc + 1)) ;;
esac
cat "\$out"
rm -f "\$out"
exit \$rc
EOF
chmod +x "$tmp/wrapper"

"$here/run.sh" "$base" "$tmp/wrapper" "$@" > "$tmp/report" 2> "$tmp/stderr"
rc=$?
cat "$tmp/report"
reported=$(grep -c '^DIFF ' "$tmp/report")
summary=$(tail -n 1 "$tmp/report")
ok=1
[ "$rc" -eq 1 ] || { echo "selftest: run.sh exited $rc, expected 1" >&2; ok=0; }
[ "$reported" -eq 1 ] || { echo "selftest: $reported commands reported, expected 1" >&2; ok=0; }
grep -q "^DIFF .*: rodimpact $target\$" "$tmp/report" || { echo "selftest: the altered command '$target' was not the one reported" >&2; ok=0; }
case $summary in
    *", 1 differ") ;;
    *) echo "selftest: summary '$summary' does not say 1 differ" >&2; ok=0 ;;
esac
if [ $ok = 1 ]; then
    echo "selftest ($mode): PASS, exactly '$target' reported"
    exit 0
fi
echo "selftest ($mode): FAIL" >&2
exit 1
