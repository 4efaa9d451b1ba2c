"""Mirror-image lines of a symmetric scene carry mirror-image tensions
(:mod:`floatmoor.analyses.symmetry`, the symmetry check of ``floatmoor check``)."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest

import floatmoor
from floatmoor.analyses.symmetry import mirror_pairs, symmetry_check, symmetry_plane
from floatmoor.cli import main
from floatmoor.io.build import build
from floatmoor.metocean.config import CurrentSpec, WaveSpec, WindSpec

ROOT = Path(__file__).resolve().parents[2]
FLAGSHIP = ROOT / "scenes" / "floatel_100yr.yaml"


def test_symmetry_plane_of_environments():
    """A common heading (opposite headings share the plane) gives the plane; crossed headings
    give none; a calm sea any plane (0)."""
    class Env:
        def __init__(self, **kw):
            self.waves = kw.get("waves")
            self.wind = kw.get("wind")
            self.current = kw.get("current")
    w = WaveSpec(hs=4.0, tp=10.0, heading=math.radians(30.0))
    assert symmetry_plane(Env(waves=w, current=CurrentSpec(z=(0.0,), speed=(1.0,),
                                                       heading=math.radians(210.0)))) \
        == pytest.approx(math.radians(30.0))
    assert symmetry_plane(Env(waves=w, wind=WindSpec(u10=20.0, heading=0.0))) is None
    assert symmetry_plane(Env()) == 0.0


def test_flagship_mirror_pairs():
    """The Floatel-like mooring: lines 1-12, 2-11, ..., 6-7 mirror images about the x-z plane
    (its anchors and fairleads are written so, mooring.yaml); none about the 45 deg plane."""
    b = build(floatmoor.load_scene(FLAGSHIP))
    assert mirror_pairs(b.mooring, 0.0) == [(f"line{i}", f"line{13 - i}") for i in range(1, 7)]
    assert mirror_pairs(b.mooring, math.radians(45.0)) == []


def test_flagship_mirror_lines_equal_in_a_short_run():
    """In a 200 s run of the flagship (100 s after the ramp) the mirror lines' tensions agree
    to round-off."""
    b = build(floatmoor.load_scene(FLAGSHIP))
    res = symmetry_check(b, duration=100.0)
    assert res["ok"] and len(res["pairs"]) == 6
    assert max(res["differences"]) < 1e-9


def test_check_warns_when_an_asymmetric_vessel_breaks_the_mirror(tmp_path, capsys):
    """A deliberately broken setting: the vessel's centre of gravity 2 m off the symmetry plane
    heels the semi, so mirror-image lines carry different tensions: `floatmoor check` warns
    and says NOT mirror images."""
    for d in ("scenes", "metocean", "vessels/floatel_like"):
        shutil.copytree(ROOT / d, tmp_path / d, ignore=shutil.ignore_patterns("source", "*.py"))
    v = tmp_path / "vessels" / "floatel_like" / "vessel.yaml"
    text = v.read_text()
    assert "centre_of_gravity: [0.0, 0.0, 7.0]" in text
    v.write_text(text.replace("centre_of_gravity: [0.0, 0.0, 7.0]",
                              "centre_of_gravity: [0.0, 2.0, 7.0]"))
    code = main(["check", str(tmp_path / "scenes" / "floatel_100yr.yaml")])
    cap = capsys.readouterr()
    assert code == 0
    assert "NOT mirror images" in cap.out
    assert "warning" in cap.err and "mirror images about the 0 deg plane" in cap.err
    # the unbroken scene says OK
    code = main(["check", str(FLAGSHIP)])
    assert "mirror images about the 0 deg plane" in capsys.readouterr().out
