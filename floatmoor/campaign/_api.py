"""The one place where the campaign reaches into the rest of floatmoor (scene building and the
two solvers), so that a reorganisation of those modules is fixed here only."""

from __future__ import annotations

import floatmoor


def load_scene(path):
    return floatmoor.load_scene(path)


def build(scene, failed_lines=None):
    from ..io.build import build as _build
    return _build(scene, failed_lines=list(failed_lines) if failed_lines else None)


def simulate(built, **kwargs):
    return floatmoor.simulate(built, **kwargs)


def frequency_domain(built):
    return floatmoor.frequency_domain(built)


def forces_spec():
    from ..io.forces_section import ForcesSpec
    return ForcesSpec
