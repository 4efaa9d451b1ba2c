"""The dry run: the campaign matrix, a short calibration run, wall time and storage estimates.

Calibration (in this process, a few seconds): two frequency-domain cases (the second is timed;
the first loads the database and the compiled kernels) and two short storms of the first case at
the campaign's time step, of ``n1`` and ``n2`` steps, giving the storm cost ``a + b n`` (setup
``a``, ``b`` per step).  The stored size of a storm is measured by writing the second storm with
the campaign's storage options and scaling its series part to the full number of samples.
"""

from __future__ import annotations

import math
import tempfile
import time
import warnings
from dataclasses import dataclass
from pathlib import Path

from .matrix import build_matrix
from .spec import CampaignSpec

__all__ = ["Estimate", "estimate", "format_estimate"]


@dataclass
class Estimate:
    n_sea_states: int
    n_headings: int
    n_conditions: int
    n_cases: int
    n_seeds: int
    n_td_cases: int | None            # exact when the FD screening was run, else None
    td_cases_min: int
    td_cases_max: int
    fd_case_s: float
    storm_s: float
    storm_setup_s: float
    step_s: float
    n_steps: int
    storm_bytes: float
    stats_bytes: float
    fd_bytes: float
    workers: int
    calibration_s: float
    mode: str

    def storms(self, n_cases=None) -> int:
        return (self.n_td_cases if n_cases is None else n_cases) * self.n_seeds

    def wall_time(self, cores: int, n_td_cases: int | None = None) -> float:
        """FD of every case plus the storms, perfectly spread over ``cores`` (s)."""
        n = self.n_td_cases if n_td_cases is None else n_td_cases
        if n is None:
            n = self.td_cases_max
        fd = self.n_cases * self.fd_case_s / cores
        return fd + math.ceil(n * self.n_seeds / cores) * self.storm_s

    def storage(self, n_td_cases: int | None = None) -> float:
        n = self.n_td_cases if n_td_cases is None else n_td_cases
        n = self.td_cases_max if n is None else n
        fd = self.n_cases * self.fd_bytes
        if self.mode == "full":
            return fd + n * self.n_seeds * self.storm_bytes
        gov = min(n, 2 * 12)  # at most one governing case per line and limit state
        return fd + n * self.n_seeds * self.stats_bytes + gov * self.n_seeds * self.storm_bytes


def _analysis(spec, base, overrides):
    an = {"duration": base.analysis.duration, "dt": base.analysis.dt,
          "transient": base.analysis.transient, "ramp": base.analysis.ramp}
    an.update(dict(spec.analysis))
    an.update({k: v for k, v in (overrides or {}).items() if v is not None})
    return an


def estimate(spec: CampaignSpec, *, workers: int = 1, seeds=None, overrides=None,
             fd_budget: float = 5.0) -> Estimate:
    """Count the matrix and calibrate (see the module docstring).  When the FD of every case is
    estimated to take at most ``fd_budget`` seconds here, it is run and screened for the exact
    number of TD cases."""
    from . import _api
    from .matrix import case_scene
    from .screening import select_cases, utilisation
    from .tasks import one_thread, storm_dataset, write_netcdf

    t0 = time.perf_counter()
    cases = build_matrix(spec)
    seeds = tuple(seeds or spec.seeds)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        base = _api.load_scene(spec.base_scene)
        an = _analysis(spec, base, overrides)
        fd_times = []
        fds = []
        for c in cases[:2]:
            scene, failed = case_scene(base, c, an)
            t = time.perf_counter()
            fds.append(_api.frequency_domain(_api.build(scene, failed_lines=failed)))
            fd_times.append(time.perf_counter() - t)
        fd_case = fd_times[-1]
        scene, failed = case_scene(base, cases[0], an)
        dt = an["dt"]
        n_steps = round(an["duration"] / dt)
        n1, n2 = min(100, n_steps), min(300, n_steps)
        one = one_thread(scene)  # as the campaign's tasks run
        _api.simulate(_api.build(scene, failed_lines=failed), seed=seeds[0], solver=one,
                      duration=n1 * dt, dt=dt, transient=0.0)  # warm-up: compiled kernels, database
        t = time.perf_counter()
        _api.simulate(_api.build(scene, failed_lines=failed), seed=seeds[0], duration=n1 * dt,
                      dt=dt, transient=0.0, solver=one)
        t1 = time.perf_counter() - t
        t = time.perf_counter()
        ds = _api.simulate(_api.build(scene, failed_lines=failed), seed=seeds[0],
                           duration=n2 * dt, dt=dt, transient=0.0, solver=one)
        t2 = time.perf_counter() - t
    step = (t2 - t1) / max(n2 - n1, 1)
    if not step > 0.1 * t2 / n2:  # timing noise of a loaded machine: the safe upper bound
        step = t2 / n2
    setup = max(t2 - step * n2, 0.0)
    with tempfile.TemporaryDirectory() as tmp:
        full = write_netcdf(storm_dataset(ds, cases[0], seeds[0], spec.storage, 0.0, True),
                            Path(tmp) / "full.nc", compression=spec.storage.compression)
        stats = write_netcdf(storm_dataset(ds, cases[0], seeds[0], spec.storage, 0.0, False),
                             Path(tmp) / "stats.nc", compression=spec.storage.compression)
    storm_bytes = stats["bytes"] + (full["bytes"] - stats["bytes"]) * n_steps / n2
    n_td = None
    nl = int(fds[0]["mbs"].size)
    lo = hi = len(cases)
    if spec.screening.time_domain == "none":
        n_td, lo, hi = 0, 0, 0
    elif spec.screening.time_domain == "screened":
        states = {c.limit_state for c in cases}
        lo = min(len(cases), max(spec.screening.top_per_line, 1) * len(states))
        if len(cases) * fd_case <= fd_budget:
            import numpy as np
            u = np.full((len(cases), nl), np.nan)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                for i, c in enumerate(cases):
                    sc, fl = case_scene(base, c, an)
                    if c.condition.kind == "transient":
                        fl = list(c.condition.lines)
                    fd = _api.frequency_domain(_api.build(sc, failed_lines=fl))
                    u[i] = utilisation(fd["tension_static"].values,
                                       fd["tension_max_total"].values, fd["mbs"].values,
                                       c.limit_state, spec.design)
            keep, _ = select_cases(u, [c.limit_state for c in cases], spec.screening)
            n_td = int(keep.sum())
    else:
        n_td = len(cases)
    return Estimate(
        n_sea_states=len(spec.sea_states),
        n_headings=len(spec.wave_headings_deg) * len(spec.wind_offsets_deg)
        * len(spec.current_offsets_deg), n_conditions=len(spec.conditions),
        n_cases=len(cases), n_seeds=len(seeds), n_td_cases=n_td, td_cases_min=lo,
        td_cases_max=hi, fd_case_s=fd_case, storm_s=setup + step * n_steps,
        storm_setup_s=setup, step_s=step, n_steps=n_steps, storm_bytes=storm_bytes,
        stats_bytes=float(stats["bytes"]), fd_bytes=30e3, workers=workers,
        calibration_s=time.perf_counter() - t0, mode=spec.storage.mode)


def _hms(s: float) -> str:
    s = float(s)
    if s < 120:
        return f"{s:.0f} s"
    if s < 7200:
        return f"{s / 60:.1f} min"
    if s < 2 * 86400:
        return f"{s / 3600:.1f} h"
    return f"{s / 86400:.1f} days"


def _bytes(b: float) -> str:
    for unit in ("B", "kB", "MB", "GB", "TB"):
        if b < 1000:
            return f"{b:.1f} {unit}"
        b /= 1000
    return f"{b:.1f} PB"


def format_estimate(e: Estimate) -> str:
    td = (f"{e.n_td_cases}" if e.n_td_cases is not None else
          f"between {e.td_cases_min} and {e.td_cases_max} (the FD screening decides; it was "
          f"not run here: {e.n_cases} FD cases x {e.fd_case_s:.2f} s)")
    n_td = e.n_td_cases if e.n_td_cases is not None else e.td_cases_max
    lines = [
        (f"matrix: {e.n_sea_states} sea state(s) x {e.n_headings} heading(s) x "
         f"{e.n_conditions} condition(s) = {e.n_cases} case(s); {e.n_seeds} seed(s) per TD "
         "case"),
        f"FD cases: {e.n_cases}",
        f"TD cases after screening: {td}",
        f"storms: {e.storms(n_td)}" + ("" if e.n_td_cases is not None else " (at most)"),
        (f"calibration ({e.calibration_s:.1f} s): FD case {e.fd_case_s:.2f} s; storm "
         f"{e.storm_s:.1f} s ({e.storm_setup_s:.2f} s setup + {e.n_steps} steps x "
         f"{e.step_s * 1e6:.0f} us)"),
    ]
    cores = sorted({1, e.workers, 2, 64, 512})
    lines.append("estimated wall time: " + ", ".join(
        f"{_hms(e.wall_time(c, n_td))} on {c} core(s)" for c in cores)
        + ("" if e.n_td_cases is not None else f" (with all {n_td} cases in TD; with "
           f"{e.td_cases_min}: " + ", ".join(f"{_hms(e.wall_time(c, e.td_cases_min))} on {c}"
                                             for c in cores) + ")"))
    lines.append(f"storage ({e.mode} mode): {_bytes(e.storage(n_td))}"
                 + ("" if e.n_td_cases is not None else
                    f" at most, {_bytes(e.storage(e.td_cases_min))} at least")
                 + f" ({_bytes(e.storm_bytes)} per full storm, {_bytes(e.stats_bytes)} "
                 "statistics only)")
    return "\n".join(lines)
