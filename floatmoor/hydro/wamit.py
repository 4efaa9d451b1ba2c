"""Reader of WAMIT numeric output files (.1, .3, .hst, .8/.9, .12d).

Nondimensionalisation (WAMIT manual, as read by OpenFAST HydroDyn WAMIT.f90), with L = ULEN:

* ``.1``  ``PER I J Abar [Bbar]``: A_ij = rho L^k Abar, B_ij = rho omega L^k Bbar, with k = 3 for
  i, j both translations, 5 for both rotations, 4 otherwise.  PER = -1 is the zero-frequency
  limit, PER = 0 the infinite-frequency limit (these rows carry no B).  Pairs that WAMIT omits
  are zero.
* ``.3``  ``PER BETA I |X| phase Re Im``: X_i = rho g A L^m Xbar, m = 2 forces, 3 moments.
  BETA in degrees, the direction the waves travel towards; WAMIT's convention is exp(+i w t),
  which is floatmoor's, so no conjugation.
* ``.hst`` ``I J Cbar``: C_ij = rho g L^k Cbar, k = 2 (3,3); 3 (3,4), (3,5); 4 rotations.
* ``.8``/``.9`` mean drift ``PER BETA1 BETA2 I |F| phase Re Im`` (or one BETA column):
  F = rho g A^2 L^m Fbar, m = 1 forces, 2 moments.
* ``.12d`` ``PER1 PER2 BETA1 BETA2 I |F| phase Re Im``: F = rho g A1 A2 L^m Fbar, m = 1, 2.
  WAMIT writes one triangle (PER1 <= PER2 or the reverse); the other follows from
  QTF(w2, w1) = conj(QTF(w1, w2)).  The diagonal w1 = w2, beta1 = beta2 is the mean drift.

Second-order data on a frequency grid other than the first-order one are interpolated
(linearly) onto the first-order grid inside their range and set to NaN outside (NaN means "not
available at this frequency"; consumers must not extrapolate silently).  The full QTF keeps its
own grid in dims ``qtf_omega``, ``qtf_omega_2``, ``qtf_wave_direction``.

Files may have CRLF line endings and a text header line (skipped).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from ..core.errors import FloatmoorWarning
from .database import DatabaseError, make_database

__all__ = ["read_wamit", "read_wamit_1", "read_wamit_3", "read_wamit_hst", "read_wamit_drift",
           "read_wamit_12d"]


def _k_matrix(i: int, j: int) -> int:
    """Length exponent for a 6x6 matrix pair (0-based indices) of A, B (+3)."""
    return 3 + (i >= 3) + (j >= 3)


def _load_table(path: Path, ncols: tuple[int, ...], what: str) -> np.ndarray:
    """Read numeric rows; skip a non-numeric header; raise naming the file and line."""
    if not path.exists():
        raise DatabaseError(path, what, f"an existing WAMIT file {path.name}", "no such file")
    text = path.read_text(errors="replace").replace("\r", "")
    rows = []
    maxc = max(ncols)
    lines = text.split("\n")
    last_data = max((k for k, ln in enumerate(lines, start=1) if ln.strip()), default=0)
    for n, line in enumerate(lines, start=1):
        parts = line.split()
        if not parts:
            continue
        try:
            vals = [float(p.replace("D", "E").replace("d", "e")) for p in parts]
        except ValueError:
            if not rows and n <= 3:  # header line ("WAMIT Numeric Output -- ...")
                continue
            raise DatabaseError(path, f"{what}, line {n}", "numbers only", line.strip()) from None
        if len(vals) not in ncols:
            raise DatabaseError(path, f"{what}, line {n}",
                                f"{' or '.join(map(str, ncols))} columns",
                                f"{len(vals)} columns: {line.strip()!r}",
                                "the file looks truncated" if n == last_data else None)
        rows.append(vals + [np.nan] * (maxc - len(vals)))
    if not rows:
        raise DatabaseError(path, what, "WAMIT numeric rows", "an empty file")
    return np.asarray(rows, float)


def _omega_from_period(per: np.ndarray) -> np.ndarray:
    return 2.0 * np.pi / per


def read_wamit_1(path, ulen: float = 1.0, rho: float = 1025.0):
    """Read a WAMIT ``.1`` file.

    Returns
    -------
    omega : (n,) rad/s increasing; A, B : (n, 6, 6) kg.. and N s/m..; A0, Ainf : (6, 6) or None.
    """
    path = Path(path)
    t = _load_table(path, (4, 5), "added mass and damping (.1)")
    per = t[:, 0]
    i = t[:, 1].astype(int) - 1
    j = t[:, 2].astype(int) - 1
    if np.any((i < 0) | (i > 5) | (j < 0) | (j > 5)):
        raise DatabaseError(path, "mode index I, J", "integers 1..6", sorted(set(i + 1) | set(j + 1)))
    scale = np.array([[rho * ulen ** _k_matrix(a, b) for b in range(6)] for a in range(6)])
    finite = per > 0
    if np.any(finite & np.isnan(t[:, 4])):
        n = int(np.argmax(finite & np.isnan(t[:, 4])))
        raise DatabaseError(path, "radiation damping", "5 columns (PER I J Abar Bbar) for PER > 0",
                            f"4 columns in data row {n + 1}")
    pers = np.unique(per[finite])[::-1]  # decreasing period = increasing omega
    omega = _omega_from_period(pers)
    n = pers.size
    A = np.zeros((n, 6, 6))
    B = np.zeros((n, 6, 6))
    index = {p: k for k, p in enumerate(pers)}
    pairs_per = [set() for _ in range(n)]
    for row, p in enumerate(per):
        if p <= 0:
            continue
        k = index[p]
        A[k, i[row], j[row]] = t[row, 3]
        B[k, i[row], j[row]] = t[row, 4]
        pairs_per[k].add((i[row], j[row]))
    # truncation: the file order is WAMIT's (one block per period); an incomplete block at the
    # end means a truncated file.
    sizes = np.array([len(s) for s in pairs_per])
    if n > 1 and sizes.max() > 0:
        typical = np.median(sizes)
        last = index[per[finite][-1]]
        if sizes[last] < typical:
            raise DatabaseError(path, "added mass and damping (.1)",
                                f"{int(typical)} (I, J) entries for every period",
                                f"{sizes[last]} entries for the last period "
                                f"{pers[last]:.6g} s", "the file looks truncated")
    A *= scale
    B *= scale * omega[:, None, None]
    A0 = Ainf = None
    for lim, name in ((-1, "zero"), (0, "inf")):
        sel = per == lim if lim == 0 else per < 0
        if np.any(sel):
            M = np.zeros((6, 6))
            M[i[sel], j[sel]] = t[sel, 3]
            M *= scale
            if name == "zero":
                A0 = M
            else:
                Ainf = M
    return omega, A, B, A0, Ainf


def read_wamit_3(path, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665):
    """Read a WAMIT ``.3`` (or ``.2``) excitation file.

    Returns
    -------
    omega : (n,) rad/s; beta : (m,) rad (direction of travel); X : (n, m, 6) complex, N/m, N m/m,
    convention exp(+i w t).
    """
    path = Path(path)
    t = _load_table(path, (7,), "excitation force (.3)")
    per, beta_deg, mode = t[:, 0], t[:, 1], t[:, 2].astype(int) - 1
    pers = np.unique(per[per > 0])[::-1]
    betas = np.unique(beta_deg)
    omega = _omega_from_period(pers)
    X = np.full((pers.size, betas.size, 6), np.nan + 0j)
    ip = {p: k for k, p in enumerate(pers)}
    ib = {b: k for k, b in enumerate(betas)}
    m = np.where(np.arange(6) >= 3, 3, 2)
    for row in range(t.shape[0]):
        if per[row] <= 0:
            continue
        X[ip[per[row]], ib[beta_deg[row]], mode[row]] = (t[row, 5] + 1j * t[row, 6])
    missing = np.isnan(X.real)
    if np.any(missing):
        # WAMIT omits modes that are exactly zero only for whole modes; a hole inside the table
        # (some periods or headings lacking) is a truncated or inconsistent file.
        present_modes = ~np.all(missing, axis=(0, 1))
        holes = missing[:, :, present_modes]
        if np.any(holes):
            k = np.argwhere(holes)[0]
            raise DatabaseError(path, "excitation force (.3)",
                                "one row per period, heading and mode",
                                f"no row for period {pers[k[0]]:.6g} s, heading "
                                f"{betas[k[1]]:g} deg", "the file looks truncated")
        X[missing] = 0.0
    X *= rho * g * ulen ** m
    return omega, np.radians(betas), X


def read_wamit_hst(path, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665) -> np.ndarray:
    """Read a WAMIT ``.hst`` file; returns the 6x6 restoring matrix (N/m, N, N m/rad)."""
    path = Path(path)
    t = _load_table(path, (3,), "hydrostatic stiffness (.hst)")
    C = np.zeros((6, 6))
    for a, b, c in t:
        C[int(a) - 1, int(b) - 1] = c * rho * g * ulen ** (_k_matrix(int(a) - 1, int(b) - 1) - 1)
    return C


def read_wamit_drift(path, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665):
    """Read a WAMIT mean-drift file ``.8`` (momentum) or ``.9`` (pressure integration).

    Returns omega (n,), beta (m,) rad, F (n, m, 6) N/m^2 and N m/m^2 (unidirectional only:
    BETA1 = BETA2).
    """
    path = Path(path)
    t = _load_table(path, (7, 8), "mean drift force")
    if np.all(np.isnan(t[:, 7])):  # PER BETA I |F| phase Re Im
        per, b1, b2, mode, re = t[:, 0], t[:, 1], t[:, 1], t[:, 2], t[:, 5]
    else:  # PER BETA1 BETA2 I |F| phase Re Im
        per, b1, b2, mode, re = t[:, 0], t[:, 1], t[:, 2], t[:, 3], t[:, 6]
    sel = (b1 == b2) & (per > 0)
    pers = np.unique(per[sel])[::-1]
    betas = np.unique(b1[sel])
    F = np.zeros((pers.size, betas.size, 6))
    ip = {p: k for k, p in enumerate(pers)}
    ib = {b: k for k, b in enumerate(betas)}
    m = np.where(np.arange(6) >= 3, 2, 1)
    for r in np.nonzero(sel)[0]:
        F[ip[per[r]], ib[b1[r]], int(mode[r]) - 1] = re[r]
    F *= rho * g * ulen ** m
    return _omega_from_period(pers), np.radians(betas), F


def read_wamit_12d(path, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665):
    """Read a WAMIT difference-frequency QTF file ``.12d`` (unidirectional part).

    Returns
    -------
    omega : (n,) rad/s; beta : (m,) rad; Q : (n, n, m, 6) complex, N/m^2 and N m/m^2, with
    Q[k, l] for (omega_k, omega_l), Hermitian completion Q[l, k] = conj(Q[k, l]).
    """
    path = Path(path)
    t = _load_table(path, (9,), "difference-frequency QTF (.12d)")
    p1, p2, b1, b2, mode = t[:, 0], t[:, 1], t[:, 2], t[:, 3], t[:, 4].astype(int) - 1
    sel = b1 == b2
    pers = np.unique(np.concatenate([p1[sel], p2[sel]]))[::-1]
    betas = np.unique(b1[sel])
    ip = {p: k for k, p in enumerate(pers)}
    ib = {b: k for k, b in enumerate(betas)}
    n = pers.size
    Q = np.full((n, n, betas.size, 6), np.nan + 0j)
    m = np.where(np.arange(6) >= 3, 2, 1)
    for r in np.nonzero(sel)[0]:
        a, b, c, d = ip[p1[r]], ip[p2[r]], ib[b1[r]], mode[r]
        val = t[r, 7] + 1j * t[r, 8]
        Q[a, b, c, d] = val
        if np.isnan(Q[b, a, c, d].real):
            Q[b, a, c, d] = np.conj(val)
    present = ~np.all(np.isnan(Q.real), axis=(0, 1, 2))
    holes = np.isnan(Q.real)[..., present]
    if np.any(holes):
        k = np.argwhere(holes)[0]
        raise DatabaseError(path, "difference-frequency QTF (.12d)",
                            "a value for every pair of periods (one triangle at least)",
                            f"nothing for periods {pers[k[0]]:.6g} s and {pers[k[1]]:.6g} s",
                            "the file looks truncated")
    Q[np.isnan(Q.real)] = 0.0
    Q *= rho * g * ulen ** m
    return _omega_from_period(pers), np.radians(betas), Q


def _onto_grid(omega_src, beta_src, F, omega, beta, what, path):
    """Linear interpolation in omega of (n_src, m_src, 6) data onto (omega, beta); NaN outside
    the source frequency range and at headings the source lacks."""
    out = np.full((omega.size, beta.size, 6), np.nan)
    for jb, b in enumerate(beta):
        hit = np.nonzero(np.isclose(beta_src, b, atol=1e-6))[0]
        if hit.size == 0:
            continue
        src = F[:, hit[0], :]
        inside = (omega >= omega_src[0] - 1e-9) & (omega <= omega_src[-1] + 1e-9)
        for d in range(6):
            out[inside, jb, d] = np.interp(omega[inside], omega_src, src[:, d])
    if np.all(np.isnan(out)):
        raise DatabaseError(path, what, "data overlapping the first-order frequencies and headings",
                            f"omega {omega_src[0]:.4g}..{omega_src[-1]:.4g} rad/s, headings "
                            f"{np.degrees(beta_src)} deg")
    return out


def read_wamit(root, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665, *,
               water_depth: float = np.inf, reference_point=(0.0, 0.0, 0.0)):
    """Read WAMIT output ``root.1``, ``root.3``, ``root.hst`` and mean drift into a database.

    Parameters
    ----------
    root : path without extension (``.../Spar`` for ``Spar.1``, ``Spar.3``, ``Spar.hst``).
    ulen : WAMIT length scale ULEN, m.
    rho : water density, kg/m^3.
    g : gravity, m/s^2.
    water_depth : m (metadata only); reference_point : body-frame point of the matrices, m.

    ``root.1`` is required.  ``root.3`` (else ``root.2``) gives the excitation; without it the
    database has no ``excitation_force`` (a warning says so).  ``root.hst`` gives the
    hydrostatic stiffness.  Mean drift: ``root.8`` (momentum) if present, else ``root.9``
    (pressure), else the diagonal of ``root.12d``; the QTF itself is kept when ``root.12d``
    exists.  Frequencies of ``.3`` must equal those of ``.1`` (a DatabaseError names both
    files otherwise).

    Returns
    -------
    xarray.Dataset in floatmoor's database form (exp(+i omega t)).
    """
    root = Path(root)
    base = str(root)
    f1 = Path(base + ".1")
    if not f1.exists():
        raise DatabaseError(f1, "added mass and damping (.1)", "an existing WAMIT .1 file",
                            "no such file", "read_wamit takes the root name without extension")
    omega, A, B, A0, Ainf = read_wamit_1(f1, ulen, rho)
    sources = [f1.name]
    X = beta = None
    for ext in (".3", ".2"):
        fx = Path(base + ext)
        if fx.exists():
            w3, beta, X = read_wamit_3(fx, ulen, rho, g)
            if w3.size != omega.size or not np.allclose(w3, omega, rtol=1e-5):
                raise DatabaseError(fx, "excitation force frequencies",
                                    f"the {omega.size} frequencies of {f1.name}",
                                    f"{w3.size} frequencies ({w3[0]:.4g}..{w3[-1]:.4g} rad/s)",
                                    "the frequency grids differ between the files")
            sources.append(fx.name)
            break
    else:
        warnings.warn(f"{base}.3: no excitation file; the database has no excitation_force",
                      FloatmoorWarning, stacklevel=2)
    C = None
    fh = Path(base + ".hst")
    if fh.exists():
        C = read_wamit_hst(fh, ulen, rho, g)
        sources.append(fh.name)
    drift = None
    qtf = None
    f12 = Path(base + ".12d")
    if f12.exists():
        qtf = read_wamit_12d(f12, ulen, rho, g)
        sources.append(f12.name)
    for ext in (".8", ".9"):
        fd = Path(base + ext)
        if fd.exists():
            drift = read_wamit_drift(fd, ulen, rho, g) + (fd,)
            sources.append(fd.name)
            break
    else:
        if qtf is not None:
            wq, bq, Q = qtf
            diag = np.stack([Q[k, k].real for k in range(wq.size)])
            drift = (wq, bq, diag, f12)
    if drift is not None and beta is None:
        beta = drift[1]
    mean_drift = None
    if drift is not None:
        mean_drift = _onto_grid(drift[0], drift[1], drift[2], omega, beta, "mean drift force",
                                drift[3])
    ds = make_database(omega, beta, added_mass=A, radiation_damping=B, excitation_force=X,
                       infinite_frequency_added_mass=Ainf, zero_frequency_added_mass=A0,
                       hydrostatic_stiffness=C, mean_drift_force=mean_drift,
                       rho=rho, g=g, water_depth=water_depth, reference_point=reference_point,
                       source="WAMIT " + ", ".join(sources))
    if qtf is not None:
        ds = add_qtf(ds, *qtf)
    ds.attrs["wamit_ulen"] = float(ulen)
    return ds


def add_qtf(ds, omega_q, beta_q, Q):
    """Attach a difference-frequency QTF on its own grid (dims ``qtf_omega``, ``qtf_omega_2``,
    ``qtf_wave_direction``, ``influenced_dof``) to a database."""
    ds = ds.assign_coords(qtf_omega=("qtf_omega", omega_q), qtf_omega_2=("qtf_omega_2", omega_q),
                          qtf_wave_direction=("qtf_wave_direction", beta_q))
    ds["difference_frequency_qtf"] = (("qtf_omega", "qtf_omega_2", "qtf_wave_direction",
                                       "influenced_dof"), Q)
    ds["difference_frequency_qtf"].attrs.update({
        "units": "N/m^2 (force), N m/m^2 (moment), per product of wave amplitudes",
        "long_name": "difference-frequency QTF Q(w1, w2), F = Re sum A1 A2 Q exp(i (w1 - w2) t)",
    })
    for c, ln in (("qtf_omega", "QTF first frequency"), ("qtf_omega_2", "QTF second frequency"),
                  ("qtf_wave_direction", "QTF wave heading (direction of travel)")):
        ds[c].attrs.update({"units": "rad" if "direction" in c else "rad/s", "long_name": ln})
    return ds
