"""The ``analysis:`` section of a scene: simulation length, time step, start-up and seeds.

```yaml
analysis: {duration: 10800.0, dt: 0.1, transient: 1200.0, ramp: 100.0, seeds: [1, 20]}
```

Every key is optional; the defaults are a 3-hour storm (10800 s, DNV-OS-E301's short-term
duration) at dt = 0.1 s, no transient window, no ramp, seed 1.

``seeds`` takes one of (see :func:`parse_seeds`):

* an integer: that one seed, ``seeds: 7``;
* a list of exactly two integers ``[first, last]``: the inclusive range, ``seeds: [1, 20]`` is
  the 20 seeds 1, 2, ..., 20;
* a string in the same syntax as the command line ``--seeds``: ranges and single seeds separated
  by commas, ``seeds: "1-20"``, ``seeds: "3,7,11"``, ``seeds: "1-5,9"``.

A list of any other length is refused (``[3, 7]`` would otherwise mean something different from
``[3, 7, 11]``); write an explicit list as a string.

``fibre_stiffness`` (mooring with fibre-rope line types, :mod:`floatmoor.mooring.fibre`):
``upper`` (default: the storm dynamic stiffness ``alpha + beta L_m`` about the mean tension,
the bound that governs the tensions), ``lower`` (the working curve's tangent also for the
dynamics: the bound that governs the offsets) or ``both`` (``floatmoor run`` runs both bounds
into the sub-folders ``fibre_lower`` and ``fibre_upper``; ``floatmoor report`` of the folder
takes the governing one and shows both; ``floatmoor fd`` writes both; a campaign runs every
condition at both bounds; a single :func:`floatmoor.simulate` runs ``upper``).
The mean offset always comes from the working curve. Ignored without fibre ropes.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

from ..core.config import Node
from ..core.errors import FloatmoorWarning, SceneError

__all__ = ["AnalysisSpec", "parse_analysis", "parse_seeds", "seeds_from_text", "ANALYSIS_KEYS",
           "check_time_steps", "MAX_SEEDS", "MAX_TIME_STEPS", "MAX_SEED"]

ANALYSIS_KEYS = ("duration", "dt", "transient", "ramp", "seeds", "fibre_stiffness")

FIBRE_STIFFNESS = ("lower", "upper", "both")
"""Values of ``analysis.fibre_stiffness``."""

MAX_SEED = 2**32 - 1
"""Largest seed accepted (numpy's SeedSequence takes any non-negative integer; we keep seeds to
32 bits so that they print and store everywhere)."""


@dataclass(frozen=True, kw_only=True)
class AnalysisSpec:
    """Time-domain settings: ``duration`` (s, the simulated length including the transient),
    ``dt`` (s), ``transient`` (s removed from the start before statistics), ``ramp`` (s of
    smooth start of the loads), ``seeds`` (tuple of ints, one realisation each) and
    ``fibre_stiffness`` (``lower``, ``upper`` or ``both``; module docstring)."""

    duration: float = 10800.0
    dt: float = 0.1
    transient: float = 0.0
    ramp: float = 0.0
    seeds: tuple[int, ...] = (1,)
    fibre_stiffness: str = "upper"

    @property
    def fibre_bounds(self) -> tuple[str, ...]:
        """The fibre stiffness bounds to run: ``("lower", "upper")`` for ``both``."""
        return ("lower", "upper") if self.fibre_stiffness == "both" else (self.fibre_stiffness,)


def parse_analysis(node: Node) -> AnalysisSpec:
    """Read an ``analysis:`` mapping into an :class:`AnalysisSpec`.

    Refused: duration <= 0, dt <= 0, dt >= duration, transient < 0 or >= duration, ramp < 0 or
    >= duration, bad seeds.  Warned: a ramp longer than the transient (the statistics would
    include the ramp-up), fewer than 1000 steps, and a statistics window (duration - transient)
    shorter than one hour.
    """
    node.reject_unknown(ANALYSIS_KEYS)
    d = AnalysisSpec()
    duration = node.float("duration", d.duration, gt=0.0, unit="s")
    dt = node.float("dt", d.dt, gt=0.0, lt=duration, unit="s")
    transient = node.float("transient", d.transient, ge=0.0, lt=duration, unit="s")
    ramp = node.float("ramp", d.ramp, ge=0.0, lt=duration, unit="s")
    seeds = parse_seeds(node, "seeds", d.seeds)
    fibre = node.str("fibre_stiffness", d.fibre_stiffness, choices=FIBRE_STIFFNESS)
    check_time_steps(node.file, duration, dt, key=node.key("dt"))
    if ramp > transient:
        _warn(node, "ramp", f"the ramp ({ramp:g} s) is longer than the transient window "
              f"({transient:g} s): the statistics include the ramp-up")
    if duration / dt < 1000.0:
        _warn(node, "dt", f"only {duration / dt:.0f} time steps in {duration:g} s")
    if duration - transient < 3600.0:
        _warn(node, "duration", f"the statistics window (duration - transient = "
              f"{duration - transient:g} s) is shorter than one hour; extreme values from it "
              "are not those of a 3-hour storm")
    return AnalysisSpec(duration=duration, dt=dt, transient=transient, ramp=ramp, seeds=seeds,
                        fibre_stiffness=fibre)


def parse_seeds(node: Node, key: str, default=SceneError.MISSING) -> tuple[int, ...]:
    """Read seeds (an int, ``[first, last]`` inclusive, or a string ``"1-20"``/``"3,7,11"``)."""
    expected = ('an integer seed, [first, last] (an inclusive range), or a string such as '
                '"1-20" or "3,7,11"')
    if key not in node:
        if default is SceneError.MISSING:
            raise node.error(key, expected)
        return tuple(default)
    value = node.raw(key)
    if isinstance(value, bool):
        raise node.error(key, expected, value)
    if isinstance(value, int):
        seeds = (value,)
    elif isinstance(value, list):
        if len(value) != 2 or any(isinstance(v, bool) or not isinstance(v, int) for v in value):
            hint = ("a two-item list is a range [first, last]; write other lists as a string, "
                    f'e.g. "{",".join(str(v) for v in value)}"' if value else None)
            raise node.error(key, expected, value, hint)
        first, last = value
        if last < first:
            raise node.error(key, "[first, last] with last >= first", value)
        for s in (first, last):
            if not 0 <= s <= MAX_SEED:
                raise node.error(key, f"seeds between 0 and {MAX_SEED}", value)
        if last - first + 1 > MAX_SEEDS:
            raise node.error(key, f"at most {MAX_SEEDS} seeds", value,
                             f"[{first}, {last}] is {last - first + 1} seeds")
        seeds = tuple(range(first, last + 1))
    elif isinstance(value, str):
        try:
            seeds = seeds_from_text(value)
        except ValueError as exc:
            raise node.error(key, expected, value, str(exc)) from None
    else:
        raise node.error(key, expected, value)
    for s in seeds:
        if not 0 <= s <= MAX_SEED:
            raise node.error(key, f"seeds between 0 and {MAX_SEED}", value)
    return seeds


MAX_SEEDS = 100_000
"""Most seeds one scene or command may ask for (a 3-hour storm takes minutes per seed; 100,000
seeds is already years of computing).  Checked before the list of seeds is built."""


_TOKEN = re.compile(r"^\s*(\d+)\s*(?:-\s*(\d+)\s*)?$")


def seeds_from_text(text: str) -> tuple[int, ...]:
    """Parse ``"1-20"``, ``"3,7,11"`` or ``"1-5,9"`` into a tuple of seeds (inclusive ranges).

    Raises ValueError on anything else (empty text, a descending range, a repeated seed).
    """
    seeds: list[int] = []
    if not text.strip():
        raise ValueError("no seeds given")
    if len(text) > 100_000:
        raise ValueError(f"a seed list of {len(text)} characters is too long")
    for part in text.split(","):
        m = _TOKEN.match(part)
        if m is None:
            raise ValueError(f"cannot read {part.strip()[:40]!r} as a seed or a range first-last")
        if max(len(g or "") for g in m.groups()) > 12:
            raise ValueError(f"a seed must be between 0 and {MAX_SEED}: "
                             f"{part.strip()[:40]!r} is out of range")
        first = int(m.group(1))
        last = int(m.group(2)) if m.group(2) is not None else first
        if last < first:
            raise ValueError(f"the range {first}-{last} runs backwards")
        if last > MAX_SEED:
            raise ValueError(f"seeds must be between 0 and {MAX_SEED}, found {last}")
        if len(seeds) + last - first + 1 > MAX_SEEDS:
            raise ValueError(f"at most {MAX_SEEDS} seeds, found {len(seeds) + last - first + 1} "
                             "or more")
        seeds.extend(range(first, last + 1))
    if len(set(seeds)) != len(seeds):
        raise ValueError("a seed is repeated")
    return tuple(seeds)


MAX_TIME_STEPS = 20_000_000
"""Most time steps one run may take: 3 hours at dt = 0.5 ms.  Motion and velocity alone need
96 bytes a step (12 doubles), 1.9 GB at the bound, before line tensions and forces."""

BYTES_PER_STEP = 96
"""Memory a time step needs at least: motion and velocity, 12 doubles."""


def check_time_steps(file, duration: float, dt: float, *, key: str = "analysis.dt") -> None:
    """SceneError when ``duration / dt`` exceeds :data:`MAX_TIME_STEPS`, stating the memory the
    time series would need (the bound is checked before anything is allocated)."""
    steps = duration / dt
    if steps > MAX_TIME_STEPS:
        need = steps * BYTES_PER_STEP
        raise SceneError(file, key, f"at most {MAX_TIME_STEPS:,} time steps (duration / dt)",
                         dt, f"duration {duration:g} s / dt {dt:g} s = {steps:.3g} steps, which "
                         f"would need at least {_bytes(need)} for the motion and velocity alone")


def _bytes(n: float) -> str:
    for unit, size in (("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n / 1e3:.3g} kB"


def _warn(node: Node, key: str, message: str) -> None:
    warnings.warn(f"{node.file}: {node.key(key)}: {message}", FloatmoorWarning, stacklevel=4)


def describe_analysis(a: AnalysisSpec) -> list[str]:
    """Lines describing the analysis settings."""
    n = len(a.seeds)
    if n == 1:
        seeds = f"seed {a.seeds[0]}"
    elif a.seeds == tuple(range(a.seeds[0], a.seeds[0] + n)):
        seeds = f"{n} seeds {a.seeds[0]}-{a.seeds[-1]}"
    else:
        seeds = f"{n} seeds " + ", ".join(str(s) for s in a.seeds)
    out = [f"analysis: duration {a.duration:g} s ({a.duration / 3600.0:.3g} h), dt {a.dt:g} s "
           f"({round(a.duration / a.dt)} steps), transient {a.transient:g} s, ramp {a.ramp:g} s",
           f"          statistics over {a.duration - a.transient:g} s; {seeds}"]
    if a.fibre_stiffness != "upper":
        out.append(f"          fibre rope stiffness bound(s): {', '.join(a.fibre_bounds)}")
    return out
