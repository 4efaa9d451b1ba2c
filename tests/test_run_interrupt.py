"""``floatmoor run`` results folders: Ctrl-C stops a batch (exit 130, no partial file, the
interrupted seeds recorded, a resume command printed); a rerun into a folder of another scene
is refused unless --force; a truncated result file is detected and computed again."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from floatmoor.cli import main

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[1]
OC3 = ROOT / "vessels" / "oc3_hywind"


def _scene(tmp_path, hs=6.0, name="oc3_waves.yaml") -> Path:
    p = tmp_path / name
    p.write_text(f"name: oc3-waves\nsite: {{water_depth: 320.0}}\n"
                 f"vessel: {OC3 / 'vessel.yaml'}\nmooring: {OC3 / 'mooring.yaml'}\n"
                 f"environment:\n  waves: {{spectrum: jonswap, hs: {hs}, tp: 12.0}}\n"
                 "analysis: {duration: 150.0, dt: 0.1, transient: 50.0, ramp: 20.0, seeds: 1}\n")
    return p


def test_sigint_stops_a_running_batch(tmp_path):
    """SIGINT while seeds run in two workers: exit 130 within a few seconds, no *.tmp file,
    interrupted.txt lists the seeds not computed, stderr says how to resume; a rerun of the
    finished seeds skips them."""
    scene = _scene(tmp_path)
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    cmd = [sys.executable, "-m", "floatmoor", "run", str(scene), "--seeds", "1-200",
           "--workers", "2", "--duration", "600", "--out", str(out)]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=env)
    try:
        t0 = time.monotonic()
        while time.monotonic() - t0 < 240.0:  # wait for the first finished seed
            if out.is_dir() and list(out.glob("*.nc")):
                break
            time.sleep(0.2)
        assert list(out.glob("*.nc")), "no seed finished in 240 s"
        time.sleep(0.5)
        t_int = time.monotonic()
        proc.send_signal(signal.SIGINT)
        stdout, stderr = proc.communicate(timeout=30)
        stopped_in = time.monotonic() - t_int
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 130, stderr
    assert stopped_in < 15.0
    assert "Traceback" not in stderr
    assert not list(out.glob("*.tmp"))
    finished = sorted(out.glob("*.nc"))
    record = (out / "interrupted.txt").read_text()
    left = [int(s) for s in record.split(":", 1)[1].split()]
    assert len(finished) + len(left) == 200 and len(left) > 0
    assert "resume with the same command" in stderr and "floatmoor run" in stderr
    done_seeds = sorted(int(f.stem.rsplit("seed", 1)[1]) for f in finished)
    assert not set(done_seeds) & set(left)
    # resume: the finished seeds are skipped (valid, same fingerprint)
    seeds = ",".join(str(s) for s in done_seeds)
    rerun = subprocess.run(cmd[:6] + [seeds] + cmd[7:], capture_output=True, text=True,
                           env=env, timeout=120)
    assert rerun.returncode == 0, rerun.stderr
    assert rerun.stdout.count("already done") == len(done_seeds)


def test_rerun_of_another_scene_into_the_same_folder(tmp_path, capsys):
    """A folder holding seeds of Hs 6 m: a rerun with Hs 8 m is refused naming the section that
    differs (environment); --force computes them again; a truncated file is computed again."""
    out = tmp_path / "out"
    a = _scene(tmp_path, 6.0)
    assert main(["run", str(a), "--seeds", "1", "--out", str(out), "--workers", "1",
                 "--duration", "60"]) == 0
    b = _scene(tmp_path, 8.0, name="oc3_waves_b.yaml")
    capsys.readouterr()
    assert main(["run", str(b), "--seeds", "1", "--out", str(out), "--workers", "1",
                 "--duration", "60"]) == 2
    err = capsys.readouterr().err
    assert str(b) in err and "differ in: environment" in err and "--force" in err
    assert main(["run", str(b), "--seeds", "1", "--out", str(out), "--workers", "1",
                 "--duration", "60", "--force"]) == 0
    assert "computing it again (--force)" in capsys.readouterr().out
    # truncate the result: detected and recomputed, not "already done"
    f = next(out.glob("*.nc"))
    data = f.read_bytes()
    f.write_bytes(data[: len(data) // 2])
    assert main(["run", str(b), "--seeds", "1", "--out", str(out), "--workers", "1",
                 "--duration", "60"]) == 0
    text = capsys.readouterr().out
    assert "unreadable or incomplete" in text and "already done" not in text
    import xarray as xr
    with xr.open_dataset(f) as ds:
        assert ds.attrs["input_fingerprint"] and ds["motion"].shape[0] == 601
