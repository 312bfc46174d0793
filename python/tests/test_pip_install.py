# SPDX-License-Identifier: GPL-3.0-or-later
"""`pip install .` works offline in a venv over Debian's python3 (pyproject.toml, setup.py driving
the project's CMake), and the installed package imports and solves from any folder.

The source is copied first (the checkout is not written to).  Under CTest the copy and its
CMake build live in the build tree (ROUGHROLL_BUILD_DIR/pip-install-test) and are kept, copies
keeping their times, so a second run recompiles only what changed; the first run builds
roughroll_core and the module (a unity build at -O0: about 30 s of CPU)."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DATA, SOURCE_DIR

TIMEOUT = 1800  # a hang guard only: a busy machine may be slow


def venv_missing():
    try:
        import ensurepip  # noqa: F401
        import venv  # noqa: F401
    except ImportError as e:
        return f"python's venv/ensurepip is missing ({e}; Debian: python3-venv, scripts/install-deps)"
    return None


def source_files(root):
    """The files of the source tree as a clone has them (tracked and new, not ignored ones)."""
    if (root / ".git").exists() and shutil.which("git"):
        r = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                           capture_output=True, check=True)
        return [f for f in r.stdout.decode().split("\0") if f and (root / f).is_file()]
    skip = ("build", ".git", "reproduction", "out")
    return [str(p.relative_to(root)) for p in root.rglob("*")
            if p.is_file() and not p.relative_to(root).parts[0].startswith(skip)]


def sync(root, target):
    """Copies root's source files to target, keeping modification times (so make sees what changed),
    and removes the files root no longer has (pip's and CMake's build-pip/ apart)."""
    names = source_files(root)
    keep = set(names)
    if target.exists():
        for path in target.rglob("*"):
            name = path.relative_to(target)
            if path.is_file() and name.parts[0] != "build-pip" and str(name) not in keep:
                path.unlink()
    for name in names:
        src, dst = root / name, target / name
        st = src.stat()
        if dst.exists() and dst.stat().st_mtime_ns == st.st_mtime_ns and dst.stat().st_size == st.st_size:
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dst)


@pytest.mark.skipif(venv_missing() is not None, reason=venv_missing() or "")
def test_pip_install_in_a_venv_offline(tmp_path):
    build = os.environ.get("ROUGHROLL_BUILD_DIR")
    work = Path(build) / "pip-install-test" if build else tmp_path
    source = work / "src"
    sync(SOURCE_DIR, source)
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, timeout=TIMEOUT)

    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONDONTWRITEBYTECODE")}
    # Offline: no index at all (numpy, setuptools and wheel are Debian's, seen by the venv).
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    # The Release build at -O0 (the build type, NDEBUG and every other flag as setup.py sets them)
    # and a unity build: this test proves the install path, the optimised numbers are the CMake
    # build's, and that a per-file build answers as the unity build does is scripts/test's check of
    # the autotools program. The module's build takes 30 s of CPU against 68 s per file, the whole
    # test 38 s (docs/performance.md, "Session 26: test command"); the installed module's xi must
    # still equal the CMake build's below.
    env["ROUGHROLL_CMAKE_ARGS"] = " ".join(filter(None, [env.get("ROUGHROLL_CMAKE_ARGS", ""),
                                                         "'-DCMAKE_CXX_FLAGS_RELEASE=-O0 -DNDEBUG'",
                                                         "-DCMAKE_UNITY_BUILD=ON"]))
    r = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "."], cwd=source, env=env,
                       capture_output=True, text=True, timeout=TIMEOUT)
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-4000:]

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    code = f"""
import pickle, roughroll
assert roughroll.__file__.startswith({str(venv)!r}), roughroll.__file__
s = roughroll.read_scene({str(DATA / 'fig2a-T1.toml')!r})
p = s.point(0.1, method="product", n=48)
assert pickle.loads(pickle.dumps(p)) == p and pickle.loads(pickle.dumps(s)) == s
print(roughroll.__version__, p.xi)
"""
    r = subprocess.run([str(venv / "bin" / "python"), "-c", code], cwd=elsewhere, env=env,
                       capture_output=True, text=True, timeout=TIMEOUT)
    assert r.returncode == 0, r.stderr
    version, xi = r.stdout.split()
    assert version == (SOURCE_DIR / "VERSION").read_text().strip()
    import roughroll
    assert float(xi) == roughroll.read_scene(DATA / "fig2a-T1.toml").point(0.1, method="product", n=48).xi

    # Nothing written into the source tree but build-pip/ (ignored by git, as build*/).
    assert not list(source.glob("python/*.egg-info")) and not (source / "build").exists()
