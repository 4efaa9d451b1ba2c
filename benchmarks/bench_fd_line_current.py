"""The frequency domain's ``line_current_drag`` (static current drag on the lines in the mean
position): its cost, and its numbers on the Floatel-like 100-year case against the coupled FE
storms (notebooks/data/fd_line_dynamics/coupled_storms.csv, benchmarks/fd_vs_coupled_storms.py).

Cost: ``frequency_domain_result`` on a built scene (a fresh copy of the mooring per call, as a
campaign's FD task gets it), with and without the option, interleaved, after one warm-up of
each (numba kernels compiled); CPU time (``time.process_time``), best of ``--repeats``.

``--relaxation S``: also the coupled FE time domain under the current alone (no waves, no wind),
started at the FD mean without line drag, S seconds; its rest position and fairlead tensions
(mean of the last 10 %) against the FD mean with the option.

``first_solve``: the first FE statics of the 12 lines in current from the still-water shape at
the default FD mean, without (``max_step`` 0) and with the trust radius of
:data:`~floatmoor.mooring.fe.current_statics.MAX_STEP`, interleaved: Newton iterations per line,
CPU (best of ``--repeats``) and the largest difference of the increments (N).

Storms: the mean, the LF surge std and the LF and WF (dynamic) tension std per line.

Run:  PYTHONPATH=. python benchmarks/bench_fd_line_current.py [--repeats 5] [--relaxation 2400]
"""

from __future__ import annotations

import argparse
import copy
import dataclasses
import os
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENES = {"flagship (132-element FE statics)": ROOT / "scenes" / "floatel_100yr.yaml",
          "FE flagship (50 elements)": ROOT / "scenes" / "floatel_100yr_fe.yaml"}
STORMS = ROOT / "notebooks" / "data" / "fd_line_dynamics" / "coupled_storms.csv"


def _load() -> str:
    return " / ".join(f"{v:.1f}" for v in os.getloadavg())


def _fd(built, **kw):
    from floatmoor.analyses.frequency_domain import frequency_domain_result
    b = dataclasses.replace(built, mooring=copy.deepcopy(built.mooring))
    c0, w0 = time.process_time(), time.perf_counter()
    r = frequency_domain_result(b, **kw)
    return r, time.process_time() - c0, time.perf_counter() - w0


def cost(repeats: int) -> None:
    from floatmoor.io.build import build
    print(f"load before: {_load()}")
    for label, path in SCENES.items():
        built = build(path)
        for tm in ("quasi_static", "dynamic"):
            cpu = {False: [], True: []}
            wall = {False: [], True: []}
            for opt in (False, True):                    # warm-up
                _fd(built, tension_model=tm, line_current_drag=opt)
            for _ in range(repeats):
                for opt in (False, True):
                    _, c, w = _fd(built, tension_model=tm, line_current_drag=opt)
                    cpu[opt].append(c)
                    wall[opt].append(w)
            print(f"{label}, {tm}: CPU best without {min(cpu[False]):.3f} s, with "
                  f"{min(cpu[True]):.3f} s (+{min(cpu[True]) - min(cpu[False]):.3f} s); wall "
                  f"median {np.median(wall[False]):.2f} / {np.median(wall[True]):.2f} s",
                  flush=True)
    print(f"load after: {_load()}")


def first_solve(repeats: int) -> None:
    from floatmoor.io.build import build
    from floatmoor.mooring.fe.current_statics import MAX_STEP, LineCurrentStatics
    for label, path in SCENES.items():
        built = build(path)
        r, _, _ = _fd(built)
        cpu = {0.0: [], MAX_STEP: []}
        out = {}
        for k in range(repeats + 1):                   # the first round: warm-up
            for m in (0.0, MAX_STEP):
                drag = LineCurrentStatics.from_scene(built.scene, copy.deepcopy(built.mooring),
                                                     pose=r.mean, max_step=m)
                c0 = time.process_time()
                out[m] = drag(r.mean)
                if k:
                    cpu[m].append(time.process_time() - c0)
        d = np.abs(out[0.0].line_force - out[MAX_STEP].line_force).max()
        print(f"{label}: first solve of the lines in current, iterations without "
              f"{out[0.0].iterations.tolist()}, with max_step {MAX_STEP:g} m "
              f"{out[MAX_STEP].iterations.tolist()}; CPU best {min(cpu[0.0]):.4f} / "
              f"{min(cpu[MAX_STEP]):.4f} s; largest line force difference {d:.3g} N",
              flush=True)


def against_storms() -> None:
    import pandas as pd

    from floatmoor.io.build import build
    df = pd.read_csv(STORMS)
    fe = df[df["model"] == "fe"]
    built = build(SCENES["FE flagship (50 elements)"])
    r0, _, _ = _fd(built, tension_model="dynamic")
    r1, _, _ = _fd(built, tension_model="dynamic", line_current_drag=True)
    print(f"mean surge: FD {r0.mean[0]:.2f} m, FD with line drag {r1.mean[0]:.2f} m, coupled "
          f"FE storms {fe['surge_mean'].mean():.2f} m; heave {r0.mean[2]:.3f} / "
          f"{r1.mean[2]:.3f} / {fe['heave_mean'].mean():.3f} m")
    lf = float(np.sqrt((fe["surge_lf_std"] ** 2).mean()))
    print(f"LF surge std: FD {r0.lf_std[0]:.3f} m, with line drag {r1.lf_std[0]:.3f} m, storms "
          f"{lf:.3f} m; surge stiffness {r0.model.stiffness[0, 0] / 1e3:.1f} / "
          f"{r1.model.stiffness[0, 0] / 1e3:.1f} kN/m, yaw {r0.model.stiffness[5, 5] / 1e6:.1f} "
          f"/ {r1.model.stiffness[5, 5] / 1e6:.1f} MN m/rad")
    print("line  LF T std: FD  with  storms")
    for i in range(6):
        n = i + 1
        st = float(np.sqrt((fe[f"line{n}_lf_std"] ** 2).mean()))
        print(f"{n:4d} {r0.tension_std_lf[i] / 1e3:14.1f} {r1.tension_std_lf[i] / 1e3:5.1f} "
              f"{st:7.1f}")
    f = r1.mean_force_line_current
    print(f"line drag at the mean: {f[0] / 1e3:.1f} kN surge, {f[2] / 1e3:.1f} kN heave, "
          f"{f[4] / 1e3:.0f} kN m pitch")
    print("line  T mean: FD  with  storms | WF std dyn.: FD  with  storms  FD/st-1  with/st-1")
    for i in range(6):
        n = i + 1
        st = float(np.sqrt((fe[f"line{n}_wf_std"] ** 2).mean()))
        tm = float(fe[f"line{n}_mean"].mean())
        a, b = r0.tension_std_wf[i] / 1e3, r1.tension_std_wf[i] / 1e3
        print(f"{n:4d} {r0.tension_static[i] / 1e3:10.1f} {r1.tension_static[i] / 1e3:6.1f} "
              f"{tm:7.1f} | {a:18.1f} {b:5.1f} {st:7.1f} {100 * (a / st - 1):+7.1f} % "
              f"{100 * (b / st - 1):+7.1f} %")


def relaxation(duration: float) -> None:
    import floatmoor
    from floatmoor.io.build import build
    sc = floatmoor.load_scene(SCENES["FE flagship (50 elements)"])
    sc = dataclasses.replace(sc, environment=dataclasses.replace(sc.environment, waves=None,
                                                                 wind=None))
    built = build(sc)
    r0, _, _ = _fd(built)
    r1, _, _ = _fd(built, line_current_drag=True)
    c0 = time.process_time()
    ds = floatmoor.simulate(build(sc), seed=1, duration=duration, ramp=0.0, transient=0.0,
                            start_pose=r0.mean)
    cpu = time.process_time() - c0
    t = ds.time.values
    last = t >= 0.9 * duration
    m = ds["motion"].values[last]
    T = ds["line_tension"].values[last].mean(axis=0)
    print(f"current only, coupled FE run {duration:g} s (CPU {cpu:.0f} s, load {_load()}): "
          f"start {r0.mean[0]:.4f} m, rest {m[:, 0].mean():.4f} m (std {m[:, 0].std():.1e}), "
          f"FD with line drag {r1.mean[0]:.4f} m; pitch {np.degrees(m[:, 4].mean()):.4f} / "
          f"{np.degrees(r1.mean[4]):.4f} deg")
    for i in range(6):
        print(f"  line {i + 1}: TD {T[i] / 1e3:8.2f} kN, FD {r1.tension_static[i] / 1e3:8.2f} kN "
              f"({100 * (r1.tension_static[i] / T[i] - 1):+.2f} %), FD without "
              f"{r0.tension_static[i] / 1e3:8.2f} kN")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--relaxation", type=float, default=0.0, metavar="S")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    first_solve(args.repeats)
    cost(args.repeats)
    against_storms()
    if args.relaxation > 0:
        relaxation(args.relaxation)


if __name__ == "__main__":
    main()
