"""Per-seed design statistics beyond the fairlead tension: anchors, fibre ropes, offsets, points.

:func:`seed_design_statistics` reads one seed's result (``motion(time, dof)``,
``line_tension(time, line)``, ``anchor_tension(time, line)``; finite-element lines add
``grounded_length(time, line)``) in its statistics window and returns, per line, limit and
point, the quantities whose seed maxima (or minima) the design checks of
:mod:`floatmoor.post.design_checks` take their characteristic values from, as they take the
characteristic tension from the seed maxima of the fairlead tension:

* anchors: the maximum and mean anchor tension (as the run recorded it); the largest horizontal
  and vertical anchor force and uplift angle ``atan(V_a / H_a)``; the smallest grounded length
  and the grounded length at the sample of the largest offset;
* fibre rope segments: the smallest tension of the rope (at the lower end of its lowest rope
  segment) and the largest length of rope on the seabed;
* offsets: the largest horizontal offset and, per offset limit, the largest ratio of the
  offset to the limit in its direction (:mod:`floatmoor.io.limits_section`);
* named points: the largest horizontal excursion and the largest upward and downward
  excursion from the point's position at zero pose.

How the line quantities are found
---------------------------------
The anchor force components, the grounded length and the rope tensions are those of the
quasi-static elastic catenary of each line at the recorded pose -- the model that produced the
fairlead tension of a quasi-static line, so exact for it (the fairlead tension recomputed there
is compared with the recorded one: a difference above ``1e-4`` of it means the mooring file
changed since the run, a SceneError).  They are evaluated at candidate samples, not at every
one: per line the ``n_candidates`` largest separated peaks (10 s apart) of the anchor tension
and of the horizontal fairlead-anchor distance (the tautest states: largest uplift, smallest
grounded length), the ``n_candidates`` smallest of that distance and of the fairlead tension
(the slackest: least rope tension, most rope on the seabed) and the sample of the largest
offset.  ``tests/post/test_design_statistics.py`` checks this against every sample of a run.
For finite-element lines the grounded length is the line's own record (every sample) and the
anchor force components and rope tensions are the quasi-static ones at the recorded pose (the
report says so); for quasi-static lines with fibre segments tracked about a slowly varying mean
tension, the static working-curve catenary at the pose (likewise said, and not compared with the
recorded tension).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError
from .capacity import is_fibre

__all__ = ["TOLERANCE", "candidate_samples", "points_earth", "seed_design_statistics"]

TOLERANCE = 1e-4
"""Largest relative difference between the recorded and the recomputed fairlead tension of a
quasi-static line (exact solver path) before the mooring file is taken to have changed."""

TOLERANCE_APPROX = 2e-2
"""The same with the opt-in predictor catenary of the time loop (``solver: {catenary:
predictor}``), which is within about 1e-3 of the exact solve."""


def points_earth(motion, points) -> np.ndarray:
    """Earth coordinates (n_t, n_points, 3) of body points (n_points, 3) at the poses
    ``motion`` (n_t, 6): ``x + R r`` with ``R = Rz(yaw) Ry(pitch) Rx(roll)``
    (:mod:`floatmoor.core.frames`), vectorised over time."""
    m = np.asarray(motion, float)
    r = np.asarray(points, float).reshape(-1, 3)
    cr, sr = np.cos(m[:, 3]), np.sin(m[:, 3])
    cp, sp = np.cos(m[:, 4]), np.sin(m[:, 4])
    cy, sy = np.cos(m[:, 5]), np.sin(m[:, 5])
    R = np.empty((m.shape[0], 3, 3))
    R[:, 0, 0] = cy * cp
    R[:, 0, 1] = cy * sp * sr - sy * cr
    R[:, 0, 2] = cy * sp * cr + sy * sr
    R[:, 1, 0] = sy * cp
    R[:, 1, 1] = sy * sp * sr + cy * cr
    R[:, 1, 2] = sy * sp * cr - cy * sr
    R[:, 2, 0] = -sp
    R[:, 2, 1] = cp * sr
    R[:, 2, 2] = cp * cr
    return m[:, None, :3] + np.einsum("tij,pj->tpi", R, r)


def _peaks(x, k: int, sep: int, largest: bool = True) -> list[int]:
    """Indices of the ``k`` largest (or smallest) local extrema of ``x`` at least ``sep``
    samples apart (greedy from the largest; the ends count as extrema)."""
    y = np.asarray(x, float) if largest else -np.asarray(x, float)
    y = np.where(np.isfinite(y), y, -np.inf)
    if y.size < 3:
        idx = np.arange(y.size)
    else:
        inner = np.flatnonzero((y[1:-1] >= y[:-2]) & (y[1:-1] > y[2:])) + 1
        idx = np.concatenate([[0], inner, [y.size - 1]])
    order = idx[np.argsort(-y[idx], kind="stable")]
    out: list[int] = []
    taken = np.zeros(y.size, bool)
    for i in order:
        if len(out) >= k or not np.isfinite(y[i]):
            break
        if taken[i]:
            continue
        out.append(int(i))
        taken[max(0, i - sep):i + sep + 1] = True
    return out


def candidate_samples(distance, tension, anchor, offset, *, k: int, sep: int) -> np.ndarray:
    """Sorted sample indices of the candidate states (see the module docstring): per line
    (columns of ``distance``, ``tension``, ``anchor``) the ``k`` largest separated peaks of the
    anchor tension and of the fairlead-anchor distance, the ``k`` smallest of the distance and
    of the fairlead tension; and the largest offset."""
    idx = {int(np.argmax(offset))} if offset.size else set()
    for i in range(distance.shape[1]):
        idx.update(_peaks(anchor[:, i], k, sep))
        idx.update(_peaks(distance[:, i], k, sep))
        idx.update(_peaks(distance[:, i], k, sep, largest=False))
        idx.update(_peaks(tension[:, i], k, sep, largest=False))
    return np.array(sorted(idx), int)


def _rope_bounds(mooring):
    """Per line: (index of the lowest fibre segment or -1, unstretched length below it, the
    submerged weight (and point loads) above its lower end)."""
    out = []
    for line in mooring.lines:
        segs = line.segments
        ks = [k for k, s in enumerate(segs) if is_fibre(mooring, s)]
        if not ks:
            out.append((-1, 0.0, 0.0))
            continue
        k = ks[0]
        below = float(sum(s.length for s in segs[:k]))
        # the weight hanging from just above its lower end: the segments from it up, and the
        # point loads at the joints above (a segment's point load acts at its upper joint; the
        # fairlead segment's is ignored, as in the catenary)
        w_above = float(sum(s.w * s.length for s in segs[k:]))
        w_above += float(sum(s.point_load for s in segs[k:len(segs) - 1]))
        out.append((k, below, w_above))
    return out


def _state_of(mooring, pose, ropes, nl):
    """Per-line H_a, V_a, grounded length, uplift angle, rope tension and rope on the seabed of
    the quasi-static catenary at ``pose`` (arrays in the order of :func:`seed_design_statistics`'
    cache: 0 H_a, 1 V_a, 2 grounded length, 4 uplift, 5 rope tension, 6 rope on the seabed)."""
    r = mooring.tensions(pose)
    ha = r["horizontal_anchor"].values
    va = r["vertical_anchor"].values
    hf = r["horizontal_fairlead"].values
    vf = r["vertical_fairlead"].values
    lb = r["grounded_length"].values
    up = np.where(ha > 0, np.degrees(np.arctan2(np.maximum(va, 0.0), np.where(ha > 0, ha, 1.0))),
                  np.where(va > 0, 90.0, 0.0))
    rope_t = np.full(nl, np.nan)
    rope_bed = np.full(nl, np.nan)
    for j, (k, below, w_above) in enumerate(ropes):
        if k >= 0:
            rope_t[j] = math.hypot(hf[j], max(vf[j] - w_above, 0.0))
            rope_bed[j] = max(0.0, lb[j] - below)
    return (ha, va, lb, r["fairlead_tension"].values, up, rope_t, rope_bed)


def _gradients(mooring, pose, *, state_at, step: float = 0.5) -> dict:
    """d q / d h and d q / d v per line (arrays (2, n_lines)) of each quantity q of
    :func:`_state_of`, from central differences of the surge, sway and heave about ``pose``
    (least squares per line: a pose change moves a line's fairlead by e.dx horizontally)."""
    n = mooring.n_lines
    base_fl = points_earth(pose[None], mooring.fairleads)[0]
    d = base_fl[:, :2] - mooring.anchors[:, :2]
    e = d / np.linalg.norm(d, axis=1)[:, None]
    diffs = {}
    moves = []
    for k in range(3):
        dp = np.zeros(6)
        dp[k] = step
        plus, minus = state_at(pose + dp), state_at(pose - dp)
        moves.append(dp[:3])
        for q in (0, 1, 2, 4, 5, 6):
            diffs.setdefault(q, []).append((np.asarray(plus[q]) - np.asarray(minus[q]))
                                           / (2 * step))
    out = {}
    for q, rows in diffs.items():
        g = np.full((2, n), np.nan)
        dq = np.array(rows)                                     # (3 moves, n lines)
        for j in range(n):
            # move k changes h by e_j . dx_k and v by dz_k (per unit step)
            M = np.array([[e[j] @ m[:2], m[2]] for m in moves]) / step
            if np.all(np.isfinite(dq[:, j])):
                g[:, j] = np.linalg.lstsq(M, dq[:, j], rcond=None)[0]
        out[q] = g
    return out


def seed_design_statistics(ds, mooring, *, start: float | None = None, end: float | None = None,
                           limits=None, n_candidates: int = 6, failed=(),
                           tolerance: float | None = None) -> dict:
    """The design statistics of one seed (see the module docstring).

    Parameters
    ----------
    ds : xarray.Dataset
        One seed's result (``time``, ``motion``, ``line_tension``, ``anchor_tension``; FE lines
        ``line_model`` and ``grounded_length``).
    mooring : MooringSystem
        The scene's mooring (all lines; the lines are evaluated one by one).
    start, end : float, optional
        The statistics window, s (default the whole record).
    limits : LimitsSpec, optional
        Offset limits and named points of the scene.
    n_candidates : int
        Candidate peaks per line and kind.
    failed : names of lines failed in this seed (left out; also a line whose recorded tension
        is zero at the last sample).
    tolerance : float, optional
        Largest relative difference of the recomputed fairlead tension of a quasi-static line
        (default :data:`TOLERANCE`, or :data:`TOLERANCE_APPROX` with a predictor solver).

    Returns
    -------
    dict
        ``line`` (names), per line arrays ``anchor_tension_max``, ``anchor_tension_mean``,
        ``anchor_h_max``, ``anchor_v_max``, ``uplift_deg_max``, ``grounded_length_min``,
        ``grounded_length_at_max_offset``, ``rope_tension_min``, ``rope_seabed_length_max``
        (N, m, deg; NaN where not applicable), ``line_model`` ("quasi-static" or
        "finite-element"), ``recompute_difference`` (relative, NaN where not compared);
        ``offset_max`` (m); per offset limit ``offset_ratio_max``; per point
        ``point_horizontal_max``, ``point_up_max``, ``point_down_max`` (m); ``n_evaluated``.
    """
    t = np.asarray(ds["time"].values, float)
    sel = np.ones(t.size, bool)
    if start is not None:
        sel &= t >= start - 1e-9
    if end is not None:
        sel &= t <= end + 1e-9
    if sel.sum() < 2:
        raise SceneError(ds.attrs.get("source_file"), "time",
                         "at least 2 samples in the statistics window", int(sel.sum()))
    t = t[sel]
    names = [str(v) for v in ds["line"].values]
    m_names = [str(v) for v in mooring.names]
    if names != m_names:
        raise SceneError(mooring.source or None, "lines", f"the lines of the results {names}",
                         m_names, "the mooring file changed since the run: run the seeds "
                         "again")
    motion = np.asarray(ds["motion"].values, float)[sel]
    T = np.asarray(ds["line_tension"].values, float)[sel]
    A = (np.asarray(ds["anchor_tension"].values, float)[sel] if "anchor_tension" in ds
         else np.full(T.shape, np.nan))
    model = (np.asarray(ds["line_model"].values).astype(str) if "line_model" in ds
             else np.array(["quasi-static"] * len(names)))
    fe = model == "finite-element"
    dead = set(map(str, failed)) | {n for n, v in zip(names, T[-1]) if v <= 0.0}
    alive = np.array([n not in dead for n in names])
    nl = len(names)
    dt = float(np.median(np.diff(t))) if t.size > 1 else 1.0
    sep = max(1, int(round(10.0 / dt)))
    fl_body = np.asarray(mooring.fairleads, float)
    fl = points_earth(motion, fl_body)                               # (n_t, n_lines, 3)
    dist = np.hypot(fl[:, :, 0] - mooring.anchors[None, :, 0],
                    fl[:, :, 1] - mooring.anchors[None, :, 1])
    offset = np.hypot(motion[:, 0], motion[:, 1])
    i_off = int(np.argmax(offset))
    cand = candidate_samples(np.where(alive[None, :], dist, np.nan),
                             np.where(alive[None, :], T, np.nan),
                             np.where(alive[None, :], A, np.nan), offset,
                             k=n_candidates, sep=sep)
    solver = str(ds.attrs.get("solver", ""))
    tol = tolerance if tolerance is not None else (TOLERANCE_APPROX if "predictor" in solver
                                                   else TOLERANCE)
    fibre_line = np.array([any(s.fibre is not None for s in ln.segments)
                           for ln in mooring.lines])
    compare = alive & ~fe & ~fibre_line
    ropes = _rope_bounds(mooring)
    out = {k: np.full(nl, np.nan) for k in (
        "anchor_tension_max", "anchor_tension_mean", "anchor_h_max", "anchor_v_max",
        "uplift_deg_max", "grounded_length_min", "grounded_length_at_max_offset",
        "rope_tension_min", "rope_seabed_length_max", "recompute_difference")}
    out["anchor_tension_max"] = np.where(alive, A.max(axis=0), np.nan)
    out["anchor_tension_mean"] = np.where(alive, A.mean(axis=0), np.nan)
    worst = np.zeros(nl)
    cache: dict = {}

    def state(i):
        """The quasi-static line states at sample i (cached, :func:`_state_of`)."""
        if i not in cache:
            cache[i] = _state_of(mooring, motion[i], ropes, nl)
        return cache[i]

    def climb(i, j, q, sign):
        """Follow quantity q of line j from sample i to its local extremum (sign +1: maximum,
        -1: minimum), one sample at a time."""
        best = sign * state(i)[q][j]
        while True:
            moved = False
            for nb in (i - 1, i + 1):
                if 0 <= nb < t.size:
                    v = sign * state(nb)[q][j]
                    if v > best + 1e-12 * abs(best):
                        best, i, moved = v, nb, True
                        break
            if not moved:
                return sign * best

    for i in cand:
        ha, va, lb, tf, up, rope_t, rope_bed = state(i)
        for j in np.flatnonzero(compare):
            rec = T[i, j]
            if rec > 0:
                worst[j] = max(worst[j], abs(tf[j] - rec) / rec)
    # per line and quantity: rank every sample by the quantity's linear estimate in the
    # fairlead's horizontal distance h and height v above the anchor (the catenary of a line
    # depends on nothing else; the gradient by differences of the surge, sway and heave about
    # the median pose), evaluate the best-ranked samples and the candidates exactly, then
    # follow the best few to their local extremum
    quantities = ((0, 1, "anchor_h_max"), (1, 1, "anchor_v_max"), (4, 1, "uplift_deg_max"),
                  (2, -1, "grounded_length_min"), (5, -1, "rope_tension_min"),
                  (6, 1, "rope_seabed_length_max"))
    h_t = dist
    v_t = fl[:, :, 2] - mooring.anchors[None, :, 2]
    grads = _gradients(mooring, np.median(motion, axis=0), state_at=lambda p: _state_of(
        mooring, p, ropes, nl))
    for j in np.flatnonzero(alive):
        for q, sign, key in quantities:
            if (q == 2 or q == 6) and fe[j]:
                continue                    # the FE line's own record (below)
            gh, gv = grads[q][:, j]
            extra = []
            if np.isfinite(gh) and np.isfinite(gv) and (gh != 0 or gv != 0):
                score = sign * (gh * h_t[:, j] + gv * v_t[:, j])
                extra = _peaks(score, n_candidates, sep)
            pool = np.unique(np.concatenate([cand, np.asarray(extra, int)]))
            vals = np.array([state(i)[q][j] for i in pool])
            if not np.isfinite(vals).any():
                continue
            order = np.argsort(-np.where(np.isfinite(vals), sign * vals, -np.inf))
            best = max(sign * climb(int(pool[k]), j, q, sign) for k in order[:3])
            out[key][j] = sign * best
        if not fe[j]:
            out["grounded_length_at_max_offset"][j] = state(i_off)[2][j]
    out["n_evaluated"] = len(cache)
    out["recompute_difference"] = np.where(compare, worst, np.nan)
    bad = np.flatnonzero(compare & (worst > tol))
    if bad.size:
        j = int(bad[np.argmax(worst[bad])])
        raise SceneError(mooring.source or None, f"lines.{names[j]}",
                         "the mooring the results were computed with (its catenary at the "
                         "recorded pose gives the recorded fairlead tension)",
                         f"a fairlead tension {100 * worst[j]:.3g} % off the recorded one "
                         f"(seed {ds.attrs.get('seed', '?')})",
                         "the mooring file changed since the run (line lengths, anchors, "
                         "line types): run the seeds again with the current file")
    if "grounded_length" in ds and fe.any():
        g = np.asarray(ds["grounded_length"].values, float)[sel]
        for j in np.flatnonzero(fe & alive):
            out["grounded_length_min"][j] = float(np.nanmin(g[:, j]))
            out["grounded_length_at_max_offset"][j] = float(g[i_off, j])
            k, below, _ = ropes[j]
            if k >= 0:
                out["rope_seabed_length_max"][j] = float(max(0.0, np.nanmax(g[:, j]) - below))
    out["line"] = names
    out["line_model"] = model
    out["offset_max"] = float(offset.max())
    direction = np.arctan2(motion[:, 1], motion[:, 0])
    if limits is not None and limits.offset:
        out["offset_limit"] = [o.name for o in limits.offset]
        out["offset_ratio_max"] = np.array(
            [float(np.max(offset / o.limit_at(direction))) for o in limits.offset])
    if limits is not None and limits.points:
        pts = np.array([p.position for p in limits.points], float)
        pe = points_earth(motion, pts)
        d = pe - pts[None]
        out["point"] = [p.name for p in limits.points]
        out["point_horizontal_max"] = np.hypot(d[:, :, 0], d[:, :, 1]).max(axis=0)
        out["point_up_max"] = np.maximum(d[:, :, 2].max(axis=0), 0.0)
        out["point_down_max"] = np.maximum(-d[:, :, 2].min(axis=0), 0.0)
    return out


_STORED = {"anchor_tension_mean": ("N", "mean anchor tension"),
           "anchor_h_max": ("N", "largest horizontal anchor force (quasi-static at the pose)"),
           "anchor_v_max": ("N", "largest vertical (upward) anchor force (quasi-static at the "
                            "pose)"),
           "uplift_deg_max": ("deg", "largest line angle above the seabed at the anchor"),
           "grounded_length_min": ("m", "smallest length of line on the seabed"),
           "grounded_length_at_max_offset": ("m", "length of line on the seabed at the largest "
                                             "offset"),
           "rope_tension_min": ("N", "smallest tension of the fibre rope"),
           "rope_seabed_length_max": ("m", "largest length of fibre rope on the seabed")}


def add_design_statistics(out, ds, mooring, *, start, limits=None, failed=()) -> None:
    """Add a storm's design statistics (:func:`seed_design_statistics`) to ``out`` (the stored
    form of a campaign storm) as ``design_<name>`` variables over ``line``,
    ``offset_limit`` and ``point``.  Never raises: a storm's result is kept when its design
    statistics cannot be made (the attribute ``design_statistics_error`` says why, and the
    campaign report does not check what they would have given)."""
    try:
        st = seed_design_statistics(ds, mooring, start=start, limits=limits, failed=failed)
    except Exception as exc:  # noqa: BLE001 - the storm itself is good; say why, go on
        out.attrs["design_statistics_error"] = f"{type(exc).__name__}: {exc}"
        return
    for k, (u, ln) in _STORED.items():
        out[f"design_{k}"] = (("line",), np.asarray(st[k], float),
                              {"units": u, "long_name": f"{ln} (after the transient)"})
    if "offset_ratio_max" in st:
        out.coords["offset_limit"] = ("offset_limit", list(st["offset_limit"]))
        out["design_offset_ratio_max"] = (("offset_limit",), st["offset_ratio_max"],
                                          {"units": "1", "long_name": "largest ratio of the "
                                           "offset to the limit in its direction"})
    if "point_horizontal_max" in st:
        out.coords["point"] = ("point", list(st["point"]))
        for k in ("point_horizontal_max", "point_up_max", "point_down_max"):
            out[f"design_{k}"] = (("point",), st[k],
                                  {"units": "m", "long_name": k.replace("_", " ")
                                   + " excursion of the point from zero pose"})
    out.attrs["design_statistics_states"] = int(st["n_evaluated"])
