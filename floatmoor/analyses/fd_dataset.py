"""The frequency-domain result as an xarray Dataset, driven by one table of variables.

Each row of :data:`VARIABLES` gives a Dataset variable's name, dims, units, long name and, when
it is not the :class:`~floatmoor.analyses.fd_result.FDResult` field of the same name, the getter
that computes it from the result (the layout of Capytaine's ``io/xarray.py``).  A long name may
quote the result as ``{r.field}``.  :data:`ATTRIBUTES` does the same for the global attributes.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass

import numpy as np
import xarray as xr

from ..core.dofs import DOF_NAMES
from .fd_result import FDResult

__all__ = ["Variable", "VARIABLES", "ATTRIBUTES", "to_dataset", "format_table"]

MIXED_UNITS = "m (surge, sway, heave), rad (roll, pitch, yaw)"
MIXED_FORCE = "N (surge, sway, heave), N m (roll, pitch, yaw)"
SPECTRUM_UNITS = "m^2 s/rad (translations), rad^2 s/rad (rotations)"
FORCE_SPECTRUM_UNITS = "N^2 s/rad (forces), N^2 m^2 s/rad (moments)"
DAMPING_UNITS = "N s/m, N s, N m s/rad"
STIFFNESS_UNITS = "N/m, N, N m/rad"


@dataclass(frozen=True)
class Variable:
    """One Dataset variable: ``get(result)`` gives its values (default: the result's field
    ``name``)."""

    name: str
    dims: tuple
    units: str
    long_name: str
    get: Callable[[FDResult], np.ndarray] | None = None

    def values(self, r: FDResult) -> np.ndarray | None:
        v = getattr(r, self.name) if self.get is None else self.get(r)
        return None if v is None else np.asarray(v)


def _diagonal(field: str):
    """Getter of the (m, 6) diagonal of an (m, 6, 6) cross-spectrum field."""
    return lambda r: np.einsum("nii->ni", getattr(r, field))


D, DD, W, MU, L = ("dof",), ("dof", "dof2"), ("omega",), ("mu",), ("line",)

VARIABLES: tuple[Variable, ...] = (
    # mean position and mean loads (eq. 2.39)
    Variable("mean", D, MIXED_UNITS, "mean position (static equilibrium, eq. 2.39)"),
    Variable("mean_force_wind", D, MIXED_FORCE, "mean wind force C_wi U^2"),
    Variable("mean_force_current", D, MIXED_FORCE, "mean current force C_cu V^2"),
    Variable("mean_force_drift", D, MIXED_FORCE,
             "mean wave drift force 2 int C_wa S dw (eq. 2.37)"),
    Variable("mean_force_model", ("model", "dof"), MIXED_FORCE,
             "mean force of each force model at rest at the mean heading (restoring "
             "constants: in the statics)"),
    # motion statistics
    Variable("wf_std", D, MIXED_UNITS, "WF standard deviation (eq. 2.41)"),
    Variable("wf_tz", D, "s", "WF mean zero up-crossing period 2 pi sqrt(m0/m2)"),
    Variable("wf_n_cycles", D, "1", "WF number of cycles duration / Tz"),
    Variable("wf_sig", D, MIXED_UNITS, "WF significant value 2 sigma (eq. 2.42)"),
    Variable("wf_max", D, MIXED_UNITS, "WF most probable maximum sigma sqrt(2 ln N) (eq. 2.43)"),
    Variable("lf_std", D, MIXED_UNITS, "LF standard deviation (eq. 2.46)"),
    Variable("lf_tz", D, "s", "LF mean zero up-crossing period 2 pi sqrt(m0/m2)"),
    Variable("lf_n_cycles", D, "1", "LF number of cycles duration / Tz"),
    Variable("lf_sig", D, MIXED_UNITS, "LF significant value 2 sigma (eq. 2.47)"),
    Variable("lf_max", D, MIXED_UNITS, "LF most probable maximum sigma sqrt(2 ln N) (eq. 2.48)"),
    Variable("max_total", D, MIXED_UNITS,
             "maximum: mean + max(LFmax + WFsig, WFmax + LFsig) (eq. 2.49)"),
    Variable("min_total", D, MIXED_UNITS,
             "minimum: mean - max(LFmax + WFsig, WFmax + LFsig) (eq. 2.49 mirrored)"),
    Variable("governing_branch", D, "1", "eq. 2.49 branch: 1 LFmax + WFsig, 2 WFmax + LFsig"),
    # spectra and transfer functions
    Variable("wave_spectrum", W, "m^2 s/rad", "wave elevation spectrum S_eta (all directions)",
             lambda r: r.model.wave_spectrum),
    Variable("rao", ("omega", "dof", "complex"), "m/m (translations), rad/m (rotations)",
             "first-order motion RAO, exp(+i omega t) (eq. 2.40); a sea of one direction",
             lambda r: None if r.solution.rao is None else
             np.stack([r.solution.rao.real, r.solution.rao.imag], axis=-1)),
    Variable("rao_direction", ("wave_direction", "omega", "dof", "complex"),
             "m/m (translations), rad/m (rotations)",
             "first-order motion RAO of each direction of a sea of several directions "
             "(responses add over the directions: sum_d |RAO_d|^2 S_d)",
             lambda r: None if r.solution.rao is not None else
             np.stack([r.solution.raos.real, r.solution.raos.imag], axis=-1)),
    Variable("wave_spectrum_direction", ("wave_direction", "omega"), "m^2 s/rad",
             "wave elevation spectrum of each direction (sea of several directions)",
             lambda r: r.model.direction_spectra),
    Variable("wf_spectrum", ("omega", "dof"), SPECTRUM_UNITS,
             "WF response spectrum |H|^2 S (eq. 2.34)", lambda r: r.solution.wf_spectrum),
    Variable("lf_spectrum", ("mu", "dof"), SPECTRUM_UNITS, "LF response spectrum (eq. 2.44)",
             lambda r: r.solution.lf_spectrum),
    Variable("lf_drift_force_spectrum", ("mu", "dof"), FORCE_SPECTRUM_UNITS,
             "slowly varying wave drift force spectrum ({r.drift_method}, eq. 2.38)",
             _diagonal("lf_drift_force_spectrum")),
    Variable("lf_wind_force_spectrum", ("mu", "dof"), FORCE_SPECTRUM_UNITS,
             "wind gust force spectrum 4 U^2 C^2 S_u", _diagonal("lf_wind_force_spectrum")),
    # the linear system
    Variable("stiffness", DD, "N/m, N, N m/rad",
             "restoring at the mean position (hydrostatic + mooring)", lambda r: r.model.stiffness),
    Variable("lf_mass", DD, "kg, kg m, kg m^2", "LF mass M + A(0) (surge, sway, yaw)",
             lambda r: r.solution.lf_mass),
    Variable("lf_damping", DD, DAMPING_UNITS,
             "LF damping: linear + linearised quadratic + wind + current (+ drift)",
             lambda r: r.solution.lf_damping),
    Variable("lf_damping_wind", DD, DAMPING_UNITS, "wind damping"),
    Variable("lf_damping_current", DD, DAMPING_UNITS, "current damping"),
    Variable("lf_damping_wave_drift", DD, DAMPING_UNITS, "wave drift damping (Aranha; option)"),
    Variable("equivalent_quadratic_damping", DD, DAMPING_UNITS,
             "stochastic linearisation sqrt(8/pi) sigma_v B_q",
             lambda r: r.solution.equivalent_damping),
    Variable("lf_natural_period", ("lf_mode",), "s",
             "undamped LF natural periods (surge/sway/yaw, heave-roll-pitch condensed)"),
    # fairlead motion along each line
    Variable("fairlead_motion_wf_spectrum", ("omega", "line"), "m^2 s/rad",
             "WF spectrum of the fairlead motion along the line (positive away from the anchor)"),
    Variable("fairlead_motion_lf_spectrum", ("mu", "line"), "m^2 s/rad",
             "LF spectrum of the fairlead motion along the line"),
    Variable("fairlead_motion_wf_std", L, "m", "WF std of the fairlead motion along the line"),
    Variable("fairlead_motion_wf_tz", L, "s", "WF Tz of the fairlead motion"),
    Variable("fairlead_motion_lf_std", L, "m", "LF std of the fairlead motion along the line"),
    Variable("fairlead_motion_lf_tz", L, "s", "LF Tz of the fairlead motion"),
    # line tensions (Wang (2016) figure 5.9 columns)
    Variable("tension_gradient", ("line", "dof"), "N/m (translations), N/rad (rotations)",
             "dT/dpose at the mean position (central differences)"),
    Variable("tangent_stiffness", L, "N/m", "dT/du, u the fairlead displacement along the line"),
    Variable("tension_static", L, "N", "static (mean) fairlead tension"),
    Variable("tension_std_lf", L, "N", "LF tension std"),
    Variable("tension_tz_lf", L, "s", "LF tension Tz"),
    Variable("tension_max_lf", L, "N", "LF tension most probable maximum (above static)"),
    Variable("tension_wf_base", L, "N", "WF base: max total - max WF (eq. 2.60)"),
    Variable("tension_std_wf", L, "N", "WF tension std"),
    Variable("tension_tz_wf", L, "s", "WF tension Tz"),
    Variable("tension_max_wf", L, "N", "WF tension most probable maximum"),
    Variable("tension_max_total", L, "N",
             "maximum tension, eq. 2.49 on the quasi-static tension"),
    Variable("tension_branch", L, "1", "eq. 2.49 branch for the tension"),
    Variable("tension_max_total_catenary", L, "N",
             "catenary tension at the most likely pose of the eq. 2.49 tension excursion "
             "(nonlinear quasi-static check of max total)"),
    Variable("mbs", L, "N", "minimum breaking strength"),
    Variable("safety_factor", L, "1", "MBS / maximum tension"),
    Variable("line_failed", L, "1", "line removed (failed)"),
    # tension_model: dynamic only (absent otherwise)
    Variable("tension_std_wf_quasi_static", L, "N", "WF tension std, quasi-static"),
    Variable("tension_tz_wf_quasi_static", L, "s", "WF tension Tz, quasi-static"),
    Variable("tension_wf_dynamic_spectrum", ("omega", "line"), "N^2 s/rad",
             "WF fairlead tension spectrum of the FE line in the frequency domain"),
    Variable("dynamic_amplification", L, "1",
             "WF tension std: dynamic (FE line) over quasi-static"),
    # line_current_drag only
    Variable("mean_force_line_current", D, MIXED_FORCE,
             "static current drag of the lines: change of the mooring force at the mean position"),
    Variable("tension_static_line_current", L, "N",
             "static current drag of the lines: change of the static fairlead tension "
             "(included in tension_static)"),
    # line_damping: fe only
    Variable("lf_damping_mooring", DD, DAMPING_UNITS,
             "LF damping of the mooring lines (FE, drag linearised with WF and LF motion) at "
             "the LF surge natural frequency"),
    Variable("lf_stiffness_mooring_dynamic", DD, STIFFNESS_UNITS,
             "LF dynamic stiffness of the mooring lines beyond their static stiffness, at the "
             "LF surge natural frequency"),
    Variable("tension_std_lf_quasi_static", L, "N",
             "LF tension std, quasi-static (catenary gradient; tension_std_lf has the FE lines' "
             "dynamics)"),
    Variable("fairlead_damping", ("line", "axis", "axis2"), "N s/m",
             "LF damping of each line at its fairlead (earth axes), at the LF surge natural "
             "frequency"),
)


def _viscous_attr(r: FDResult) -> str:
    if r.viscous_drift_model == "slender_elements":
        return ("slender_elements (frequency domain: their current load and its damping; no "
                "viscous wave drift)")
    return r.viscous_drift_model


ATTRIBUTES: tuple[tuple[str, Callable[[FDResult], object]], ...] = (
    ("title", lambda r: "floatmoor frequency-domain analysis (MIMOSA-style)"),
    ("scene", lambda r: r.scene),
    ("scene_name", lambda r: r.scene_name),
    ("floatmoor_version", lambda r: _floatmoor_version()),
    ("numpy_version", lambda r: np.__version__),
    ("xarray_version", lambda r: xr.__version__),
    ("options", lambda r: repr(asdict(r.options))),
    ("duration", lambda r: r.options.duration),
    ("tension_model", lambda r: r.options.tension_model),
    ("line_current_drag", lambda r: int(r.mean_force_line_current is not None)),
    ("line_damping", lambda r: r.options.line_damping),
    ("line_damping_frequency", lambda r: float("nan") if r.lf_mooring_frequency is None
     else r.lf_mooring_frequency),
    ("line_damping_iterations", lambda r: r.line_damping_iterations or 0),
    ("drift_method", lambda r: r.drift_method if r.has_waves else "none (no waves)"),
    ("models", lambda r: ", ".join(r.models)),
    ("viscous_drift_model", _viscous_attr),
    ("lf_added_mass_source", lambda r: r.lf_added_mass_source),
    ("lf_cutoff_frequency", lambda r: float(r.model.mu[-1])),
    ("wave_heading", lambda r: r.wave_heading),
    ("wind_speed_at_coefficient_height", lambda r: r.wind_speed_at_coefficient_height),
    ("wind_coefficient_height", lambda r: r.wind_coefficient_height),
    ("current_speed_surface", lambda r: r.current_speed_surface),
    ("wave_spectrum_fraction_covered", lambda r: r.wave_spectrum_fraction_covered),
    ("linearisation_iterations", lambda r: r.linearisation_iterations),
    ("statics_iterations", lambda r: r.statics_iterations),
    ("notes", lambda r: "; ".join(r.notes)),
    ("run_time_s", lambda r: r.run_time_s),
    ("run_date_utc", lambda r: time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())),
)


def _floatmoor_version() -> str:
    from .. import __version__
    return __version__


def to_dataset(r: FDResult) -> xr.Dataset:
    """The Dataset of a frequency-domain result: dims ``dof``, ``dof2``, ``omega``, ``mu``,
    ``line``, ``complex``, ``lf_mode``; every variable of :data:`VARIABLES` with ``units`` and
    ``long_name``; the attributes of :data:`ATTRIBUTES`."""
    data = {v.name: (v.dims, v.values(r), {"units": v.units,
                                           "long_name": v.long_name.format(r=r)})
            for v in VARIABLES if v.values(r) is not None}
    coords = {"dof": list(DOF_NAMES), "dof2": list(DOF_NAMES),
              "omega": ("omega", r.model.omega, {"units": "rad/s", "long_name": "wave frequency"}),
              "mu": ("mu", r.model.mu, {"units": "rad/s",
                                        "long_name": "low (difference) frequency"}),
              "line": list(r.line_names), "complex": ["re", "im"],
              "lf_mode": np.arange(np.asarray(r.lf_natural_period).size),
              "model": ("model", list(r.models), {"units": "", "long_name": "force model "
                                                  "(the order of the time domain's terms)"})}
    if r.model.direction_spectra is not None:
        coords["wave_direction"] = ("wave_direction", np.asarray(r.model.directions, float),
                                    {"units": "rad", "long_name": "direction of travel of the "
                                     "waves (from +x towards +y)"})
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({name: get(r) for name, get in ATTRIBUTES})
    return ds


def format_table(ds: xr.Dataset) -> str:
    """The MIMOSA-style report of a frequency-domain Dataset: motions (mean, LF, WF, eq. 2.49
    total) and the line tension table of Wang (2016) figure 5.9 (kN)."""
    out = [f"Frequency-domain analysis: {ds.attrs.get('scene_name', '')}",
           f"  duration {ds.attrs['duration']:g} s, tension model {ds.attrs['tension_model']}, "
           f"drift {ds.attrs['drift_method']}, LF mass: {ds.attrs['lf_added_mass_source']}",
           "",
           "* MOTIONS (translations m, rotations deg) *",
           "  DOF      Mean    StD LF  Max LF   StD WF  Sig WF   Max WF   Max Tot  Min Tot"]
    for i, d in enumerate(ds["dof"].values):
        f = 1.0 if i < 3 else 180.0 / math.pi
        vals = [ds[k].values[i] * f for k in ("mean", "lf_std", "lf_max", "wf_std", "wf_sig",
                                              "wf_max", "max_total", "min_total")]
        out.append(f"  {d:6s}" + "".join(f"{x:9.2f}" for x in vals))
    if "mean_force_line_current" in ds:
        f = ds["mean_force_line_current"].values
        out.append(f"  (Mean with the static current drag of the lines: {f[0] / 1e3:.1f} kN "
                   f"surge, {f[1] / 1e3:.1f} kN sway, {f[5] / 1e3:.1f} kN m yaw; the static "
                   "tensions include it)")
    out += ["", "* MAXIMUM LINE TENSIONS. LF AND WF MOTION *  (kN)",
            "  Line       Static  StD LF  Max LF WF Base  StD WF  Max WF Max Tot  Safety  Max Tot",
            "                                                                      factor  catenary"]
    cols = ("tension_static", "tension_std_lf", "tension_max_lf", "tension_wf_base",
            "tension_std_wf", "tension_max_wf", "tension_max_total")
    for j, name in enumerate(ds["line"].values):
        if bool(ds["line_failed"].values[j]):
            out.append(f"  {str(name):9s}  failed (removed)")
            continue
        vals = [ds[c].values[j] / 1e3 for c in cols]
        out.append(f"  {str(name):9s}" + "".join(f"{x:8.1f}" for x in vals)
                   + f"{ds['safety_factor'].values[j]:8.2f}"
                   + f"{ds['tension_max_total_catenary'].values[j] / 1e3:9.1f}")
    dynamic = "dynamic_amplification" in ds
    lf_dyn = ds.attrs.get("line_damping") == "fe"
    if dynamic:
        out += [("  (StD WF, Max WF, Max Tot, Safety factor: dynamic WF tension of the FE lines; "
                 + ("LF with the FE lines' dynamics)" if lf_dyn else "LF quasi-static)")), "",
                "* WAVE-FREQUENCY TENSION: QUASI-STATIC AND DYNAMIC (FE line) *  (kN)",
                "  Line      StD WF QS  StD WF dyn   Dyn. ampl.  Tz QS (s)  Tz dyn (s)"]
        for j, name in enumerate(ds["line"].values):
            if bool(ds["line_failed"].values[j]):
                continue
            out.append(f"  {name!s:9s}{ds['tension_std_wf_quasi_static'].values[j] / 1e3:10.1f}"
                       f"{ds['tension_std_wf'].values[j] / 1e3:12.1f}"
                       f"{ds['dynamic_amplification'].values[j]:13.2f}"
                       f"{ds['tension_tz_wf_quasi_static'].values[j]:11.2f}"
                       f"{ds['tension_tz_wf'].values[j]:12.2f}")
    kind = {(True, True): "WF and LF dynamic (FE lines)", (True, False): "WF dynamic / LF "
            "quasi-static", (False, True): "WF quasi-static / LF dynamic (FE lines)",
            (False, False): "quasi-static"}[(bool(dynamic), lf_dyn)]
    out += ["  (Max Tot: eq. 2.49 on the linearised " + kind + " tension; Max Tot catenary: the "
            "catenary at the most likely pose of that excursion)"]
    if ds.attrs.get("notes"):
        out += ["", "notes: " + ds.attrs["notes"]]
    return "\n".join(out)
