# SPDX-License-Identifier: GPL-3.0-or-later
"""A load given as Q/f (keyword Q_over_f=, scene key Q_over_f) or as P1 in N/m (keyword P1= of a
physical scene) wherever Q= is accepted (issue 25): the same point as the program's --Q-over-f
and --P1 and as the Q they stand for, bit for bit; one load only; bad values raise InputError
with the program's message; a load just below gross sliding stays below it."""

import math

import numpy as np
import pytest

import roughroll
from conftest import DATA, cli_error, cli_json, without_seconds


def same(a, b):
    return without_seconds(a.to_dict()) == without_seconds(b.to_dict())


@pytest.mark.parametrize("name,args,kw", [
    ("fig2a-T1.toml", ["--Q-over-f", "0.5", "--n", "32"], {"Q_over_f": 0.5, "n": 32}),
    ("fig2a-T1.toml", ["--Q-over-f", "-0.25", "--friction", "0.2", "--n", "32"],
     {"Q_over_f": -0.25, "friction": 0.2, "n": 32}),
    ("steel-rollers.toml", ["--P1", "1e4", "--n", "32"], {"P1": 1e4, "n": 32}),
    ("steel-rollers.toml", ["--Q-over-f", "0.9", "--n", "32"], {"Q_over_f": 0.9, "n": 32}),
], ids=["ratio", "ratio-friction", "P1", "ratio-physical"])
def test_keywords_equal_program_options(name, args, kw):
    expected = cli_json("point", DATA / name, "--json", *args)
    got = roughroll.read_scene(DATA / name).point(**kw).to_dict()
    assert without_seconds(got) == without_seconds(expected)


def test_ratio_is_the_q_it_stands_for():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    assert same(s.point(Q_over_f=0.5, n=32), s.point(0.15, n=32))
    assert s.point(Q_over_f=0.5, n=32).Q == 0.15
    assert same(roughroll.point(s, Q_over_f=-1.0, n=32), s.point(-0.3, n=32))
    # The traction takes it too.
    a, b = s.traction(Q_over_f=0.5, n=32, points=9), s.traction(0.15, n=32, points=9)
    for key in ("p", "p1", "slip_velocity", "p_hertz", "p1_carter"):
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
    steel = roughroll.read_scene(DATA / "steel-rollers.toml")
    assert same(steel.point(P1=1e4, n=32), steel.point(0.1, n=32))
    assert same(steel.point(P1=1.5e4, n=32), steel.point(n=32))  # the scene's own P1
    assert steel.traction(P1=1e4, n=32, points=5)["point"].si["P1_N_per_m"] == 1e4


def test_scene_key():
    d = {"label": "Fig. 2a, curve 3: T_1^(1) = T_1^(2) = 1, A_1^(1) = A_1^(2) = 0.5", "friction": 0.3, "Q_over_f": 0.5, "cylinder1": {"tangential": {"T": 1, "A": 0.5}, "normal": {"T": 1, "A": 0.5}},
         "solver": {"n": 32, "method": "product"}}
    s = roughroll.Scene(d)
    assert s.Q == 0.15 and s.Q_over_f == 0.5
    file = roughroll.read_scene(DATA / "fig2a-T1.toml")
    assert same(s.point(), file.point(n=32))
    # The ratio follows the friction keyword; a scene's Q does not.
    assert s.point(friction=0.2).Q == pytest.approx(0.1, rel=1e-15)
    assert file.point(friction=0.6, n=32).Q == 0.15
    # replace() switches between the two forms.
    assert same(file.replace(Q=None, Q_over_f=0.5, solver={"n": 32}).point(), file.point(n=32))
    assert roughroll.read_scene(DATA / "fig2a-T1.toml").Q_over_f == 0.5  # Q/f of the scene's Q


def test_just_below_gross_sliding():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    p = s.point(Q_over_f=1 - 1e-9, n=32)
    assert p.Q < p.f and p.Q / p.f == pytest.approx(1 - 1e-9, abs=1e-15)
    assert p.c0 > -1  # a stick zone, not gross sliding
    q = math.nextafter(1.0, 0.0)
    assert s.point(Q_over_f=q, n=32).Q < 0.3


def test_one_load_only():
    s = roughroll.read_scene(DATA / "steel-rollers.toml")
    for kw in ({"Q": 0.1, "Q_over_f": 0.5}, {"Q": 0.1, "P1": 1e4}, {"Q_over_f": 0.5, "P1": 1e4}):
        with pytest.raises(roughroll.InputError, match="give the load once, as Q, Q_over_f or P1"):
            s.point(**kw)
        with pytest.raises(roughroll.InputError, match="give the load once"):
            s.traction(**kw, points=5)
    with pytest.raises(roughroll.InputError, match="not both"):
        roughroll.Scene(friction=0.3, Q=0.1, Q_over_f=0.5)


@pytest.mark.parametrize("name,options,kw", [
    ("fig2a-T1.toml", ["--Q-over-f", "1.5"], {"Q_over_f": 1.5}),
    ("fig2a-T1.toml", ["--Q-over-f=-1.0000001"], {"Q_over_f": -1.0000001}),
    ("fig2a-T1.toml", ["--Q-over-f", "nan"], {"Q_over_f": math.nan}),
    ("fig2a-T1.toml", ["--Q-over-f", "inf"], {"Q_over_f": math.inf}),
    ("fig2a-T1.toml", ["--P1", "1e4"], {"P1": 1e4}),
    ("steel-rollers.toml", ["--P1", "30001"], {"P1": 30001.0}),
    ("steel-rollers.toml", ["--P1", "nan"], {"P1": math.nan}),
    ("steel-rollers.toml", ["--friction", "0.1", "--Q-over-f", "2"], {"friction": 0.1, "Q_over_f": 2.0}),
], ids=["above", "below", "nan", "inf", "P1-dimensionless", "P1-slides", "P1-nan", "ratio-friction"])
def test_bad_loads_raise_the_programs_message(name, options, kw):
    message = cli_error("point", DATA / name, *options)
    with pytest.raises(roughroll.InputError) as caught:
        roughroll.read_scene(DATA / name).point(**kw)
    assert str(caught.value) == message


def test_wrong_types():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    for kw in ({"Q_over_f": "0.5"}, {"P1": [1e4]}, {"Q_over_f": True}):
        with pytest.raises(TypeError):
            s.point(**kw)


def test_many_points():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    by_ratio = s.points(Q_over_f=[0.25, 0.5], n=32, threads=2)
    by_q = s.points([0.075, 0.15], n=32)
    assert all(same(a, b) for a, b in zip(by_ratio, by_q))
    steel = roughroll.read_scene(DATA / "steel-rollers.toml")
    got = roughroll.solve([(steel, {"P1": 1e4}), (s, {"Q_over_f": 0.5}), (s, 0.15)], n=32, threads=2)
    assert same(got[0], steel.point(0.1, n=32))
    assert same(got[1], got[2])
    with pytest.raises(roughroll.InputError, match=r"^items\[0\] \(P1 = 10000, scene 'Fig. 2a.*'\): P1 \(N/m\) needs a physical scene"):
        roughroll.solve([(s, {"P1": 1e4})])
    with pytest.raises(roughroll.InputError, match=r"^items\[0\] \(Q_over_f = 2, scene 'Fig. 2a.*'\): Q_over_f must lie in \[-1, 1\]"):
        roughroll.solve([(s, {"Q_over_f": 2})])
    with pytest.raises(TypeError):
        roughroll.solve([(s, {"q": 0.1})])
    with pytest.raises(roughroll.InputError, match="give the loads once"):
        s.points([0.1], Q_over_f=[0.5])


def test_curve_at_ratios():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    by_ratio = s.curve(Q_over_f=[0.0, 0.5, -0.5, 1.0], n=32)
    by_q = s.curve([0.0, 0.15, -0.15, 0.3], n=32)
    for key in ("Q", "Q_over_f", "c0", "xi", "xi_carter"):
        np.testing.assert_array_equal(by_ratio[key], by_q[key], err_msg=key)
    # At another friction the ratios stay ratios.
    np.testing.assert_array_equal(s.curve(Q_over_f=[0.5], friction=0.2, n=32)["Q"], [0.1])
    with pytest.raises(roughroll.InputError, match="Q_over_f must lie in"):
        s.curve(Q_over_f=[0.5, 1.5], n=32)
    with pytest.raises(roughroll.InputError, match="give the loads once"):
        s.curve([0.1], Q_over_f=[0.5])
    with pytest.raises(roughroll.InputError, match="sweep"):
        s.curve(Q_over_f=[0.5], sweep=True)
