"""Benchmark of design campaigns (`floatmoor campaign`): overhead, speed-up, extrapolation.

Run (the command for a quiet 2-core machine, about 5 minutes):

    .venv/bin/python benchmarks/bench_campaign.py --storage statistics --seeds 6

Options: ``--storms-duration`` (default 12000 s at dt 0.1 s, the example campaign's 3-hour
storm), ``--seeds``, ``--storage full|statistics`` (statistics is the example campaign's mode:
the statistics of every storm, then the governing cases' series rerun from their seeds and
counted as storms), ``--repeats`` (pairs of 1- and 2-worker runs, alternately),
``--skip-dry-run``, ``--compare TREE`` (another checkout of floatmoor, e.g. the code before a
change: each repeat then runs TREE and this tree alternately, same campaign, same cluster
sizes), ``--td-cases`` (the example's TD cases after screening, for the extrapolation).

* ``--dry-run`` of the example campaign (7 sea states x 24 headings x 13 conditions) in a fresh
  process, as a user types it (target < 10 s);
* a campaign of the 100-year peak sea state, 2 wave headings, intact, ``--seeds`` seeds, every
  case in TD, on a Dask LocalCluster of 1 and of 2 single-threaded workers, the cluster that
  ``floatmoor campaign`` starts (``engine.local_cluster``), started outside ``run_campaign``
  (its start is printed apart).

Definition of the overhead (target < 5 %).  The work is the storms' own run time (the wall time
of each ``simulate`` call, ``simulate_s``) plus the FD cases' (``frequency_domain`` calls,
``solve_s``); ideal = work / workers; overhead = (wall of ``run_campaign`` - ideal) / ideal.  It
is printed split into

* per storm: task wall - ``simulate`` (case scene, statistics, writing the file), the mean;
* warm-up, once per worker: imports, base scene, compiled-kernel caches (``warm_worker``, run on
  every worker before its first task, while the client reads the base scene; with ``--compare``
  on a tree without it: the first FD task's wall - its solve time);
* the rest: the client (campaign file, record, manifest, screening), scheduling, and the
  workers idle at the end of a phase (the FD phase, the storms, the series reruns: each waits
  for its last task) = wall - (tasks + warm-up) / workers.

CPU-time figures (``time.process_time`` of the client process, which holds the LocalCluster's
scheduler, and of every worker process, all threads) are printed too: on a loaded machine the
wall figures measure the waiting for a core, the CPU figures what the campaign adds.  CPU
overhead = (client CPU + workers' CPU - simulate CPU - FD solve CPU) / (simulate + FD solve CPU).
The speed-up is wall(1 worker) / wall(2 workers); the storms' own run time per storm on 2
workers over 1 worker (two storms share the memory bandwidth of the 2 cores) is printed with
it, as it bounds the speed-up whatever the campaign does.

The example campaign's wall time on 1, 2, 64 and 512 cores is extrapolated from the measured
per-storm cost (in this process, warm) and the measured overheads (module docstring of the
extrapolation below).
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


def campaign_run(tree: Path, campaign: Path, workers: int) -> dict:
    """One ``run_campaign`` of ``campaign`` with the floatmoor of ``tree`` on a new LocalCluster
    of ``workers``, in a fresh process (this script with ``--one-run``): its JSON summary."""
    env = dict(os.environ, PYTHONPATH=str(tree), OMP_NUM_THREADS="1", MKL_NUM_THREADS="1",
               OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, __file__, "--one-run", str(tree), str(campaign),
                          str(workers)], capture_output=True, text=True, env=env, cwd=tree,
                         check=False)
    if out.returncode:
        raise RuntimeError(f"campaign run failed:\n{out.stdout}\n{out.stderr}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def one_run(tree: Path, campaign: Path, workers: int) -> dict:
    """In this (fresh) process: cluster, campaign, the raw times of every task and warm-up."""
    import logging
    import warnings

    from dask.distributed import Client, LocalCluster

    from floatmoor.campaign import engine
    from floatmoor.campaign.engine import run_campaign
    warnings.simplefilter("ignore")
    t = time.perf_counter()
    if hasattr(engine, "local_cluster"):  # the cluster `floatmoor campaign` starts
        cluster = engine.local_cluster(workers)
    else:  # code from before it
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0", silence_logs=logging.ERROR)
    client = Client(cluster)
    start = time.perf_counter() - t
    outs = []
    try:
        with tempfile.TemporaryDirectory() as out:
            cpu_w0 = client.run(time.process_time)
            cpu_c0, load0 = time.process_time(), _load()
            t = time.perf_counter()
            r = run_campaign(campaign, out, client=client, echo=None, on_outcome=outs.append)
            wall = time.perf_counter() - t
            cpu_c = time.process_time() - cpu_c0
            cpu_w1 = client.run(time.process_time)
    finally:
        client.close()
        cluster.close()
    keep = ("kind", "status", "wall_time_s", "simulate_s", "solve_s", "cpu_s", "simulate_cpu_s",
            "solve_cpu_s", "pid", "bytes", "error")
    return {"tree": str(tree), "workers": workers, "cluster_start": start, "wall": wall,
            "client_cpu": cpu_c, "workers_cpu": sum(cpu_w1[k] - cpu_w0[k] for k in cpu_w1),
            "warmup": list(getattr(r, "warmup", [])), "load": f"{load0} -> {_load()}",
            "tasks": [{k: o.get(k) for k in keep} for o in outs]}


def summarise(run: dict) -> dict:
    """The overhead of one run, split as in the module docstring (wall and CPU)."""
    w = run["workers"]
    tasks = run["tasks"]
    storms = [x for x in tasks if x["kind"] in ("td", "series") and x.get("simulate_s")]
    fd = [x for x in tasks if x["kind"] == "fd"]
    bad = [x for x in tasks if x["status"] != "done"]
    sim = sum(x["simulate_s"] for x in storms)
    solve = sum(x.get("solve_s") or 0.0 for x in fd)
    work = sim + solve
    task_wall = sum(x["wall_time_s"] for x in storms + fd)
    per_storm = sum(x["wall_time_s"] - x["simulate_s"] for x in storms) / max(1, len(storms))
    per_fd = (sum(x["wall_time_s"] - (x.get("solve_s") or 0.0) for x in fd) / max(1, len(fd)))
    if run["warmup"]:
        warm = [x["wall_time_s"] for x in run["warmup"]]
        warm_cpu = [x["cpu_s"] for x in run["warmup"]]
        warm_src = "warm_worker"
    else:  # code without warm_worker: the first FD task of each worker holds its warm-up
        first = {}
        for x in fd:
            first.setdefault(x.get("pid"), x)
        warm = [x["wall_time_s"] - (x.get("solve_s") or 0.0) - per_fd for x in first.values()]
        warm_cpu = []
        warm_src = "first FD task - solve"
    ideal = work / w
    rest = run["wall"] - (task_wall + sum(warm)) / w
    out = {"workers": w, "wall": run["wall"], "storms": len(storms), "fd": len(fd),
           "failed": len(bad), "simulate": sim, "simulate_per_storm": sim / max(1, len(storms)),
           "fd_solve": solve, "overhead": (run["wall"] - ideal) / ideal,
           "per_storm": per_storm, "per_storm_total": per_storm * len(storms) / w,
           "warmup": warm, "warmup_src": warm_src, "rest": rest,
           "cluster_start": run["cluster_start"], "load": run["load"]}
    if storms and all(x.get("cpu_s") is not None for x in storms + fd):
        sim_cpu = sum(x["simulate_cpu_s"] for x in storms)
        solve_cpu = sum(x.get("solve_cpu_s") or 0.0 for x in fd)
        own = sim_cpu + solve_cpu
        total = run["client_cpu"] + run["workers_cpu"]
        out.update(cpu_per_storm=sum(x["cpu_s"] - x["simulate_cpu_s"] for x in storms)
                   / len(storms), cpu_warmup=warm_cpu, cpu_client=run["client_cpu"],
                   cpu_workers=run["workers_cpu"], cpu_overhead=(total - own) / own,
                   cpu_own=own)
    return out


def report(label: str, r: dict) -> None:
    w = r["workers"]
    print(f"{label}: LocalCluster {w} worker(s) (start {r['cluster_start']:.1f} s), load "
          f"{r['load']}: {r['storms']} storms + {r['fd']} FD ({r['failed']} failed) in "
          f"{r['wall']:.1f} s; storms' own run time {r['simulate']:.1f} s "
          f"({r['simulate_per_storm']:.2f} s each), FD solve {r['fd_solve']:.2f} s")
    print(f"    overhead {100 * r['overhead']:.1f} % of the ideal "
          f"{(r['simulate'] + r['fd_solve']) / w:.1f} s = per storm {r['per_storm']:.3f} s "
          f"(x {r['storms']} / {w} = {r['per_storm_total']:.1f} s) + warm-up per worker "
          + "/".join(f"{x:.1f}" for x in r["warmup"]) + f" s ({r['warmup_src']}) + client, "
          f"scheduling and idle ends of phases {r['rest']:.1f} s")
    if "cpu_overhead" in r:
        print(f"    CPU: overhead {100 * r['cpu_overhead']:.1f} % of the storms' and FD's own "
              f"{r['cpu_own']:.1f} s; per storm outside simulate {r['cpu_per_storm']:.3f} s; "
              f"warm-up " + "/".join(f"{x:.1f}" for x in r["cpu_warmup"]) + " s per worker; "
              f"client + scheduler {r['cpu_client']:.1f} s; worker processes "
              f"{r['cpu_workers']:.1f} s in all")


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


def extrapolate(runs: list[dict], storm_s: float, n_fd: int, n_td: int, n_seeds: int,
                n_gov: int) -> dict:
    """Wall time of the example campaign on 1, 2, 64 and 512 cores from the 1-worker runs.

    T(c) = warm-up + client + n_fd (fd + o_fd) / c + ceil(n_td n_seeds / c) (storm + o)
    + ceil(n_gov n_seeds / c) (storm + o), with storm the 3-hour storm's own run time, o the
    per-storm overhead, fd and o_fd the FD case's solve time and the rest of its task, warm-up
    the worker warm-up (paid by every worker at once) and client the rest of the 1-worker run
    (client, scheduling: no idle ends of phases with one worker).  The ceil terms are the
    rounds of storms: their last round is the idle end of the phase.  Every core a worker of
    the speed of this machine's; the series reruns of statistics mode counted for ``n_gov``
    governing cases (at most one per line and limit state)."""
    import math
    import statistics as st
    one = [r for r in runs if r["workers"] == 1]
    o = st.mean(r["per_storm"] for r in one)
    warm = st.mean(x for r in one for x in r["warmup"])
    client = st.mean(r["rest"] for r in one)
    fd = st.mean(r["fd_solve"] / max(1, r["fd"]) for r in one)
    o_fd = st.mean((r["wall"] - r["rest"] - sum(r["warmup"]) - r["simulate"]
                    - r["per_storm"] * r["storms"] - r["fd_solve"]) / max(1, r["fd"])
                   for r in one)
    out = {"storm_s": storm_s, "per_storm_s": o, "warmup_s": warm, "client_s": client,
           "fd_s": fd, "fd_overhead_s": o_fd, "n_fd": n_fd, "n_td": n_td, "n_gov": n_gov,
           "hours": {}, "overhead": {}}
    for c in (1, 2, 64, 512):
        own = n_fd * fd / c + (math.ceil(n_td * n_seeds / c)
                               + math.ceil(n_gov * n_seeds / c)) * storm_s
        t = (warm + client + n_fd * (fd + o_fd) / c
             + (math.ceil(n_td * n_seeds / c) + math.ceil(n_gov * n_seeds / c)) * (storm_s + o))
        ideal = (n_fd * fd + (n_td + n_gov) * n_seeds * storm_s) / c
        out["hours"][c] = t / 3600.0
        out["overhead"][c] = (t - ideal) / ideal
        out.setdefault("rounds_idle", {})[c] = (own - ideal) / ideal
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--storms-duration", type=float, default=12000.0)
    ap.add_argument("--seeds", type=int, default=6)
    ap.add_argument("--repeats", type=int, default=1, help="pairs of 1- and 2-worker runs")
    ap.add_argument("--skip-dry-run", action="store_true")
    ap.add_argument("--storage", choices=("full", "statistics"), default="statistics",
                    help="storage mode of the bench campaign (the example campaign's is "
                         "statistics: the governing cases' series rerun at the end, counted "
                         "as storms)")
    ap.add_argument("--compare", type=Path, default=None,
                    help="another floatmoor checkout, run alternately with this one")
    ap.add_argument("--td-cases", type=int, default=168,
                    help="TD cases of the example campaign after its FD screening")
    ap.add_argument("--one-run", nargs=3, metavar=("TREE", "CAMPAIGN", "WORKERS"),
                    help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one_run:
        tree, campaign, workers = args.one_run
        sys.path.insert(0, tree)
        print(json.dumps(one_run(Path(tree), Path(campaign), int(workers)), default=str))
        return
    print(f"load average at start: {_load()}")
    dr = float("nan") if args.skip_dry_run else dry_run()
    print(f"dry run of the example campaign: {dr:.1f} s (load {_load()})")
    trees = [ROOT] if args.compare is None else [args.compare.resolve(), ROOT]
    names = {ROOT: "this tree"} | ({} if args.compare is None else {trees[0]: "compare"})
    summaries = {t: [] for t in trees}
    with tempfile.TemporaryDirectory() as tmp:
        paths = {}
        for i, t in enumerate(trees):
            paths[t] = Path(tmp) / f"bench{i}.yaml"
            paths[t].write_text(CAMPAIGN.format(
                base=(t / "scenes" / "floatel_100yr.yaml").as_posix(), seeds=args.seeds,
                duration=args.storms_duration, storage=args.storage))
        storm_wall, step = simulate_times(paths[ROOT])
        print(f"one storm of {args.storms_duration:g} s in this process: {storm_wall:.2f} s "
              f"(loop {step * 1e6:.0f} us per step; load {_load()})")
        for _ in range(args.repeats):
            for w in (1, 2):
                for t in trees:
                    r = summarise(campaign_run(t, paths[t], w))
                    summaries[t].append(r)
                    report(names[t], r)
    for t in trees:
        one = [r for r in summaries[t] if r["workers"] == 1]
        two = [r for r in summaries[t] if r["workers"] == 2]
        for a, b in zip(one, two):
            print(f"{names[t]}: speed-up 2 workers / 1: {a['wall'] / b['wall']:.2f} (with the "
                  f"cluster start: {(a['wall'] + a['cluster_start']) / (b['wall'] + b['cluster_start']):.2f}); "
                  f"storms' own run time per storm 2 / 1 worker: "
                  f"{b['simulate_per_storm'] / a['simulate_per_storm']:.2f}")
    # extrapolation of the example campaign
    from floatmoor.campaign.matrix import build_matrix
    from floatmoor.campaign.spec import load_campaign
    spec = load_campaign(ROOT / "campaigns" / "floatel_uls_als.yaml")
    n_fd, n_seeds = len(build_matrix(spec)), len(spec.seeds)
    own = summaries[ROOT]
    storm = st_mean([r["simulate_per_storm"] for r in own if r["workers"] == 1])
    storm = storm * 12000.0 / args.storms_duration
    n_gov = min(args.td_cases, 24)
    e = extrapolate(own, storm, n_fd, args.td_cases, n_seeds, n_gov)
    print(f"example campaign: {n_fd} FD cases at {e['fd_s']:.2f} s (+ {e['fd_overhead_s']:.2f} "
          f"s), {args.td_cases} TD cases x {n_seeds} seeds + the series of at most {n_gov} "
          f"governing cases; 3-hour storm {storm:.2f} s (+ {e['per_storm_s']:.3f} s per storm), "
          f"warm-up {e['warmup_s']:.1f} s, client {e['client_s']:.1f} s:")
    print("  " + ", ".join(f"{e['hours'][c]:.2f} h on {c} core(s) (overhead "
                           f"{100 * e['overhead'][c]:.1f} %, of which last rounds "
                           f"{100 * e['rounds_idle'][c]:.1f} %)" for c in (1, 2, 64, 512)))
    print(json.dumps({"dry_run_s": dr, "storm_wall_in_process_s": storm_wall,
                      "summaries": {names[t]: summaries[t] for t in trees},
                      "extrapolation": e}, default=str))


def st_mean(xs):
    return sum(xs) / len(xs)


if __name__ == "__main__":
    main()
