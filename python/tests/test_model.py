# SPDX-License-Identifier: GPL-3.0-or-later
"""The model's pieces against independent routes: Carter's closed form written out here, the
kernel formula (3.23)-(3.24), the quadrature rule (4.6)-(4.7) and Hertz's solution."""

import math

import numpy as np
import pytest

import roughroll
from conftest import DATA


def test_carter_closed_form():
    f = 0.3
    for Q in [0.0, 0.03, 0.15, 0.29, 0.3, -0.15]:
        s = math.sqrt(1 - abs(Q) / f)
        c0, xi = roughroll.carter(Q, f)
        assert c0 == pytest.approx(2 * s - 1, abs=1e-15)
        assert xi == pytest.approx(math.copysign(2 * f / math.pi * (1 - s), Q), abs=1e-15)
    c0, xi = roughroll.carter(np.array([0.0, 0.15, 0.3]), f)
    assert c0.shape == xi.shape == (3,)
    assert c0.tolist() == [roughroll.carter(Q, f).c0 for Q in [0.0, 0.15, 0.3]]


def test_smooth_scene_is_carter():
    p = roughroll.point({"friction": 0.3}, 0.15)
    assert (p.c0, p.xi) == tuple(roughroll.carter(0.15, 0.3))
    assert p.hertz_load_ratio == 1.0


def test_kernel_formula():
    z = np.array([-2.0, -0.5, 0.25, 1.0, 3.0])
    terms = [(1.0, 0.5), (0.25, 2.0)]
    expected = sum(T * np.exp(-A * np.abs(z)) for T, A in terms) * np.sign(z)
    np.testing.assert_allclose(roughroll.kernel(terms, z), expected, rtol=1e-15)
    assert roughroll.kernel(terms, 0.0).tolist() == [0.0]
    assert roughroll.kernel([{"T": 1.0, "A": 0.5}], [1.0])[0] == pytest.approx(math.exp(-0.5))


def test_normal_problem_hertz_and_quadrature():
    h = roughroll.normal_problem(n=40, r=[0.0, 0.5])
    assert h["hertz_load_ratio"] == 1.0
    np.testing.assert_allclose(h["p"], 2 / math.pi * np.sqrt(1 - np.array([0.0, 0.25])), rtol=1e-14)
    # (4.6): sum w_k = int sqrt(1 - x^2) dx = pi/2; (4.7): n + 1 collocation points.
    assert h["weights"].sum() == pytest.approx(math.pi / 2, rel=1e-14)
    assert len(h["collocation"]) == 41


def test_normal_problem_is_the_scenes():
    # The same normal problem a scene's point solves, for method product at the same n.
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    p = s.point(method="product", n=64)
    d = roughroll.normal_problem([(1.0, 0.5)], n=64, method="product")
    assert d["hertz_load_ratio"] == p.hertz_load_ratio
    assert d["gamma"] == p.gamma
    # Product integration converges like 1/n^4: n = 64 and n = 128 agree to ~1e-7.
    fine = roughroll.normal_problem([(1.0, 0.5)], n=128, method="product")
    assert fine["hertz_load_ratio"] == pytest.approx(d["hertz_load_ratio"], rel=1e-6)


def test_citation_and_version():
    # CITATION.cff, VERSION and the module name one version; the JSON carries the paper.
    from conftest import SOURCE_DIR
    version = (SOURCE_DIR / "VERSION").read_text().split()[0]
    assert roughroll.__version__ == version
    cff = (SOURCE_DIR / "CITATION.cff").read_text()
    assert f'version: "{version}"' in cff
    assert "Rolling contact of long elastic cylinders with surface roughness described by a two parameter model" in cff
    assert "Pauk" in roughroll.REFERENCE and "two parameter model" in roughroll.REFERENCE
    assert roughroll.point({"friction": 0.3}, 0.1).reference == roughroll.REFERENCE
    assert roughroll.roughness(DATA / "roughness" / "flat-linear.toml")["reference"] == roughroll.REFERENCE


def test_every_call_has_a_docstring_citing_the_paper():
    import re
    calls = [roughroll.read_scene, roughroll.point, roughroll.solve, roughroll.roughness, roughroll.carter,
             roughroll.kernel, roughroll.normal_problem, roughroll.Scene, roughroll.Scene.point,
             roughroll.Scene.curve, roughroll.Scene.traction, roughroll.Point]
    for call in calls:
        doc = call.__doc__ or ""
        assert doc.strip(), call
    # The solvers' docstrings name the equations they solve, e.g. (3.21) or (4.5).
    for call in (roughroll.Scene.point, roughroll.Scene.curve, roughroll.Scene.traction, roughroll.roughness,
                 roughroll.carter, roughroll.kernel, roughroll.normal_problem, roughroll.Point):
        assert re.search(r"\(\d\.\d+\)", call.__doc__), call
