# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared fixtures: the program built beside the module (for agreement tests) and the data folder.

CTest (python/CMakeLists.txt) sets PYTHONPATH to the build's module folder, ROUGHROLL_PROGRAM to
build/roughroll and ROUGHROLL_SOURCE_DIR to the source tree.
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("ROUGHROLL_SOURCE_DIR", Path(__file__).resolve().parents[2]))
DATA = SOURCE_DIR / "data"


def program():
    path = os.environ.get("ROUGHROLL_PROGRAM")
    if not path:
        pytest.skip("ROUGHROLL_PROGRAM (build/roughroll) not set: run through CTest")
    return path


def run(*args, cwd=None):
    """The program's exit status, stdout and stderr."""
    r = subprocess.run([program(), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=900)  # a hang guard, not a speed limit
    return r.returncode, r.stdout, r.stderr


def cli_json(*args, cwd=None):
    status, out, err = run(*args, cwd=cwd)
    assert status == 0, err
    return json.loads(out)


def cli_error(*args, cwd=None):
    """The one line the program prints after 'roughroll: error: ' (exit status 2)."""
    status, out, err = run(*args, cwd=cwd)
    assert status == 2, (status, out, err)
    assert out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("roughroll: error: "), err
    return lines[0][len("roughroll: error: "):]


def without_seconds(d):
    d = dict(d)
    d.pop("seconds")
    return d


@pytest.fixture
def data():
    return DATA
