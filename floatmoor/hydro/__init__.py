"""floatmoor.hydro: hydrodynamic databases (xarray), WAMIT/Capytaine readers, retardation
functions and vessel files.  See :mod:`floatmoor.hydro.database` for the database form."""

from .capytaine_io import from_capytaine_dataset, read_capytaine
from .database import (
    DOF_NAMES,
    PHASE_CONVENTION,
    DatabaseError,
    interpolate_heading,
    load_database,
    make_database,
    save_database,
    validate_database,
)
from .retardation import (
    consistency_report,
    cutoff_time,
    fit_infinite_frequency_added_mass,
    format_consistency,
    reconstruct_from_retardation,
    retardation_function,
)
from .vessel import CoefficientTable, Vessel, load_vessel
from .wamit import read_wamit

__all__ = ["DOF_NAMES", "PHASE_CONVENTION", "DatabaseError", "load_database", "make_database",
           "save_database", "validate_database", "interpolate_heading", "read_wamit", "read_capytaine",
           "from_capytaine_dataset", "retardation_function", "cutoff_time",
           "reconstruct_from_retardation", "fit_infinite_frequency_added_mass",
           "consistency_report", "format_consistency", "Vessel", "CoefficientTable",
           "load_vessel"]
