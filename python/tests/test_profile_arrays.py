# SPDX-License-Identifier: GPL-3.0-or-later
"""A measured profile given as arrays (issue 25): NumPy arrays of x1 and h0, the CSV's columns,
as the micro-geometry keys profile_x1 and profile_h0 of a scene or a roughness spec, give the
very numbers of the CSV path; bad arrays raise InputError (TypeError for a wrong shape) naming
the problem; a scene with arrays pickles and round-trips through to_dict."""

import copy
import pickle
import tomllib

import numpy as np
import pytest

import roughroll
from conftest import DATA


def profile():
    x1, h0 = np.loadtxt(DATA / "profiles" / "ground.csv", delimiter=",", comments="#", skiprows=4, unpack=True)
    return x1, h0


def spec_with_arrays():
    spec = tomllib.loads((DATA / "roughness" / "ground-measured.toml").read_text())
    x1, h0 = profile()
    spec.pop("profile_csv")
    spec["profile_x1"], spec["profile_h0"] = x1, h0
    return spec


def test_roughness_from_arrays_equals_csv():
    expected = roughroll.roughness(DATA / "roughness" / "ground-measured.toml")
    got = roughroll.roughness(spec_with_arrays())
    for key in ("k_tangential", "t_tangential", "k_normal", "t_normal"):
        assert got[key] == expected[key], key


def test_scene_from_arrays_equals_csv():
    file = roughroll.read_scene(DATA / "steel-rollers-ground.toml")
    d = file.to_dict()
    x1, h0 = profile()
    layer = dict(d["cylinder1"]["micro_geometry"])
    layer.pop("profile_csv")
    layer["profile_x1"], layer["profile_h0"] = x1, h0
    d["cylinder1"] = {"micro_geometry": layer}
    s = roughroll.Scene(d)  # no base_dir needed: no file is read
    assert s.physical["cylinder1"] == file.physical["cylinder1"]
    a, b = s.point(n=32, method="product").to_dict(), file.point(n=32, method="product").to_dict()
    a.pop("seconds"), b.pop("seconds")
    assert a == b
    # The arrays travel with the scene: pickled, copied, and back through to_dict.
    assert pickle.loads(pickle.dumps(s)) == s
    assert copy.deepcopy(s) == s
    back = s.to_dict()["cylinder1"]["micro_geometry"]
    assert back["profile_x1"] == x1.tolist() and back["profile_h0"] == h0.tolist()
    # file.replace with arrays in place of the CSV.
    r = file.replace(cylinder1={"micro_geometry": {"profile_csv": None, "profile_x1": x1, "profile_h0": h0}})
    assert r.physical["cylinder1"] == file.physical["cylinder1"]


BASE = dict(lambda0=1.15e11, mu0=7.7e10, H=1e-5, l=4e-6, profile="measured", decay="cosine")
X = np.array([0, 1e-6, 2e-6, 3e-6])
H = np.array([1e-6, 2e-6, 3e-6, 2e-6])


@pytest.mark.parametrize("x1,h0,words", [
    (X, H[:3], "profile_x1' has 4 samples but '"),
    (X[:3], H[:3], "needs at least 4 samples"),
    (np.array([0, 1e-6, np.nan, 3e-6]), H, "index:2: x1 = nan is not finite"),
    (X, np.array([1e-6, np.inf, 3e-6, 2e-6]), "index:1: h0 = inf is not finite"),
    (np.array([0, 2e-6, 1e-6, 3e-6]), H, "index:2: x1 = 1e-06 does not increase"),
    (X + 1e-7, H, "index:0: the first sample must be at x1 = 0"),
    (np.array([0, 1e-6, 2e-6, 5e-6]), H, "index:3: x1 = 5e-06 is beyond the period l = 4e-06"),
    (X, -H, "index:0: h0 = -1e-06 is below 0"),
    (X, H + 1e-5, "is not below H = 1e-05"),
    (np.array([]), np.array([]), "needs at least 4 samples"),
], ids=["lengths", "too-few", "x-nan", "h-inf", "not-increasing", "not-from-0", "beyond-l", "negative", "above-H", "empty"])
def test_bad_arrays_raise_naming_the_problem(x1, h0, words):
    with pytest.raises(roughroll.InputError, match=None) as caught:
        roughroll.roughness(dict(BASE, profile_x1=x1, profile_h0=h0))
    assert words in str(caught.value)
    # The same in a scene's micro-geometry, the key named with its table.
    scene = dict(E=210e9, nu=0.3, R1=0.02, R2=0.02, P2=1e5, Q=0.1, friction=0.3,
                 cylinder1={"micro_geometry": dict(BASE, profile_x1=x1, profile_h0=h0)})
    with pytest.raises(roughroll.InputError) as caught:
        roughroll.Scene(scene)
    assert words in str(caught.value) and "cylinder1.micro_geometry" in str(caught.value)


def test_wrong_shapes_and_mixtures():
    with pytest.raises(TypeError, match="one-dimensional"):
        roughroll.roughness(dict(BASE, profile_x1=np.zeros((2, 4)), profile_h0=H))
    with pytest.raises(roughroll.InputError, match="missing key 'profile_h0'"):
        roughroll.roughness(dict(BASE, profile_x1=X))
    with pytest.raises(roughroll.InputError, match="not both"):
        roughroll.roughness(dict(BASE, profile_x1=X, profile_h0=H, profile_csv="p.csv"))
    with pytest.raises(roughroll.InputError, match="must be a number"):
        roughroll.roughness(dict(BASE, profile_x1=["0", "1e-6", "2e-6", "3e-6"], profile_h0=H))
    # Plain lists work as arrays do.
    assert roughroll.roughness(dict(BASE, profile_x1=X.tolist(), profile_h0=H.tolist())) == \
        roughroll.roughness(dict(BASE, profile_x1=X, profile_h0=H))


def test_float_arrays_are_written_as_their_lists():
    # The fast path for float arrays writes what the element-wise one writes, nan and inf included.
    from roughroll import _toml
    v = np.array([0.0, 1e-300, -2.5, np.nan, np.inf, -np.inf, 1 / 3, 5e-324 * 0])
    assert _toml.dumps({"a": v}) == _toml.dumps({"a": [float(e) for e in v]})
    assert _toml.dumps({"a": np.array([1, 2])}) == _toml.dumps({"a": [1, 2]})
