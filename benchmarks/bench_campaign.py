"""Benchmark of design campaigns (`floatmoor campaign`).

Run:  .venv/bin/python benchmarks/bench_campaign.py [--storms-duration 12000] [--seeds 4]
      [--repeats 1] [--skip-dry-run]

* ``--dry-run`` of the example campaign (7 sea states x 24 headings x 13 conditions) in a fresh
  process, as a user types it (target < 10 s);
* a small campaign (the 100-year peak sea state, 2 headings, intact, ``--seeds`` seeds of
  ``--storms-duration`` s at dt 0.1 s, every case in TD) on a Dask LocalCluster of 1 and of 2
  workers (``--repeats`` times, alternately): wall time of ``run_campaign``, the speed-up
  (target: 2 workers >= 1.8 x faster than 1) and the campaign overhead (target < 5 %).

  Overhead.  The work is the storms' own run time (the wall time of each ``simulate`` call, in
  the manifest's ``simulate_s``) plus the FD cases' (``frequency_domain`` calls, ``solve_s``);
  ideal = work / workers; overhead = (wall - ideal) / ideal.  It holds everything else:
  the client (campaign file, record, manifest, screening), the scheduling, each worker's warm-up
  (imports, base scene build, compiled-kernel cache loads; paid once per worker, in its first
  task), and per task the case scene, statistics and compressed writing.  The cluster start is
  outside ``run_campaign`` and reported apart.  Also printed: the per-storm part (task wall -
  simulate, mean) and the overhead with the FD tasks' whole wall time (warm-up included)
  counted as work, as this script measured it before.
* the example campaign's wall time on 1, 2, 64 and 512 cores, extrapolated from the measured
  cost per time step and per FD case (the number of TD cases from ``results/campaign`` when a
  screened run is there, else the bounds).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

CAMPAIGN = """name: bench
base_scene: {base}
sea_states: {{list: [{{name: peak, hs: 16.0, tp: 18.2}}]}}
headings: {{waves_deg: [0, 15]}}
conditions: {{intact: true}}
seeds: "1-{seeds}"
analysis: {{duration: {duration}, dt: 0.1, transient: 1200.0, ramp: 100.0}}
screening: {{time_domain: all}}
storage: {{mode: {storage}, precision: float32, compression: 4}}
"""


def _load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def dry_run() -> float:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    t = time.perf_counter()
    out = subprocess.run([sys.executable, "-m", "floatmoor", "campaign",
                          str(ROOT / "campaigns" / "floatel_uls_als.yaml"), "--dry-run"],
                         capture_output=True, text=True, env=env, cwd=ROOT, check=False)
    wall = time.perf_counter() - t
    print(out.stdout)
    if out.returncode:
        print(out.stderr)
    return wall


def campaign_run(path: Path, workers: int) -> dict:
    import logging

    from dask.distributed import Client, LocalCluster

    from floatmoor.campaign import store
    from floatmoor.campaign.engine import run_campaign
    t = time.perf_counter()
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=logging.ERROR)
    client = Client(cluster)
    start = time.perf_counter() - t
    try:
        with tempfile.TemporaryDirectory() as out:
            t = time.perf_counter()
            r = run_campaign(path, out, client=client, echo=None)
            wall = time.perf_counter() - t
            rows = store.Manifest(out).rows()
            # storms: the TD tasks and, in statistics mode, the governing cases' series reruns
            td = [x for x in rows if x["kind"] in ("td", "series")]
            fd = [x for x in rows if x["kind"] == "fd"]
            odd = [x for x in td if not x["simulate_s"]]
            if odd:  # a storm without a simulate time (failed or not run): say so, do not count it
                print(f"{len(odd)} TD row(s) without a simulate time: "
                      f"{sorted({(x['status'], x.get('error', '')[:80]) for x in odd})}")
            sim = sum(float(x["simulate_s"]) for x in td if x["simulate_s"])
            task = sum(float(x["wall_time_s"]) for x in td if x["simulate_s"])
            fd_task = sum(float(x["wall_time_s"]) for x in fd)
            # FD solve time (an older manifest without it: the task wall)
            fd_solve = sum(float(x.get("solve_s") or x["wall_time_s"]) for x in fd)
            nbytes = sum(int(x["bytes"]) for x in td if x["bytes"])
    finally:
        client.close()
        cluster.close()
    ideal = (sim + fd_solve) / workers
    ideal_fd_task = (sim + fd_task) / workers
    return {"workers": workers, "cluster_start": start, "wall": wall, "task": task,
            "simulate": sim, "fd_tasks": fd_task, "fd_solve": fd_solve,
            "storms": len(td), "fd": r.ran.get("fd", 0), "bytes": nbytes, "load": _load(),
            "overhead": (wall - ideal) / ideal,
            "overhead_with_start": (wall + start - ideal) / ideal,
            "overhead_fd_task_as_work": (wall - ideal_fd_task) / ideal_fd_task,
            "per_storm": (task - sim) / max(1, len(td) - len(odd))}


def simulate_times(path: Path) -> tuple[float, float]:
    """Setup + loop time of one storm of the bench campaign in this process (2nd run: warm)."""
    import warnings

    from floatmoor.campaign import _api
    from floatmoor.campaign.matrix import build_matrix, case_scene
    from floatmoor.campaign.spec import load_campaign
    spec = load_campaign(path)
    case = build_matrix(spec)[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        base = _api.load_scene(spec.base_scene)
        scene, failed = case_scene(base, case, dict(spec.analysis))
        for _ in range(2):
            t = time.perf_counter()
            ds = _api.simulate(_api.build(scene, failed_lines=failed), seed=1)
            wall = time.perf_counter() - t
    n = round(scene.analysis.duration / scene.analysis.dt)
    return wall, float(ds.attrs["run_time_s"]) / n


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--storms-duration", type=float, default=12000.0)
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--repeats", type=int, default=1, help="pairs of 1- and 2-worker runs")
    ap.add_argument("--skip-dry-run", action="store_true")
    ap.add_argument("--storage", choices=("full", "statistics"), default="full",
                    help="storage mode of the bench campaign (the example campaign's is "
                         "statistics: the governing cases' series rerun at the end, counted "
                         "as storms)")
    args = ap.parse_args()
    print(f"load average at start: {_load()}")
    dr = float("nan") if args.skip_dry_run else dry_run()
    print(f"dry run of the example campaign: {dr:.1f} s (load {_load()})")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.yaml"
        path.write_text(CAMPAIGN.format(base=(ROOT / "scenes" / "floatel_100yr.yaml").as_posix(),
                                        seeds=args.seeds, duration=args.storms_duration,
                                        storage=args.storage))
        storm_wall, step = simulate_times(path)
        print(f"one storm of {args.storms_duration:g} s in this process: {storm_wall:.2f} s "
              f"(loop {step * 1e6:.0f} us per step)")
        runs = []
        for _ in range(args.repeats):
            for w in (1, 2):
                r = campaign_run(path, w)
                runs.append(r)
                print(f"LocalCluster {w} worker(s) (start {r['cluster_start']:.1f} s): "
                      f"{r['storms']} storms + {r['fd']} FD in {r['wall']:.1f} s; storms' own "
                      f"run time {r['simulate']:.1f} s, FD solve {r['fd_solve']:.2f} s (FD tasks "
                      f"{r['fd_tasks']:.1f} s with the worker warm-up); overhead "
                      f"{100 * r['overhead']:.1f} % (with the cluster start "
                      f"{100 * r['overhead_with_start']:.1f} %; FD task time as work "
                      f"{100 * r['overhead_fd_task_as_work']:.1f} %); per storm task - simulate "
                      f"{r['per_storm']:.2f} s; {r['bytes'] / 1e6:.1f} MB (load {r['load']})")
        one = [r for r in runs if r["workers"] == 1]
        two = [r for r in runs if r["workers"] == 2]
        for a, b in zip(one, two):
            print(f"speed-up 2 workers / 1: {a['wall'] / b['wall']:.2f} (with the cluster start: "
                  f"{(a['wall'] + a['cluster_start']) / (b['wall'] + b['cluster_start']):.2f})")
    # extrapolation of the example campaign
    from floatmoor.campaign.estimate import estimate
    from floatmoor.campaign.spec import load_campaign
    spec = load_campaign(ROOT / "campaigns" / "floatel_uls_als.yaml")
    e = estimate(spec, fd_budget=0.0)
    n_steps = 120000
    storm = storm_wall - step * args.storms_duration / 0.1 + step * n_steps
    scr = ROOT / "results" / "campaign" / "screening.csv"
    n_td = None
    if scr.is_file():
        rows = scr.read_text().splitlines()[1:]
        n_td = sum(int(r.split(",")[3]) for r in rows if r)
    print(f"example: {e.n_cases} FD cases at {e.fd_case_s:.2f} s; 3-hour storm (12000 s, dt 0.1)"
          f" {storm:.1f} s; TD cases: {n_td if n_td is not None else 'unknown'}")
    for nc in ([n_td] if n_td is not None else [e.td_cases_min, e.td_cases_max]):
        e.storm_s = storm
        print(f"  {nc} TD cases x 20 seeds: " + ", ".join(
            f"{e.wall_time(c, nc) / 3600:.2f} h on {c}" for c in (1, 2, 64, 512)))
    print(json.dumps({"dry_run_s": dr, "runs": runs, "storm_3h_s": storm,
                      "fd_case_s": e.fd_case_s}, default=str))


if __name__ == "__main__":
    main()
