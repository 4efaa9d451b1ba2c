"""Build database.nc of the Floatel-like semi-submersible with Capytaine (optional dependency).

Geometry (parametric, survival draft 13 m), from Wang (2016) table 5.1, table 6.1 and
the drag widths of table 6.3 (D = C2 / (0.5 rho C_D)):

* two pontoons along y, centred at x = +-25.25 m, width 14.0 m (x), height 8.625 m
  (z = -13.0 .. -4.375 m: table 6.1 puts the pontoon axis at z = -8.6875 and the column
  bottoms at -4.375 m);
* four columns at (+-25.25, +-25.5) m, 14.0 m (x) by 12.5 m (y), from the pontoon tops to
  above the water line (only the wetted part z = -4.375 .. 0 is panelled);
* pontoon length 90 m (table 6.1 spans y = -45 .. 45 m; table 5.1's 64.5 m would give only
  19,000 t).  Displaced volume 2 x 14 x 8.625 x 90 + 4 x 14 x 12.5 x 4.375 = 24,797.5 m^3,
  i.e. 25,417 t at 1.025 t/m^3, 0.2 % below the survival displacement 25,472 t of table 5.1.

Computed: added mass, radiation damping, excitation (Froude-Krylov + diffraction) for
omega = 0.05 .. 2.50 rad/s step 0.025 (fine enough to resolve the sharp potential-flow
resonances of the water between the pontoons near 0.9 and 1.4 rad/s) and headings 0 .. 180 deg step 30 (the hull is symmetric
about both axes, so 180 .. 360 deg follow by symmetry; the data are mirrored here), water depth
150 m; hydrostatic stiffness from the mesh with the centre of mass put at the reference point
(so that it holds the waterplane and buoyancy terms only, like WAMIT's .hst); mean drift forces
in surge, sway and yaw from Capytaine's far-field (Maruo / Kochin function) formula
``capytaine.post_pro.mean_drift_force.far_field_mean_drift_force``, using the free-floating
motion RAOs of the vessel described in vessel.yaml (mass, CoG, radii of gyration, linear
damping; the mooring stiffness is neglected at wave frequencies).  Irregular frequencies are
removed with a lid on the column waterplanes.

Usage:  OMP_NUM_THREADS=1 python make_database.py [panel_size_m]   (about 15 min on one core)
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import capytaine as cpt
import numpy as np
import xarray as xr
from capytaine.post_pro.mean_drift_force import far_field_mean_drift_force

from floatmoor.core.config import Node
from floatmoor.hydro import from_capytaine_dataset, save_database
from floatmoor.hydro.vessel import gravity_stiffness, rigid_body_mass_matrix

HERE = Path(__file__).resolve().parent

# Known limits, stored as the database attribute ``limitations`` and printed with the
# consistency report (``floatmoor check``).
LIMITATIONS = (
    "frequency range ends at 2.5 rad/s, where the damping has not decayed (surge 5 %, sway 5 %, "
    "yaw 7 % of its peak): the retardation functions depend on the tail model and reproduce the "
    "database only to 8-16 % in sway, pitch and yaw (consistency report, band 0.2-2 rad/s). "
    "Extending to 4 rad/s needs panels of lambda/6-8 = 0.5-0.6 m there (lambda = 3.85 m), "
    "about 33,000 panels instead of 1,616: not feasible with a dense BEM solver here.\n"
    "the 2.5 m panels are lambda/6 only up to 2.0 rad/s and lambda/8 up to 1.75 rad/s; the "
    "values above 2 rad/s (e.g. the sway spike at 2.4 rad/s) are less reliable than below")
RHO, G, DEPTH = 1025.0, 9.80665, 150.0
PONTOON_X = 25.25
PONTOON_W, PONTOON_H, PONTOON_L = 14.0, 8.625, 90.0
Z_BOTTOM, Z_PONT_TOP = -13.0, -4.375
COL_X, COL_Y = 25.25, 25.5
COL_WX, COL_WY = 14.0, 12.5


def volume() -> float:
    """Displaced volume of the parametric hull, m^3."""
    return 2 * PONTOON_W * PONTOON_H * PONTOON_L + 4 * COL_WX * COL_WY * (-Z_PONT_TOP)


def quad_grid(origin, u, v, h):
    """Quads covering the parallelogram origin + s u + t v; normal along u x v."""
    origin, u, v = (np.asarray(a, float) for a in (origin, u, v))
    nu = max(1, math.ceil(np.linalg.norm(u) / h))
    nv = max(1, math.ceil(np.linalg.norm(v) / h))
    s = np.linspace(0, 1, nu + 1)
    t = np.linspace(0, 1, nv + 1)
    verts = origin + s[:, None, None] * u + t[None, :, None] * v
    verts = verts.reshape(-1, 3)
    idx = np.arange((nu + 1) * (nv + 1)).reshape(nu + 1, nv + 1)
    faces = np.stack([idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]], axis=-1)
    return verts, faces.reshape(-1, 4)


def box_walls(x0, x1, y0, y1, z0, z1, h, bottom=True, top_strips=None):
    """Outward-normal quads of a box; top_strips = list of (y0, y1) for the top face parts."""
    ex, ey, ez = np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([0, 0, 1.0])
    Lx, Ly, Lz = x1 - x0, y1 - y0, z1 - z0
    parts = [
        quad_grid((x0, y0, z0), Lz * ez, Ly * ey, h),   # x = x0, normal -x
        quad_grid((x1, y0, z0), Ly * ey, Lz * ez, h),   # x = x1, normal +x
        quad_grid((x0, y0, z0), Lx * ex, Lz * ez, h),   # y = y0, normal -y
        quad_grid((x0, y1, z0), Lz * ez, Lx * ex, h),   # y = y1, normal +y
    ]
    if bottom:
        parts.append(quad_grid((x0, y0, z0), Ly * ey, Lx * ex, h))  # normal -z
    for (ya, yb) in (top_strips or []):
        parts.append(quad_grid((x0, ya, z1), Lx * ex, (yb - ya) * ey, h))  # normal +z
    return parts


def hull_mesh(h=2.5):
    parts = []
    yL = PONTOON_L / 2
    yc0, yc1 = COL_Y - COL_WY / 2, COL_Y + COL_WY / 2
    for sx in (-1, 1):
        xc = sx * PONTOON_X
        strips = [(-yL, -yc1), (-yc0, yc0), (yc1, yL)]
        parts += box_walls(xc - PONTOON_W / 2, xc + PONTOON_W / 2, -yL, yL, Z_BOTTOM, Z_PONT_TOP,
                           h, bottom=True, top_strips=strips)
        for sy in (-1, 1):
            yc = sy * COL_Y
            parts += box_walls(xc - COL_WX / 2, xc + COL_WX / 2, yc - COL_WY / 2, yc + COL_WY / 2,
                               Z_PONT_TOP, 0.0, h, bottom=False)
    verts, faces, n = [], [], 0
    for v, f in parts:
        verts.append(v)
        faces.append(f + n)
        n += v.shape[0]
    return cpt.Mesh(np.concatenate(verts), np.concatenate(faces), name="floatel_like")


def lid_mesh(h=2.5):
    parts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            xc, yc = sx * COL_X, sy * COL_Y
            parts.append(quad_grid((xc - COL_WX / 2, yc - COL_WY / 2, -0.01), COL_WX * np.array([1.0, 0, 0]),
                                   COL_WY * np.array([0, 1.0, 0]), h))
    verts, faces, n = [], [], 0
    for v, f in parts:
        verts.append(v)
        faces.append(f + n)
        n += v.shape[0]
    return cpt.Mesh(np.concatenate(verts), np.concatenate(faces), name="lid")


def main(h=2.5, omegas=None, headings_deg=None, out=HERE / "database.nc"):
    t0 = time.time()
    omegas = np.round(np.arange(0.05, 2.5001, 0.025), 4) if omegas is None else np.asarray(omegas)
    headings_deg = np.arange(0.0, 180.1, 30.0) if headings_deg is None else np.asarray(headings_deg)
    mesh = hull_mesh(h)
    print(f"panels {mesh.nb_faces}, mesh volume {mesh.volume:.1f} m^3 (design {volume():.1f})",
          flush=True)
    body = cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh(h),
                            dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, 0)),
                            center_of_mass=(0, 0, 0), name="floatel_like")
    # hydrostatics with the CoG at the reference point: waterplane + buoyancy terms only
    C_hyd = np.asarray(body.compute_hydrostatic_stiffness(rho=RHO, g=G).values)
    theta = np.linspace(-2 * 2 * np.pi / 72, 2 * np.pi + 2 * 2 * np.pi / 72, 77)
    test = xr.Dataset(coords={"omega": omegas, "wave_direction": np.radians(headings_deg),
                              "radiating_dof": list(body.dofs), "water_depth": [DEPTH],
                              "rho": [RHO], "g": [G], "theta": theta})
    cds = cpt.BEMSolver().fill_dataset(test, body, hydrostatics=False)
    cds = cds.squeeze(drop=False)
    print(f"BEM done in {time.time() - t0:.0f} s", flush=True)
    # RAO in Capytaine's convention exp(-i w t): [-w^2 (M + A) - i w (B + B_lin) + C] xi = F
    vnode = Node.load(HERE / "vessel.yaml")
    m = vnode.float("mass")
    cog = vnode.array("centre_of_gravity", shape=(3,))
    Icg = np.diag(vnode.array("inertia_cg", shape=(3,)))
    Blin = vnode.array("linear_damping", shape=(6, 6))
    M = rigid_body_mass_matrix(m, cog, Icg)
    C = C_hyd + gravity_stiffness(m, cog, G)
    dofs = [str(d) for d in cds.radiating_dof.values]
    A = cds.added_mass.transpose("omega", "influenced_dof", "radiating_dof").sel(
        influenced_dof=dofs, radiating_dof=dofs).values
    B = cds.radiation_damping.transpose("omega", "influenced_dof", "radiating_dof").sel(
        influenced_dof=dofs, radiating_dof=dofs).values
    F = (cds.Froude_Krylov_force + cds.diffraction_force).transpose(
        "omega", "wave_direction", "influenced_dof").sel(influenced_dof=dofs).values
    xi = np.empty_like(F)
    for k, w in enumerate(omegas):
        Z = -w ** 2 * (M + A[k]) - 1j * w * (B[k] + Blin) + C
        xi[k] = np.linalg.solve(Z, F[k].T).T
    X = xr.DataArray(xi, dims=("omega", "wave_direction", "radiating_dof"),
                     coords={"omega": omegas, "wave_direction": cds.wave_direction.values,
                             "radiating_dof": dofs})
    drift = far_field_mean_drift_force(X, cds)
    md = np.zeros((omegas.size, headings_deg.size, 6))
    for name, k in (("drift_force_surge", 0), ("drift_force_sway", 1), ("drift_force_yaw", 5)):
        d = drift[name].values
        md[:, :, k] = np.real(np.diagonal(d, axis1=1, axis2=2))
    cds = cds.drop_vars([v for v in cds.data_vars if v.startswith("kochin")] +
                        ["theta"], errors="ignore")
    cds["hydrostatic_stiffness"] = (("influenced_dof", "radiating_dof"), C_hyd)
    ds = from_capytaine_dataset(cds, where="vessels/floatel_like/make_database.py")
    ds["mean_drift_force"] = (("omega", "wave_direction", "influenced_dof"), md)
    ds = mirror_headings(ds)
    ds = symmetrize(ds)
    ds.attrs["displaced_volume"] = float(mesh.volume)
    ds.attrs["mesh_panels"] = int(mesh.nb_faces)
    ds.attrs["limitations"] = LIMITATIONS
    ds.attrs["mean_drift_method"] = ("Capytaine far-field (Maruo/Kochin) formula with "
                                     "free-floating RAOs from vessel.yaml")
    ds.attrs["source"] = ("Capytaine " + cpt.__version__ + ", vessels/floatel_like/make_database.py, "
                          f"{mesh.nb_faces} panels + lid")
    from floatmoor.hydro.database import _set_attrs
    ds = _set_attrs(ds)
    save_database(ds, out)
    print(f"wrote {out} ({out.stat().st_size} bytes) in {time.time() - t0:.0f} s", flush=True)
    print("surge drift at 0 deg (N/m^2):", np.round(md[::6, 0, 0]))
    return ds


def symmetrize(ds):
    """Replace A and B by (X + X^T) / 2 (potential-flow reciprocity; the panel model's
    asymmetry, a discretisation error, is kept in the attribute ``max_asymmetry_removed``)."""
    worst = 0.0
    for v in ("added_mass", "radiation_damping"):
        X = ds[v].values
        d = np.max(np.abs(np.diagonal(X, axis1=1, axis2=2)), axis=0)
        scale = np.sqrt(np.outer(d, d))
        scale[scale == 0] = np.inf
        worst = max(worst, float(np.max(np.abs(X - np.swapaxes(X, 1, 2)) / scale)))
        ds[v] = (ds[v].dims, 0.5 * (X + np.swapaxes(X, 1, 2)), ds[v].attrs)
    ds.attrs["max_asymmetry_removed"] = worst
    return ds


def mirror_headings(ds):
    """Extend headings 0..180 deg to 0..330 deg using the symmetry about the x axis (y -> -y):
    X(-beta) has sway, roll and yaw negated; drift likewise."""
    beta = ds.wave_direction.values
    new = [b for b in beta if 1e-9 < b < np.pi - 1e-9]
    if not new:
        return ds
    sign = xr.DataArray([1, -1, 1, -1, 1, -1], dims="influenced_dof",
                        coords={"influenced_dof": ds.influenced_dof.values})
    part = ds[["excitation_force", "mean_drift_force"]].sel(wave_direction=new[::-1])
    part = (part * sign).assign_coords(wave_direction=2 * np.pi - np.asarray(new[::-1]))
    rest = ds.drop_vars(["excitation_force", "mean_drift_force"])
    both = xr.concat([ds[["excitation_force", "mean_drift_force"]], part], dim="wave_direction")
    out = rest.assign_coords(wave_direction=both.wave_direction)
    out["excitation_force"] = both.excitation_force
    out["mean_drift_force"] = both.mean_drift_force
    out.attrs = ds.attrs
    return out


if __name__ == "__main__":
    h = float(sys.argv[1]) if len(sys.argv) > 1 else 2.5
    main(h)
