# SPDX-License-Identifier: GPL-3.0-or-later
"""Scene.traction returns every column of `roughroll traction`'s CSV (issue 25): the smooth
cylinders' p_hertz and p1_carter for every scene, and for a physical scene x1_m, p2_Pa, p1_Pa in
SI units, bit for bit as the CSV's shortest round-trip digits; checked independently against
Hertz's and Carter's closed forms and the SI scales of the point."""

import csv
import io
import math

import numpy as np
import pytest

import roughroll
from conftest import DATA, run


def program_csv(tmp_path, name, *options):
    status, _, err = run("traction", DATA / name, "--points", "41", "--no-plot", "--out", tmp_path, "--name", "t",
                         *options)
    assert status == 0, err
    rows = [r for r in csv.reader(io.StringIO((tmp_path / "traction-t.csv").read_text())) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {h: np.array([float(row[i]) if h != "zone" else math.nan for row in body]) for i, h in enumerate(header)}


@pytest.mark.parametrize("name,options,kw", [
    ("fig2a-T1.toml", [], {}),
    ("steel-rollers.toml", ["--n", "32"], {"n": 32}),
    ("steel-rollers.toml", ["--n", "32", "--P1", "-2e4"], {"n": 32, "P1": -2e4}),
    ("aluminium-on-steel.toml", ["--n", "32"], {"n": 32}),
], ids=["dimensionless", "physical", "physical-P1", "dissimilar"])
def test_columns_equal_program_csv(tmp_path, name, options, kw):
    expected = program_csv(tmp_path, name, *options)
    got = roughroll.read_scene(DATA / name).traction(points=41, **kw)
    physical = "x1_m" in expected
    columns = ["r", "p", "p1", "slip_velocity", "p_hertz", "p1_carter"] + (["x1_m", "p2_Pa", "p1_Pa"] if physical else [])
    for key in columns:
        np.testing.assert_array_equal(got[key], expected[key], err_msg=key)
    assert ("x1_m" in got) == physical and ("p2_Pa" in got) == physical and ("p1_Pa" in got) == physical


def test_columns_by_their_definitions():
    # Independent of the shared code: the SI columns are the dimensionless ones times the point's
    # scales (a, P2/a), and the smooth ones are Hertz's and Carter's closed forms.
    s = roughroll.read_scene(DATA / "steel-rollers.toml")
    t = s.traction(points=201, n=32)
    si = t["point"].si
    a, P2 = si["a_m"], si["P2_N_per_m"]
    np.testing.assert_allclose(t["x1_m"], t["r"] * a, rtol=1e-15, atol=0)
    np.testing.assert_allclose(t["p2_Pa"], t["p"] * P2 / a, rtol=1e-14)
    np.testing.assert_allclose(t["p1_Pa"], t["p1"] * P2 / a, rtol=1e-14, atol=1e-6)
    r = t["r"]
    np.testing.assert_allclose(t["p_hertz"], 2 / math.pi * np.sqrt(1 - r**2), rtol=1e-14, atol=1e-15)
    Q, f = t["point"].Q, t["point"].f
    rho = math.sqrt(1 - Q / f)  # Carter: the stick zone [-1, 2 rho - 1]
    c0 = 2 * rho - 1
    stick = r < c0
    carter = f * t["p_hertz"] - np.where(stick, 2 * f / math.pi * np.sqrt(np.maximum(0, rho**2 - (r + 1 - rho)**2)), 0)
    np.testing.assert_allclose(t["p1_carter"], carter, rtol=1e-12, atol=1e-15)
    # Carter's traction carries the load Q; Hertz's pressure the load 1 (each on its own width).
    rr = np.linspace(-1, 1, 20001)
    tt = s.traction(r=rr, n=32)
    assert np.trapz(tt["p1_carter"], rr) == pytest.approx(Q, abs=1e-5)
    assert np.trapz(tt["p_hertz"], rr) == pytest.approx(1.0, abs=1e-5)
    # A dimensionless scene has no SI columns.
    assert "x1_m" not in roughroll.read_scene(DATA / "fig2a-T1.toml").traction(points=5)
