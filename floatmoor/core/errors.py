"""Errors and warnings raised by floatmoor.

Two kinds of failure matter to a mooring engineer:

* :class:`SceneError` -- a mistake in an input file.  It names the file, the key path inside
  it (``environment.waves.hs``), what was expected and what was found, so the user can fix the
  file without reading a traceback.  The CLI prints it and exits with status 2.
* :class:`NumericalError` -- a run that went wrong (NaN, exploding state, no convergence).  It
  names the simulated time, the line or degree of freedom concerned and a likely remedy.
"""

from __future__ import annotations

import math
import os

__all__ = ["FloatmoorError", "SceneError", "NumericalError", "ConvergenceError", "FloatmoorWarning",
           "argument_error", "check_positive"]


class FloatmoorError(Exception):
    """Base class of every error floatmoor raises on purpose."""


def _short(value, limit: int = 80) -> str:
    """A repr of ``value`` cut to ``limit`` characters, built without ever forming the full
    representation (a value may be an alias bomb or a cyclic list); numpy scalars and arrays are
    shown as plain numbers and lists."""
    out: list[str] = []
    budget = [limit + 1]

    def put(text: str) -> bool:
        out.append(text[: budget[0]])
        budget[0] -= len(text)
        return budget[0] > 0

    def walk(v, depth: int) -> bool:
        if depth > 6:
            return put("...")
        if hasattr(v, "tolist") and hasattr(v, "dtype"):  # numpy scalar or array
            v = v.ravel()[:limit].tolist() if getattr(v, "ndim", 0) else v.item()
        if isinstance(v, (list, tuple)):
            open_, close = ("[", "]") if isinstance(v, list) else ("(", ")")
            if not put(open_):
                return False
            for i, item in enumerate(v):
                if i and not put(", "):
                    return False
                if not walk(item, depth + 1):
                    return False
            return put(close)
        if isinstance(v, dict):
            if not put("{"):
                return False
            for i, (k, item) in enumerate(v.items()):
                if (i and not put(", ")) or not walk(k, depth + 1) or not put(": "):
                    return False
                if not walk(item, depth + 1):
                    return False
            return put("}")
        if isinstance(v, int) and not isinstance(v, bool) and v.bit_length() > 200:
            return put(f"<an integer of about {int(v.bit_length() * 0.30103)} digits>")
        if isinstance(v, str) and len(v) > limit:
            v = v[:limit]
        return put(repr(v))

    walk(value, 0)
    text = "".join(out)
    return text if len(text) <= limit else text[: limit - 3] + "..."


class SceneError(FloatmoorError, ValueError):
    """A mistake in a scene, vessel, metocean or line-type file.

    Parameters
    ----------
    file:
        Path of the file holding the mistake (``None`` for a scene built in Python).
    key:
        Dotted key path inside the file, e.g. ``"environment.waves.hs"`` or
        ``"mooring.lines[3].segments[0].length"``.  Empty for the file as a whole.
    expected:
        What the key should hold, in words ("a number > 0", "one of: jonswap, ...").
    found:
        What was found.  Use :data:`SceneError.MISSING` for a missing key.
    hint:
        Optional advice appended to the message.
    """

    MISSING = object()
    NOT_APPLICABLE = object()
    """``found`` for a mistake that is not a value (the hint says what was found)."""

    def __init__(self, file, key: str, expected: str, found=MISSING, hint: str | None = None):
        self.file = None if file is None else os.fspath(file)
        self.key = key
        self.expected = expected
        self.found = found
        self.hint = hint
        super().__init__(self._message())

    def _message(self) -> str:
        where = self.file if self.file is not None else "(given in Python)"
        if self.key:
            where += f": {self.key}"
        if self.found is SceneError.MISSING:
            found = "nothing (the key is missing)"
        else:
            found = _short(self.found)
        msg = f"{where}: expected {self.expected}"
        if self.found is not SceneError.NOT_APPLICABLE:
            msg += f", found {found}"
        if self.hint:
            msg += f" ({self.hint})"
        return msg

    def __reduce__(self):  # keep the error picklable across worker processes
        sentinel = (1 if self.found is SceneError.MISSING else
                    2 if self.found is SceneError.NOT_APPLICABLE else 0)
        return (_rebuild_scene_error, (self.file, self.key, self.expected,
                                       None if sentinel else self.found, sentinel, self.hint))


def _rebuild_scene_error(file, key, expected, found, missing, hint):
    found = {1: SceneError.MISSING, 2: SceneError.NOT_APPLICABLE}.get(int(missing), found)
    return SceneError(file, key, expected, found, hint)


def argument_error(key: str, expected: str, found=SceneError.MISSING,
                   hint: str | None = None) -> SceneError:
    """The :class:`SceneError` of a value given in Python rather than read from a file.

    ``key`` names the argument (or ``argument.field``); the error carries no file name.
    """
    return SceneError(None, key, expected, found, hint)


def check_positive(value, key: str) -> float:
    """``value`` as a finite float > 0, else the :func:`argument_error` naming ``key``."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise argument_error(key, "a number > 0", value) from None
    if not math.isfinite(v) or v <= 0.0:
        raise argument_error(key, "a number > 0", value)
    return v


class NumericalError(FloatmoorError, RuntimeError):
    """A numerical failure during a run.

    Parameters
    ----------
    what:
        What went wrong ("NaN in the state", "no convergence after 50 iterations").
    time:
        Simulated time in s at which it happened, if in a time loop.
    where:
        The DOF, line or model concerned ("surge", "line 7", "catenary").
    remedy:
        A likely remedy ("reduce dt", "add damping in yaw", ...).
    """

    def __init__(self, what: str, *, time: float | None = None, where: str | None = None,
                 remedy: str | None = None):
        self.what = what
        self.time = time
        self.where = where
        self.remedy = remedy
        parts = [what]
        if time is not None:
            parts.append(f"at t = {time:.3f} s")
        if where:
            parts.append(f"in {where}")
        msg = " ".join(parts)
        if remedy:
            msg += f". Likely remedy: {remedy}"
        super().__init__(msg)

    def __reduce__(self):
        return (_rebuild_numerical_error, (type(self), self.what, self.time, self.where, self.remedy))


def _rebuild_numerical_error(cls, what, time, where, remedy):
    return cls(what, time=time, where=where, remedy=remedy)


class ConvergenceError(NumericalError):
    """An iterative solver (catenary, equilibrium, stochastic linearisation) did not converge."""


class FloatmoorWarning(UserWarning):
    """Warnings about questionable but usable input or results."""
