"""The statistics table of ``floatmoor run``: most loaded lines first, and lines whose maxima
are equal as printed (mirror-image lines of a symmetric mooring, which differ by round-off
only) in the scene's line order, so that the table of the README's flagship command is the
same on every machine."""

import numpy as np
import xarray as xr

from floatmoor.commands.run import summary_table


def _seed_file(path, maxima_kn):
    """A seed file with four lines whose tensions peak at ``maxima_kn`` (kN) after the
    transient; the transient part holds a larger value that the table must ignore."""
    t = np.arange(0.0, 10.0, 1.0)
    T = np.full((t.size, len(maxima_kn)), 1000.0e3)
    T[2, :] = 9000.0e3  # inside the transient (t < 3 s)
    for i, m in enumerate(maxima_kn):
        T[6, i] = m * 1e3
    motion = np.zeros((t.size, 6))
    motion[:, 0] = np.linspace(0.0, 9.0, t.size)
    ds = xr.Dataset({"motion": (("time", "dof"), motion),
                     "line_tension": (("time", "line"), T)},
                    coords={"time": t, "line": ["line1", "line2", "line3", "line4"]},
                    attrs={"transient": 3.0})
    ds.to_netcdf(path)
    return path


def _order(table):
    return [row.split()[0] for row in table.splitlines()[3:]]


def test_lines_equal_as_printed_keep_the_scene_order(tmp_path):
    # line4 and line2 mirror each other: equal to 1e-9 kN, line4 larger by round-off
    files = [_seed_file(tmp_path / f"s{k}.nc", [2000.0, 2500.0, 1500.0, 2500.0 + 1e-9])
             for k in range(2)]
    table = summary_table(files, n_lines=3)
    assert _order(table) == ["line2", "line4", "line1"], table
    # the offset row after the transient: max 9 m, mean of 3..9 m
    off = table.splitlines()[2].split()
    assert off[:2] == ["offset", "(m)"] and float(off[4]) == 9.0 and float(off[2]) == 6.0


def test_lines_differing_as_printed_are_ordered_by_their_maximum(tmp_path):
    # 0.2 kN apart: printed differently, so the larger comes first whatever the line order
    files = [_seed_file(tmp_path / "s.nc", [2000.0, 2500.0, 1500.0, 2500.2])]
    assert _order(summary_table(files, n_lines=2)) == ["line4", "line2"]
