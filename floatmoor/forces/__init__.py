"""floatmoor.forces: the force models, each one file serving the time and the frequency domain.

One interface (:class:`ForceModel`: ``wanted``, ``setup``, ``force``, ``contribute``,
``frequency_domain``, optional ``stiffness``, ``damping_linearized``, ``channels``),
registered by name in :data:`REGISTRY`, in the order both domains assemble them:

* ``hydrostatics``       buoyancy - weight, linear hydrostatic + gravity + additional restoring
* ``mooring``            quasi-static catenary lines at the instantaneous fairleads, line failure
* ``radiation``          radiation memory (retardation functions); A(w), B(w) in the FD
* ``damping_linear``, ``damping_quadratic``  the vessel's full matrices
* ``wave1``              first-order wave excitation
* ``drift_newman``       mean + slow drift, Newman's approximation
* ``drift_qtf``          mean + slow drift from the full difference-frequency QTF
* ``wind``, ``current``  quadratic in the relative velocity (NPD gust for wind)
* ``slender_elements``   Morison drag strips on the hull (viscous drift, Wang (2016) ch. 6)
* ``wave_drift_damping`` Aranha's wave drift damping on the low-frequency motion

A model's ``contribute`` adds its time-domain terms, each of one kind
(:mod:`floatmoor.forces.terms`); the kernel sums the terms kind by kind and knows no model.
Its ``frequency_domain`` gives its mean force, linearised stiffness and damping and its WF and
LF excitation (:class:`FDTerms`); models of the linear kinds get it from their terms.  A new
model is one new module here (a registered :class:`ForceModel`) and its name in the import
line below (the import order is the registry's order).  Rules that combine models (viscous
drift: extra damping, current double counting, corrected drift) are applied where the scene's
models are chosen (:func:`floatmoor.io.build.model_inputs`) and reach the models as
``SetupContext.inputs`` / ``FDContext.inputs``.
"""

# the import order is the registry's order (the order of the terms in the time loop)
from . import hydrostatics, mooring, radiation, damping, waves  # noqa: F401, I001
from . import environment, slender, wave_drift_damping  # noqa: F401, I001
from .base import (
    GROUPS,
    REGISTRY,
    FDContext,
    FDTerms,
    ForceModel,
    KernelAssembly,
    SetupContext,
    model_class,
    register,
    select_models,
)
from .damping import LinearDamping, QuadraticDamping
from .environment import Current, Wind
from .hydrostatics import Hydrostatics
from .mooring import QuasiStaticMooring
from .radiation import Radiation, infinite_frequency_added_mass, retardation_matrix
from .series import derived_seed
from .wave_drift_damping import WaveDriftDamping
from .waves import DriftNewman, DriftQTF, FirstOrderWave, WaveComponents, wave_components

__all__ = ["ForceModel", "SetupContext", "KernelAssembly", "FDContext", "FDTerms", "REGISTRY",
           "register", "model_class", "select_models", "Hydrostatics", "LinearDamping",
           "QuadraticDamping", "QuasiStaticMooring", "Radiation", "FirstOrderWave", "DriftNewman",
           "DriftQTF", "Wind", "Current", "WaveDriftDamping", "WaveComponents",
           "wave_components", "derived_seed", "infinite_frequency_added_mass",
           "retardation_matrix", "GROUPS"]
