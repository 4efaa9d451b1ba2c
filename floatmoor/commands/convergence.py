"""``floatmoor convergence SCENE.yaml``: error against run time for halving time steps.

Runs the same seed at dt = 0.4, 0.2, 0.1, ... s (``--levels``) and prints, for the maximum
horizontal offset and the maximum line tension (after the transient), the relative error
against the finest run next to the wall time of the time loop; ``--plot FILE`` draws both
(matplotlib, optional).  ``--solver catenary=predictor,memory=state_space`` also runs every
time step with those ``solver:`` options (:mod:`floatmoor.io.solver_section`): their rows give
the error against the same finest exact run, their difference from the exact run at the same
time step (the error of the approximation itself) and their wall time.
"""

from __future__ import annotations

import argparse

HELP = "time-step convergence: max offset and max tension error against wall time"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file")
    p.add_argument("--seed", type=int, default=None, help="seed (default: the scene's first)")
    p.add_argument("--duration", type=float, default=None, metavar="S",
                   help="simulated length in s (default: analysis.duration)")
    p.add_argument("--dt0", type=float, default=0.4, metavar="S",
                   help="largest time step, s (default 0.4)")
    p.add_argument("--levels", type=int, default=5, metavar="N",
                   help="number of time steps dt0, dt0/2, ... (default 5)")
    p.add_argument("--plot", default=None, metavar="FILE", help="save a plot (png/pdf/svg)")
    p.add_argument("--solver", default=None, metavar="KEY=VALUE[,KEY=VALUE]",
                   help="also run with these solver options, e.g. "
                        "catenary=predictor,memory=state_space or fe_stages=linear")


def parse_solver_option(text: str):
    """``catenary=predictor,memory=state_space`` -> SolverSpec (UsageError when malformed)."""
    from ..cli import UsageError
    from ..io.solver_section import CATENARY_MODES, FE_STAGE_MODES, MEMORY_MODES, SolverSpec
    choices = {"catenary": CATENARY_MODES, "memory": MEMORY_MODES, "fe_stages": FE_STAGE_MODES}
    kw = {}
    for item in text.split(","):
        key, _, value = item.partition("=")
        key, value = key.strip(), value.strip()
        if key == "memory_fit_tol":
            try:
                kw[key] = float(value)
            except ValueError:
                raise UsageError(f"--solver: memory_fit_tol is a number, found {value!r}") \
                    from None
            if not 0.0 < kw[key] < 1.0:
                raise UsageError(f"--solver: memory_fit_tol between 0 and 1, found {value}")
            continue
        if key not in choices or value not in choices[key]:
            raise UsageError("--solver: expected KEY=VALUE with " + "; ".join(
                f"{k} one of {', '.join(v)}" for k, v in choices.items())
                + f"; memory_fit_tol a number, found {item!r}")
        kw[key] = value
    return SolverSpec(**kw)


def convergence_study(scene, *, seed=None, duration=None, dt0=0.4, levels=5, echo=None,
                      solver=None):
    """Run the halving sequence; returns a list of dicts (dt, solver, max_offset,
    max_tension, wall_time, error_offset, error_tension; errors relative to the finest exact
    run).  With ``solver`` (a :class:`~floatmoor.io.solver_section.SolverSpec`) every dt is
    also run with those options; their rows carry ``difference``, the larger relative
    difference of the max offset and max tension from the exact run at the same dt."""
    import warnings

    import numpy as np

    from ..analyses.simulate import simulate
    from ..io.solver_section import SolverSpec

    exact = SolverSpec()
    specs = [exact] if solver is None or solver.exact else [exact, solver]
    rows = []
    for k in range(levels):
        dt = dt0 / 2 ** k
        for spec in specs:
            name = "exact" if spec is exact else spec.describe()
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
    ok = [r for r in rows if "error" not in r and r["solver"] == "exact"]
    if ok:
        ref = ok[-1]
        same = {r["dt"]: r for r in ok}
        for r in rows:
            if "error" in r:
                continue
            r["error_offset"] = abs(r["max_offset"] / ref["max_offset"] - 1.0)
            r["error_tension"] = abs(r["max_tension"] / ref["max_tension"] - 1.0)
            e = same.get(r["dt"])
            if r["solver"] != "exact" and e is not None:
                r["difference"] = max(abs(r["max_offset"] / e["max_offset"] - 1.0),
                                      abs(r["max_tension"] / e["max_tension"] - 1.0))
    return rows


def format_table(rows) -> str:
    options = any(r.get("solver", "exact") != "exact" for r in rows)
    out = [f"{'dt (s)':>8s}{'max offset (m)':>16s}{'error':>10s}{'max tension (kN)':>18s}"
           f"{'error':>10s}{'wall (s)':>10s}" + ("  solver (difference from exact)"
                                                   if options else "")]
    for r in rows:
        if "error" in r:
            out.append(f"{r['dt']:8.4f}  {r['error']}")
            continue
        line = (f"{r['dt']:8.4f}{r['max_offset']:16.3f}{100 * r['error_offset']:9.3f}%"
                f"{r['max_tension'] / 1e3:18.1f}{100 * r['error_tension']:9.3f}%"
                f"{r['wall_time']:10.2f}")
        if options:
            line += f"  {r.get('solver', 'exact')}"
            if "difference" in r:
                line += f" ({100 * r['difference']:.2g} %)"
        out.append(line)
    out.append("errors relative to the finest time step" + (" of the exact path" if options
                                                            else ""))
    return "\n".join(out)


def plot(rows, path) -> None:
    from matplotlib.figure import Figure

    fast = [r for r in rows if "error" not in r and r.get("solver", "exact") != "exact"]
    ok = [r for r in rows if "error" not in r and r.get("solver", "exact") == "exact"][:-1]
    fig = Figure(figsize=(6, 4))
    ax = fig.add_subplot()
    if fast:
        ax.loglog([r["wall_time"] for r in fast],
                  [max(r["error_tension"], 1e-16) for r in fast], "^--",
                  label=f"max tension, {fast[0]['solver']}")
    ax.loglog([r["wall_time"] for r in ok], [max(r["error_offset"], 1e-16) for r in ok], "o-",
              label="max offset")
    ax.loglog([r["wall_time"] for r in ok], [max(r["error_tension"], 1e-16) for r in ok], "s-",
              label="max tension")
    for r in ok:
        ax.annotate(f"dt {r['dt']:g}", (r["wall_time"], max(r["error_offset"], 1e-16)),
                    fontsize=7)
    ax.set_xlabel("wall time of the time loop (s)")
    ax.set_ylabel("relative error against the finest dt")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)


def run(args: argparse.Namespace) -> int:
    from ..cli import EXIT_OK, UsageError
    from ..io.scene import load_scene

    if args.levels < 2:
        raise UsageError("--levels must be >= 2")
    if not args.dt0 > 0:
        raise UsageError("--dt0 must be > 0")
    solver = parse_solver_option(args.solver) if args.solver else None
    scene = load_scene(args.scene)
    rows = convergence_study(scene, seed=args.seed, duration=args.duration, dt0=args.dt0,
                             levels=args.levels, echo=lambda s: print(s, flush=True),
                             solver=solver)
    print(format_table(rows))
    if args.plot:
        try:
            plot(rows, args.plot)
            print(f"plot written to {args.plot}")
        except ImportError:
            print("matplotlib is not installed: no plot")
    return EXIT_OK
