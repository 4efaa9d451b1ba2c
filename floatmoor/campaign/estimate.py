"""The dry run: the campaign matrix, a short calibration run, wall time and storage estimates.

Calibration (in this process, 10-30 s), in CPU seconds of this process (the wall time of a
single-threaded task on an idle core: unlike the wall time it does not change with what else
the machine runs, so consecutive dry runs agree): the frequency domain of up to four cases
(the first loads the database and the compiled kernels; the median of the others is the FD
case cost), then, with the kernels warm (short storms first compile or load them, untimed),
storms of the first case as its campaign tasks run them, a short one (200 steps) and a long one
(about :data:`CAL_LOOP_S` s), :data:`CAL_RUNS` times: a storm of ``n`` steps costs ``a + b n``
(``b`` the time loop per step and the growth of the set-up with the duration, ``a`` the rest of
the set-up), plus the writing of its result; the median ``a`` and ``b`` give the estimate, the
spread of ``b`` its range (printed).  Measured on the Floatel example (2-core machine,
``benchmarks/bench_dry_run.py``, benchmarks/RESULTS.md): within 30 % of the storms the campaign
then runs.  The stored size of a storm is measured by writing a calibration storm with the
campaign's storage options and scaling its series part to the full number of samples.

The number of time-domain cases is exact when the frequency domain of every case is estimated
to take at most ``fd_budget`` seconds here (it is then run and screened); otherwise the dry run
gives the bounds and the time the exact count would need.
"""

from __future__ import annotations

import math
import statistics
import tempfile
import time
import warnings
from dataclasses import dataclass
from pathlib import Path

from .matrix import build_matrix
from .spec import CampaignSpec

__all__ = ["Estimate", "estimate", "format_estimate"]

CAL_RUNS = 3
"""Timed calibration runs of the time loop."""

CAL_LOOP_S = 1.0
"""CPU seconds of the long calibration storm (its steps chosen from a probe storm)."""


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
    step_min_s: float = math.nan       # spread of the calibration runs (time per step)
    step_max_s: float = math.nan
    write_s: float = 0.0               # statistics and writing of one storm's result

    def storms(self, n_cases=None) -> int:
        return (self.n_td_cases if n_cases is None else n_cases) * self.n_seeds

    def storm_range(self) -> tuple[float, float]:
        """The storm cost at the fastest and the slowest calibration run (s)."""
        rest = self.storm_setup_s + self.write_s
        return rest + self.step_min_s * self.n_steps, rest + self.step_max_s * self.n_steps

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


def _storm(_api, built, seed, solver, **kw):
    """A storm of the built case scene as a campaign task runs it (the vessel and mooring built
    once per worker, a fresh copy of the mooring per storm), timed in CPU seconds of this
    process (the wall time of a storm on an idle core; unlike the wall time it does not
    depend on what else the machine runs): (dataset, CPU s)."""
    import copy
    import dataclasses
    c = time.process_time()
    b = dataclasses.replace(built, mooring=copy.deepcopy(built.mooring))
    ds = _api.simulate(b, seed=seed, solver=solver, **kw)
    return ds, time.process_time() - c


def estimate(spec: CampaignSpec, *, workers: int = 1, seeds=None, overrides=None,
             fd_budget: float = 5.0) -> Estimate:
    """Count the matrix and calibrate (see the module docstring).  When the FD of every case is
    estimated to take at most ``fd_budget`` seconds here, it is run and screened for the exact
    number of TD cases."""
    from . import _api
    from .engine import campaign_analysis
    from .matrix import case_scene
    from .screening import select_cases, utilisation
    from .spec import check_times
    from .tasks import one_thread, storm_dataset, write_netcdf

    t0 = time.perf_counter()
    seeds = tuple(seeds or spec.seeds)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        base = _api.load_scene(spec.base_scene)
        full_an = check_times(spec, base, overrides)   # refuses e.g. --duration < transient
        an = campaign_analysis(spec, overrides)
        cases = build_matrix(spec)
        fd_times = []
        fds = []
        for c in cases[:4]:
            scene, failed = case_scene(base, c, an)
            if c.condition.kind == "transient":
                failed = list(c.condition.lines)
            t = time.process_time()
            fds.append(_api.frequency_domain(_api.build(scene, failed_lines=failed)))
            fd_times.append(time.process_time() - t)
        fd_case = statistics.median(fd_times[1:]) if len(fd_times) > 1 else fd_times[0]
        scene, failed = case_scene(base, cases[0], an)
        dt = full_an["dt"]
        n_steps = round(full_an["duration"] / dt)
        one = one_thread(scene)  # as the campaign's tasks run
        built = _api.build(scene, failed_lines=failed)
        # warm-up: the compiled kernels (compiled or loaded from numba's cache), the database
        n0 = min(200, n_steps)
        for _ in range(2):
            _, c0 = _storm(_api, built, seeds[0], one, duration=n0 * dt, dt=dt, transient=0.0)
        _, c_probe = _storm(_api, built, seeds[0], one, duration=min(n_steps, 10 * n0) * dt,
                            dt=dt, transient=0.0)
        per = max((c_probe - c0) / max(min(n_steps, 10 * n0) - n0, 1), 1e-7)
        n_cal = min(n_steps, max(2 * n0, round(CAL_LOOP_S / per)))
        # a storm costs a + b n CPU seconds for n steps: b the time loop per step and the
        # growth of the set-up with the duration (wave and wind realisations, force series),
        # a the rest of the set-up; from a short and a long storm, CAL_RUNS times
        steps, setups = [], []
        for _ in range(CAL_RUNS):
            _, c_short = _storm(_api, built, seeds[0], one, duration=n0 * dt, dt=dt,
                                transient=0.0)
            ds, c_long = _storm(_api, built, seeds[0], one, duration=n_cal * dt, dt=dt,
                                transient=0.0)
            b = max(c_long - c_short, 0.0) / max(n_cal - n0, 1)
            steps.append(b)
            setups.append(max(c_short - b * n0, 0.0))
        setup = statistics.median(setups)
    with tempfile.TemporaryDirectory() as tmp:
        keep = spec.storage.mode == "full"
        times = []
        for i in range(2):  # the first write loads the netCDF machinery: the second is timed
            t = time.process_time()
            out = write_netcdf(storm_dataset(ds, cases[0], seeds[0], spec.storage, 0.0, keep),
                               Path(tmp) / f"storm{i}.nc", compression=spec.storage.compression)
            times.append(time.process_time() - t)
        full = write_netcdf(storm_dataset(ds, cases[0], seeds[0], spec.storage, 0.0, True),
                            Path(tmp) / "full.nc", compression=spec.storage.compression)
        stats = write_netcdf(storm_dataset(ds, cases[0], seeds[0], spec.storage, 0.0, False),
                             Path(tmp) / "stats.nc", compression=spec.storage.compression)
    del out
    write_s = times[-1] * (n_steps / n_cal if keep else 1.0)
    step = statistics.median(steps)
    storm_bytes = stats["bytes"] + (full["bytes"] - stats["bytes"]) * n_steps / n_cal
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
            keep_cases, _ = select_cases(u, [c.limit_state for c in cases], spec.screening)
            n_td = int(keep_cases.sum())
    else:
        n_td = len(cases)
    return Estimate(
        n_sea_states=len(spec.sea_states),
        n_headings=len(spec.wave_headings_deg) * len(spec.wind_offsets_deg)
        * len(spec.current_offsets_deg), n_conditions=len(spec.conditions),
        n_cases=len(cases), n_seeds=len(seeds), n_td_cases=n_td, td_cases_min=lo,
        td_cases_max=hi, fd_case_s=fd_case, storm_s=setup + step * n_steps + write_s,
        storm_setup_s=setup, step_s=step, n_steps=n_steps, storm_bytes=storm_bytes,
        stats_bytes=float(stats["bytes"]), fd_bytes=30e3, workers=workers,
        calibration_s=time.perf_counter() - t0, mode=spec.storage.mode,
        step_min_s=min(steps), step_max_s=max(steps), write_s=write_s)


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
        (f"calibration ({e.calibration_s:.1f} s, kernels warm; CPU time, the wall time on "
         f"idle cores): FD case {e.fd_case_s:.2f} s; storm {e.storm_s:.1f} s "
         f"({e.storm_setup_s:.2f} s setup + {e.n_steps} steps x {e.step_s * 1e6:.0f} us + "
         f"{e.write_s:.2f} s writing; {e.storm_range()[0]:.1f}-{e.storm_range()[1]:.1f} s "
         f"over the {CAL_RUNS} calibration runs)"),
    ]
    if e.n_td_cases is None:
        lines.append(f"the exact TD count needs the FD of all {e.n_cases} cases: about "
                     f"{_hms(e.n_cases * e.fd_case_s)} here (--fd-budget "
                     f"{math.ceil(e.n_cases * e.fd_case_s * 1.2)} runs it)")
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
