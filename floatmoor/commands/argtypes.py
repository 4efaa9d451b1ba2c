"""argparse types shared by the subcommands (a bad value is a usage error, exit status 2)."""

from __future__ import annotations

import argparse

__all__ = ["positive_float", "nonnegative_float", "seed_int"]


def _number(text: str, ok, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, found {text!r}") from None
    if not (ok(value) and value < float("inf")):
        raise argparse.ArgumentTypeError(f"expected a number {what}, found {text}")
    return value


def positive_float(text: str) -> float:
    """A finite number > 0."""
    return _number(text, lambda v: v > 0.0, "> 0")


def nonnegative_float(text: str) -> float:
    """A finite number >= 0."""
    return _number(text, lambda v: v >= 0.0, ">= 0")


def seed_int(text: str) -> int:
    """A seed, an integer >= 0."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer seed, found {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected a seed >= 0, found {text}")
    return value
