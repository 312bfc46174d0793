# SPDX-License-Identifier: GPL-3.0-or-later
"""The module and the program give the same numbers, bit for bit: points (every field of the
JSON but the wall time), curves (the CSV's shortest round-trip digits parse to the same
doubles), tractions, roughness parameters; scenes from dicts equal scenes from files."""

import csv
import io
import math
import tomllib

import numpy as np
import pytest

import roughroll
from conftest import DATA, cli_json, run, without_seconds

# (scene file, program options, Python keywords): every method, the special loads and the
# mirror case, a physical scene given by k, t and one given by its micro-geometry.
POINTS = [
    ("fig2a-T1.toml", [], {}),
    ("fig2a-T1.toml", ["--Q", "0.2", "--method", "paper", "--n", "40"], {"Q": 0.2, "method": "paper", "n": 40}),
    ("fig2a-T1.toml", ["--method", "extrapolated"], {"method": "extrapolated"}),
    ("fig2a-T1.toml", ["--method", "one-parameter", "--n", "64"], {"method": "one-parameter", "n": 64}),
    ("fig2a-T1.toml", ["--Q", "0"], {"Q": 0}),
    ("fig2a-T1.toml", ["--Q", "0.3"], {"Q": 0.3}),
    ("fig2a-T1.toml", ["--Q", "-0.1"], {"Q": -0.1}),
    ("fig2a-T0.toml", [], {}),
    ("unequal-kernels.toml", ["--n", "48"], {"n": 48}),
    ("steel-rollers.toml", [], {}),
    ("steel-rollers-ground.toml", ["--method", "product", "--n", "48"], {"method": "product", "n": 48}),
    # The zone search (docs/formulation.md section 7): found where the single zone fails, or
    # refused to it ("single": the single zone, its checks failed), or forced ("general").
    ("leading-slip.toml", [], {}),
    ("leading-slip.toml", ["--zones", "single"], {"zones": "single"}),
    ("fig2a-T1.toml", ["--zones", "general", "--method", "product", "--n", "48"],
     {"zones": "general", "method": "product", "n": 48}),
    # The friction over the scene's (Q = 0.15 stays: Q/f = 0.25).
    ("fig2a-T1.toml", ["--friction", "0.6"], {"friction": 0.6}),
]


@pytest.mark.parametrize("name,args,kw", POINTS, ids=lambda v: str(v) if isinstance(v, str) else None)
def test_point_equals_program_json(name, args, kw):
    path = DATA / name
    expected = cli_json("point", path, "--json", *args)
    got = roughroll.read_scene(path).point(**kw).to_dict()
    assert set(got) == set(expected)
    assert without_seconds(got) == without_seconds(expected)
    assert got["seconds"] > 0
    assert got["reference"] == roughroll.REFERENCE


def test_point_fields_are_attributes():
    p = roughroll.point(DATA / "fig2a-T1.toml")
    for key, value in p.to_dict().items():
        assert getattr(p, key) == value
    with pytest.raises(AttributeError):
        p.no_such_field
    with pytest.raises(AttributeError):
        p.c0 = 1.0
    assert "c0=" in repr(p)


@pytest.mark.parametrize("name", ["fig2a-T1.toml", "unequal-kernels.toml", "steel-rollers.toml",
                                  "steel-rollers-ground.toml"])
def test_scene_from_dict_equals_scene_from_file(name):
    path = DATA / name
    keys = tomllib.loads(path.read_text())
    from_file = roughroll.read_scene(path).point(n=32, method="product").to_dict()
    from_dict = roughroll.Scene(keys, base_dir=DATA).point(n=32, method="product").to_dict()
    assert without_seconds(from_dict) == without_seconds(from_file)
    # Keyword arguments are the same keys.
    from_kw = roughroll.scene(base_dir=DATA, **keys).point(n=32, method="product").to_dict()
    assert without_seconds(from_kw) == without_seconds(from_file)


def read_csv(text):
    rows = [r for r in csv.reader(io.StringIO(text)) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {h: [row[i] for row in body] for i, h in enumerate(header)}


def as_float(column):
    return np.array([float(x) if x != "" else math.nan for x in column])


@pytest.mark.parametrize("name,args,kw", [
    ("fig2a-T1.toml", ["--points", "9"], {"points": 9}),
    ("fig2a-T1.toml", ["--points", "9", "--sweep", "--method", "product"], {"points": 9, "sweep": True, "method": "product"}),
    ("fig2a-T0.5.toml", ["--points", "7", "--method", "paper", "--n", "30"], {"points": 7, "method": "paper", "n": 30}),
    ("steel-rollers.toml", ["--points", "5", "--sweep"], {"points": 5, "sweep": True}),
    ("fig2a-T1.toml", ["--points", "5", "--friction", "0.45"], {"points": 5, "friction": 0.45}),
], ids=["given-loads", "swept", "paper", "physical", "friction"])
def test_curve_equals_program_csv(name, args, kw):
    status, out, err = run("curve", DATA / name, *args)
    assert status == 0, err
    expected = read_csv(out)
    got = roughroll.read_scene(DATA / name).curve(**kw)
    assert set(got) == set(expected)
    assert_curve_equal(got, expected)


def assert_curve_equal(got, expected):
    refused = [s == "refused" for s in expected["status"]]
    for key, column in expected.items():
        if key == "checks_hold":
            assert got[key].tolist() == [c == "1" for c in column]
        elif key in ("status", "zone_path"):
            assert got[key].tolist() == column
        elif key in ("zones", "n"):  # int arrays: 0 where the CSV is empty (a refused row)
            assert got[key].tolist() == [0 if r else int(c) for r, c in zip(refused, column)]
        else:
            np.testing.assert_array_equal(got[key], as_float(column), err_msg=key)


# A physical pair at full coupling: the width follows the tangential load, a width per point and
# per curve row (docs/formulation.md 8(e)): gross sliding at Q = -f and f, each at its own width
# (equal here: lambda is even in Q at gross sliding; FullCouplingPhysical.CurveRowsHaveTheirOwnWidths
# has loads whose widths differ).
def test_physical_full_coupling_equals_program(tmp_path):
    text = (DATA / "aluminium-on-steel.toml").read_text().replace('coupling = "johnson"', 'coupling = "full"')
    path = tmp_path / "pair-full.toml"
    path.write_text(text + '[solver]\nn = 32\nmethod = "product"\n')
    expected = cli_json("point", path, "--json")
    got = roughroll.read_scene(path).point().to_dict()
    assert without_seconds(got) == without_seconds(expected)
    assert got["si"]["a_over_a_hertz"] != 1.0
    status, out, err = run("curve", path, "--points", "2")
    assert status == 0, err
    curve = roughroll.read_scene(path).curve(points=2)
    assert_curve_equal(curve, read_csv(out))
    assert curve["status"].tolist() == ["ok", "ok"]


# A curve with refused points (issue 10's leftover): a very stiff normal layer at n = 16, where
# some loads have no honest error estimate. The program exits 3 with one stderr line per
# refused row; the module gives the same rows (NaN where the CSV is empty) and warns the same
# lines.
STIFF = """friction = 0.3
[cylinder2.normal]
T = 1e6
A = 1
[solver]
n = 16
method = "product"
"""


@pytest.mark.parametrize("sweep,points", [(False, 7), (True, 5)], ids=["given-loads", "swept"])
def test_curve_with_refused_points_equals_program(tmp_path, sweep, points):
    path = tmp_path / "stiff.toml"
    path.write_text(STIFF)
    status, out, err = run("curve", path, "--points", points, *(["--sweep"] if sweep else []))
    assert status == 3, err
    expected = read_csv(out)
    with pytest.warns(roughroll.RefusedPointWarning) as record:
        got = roughroll.read_scene(path).curve(points=points, sweep=sweep)
    assert set(got) == set(expected)
    assert_curve_equal(got, expected)
    refused = got["status"] == "refused"
    assert 1 <= refused.sum() < len(refused)
    assert np.all(np.isnan(got["xi"][refused])) and np.all(np.isfinite(got["xi"][~refused]))
    # Carter's columns are numbers in every row (at the given load, or at the given c0 on a swept
    # curve), and no answered row has a load outside [0, f] (the swept curve's Q(c0) = -28.8 at
    # c0 = 0.5 of this scene is refused: no physical point).
    assert np.all(np.isfinite(got["xi_carter"])) and np.all(np.isfinite(got["c0_carter"]))
    f = 0.3
    assert np.all((got["Q"][~refused] >= 0) & (got["Q"][~refused] <= f))
    lines = [str(w.message) for w in record if issubclass(w.category, roughroll.RefusedPointWarning)]
    assert ["roughroll: refused: " + line for line in lines] == err.splitlines()


def test_curve_at_given_loads_equals_points():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    loads = [0.05, 0.15, 0.25]
    c = s.curve(loads)
    for i, Q in enumerate(loads):
        p = s.point(Q)
        assert (c["Q"][i], c["c0"][i], c["xi"][i]) == (p.Q, p.c0, p.xi)


# Dissimilar rollers (docs/formulation.md 8(j)): the default loads run from -f to f (the curve is not
# odd in Q), the module's curve is the program's CSV, the creep rises with the load, and a row is the
# point at its load (to the bit where no previous row gave a start: the braked three zones; five-zone
# rows start from the previous row's ends, the same root to Newton's resolution).
DISSIMILAR = """friction = 0.05
beta_d = 0.1438337435056057
[solver]
n = 16
"""


def test_dissimilar_curve_covers_both_signs_and_equals_program(tmp_path):
    path = tmp_path / "dissimilar.toml"
    path.write_text(DISSIMILAR)
    status, out, err = run("curve", path, "--points", "5")
    assert status == 0, err
    expected = read_csv(out)
    s = roughroll.read_scene(path)
    got = s.curve(points=5)
    assert_curve_equal(got, expected)
    assert got["Q"].tolist() == [-0.05, -0.025, 0.0, 0.025, 0.05]
    assert np.all(np.diff(got["xi"]) > 0)
    braked = s.point(-0.025)
    assert (got["c0"][1], got["xi"][1]) == (braked.c0, braked.xi)
    free = s.point(0.0)
    assert abs(got["xi"][2] - free.xi) <= 1e-12


# A row answered with its edge layers neglected says so, as the point does (formulation 7(i), 8(n)).
def test_curve_row_says_layers_neglected():
    s = roughroll.read_scene(DATA / "aluminium-on-steel.toml")
    got = s.curve(points=3, friction=5.0)
    assert got["zone_path"].tolist() == ["general", "no-slip", "general"]
    assert s.point(0.0, friction=5.0).to_dict()["zone_path"] == "no-slip"


# leading-slip.toml takes the general zone search (slip, stick, slip: docs/formulation.md
# section 7): its stick zone is [start, c0], not [-1, c0].
@pytest.mark.parametrize("name", ["traction-example.toml", "leading-slip.toml"])
def test_traction_equals_program_csv(tmp_path, name):
    status, _, err = run("traction", DATA / name, "--points", "41", "--no-plot",
                         "--out", tmp_path, "--name", "t")
    assert status == 0, err
    expected = read_csv((tmp_path / "traction-t.csv").read_text())
    got = roughroll.read_scene(DATA / name).traction(points=41)
    for key, column in [("r", "r"), ("p", "p"), ("p1", "p1"), ("slip_velocity", "slip_velocity"), ("f_p", "f_p")]:
        np.testing.assert_array_equal(got[key], as_float(expected[column]), err_msg=key)
    assert got["stick"].tolist() == [z == "stick" for z in expected["zone"]]
    # Independent: the pressure integrates to 1 (4.3) and the traction to Q (3.22); the
    # traction never exceeds f p (3.3).
    r = np.linspace(-1, 1, 2001)
    t = roughroll.read_scene(DATA / "traction-example.toml").traction(r=r)
    assert np.trapz(t["p"], r) == pytest.approx(1.0, abs=2e-5)
    assert np.trapz(t["p1"], r) == pytest.approx(t["point"].Q, abs=2e-5)
    assert np.all(np.abs(t["p1"]) <= t["f_p"] + 1e-12)


def test_roughness_equals_program_json():
    spec = DATA / "roughness" / "ground-measured.toml"
    expected = cli_json("roughness", spec, "--json")
    assert roughroll.roughness(spec) == expected
    assert roughroll.roughness(str(spec)) == expected
    keys = tomllib.loads(spec.read_text())
    from_dict = roughroll.roughness(keys, base_dir=spec.parent)
    assert {k: v for k, v in from_dict.items() if k != "spec"} == {k: v for k, v in expected.items() if k != "spec"}


def test_friction_keyword_is_the_scene_with_that_friction(tmp_path):
    # friction= replaces the scene's key: the same point as a scene file with that friction.
    text = (DATA / "fig2a-T1.toml").read_text().replace("friction = 0.3", "friction = 0.6")
    assert "friction = 0.6" in text
    path = tmp_path / "f06.toml"
    path.write_text(text)
    a = roughroll.read_scene(DATA / "fig2a-T1.toml").point(friction=0.6, n=32, method="product").to_dict()
    b = roughroll.read_scene(path).point(n=32, method="product").to_dict()
    assert without_seconds(a) == without_seconds(b)
    assert a["f"] == 0.6


@pytest.mark.parametrize("friction,error,text", [
    (0.0, roughroll.InputError, "friction 0 is outside"),
    (math.nan, roughroll.InputError, "friction nan is outside"),
    (0.1, roughroll.InputError, "slide"),  # the scene's Q = 0.15 above the new f
    ("0.3", TypeError, "friction must be a number"),
])
def test_friction_keyword_refuses_bad_values(friction, error, text):
    with pytest.raises(error, match=text):
        roughroll.point(DATA / "fig2a-T1.toml", friction=friction)

