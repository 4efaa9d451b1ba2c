"""Faults during a run or a campaign: a finished result is never lost, a partial one never taken
as done, and the final numbers equal those of an uninterrupted run.

* ``floatmoor run`` killed with SIGKILL mid-way, then resumed;
* ``floatmoor campaign`` killed with SIGKILL mid-way, then resumed;
* a Dask worker killed during a campaign;
* a full disk (a small tmpfs; skipped where it cannot be mounted, e.g. without root: the fast
  test ``tests/io/test_hostile_inputs.py::test_a_full_disk_is_reported_as_such`` simulates it);
* two runs started into one folder.

Every test compares the final result files with those of an uninterrupted run of the same
command into another folder, array by array (bit for bit).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

pytestmark = [pytest.mark.slow,
              pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")]

ROOT = Path(__file__).resolve().parents[1]
OC3 = ROOT / "vessels" / "oc3_hywind"
MINI = ROOT / "tests" / "campaign" / "mini.yaml"
ENV = dict(os.environ, PYTHONPATH=str(ROOT))


def _scene(tmp_path) -> Path:
    p = tmp_path / "oc3.yaml"
    p.write_text(f"name: oc3-faults\nsite: {{water_depth: 320.0}}\n"
                 f"vessel: {OC3 / 'vessel.yaml'}\nmooring: {OC3 / 'mooring.yaml'}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 6.0, tp: 12.0}\n"
                 "analysis: {duration: 300.0, dt: 0.1, transient: 50.0, ramp: 20.0, "
                 "seeds: [1, 6]}\n")
    return p


def _floatmoor(*argv, **kw):
    return [sys.executable, "-m", "floatmoor", *map(str, argv)]


def _arrays(path) -> dict:
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        return {k: np.asarray(v[...]) for k, v in nc.variables.items()}


def _assert_same_files(a_dir, b_dir, pattern):
    a = sorted(Path(a_dir).glob(pattern))
    b = sorted(Path(b_dir).glob(pattern))
    assert [p.relative_to(a_dir) for p in a] == [p.relative_to(b_dir) for p in b] and a
    for pa, pb in zip(a, b):
        xa, xb = _arrays(pa), _arrays(pb)
        assert xa.keys() == xb.keys()
        for k in xa:
            np.testing.assert_array_equal(xa[k], xb[k], err_msg=f"{pa.name}: {k}")


def _wait_for(predicate, timeout, what):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        if predicate():
            return
        time.sleep(0.1)
    raise AssertionError(f"{what} within {timeout} s")


def _children(pid) -> list[int]:
    out = []
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                stat = (d / "stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                out.append(int(d.name))
    return out


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """Seeds 1-6 of the short OC3 scene, uninterrupted."""
    tmp = tmp_path_factory.mktemp("ref")
    scene = _scene(tmp)
    out = tmp / "ref"
    done = subprocess.run(_floatmoor("run", scene, "--out", out, "--workers", "2"), env=ENV,
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    return scene, out


def test_run_killed_then_resumed(reference, tmp_path):
    """SIGKILL of ``floatmoor run`` (the parent alone) after two seeds: its workers end with it,
    the finished files are whole and kept (not recomputed: same modification time), no
    temporary file is taken for a result, the folder is not left locked; the resume computes
    the rest and every file equals the uninterrupted run's."""
    scene, ref = reference
    out = tmp_path / "out"
    proc = subprocess.Popen(_floatmoor("run", scene, "--out", out, "--workers", "2"), env=ENV,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        _wait_for(lambda: len(list(out.glob("*.nc"))) >= 2, 600, "two seeds finished")
        workers = _children(proc.pid)
        proc.send_signal(signal.SIGKILL)
        proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    _wait_for(lambda: not any(Path(f"/proc/{w}").exists() for w in workers), 30,
              "the workers ended with their parent")
    kept = {p: p.stat().st_mtime_ns for p in out.glob("*.nc")}
    assert 2 <= len(kept) < 6
    resume = subprocess.run(_floatmoor("run", scene, "--out", out, "--workers", "2"), env=ENV,
                            capture_output=True, text=True, timeout=900)
    assert resume.returncode == 0, resume.stderr
    assert resume.stdout.count("already done") == len(kept)
    assert all(p.stat().st_mtime_ns == t for p, t in kept.items())
    assert not list(out.glob("*.tmp"))
    _assert_same_files(ref, out, "*.nc")


def test_two_runs_into_one_folder(reference, tmp_path):
    """A second ``floatmoor run`` into a folder the first is writing into is refused at once
    (exit 2, naming the first's process); the first finishes every seed, equal to the
    uninterrupted run (two runs used to lose a seed)."""
    scene, ref = reference
    out = tmp_path / "out"
    cmd = _floatmoor("run", scene, "--out", out, "--workers", "2", "--seeds", "1-40")
    first = subprocess.Popen(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    try:
        lock = out / ".floatmoor.lock"
        _wait_for(lambda: lock.is_file() and lock.read_text().strip(), 120, "the lock taken")
        t0 = time.monotonic()
        second = subprocess.run(cmd, env=ENV, capture_output=True, text=True, timeout=300)
        assert first.poll() is None, "the first run ended before the second started"
        assert second.returncode == 2, second.stderr
        assert f"pid {first.pid} (floatmoor run oc3.yaml" in second.stderr
        assert "Traceback" not in second.stderr and time.monotonic() - t0 < 60
        stdout, stderr = first.communicate(timeout=900)
    finally:
        if first.poll() is None:
            first.kill()
    assert first.returncode == 0, stderr
    assert len(list(out.glob("*.nc"))) == 40
    _assert_same_files(ref, out, "*_seed000[1-6].nc")


def _mount_tmpfs(path: Path, size: str) -> bool:
    path.mkdir(parents=True, exist_ok=True)
    try:
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)],
                           capture_output=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return False
    return r.returncode == 0


def test_full_disk_run(reference, tmp_path):
    """``floatmoor run`` onto a tmpfs with room for about two seed files: it stops saying the
    disk is full (exit 2, the folder and the free space named), keeps the finished seeds; after
    the tmpfs is enlarged the same command computes the rest, equal to the uninterrupted
    run."""
    scene, ref = reference
    one = max(p.stat().st_size for p in ref.glob("*.nc"))
    disk = tmp_path / "disk"
    if not _mount_tmpfs(disk, f"{int(2.5 * one) // 1024}k"):
        pytest.skip("cannot mount a tmpfs here (needs root): the full disk is simulated in "
                    "tests/io/test_hostile_inputs.py")
    try:
        out = disk / "out"
        full = subprocess.run(_floatmoor("run", scene, "--out", out, "--workers", "1"), env=ENV,
                              capture_output=True, text=True, timeout=900)
        assert full.returncode == 2, full.stdout + full.stderr
        assert f"floatmoor: error: {out}: no space left on the device" in full.stderr
        assert "finished and kept" in full.stderr and "Traceback" not in full.stderr
        kept = sorted(out.glob("*.nc"))
        assert 1 <= len(kept) <= 2 and not list(out.glob("*.tmp"))
        subprocess.run(["mount", "-o", f"remount,size={10 * one // 1024}k", str(disk)],
                       check=True, timeout=30)
        resume = subprocess.run(_floatmoor("run", scene, "--out", out, "--workers", "1"),
                                env=ENV, capture_output=True, text=True, timeout=900)
        assert resume.returncode == 0, resume.stderr
        assert resume.stdout.count("already done") == len(kept)
        _assert_same_files(ref, out, "*.nc")
    finally:
        subprocess.run(["umount", "-l", str(disk)], timeout=30)


# -- campaigns ------------------------------------------------------------------------------------
CAMPAIGN = ("--scheduler", "serial", "--duration", "150")


@pytest.fixture(scope="module")
def campaign_reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("campaign") / "ref"
    done = subprocess.run(_floatmoor("campaign", MINI, "--out", out, *CAMPAIGN), env=ENV,
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    return out


def _td_done(out):
    from floatmoor.campaign import store
    if not (out / store.MANIFEST).is_file():
        return 0
    return sum(1 for (k, _, _), r in store.Manifest(out).latest().items()
               if k == "td" and r["status"] == "done")


def test_campaign_killed_then_resumed(campaign_reference, tmp_path):
    """SIGKILL of ``floatmoor campaign`` after two storms: the resume keeps the FD case and the
    two storms (not recomputed), computes the two others, and every result file equals the
    uninterrupted campaign's."""
    out = tmp_path / "out"
    proc = subprocess.Popen(_floatmoor("campaign", MINI, "--out", out, *CAMPAIGN), env=ENV,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        _wait_for(lambda: _td_done(out) >= 2, 600, "two storms finished")
        proc.send_signal(signal.SIGKILL)
        proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    from floatmoor.campaign import store
    n = _td_done(out)
    done = [store.storm_path(out, c, s) for (k, c, s), r in store.Manifest(out).latest().items()
            if k == "td" and r["status"] == "done"]
    kept = {p: p.stat().st_mtime_ns for p in done}
    assert 2 <= n < 4
    resume = subprocess.run(_floatmoor("campaign", MINI, "--out", out, *CAMPAIGN), env=ENV,
                            capture_output=True, text=True, timeout=900)
    assert resume.returncode == 0, resume.stderr
    assert f"already done: fd 1, td {n}" in resume.stdout, resume.stdout
    assert all(p.stat().st_mtime_ns == t for p, t in kept.items())   # kept, not recomputed
    assert not list(out.rglob("*.tmp"))
    _assert_same_files(campaign_reference, out, "td/*/*.nc")
    _assert_same_files(campaign_reference, out, "fd/*.nc")


def test_dask_worker_killed_during_a_campaign(campaign_reference, tmp_path):
    """A Dask worker killed (SIGKILL) at the first finished storm: the scheduler reruns its
    task on the other worker; every storm is done once in the manifest and equals the serial,
    uninterrupted campaign's."""
    import logging

    from dask.distributed import Client, LocalCluster

    from floatmoor.campaign import store
    from floatmoor.campaign.engine import run_campaign
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=logging.ERROR)
    client = Client(cluster)
    killed = []

    def kill_one(outcome):
        if outcome["kind"] == "td" and not killed:
            pid = min(client.run(os.getpid).values())
            os.kill(pid, signal.SIGKILL)
            killed.append(pid)

    out = tmp_path / "out"
    try:
        r = run_campaign(MINI, out, client=client, echo=None, on_outcome=kill_one,
                         analysis_overrides={"duration": 150.0})
    finally:
        client.close()
        cluster.close()
    assert killed and not r.failed
    td = [v for k, v in store.Manifest(out).latest().items() if k[0] == "td"]
    assert len(td) == 4 and all(v["status"] == "done" for v in td)
    _assert_same_files(campaign_reference, out, "td/*/*.nc")


def test_full_disk_campaign(campaign_reference, tmp_path):
    """A campaign onto a tmpfs that fills after the FD case and a storm or two: it stops saying
    the disk is full (exit 2), the finished results are in the manifest; enlarged, the same
    command resumes and every result equals the uninterrupted campaign's."""
    storms = sorted((campaign_reference / "td").rglob("*.nc"))
    one = max(p.stat().st_size for p in storms)
    base = sum(p.stat().st_size for p in campaign_reference.rglob("*") if p.is_file()
               and p not in storms)
    disk = tmp_path / "disk"
    if not _mount_tmpfs(disk, f"{(base + int(1.5 * one) + 65536) // 1024}k"):
        pytest.skip("cannot mount a tmpfs here (needs root)")
    try:
        out = disk / "out"
        full = subprocess.run(_floatmoor("campaign", MINI, "--out", out, *CAMPAIGN), env=ENV,
                              capture_output=True, text=True, timeout=900)
        assert full.returncode == 2, full.stdout + full.stderr
        assert "no space left on the device" in full.stderr, full.stderr
        assert "Traceback" not in full.stderr
        n = _td_done(out)
        subprocess.run(["mount", "-o", f"remount,size={(base + 10 * one) // 1024}k", str(disk)],
                       check=True, timeout=30)
        resume = subprocess.run(_floatmoor("campaign", MINI, "--out", out, *CAMPAIGN), env=ENV,
                                capture_output=True, text=True, timeout=900)
        assert resume.returncode == 0, resume.stderr
        assert f"td {n}" in resume.stdout.split("already done:")[1]
        _assert_same_files(campaign_reference, out, "td/*/*.nc")
    finally:
        subprocess.run(["umount", "-l", str(disk)], timeout=30)
