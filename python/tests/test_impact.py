"""impact(): planar impacts from files and dicts; the paper's scene as bodies is solve's."""

import sys
from fractions import Fraction as F

import pytest

import rodimpact
from conftest import EXAMPLES

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
    with pytest.raises(ValueError, match=r"^law: expected newton, poisson, energetic or all"):
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
