# SPDX-License-Identifier: GPL-3.0-or-later
"""Points, curves, tractions and scenes travel: pickle, copy and deep-copy give equal objects, and
a scene unpickled elsewhere solves to the same numbers.  Scenes as templates (to_dict, replace)
and a repr that tells scenes apart."""

import copy
import os
import pickle

import numpy as np
import pytest

import roughroll
from conftest import DATA, without_seconds

SCENES = ("fig2a-T1.toml", "fig2a-T0.toml", "steel-rollers.toml", "steel-rollers-ground.toml",
          "aluminium-on-steel.toml", "unequal-kernels.toml")


def round_trips(x):
    """x through every protocol of pickle, copy.copy and copy.deepcopy."""
    out = [pickle.loads(pickle.dumps(x, protocol)) for protocol in range(pickle.HIGHEST_PROTOCOL + 1)]
    return out + [copy.copy(x), copy.deepcopy(x)]


def test_point_round_trips():
    p = roughroll.read_scene(DATA / "fig2a-T1.toml").point(0.2, method="product", n=48)
    for q in round_trips(p):
        assert isinstance(q, roughroll.Point)
        assert q == p
        assert q.to_dict() == p.to_dict()
        assert (q.c0, q.xi, q.checks) == (p.c0, p.xi, p.checks)
        assert repr(q) == repr(p)
        with pytest.raises(AttributeError, match="no field 'nonesuch'"):
            q.nonesuch
        with pytest.raises(AttributeError, match="read-only"):
            q.xi = 0


def test_deep_copy_is_independent():
    p = roughroll.point(DATA / "fig2a-T1.toml", 0.1, method="product", n=48)
    q = copy.deepcopy(p)
    q.checks[next(iter(q.checks))] = "changed"  # a nested dict of the copy, not of p
    assert q != p


def test_physical_point_round_trips():
    p = roughroll.read_scene(DATA / "steel-rollers.toml").point(method="product", n=48)
    assert p.si is not None
    for q in round_trips(p):
        assert q == p and q.si == p.si


def test_curve_and_traction_round_trip():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    c = s.curve(points=5, method="product", n=48)
    for d in round_trips(c):
        assert d.keys() == c.keys()
        for k in c:
            np.testing.assert_array_equal(d[k], c[k])
    t = s.traction(0.2, points=11, method="product", n=48)
    for d in round_trips(t):
        assert d["point"] == t["point"]
        for k in ("r", "p", "p1", "slip_velocity", "stick", "f_p"):
            np.testing.assert_array_equal(d[k], t[k])


@pytest.mark.parametrize("name", SCENES)
def test_scene_round_trips(name):
    s = roughroll.read_scene(DATA / name)
    for t in round_trips(s):
        assert isinstance(t, roughroll.Scene)
        assert t == s and hash(t) == hash(s)
        assert repr(t) == repr(s)
        assert (t.label, t.friction, t.Q, t.n, t.method, t.roughness, t.physical, t.source, t.base_dir) == \
               (s.label, s.friction, s.Q, s.n, s.method, s.roughness, s.physical, s.source, s.base_dir)


def test_unpickled_scene_solves_the_same_in_another_folder(tmp_path, monkeypatch):
    # steel-rollers-ground.toml reads profiles/ground.csv relative to its own folder.
    monkeypatch.chdir(DATA)
    s = roughroll.read_scene("steel-rollers-ground.toml")
    text = pickle.dumps(s)
    monkeypatch.chdir(tmp_path)
    t = pickle.loads(text)
    assert t == s
    assert without_seconds(t.point(method="product", n=48).to_dict()) == \
           without_seconds(s.point(method="product", n=48).to_dict())


def test_dict_and_toml_scenes_round_trip():
    d = {"label": "dict", "friction": 0.3, "Q": 0.1, "cylinder1": {"tangential": {"T": 0.5, "A": 0.5}},
         "solver": {"n": 48, "method": "product"}}
    s = roughroll.Scene(d)
    for t in round_trips(s):
        assert t == s and t.point().to_dict() | {"seconds": 0} == s.point().to_dict() | {"seconds": 0}
    assert s.to_dict() == d
    u = roughroll.Scene.from_toml('friction = 0.3\nQ = 0.1\n[cylinder1.tangential]\nT = 0.5\nA = 0.5\n', "mine")
    assert pickle.loads(pickle.dumps(u)) == u and pickle.loads(pickle.dumps(u)).source == "mine"


def test_scene_equality():
    a = roughroll.read_scene(DATA / "fig2a-T1.toml")
    b = roughroll.Scene(a.to_dict(), base_dir=a.base_dir)
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert a != a.replace(friction=0.25)
    assert a != roughroll.Scene(a.to_dict(), base_dir="/")  # profile_csv would resolve elsewhere
    assert a != a.to_dict()


def test_to_dict_is_the_file():
    s = roughroll.read_scene(DATA / "steel-rollers-ground.toml")
    d = s.to_dict()
    assert d["P2"] == 1.0e5 and d["cylinder1"]["micro_geometry"]["profile_csv"] == "profiles/ground.csv"
    assert s.base_dir == str(DATA.resolve())
    d["P2"] = 0  # a copy: the scene is unchanged
    assert s.to_dict()["P2"] == 1.0e5


def test_replace_keeps_relative_paths_relative_to_the_file(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # profiles/ground.csv is not here
    s = roughroll.read_scene(DATA / "steel-rollers-ground.toml")
    t = s.replace(P2=2.0e5, P1=3.0e4)
    assert t.physical["P2"] == 2.0e5 and t.Q == 0.15
    assert t.to_dict() == s.to_dict() | {"P2": 2.0e5, "P1": 3.0e4}
    assert t.base_dir == s.base_dir
    assert t.point(method="product", n=48).si != s.point(method="product", n=48).si
    # The same scene typed as a dict resolves profile_csv against the working folder: refused here.
    with pytest.raises(roughroll.InputError, match="profile_csv"):
        roughroll.Scene(t.to_dict())


def test_replace_merges_tables_and_removes_with_none():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    t = s.replace(solver={"n": 64})
    assert t.n == 64 and t.method == s.method
    assert t.replace(solver=None).method == "extrapolated"
    smooth = s.replace(cylinder1=None, cylinder2=None)
    assert smooth.roughness == {"cylinder1": {"tangential": None, "normal": None},
                                "cylinder2": {"tangential": None, "normal": None}}
    assert s.replace() == s
    with pytest.raises(roughroll.InputError, match="fig2a-T1.toml \\(with nonesuch replaced\\).*nonesuch"):
        s.replace(nonesuch=1)
    with pytest.raises(roughroll.InputError, match="friction"):
        s.replace(friction=-1)


def test_repr_tells_scenes_apart():
    rough = roughroll.read_scene(DATA / "fig2a-T1.toml")
    smooth = rough.replace(cylinder1=None, cylinder2=None)
    assert repr(rough) != repr(smooth)
    assert "T=1.0" in repr(rough) and "smooth" in repr(smooth) and "T=" not in repr(smooth)
    steel = roughroll.read_scene(DATA / "steel-rollers.toml")
    r = repr(steel)
    assert "E=210000000000.0" in r and "nu=0.3" in r and "k=400000000000000.0" in r and "cylinder2 smooth" in r
    alu = roughroll.read_scene(DATA / "aluminium-on-steel.toml")
    assert "shear_modulus" in repr(alu) and "beta_d=" in repr(alu)
    full = alu.replace(coupling="full")
    assert "coupling='full'" in repr(full) and repr(full) != repr(alu)
