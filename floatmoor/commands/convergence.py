"""``floatmoor convergence SCENE.yaml``: error against run time for halving time steps.

Runs the analysis :func:`floatmoor.analyses.convergence.convergence_study`: the same seed at
dt = 0.4, 0.2, 0.1, ... s (``--levels``), and prints, for the maximum
horizontal offset and the maximum line tension (after the transient), the relative error
against the finest run next to the wall time of the time loop; ``--plot FILE`` draws both
(matplotlib, optional).  ``--solver catenary=predictor,memory=state_space`` also runs every
time step with those ``solver:`` options (:mod:`floatmoor.io.solver_section`): their rows give
the error against the same finest run with the default options, their difference from the
default run at the same time step (the error of the approximation itself) and their wall time.
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
                        "catenary=predictor,memory=state_space, fe_stages=catenary or "
                        "fe_stiffness_interval=0")


def parse_solver_option(text: str):
    """``catenary=predictor,memory=state_space`` -> SolverSpec (UsageError when malformed)."""
    from ..cli import UsageError
    from ..io.solver_section import (
        CATENARY_MODES,
        FE_STAGE_MODES,
        FE_STIFFNESS_INTERVAL_MAX,
        MEMORY_MODES,
        SolverSpec,
    )
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
        if key == "fe_stiffness_interval":
            try:
                kw[key] = float(value)
            except ValueError:
                raise UsageError(f"--solver: fe_stiffness_interval is a number (s), found "
                                 f"{value!r}") from None
            if not 0.0 <= kw[key] <= FE_STIFFNESS_INTERVAL_MAX:
                raise UsageError(f"--solver: fe_stiffness_interval from 0 to "
                                 f"{FE_STIFFNESS_INTERVAL_MAX:g} s, found {value}")
            continue
        if key not in choices or value not in choices[key]:
            raise UsageError("--solver: expected KEY=VALUE with " + "; ".join(
                f"{k} one of {', '.join(v)}" for k, v in choices.items())
                + "; memory_fit_tol a number; fe_stiffness_interval a number (s), found "
                + repr(item))
        kw[key] = value
    return SolverSpec(**kw)


def plot(rows, path) -> None:
    from matplotlib.figure import Figure

    fast = [r for r in rows if "error" not in r and r.get("solver", "default") != "default"]
    ok = [r for r in rows if "error" not in r and r.get("solver", "default") == "default"][:-1]
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
    from ..analyses.convergence import convergence_study, format_table
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
