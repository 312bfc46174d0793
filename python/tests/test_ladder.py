# SPDX-License-Identifier: GPL-3.0-or-later
"""The ladder that chooses n (issue 24, 5; docs/performance.md "The ladder chooses n") from Python:
without n the one-parameter case near gross sliding (eps1 = 0.1, eps2 = 0.3, Q/f = 0.9999), whose
checks fail at n = 128, is answered as the program answers it (Point.n: n = 256 at tolerance 1e-3; at the
default 1e-4 its stick start's estimate takes it to n = 1000, docs/formulation.md 7(e) "The start's estimate"),
n=128 is today's flagged point, a curve has each row's n, and bad tolerances raise InputError with one line."""

import numpy as np
import pytest

import roughroll
from conftest import cli_json, without_seconds

NEAR = {"friction": 0.3, "Q": 0.29997,
        "cylinder1": {"tangential": {"T": 0.05, "A": 1.0}, "normal": {"T": 0.15, "A": 1.0}},
        "solver": {"method": "one-parameter"}}


def test_point_climbs_as_the_program(tmp_path):
    s = roughroll.Scene(NEAR)
    assert s.n == 128 and s.tolerance == 1e-4
    p = s.point(tolerance=1e-3)
    assert p.n == 256 and p.checks_hold and p.error_estimate is not None
    assert 0 < p.error_estimate["stick_start"] <= 1e-3 * (1 + p.stick_start)
    path = tmp_path / "near.toml"
    path.write_text('friction = 0.3\nQ = 0.29997\n[cylinder1.tangential]\nT = 0.05\nA = 1.0\n'
                    '[cylinder1.normal]\nT = 0.15\nA = 1.0\n[solver]\nmethod = "one-parameter"\n')
    assert without_seconds(p.to_dict()) == without_seconds(cli_json("point", path, "--json", "--tolerance", "1e-3"))
    flagged = s.point(n=128)
    assert flagged.n == 128 and not flagged.checks_hold and flagged.error_estimate is None


def test_curve_reports_each_rows_n():
    # The second row's stick start (+- 1.8e-5 at n = 256, 4.5e-6 at 512) meets 3e-4 (1 + s) = 6.4e-6 at n = 512 (at 256
    # before session 26, when the start had no estimate).
    c = roughroll.Scene(NEAR).curve([0.15, 0.29997], tolerance=3e-4)
    assert c["n"].tolist() == [128, 512]
    assert np.all(c["stick_start_error_estimate"] <= 3e-4 * (1 + c["stick_start"]))
    assert np.all(c["status"] == "ok")


@pytest.mark.parametrize("tol", [0.0, -1e-6, 1.0, 2.0, float("nan"), float("inf")])
def test_bad_tolerance(tol):
    with pytest.raises(roughroll.InputError, match="tolerance"):
        roughroll.Scene(NEAR).point(tolerance=tol)


def test_n_and_tolerance_together():
    with pytest.raises(roughroll.InputError, match="give one"):
        roughroll.Scene(NEAR).point(n=64, tolerance=1e-6)
    with pytest.raises(roughroll.InputError, match="solver.tolerance"):
        roughroll.Scene(dict(NEAR, solver={"n": 64, "tolerance": 1e-6}))
    assert roughroll.Scene(dict(NEAR, solver={"n": 64})).tolerance is None
