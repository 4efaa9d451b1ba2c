"""Degree-of-freedom names and indices, in floatmoor's fixed order."""

DOF_NAMES = ("surge", "sway", "heave", "roll", "pitch", "yaw")
SURGE, SWAY, HEAVE, ROLL, PITCH, YAW = range(6)
DOF_UNITS = ("m", "m", "m", "rad", "rad", "rad")
FORCE_UNITS = ("N", "N", "N", "N m", "N m", "N m")


def dof_index(name: str) -> int:
    """Index of a DOF by name (``"surge"`` -> 0)."""
    try:
        return DOF_NAMES.index(name)
    except ValueError:
        raise KeyError(f"unknown DOF {name!r}; the DOFs are {', '.join(DOF_NAMES)}") from None
