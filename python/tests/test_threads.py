# SPDX-License-Identifier: GPL-3.0-or-later
"""The batch call solves on several threads with exactly the serial loop's numbers, and the GIL
is released while the library solves."""

import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

import roughroll
from conftest import DATA, without_seconds


def scenes():
    return [roughroll.read_scene(DATA / name) for name in
            ("fig2a-T0.5.toml", "fig2a-T1.toml", "fig2b-A1.toml", "unequal-kernels.toml", "steel-rollers.toml")]


def test_batch_equals_serial_loop():
    items = [(s, Q) for s in scenes() for Q in (None, 0.05, 0.25)]
    items = [(s, Q if Q is not None and (s.Q is None or s.physical is None) else None) for s, Q in items]
    serial = [roughroll.point(s, Q, method="product", n=48) for s, Q in items]
    for threads in (1, 2, 3, 7):
        batch = roughroll.solve(items, threads=threads, method="product", n=48)
        assert [without_seconds(p.to_dict()) for p in batch] == [without_seconds(p.to_dict()) for p in serial]


def test_points_of_a_scene():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    loads = [0.0, 0.1, 0.2, 0.3, -0.2]
    got = s.points(loads, threads=2)
    assert [p.to_dict() | {"seconds": 0} for p in got] == [s.point(Q).to_dict() | {"seconds": 0} for Q in loads]


def test_python_threads_share_the_module():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    loads = [0.01 * k for k in range(1, 13)]
    serial = [without_seconds(s.point(Q).to_dict()) for Q in loads]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(lambda Q: without_seconds(s.point(Q).to_dict()), loads))
    assert parallel == serial


def test_gil_released_during_a_solve():
    # A long batch on a worker thread; this thread sleeps 0.3 s and then needs the GIL to go on.
    # With the GIL released by the solve it goes on at once; held, only when the solve returns.
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    items = [(s, 0.3 * k / 10) for k in range(1, 9)] * 4  # about 2 s on this machine
    times = {}
    started = threading.Event()

    def worker():
        times["call"] = time.monotonic()
        started.set()
        roughroll.solve(items, threads=1, method="paper", n=400)
        times["return"] = time.monotonic()

    t = threading.Thread(target=worker)
    t.start()
    started.wait()
    time.sleep(0.3)
    resumed = time.monotonic()
    t.join()
    solve_time = times["return"] - times["call"]
    assert solve_time > 1.0, "the solve is too short for this check: make it longer"
    assert resumed - times["call"] < solve_time - 0.5, "the solve held the GIL"


def test_threads_argument_checked():
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    with pytest.raises(roughroll.InputError):
        roughroll.solve([s], threads=0)
    with pytest.raises(TypeError):
        roughroll.solve([s], threads=1.5)
    with pytest.raises(TypeError):
        roughroll.solve([s], threads=True)
    assert roughroll.solve([], threads=2) == []


def test_batch_error_is_the_first_failing_item():
    good = roughroll.read_scene(DATA / "fig2a-T1.toml")
    with pytest.raises(roughroll.InputError, match=r"\|Q\| = 0.5 exceeds f = 0.3"):
        roughroll.solve([(good, 0.1), (good, 0.5), (good, float("nan"))], threads=2)


def test_threads_minus_one_is_every_core(monkeypatch):
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    items = [(s, 0.05 * k) for k in range(1, 5)]
    serial = [without_seconds(p.to_dict()) for p in roughroll.solve(items, method="product", n=48)]
    for threads in (-1, -2):
        got = roughroll.solve(items, threads=threads, method="product", n=48)
        assert [without_seconds(p.to_dict()) for p in got] == serial
    monkeypatch.setattr(roughroll, "_cores", lambda: 2)
    roughroll.solve(items[:1], threads=-2)  # one thread left
    with pytest.raises(roughroll.InputError, match=r"threads = -3 leaves no thread of the 2 cores"):
        roughroll.solve(items[:1], threads=-3)


def test_batch_error_names_the_item():
    good = roughroll.read_scene(DATA / "fig2a-T1.toml")
    smooth = roughroll.Scene(friction=0.3)  # no Q, no label
    with pytest.raises(roughroll.InputError) as e:
        roughroll.solve([(good, 0.1), good, (good, 0.5), (good, float("nan"))], threads=2)
    assert str(e.value) == ("items[2] (Q = 0.5, scene 'Fig. 2a, curve 3: T_1^(1) = T_1^(2) = 1, A_1^(1) = A_1^(2) = 0.5'): "
                            "Q must satisfy |Q| <= f, but |Q| = 0.5 exceeds f = 0.3: the cylinders slide")
    with pytest.raises(roughroll.InputError, match=r"^items\[1\] \(no Q\): no load Q given"):
        roughroll.solve([good, smooth])
    with pytest.raises(roughroll.InputError, match=r"^items\[0\] \(the scene's Q = 0.15, scene 'Fig. 2a"):
        roughroll.solve([good], method="nonesuch")


# What each Ctrl-C script starts with. Python's default SIGINT handler: a background job of a non-interactive shell
# (`.ci/run &`) inherits SIGINT ignored, Python then installs no handler and the script's os.kill is lost (the solve
# returns, not interrupted); these tests check roughroll's response to that handler, whatever the parent's
# disposition. interrupt_after: SIGINT once the process (every thread) has spent `cpu` more seconds of CPU, so that
# the interrupt lands after a given share of the work whatever the machine's load (a timer of the clock lands later
# in the work on an idle machine than on a busy one), and the scripts compare CPU seconds, not the clock's.
PRELUDE = r"""
import os, signal, threading, time
signal.signal(signal.SIGINT, signal.default_int_handler)


def interrupt_after(cpu):
    start = time.process_time()

    def wait():
        while time.process_time() - start < cpu:
            time.sleep(0.005)
        os.kill(os.getpid(), signal.SIGINT)

    # A daemon: where the solve returns uninterrupted, the script prints "returned" and exits.
    thread = threading.Thread(target=wait, daemon=True)
    thread.start()
    return start
"""


def interrupted_run(script, scene):
    """Runs a Ctrl-C script in a process of its own (SIGINT there cannot stop this test session)."""
    return subprocess.run([sys.executable, "-c", PRELUDE + script, str(DATA / scene)], capture_output=True,
                          text=True, timeout=900)


INTERRUPT = r"""
import sys
import roughroll
s = roughroll.read_scene(sys.argv[1])
c0 = time.process_time()
roughroll.solve([(s, 0.1)] * 4, method="paper", n=400)
one = (time.process_time() - c0) / 4
items = [(s, 0.3 * k / 41) for k in range(1, 41)] * 5
tasks = len(os.listdir("/proc/self/task"))
c0 = interrupt_after(2 * one)
try:
    roughroll.solve(items, threads=2, method="paper", n=400)
    print("returned", time.process_time() - c0, len(items) * one)
except KeyboardInterrupt:
    cpu = time.process_time() - c0
    print("interrupted", cpu, len(items) * one, len(os.listdir("/proc/self/task")) - tasks)
"""


def test_ctrl_c_stops_a_batch_between_points():
    r = interrupted_run(INTERRUPT, "fig2a-T1.toml")
    assert r.returncode == 0, r.stderr
    what, cpu, whole, *threads = r.stdout.split()
    assert what == "interrupted", r.stdout
    # Interrupted after two points' CPU: the batch stops with the points in flight and those the two
    # threads start before the next check (every 0.1 s), far from its 200 points' CPU (one point's
    # measured in the same process just before). A batch that ran to its end and raised only after
    # takes the whole.
    assert float(cpu) < float(whole) / 4, r.stdout
    assert threads == ["0"], "a thread of the batch is still running"


CURVE_INTERRUPT = r"""
import sys
import roughroll
s = roughroll.read_scene(sys.argv[1])
c0 = time.process_time()
s.curve([0.1] * 4, method="paper", n=400)
one = (time.process_time() - c0) / 4
loads = [0.3 * k / 201 for k in range(1, 201)]
c0 = interrupt_after(2 * one)
try:
    s.curve(loads, method="paper", n=400)
    print("returned", time.process_time() - c0, len(loads) * one)
except KeyboardInterrupt:
    print("interrupted", time.process_time() - c0, len(loads) * one)
"""


def test_ctrl_c_stops_a_curve_between_rows():
    # Issue 23, 4: a curve ran to its end under Ctrl-C (the GIL released, no check between rows).
    r = interrupted_run(CURVE_INTERRUPT, "fig2a-T1.toml")
    assert r.returncode == 0, r.stderr
    what, cpu, whole = r.stdout.split()
    assert what == "interrupted", r.stdout
    # Interrupted after two rows' CPU: stopped with the row in flight, far less than the whole curve's.
    assert float(cpu) < float(whole) / 4, r.stdout


POINT_INTERRUPT = r"""
import sys
import roughroll
s = roughroll.read_scene(sys.argv[1]).replace(coupling="full")
c0 = time.process_time()
s.point(0.0, n=48)  # full coupling refuses free rolling at n = 32 (docs/formulation.md 8(r))
whole = time.process_time() - c0
c0 = interrupt_after(0.1 * whole)
try:
    s.point(0.0, n=48)
    print("returned", time.process_time() - c0, whole)
except KeyboardInterrupt:
    print("interrupted", time.process_time() - c0, whole)
"""


def test_ctrl_c_stops_a_single_point_between_levels():
    # Issue 23, 4: one long point (full coupling: the width search's coupled points, the alternation's
    # steps, the estimate's levels) ran to its end under Ctrl-C; the contact's checkpoint now raises
    # KeyboardInterrupt before the next level or alternation step.
    r = interrupted_run(POINT_INTERRUPT, "aluminium-on-steel.toml")
    assert r.returncode == 0, r.stderr
    what, cpu, whole = r.stdout.split()
    assert what == "interrupted", r.stdout
    # Interrupted after a tenth of the point's own CPU (measured in the same process just before): it
    # stops at the next of its many checkpoints, well before the end (a returned point, or one that
    # ran to the end and was interrupted only after, takes the whole).
    assert float(cpu) < 0.6 * float(whole), r.stdout
