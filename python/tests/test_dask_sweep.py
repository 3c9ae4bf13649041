"""Sweeps: the Dask sweep on a two-process LocalCluster equals the local
sweep row for row, also when a worker is killed mid-sweep."""

import math
import os
import signal
import threading
import time

import pytest

import pegdyn
from conftest import SCENES

distributed = pytest.importorskip("dask.distributed")


def rows_equal(a, b):
    assert len(a) == len(b)
    for ra, rb in zip(a, b):
        assert ra.keys() == rb.keys()
        for k in ra:
            x, y = ra[k], rb[k]
            if isinstance(x, float) and math.isnan(x):
                assert isinstance(y, float) and math.isnan(y), k
            else:
                assert x == y, (k, x, y)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def pendulum(t_end):
    s = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum"))
    return s.with_values({"integrator.t_end": t_end, "integrator.output_interval": 0.1})


GRID = {"pendulum.theta0_deg": [5.0, 30.0, 60.0, 90.0, 120.0], "pendulum.length": [0.5, 1.0, 2.0]}


def test_local_sweep_rows():
    r = pegdyn.sweep(pendulum(2.0), GRID)
    assert len(r) == 15
    assert [row["index"] for row in r] == list(range(15))
    # Last key varies fastest.
    assert r[1]["pendulum.length"] == 1.0 and r[1]["pendulum.theta0_deg"] == 5.0
    assert all(row["outcome"] == "ok" for row in r)
    # Energy is conserved at every point (a real physical value per row).
    drift = r["max |E - E0| / (m g L)"]
    assert max(drift) < 1e-8
    # Given points give the same rows as the grid.
    pts = [{k: row[k] for k in GRID} for row in r]
    rows_equal(pegdyn.sweep(pendulum(2.0), points=pts).rows, r.rows)


def test_dask_sweep_equals_local(client):
    scene = pendulum(2.0)
    local = pegdyn.sweep(scene, GRID)
    for batch in (None, 1, 4, 100):
        rows_equal(pegdyn.sweep(scene, GRID, client=client, batch_size=batch).rows, local.rows)


def test_dask_sweep_survives_a_killed_worker(client):
    scene = pendulum(50.0)
    grid = {"pendulum.theta0_deg": [float(a) / 2 for a in range(1, 241)]}
    local = pegdyn.sweep(scene, grid)
    before = client.run(os.getpid)
    victim = sorted(before.values())[0]

    def kill():
        # Wait until batches are running, then kill one worker process.
        deadline = time.time() + 30
        while time.time() < deadline and not any(client.processing().values()):
            time.sleep(0.005)
        os.kill(victim, signal.SIGKILL)
        killed.append(time.time())

    killed = []
    t = threading.Thread(target=kill)
    t.start()
    # Single-threaded batches of 4 points: the sweep lasts long enough for
    # the kill to land mid-sweep.
    got = pegdyn.sweep(scene, grid, client=client, batch_size=4, threads=1)
    done = time.time()
    t.join()
    assert killed and killed[0] < done, "the worker was not killed mid-sweep"
    client.wait_for_workers(2, timeout=60)
    after = client.run(os.getpid)
    assert victim not in after.values()
    rows_equal(got.rows, local.rows)


def test_pandas_frame():
    pytest.importorskip("pandas")
    df = pegdyn.sweep(pendulum(0.5), {"pendulum.mass": [1.0, 2.0]}).to_pandas()
    assert list(df["pendulum.mass"]) == [1.0, 2.0]
    assert list(df.columns[:2]) == ["index", "pendulum.mass"]


def test_a_metric_named_like_a_row_field_does_not_overwrite_it():
    # The 3-D kinds report an `outcome` code among their metrics; the row's
    # own `outcome` ("ok", "stopped", ...) stays, the code comes beside it.
    s = pegdyn.load(next(p for p in SCENES if p.stem == "insert_rcc"))
    (row,) = pegdyn.sweep(s, points=[{"integrator.t_end": 0.02}])
    assert row["outcome"] == "ok", row
    assert row["error"] is None
    # Ended at t_end before the rim reached the mouth: stopped (code 5).
    assert row["outcome (summary)"] == 5.0, row
    assert row["end time [s]"] == 0.02
