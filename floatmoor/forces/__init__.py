"""floatmoor.forces: the force models that plug into the solvers.

One interface (:class:`ForceModel`: ``setup``, ``force``, optional ``stiffness``,
``damping_linearized``, ``channels``, ``contribute``), registered by name in :data:`REGISTRY`:

* ``hydrostatics``      buoyancy - weight, linear hydrostatic + gravity + additional restoring
* ``mooring``           quasi-static catenary lines at the instantaneous fairleads, line failure
* ``radiation``         radiation memory (retardation functions)
* ``damping_linear``, ``damping_quadratic``
* ``wave1``             first-order wave excitation
* ``drift_newman``      mean + slow drift, Newman's approximation
* ``drift_qtf``         mean + slow drift from the full difference-frequency QTF
* ``wind``, ``current`` quadratic in the relative velocity (NPD gust for wind)
* ``slender_elements`` Morison drag strips on the hull (viscous drift, seed 002 ch. 6)
"""

from .base import (REGISTRY, ForceModel, KernelAssembly, SetupContext, model_class, register)
from . import hydrostatics, mooring, radiation, waves, environment, slender  # noqa: F401
from .environment import Current, Wind, derived_seed
from .hydrostatics import Hydrostatics, LinearDamping, QuadraticDamping
from .mooring import QuasiStaticMooring
from .radiation import Radiation, infinite_frequency_added_mass, retardation_matrix
from .waves import DriftNewman, DriftQTF, FirstOrderWave, WaveComponents, wave_components

__all__ = ["ForceModel", "SetupContext", "KernelAssembly", "REGISTRY", "register", "model_class",
           "Hydrostatics", "LinearDamping", "QuadraticDamping", "QuasiStaticMooring",
           "Radiation", "FirstOrderWave", "DriftNewman", "DriftQTF", "Wind", "Current", "WaveComponents",
           "wave_components", "derived_seed", "infinite_frequency_added_mass",
           "retardation_matrix", "GROUPS"]

GROUPS = {"drift": ("drift_newman", "drift_qtf"),
          "damping": ("damping_linear", "damping_quadratic"),
          "waves": ("wave1", "drift_newman", "drift_qtf")}
"""Names that exclude several models at once (``forces: {exclude: [drift]}``)."""
