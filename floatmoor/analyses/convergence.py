"""Time-step convergence of a scene: error against run time for halving time steps.

:func:`convergence_study` runs the same seed at dt = dt0, dt0/2, ... and gives, for the maximum
horizontal offset and the maximum line tension after the transient, the relative error against
the finest run beside the wall time of the time loop; with ``solver`` options
(:mod:`floatmoor.io.solver_section`) every dt runs with them too, and their rows give their
difference from the run with the default options at the same dt (the error of the
approximation itself).
``floatmoor convergence`` prints :func:`format_table` and plots the rows.
"""

from __future__ import annotations

__all__ = ["convergence_study", "format_table"]


def convergence_study(scene, *, seed=None, duration=None, dt0=0.4, levels=5, echo=None,
                      solver=None):
    """Run the halving sequence; returns a list of dicts (dt, solver, max_offset,
    max_tension, wall_time, error_offset, error_tension; errors relative to the finest run
    with the default options, named ``default``).  With ``solver`` (a :class:`~floatmoor.io.solver_section.SolverSpec`) every dt is
    also run with those options; their rows carry ``difference``, the larger relative
    difference of the max offset and max tension from the default run at the same dt."""
    import warnings

    import numpy as np

    from ..analyses.simulate import simulate
    from ..io.solver_section import SolverSpec

    default = SolverSpec()
    specs = [default] if solver is None or solver.is_default else [default, solver]
    rows = []
    for k in range(levels):
        dt = dt0 / 2 ** k
        for spec in specs:
            name = "default" if spec is default else spec.describe()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                try:
                    ds = simulate(scene, seed=seed, duration=duration, dt=dt, solver=spec)
                except Exception as exc:  # too large a dt may be refused: report it, go on
                    rows.append({"dt": dt, "solver": name,
                                 "error": f"{type(exc).__name__}: {exc}"})
                    if echo:
                        echo(f"dt {dt:g} s ({name}): {type(exc).__name__}: {exc}")
                    continue
            sel = ds["time"].values >= ds.attrs["transient"]
            m = ds["motion"].values[sel]
            row = {"dt": dt, "solver": name,
                   "max_offset": float(np.hypot(m[:, 0], m[:, 1]).max()),
                   "max_tension": float(ds["line_tension"].values[sel].max())
                   if "line_tension" in ds else float("nan"),
                   "wall_time": float(ds.attrs["run_time_s"])}
            rows.append(row)
            if echo:
                echo(f"dt {dt:g} s ({name}) done in {row['wall_time']:.2f} s")
    ok = [r for r in rows if "error" not in r and r["solver"] == "default"]
    if ok:
        ref = ok[-1]
        same = {r["dt"]: r for r in ok}
        for r in rows:
            if "error" in r:
                continue
            r["error_offset"] = abs(r["max_offset"] / ref["max_offset"] - 1.0)
            r["error_tension"] = abs(r["max_tension"] / ref["max_tension"] - 1.0)
            e = same.get(r["dt"])
            if r["solver"] != "default" and e is not None:
                r["difference"] = max(abs(r["max_offset"] / e["max_offset"] - 1.0),
                                      abs(r["max_tension"] / e["max_tension"] - 1.0))
    return rows


def format_table(rows) -> str:
    options = any(r.get("solver", "default") != "default" for r in rows)
    out = [f"{'dt (s)':>8s}{'max offset (m)':>16s}{'error':>10s}{'max tension (kN)':>18s}"
           f"{'error':>10s}{'wall (s)':>10s}" + ("  solver (difference from default)"
                                                   if options else "")]
    for r in rows:
        if "error" in r:
            out.append(f"{r['dt']:8.4f}  {r['error']}")
            continue
        line = (f"{r['dt']:8.4f}{r['max_offset']:16.3f}{100 * r['error_offset']:9.3f}%"
                f"{r['max_tension'] / 1e3:18.1f}{100 * r['error_tension']:9.3f}%"
                f"{r['wall_time']:10.2f}")
        if options:
            line += f"  {r.get('solver', 'default')}"
            if "difference" in r:
                line += f" ({100 * r['difference']:.2g} %)"
        out.append(line)
    out.append("errors relative to the finest time step" + (" of the default options" if options
                                                            else ""))
    return "\n".join(out)
