"""The result of the frequency-domain analysis as plain numpy arrays (no xarray).

:func:`floatmoor.analyses.frequency_domain.frequency_domain_result` returns an :class:`FDResult`;
:func:`floatmoor.analyses.fd_dataset.to_dataset` turns it into the Dataset that
:func:`floatmoor.frequency_domain` returns (the variable names below are the Dataset's).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..solvers.frequency_domain import FDModel, FDOptions, FDSolution

__all__ = ["FDResult"]


@dataclass(frozen=True, kw_only=True)
class FDResult:
    """Frequency-domain analysis of one scene (SI units, DOF order surge .. yaw, earth axes).

    Per-line arrays follow ``line_names``; a failed (removed) line has NaN in its tension and
    stiffness values (``line_failed`` True).  Equation numbers: Wang (2016).

    The linear system and its solution
        model : :class:`~floatmoor.solvers.frequency_domain.FDModel` about the mean position:
            ``omega`` (n,) and ``mu`` (m,) grids, ``wave_spectrum``, ``stiffness`` (hydrostatic
            plus mooring), the mass, added mass and damping as solved.
        solution : :class:`~floatmoor.solvers.frequency_domain.FDSolution`: ``rao`` (n, 6),
            ``wf_spectrum``, ``lf_spectrum``, ``lf_mass``, ``lf_damping``,
            ``equivalent_damping`` and the covariances.

    Mean position (eq. 2.39)
        mean (6,); mean_force_wind, mean_force_current, mean_force_drift (6,) N, N m;
        mean_force_model (n_models, 6) the mean force of every force model of ``models`` (the
        restoring models' constants are not in it: they are part of the statics).
        With ``line_current_drag`` (None otherwise): mean_force_line_current (6,), the current
        drag's change of the mooring force at the mean position, and
        tension_static_line_current (n_lines,), its change of the static fairlead tensions
        (included in ``tension_static``), N.

    Low-frequency ingredients
        lf_drift_force_spectrum, lf_wind_force_spectrum : (m, 6, 6) force cross-spectra;
        lf_damping_wind, lf_damping_current, lf_damping_wave_drift : (6, 6);
        lf_natural_period : (3,) s, undamped (surge/sway/yaw, heave-roll-pitch condensed).

    Motion statistics (6,) each
        wf_std, wf_tz, wf_n_cycles, wf_sig, wf_max, lf_std, lf_tz, lf_n_cycles, lf_sig,
        lf_max; max_total, min_total, governing_branch (eq. 2.49).

    Lines (n_lines,) each, except where noted
        line_failed, mbs, tension_gradient (n_lines, 6), tangent_stiffness,
        fairlead_motion_wf_spectrum (n, n_lines), fairlead_motion_lf_spectrum (m, n_lines),
        fairlead_motion_wf_std/_tz, fairlead_motion_lf_std/_tz, tension_static,
        tension_std_lf, tension_tz_lf, tension_max_lf, tension_wf_base, tension_std_wf,
        tension_tz_wf, tension_max_wf, tension_max_total, tension_branch,
        tension_max_total_catenary, safety_factor (figure 5.9 columns).

    Provenance
        scene (file or name), scene_name, options, models (the force models, in the order of
        the time domain's), has_waves, drift_method (the resolved ``newman``, ``qtf`` or
        ``none``), viscous_drift_model, lf_added_mass_source, wave_heading (rad),
        wind_speed_at_coefficient_height, wind_coefficient_height (NaN without wind force),
        current_speed_surface, wave_spectrum_fraction_covered, linearisation_iterations,
        statics_iterations, notes (the warnings and remarks of the run), run_time_s.
    """

    scene: str
    scene_name: str
    options: FDOptions
    model: FDModel
    solution: FDSolution
    line_names: tuple
    # mean position
    mean: np.ndarray
    mean_force_wind: np.ndarray
    mean_force_current: np.ndarray
    mean_force_drift: np.ndarray
    mean_force_model: np.ndarray
    statics_iterations: int
    # low-frequency ingredients
    lf_drift_force_spectrum: np.ndarray
    lf_wind_force_spectrum: np.ndarray
    lf_damping_wind: np.ndarray
    lf_damping_current: np.ndarray
    lf_damping_wave_drift: np.ndarray
    lf_natural_period: np.ndarray
    # motion statistics
    wf_std: np.ndarray
    wf_tz: np.ndarray
    wf_n_cycles: np.ndarray
    wf_sig: np.ndarray
    wf_max: np.ndarray
    lf_std: np.ndarray
    lf_tz: np.ndarray
    lf_n_cycles: np.ndarray
    lf_sig: np.ndarray
    lf_max: np.ndarray
    max_total: np.ndarray
    min_total: np.ndarray
    governing_branch: np.ndarray
    # lines
    line_failed: np.ndarray
    mbs: np.ndarray
    tension_gradient: np.ndarray
    tangent_stiffness: np.ndarray
    fairlead_motion_wf_spectrum: np.ndarray
    fairlead_motion_lf_spectrum: np.ndarray
    fairlead_motion_wf_std: np.ndarray
    fairlead_motion_wf_tz: np.ndarray
    fairlead_motion_lf_std: np.ndarray
    fairlead_motion_lf_tz: np.ndarray
    tension_static: np.ndarray
    tension_std_lf: np.ndarray
    tension_tz_lf: np.ndarray
    tension_max_lf: np.ndarray
    tension_wf_base: np.ndarray
    tension_std_wf: np.ndarray
    tension_tz_wf: np.ndarray
    tension_max_wf: np.ndarray
    tension_max_total: np.ndarray
    tension_branch: np.ndarray
    tension_max_total_catenary: np.ndarray
    safety_factor: np.ndarray
    # provenance
    has_waves: bool
    drift_method: str
    viscous_drift_model: str
    lf_added_mass_source: str
    wave_heading: float
    wind_speed_at_coefficient_height: float
    wind_coefficient_height: float
    current_speed_surface: float
    wave_spectrum_fraction_covered: float
    linearisation_iterations: int
    models: tuple = ()
    notes: tuple = ()
    run_time_s: float = float("nan")
    # tension_model: dynamic (None otherwise): the quasi-static WF tension beside the dynamic one
    tension_std_wf_quasi_static: np.ndarray | None = None
    tension_tz_wf_quasi_static: np.ndarray | None = None
    tension_wf_dynamic_spectrum: np.ndarray | None = None
    dynamic_amplification: np.ndarray | None = None
    # line_current_drag (None otherwise): the lines' static current drag at the mean position
    mean_force_line_current: np.ndarray | None = None
    tension_static_line_current: np.ndarray | None = None
    # line_damping: fe (None otherwise): the lines' LF impedance at the LF surge natural
    # frequency (analyses/fd_line_damping.py)
    lf_damping_mooring: np.ndarray | None = None
    lf_stiffness_mooring_dynamic: np.ndarray | None = None
    lf_mooring_frequency: float | None = None
    fairlead_damping: np.ndarray | None = None
    line_damping_iterations: int | None = None
    tension_std_lf_quasi_static: np.ndarray | None = None
