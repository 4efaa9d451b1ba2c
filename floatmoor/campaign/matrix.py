"""The case matrix of a campaign and the scene of one case.

A case is one sea state, one heading of each environment component and one mooring condition;
its storms are the campaign's seeds.  :func:`case_scene` derives the case's scene from the
base scene by replacing the sea state and the headings (``dataclasses.replace`` on the frozen
scene), and names the lines to remove (``failed`` condition) or adds the ``forces:
line_failure`` time (``transient`` condition).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from .spec import CampaignSpec, Condition, SeaState

__all__ = ["Case", "build_matrix", "case_scene"]


def _deg_tag(x: float) -> str:
    """An angle as a file-name-safe tag: ``015p0`` for 15 deg (0.1 deg steps, as before), with
    up to three decimals when finer (``000p04``), ``m030p0`` for -30 deg (an offset)."""
    v = x % 360.0 if x >= 0 else x
    if abs(round(v, 1) - v) < 1e-9:
        s = f"{v:05.1f}" if x >= 0 else f"{v:+06.1f}"
    else:
        s = (f"{v:07.3f}" if x >= 0 else f"{v:+08.3f}").rstrip("0")
    return s.replace(".", "p").replace("-", "m").replace("+", "")


@dataclass(frozen=True, kw_only=True)
class Case:
    """One case of the matrix (headings in degrees, direction of travel)."""
    index: int
    sea_state_index: int
    sea_state: SeaState
    wave_heading_deg: float
    wind_heading_deg: float
    current_heading_deg: float
    condition: Condition

    @property
    def id(self) -> str:
        """A file-name-safe identifier, unique in the campaign."""
        w = self.wave_heading_deg
        return (f"ss{self.sea_state_index + 1}_h{_deg_tag(w)}"
                f"_wi{_deg_tag(self.wind_heading_deg - w)}"
                f"_cu{_deg_tag(self.current_heading_deg - w)}_{self.condition.name}")

    @property
    def limit_state(self) -> str:
        return self.condition.limit_state

    def row(self) -> dict:
        """The case's parameters as a flat mapping (manifest columns)."""
        c = self.condition
        return {"case": self.id, "sea_state": self.sea_state.name, "hs": self.sea_state.hs,
                "tp": self.sea_state.tp, "wave_heading_deg": self.wave_heading_deg,
                "wind_heading_deg": self.wind_heading_deg,
                "current_heading_deg": self.current_heading_deg, "condition": c.name,
                "limit_state": c.limit_state}


def build_matrix(spec: CampaignSpec) -> list[Case]:
    """Every case: sea states x wave headings x wind offsets x current offsets x conditions.

    Case identifiers name the result files, so two cases with one identifier would overwrite
    each other's results: a collision is a SceneError naming the campaign file and both cases
    (:func:`floatmoor.campaign.spec.load_campaign` refuses repeated directions, sea states
    and conditions first, so this is a last guard)."""
    from ..core.errors import SceneError
    out = []
    seen: dict[str, Case] = {}
    for i, ss in enumerate(spec.sea_states):
        for w in spec.wave_headings_deg:
            for dw in spec.wind_offsets_deg:
                for dc in spec.current_offsets_deg:
                    for c in spec.conditions:
                        case = Case(index=len(out), sea_state_index=i, sea_state=ss,
                                    wave_heading_deg=w, wind_heading_deg=w + dw,
                                    current_heading_deg=w + dc, condition=c)
                        other = seen.get(case.id)
                        if other is not None:
                            raise SceneError(spec.file, "headings", "cases with distinct "
                                             "identifiers (each names its result files)",
                                             f"{case.id} twice", f"case {other.index + 1} "
                                             f"{other.row()} and case {case.index + 1} "
                                             f"{case.row()}")
                        seen[case.id] = case
                        out.append(case)
    return out


def case_scene(base, case: Case, analysis: dict | None = None):
    """(scene, failed_lines) of ``case`` derived from the base :class:`~floatmoor.io.scene.Scene`.

    The base scene's wave spectrum keeps its type and discretisation; Hs, Tp and gamma come
    from the sea state.  A sea state of several wave systems replaces the base scene's waves
    by its systems (discretisation kept), each turned by the case's wave heading; a base scene
    of several systems needs such sea states (SceneError otherwise).  Components absent from
    the base scene stay absent.  ``analysis`` overrides the base scene's ``analysis`` fields
    (duration, dt, transient, ramp).
    """
    from ..core.errors import SceneError
    from ..metocean.config import WaveSpec, WaveSystems
    from . import _api

    env = base.environment
    rep = {}
    heading = math.radians(case.wave_heading_deg)
    ss = case.sea_state
    if env.waves is not None and ss.systems:
        w = env.waves
        rep["waves"] = WaveSystems(
            systems=tuple(dataclasses.replace(s, heading=heading + s.heading)
                          for s in ss.systems), names=tuple(ss.system_names),
            omega_min=w.omega_min, omega_max=w.omega_max, n_frequencies=w.n_frequencies,
            random_amplitudes=w.random_amplitudes)
    elif env.waves is not None and not isinstance(env.waves, WaveSpec):
        raise SceneError(base.file, "environment.waves", "one sea state in the base scene of a "
                         "campaign whose sea states are Hs and Tp (or sea states given as "
                         "systems: for a base scene of several wave systems)",
                         f"{len(env.waves.systems)} wave systems",
                         hint=f"sea state {ss.name!r}")
    elif env.waves is not None:
        rep["waves"] = dataclasses.replace(env.waves, hs=ss.hs, tp=ss.tp, gamma=ss.gamma,
                                           heading=heading)
    if env.wind is not None:
        rep["wind"] = dataclasses.replace(env.wind, heading=math.radians(case.wind_heading_deg))
    if env.current is not None:
        rep["current"] = dataclasses.replace(env.current,
                                             heading=math.radians(case.current_heading_deg))
    env = dataclasses.replace(env, **rep)
    changes = {"environment": env, "name": f"{base.name}:{case.id}"}
    if analysis:
        changes["analysis"] = dataclasses.replace(base.analysis, **analysis)
    c = case.condition
    if c.fibre_bound:
        changes["analysis"] = dataclasses.replace(changes.get("analysis", base.analysis),
                                                  fibre_stiffness=c.fibre_bound)
    failed = None
    if c.kind == "failed":
        failed = list(c.lines)
    elif c.kind == "transient":
        forces = base.forces if base.forces is not None else _api.forces_spec()()
        lf = dict(forces.line_failure)
        lf.update({ln: float(c.break_time) for ln in c.lines})
        changes["forces"] = dataclasses.replace(forces, line_failure=lf)
    return dataclasses.replace(base, **changes), failed
