"""The mass budget of an imported floating model: every rigid mass built, their total, centre of
gravity and inertia, against the hydrostatic equilibrium at zero pose,

    buoyancy rho g V  =  weight m g  +  vertical pull of the mooring (and + AddF0's Fz up),

with V the displaced volume of the potential-flow model (HydroDyn ``PtfmVol0``).  A budget that
does not close within :data:`BUDGET_TOLERANCE` of the buoyancy names the likely missing item.
The budget is printed by the import and written into the vessel file (``mass_budget``,
:mod:`floatmoor.hydro.vessel`), where it is checked against the vessel's masses on every load.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bodies import combine

__all__ = ["BUDGET_TOLERANCE", "MassBudget", "mass_budget"]

BUDGET_TOLERANCE = 0.005
"""Largest vertical imbalance at zero pose, as a fraction of the buoyancy, of a budget that
closes (0.5 %: the heave offset it causes is then below 0.5 % of V / A_wp, a few centimetres
for the reference models)."""


@dataclass(frozen=True, kw_only=True)
class MassBudget:
    items: tuple            # RigidMass
    mass: float
    cog: np.ndarray
    inertia: np.ndarray
    volume: float
    water_density: float
    gravity: float
    mooring_vertical: float  # N, downward pull of the lines at zero pose (> 0 pulls down)
    preload_vertical: float  # N, AddF0 Fz (up positive)
    suspects: tuple          # (name, kg or None if unknown) of items missing or doubtful;
                             # a negative mass is buoyancy outside PtfmVol0

    @property
    def buoyancy(self) -> float:
        return self.water_density * self.gravity * self.volume

    @property
    def weight(self) -> float:
        return self.mass * self.gravity

    @property
    def imbalance(self) -> float:
        """N, buoyancy - weight - mooring pull + preload (> 0: the body would rise)."""
        return self.buoyancy - self.weight - self.mooring_vertical + self.preload_vertical

    @property
    def fraction(self) -> float:
        return self.imbalance / self.buoyancy if self.buoyancy > 0 else float("inf")

    @property
    def closes(self) -> bool:
        return abs(self.fraction) <= BUDGET_TOLERANCE

    def likely_missing(self) -> str:
        """Words naming what most likely explains an imbalance."""
        dm = self.imbalance / self.gravity  # kg: > 0 mass missing, < 0 mass too much
        if dm > 0:
            unknown = [n for n, m in self.suspects if m is None]
            if unknown:
                return f"about {dm / 1e3:.4g} t is missing: most likely {' and '.join(unknown)}"
            known = [(n, m) for n, m in self.suspects if m is not None and m > 0]
            if known:
                n, m = min(known, key=lambda s: abs(s[1] - dm))
                if abs(m - dm) < 0.5 * dm:
                    return f"about {dm / 1e3:.4g} t is missing: most likely {n} ({m / 1e3:.4g} t)"
            return (f"about {dm / 1e3:.4g} t of mass is missing (ballast that neither ElastoDyn "
                    f"nor a HydroDyn fill group holds, a mass in a file not read, or a mooring "
                    f"pretension not imported)")
        heavy = [(n, m) for n, m in self.suspects if m is not None and m < 0]
        if heavy:
            n, m = min(heavy, key=lambda s: abs(s[1] - dm))
            return (f"the body is {-dm / 1e3:.4g} t too heavy for its displaced volume: most "
                    f"likely {n} ({-m / 1e3:.4g} t of buoyancy not in PtfmVol0)")
        return (f"the body is {-dm / 1e3:.4g} t too heavy for its displaced volume (PtfmVol0 "
                f"too small, a mass counted twice, or buoyancy of members outside the "
                f"potential-flow model)")

    def lines(self) -> list[str]:
        """The budget as printed by the import."""
        out = ["mass budget (zero pose, body frame: x downwind, z up from the still-water line):"]
        for it in self.items:
            c = ", ".join(f"{v:.4g}" for v in it.cog)
            out.append(f"  {it.name:<14} {it.mass:>14,.0f} kg  at ({c}) m   {it.source}")
        c = ", ".join(f"{v:.4g}" for v in self.cog)
        Id = ", ".join(f"{v:.4g}" for v in np.diag(self.inertia))
        out.append(f"  {'total':<14} {self.mass:>14,.0f} kg  CoG ({c}) m, inertia about the "
                   f"CoG (xx, yy, zz) ({Id}) kg m^2")
        out.append(f"  buoyancy rho g V = {self.water_density:g} x {self.gravity:g} x "
                   f"{self.volume:.6g} m^3 = {self.buoyancy / 1e3:,.1f} kN; weight "
                   f"{self.weight / 1e3:,.1f} kN; mooring vertical pull "
                   f"{self.mooring_vertical / 1e3:,.1f} kN"
                   + (f"; AddF0 Fz {self.preload_vertical / 1e3:,.1f} kN"
                      if self.preload_vertical else ""))
        verdict = ("closes" if self.closes else "does NOT close")
        out.append(f"  imbalance (buoyancy - weight - mooring pull) {self.imbalance / 1e3:,.1f} kN "
                   f"= {100 * self.fraction:+.3f} % of the buoyancy: {verdict} within "
                   f"{100 * BUDGET_TOLERANCE:g} %")
        if not self.closes:
            out.append(f"  {self.likely_missing()}")
        return out

    def yaml(self, fmt) -> str:
        """The ``mass_budget:`` section of the vessel file."""
        L = ["# Mass budget of the import: the masses above (platform and point masses) against",
             "# the hydrostatic equilibrium at zero pose.  floatmoor checks on every load that the",
             "# masses still sum to total_mass: edit the masses and delete this section together.",
             "mass_budget:",
             "  items:"]
        for it in self.items:
            L.append(f"    - {{name: {it.name}, mass: {fmt(it.mass)}, position: ["
                     + ", ".join(fmt(v) for v in it.cog) + "]}")
        L += [f"  total_mass: {fmt(self.mass)}   # kg",
              "  centre_of_gravity: [" + ", ".join(fmt(v) for v in self.cog) + "]   # m",
              "  inertia_cg: [" + ", ".join("[" + ", ".join(fmt(v) for v in r) + "]"
                                            for r in self.inertia) + "]   # kg m^2",
              f"  displaced_volume: {fmt(self.volume)}   # m^3, HydroDyn PtfmVol0",
              f"  water_density: {fmt(self.water_density)}",
              f"  gravity: {fmt(self.gravity)}",
              f"  buoyancy: {fmt(self.buoyancy)}   # N",
              f"  weight: {fmt(self.weight)}   # N",
              f"  mooring_vertical: {fmt(self.mooring_vertical)}   # N, downward pull of the "
              f"lines at zero pose",
              f"  preload_vertical: {fmt(self.preload_vertical)}   # N, HydroDyn AddF0 Fz (up)",
              f"  imbalance: {fmt(self.imbalance)}   # N, buoyancy - weight - mooring + preload",
              f"  imbalance_fraction: {fmt(self.fraction)}   # of the buoyancy",
              f"  closes: {'true' if self.closes else 'false'}   # within "
              f"{100 * BUDGET_TOLERANCE:g} %"]
        return "\n".join(L) + "\n"


def mass_budget(items, *, volume, water_density, gravity, mooring_vertical=0.0,
                preload_vertical=0.0, suspects=()) -> MassBudget:
    m, c, I = combine(items)
    return MassBudget(items=tuple(items), mass=m, cog=c, inertia=I, volume=float(volume),
                      water_density=float(water_density), gravity=float(gravity),
                      mooring_vertical=float(mooring_vertical),
                      preload_vertical=float(preload_vertical), suspects=tuple(suspects))
