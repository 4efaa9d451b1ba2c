"""Export to MoorDyn v2 and back (floatmoor.io.moordyn.export), and a run of the exported file
in MoorDyn (Hall's MoorDyn v2, the ``moordyn`` Python package, optional)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.cli import main
from floatmoor.core.config import Node
from floatmoor.core.errors import FloatmoorWarning
from floatmoor.io import moordyn
from floatmoor.io.mooring_section import parse_mooring

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data"


def _read(path, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        return moordyn.read_model(path, **kw)


@pytest.mark.parametrize("source", ["oc3", "clump", "floatel"])
def test_export_then_import_gives_the_same_system(tmp_path, source):
    if source == "oc3":
        sys0 = parse_mooring(Node.load(ROOT / "vessels/oc3_hywind/mooring.yaml"), water_depth=320.0)
    elif source == "floatel":  # 12 lines of chain - polyester - chain from the type library
        sys0 = parse_mooring(Node.load(ROOT / "vessels/floatel_like/mooring_fe.yaml"),
                             water_depth=150.0)
    else:
        sys0 = _read(DATA / "moordyn_v2_clump.dat").system
    out = tmp_path / "exported.dat"
    moordyn.export(sys0, out)
    back = _read(out, water_depth=sys0.water_depth).system
    assert back.n_lines == sys0.n_lines
    for a, b in zip(sys0.lines, back.lines):
        assert a.anchor == b.anchor and a.fairlead == b.fairlead and a.cb == b.cb
        for s, t in zip(a.segments, b.segments):
            assert s.length == t.length and s.ea == t.ea
            assert t.w == pytest.approx(s.w, rel=1e-12)
            assert t.point_load == pytest.approx(s.point_load, rel=1e-12, abs=1e-9)
    np.testing.assert_allclose(back.tensions()["fairlead_tension"].values,
                               sys0.tensions()["fairlead_tension"].values, rtol=1e-12)
    np.testing.assert_allclose(back.stiffness(), sys0.stiffness(), rtol=1e-9,
                               atol=1e-9 * np.abs(sys0.stiffness()).max())
    fe0, fe1 = sys0.line_models.options, back.line_models.options
    assert fe1.internal_damping == fe0.internal_damping
    if fe0.n_elements is not None:
        assert fe1.n_elements == fe0.n_elements
    for name, lt0 in sys0.line_types.items():
        lt1 = back.line_types[name]
        # the exported diameter is the volume-equivalent one; drag per metre is kept
        assert lt1.displaced_volume == pytest.approx(lt0.displaced_volume, rel=1e-12)
        assert lt1.cdn * lt1.diameter == pytest.approx(lt0.cdn * lt0.diameter, rel=1e-12)
        assert lt1.cdt * lt1.diameter == pytest.approx(lt0.cdt * lt0.diameter, rel=1e-12)
        assert (lt1.can, lt1.cat) == (lt0.can, lt0.cat)


def test_cli_export_scene(tmp_path, capsys):
    out = tmp_path / "oc3.dat"
    assert main(["export", "moordyn", str(ROOT / "scenes/oc3_hywind.yaml"), "--out", str(out)]) == 0
    back = _read(out).system
    assert back.n_lines == 3 and back.water_depth == 320.0
    assert main(["export", "moordyn", str(ROOT / "vessels/oc3_hywind/mooring.yaml"),
                 "--out", str(out)]) == 2
    assert "--water-depth" in capsys.readouterr().err


def test_exported_file_runs_in_moordyn(tmp_path):
    """MoorDyn's static fairlead tension of the exported OC3 mooring equals floatmoor's
    catenary within 0.1 % (MoorDyn: 45 lumped-mass segments on seabed springs, dynamic
    relaxation to its default threshold; measured 0.027 %)."""
    mdl = pytest.importorskip("moordyn")
    sys0 = parse_mooring(Node.load(ROOT / "vessels/oc3_hywind/mooring.yaml"), water_depth=320.0)
    out = tmp_path / "oc3.dat"
    moordyn.export(sys0, out)
    s = mdl.Create(str(out))
    x = sys0.fairleads.ravel().tolist()
    mdl.Init(s, x, [0.0] * len(x))
    # coupled points are 2, 4, 6 (each line: anchor, fairlead)
    f = [np.linalg.norm(mdl.GetPointForce(mdl.GetPoint(s, 2 * k + 2))) for k in range(3)]
    mdl.Close(s)
    np.testing.assert_allclose(f, sys0.tensions()["fairlead_tension"].values, rtol=1e-3)
