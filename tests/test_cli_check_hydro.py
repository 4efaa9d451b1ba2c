"""``floatmoor check`` prints the hydrodynamic consistency report of the scene's vessel
database; ``--quick`` skips it."""

from pathlib import Path

import pytest

from floatmoor.cli import main
from floatmoor.hydro import consistency_report, load_vessel

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
VESSEL = ROOT / "vessels" / "floatel_like" / "vessel.yaml"


def _rows(out):
    rows = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 6 and "-" in parts[0] and parts[0].split("-")[0] in (
                "surge", "sway", "heave", "roll", "pitch", "yaw"):
            rows[parts[0]] = [float(p) for p in parts[1:]]
    return rows


def test_check_prints_the_consistency_report(capsys):
    assert main(["check", str(SCENE)]) == 0
    captured = capsys.readouterr()
    out = captured.out
    assert "Retardation-function consistency" in out
    assert out.rstrip().endswith(f"{SCENE}: OK")
    # the report comes after the vessel line and before the mooring line
    assert out.index("vessel file read") < out.index("Retardation-function") < \
        out.index("mooring read")
    # the printed errors are those of consistency_report on the same database (independent call)
    with pytest.warns(Warning):
        rep = consistency_report(load_vessel(VESSEL).database)
    rows = _rows(out)
    for name, i in (("surge", 0), ("heave", 2), ("yaw", 5)):
        err_a, err_b = rows[f"{name}-{name}"][:2]
        assert err_a == pytest.approx(100 * float(rep.max_rel_error_added_mass[i, i]), abs=1e-3)
        assert err_b == pytest.approx(100 * float(rep.max_rel_error_damping[i, i]), abs=1e-3)
    # every diagonal pair is listed
    for name in ("surge", "sway", "heave", "roll", "pitch", "yaw"):
        assert f"{name}-{name}" in rows
    # the database's warnings (undecayed damping at 2.5 rad/s) are printed once, in the report
    assert "warnings:" in out and "has not decayed" in out
    assert "has not decayed" not in captured.err


def test_check_quick_prints_no_report(capsys):
    assert main(["check", "--quick", str(SCENE)]) == 0
    out = capsys.readouterr().out
    assert "Retardation-function consistency" not in out
    assert "vessel file read" not in out
