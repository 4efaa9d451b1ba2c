"""floatmoor: coupled floater and mooring analysis in time and frequency domain.

The user API, plain functions of a scene (a file path, a loaded scene or a built scene)::

    import floatmoor
    scene = floatmoor.load_scene("scenes/floatel_100yr.yaml")
    eq = floatmoor.equilibrium(scene)          # static equilibrium (pose, tensions, stiffness)
    fd = floatmoor.frequency_domain(scene)     # xarray Dataset (mean, LF, WF, maxima, tensions)
    ts = floatmoor.simulate(scene, seed=1)     # xarray Dataset (time series of one seed)
    floatmoor.run_seeds("scene.yaml", range(1, 21), "out/")   # many seeds, one file each

They live in :mod:`floatmoor.analyses` (one module per analysis) and are imported on first
use, so ``import floatmoor`` stays light.
"""

from .core.numba_cache import configure as _configure_numba_cache

# numba's cache folder, keyed by the kernel sources (before any kernel is decorated)
_NUMBA_CACHE = _configure_numba_cache()

from importlib import import_module as _import_module  # noqa: E402
from importlib.metadata import PackageNotFoundError  # noqa: E402
from importlib.metadata import version as _version  # noqa: E402

from .core.errors import (  # noqa: E402
    ConvergenceError,
    FloatmoorError,
    FloatmoorWarning,
    NumericalError,
    SceneError,
)

try:
    __version__ = _version("floatmoor")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.0.0+unknown"

# public name -> "module:name" that defines it (imported on first use by __getattr__)
_LAZY = {
    "load_scene": "floatmoor.io.scene:load_scene",
    "build": "floatmoor.io.build:build",
    "equilibrium": "floatmoor.analyses.statics:equilibrium",
    "restoring_curves": "floatmoor.analyses.statics:restoring_curves",
    "simulate": "floatmoor.analyses.simulate:simulate",
    "run_seeds": "floatmoor.analyses.runner:run_seeds",
    "frequency_domain": "floatmoor.analyses.frequency_domain:frequency_domain",
    "frequency_domain_result": "floatmoor.analyses.frequency_domain:frequency_domain_result",
    "format_fd_table": "floatmoor.analyses.fd_dataset:format_table",
    "fatigue_analysis": "floatmoor.analyses.fatigue:fatigue_analysis",
    "convergence_study": "floatmoor.analyses.convergence:convergence_study",
    "FDOptions": "floatmoor.solvers.frequency_domain:FDOptions",
}

__all__ = ["__version__", "SceneError", "NumericalError", "ConvergenceError", "FloatmoorError",
           "FloatmoorWarning", *_LAZY]


def __getattr__(name):
    where = _LAZY.get(name)
    if where is None:
        raise AttributeError(f"module 'floatmoor' has no attribute {name!r}")
    module, attr = where.split(":")
    obj = getattr(_import_module(module), attr)
    globals()[name] = obj  # later look-ups skip __getattr__
    return obj


def __dir__():
    return sorted(set(globals()) | set(_LAZY))
