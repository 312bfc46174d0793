# SPDX-License-Identifier: GPL-3.0-or-later
"""roughroll.plot (issue 25, 4): each drawing written to a PNG that is whole and not blank.

The figures are looked at by a person (docs/reproduction.md); here each must draw without an
error, on its own Axes or a new figure, and put something on the canvas: a PNG whose pixels
are not all one colour.  Set ROUGHROLL_PLOT_DIR to keep the PNGs.
"""

import os
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import roughroll  # noqa: E402
import roughroll.plot  # noqa: E402

DATA = Path(__file__).resolve().parents[2] / "data"


@pytest.fixture(scope="module")
def out_dir():
    kept = os.environ.get("ROUGHROLL_PLOT_DIR")
    if kept:
        Path(kept).mkdir(parents=True, exist_ok=True)
        yield Path(kept)
        return
    with tempfile.TemporaryDirectory() as d:
        yield Path(d)


def saved(fig, path):
    """The figure as a PNG at `path`; asserts the file is a whole PNG with more than one colour."""
    fig.savefig(path, dpi=80)
    plt.close(fig)
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path.name} is not a PNG"
    assert data[-12:] == b"\x00\x00\x00\x00IEND\xaeB`\x82", f"{path.name} has no IEND chunk"
    pixels = plt.imread(path)
    assert pixels.reshape(-1, pixels.shape[-1]).std(axis=0).max() > 0.01, f"{path.name} is blank"
    return pixels


def lines_with_data(ax):
    return [l for l in ax.get_lines() if np.isfinite(np.asarray(l.get_ydata(), dtype=float)).any()]


def test_creep_curve_dimensionless_with_carter(out_dir):
    scene = roughroll.read_scene(DATA / "traction-example.toml")
    fig, ax = plt.subplots()
    returned = roughroll.plot.creep_curve(scene.curve(points=15), ax=ax, label="T = 1, A = 0.5")
    assert returned is ax
    labels = [l.get_label() for l in ax.get_lines()]
    assert "Carter: smooth rollers" in labels and "T = 1, A = 0.5" in labels
    # A second curve on the same Axes does not draw Carter's again.
    roughroll.plot.creep_curve(roughroll.read_scene(DATA / "fig2a-T0.toml").curve(points=15), ax=ax, label="T = 0")
    assert [l.get_label() for l in ax.get_lines()].count("Carter: smooth rollers") == 1
    saved(fig, out_dir / "creep_curve.png")


def test_creep_curve_physical_in_newtons_per_mm(out_dir):
    c = roughroll.read_scene(DATA / "steel-rollers-ground.toml").curve(points=11)
    ax = roughroll.plot.creep_curve(c)  # a new figure
    assert "N/mm" in ax.get_xlabel()
    # P1 in N/mm: the largest is f P2, 30 N/mm for 100 N/mm and f = 0.3.
    x = np.concatenate([np.asarray(l.get_xdata(), dtype=float) for l in lines_with_data(ax)])
    assert np.nanmax(x) == pytest.approx(np.nanmax(c["P1_N_per_m"]) / 1e3)
    saved(ax.figure, out_dir / "creep_curve_physical.png")
    dimensionless = roughroll.plot.creep_curve(c, units="dimensionless")
    assert "Q/f" in dimensionless.get_xlabel()
    plt.close(dimensionless.figure)


def test_creep_curve_refused_rows_are_ticks_not_values(out_dir):
    stiff = roughroll.scene({"friction": 0.3, "Q": 0.15, "cylinder2": {"normal": {"T": 1e6, "A": 1}},
                             "solver": {"n": 16, "method": "product"}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", roughroll.RefusedPointWarning)
        c = stiff.curve(points=7)
    refused = int((c["status"] == "refused").sum())
    assert refused > 0, "the stiff scene no longer refuses a row: pick another"
    ax = roughroll.plot.creep_curve(c)
    ticks = [l for l in ax.get_lines() if "refused" in l.get_label()]
    assert len(ticks) == 1 and len(ticks[0].get_xdata()) == refused
    # Drawn in axes coordinates at the bottom (y = 0 of the frame), not at a creep value.
    assert ticks[0].get_transform() == ax.get_xaxis_transform()
    saved(ax.figure, out_dir / "creep_curve_refused.png")


def test_traction_zones_named(out_dir):
    t = roughroll.read_scene(DATA / "traction-example.toml").traction(points=201)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
    roughroll.plot.traction(t, ax=top)
    roughroll.plot.slip_velocity(t, ax=bottom)
    names = [text.get_text() for text in top.texts]
    assert "stick" in names and "slip" in names
    assert not hasattr(top, "p1_axis"), "f = 0.3: p1 is drawn on p's axis"
    saved(fig, out_dir / "traction.png")


def test_traction_small_p1_gets_its_own_axis_and_every_zone_a_name(out_dir):
    # Aluminium on steel, f = 0.05, Q/f = +0.75: five zones, the trailing stick zone 3e-4 a wide.
    t = roughroll.read_scene(DATA / "aluminium-on-steel.toml").traction(Q=0.0375, n=16, points=401)
    zones = t["point"].to_dict()["zones"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(9, 7))
    ax = roughroll.plot.traction(t, ax=top)
    roughroll.plot.slip_velocity(t, ax=bottom)
    assert hasattr(ax, "p1_axis"), "p1 (f = 0.05) on p's scale would be a flat line"
    lo, hi = ax.p1_axis.get_ylim()
    assert hi == pytest.approx(ax.get_ylim()[1] * 0.05)
    named = [text.get_text() for text in ax.texts]
    if "x1_m" in t:
        assert "mm" in ax.get_xlabel()
    # Every zone named: the wide ones above the frame, the narrow ones by an arrow.
    assert len(named) == len(zones), (named, zones)
    assert any("wide" in name for name in named)
    saved(fig, out_dir / "traction_al_steel.png")


def test_bad_units_are_refused():
    c = roughroll.read_scene(DATA / "traction-example.toml").curve(points=5)
    with pytest.raises(ValueError, match="units"):
        roughroll.plot.creep_curve(c, units="imperial")
    with pytest.raises(ValueError, match="SI columns"):
        roughroll.plot.creep_curve(c, units="si")
    plt.close("all")
