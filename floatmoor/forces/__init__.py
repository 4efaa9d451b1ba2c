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
* ``slender_elements`` Morison drag strips on the hull (viscous drift, Wang (2016) ch. 6)

A model's ``contribute`` adds its force terms, each of one kind (:mod:`floatmoor.forces.terms`:
restoring, mooring, damping, quadratic damping, memory, relative flow, strips, series); the
time-domain kernel sums the terms kind by kind and knows no model.  A new model of an existing
kind is one new module here (a registered :class:`ForceModel`) and its name in the import line
below.  Rules that combine models (viscous drift: extra damping, current double counting,
corrected drift) are applied where the scene's models are chosen
(:func:`floatmoor.io.build.model_inputs`) and reach the models as ``SetupContext.inputs``.
"""

from . import environment, hydrostatics, mooring, radiation, slender, waves  # noqa: F401
from .base import REGISTRY, ForceModel, KernelAssembly, SetupContext, model_class, register
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
