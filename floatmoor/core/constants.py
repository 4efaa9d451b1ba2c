"""Physical constants and defaults (SI units)."""

GRAVITY = 9.80665
"""Standard acceleration of gravity, m/s^2."""

RHO_WATER = 1025.0
"""Default sea-water density, kg/m^3."""

RHO_AIR = 1.226
"""Default air density, kg/m^3 (DNV-RP-C205 sec. 5.1 uses 1.226 at 15 deg C)."""

KINEMATIC_VISCOSITY_WATER = 1.19e-6
"""Sea-water kinematic viscosity at 15 deg C, m^2/s (DNV-RP-C205 app. F)."""
