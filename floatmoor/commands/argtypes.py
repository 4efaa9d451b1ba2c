"""argparse types shared by the subcommands (a bad value is a usage error, exit status 2)."""

from __future__ import annotations

import argparse

__all__ = ["positive_float", "nonnegative_float", "seed_int", "positive_int", "thread_count",
           "MAX_SEED"]


def _number(text: str, ok, what: str) -> float:
    try:
        value = float(text)
    except (ValueError, OverflowError):
        raise argparse.ArgumentTypeError(f"expected a number, found {text[:40]!r}") from None
    if not (ok(value) and value < float("inf")):
        raise argparse.ArgumentTypeError(f"expected a number {what}, found {text}")
    return value


def positive_float(text: str) -> float:
    """A finite number > 0."""
    return _number(text, lambda v: v > 0.0, "> 0")


def nonnegative_float(text: str) -> float:
    """A finite number >= 0."""
    return _number(text, lambda v: v >= 0.0, ">= 0")


MAX_SEED = 2**32 - 1
"""Largest seed (the same as :data:`floatmoor.io.analysis.MAX_SEED`; kept here so that parsing the
command line imports nothing heavy)."""


def seed_int(text: str) -> int:
    """A seed, an integer in [0, 2**32 - 1]."""
    if len(text) > 20:
        raise argparse.ArgumentTypeError(f"expected a seed between 0 and {MAX_SEED}, found a "
                                         f"{len(text)}-character value")
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer seed, found {text!r}") from None
    if not 0 <= value <= MAX_SEED:
        raise argparse.ArgumentTypeError(f"expected a seed between 0 and {MAX_SEED}, found {text}")
    return value


def positive_int(text: str) -> int:
    """An integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, found {text[:40]!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, found {text}")
    return value


def thread_count(text: str) -> int | str:
    """A thread count: an integer >= 1 or ``auto``."""
    if text.strip().lower() == "auto":
        return "auto"
    try:
        return positive_int(text)
    except argparse.ArgumentTypeError:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1 or auto, found "
                                         f"{text[:40]!r}") from None


def check_out_dir(path) -> None:
    """Raise :class:`floatmoor.cli.UsageError` (exit 2, naming ``path``) unless ``path`` is a
    folder that exists or can be created and is writable (checked before any computing)."""
    import os
    from pathlib import Path

    from ..cli import UsageError

    p = Path(path)
    if p.exists() and not p.is_dir():
        raise UsageError(f"--out {p}: expected a folder, found an existing file")
    parent = p
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir():
        raise UsageError(f"--out {p}: cannot create the folder, {parent} is a file")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise UsageError(f"--out {p}: cannot write in {parent} (permission denied)")


def check_out_file(path, *, overwrite: bool = True) -> None:
    """Raise :class:`floatmoor.cli.UsageError` (exit 2, naming ``path``) unless ``path`` can be
    written as a file: not a folder, its folder exists (or can be created) and is writable."""
    import os
    from pathlib import Path

    from ..cli import UsageError

    p = Path(path)
    if p.is_dir():
        raise UsageError(f"--out {p}: expected a file name, found an existing folder")
    if p.exists() and not overwrite:
        raise UsageError(f"--out {p}: the file exists")
    parent = p.parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir():
        raise UsageError(f"--out {p}: cannot create the file, {parent} is a file")
    if not os.access(parent, os.W_OK | os.X_OK) or (p.exists() and not os.access(p, os.W_OK)):
        raise UsageError(f"--out {p}: cannot write there (permission denied)")
