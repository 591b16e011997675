#!/usr/bin/env python3
"""Run a corpus of rodimpact command lines with two binaries and compare every output byte.

Usage (normally through run.sh):
    compare.py OLD_BIN NEW_BIN [--quick] [--jobs N] [--seed S] [--filter REGEX] [--no-fuzz]
               [--corpus FILE] [--report DIR] [--keep] [--list] [--diff-lines N] [--timeout S]

For every command line of the corpus (commands.txt, plus the command lines fuzz.py writes for
its generated inputs) each binary runs in a fresh, empty working directory. Both runs of one
command use the SAME directory path (it is created, used, captured and removed for the old
binary, then created again for the new one), so a path the program prints or writes is the same
for both. Both binaries are copied into a private directory under the name `rodimpact` and run
with argv[0] = "rodimpact", so clap's usage lines agree. What is compared, after the documented
normalisations (NORMALISATIONS below, also listed in README.md):

  * the exit status (or the signal, or a timeout),
  * standard output and standard error, byte for byte,
  * every file, directory and symbolic link in the working directory after the run
    (relative path, kind, permission bits, bytes or link target).

Python 3.11 standard library only.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import difflib
import hashlib
import os
import re
import shlex
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SUBCOMMANDS = {"solve", "prove", "paper", "table", "plot", "impact", "check", "formula", "explore",
               "handout", "stability", "batch", "scenes", "simulate", "help"}

# --------------------------------------------------------------------------------------------
# Normalisations. Each is (name, applies(cmd, artifact_name) -> bool, function(bytes) -> bytes).
# Applied identically to the old and the new output before they are compared. Keep this list in
# step with README.md ("Normalisations").
# --------------------------------------------------------------------------------------------

WASM_RE = re.compile(
    rb'(<script type="application/octet-stream" id="rodimpact-wasm">)[A-Za-z0-9+/=\r\n]*(</script>)'
)


def norm_wasm(data: bytes) -> bytes:
    """The base64 (zlib) WebAssembly module inlined in explore's pages: it is the library
    compiled to wasm32 and changes with any change of the library."""
    return WASM_RE.sub(rb"\1[wasm module: normalised by bench/compare]\2", data)


SECONDS_RE = re.compile(rb'("seconds": )-?[0-9][0-9.eE+-]*')
PROVE_MS_RE = re.compile(rb"^([CX][0-9]+ .*?) ( *[0-9]+\.[0-9]{3}) ms", re.M)
MD_LAST_CELL_RE = re.compile(rb"^(\|.*\| )[0-9][0-9.eE+-]*( \|)$", re.M)
NANOS_RE = re.compile(rb'("median_nanos": )-?[0-9][0-9.eE+-]*')


def norm_prove_time(data: bytes) -> bytes:
    """`prove`: each claim's line ends with the time it took to decide (`{:>9.3} ms`), and
    `prove --json` has it as "seconds"."""
    data = SECONDS_RE.sub(rb'\1"[time]"', data)
    return PROVE_MS_RE.sub(lambda m: m.group(1) + b" " + b"[time]".rjust(len(m.group(2))) + b" ms", data)


def norm_simulate_time(data: bytes) -> bytes:
    """`simulate`: the last column of its Markdown tables, `time (s)`, and "seconds" in JSON
    are the measured run time of each integration."""
    data = SECONDS_RE.sub(rb'\1"[time]"', data)
    return MD_LAST_CELL_RE.sub(rb"\1[time]\2", data)


def norm_stability_text(data: bytes) -> bytes:
    """`stability` (md and json): the median time per evaluation (last column, "median_nanos")
    is measured."""
    data = NANOS_RE.sub(rb'\1"[time]"', data)
    return MD_LAST_CELL_RE.sub(rb"\1[time]\2", data)


SVG_TEXT_RE = re.compile(rb"<text[^>]*>([^<]*)</text>")
NUMERIC_LABEL_RE = re.compile(rb"^[-+]?[0-9.,eE+-]+$")


def norm_stability_svg(data: bytes) -> bytes:
    """`stability --plot`: the x axis is the measured time, so every coordinate, the tick
    labels, and even which labels get a leader line move from run to run. What is kept and
    compared: the SVG's first line (its size), every text that is not a number (titles, axis
    names, legend, marker labels, off-scale notes) in order, and the number of markers
    (<circle> and <polygon> elements)."""
    first = data.split(b"\n", 1)[0]
    texts = [t for t in SVG_TEXT_RE.findall(data) if not NUMERIC_LABEL_RE.match(t.strip())]
    counts = b"circles %d, polygons %d" % (data.count(b"<circle"), data.count(b"<polygon"))
    return b"\n".join([b"[stability plot, normalised by bench/compare]", first, counts, *texts]) + b"\n"


TMPNAME_RE = re.compile(rb"(/?\.[^/\s\"']+)\.[A-Za-z0-9]{8}\.tmp")


def norm_tmpname(data: bytes) -> bytes:
    """Error messages about an output file that cannot be written quote the hidden temporary
    file `.<name>.<8 random characters>.tmp` (io::write_atomic): the random part."""
    return TMPNAME_RE.sub(rb"\1.[random].tmp", data)


def is_sub(cmd: list[str], name: str) -> bool:
    return bool(cmd) and cmd[0] == name


NORMALISATIONS = [
    ("wasm-module", lambda cmd, art: True, norm_wasm),
    ("temp-file-name", lambda cmd, art: art == "stderr", norm_tmpname),
    ("prove-time", lambda cmd, art: is_sub(cmd, "prove") and art == "stdout", norm_prove_time),
    ("simulate-time", lambda cmd, art: is_sub(cmd, "simulate") and art == "stdout", norm_simulate_time),
    ("stability-time", lambda cmd, art: is_sub(cmd, "stability") and art == "stdout", norm_stability_text),
    (
        "stability-plot",
        lambda cmd, art: is_sub(cmd, "stability") and art.startswith("file:") and art.endswith(".svg"),
        norm_stability_svg,
    ),
]


def normalise(cmd: list[str], art: str, data: bytes, used: set[str]) -> bytes:
    for name, applies, fn in NORMALISATIONS:
        if applies(cmd, art):
            new = fn(data)
            if new != data:
                used.add(name)
            data = new
    return data


# --------------------------------------------------------------------------------------------
# The corpus
# --------------------------------------------------------------------------------------------


@dataclass
class Command:
    index: int
    line: str  # as written (placeholders kept), for the report
    args: list[str]  # the arguments after the program name, placeholders substituted
    stdin: str | None  # a file to feed on standard input
    setup: str | None  # a shell snippet run in the working directory first
    quick: bool
    origin: str  # file:line


def parse_corpus(path: Path, subst: dict[str, str], origin_name: str) -> list[Command]:
    cmds = []
    for lineno, raw in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        quick = False
        setup = None
        # leading tags: [q] (in --quick), [setup: shell snippet]
        while line.startswith("["):
            end = line.index("]")
            tag = line[1:end].strip()
            line = line[end + 1 :].strip()
            if tag == "q":
                quick = True
            elif tag.startswith("setup:"):
                setup = tag[len("setup:") :].strip()
            else:
                raise SystemExit(f"{path}:{lineno}: unknown tag [{tag}]")
        text = line
        for key, value in subst.items():
            text = text.replace(key, value)
        if setup:
            for key, value in subst.items():
                setup = setup.replace(key, value)
        toks = shlex.split(text)
        stdin = None
        if "<" in toks:
            i = toks.index("<")
            stdin = toks[i + 1]
            toks = toks[:i] + toks[i + 2 :]
        if toks and toks[0] == "rodimpact":
            toks = toks[1:]
        cmds.append(Command(0, line, toks, stdin, setup, quick, f"{origin_name}:{lineno}"))
    return cmds


# --------------------------------------------------------------------------------------------
# Running
# --------------------------------------------------------------------------------------------


@dataclass
class Result:
    status: str  # "exit 0", "signal 9", "timeout"
    stdout: bytes
    stderr: bytes
    files: dict[str, tuple[str, int, bytes]]  # relpath -> (kind, mode bits, content or target)
    seconds: float


def snapshot(root: Path) -> dict[str, tuple[str, int, bytes]]:
    out: dict[str, tuple[str, int, bytes]] = {}
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        dirnames.sort()
        for name in sorted(dirnames + filenames):
            p = Path(dirpath) / name
            rel = str(p.relative_to(root))
            st = os.lstat(p)
            mode = stat.S_IMODE(st.st_mode)
            if stat.S_ISLNK(st.st_mode):
                out[rel] = ("link", 0, os.readlink(p).encode())
            elif stat.S_ISDIR(st.st_mode):
                out[rel] = ("dir", mode, b"")
            elif stat.S_ISREG(st.st_mode):
                out[rel] = ("file", mode, p.read_bytes())
            else:
                out[rel] = ("other", mode, b"")
    return out


def run_one(binary: Path, cmd: Command, slot: Path, base_env: dict[str, str], timeout: float) -> Result:
    """Run one command in slot/work, with HOME = slot/home and TMPDIR = slot/tmp (both
    snapshotted too, under home/ and tmp/, so a file written anywhere there is compared)."""
    workdir = slot / "work"
    for d in ("work", "home", "tmp"):
        if (slot / d).exists():
            shutil.rmtree(slot / d)
        (slot / d).mkdir(parents=True)
    env = dict(base_env, HOME=str(slot / "home"), TMPDIR=str(slot / "tmp"))
    if cmd.setup:
        subprocess.run(["sh", "-c", cmd.setup], cwd=workdir, env=env, check=True)
    stdin = open(cmd.stdin, "rb") if cmd.stdin else subprocess.DEVNULL
    t0 = time.monotonic()
    try:
        proc = subprocess.Popen(
            ["rodimpact", *cmd.args],
            executable=str(binary),
            cwd=workdir,
            env=env,
            stdin=stdin,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            start_new_session=True,
        )
        try:
            out, err = proc.communicate(timeout=timeout)
            status = f"exit {proc.returncode}" if proc.returncode >= 0 else f"signal {-proc.returncode}"
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, err = proc.communicate()
            status = "timeout"
    finally:
        if cmd.stdin:
            stdin.close()
    seconds = time.monotonic() - t0
    files = snapshot(workdir)
    for d, label in (("home", "$HOME"), ("tmp", "$TMPDIR")):
        for rel, v in snapshot(slot / d).items():
            files[f"{label}/{rel}"] = v
    for d in ("work", "home", "tmp"):
        shutil.rmtree(slot / d)
    return Result(status, out, err, files, seconds)


@dataclass
class Outcome:
    cmd: Command
    same: bool
    details: list[str] = field(default_factory=list)
    seconds_old: float = 0.0
    seconds_new: float = 0.0
    normalised: set[str] = field(default_factory=set)


def first_diff_lines(a: bytes, b: bytes, name: str, max_lines: int) -> list[str]:
    """A short unified diff of a against b: the changed region only, cut to max_lines."""
    def is_text(x: bytes) -> bool:
        return b"\0" not in x[:65536]

    if not (is_text(a) and is_text(b)):
        n = min(len(a), len(b))
        k = next((i for i in range(n) if a[i] != b[i]), n)
        return [f"    {name}: binary content differs ({len(a)} vs {len(b)} bytes, first at byte {k})"]
    la = a.decode("utf-8", "replace").splitlines(keepends=True)
    lb = b.decode("utf-8", "replace").splitlines(keepends=True)
    # trim the common head and tail so that difflib works on the changed region only
    head = 0
    while head < len(la) and head < len(lb) and la[head] == lb[head]:
        head += 1
    tail = 0
    while tail < len(la) - head and tail < len(lb) - head and la[-1 - tail] == lb[-1 - tail]:
        tail += 1
    ctx = 2
    s = max(0, head - ctx)
    ea = min(len(la), len(la) - tail + ctx, s + 400)
    eb = min(len(lb), len(lb) - tail + ctx, s + 400)
    diff = list(
        difflib.unified_diff(la[s:ea], lb[s:eb], fromfile=f"old/{name}", tofile=f"new/{name}", n=ctx)
    )
    out = []
    for d in diff:
        # hunk headers are relative to the trimmed window: shift them back
        if d.startswith("@@"):
            m = re.match(r"@@ -(\d+)(,\d+)? \+(\d+)(,\d+)? @@", d)
            if m:
                d = f"@@ -{int(m.group(1)) + s}{m.group(2) or ''} +{int(m.group(3)) + s}{m.group(4) or ''} @@\n"
        d = d.rstrip("\n")
        if len(d) > 240:
            d = d[:240] + f"... [{len(d) - 240} more characters]"
        out.append("    " + d)
        if len(out) >= max_lines:
            out.append("    ... (diff cut)")
            break
    if not out:
        out = [f"    {name}: differs only in line endings or final newline ({len(a)} vs {len(b)} bytes)"]
    return out


def compare(cmd: Command, old: Result, new: Result, max_lines: int) -> Outcome:
    oc = Outcome(cmd, True, seconds_old=old.seconds, seconds_new=new.seconds)
    if old.status != new.status:
        oc.details.append(f"    status: old {old.status}, new {new.status}")
    if old.status == "timeout" or new.status == "timeout":
        oc.details.append("    timeout: the command did not finish in time (cannot be compared)")
    arts: list[tuple[str, bytes | None, bytes | None]] = [
        ("stdout", old.stdout, new.stdout),
        ("stderr", old.stderr, new.stderr),
    ]
    for rel in sorted(set(old.files) | set(new.files)):
        o = old.files.get(rel)
        n = new.files.get(rel)
        if o is None or n is None:
            oc.details.append(f"    file {rel}: only in {'new' if o is None else 'old'}")
            continue
        if o[0] != n[0]:
            oc.details.append(f"    file {rel}: a {o[0]} in old, a {n[0]} in new")
            continue
        if o[1] != n[1]:
            oc.details.append(f"    file {rel}: mode {o[1]:o} in old, {n[1]:o} in new")
        if o[0] == "link" and o[2] != n[2]:
            oc.details.append(f"    link {rel}: -> {o[2]!r} in old, -> {n[2]!r} in new")
        if o[0] == "file":
            arts.append((f"file:{rel}", o[2], n[2]))
    shown = 0
    for name, a, b in arts:
        if a == b:
            continue
        a2 = normalise(cmd.args, name, a, oc.normalised)
        b2 = normalise(cmd.args, name, b, oc.normalised)
        if a2 == b2:
            continue
        if shown >= 3:
            oc.details.append(f"    {name}: differs too (not shown)")
            continue
        shown += 1
        oc.details.append(f"    {name} differs:")
        oc.details.extend(first_diff_lines(a2, b2, name, max_lines))
    oc.same = not oc.details
    return oc


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--quick", action="store_true", help="the quick subset ([q] lines, fewer fuzzed inputs)")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("COMPARE_JOBS", "1")))
    ap.add_argument("--seed", type=int, default=int(os.environ.get("COMPARE_SEED", "1")))
    ap.add_argument("--filter", help="only command lines matching this regular expression")
    ap.add_argument("--no-fuzz", action="store_true", help="leave out the fuzzed inputs")
    ap.add_argument("--corpus", type=Path, default=HERE / "commands.txt")
    ap.add_argument("--report", type=Path, help="also write the full list of differences here")
    ap.add_argument("--keep", action="store_true", help="keep the temporary directory")
    ap.add_argument("--list", action="store_true", help="print the command lines and exit")
    ap.add_argument("--diff-lines", type=int, default=20)
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per command and binary")
    ap.add_argument("--times", type=Path, help="write each command's run times (old, new) as TSV")
    ap.add_argument("--repo", type=Path, default=REPO, help="the checkout whose input files {R} names")
    args = ap.parse_args()

    for b in (args.old, args.new):
        if not (os.path.isfile(b) and os.access(b, os.X_OK)):
            print(f"compare: not an executable file: {b}", file=sys.stderr)
            return 2

    t_start = time.monotonic()
    tmp = Path(tempfile.mkdtemp(prefix="rodimpact-compare."))
    try:
        # both binaries under one name
        bins = {}
        for side, src in (("old", args.old), ("new", args.new)):
            d = tmp / "bin" / side
            d.mkdir(parents=True)
            shutil.copy2(src, d / "rodimpact")
            bins[side] = d / "rodimpact"
        env = {
            "PATH": "/usr/local/bin:/usr/bin:/bin",
            "LANG": "C.UTF-8",
            "LC_ALL": "C.UTF-8",
            "TZ": "UTC",
        }
        repo = args.repo.resolve()
        subst = {"{R}": str(repo)}

        cmds = parse_corpus(args.corpus, subst, args.corpus.name)
        if not args.no_fuzz:
            fuzzdir = tmp / "fuzz"
            fz = [sys.executable, str(HERE / "fuzz.py"), str(args.seed), str(fuzzdir), "--bin", str(bins["old"])]
            if args.quick:
                fz.append("--quick")
            t0 = time.monotonic()
            subprocess.run(fz, check=True)
            print(f"fuzz: seed {args.seed}, inputs written in {time.monotonic() - t0:.1f} s", file=sys.stderr)
            subst2 = dict(subst, **{"{F}": str(fuzzdir)})
            cmds += parse_corpus(fuzzdir / "commands.txt", subst2, "fuzz/commands.txt")
        if args.quick:
            cmds = [c for c in cmds if c.quick or c.origin.startswith("fuzz/")]
        if args.filter:
            rx = re.compile(args.filter)
            cmds = [c for c in cmds if rx.search(c.line)]
        for i, c in enumerate(cmds, 1):
            c.index = i
        missing = sorted({m for c in cmds for m in re.findall(re.escape(str(repo)) + r"/[^\s'\"]+", c.line.replace("{R}", str(repo)))
                          if not os.path.exists(m) and "nosuch" not in m})
        if missing:
            print(f"compare: WARNING: {len(missing)} input file(s) of the corpus are missing from {repo} "
                  f"(both binaries will just report them missing): " + ", ".join(missing[:10]), file=sys.stderr)
        by_sub: dict[str, int] = {}
        for c in cmds:
            sub = c.args[0] if c.args and not c.args[0].startswith("-") else "(none/flags)"
            sub = sub if sub in SUBCOMMANDS else "(other)"
            by_sub[sub] = by_sub.get(sub, 0) + 1
        if args.list:
            for c in cmds:
                print(f"{c.index}\t{c.origin}\t{c.line}")
            print("by subcommand: " + ", ".join(f"{k} {v}" for k, v in sorted(by_sub.items(), key=lambda kv: -kv[1])),
                  file=sys.stderr)
            return 0

        slots = [tmp / f"w{j}" for j in range(max(1, args.jobs))]
        free = list(slots)
        lock = threading.Lock()

        def job(cmd: Command) -> Outcome:
            with lock:
                slot = free.pop()
            try:
                old = run_one(bins["old"], cmd, slot, env, args.timeout)
                new = run_one(bins["new"], cmd, slot, env, args.timeout)
                return compare(cmd, old, new, args.diff_lines)
            except Exception as e:  # a harness failure is reported as a difference
                return Outcome(cmd, False, [f"    harness error: {type(e).__name__}: {e}"])
            finally:
                with lock:
                    free.append(slot)

        n = len(cmds)
        print(f"running {n} commands ({'quick' if args.quick else 'full'}) with {args.jobs} job(s)", file=sys.stderr)
        identical = 0
        differ = 0
        report_lines: list[str] = []
        normalised_count: dict[str, int] = {}
        times = []
        last_progress = time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
            for k, oc in enumerate(ex.map(job, cmds), 1):
                times.append(oc)
                for name in oc.normalised:
                    normalised_count[name] = normalised_count.get(name, 0) + 1
                if oc.same:
                    identical += 1
                else:
                    differ += 1
                    head = f"DIFF #{oc.cmd.index} ({oc.cmd.origin}): {oc.cmd.line}"
                    block = [head] + oc.details
                    print("\n".join(block), flush=True)
                    report_lines.extend(block)
                now = time.monotonic()
                if sys.stderr.isatty() and now - last_progress > 2:
                    print(f"  {k}/{n} done, {differ} differ", file=sys.stderr, end="\r")
                    last_progress = now
                elif not sys.stderr.isatty() and now - last_progress > 60:
                    print(f"  {k}/{n} done, {differ} differ", file=sys.stderr)
                    last_progress = now
        elapsed = time.monotonic() - t_start
        if normalised_count:
            parts = ", ".join(f"{k} in {v} command(s)" for k, v in sorted(normalised_count.items()))
            print(f"normalised: {parts}", file=sys.stderr)
        print(f"elapsed {elapsed:.1f} s", file=sys.stderr)
        summary = f"{n} commands, {identical} identical, {differ} differ"
        print(summary)
        if args.report:
            args.report.write_text("\n".join(report_lines + [summary]) + "\n", encoding="utf-8")
        if args.times:
            with open(args.times, "w", encoding="utf-8") as f:
                for oc in times:
                    f.write(f"{oc.seconds_old:.3f}\t{oc.seconds_new:.3f}\t{oc.cmd.line}\n")
        return 1 if differ else 0
    finally:
        if args.keep:
            print(f"kept {tmp}", file=sys.stderr)
        else:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
