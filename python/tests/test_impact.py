"""impact(): planar impacts from files and dicts; the paper's scene as bodies is solve's."""

import json
import sys
from fractions import Fraction as F

import pytest

import rodimpact
from conftest import EXAMPLES, REPO

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    tomllib = None

PAPER = EXAMPLES / "impacts" / "paper-as-bodies.toml"


def test_the_papers_scene_as_bodies_is_solves_answer_under_every_law():
    # m = M = 1, l = 1, a = 1/2, v0 = 1: v = 3/11, V = 8/11, |omega| = 12/11 (test_solve).
    r = rodimpact.impact(PAPER)
    s = rodimpact.solve(m=1, M=1, a="1/2")
    assert [x.law for x in r.laws] == ["newton", "poisson", "energetic"]
    for law in ("newton", "poisson", "energetic"):
        bodies = r.law(law).bodies
        assert bodies.projectile.velocity == [s.v, 0]
        assert bodies.rod.velocity == [s.V, 0]
        # counterclockwise positive here; the struck arm moves forward: clockwise
        assert bodies.rod.omega == -s.omega
        assert r.law(law).energy.change == 0


@pytest.mark.skipif(tomllib is None, reason="tomllib is Python 3.11+")
def test_a_dict_is_the_files_structure():
    for name in ("paper-as-bodies.toml", "cradle-3.toml", "tilted-rod-rough-floor.toml"):
        path = EXAMPLES / "impacts" / name
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        assert rodimpact.impact(scene).to_dict() == rodimpact.impact(path).to_dict(), name


def test_built_dict_with_fractions():
    scene = {
        "body": [
            {"name": "puck", "mass": 1, "velocity": [1, 0]},
            {"name": "wall", "fixed": True},
        ],
        "contact": [{"bodies": ["puck", "wall"], "point": [0, 0], "normal": [-1, 0], "e": F(1, 2)}],
    }
    r = rodimpact.impact(scene, law="newton")
    # A point mass against a wall: the normal velocity reverses and shrinks by e.
    assert r.law("newton").bodies.puck.velocity == [F(-1, 2), 0]
    assert r.law("newton").energy.change == F(-3, 8)


def test_several_contacts_models():
    r = rodimpact.impact(EXAMPLES / "impacts" / "cradle-3.toml", model="simultaneous-newton")
    assert "models" in r
    with pytest.raises(ValueError, match=r"^law: several contacts"):
        rodimpact.impact(EXAMPLES / "impacts" / "cradle-3.toml", law="newton")
    with pytest.raises(ValueError, match=r"^model: one contact"):
        rodimpact.impact(PAPER, model="pgs:3")


def test_bad_scenes():
    with pytest.raises(ValueError, match=r"the float 0\.5 is not exact"):
        rodimpact.impact({"body": [{"name": "a", "mass": 0.5}]})
    with pytest.raises(ValueError, match=r"^law: expected newton, poisson, energetic \(stronge\), lcp-newton, lcp-poisson, split or all"):
        rodimpact.impact(PAPER, law="hooke")
    with pytest.raises(ValueError, match=r"cannot read"):
        rodimpact.impact(EXAMPLES / "impacts" / "no-such-scene.toml")
    receding = {
        "body": [{"name": "puck", "mass": "1", "velocity": ["-1", "0"]}, {"name": "wall", "fixed": True}],
        "contact": [{"bodies": ["puck", "wall"], "point": ["0", "0"], "normal": ["-1", "0"]}],
    }
    with pytest.raises(ValueError):
        rodimpact.impact(receding)


def test_to_dict_is_the_clis_json(cli_json):
    for name in ("paper-as-bodies.toml", "cradle-3.toml", "box-lands-flat-friction.toml"):
        path = f"examples/impacts/{name}"
        assert rodimpact.impact(EXAMPLES / "impacts" / name).to_dict() == cli_json(
            "impact", path, "--format", "json"
        ), name


def test_engine_laws_and_an_engines_step():
    tilted = EXAMPLES / "impacts" / "tilted-rod-rough-floor.toml"
    # lcp-newton: Newton's target on the final normal velocity and Coulomb's law on the final
    # slip; the end sticks (u_t' = 0) under P = (1/5, 11/10), and the rod gains 1/10 J (X39).
    r = rodimpact.impact(tilted, law="lcp-newton")
    answer = r.law("lcp-newton")
    assert answer.bodies.rod.velocity == [F(6, 5), F(1, 10)]
    assert answer.bodies.rod.omega == F(-3, 2)
    assert answer.energy.change == F(1, 10)
    assert r.engine_step is None
    # pymunk's step of 10 iterations, replayed exactly: not yet lcp-newton, gaining energy too.
    r = rodimpact.impact(tilted, law="lcp-newton", engine="pymunk-7")
    step = r.engine_step
    assert step.engine == "pymunk-7" and step.law == "lcp-newton"
    assert 0 < step.energy.change < F(1, 10)
    assert r.law("lcp-newton").energy.change == F(1, 10)
    # Box2D 2.3: an approach at exactly its threshold (1 m/s) does not bounce.
    step = rodimpact.impact(tilted, law="split", engine="box2d-2.3").engine_step
    assert step.contact_velocity.normal.after == 0
    # Several contacts: the engine's step is a model named after it.
    step = rodimpact.impact(EXAMPLES / "impacts" / "cradle-3.toml", engine="pymunk-7").engine_step
    assert step.model == "pymunk-7" and step.engine == "pymunk-7"
    with pytest.raises(ValueError, match=r"^engine: "):
        rodimpact.impact(tilted, engine="havok")


def _scene(claimed_velocity):
    return {
        "id": "wall",
        "body": [
            {"name": "p", "mass": "1", "velocity": ["1", "0"]},
            {"name": "wall", "fixed": True},
        ],
        "contact": [{"bodies": ["p", "wall"], "point": ["0", "0"], "normal": ["-1", "0"]}],
        "claimed": {"engine": "pymunk 7.3.1", "bodies": {"p": {"velocity": claimed_velocity, "omega": "0"}}},
    }


def test_audit_impacts_of_records():
    # A ball bouncing elastically off a wall: claimed right, then at half the speed.
    rows = rodimpact.audit_impacts([_scene(["-1", "0"]), _scene(["-0.5", "0"])])
    records = rows.to_dict("records")
    assert [r["diagnosis"] for r in records] == ["ok", "energy-loss"]
    assert records[0]["closest"] == "newton" and records[0]["rel_error"]["newton"] == 0.0
    # sqrt(K(claim - exact)/K(before)) = sqrt((1/2)(1/2)^2/(1/2)) = 1/2
    assert records[1]["rel_error"]["newton"] == 0.5 and records[1]["matches"] == []
    summary = rows.attrs["summary"]
    assert not summary.ok and summary.scenes == 2
    assert summary.findings == {"energy-loss": ["wall"]}
    # pymunk's step is exact here: the whole error is what the replay leaves out.
    assert records[1]["error_split"]["of_rounding"] == 0.5


def test_audit_impacts_of_a_file_is_the_clis(cli):
    # The file of pymunk's planar impacts: the same lines and summary as the command line's.
    path = REPO / "tests" / "data" / "engines" / "impacts" / "pymunk-7.3.1.jsonl"
    rows = rodimpact.audit_impacts(path, rtol="1e-2")
    code, out, err = cli("impact", "--batch", str(path), "--rtol", "1e-2")
    assert code == 1
    cli_lines = [json.loads(line) for line in out.splitlines()]
    assert list(rows["id"]) == [line["id"] for line in cli_lines]
    assert list(rows["closest"]) == [line["closest"] for line in cli_lines]
    assert str(rows.attrs["summary"]) == err
    assert rows.attrs["summary"].findings == {"off": ["ball-on-column", "cradle-12-two-balls"]}
    split = rows.set_index("id").loc["box-corner", "error_split"]
    assert split["profile"] == "pymunk-7" and split["of_law"] == 0.0
    assert 1e-3 < split["of_iterations"] < 2e-3 and split["of_rounding"] < 1e-5


def test_audit_impacts_options_and_errors(tmp_path):
    path = REPO / "tests" / "data" / "engines" / "impacts" / "pymunk-7.3.1.jsonl"
    known = tmp_path / "known.csv"
    known.write_text("id,finding\nball-on-column,off\ncradle-12-two-balls,off\n")
    rows = rodimpact.audit_impacts(path, rtol=F(1, 100), expect=known)
    assert rows.attrs["summary"].ok
    rows = rodimpact.audit_impacts(path, rtol="1e-2", engine="bullet-3")
    assert set(rows["error_split"].dropna().map(lambda s: s["profile"])) == {"bullet-3"}
    with pytest.raises(ValueError, match=r"^rtol: must be a number from 0 to 1, got -1$"):
        rodimpact.audit_impacts(path, rtol="-1")
    with pytest.raises(ValueError, match=r"^engine: "):
        rodimpact.audit_impacts(path, engine="havok")
    with pytest.raises(ValueError, match=r"^float: expected f32 or f64"):
        rodimpact.audit_impacts(path, ulps=4, float_format="f16")
    with pytest.raises(ValueError, match=r"^scenes: line 1"):
        rodimpact.audit_impacts([{"body": []}])
    with pytest.raises(ValueError, match=r"one scene"):
        rodimpact.audit_impacts(_scene(["-1", "0"]))
    with pytest.raises(ValueError, match=r"cannot read"):
        rodimpact.audit_impacts(tmp_path / "missing.jsonl")


# A child that calls impact() on a box landing flat on 32 points (every model: seconds of exact
# work) while a thread sends it SIGINT every 50 ms. A signal that arrives inside the call stops
# the exact work at once as KeyboardInterrupt("rodimpact: interrupted"); one that arrives between
# calls is Python's own KeyboardInterrupt, and the child calls again. Without the library's
# interrupt hook the call would run to its end every time and never say so.
INTERRUPTED_CHILD = r"""
import os, signal, threading, time
import rodimpact

contacts = [
    {"bodies": ["box", "floor"], "point": [f"{2 * k - 31}/31", "0"], "normal": ["0", "1"], "e": "1/2"}
    for k in range(32)
]
scene = {
    "body": [
        {"name": "box", "mass": "1", "shape": "box", "width": "2", "height": "1",
         "position": ["0", "1/2"], "velocity": ["0", "-1"]},
        {"name": "floor", "fixed": True},
    ],
    "contact": contacts,
}

# Ctrl-C counts only while a call is under way: between calls (and once the answer is in) the
# handler ignores it, so no signal can escape the loop.
armed = False

def on_interrupt(signum, frame):
    if armed:
        raise KeyboardInterrupt

signal.signal(signal.SIGINT, on_interrupt)

def keep_interrupting():
    while True:
        time.sleep(0.05)
        os.kill(os.getpid(), signal.SIGINT)

threading.Thread(target=keep_interrupting, daemon=True).start()
result = "never inside"
for attempt in range(20):
    try:
        armed = True
        rodimpact.impact(scene)
        armed = False
    except KeyboardInterrupt as e:
        armed = False
        if str(e) == "rodimpact: interrupted":
            result = "inside"
            break
print(result)
"""


def test_ctrl_c_stops_the_exact_work():
    import subprocess

    out = subprocess.run(
        [sys.executable, "-c", INTERRUPTED_CHILD], capture_output=True, text=True, timeout=600
    )
    assert (out.stdout, out.returncode) == ("inside\n", 0), out.stderr


def test_a_law_without_an_answer_beside_the_others():
    # A pinned body on a rough wall: Newton's and Stronge's laws never end the impact.
    scene = {
        "body": [
            {"name": "A", "mass": "1", "inertia": "4/3", "position": ["1", "2"],
             "velocity": ["28/15", "-7/6"], "omega": "-7/3"},
            {"name": "B", "fixed": True},
        ],
        "pin": [{"body": "A", "point": ["1/2", "6/5"]}],
        "contact": [{"bodies": ["A", "B"], "point": ["2", "2"], "normal": ["-1/2", "0"],
                     "e": "1", "mu": "2/3"}],
    }
    r = rodimpact.impact(scene)
    assert [x.law for x in r.laws] == ["poisson"]
    assert sorted(r.not_answered) == ["energetic", "newton"]
    assert r.not_answered["newton"].startswith("under newton's law the impact never ends")
    with pytest.raises(KeyError, match="newton: not answered: under newton's law"):
        r.law("newton")
    with pytest.raises(ValueError, match="under newton's law the impact never ends"):
        rodimpact.impact(scene, law="newton")
    assert rodimpact.impact(PAPER).not_answered == {}


def test_a_dict_may_say_bodies_and_contacts():
    # NEWCOMER m25: the natural plurals in a dict are the file's keys.
    plural = {
        "bodies": [
            {"name": "puck", "mass": "1", "position": ["0", "0"], "velocity": ["1", "0"]},
            {"name": "wall", "fixed": True},
        ],
        "contacts": [{"bodies": ["puck", "wall"], "point": ["0", "0"], "normal": ["-1", "0"], "e": "1/2"}],
    }
    singular = {"body": plural["bodies"], "contact": plural["contacts"]}
    assert rodimpact.impact(plural).to_dict() == rodimpact.impact(singular).to_dict()
    assert rodimpact.impact(plural).law("newton").bodies.puck.velocity == [F(-1, 2), 0]
    with pytest.raises(ValueError, match="^scene: both 'body' and 'bodies' given"):
        rodimpact.impact({**singular, "bodies": plural["bodies"]})


def test_a_dict_that_contains_itself_is_named():
    # RELIABILITY H13: it was Python's RecursionError.
    scene = {"body": [{"name": "puck", "mass": "1"}]}
    scene["body"][0]["shape"] = scene
    with pytest.raises(ValueError, match=r"^body\[0\]\.shape.*: contains itself$"):
        rodimpact.impact(scene)


def test_messages_name_keyword_arguments_not_flags():
    # NEWCOMER m25: "(the laws do: --law)" in a Python error named a flag Python does not have.
    with pytest.raises(ValueError, match=r"^model: one contact: .*\(the laws do: law=\)$"):
        rodimpact.impact(PAPER, model="pgs:3")
