# SPDX-License-Identifier: GPL-3.0-or-later
"""`cmake --install` puts the package where Debian's python3 finds it: under the prefix, in the
folder ROUGHROLL_PYTHON_INSTALL_DIR, which is on sys.path for the default prefix /usr/local."""

import os
import subprocess
import sys

import pytest


def build_dir():
    d = os.environ.get("ROUGHROLL_BUILD_DIR")
    if not d:
        pytest.skip("ROUGHROLL_BUILD_DIR not set: run through CTest")
    return d


def test_installed_package_imports_and_solves(tmp_path):
    build = build_dir()
    folder = os.environ["ROUGHROLL_PYTHON_INSTALL_DIR"]
    prefix = tmp_path / "prefix"
    r = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    site = prefix / folder
    assert (site / "roughroll" / "__init__.py").is_file()
    code = ("import roughroll; assert roughroll.__file__.startswith(%r), roughroll.__file__; "
            "print(roughroll.point({'friction': 0.3}, 0.15).xi)") % str(site)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert float(r.stdout) == pytest.approx(roughroll_carter_xi(), rel=1e-14)


def roughroll_carter_xi():
    import math
    return 2 * 0.3 / math.pi * (1 - math.sqrt(1 - 0.5))


def test_default_prefix_is_on_pythons_path():
    folder = os.environ.get("ROUGHROLL_PYTHON_INSTALL_DIR") or pytest.skip("run through CTest")
    assert os.path.join("/usr/local", folder) in sys.path
