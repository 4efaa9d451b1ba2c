"""floatmoor.io: scene files -> validated, frozen configuration objects.

See :mod:`floatmoor.io.scene` for the scene format.
"""

from .analysis import AnalysisSpec, seeds_from_text
from .environment import load_environment
from .scene import SECTIONS, Scene, Section, load_scene
from .site import SiteSpec

__all__ = ["load_scene", "Scene", "Section", "SECTIONS", "SiteSpec", "AnalysisSpec",
           "load_environment", "seeds_from_text"]
