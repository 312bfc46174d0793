# SPDX-License-Identifier: GPL-3.0-or-later
"""Scenes and points through a real Dask cluster: a scheduler and two workers, separate processes
on 127.0.0.1 started here (in another working folder, with the module on PYTHONPATH only), tasks
that capture scenes and return points equal to the serial loop's."""

import functools
import os
import socket
import subprocess
import sys
import time

import pytest

import roughroll
from conftest import DATA, without_seconds

distributed = pytest.importorskip("distributed", reason="Dask's distributed (Debian: python3-distributed, scripts/install-deps) is not installed")

# Generous: the machine may be busy. Only a hang is caught, never slowness.
START_TIMEOUT = 300
RESULT_TIMEOUT = 600


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def stop(processes):
    for p in processes:
        if p.poll() is None:
            p.terminate()
    for p in processes:
        try:
            p.wait(timeout=30)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dask")
    env = dict(os.environ)
    # The workers import roughroll from where this process did (the build tree's python folder).
    env["PYTHONPATH"] = os.path.dirname(os.path.dirname(os.path.abspath(roughroll.__file__)))
    address = f"tcp://127.0.0.1:{free_port()}"
    processes = []
    logs = []

    def start(name, *args):
        log = open(folder / f"{name}.log", "w")
        logs.append(log)
        processes.append(subprocess.Popen([sys.executable, "-m", *args], cwd=folder, env=env,
                                          stdout=log, stderr=subprocess.STDOUT))

    try:
        start("scheduler", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1],
              "--no-dashboard", "--no-show")
        for k in (1, 2):
            start(f"worker{k}", "distributed.cli.dask_worker", address, "--host", "127.0.0.1", "--nthreads", "1",
                  "--no-nanny", "--no-dashboard", "--memory-limit", "0", "--local-directory", str(folder / f"w{k}"))
        c = distributed.Client(address, timeout=START_TIMEOUT)
        try:
            c.wait_for_workers(2, timeout=START_TIMEOUT)
            yield c
        finally:
            c.close()
    except Exception:
        for log in logs:
            log.flush()
        print("\n".join((folder / f"{n}.log").read_text() for n in ("scheduler", "worker1", "worker2")
                        if (folder / f"{n}.log").exists()))
        raise
    finally:
        stop(processes)
        for log in logs:
            log.close()


def test_cluster_has_two_worker_processes(client):
    workers = client.scheduler_info()["workers"]
    assert len(workers) == 2
    pids = client.run(os.getpid)
    assert len(set(pids.values())) == 2 and os.getpid() not in pids.values()


def test_tasks_capturing_scenes_return_the_serial_points(client):
    scenes = [roughroll.read_scene(DATA / name) for name in ("fig2a-T1.toml", "steel-rollers-ground.toml")]
    loads = [0.05, 0.1, 0.2, -0.15]
    serial = [without_seconds(s.point(Q, method="product", n=48).to_dict()) for s in scenes for Q in loads]
    # A bound method carries its scene; each task pickles it to a worker and a Point back.
    futures = [client.submit(functools.partial(s.point, method="product", n=48), Q, pure=False)
               for s in scenes for Q in loads]
    points = client.gather(futures)
    assert all(isinstance(p, roughroll.Point) for p in points)
    assert [without_seconds(p.to_dict()) for p in points] == serial
    # Both workers took part (tasks are spread over idle workers).
    assert len({w for ws in client.who_has(futures).values() for w in ws}) == 2


def test_batches_and_scenes_travel_both_ways(client):
    s = roughroll.read_scene(DATA / "fig2a-T1.toml")
    items = [(s.replace(friction=f), 0.5 * f) for f in (0.2, 0.3, 0.4)]
    solved = client.submit(functools.partial(roughroll.solve, method="product", n=48), items, pure=False)
    got = solved.result(timeout=RESULT_TIMEOUT)
    assert [without_seconds(p.to_dict()) for p in got] == \
           [without_seconds(p.to_dict()) for p in roughroll.solve(items, method="product", n=48)]
    # A scene made on a worker arrives equal to the one made here.
    made = client.submit(roughroll.read_scene, str(DATA / "steel-rollers-ground.toml"), pure=False)
    assert made.result(timeout=RESULT_TIMEOUT) == roughroll.read_scene(DATA / "steel-rollers-ground.toml")
