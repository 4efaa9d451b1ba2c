"""What a campaign task does inside a Dask worker: no scheduler round trip per netCDF variable
written, and the per-worker warm-up changes no result."""

import multiprocessing
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from floatmoor.campaign.engine import SINGLE_THREAD_ENV
from floatmoor.campaign.matrix import build_matrix
from floatmoor.campaign.spec import load_campaign
from floatmoor.campaign.tasks import run_storm, warm_worker, write_netcdf

HERE = Path(__file__).parent
distributed = pytest.importorskip("dask.distributed")


def _dataset():
    t = np.arange(2000) * 0.1
    return xr.Dataset({"a": (("time",), np.sin(t), {"units": "m"}),
                       "b": (("time", "line"), np.cos(np.outer(t, [1.0, 2.0, 3.0])))},
                      coords={"time": t, "line": ["l1", "l2", "l3"]}, attrs={"case": "x"})


def _count_lock_acquires(path, use_write_netcdf):
    """In a worker thread: write a small dataset; how many distributed.Lock acquisitions."""
    from distributed.lock import Lock
    calls = []
    original = Lock.acquire

    def counting(self, *args, **kwargs):
        calls.append(1)
        return original(self, *args, **kwargs)

    Lock.acquire = counting
    try:
        if use_write_netcdf:
            write_netcdf(_dataset(), Path(path))
        else:
            _dataset().to_netcdf(path, engine="netcdf4")
    finally:
        Lock.acquire = original
    return len(calls)


def test_write_in_a_worker_takes_no_distributed_lock(tmp_path):
    """xarray, inside a Dask worker, locks each file with a ``distributed.Lock`` (scheduler round
    trips for every variable and attribute: 0.2-0.5 s per storm file measured in a LocalCluster
    worker).  ``write_netcdf`` writes under a process-local lock; the file's bytes are those of
    the same write outside Dask."""
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        plain = client.submit(_count_lock_acquires, tmp_path / "plain.nc", False).result()
        if plain == 0:
            pytest.skip("this xarray takes no distributed lock in a worker: nothing to avoid")
        ours = client.submit(_count_lock_acquires, tmp_path / "ours.nc", True).result()
    assert ours == 0
    write_netcdf(_dataset(), tmp_path / "outside.nc")
    assert (tmp_path / "ours.nc").read_bytes() == (tmp_path / "outside.nc").read_bytes()


def _storm_in_fresh_process(base, case, analysis, storage, out, warm):
    if warm:
        info = warm_worker(base, analysis)
        assert not info["error"], info["error"]
    o = run_storm(base, case, 2, analysis, storage, out)
    assert o["status"] == "done", o["error"]
    return o


@pytest.mark.slow  # two fresh processes (imports, scene, kernel caches) and three short storms
def test_warmed_worker_gives_the_file_of_a_fresh_process(tmp_path, monkeypatch):
    """A storm run after ``warm_worker`` (base scene, built mooring and the kernels loaded by a
    short FD and a 20-step storm in the same process) is byte for byte the storm run first in a
    fresh process: the warm-up leaves no state that a task reads.  A failed-line case is run
    after the intact warm-up as well (the built mooring is cached per condition)."""
    for k, v in SINGLE_THREAD_ENV.items():
        monkeypatch.setenv(k, v)
    spec = load_campaign(HERE / "tiny_all.yaml")
    cases = build_matrix(spec)
    base = str(Path(spec.base_scene).resolve())
    analysis = dict(spec.analysis)
    ctx = multiprocessing.get_context("spawn")
    for case in (cases[0], next(c for c in cases if c.condition.lines)):
        files = []
        for warm in (False, True):
            out = tmp_path / f"{case.id}-{warm}.nc"
            with ProcessPoolExecutor(1, mp_context=ctx) as pool:
                pool.submit(_storm_in_fresh_process, base, case, analysis, spec.storage,
                            str(out), warm).result()
            files.append(out.read_bytes())
        assert files[0] == files[1], case.id


def test_tables_returned_by_the_tasks_are_the_files(tmp_path):
    """The client screens with the values the FD and storm tasks return (``table``) instead of
    reading every file back: they are the files' values, bit for bit, and the loaders give the
    same arrays from either."""
    from floatmoor.campaign import store
    from floatmoor.campaign.tasks import run_fd_cases
    spec = load_campaign(HERE / "mini.yaml")
    case = build_matrix(spec)[0]
    base = str(Path(spec.base_scene).resolve())
    analysis = dict(spec.analysis)
    fd = run_fd_cases(base, [case], analysis, str(tmp_path))[0]
    path = store.storm_path(tmp_path, case.id, 1)
    td = run_storm(base, case, 1, analysis, spec.storage, str(path))
    assert fd["status"] == td["status"] == "done"
    for o, names, p in ((fd, store.FD_TABLE_VARS, store.fd_path(tmp_path, case.id)),
                        (td, store.TD_TABLE_VARS, path)):
        on_disk = store._read_vars(p, names)
        assert sorted(o["table"]) == sorted(on_disk) == sorted(names)
        for k in names:
            assert o["table"][k].tobytes() == on_disk[k].tobytes(), k
    a = store.load_fd_table(tmp_path, [case.id])
    b = store.load_fd_table(tmp_path / "elsewhere", [case.id], {case.id: fd["table"]})
    a2 = store.load_td_statistics(tmp_path, [case.id], [1])
    b2 = store.load_td_statistics(tmp_path / "elsewhere", [case.id], [1],
                                  known={(case.id, 1): td["table"]})
    for x, y in ((a, b), (a2, b2)):
        assert sorted(x) == sorted(y)
        for k in x:
            np.testing.assert_array_equal(x[k], y[k])
