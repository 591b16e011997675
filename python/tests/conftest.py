"""Shared helpers: the repository's paths and the command-line binary, when one is given.

``RODIMPACT_CLI`` (the path of a built ``rodimpact`` binary) turns on the tests that compare
``to_dict()`` and the error messages with the command line's own output; without it they are
skipped and everything else runs.
"""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
DATA = REPO / "tests" / "data"


def cli_path():
    path = os.environ.get("RODIMPACT_CLI")
    return path if path and os.access(path, os.X_OK) else None


@pytest.fixture
def cli():
    """Runs the command line: ``cli("solve", "--m", "1", ...)`` is ``(exit, stdout, stderr)``."""
    path = cli_path()
    if path is None:
        pytest.skip("RODIMPACT_CLI not set: no command-line binary to compare with")

    def run(*args):
        done = subprocess.run([path, *args], capture_output=True, text=True, cwd=REPO)
        return done.returncode, done.stdout, done.stderr

    return run


@pytest.fixture
def cli_json(cli):
    def run(*args):
        code, out, err = cli(*args)
        assert out, f"no JSON from rodimpact {' '.join(args)}: {err}"
        return json.loads(out)

    return run
