"""The ``floatmoor`` command.

``floatmoor check SCENE.yaml``        validate a scene and print what it would build
``floatmoor environment SCENE.yaml``  realise the scene's environment and print its statistics
``floatmoor statics SCENE.yaml``      equilibrium, tensions, stiffness (:mod:`floatmoor.commands.statics`)
``floatmoor run SCENE.yaml``          time-domain storms (:mod:`floatmoor.commands.run`)
``floatmoor fd SCENE.yaml``           frequency-domain analysis (:mod:`floatmoor.commands.fd`)
``floatmoor convergence SCENE.yaml``  time-step convergence (:mod:`floatmoor.commands.convergence`)
``floatmoor lines SCENE.yaml``        FE lines driven by recorded or harmonic motion (:mod:`floatmoor.commands.lines`)
``floatmoor report RESULTS_DIR``      Gumbel statistics and DNV-OS-E301 checks (:mod:`floatmoor.commands.report`)
``floatmoor import FORMAT FILE``     MoorDyn, MAP++ or OpenFAST model -> floatmoor files (:mod:`floatmoor.commands.import_`)
``floatmoor export moordyn FILE``    mooring -> MoorDyn v2 input file (:mod:`floatmoor.commands.export`)
``floatmoor compile SCENE.yaml ...``  the scenes' storm kernels compiled ahead (:mod:`floatmoor.commands.compile`)

Exit status: 0 success (``report``: 1 when a line fails its design check), 2 a mistake in an input file (:class:`~floatmoor.SceneError`, printed
as ``floatmoor: error: <message>`` without a traceback) or on the command line, 3 a numerical
failure (:class:`~floatmoor.NumericalError`), 130 interrupted (Ctrl-C).

Adding a subcommand
-------------------
Write a module ``floatmoor/commands/<name>.py`` with ``HELP``, ``add_arguments(parser)`` and
``run(args) -> int`` (import heavy modules inside ``run`` so that ``floatmoor --help`` and
``floatmoor check`` stay fast), and add one entry ``("<name>", "floatmoor.commands.<name>")`` to
:data:`COMMANDS` (or a :class:`Command` built from any two functions).
"""

from __future__ import annotations

import argparse
import importlib
import sys
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from . import __version__
from .commands.argtypes import positive_float, seed_int  # noqa: F401 (re-exported)
from .core.errors import FloatmoorWarning, NumericalError, SceneError

__all__ = ["main", "Command", "COMMANDS", "commands", "module_command", "build_parser",
           "UsageError"]

EXIT_OK = 0
EXIT_SCENE_ERROR = 2
EXIT_NUMERICAL_ERROR = 3
EXIT_INTERRUPTED = 130


class UsageError(Exception):
    """A command-line mistake found after parsing (printed like a SceneError, exit status 2)."""


@dataclass(frozen=True)
class Command:
    """A subcommand: its name, one-line help, and the functions adding its arguments and
    running it (returning the exit status)."""

    name: str
    help: str
    add_arguments: Callable[[argparse.ArgumentParser], None]
    run: Callable[[argparse.Namespace], int]
    description: str | None = None


def module_command(name: str, module: str) -> Command:
    """A :class:`Command` defined by a module with ``HELP``, ``add_arguments(parser)`` and
    ``run(args) -> int`` (the convention of :mod:`floatmoor.commands`).  The module is imported
    when the parser is built, so it must keep heavy imports inside ``run``."""
    mod = importlib.import_module(module)
    doc = (mod.__doc__ or "").strip()
    return Command(name, mod.HELP, mod.add_arguments, mod.run, description=doc or None)


# -- argument types -------------------------------------------------------------------------------


# -- check ----------------------------------------------------------------------------------------
def _check_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file")
    p.add_argument("--quick", action="store_true",
                   help="validate the scene and its environment only; do not read the vessel "
                        "file, its hydrodynamic database and the mooring, and print no "
                        "hydrodynamic consistency report")
    p.add_argument("--no-symmetry", action="store_true",
                   help="skip the symmetry check (a short run comparing the tensions of lines "
                        "that are mirror images about the environment's heading)")


def _check_run(args: argparse.Namespace) -> int:
    from .io.scene import load_scene

    scene = load_scene(args.scene)
    print(scene.describe())
    if not args.quick:
        for line in _read_references(scene):
            print(line)
        if scene.vessel is not None:
            from .io.build import build
            from .io.plausibility import check_built
            built = build(scene)
            check_built(built)
            print("plausibility: depth, mass and displacement, stability, model inputs: OK")
            unknown = built.mooring.unknown_mbs() if built.mooring is not None else ""
            if unknown:
                print(f"design checks (report, DNV-OS-E301, campaign, fatigue) refused until "
                      f"the MBS is set: {unknown}")
            if not args.no_symmetry:
                _symmetry_report(built)
    print(f"{args.scene}: OK")
    return EXIT_OK


def _symmetry_report(built) -> None:
    """Mirror-image lines of a symmetric scene against a short run
    (:func:`floatmoor.analyses.symmetry.symmetry_check`): a line printed, a FloatmoorWarning
    when they are not mirror images in the results."""
    from .analyses.symmetry import SYMMETRY_RTOL, mirror_pairs, symmetry_plane

    if built.mooring is None:
        return
    h = symmetry_plane(built.scene.environment)
    if h is None or not mirror_pairs(built.mooring, h):
        print("symmetry: no mirror-image lines about the environment's heading (not checked)")
        return
    from .analyses.symmetry import symmetry_check
    print("symmetry: mirror-image lines found; comparing their tensions over a short run "
          "(compiling the time loop once if needed) ...", flush=True)
    res = symmetry_check(built)
    pairs = ", ".join(f"{a}/{b}" for a, b in res["pairs"])
    worst = max(res["differences"])
    if res["ok"]:
        print(f"symmetry: {pairs} mirror images about the {res['plane_deg']:g} deg plane; "
              f"tensions equal within {worst:.1e} of the largest over {res['duration']:g} s: OK")
        return
    bad = ", ".join(f"{a}/{b} {d:.2e}" for (a, b), d in zip(res["pairs"], res["differences"])
                    if d > SYMMETRY_RTOL)
    warnings.warn(f"symmetry: lines that are mirror images about the {res['plane_deg']:g} deg "
                  f"plane of the environment differ in a {res['duration']:g} s run by more than "
                  f"{SYMMETRY_RTOL:g} of the largest tension ({bad}): the vessel database, mass "
                  "or damping, a coordinate, or the solution breaks the symmetry",
                  FloatmoorWarning, stacklevel=2)
    print(f"symmetry: NOT mirror images in the results ({bad}; see the warning)")


def _read_references(scene) -> list[str]:
    """Read the files the scene refers to with their own readers (a mistake in them is a
    SceneError naming that file); return lines describing what was read."""
    lines = []
    if scene.vessel is not None:
        try:
            from .hydro import load_vessel
        except ImportError:  # pragma: no cover - the hydro layer ships load_vessel
            lines.append("vessel file: not read (floatmoor.hydro.load_vessel is not available)")
        else:
            v = load_vessel(scene.vessel)
            sizes = ", ".join(f"{n} {k}" for k, n in v.database.sizes.items()
                              if k in ("omega", "wave_direction"))
            text = (f"vessel file read: {v.name}, mass {v.mass:.6g} kg, database "
                    f"{v.database_path} ({sizes})")
            if v.fairleads:
                text += f", {len(v.fairleads)} fairleads"
            lines.append(text)
            lines.append(_hydro_report(v))
    if scene.mooring is not None:
        try:
            from .io.mooring_section import parse_mooring
        except ImportError:  # pragma: no cover - io ships the mooring reader
            lines.append("mooring: not read (floatmoor.io.mooring_section is not available)")
        else:
            site = scene.site
            ms = parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                               water_density=site.water_density, gravity=site.gravity)
            t = ms.tensions()
            active = ~t["failed"].values
            tf = t["fairlead_tension"].values[active]
            failed = [str(n) for n, f in zip(t["line"].values, t["failed"].values) if f]
            text = (f"mooring read: {ms.n_lines} lines; at zero offset fairlead tension "
                    f"{tf.min() / 1e3:.1f}-{tf.max() / 1e3:.1f} kN, max utilisation "
                    f"{float(t['utilisation'].values[active].max()):.3f} of MBS")
            if failed:
                text += "; failed: " + ", ".join(failed)
            lines.append(text)
    return lines


def _hydro_report(vessel) -> str:
    """The retardation-function consistency report of the vessel's hydrodynamic database
    (:func:`floatmoor.hydro.consistency_report`).  Its warnings (undecayed damping,
    irregular-frequency spikes) are part of the printed table, so they are not repeated on
    stderr.  Takes about 0.1 s for the shipped vessels; nothing is cached."""
    from .hydro import consistency_report, format_consistency

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        report = consistency_report(vessel.database)
    report.attrs.setdefault("source", str(vessel.database_path))
    return format_consistency(report)


# -- environment ----------------------------------------------------------------------------------
def _environment_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file")
    p.add_argument("--seed", type=seed_int, default=None,
                   help="seed of the realisation (default: the scene's first seed)")
    p.add_argument("--duration", type=positive_float, default=None, metavar="S",
                   help="length of the realisation in s (default: the scene's analysis.duration)")
    p.add_argument("--dt", type=positive_float, default=None, metavar="S",
                   help="time step in s (default: the scene's analysis.dt)")


def _environment_run(args: argparse.Namespace) -> int:
    from .io.scene import load_scene

    scene = load_scene(args.scene)
    duration = scene.analysis.duration if args.duration is None else args.duration
    dt = scene.analysis.dt if args.dt is None else args.dt
    seed = scene.analysis.seeds[0] if args.seed is None else args.seed
    if dt >= duration:
        raise UsageError(f"the time step --dt {dt:g} s must be shorter than the duration "
                         f"{duration:g} s")
    from .io.analysis import check_time_steps
    check_time_steps(scene.file, duration, dt, key="--dt" if args.dt is not None else
                     "--duration" if args.duration is not None else "analysis.dt")
    from .io.checks import check_dt_resolves_waves
    check_dt_resolves_waves(scene.file, "--dt" if args.dt is not None else "analysis.dt", dt,
                            scene.environment.waves)
    from .metocean.summary import environment_summary, format_summary

    summary = environment_summary(scene.environment, water_depth=scene.site.water_depth,
                                  duration=duration, dt=dt, seed=seed)
    print(f"scene: {scene.name}  [{scene.file}]")
    print(format_summary(summary))
    return EXIT_OK


COMMANDS: list[Command | tuple[str, str]] = [
    Command("check", "validate a scene and print what it would build",
            _check_arguments, _check_run),
    Command("environment", "realise the scene's waves, wind and current and print statistics",
            _environment_arguments, _environment_run),
    ("statics", "floatmoor.commands.statics"),
    ("run", "floatmoor.commands.run"),
    ("fd", "floatmoor.commands.fd"),
    ("fatigue", "floatmoor.commands.fatigue"),
    ("convergence", "floatmoor.commands.convergence"),
    ("report", "floatmoor.commands.report"),
    ("lines", "floatmoor.commands.lines"),
    ("import", "floatmoor.commands.import_"),
    ("export", "floatmoor.commands.export"),
    ("campaign", "floatmoor.commands.campaign"),
    ("compile", "floatmoor.commands.compile"),
]
"""The subcommands, in the order ``--help`` lists them: a :class:`Command`, or
``(name, module)`` for a module following the :mod:`floatmoor.commands` convention."""


def commands() -> list[Command]:
    """The registered subcommands as :class:`Command` objects (modules imported)."""
    return [c if isinstance(c, Command) else module_command(*c) for c in COMMANDS]


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``floatmoor`` command."""
    parser = argparse.ArgumentParser(
        prog="floatmoor",
        description="Coupled floater and mooring analysis in time and frequency domain.",
        epilog="Exit status: 0 ok, 2 input error, 3 numerical failure, 130 interrupted.")
    parser.add_argument("--version", action="version", version=f"floatmoor {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for cmd in commands():
        p = sub.add_parser(cmd.name, help=cmd.help, description=cmd.description or cmd.help,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        cmd.add_arguments(p)
        p.set_defaults(_run=cmd.run)
    return parser


def _show_warning(message, category, filename, lineno, file=None, line=None):
    """Print FloatmoorWarnings as ``floatmoor: warning: ...`` (no source line)."""
    stream = sys.stderr if file is None else file
    if issubclass(category, FloatmoorWarning):
        stream.write(f"floatmoor: warning: {message}\n")
    else:
        stream.write(warnings.formatwarning(message, category, filename, lineno, line))


def _with_input_file(exc: SceneError, args: argparse.Namespace) -> SceneError:
    """A SceneError raised without a file (by a model checking its arguments) names the input
    the command was given: the scene file, or the results folder of ``report``."""
    source = getattr(args, "scene", None) or getattr(args, "results_dir", None)
    if not source:
        return exc
    return SceneError(source, exc.key, exc.expected, exc.found, exc.hint)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the ``floatmoor`` command with ``argv`` (default ``sys.argv[1:]``); return the exit
    status."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a command-line mistake (status 2)
        return exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
    with warnings.catch_warnings():
        warnings.showwarning = _show_warning
        warnings.simplefilter("default", FloatmoorWarning)
        warnings.simplefilter("ignore", RuntimeWarning)  # numpy noise; NaN results are errors
        try:
            return int(args._run(args))
        except (SceneError, UsageError) as exc:
            if isinstance(exc, SceneError) and exc.file is None:
                exc = _with_input_file(exc, args)
            print(f"floatmoor: error: {exc}", file=sys.stderr)
            return EXIT_SCENE_ERROR
        except NumericalError as exc:
            print(f"floatmoor: numerical error: {exc}", file=sys.stderr)
            return EXIT_NUMERICAL_ERROR
        except KeyboardInterrupt:
            print("floatmoor: interrupted", file=sys.stderr)
            return EXIT_INTERRUPTED
        except OSError as exc:  # a file named on the command line cannot be read or written
            name = exc.filename if exc.filename is not None else ""
            what = exc.strerror or type(exc).__name__
            print(f"floatmoor: error: {name}: {what}" if name else f"floatmoor: error: {exc}",
                  file=sys.stderr)
            return EXIT_SCENE_ERROR


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
