"""floatmoor: coupled floater and mooring analysis in time and frequency domain."""

from importlib.metadata import PackageNotFoundError, version as _version

from .core.errors import ConvergenceError, FloatmoorError, FloatmoorWarning, NumericalError, SceneError

try:
    __version__ = _version("floatmoor")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.0.0+unknown"

__all__ = ["__version__", "SceneError", "NumericalError", "ConvergenceError", "FloatmoorError",
           "FloatmoorWarning", "load_scene", "simulate", "frequency_domain", "statics"]


def __getattr__(name):
    # Lazy: `import floatmoor` stays light; `floatmoor.load_scene` imports the scene reader.
    if name == "load_scene":
        from .io.scene import load_scene
        return load_scene
    if name == "simulate":
        from .simulate import simulate
        return simulate
    if name in ("frequency_domain", "statics"):
        # submodules; floatmoor.frequency_domain is callable: frequency_domain(scene) runs it
        import importlib
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module 'floatmoor' has no attribute {name!r}")
