"""floatmoor.metocean: wave, wind and current spectra, realisations and wave kinematics.

Public API (SI units; headings in rad, direction of travel from +x towards +y):

* configuration: :class:`WaveSpec`, :class:`WaveSystems`, :class:`WindSpec`, :class:`CurrentSpec`, :class:`Environment`
* wave spectra (m^2 s/rad): :func:`jonswap`, :func:`pierson_moskowitz`, :func:`torsethaugen`,
  :func:`dnv_gamma`, :func:`wave_spectrum`, :func:`spreading_directions`
* wind (S in m^2/s, f in Hz): :func:`npd_wind_spectrum`, :func:`npd_wind_profile`,
  :func:`api_wind_spectrum`, :func:`wind_spectrum`
* current: :func:`current_speed`, :func:`current_velocity`
* realisations: :func:`realise_waves` -> :class:`WaveRealisation`, :func:`realise_wind` ->
  :class:`WindRealisation`
* kinematics: :func:`wavenumber`, :func:`airy_kinematics`, kernel :func:`airy_kinematics_into`
* summary: :func:`environment_summary`, :func:`format_summary`
"""

from floatmoor.metocean.config import (
    CURRENT_PROFILES,
    SPREADING_FUNCTIONS,
    WAVE_SPECTRA,
    WIND_SPECTRA,
    CurrentSpec,
    Environment,
    WaveSpec,
    WaveSystems,
    WindSpec,
    total_hs,
    wave_systems,
)
from floatmoor.metocean.current import (
    CURRENT_PROFILE_KERNELS,
    current_speed,
    current_velocity,
    piecewise_linear_speed_into,
    power_law_speed_into,
)
from floatmoor.metocean.kinematics import (
    airy_kinematics,
    airy_kinematics_into,
    depth_factors,
    surface_elevation_into,
    wavenumber,
)
from floatmoor.metocean.realisation import (
    WaveRealisation,
    WindRealisation,
    cosine_sum_uniform_into,
    realise_waves,
    realise_wind,
)
from floatmoor.metocean.spectra import (
    WAVE_SPECTRUM_FUNCTIONS,
    cos2s_spreading,
    default_omega_range,
    dnv_gamma,
    dnv_jonswap_normalisation,
    jonswap,
    pierson_moskowitz,
    sea_directions,
    spectral_moment,
    spectrum_gamma,
    spreading_directions,
    torsethaugen,
    torsethaugen_parameters,
    wave_spectrum,
)
from floatmoor.metocean.summary import environment_summary, format_summary, zero_upcrossing_waves
from floatmoor.metocean.wind import (
    WIND_SPECTRUM_FUNCTIONS,
    api_turbulence_intensity,
    api_wind_profile,
    api_wind_spectrum,
    constant_wind_spectrum,
    npd_turbulence_intensity,
    npd_wind_profile,
    npd_wind_spectrum,
    wind_mean_speed,
    wind_spectrum,
)

__all__ = [
    "WaveSpec", "WaveSystems", "WindSpec", "CurrentSpec", "Environment", "WAVE_SPECTRA",
    "WIND_SPECTRA", "CURRENT_PROFILES", "SPREADING_FUNCTIONS", "wave_systems", "total_hs",
    "sea_directions",
    "jonswap", "pierson_moskowitz", "torsethaugen", "torsethaugen_parameters", "dnv_gamma",
    "dnv_jonswap_normalisation", "wave_spectrum", "WAVE_SPECTRUM_FUNCTIONS", "spectral_moment",
    "spectrum_gamma", "cos2s_spreading", "spreading_directions", "default_omega_range",
    "npd_wind_spectrum", "npd_wind_profile", "npd_turbulence_intensity", "api_wind_spectrum",
    "api_wind_profile", "api_turbulence_intensity", "constant_wind_spectrum", "wind_spectrum",
    "wind_mean_speed", "WIND_SPECTRUM_FUNCTIONS",
    "current_speed", "current_velocity", "piecewise_linear_speed_into", "power_law_speed_into",
    "CURRENT_PROFILE_KERNELS",
    "realise_waves", "realise_wind", "WaveRealisation", "WindRealisation",
    "cosine_sum_uniform_into",
    "wavenumber", "depth_factors", "airy_kinematics", "airy_kinematics_into",
    "surface_elevation_into",
    "environment_summary", "format_summary", "zero_upcrossing_waves",
]
