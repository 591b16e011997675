"""audit(): the batch audit from a file, a DataFrame and a pyarrow Table."""

import csv
import random
from fractions import Fraction as F

import pytest

import rodimpact
from conftest import DATA, REPO
from test_solve import derived

pd = pytest.importorskip("pandas")
pa = pytest.importorskip("pyarrow")


def scenes(n, seed=7):
    rng = random.Random(seed)
    rows = []
    for k in range(n):
        m, M = F(rng.randint(1, 40), rng.randint(1, 9)), F(rng.randint(1, 40), rng.randint(1, 9))
        a = F(rng.randint(-10, 10), 10)
        v, V, omega, _ = derived(m, M, F(1), a)
        rows.append(dict(id=f"s{k}", m=m, M=M, a=a, v=v, V=V, omega=omega))
    return rows


def test_dataframe_round_trip_with_exact_claims():
    rows = scenes(300)
    df = pd.DataFrame(rows).set_index("id")
    df["note"] = "kept"
    out = rodimpact.audit(df.reset_index())
    # The input's columns come back as they were, the audit's are appended.
    assert list(out.columns[: 8]) == ["id", "m", "M", "a", "v", "V", "omega", "note"]
    assert out["m"].tolist() == [r["m"] for r in rows]  # still Fractions
    assert (out["note"] == "kept").all()
    assert out["laws_held"].all()
    assert out["v_ok"].all() and out["V_ok"].all() and out["omega_ok"].all()
    assert (out["diagnosis"] == "ok").all()
    assert [F(x) for x in out["omega_exact"]] == [r["omega"] for r in rows]
    assert out["omega_rel_error"].dtype == "float64"
    assert str(out["laws_held"].dtype) == "boolean"
    summary = out.attrs["summary"]
    assert summary.ok and summary.rows == 300
    assert "300 rows, laws held exactly on 300" in summary


def test_the_index_is_kept():
    df = pd.DataFrame({"m": [1, 2], "M": [1, 1]}, index=["first", "second"])
    out = rodimpact.audit(df)
    assert list(out.index) == ["first", "second"]
    assert list(out["omega"]) == ["6/5", "4/3"]


def test_float_claims_an_engine_wrote():
    # The engine's floats are read as their shortest repr, as its CSV would hold them.
    df = pd.DataFrame({"m": [1, 1, 1], "M": [1, 1, 1], "v": [0.6, 0.6000001, 1.0],
                       "V": [0.4, 0.4, 0.0], "omega": [1.2, 1.2, 0.0]})
    out = rodimpact.audit(df, rtol="1e-9")
    assert out["v_ok"].tolist() == [True, False, False]
    assert out["diagnosis"].tolist()[2] == "no-contact"
    assert out["v_rel_error"][1] == pytest.approx(1e-7 / 0.6, rel=1e-2)
    assert not out.attrs["summary"].ok
    assert "claims agree within a relative 0.000000001" in out.attrs["summary"]


def test_missing_claims_are_empty_cells():
    df = pd.DataFrame({"m": [1, 1], "M": [1, 1], "v": [None, "3/5"]})
    out = rodimpact.audit(df)
    assert out["v_ok"].tolist()[1] is True
    assert pd.isna(out["v_ok"].tolist()[0])


def test_pyarrow_table():
    table = pa.table({"m": ["1", "2"], "M": ["1", "1"], "a": ["1/2", "1"]})
    out = rodimpact.audit(table)
    assert list(out["omega"]) == ["12/11", "4/3"]


def test_file_matches_the_reference_data():
    # tests/data/bench-textbook.csv: 10,000 scenes with v, V, omega from an independent
    # implementation (tests/data/README.md).
    out = rodimpact.audit(DATA / "bench-textbook.csv")
    assert len(out) == 10_000
    assert out["v_ok"].all() and out["V_ok"].all() and out["omega_ok"].all()
    assert out.attrs["summary"].ok
    with open(DATA / "bench-textbook.csv") as f:
        first = next(csv.DictReader(f))
    assert out["omega_exact"][0] == first["omega"]


def test_the_file_output_is_the_clis(cli, tmp_path):
    for name in ["bench-textbook.csv", "engines/mujoco-4.0.0-f64.csv", "engines/box2d-2.3.10-f32.csv"]:
        cli_out = tmp_path / "cli.csv"
        code, _, err = cli("batch", f"tests/data/{name}", "--ulps", "4", "--out", str(cli_out))
        out = rodimpact.audit(DATA / name, ulps=4)
        with open(cli_out, newline="") as f:
            rows = list(csv.reader(f))
        assert list(out.columns) == rows[0], name
        assert len(out) == len(rows) - 1
        text = out.astype(object).where(out.notna(), None)
        for i in (0, len(rows) // 2, len(rows) - 2):
            for j, name_j in enumerate(rows[0]):
                cell = text.iloc[i, j]
                want = rows[i + 1][j]
                if cell is None:
                    assert want in ("", "-"), (name, i, name_j)
                elif isinstance(cell, (bool,)) or str(out[name_j].dtype) == "boolean":
                    assert want == str(bool(cell)).lower(), (name, i, name_j)
                elif isinstance(cell, float):
                    assert float(want.lstrip("+")) == cell or (cell != cell and want == "nan")
                else:
                    assert cell == want, (name, i, name_j)
        assert (code == 0) == out.attrs["summary"].ok, name
        assert err == str(out.attrs["summary"]), name


def test_bad_rows_and_options():
    with pytest.raises(ValueError, match=r"^row 2, column M: must be > 0, got -1$"):
        rodimpact.audit(pd.DataFrame({"m": [1, 1, 2], "M": [1, -1, 1]}))
    with pytest.raises(ValueError, match=r"^header: column 'm' given twice$"):
        rodimpact.audit(pa.table([pa.array(["1"]), pa.array(["1"]), pa.array(["1"])], names=["m", "M", "m"]))
    with pytest.raises(ValueError, match=r"^rtol: give either rtol or ulps, not both$"):
        rodimpact.audit(pd.DataFrame({"m": [1], "M": [1]}), rtol="1e-9", ulps=4)
    with pytest.raises(ValueError, match=r"^backend: expected exact or f64"):
        rodimpact.audit(pd.DataFrame({"m": [1], "M": [1]}), backend="f16")
    with pytest.raises(ValueError, match=r"^FILE: cannot read"):
        rodimpact.audit(REPO / "no-such-file.csv")
    with pytest.raises(ValueError, match=r"^row 1, column m: a cell holds a comma or a line break$"):
        rodimpact.audit(pd.DataFrame({"m": ["1,5"], "M": ["1"]}))


def test_bad_row_error_is_the_clis(cli, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("m,M\n1,1\n2,-1\n")
    code, _, err = cli("batch", str(path))
    with pytest.raises(ValueError) as caught:
        rodimpact.audit(path)
    assert code == 2 and err.strip() == "error: " + str(caught.value)


def test_many_rows_stream_in_blocks():
    # More rows than one block (65,536) and one fed piece (32,768), in input order.
    n = 70_000
    df = pd.DataFrame({"m": [1 + (k % 5) for k in range(n)], "M": [1] * n})
    out = rodimpact.audit(df)
    assert len(out) == n
    assert out["omega"].iloc[n - 1] == rodimpact.solve(m=1 + ((n - 1) % 5), M=1)["omega"]["exact"]


def test_f64_backend():
    out = rodimpact.audit(pd.DataFrame({"m": [1], "M": [1]}), backend="f64")
    assert out["omega_f64"].tolist() == [1.2]


def test_summary_is_the_clis_stderr_with_atol(cli):
    name = "tests/data/engines/pybullet-3.2.7-f64.csv"
    code, _, err = cli("batch", name, "--rtol", "1e-6", "--atol", "1e-12", "--out", "/dev/null")
    out = rodimpact.audit(REPO / name, rtol="1e-6", atol=1e-12)  # a float tolerance: its repr
    assert str(out.attrs["summary"]) == err
    assert (code == 0) == out.attrs["summary"].ok


def test_without_pyarrow_a_dataframe_all_the_same(monkeypatch):
    import sys

    with_pyarrow = rodimpact.audit(DATA / "bench-textbook.csv")
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    frame = rodimpact.audit(DATA / "bench-textbook.csv")
    assert isinstance(frame, pd.DataFrame) and len(frame) == 10_000
    assert list(frame.columns) == list(with_pyarrow.columns)
    assert str(frame.attrs["summary"]) == str(with_pyarrow.attrs["summary"])
    for name in frame.columns:
        mine, theirs = frame[name], with_pyarrow[name]
        if name.endswith("_ok") or name == "laws_held":
            assert str(mine.dtype) == "boolean", name
        if mine.dtype.kind == "f":
            assert mine.equals(theirs), name
        else:
            assert [str(x) for x in mine] == [str(x) for x in theirs], name
    assert frame["omega_ok"][0] == True and frame["diagnosis"][0] == "ok"  # noqa: E712


def test_without_pyarrow_or_pandas_rows_are_dicts(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pandas", None)
    rows = rodimpact.audit(DATA / "bench-textbook.csv")
    assert len(rows) == 10_000
    assert rows[0]["omega_ok"] == "true" and rows[0]["diagnosis"] == "ok"
