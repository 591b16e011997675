"""docs/python.md as a notebook: its Python cells run in order, in one namespace, from the
repository's root, and each prints exactly the output block that follows it."""

import contextlib
import io
import os
import re

import pytest

from conftest import REPO

DOC = REPO / "docs" / "python.md"
CELL = re.compile(r"```(python|text)\n(.*?)```", re.S)


def cells():
    """(code, expected output or None) for every ```python cell of the page."""
    found = CELL.findall(DOC.read_text(encoding="utf-8"))
    out = []
    for k, (kind, body) in enumerate(found):
        if kind != "python":
            continue
        expected = found[k + 1][1] if k + 1 < len(found) and found[k + 1][0] == "text" else None
        out.append((body, expected))
    return out


def test_the_page_has_cells():
    assert len(cells()) >= 8


def test_every_cell_prints_its_output(monkeypatch):
    pytest.importorskip("sympy")
    pytest.importorskip("pandas")
    pytest.importorskip("pyarrow")
    monkeypatch.chdir(REPO)
    namespace = {"__name__": "__docs__"}
    for number, (code, expected) in enumerate(cells(), 1):
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(compile(code, f"docs/python.md cell {number}", "exec"), namespace)
        if expected is not None:
            got = "\n".join(line.rstrip() for line in printed.getvalue().splitlines())
            want = "\n".join(line.rstrip() for line in expected.splitlines())
            assert got.rstrip("\n") == want.rstrip("\n"), f"cell {number}:\n{code}"
