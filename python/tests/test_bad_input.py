# SPDX-License-Identifier: GPL-3.0-or-later
"""Every bad input of docs/robustness.md that applies to the Python API raises the matching
exception with the program's one-line message (word for word, compared with the program's
stderr); Python-only mistakes (wrong types, None, NaN, huge arrays) raise and never crash."""

import math
import tomllib

import numpy as np
import pytest

import roughroll
from conftest import DATA, cli_error

GOOD = """friction = 0.3
Q = 0.15
[cylinder1.tangential]
T = 0.5
A = 0.5
[cylinder1.normal]
T = 0.5
A = 0.5
[solver]
n = 20
"""

PHYSICAL = """E = 210e9
nu = 0.3
R1 = 0.02
R2 = 0.02
P2 = 1.0e5
friction = 0.3
Q = 0.15
[cylinder1.tangential]
k = 4.0e14
t = 1.5e6
"""

# name, scene text, program options (and Python keywords), exception. The rows of
# docs/robustness.md ("Every kind of bad input") that a scene or a point's options reach.
I, R, N = roughroll.InputError, roughroll.ResolutionError, roughroll.NumericalError
ROWS = [
    ("empty-file", "", {}, I),
    ("malformed-toml", "friction = ", {}, I),
    ("truncated-toml", GOOD[:40], {}, I),
    ("wrong-type", 'friction = "high"', {}, I),
    ("wrong-type-T", GOOD.replace("T = 0.5", 'T = "0.5"', 1), {}, I),
    ("wrong-type-table", "friction = 0.3\ncylinder1 = 3", {}, I),
    ("array-of-tables", "friction = 0.3\n[[cylinder1]]", {}, I),
    ("n-float", GOOD.replace("n = 20", "n = 20.5"), {}, I),
    ("method-type", GOOD + "method = 1\n", {}, I),
    ("label-type", "label = 3\n" + GOOD, {}, I),
    ("unknown-key-top", "frction = 0.3\n" + GOOD, {}, I),
    ("unknown-key", GOOD + "frction = 0.3\n", {}, I),
    ("unknown-nested-key", GOOD.replace("A = 0.5", "Ax = 0.5", 1), {}, I),
    ("unknown-table", GOOD + "[cylinder3.normal]\nT = 1\nA = 1\n", {}, I),
    ("term-missing-A", GOOD.replace("A = 0.5\n", "", 1), {}, I),
    ("Q-missing", GOOD.replace("Q = 0.15\n", ""), {}, I),
    ("f-zero", "friction = 0.0", {}, I),
    ("f-negative", "friction = -0.3", {}, I),
    ("f-nan", "friction = nan", {}, I),
    ("f-inf", "friction = inf", {}, I),
    ("Q-nan-scene", GOOD.replace("Q = 0.15", "Q = nan"), {}, I),
    ("Q-inf-scene", GOOD.replace("Q = 0.15", "Q = inf"), {}, I),
    ("Q-above-f", GOOD.replace("Q = 0.15", "Q = 0.31"), {}, I),
    ("Q-huge-scene", GOOD.replace("Q = 0.15", "Q = 1e308"), {}, I),
    ("Q-nan-cli", GOOD, {"Q": math.nan}, I),
    ("Q-inf-cli", GOOD, {"Q": math.inf}, I),
    ("Q-below-minus-f", GOOD, {"Q": -0.3000001}, I),
    ("T-negative", GOOD.replace("T = 0.5", "T = -0.5", 1), {}, I),
    ("T-nan", GOOD.replace("T = 0.5", "T = nan", 1), {}, I),
    ("A-negative", GOOD.replace("A = 0.5", "A = -0.5", 1), {}, I),
    ("A-infinite", GOOD.replace("A = 0.5", "A = inf", 1), {}, I),
    ("A-nan", GOOD.replace("A = 0.5", "A = nan", 1), {}, I),
    ("n-small", GOOD.replace("n = 20", "n = 1"), {}, I),
    ("n-huge", GOOD.replace("n = 20", "n = 100000000"), {}, I),
    ("n-wraps-int", GOOD.replace("n = 20", "n = 4294967316"), {}, I),
    ("method-scene", GOOD + 'method = "spectral"\n', {}, I),
    ("n-cli", GOOD, {"n": 5000}, I),
    ("n-cli-negative", GOOD, {"n": -3}, I),
    ("n-cli-zero", GOOD, {"n": 0}, I),
    ("method-cli", GOOD, {"method": "spectral"}, I),
    ("physical-missing-R2", PHYSICAL.replace("R2 = 0.02\n", ""), {}, I),
    ("physical-nu-range", PHYSICAL.replace("nu = 0.3", "nu = 0.7"), {}, I),
    ("beta-d-bound", "beta_d = 0.75\n" + GOOD, {}, I),
    ("coupling-unknown", 'coupling = "strong"\n' + GOOD, {}, I),
    ("pair-poisson-range", PHYSICAL.replace("E = 210e9\nnu = 0.3\n", "")
     + "[cylinder1]\nshear_modulus = 23e9\npoisson = 0.6\n[cylinder2]\nshear_modulus = 82e9\npoisson = 0.28\n", {}, I),
    ("pair-and-E", PHYSICAL + "[cylinder1]\nshear_modulus = 23e9\npoisson = 0.3\n[cylinder2]\nshear_modulus = 82e9\npoisson = 0.28\n", {}, I),
    ("physical-E-negative", PHYSICAL.replace("E = 210e9", "E = -1.0"), {}, I),
    ("physical-R-zero", PHYSICAL.replace("R1 = 0.02", "R1 = 0.0"), {}, I),
    ("physical-two-planes", PHYSICAL.replace("R1 = 0.02", "R1 = inf").replace("R2 = 0.02", "R2 = inf"), {}, I),
    ("physical-P2-nan", PHYSICAL.replace("P2 = 1.0e5", "P2 = nan"), {}, I),
    ("physical-P1-slides", PHYSICAL.replace("Q = 0.15", "P1 = 3.1e4"), {}, I),
    ("physical-P1-and-Q", PHYSICAL.replace("Q = 0.15", "Q = 0.15\nP1 = 1e4"), {}, I),
    ("physical-P1-hertz-width", PHYSICAL.replace("Q = 0.15", 'P1 = 1e4\ncontact_width = "hertz"'), {}, I),
    ("physical-width-rule", PHYSICAL.replace("friction = 0.3", 'friction = 0.3\ncontact_width = "wide"'), {}, I),
    ("physical-t-zero", PHYSICAL.replace("t = 1.5e6", "t = 0.0"), {}, I),
    ("physical-k-negative", PHYSICAL.replace("k = 4.0e14", "k = -4e14"), {}, I),
    ("physical-term-half", PHYSICAL.replace("k = 4.0e14\n", ""), {}, I),
    ("physical-term-mixed", PHYSICAL.replace("t = 1.5e6", "t = 1.5e6\nT = 1.0"), {}, I),
    ("k-t-without-physical", "friction = 0.3\nQ = 0.1\n[cylinder1.normal]\nk = 1.0\nt = 1.0\n", {}, I),
    ("physical-width-above-radius", PHYSICAL.replace("R1 = 0.02", "R1 = 1e-12").replace("R2 = 0.02", "R2 = 1e-12"), {}, I),
    ("beyond-resolution", GOOD.replace("A = 0.5", "A = 1000") + 'method = "paper"\n', {}, R),
    ("extrapolated-coarse-level", GOOD.replace("A = 0.5", "A = 1e308", 1), {}, R),
    ("singular-system", GOOD.replace("T = 0.5", "T = 1e15", 1), {}, N),
    ("infinite-creep", GOOD.replace("T = 0.5", "T = 1e308", 1), {"Q": 0.3}, N),
    ("load-below-precision", GOOD, {"Q": 1e-15}, R),
]


def options(kw):
    out = []
    for key, value in kw.items():
        out += [f"--{key}", str(value)]
    return out


@pytest.mark.parametrize("name,text,kw,error", ROWS, ids=[r[0] for r in ROWS])
def test_scene_file_raises_the_programs_message(tmp_path, name, text, kw, error):
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    message = cli_error("point", path, *options(kw))
    with pytest.raises(error) as caught:
        roughroll.read_scene(path).point(**kw)
    assert str(caught.value) == message
    assert isinstance(caught.value, roughroll.Error)


@pytest.mark.parametrize("name,text,kw,error", ROWS, ids=[r[0] for r in ROWS])
def test_scene_dict_raises_the_same_message(tmp_path, name, text, kw, error):
    # The same scene as a dict (where it is valid TOML): the same message, the source named "scene".
    try:
        keys = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        pytest.skip("not valid TOML: no dict to give")
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    message = cli_error("point", path, *options(kw))
    with pytest.raises(error) as caught:
        roughroll.Scene(keys).point(**kw)
    assert str(caught.value) == message.replace(str(path), "scene")


def test_exception_hierarchy():
    assert issubclass(roughroll.InputError, ValueError)
    assert issubclass(roughroll.NumericalError, ArithmeticError)
    for e in (roughroll.InputError, roughroll.ResolutionError, roughroll.NumericalError):
        assert issubclass(e, roughroll.Error)


def test_file_errors(tmp_path):
    for path in [tmp_path / "nope.toml", tmp_path, "/dev/null"]:
        message = cli_error("point", path)
        with pytest.raises(roughroll.InputError) as caught:
            roughroll.read_scene(path)
        assert str(caught.value) == message
    with pytest.raises(roughroll.InputError, match="NUL"):
        roughroll.read_scene("data/fig2a-T1.toml\0x")


GOOD_SCENE = dict(friction=0.3, Q=0.15, cylinder1={"tangential": {"T": 0.5, "A": 0.5}}, solver={"n": 20})


@pytest.mark.parametrize("call", [
    lambda s: s.point("0.1"),
    lambda s: s.point([0.1]),
    lambda s: s.point(True),
    lambda s: s.point(n=20.0),
    lambda s: s.point(n="20"),
    lambda s: s.point(method=3),
    lambda s: s.point(zones=True),
    lambda s: s.curve(loads=[[0.1, 0.2]]),
    lambda s: s.curve(loads=["a"]),
    lambda s: s.curve(points=2.5),
    lambda s: s.curve(sweep="no"),
    lambda s: s.traction(r="x"),
    lambda s: roughroll.read_scene(3),
    lambda s: roughroll.point(3.0),
    lambda s: roughroll.Scene([1, 2]),
    lambda s: roughroll.Scene({1: 2}),
    lambda s: roughroll.Scene(friction=object()),
    lambda s: roughroll.solve([(s,)]),
    lambda s: roughroll.solve(3),
    lambda s: roughroll.carter("a", 0.3),
], ids=lambda c: None)
def test_wrong_types_raise_type_error(call):
    s = roughroll.Scene(GOOD_SCENE)
    with pytest.raises(TypeError):
        call(s)


@pytest.mark.parametrize("call,error", [
    (lambda s: s.point(n=10**30), roughroll.InputError),
    (lambda s: s.point(zones="several"), roughroll.InputError),
    (lambda s: s.point(-math.inf), roughroll.InputError),
    (lambda s: s.curve(points=1), roughroll.InputError),
    (lambda s: s.curve(points=10**30), roughroll.InputError),
    (lambda s: s.curve(loads=[0.1, math.nan]), roughroll.InputError),
    (lambda s: s.curve(loads=[0.1], sweep=True), roughroll.InputError),
    (lambda s: s.traction(points=2), roughroll.InputError),
    (lambda s: s.traction(r=[0.0, 1.5]), roughroll.InputError),
    (lambda s: s.traction(r=[math.nan]), roughroll.InputError),
    (lambda s: roughroll.Scene(), roughroll.InputError),
    (lambda s: roughroll.Scene(friction=0.3, Q=None).point(), roughroll.InputError),
    (lambda s: roughroll.Scene(friction=0.3, label="a\ud800"), roughroll.InputError),
    (lambda s: roughroll.Scene(friction=0.3, solver={"n": 10**30}), roughroll.InputError),
    (lambda s: roughroll.carter(0.5, 0.3), roughroll.InputError),
    (lambda s: roughroll.carter(0.1, math.nan), roughroll.InputError),
    (lambda s: roughroll.carter([0.1, math.nan], 0.3), roughroll.InputError),
    (lambda s: roughroll.kernel([(1.0, -1.0)], [1.0]), roughroll.InputError),
    (lambda s: roughroll.kernel([(math.inf, 1.0)], [1.0]), roughroll.InputError),
    (lambda s: roughroll.normal_problem([(1.0, 0.5)], method="extrapolated"), roughroll.InputError),
    (lambda s: roughroll.normal_problem([(1.0, 0.5)], n=1), roughroll.InputError),
    (lambda s: roughroll.roughness({"profile": "flat"}), roughroll.InputError),
    (lambda s: roughroll.roughness("no/such/spec.toml"), roughroll.InputError),
], ids=lambda c: None)
def test_bad_values_raise(call, error):
    s = roughroll.Scene(GOOD_SCENE)
    with pytest.raises(error):
        call(s)


def test_huge_arrays_do_not_crash():
    s = roughroll.Scene(GOOD_SCENE)
    z = np.linspace(-5, 5, 2_000_001)
    assert roughroll.kernel([(0.5, 0.5)], z).shape == z.shape
    t = s.traction(r=np.linspace(-1, 1, 100_001))
    assert t["p"].shape == (100_001,)
    with pytest.raises(roughroll.InputError):
        s.curve(loads=np.full(10_000_000, 0.31))  # refused at the first load, not after solving
