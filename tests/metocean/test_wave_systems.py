"""Several wave systems in one sea state (a wind sea and a swell from another direction): the
scene key, the realisation, the forces of both domains and the campaign sea states.

Independent expectations: independent systems' variances add (first-order responses and the
mean drift are sums over the systems); the slow-drift spectrum of Newman's approximation across
directions against its definition summed pair by pair; the realisation of a sea of two systems
is the components of each system realised alone on the common grid.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.core.config import Node
from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.forces.spectral import newman_drift_spectrum, newman_drift_spectrum_directions
from floatmoor.forces.waves import sea_is_unidirectional, wave_components
from floatmoor.io.environment import parse_waves
from floatmoor.metocean.config import WaveSpec, WaveSystems, total_hs, wave_systems
from floatmoor.metocean.realisation import realise_waves, system_seed
from floatmoor.metocean.spectra import sea_directions, wave_spectrum

ROOT = Path(__file__).resolve().parents[2]
FLOATEL = ROOT / "vessels" / "floatel_like"
WIND_SEA = {"name": "wind_sea", "spectrum": "jonswap", "hs": 6.0, "tp": 10.0, "heading_deg": 0.0}
SWELL = {"name": "swell", "spectrum": "jonswap", "hs": 3.0, "tp": 16.0, "gamma": 5.0,
         "heading_deg": 90.0}


def _waves(data):
    return parse_waves(Node(data, "s.yaml", "environment.waves"), water_depth=150.0)


def test_scene_key_reads_every_system():
    sea = _waves({"systems": [WIND_SEA, {**SWELL, "spreading": "cos2s", "n_directions": 5}],
                  "discretisation": {"n_frequencies": 900}, "random_amplitudes": True})
    assert isinstance(sea, WaveSystems) and sea.names == ("wind_sea", "swell")
    assert sea.hs == pytest.approx(math.hypot(6.0, 3.0))
    assert sea.dominant.tp == 10.0
    s = wave_systems(sea)  # the sea's discretisation on every system
    assert [x.n_frequencies for x in s] == [900, 900] and all(x.random_amplitudes for x in s)
    assert s[1].heading == pytest.approx(math.pi / 2) and s[1].n_directions == 5
    assert not sea_is_unidirectional(sea)
    one = _waves({"systems": [WIND_SEA]})
    assert isinstance(one, WaveSystems) and total_hs(one) == 6.0


@pytest.mark.parametrize("data, key", [
    ({"systems": []}, "environment.waves.systems"),
    ({"systems": [WIND_SEA, WIND_SEA]}, "environment.waves.systems"),
    ({"systems": [{**WIND_SEA, "discretisation": {"n_frequencies": 10}}]},
     "environment.waves.systems[0].discretisation"),
    ({"systems": [{**WIND_SEA, "hs": 16.0, "tp": 5.0}]}, "environment.waves.systems[0].hs"),
    ({"systems": [WIND_SEA], "discretisation": {"omega_max": 0.5}},
     "environment.waves.discretisation.omega_max"),
    ({"systems": [WIND_SEA], "hs": 2.0}, "environment.waves.hs"),
    ({"systems": [{**WIND_SEA, "name": f"s{i}"} for i in range(9)]},
     "environment.waves.systems"),
])
def test_scene_key_mistakes_are_scene_errors(data, key):
    with pytest.raises(SceneError) as e:
        _waves(data)
    assert e.value.key == key


def test_sea_directions_add_to_the_sea():
    """Every system's spectrum times its spreading weights, equal directions merged; one
    long-crested system gives its own spectrum."""
    w = np.linspace(0.2, 2.0, 400)
    one = WaveSpec(hs=6.0, tp=10.0)
    d, S = sea_directions(one, w)
    assert d.tolist() == [0.0] and np.array_equal(S[0], wave_spectrum(one, w))
    spread = replace(one, tp=14.0, spreading="cos2s", n_directions=5)  # -144 ... 144 deg
    sea = WaveSystems(systems=(one, spread, replace(one, hs=2.0, heading=math.pi / 2)))
    d, S = sea_directions(sea, w)
    assert d.size == 6  # 0 deg merged (the first system and the middle spreading bin)
    np.testing.assert_allclose(S.sum(axis=0), wave_spectrum(one, w) + wave_spectrum(spread, w)
                               + wave_spectrum(replace(one, hs=2.0), w), rtol=1e-12)
    m0 = np.trapezoid(S.sum(axis=0), w)
    assert m0 == pytest.approx((sea.hs / 4.0) ** 2, rel=0.02)


def test_realisation_is_every_system_on_one_grid():
    """The components of a two-system sea are each system realised alone (system 0 with the
    run's seed, system 1 with its own stream) on the bins of one FFT grid, which starts at the
    lowest band (here system 0's, the swell: its components are those of the swell alone)."""
    swell = WaveSpec(hs=3.0, tp=16.0, gamma=5.0, heading=math.pi / 2)
    sea = WaveSpec(hs=6.0, tp=10.0)
    h, duration, seed = 0.1, 1800.0, 7
    comp = wave_components(WaveSystems(systems=(swell, sea)), duration=duration, seed=seed,
                           h=h, water_depth=150.0, gravity=9.80665)
    grid = comp.grid
    r = comp.realisation
    idx = (r.omega - grid.w0) / grid.dw
    np.testing.assert_allclose(idx, np.round(idx), atol=1e-6)  # every component on the grid
    assert grid.N * h >= duration
    first = wave_components(swell, duration=duration, seed=seed, h=h, water_depth=150.0,
                            gravity=9.80665).realisation
    n0 = first.omega.size
    np.testing.assert_array_equal(r.amplitude[:n0], first.amplitude)
    np.testing.assert_array_equal(r.phase[:n0], first.phase)
    np.testing.assert_allclose(r.omega[:n0], first.omega, rtol=1e-12)
    sel = r.direction == 0.0
    alone = realise_waves(sea, duration=duration, seed=system_seed(seed, 1), water_depth=150.0,
                          n_frequencies=int(sel.sum()),
                          omega_min=r.omega[sel][0] - 0.5 * grid.dw,
                          omega_max=r.omega[sel][-1] + 0.5 * grid.dw, random_frequencies=False)
    np.testing.assert_allclose(r.amplitude[sel], alone.amplitude, rtol=1e-9)
    np.testing.assert_array_equal(r.phase[sel], alone.phase)
    assert system_seed(seed, 1) != seed  # independent phases
    # each system's energy is its own Hs (within the spectral cut-offs)
    for spec, s in ((swell, ~sel), (sea, sel)):
        assert 4.0 * math.sqrt(0.5 * np.sum(r.amplitude[s] ** 2)) == pytest.approx(spec.hs,
                                                                                  rel=0.01)


def test_newman_across_directions_against_the_pair_sum():
    """The O(n_dir) form of the slow-drift spectrum equals its definition summed over every
    pair of directions (d, e) with T = (C_d + C_e)/2 at w + mu/2; one direction reduces to the
    unidirectional formula (Wang (2016) eq. 2.38)."""
    rng = np.random.default_rng(3)
    w = np.linspace(0.3, 1.5, 60)
    mu = np.linspace(0.0, 0.2, 7)
    S = np.abs(rng.normal(size=(3, w.size)))
    C = rng.normal(size=(3, w.size, 6)) * 1e4
    got = newman_drift_spectrum_directions(w, S, C, mu)
    from floatmoor.core.quadrature import trapezoid_weights
    q = trapezoid_weights(w)
    want = np.zeros_like(got)
    for k, m in enumerate(mu):
        for d in range(3):
            for e in range(3):
                s2 = np.interp(w + m, w, S[e], right=0.0)
                T = 0.5 * np.stack([np.interp(w + 0.5 * m, w, C[d][:, j], right=0.0)
                                    + np.interp(w + 0.5 * m, w, C[e][:, j], right=0.0)
                                    for j in range(6)], axis=1)
                want[k] += 8.0 * np.einsum("n,ni,nj->ij", q * S[d] * s2, T, T)
    np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-12 * np.abs(want).max())
    np.testing.assert_array_equal(newman_drift_spectrum_directions(w, S[:1], C[:1], mu),
                                  newman_drift_spectrum(w, S[0], C[0], mu))


def _scene(tmp_path, name, waves):
    sc = {"name": name, "site": {"water_depth": 150.0, "water_density": 1025.0},
          "vessel": str(FLOATEL / "vessel.yaml"), "mooring": str(FLOATEL / "mooring.yaml"),
          "environment": {"waves": waves},
          "analysis": {"duration": 1300.0, "dt": 0.1, "transient": 300.0, "ramp": 100.0}}
    p = tmp_path / f"{name}.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    return p


@pytest.fixture(scope="module")
def fd_runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("systems")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        both = floatmoor.frequency_domain_result(
            _scene(tmp, "both", {"systems": [WIND_SEA, SWELL]}))
        alone = [floatmoor.frequency_domain_result(
            _scene(tmp, s["name"], {k: v for k, v in s.items() if k != "name"}))
            for s in (WIND_SEA, SWELL)]
    return both, alone


def test_fd_first_order_and_mean_drift_add_over_the_systems(fd_runs):
    """Independent systems: the FD's WF variances and mean drift forces of the two-system sea
    are the sums of each system's alone (the mean position moves with the drift, so the
    linearisation point differs slightly: 2 %); the Dataset gives the RAO of each direction."""
    both, (a, b) = fd_runs
    assert both.drift_method == "newman"  # two directions: no QTF, whatever the database
    # (at the mean headings of the three runs, which differ by a few microradians)
    np.testing.assert_allclose(both.mean_force_drift, a.mean_force_drift + b.mean_force_drift,
                               rtol=1e-5, atol=1e-5 * np.abs(both.mean_force_drift).max())
    var = a.wf_std ** 2 + b.wf_std ** 2
    for k in (0, 1, 2, 3, 4):  # surge and pitch from the wind sea, sway and roll from the swell
        assert both.wf_std[k] ** 2 == pytest.approx(var[k], rel=0.02), k
    assert b.wf_std[1] > 0.5 * both.wf_std[1] and a.wf_std[1] < 1e-6
    ds = floatmoor.analyses.fd_dataset.to_dataset(both)
    assert "rao" not in ds and ds["rao_direction"].sizes["wave_direction"] == 2
    np.testing.assert_allclose(ds["wave_spectrum_direction"].sum("wave_direction"),
                               ds["wave_spectrum"], rtol=1e-12)
    # the slow drift couples the systems: more than the sum of each system's own
    assert both.lf_std[0] > 0.0


def test_td_sums_the_systems(tmp_path):
    """The time domain realises both systems (the recorded elevation is the sum of each
    system's elevation on the common grid), and its first-order force is their sum."""
    p = _scene(tmp_path, "td", {"systems": [WIND_SEA, SWELL]})
    built = floatmoor.build(p)
    from floatmoor.solvers.time_domain import assemble
    a = assemble(built, seed=3, dt=0.1, duration=200.0)
    assert {"wave1", "drift_newman"} <= set(a.models)
    r = a.waves.realisation
    assert set(np.round(np.degrees(np.unique(r.direction)), 9)) == {0.0, 90.0}
    eta = a.waves.elevation(101, 0.5)
    parts = [replace(a.waves, realisation=replace(
        r, omega=r.omega[s], amplitude=r.amplitude[s], phase=r.phase[s], direction=r.direction[s],
        k=r.k[s])).elevation(101, 0.5) for s in (r.direction == 0.0, r.direction != 0.0)]
    np.testing.assert_allclose(eta, parts[0] + parts[1], atol=1e-9)
    f = a.models["wave1"].series
    assert np.abs(f[:, 1]).max() > 0.2 * np.abs(f[:, 0]).max()  # the swell's sway force


def test_campaign_sea_state_of_systems_turns_with_the_case(tmp_path):
    """A campaign sea state given as systems: every system turned by the case's wave heading
    (heading_offset_deg from it), the base scene's discretisation kept; a base scene of
    several systems with Hs/Tp sea states is refused."""
    from floatmoor.campaign.matrix import build_matrix, case_scene
    from floatmoor.campaign.spec import load_campaign
    base = (ROOT / "scenes" / "floatel_100yr.yaml").as_posix()
    c = tmp_path / "c.yaml"
    c.write_text(f"""
name: t
base_scene: {base}
sea_states:
  list:
    - {{name: sea_swell, systems: [{{hs: 14.0, tp: 16.0}},
                                    {{hs: 4.0, tp: 22.0, gamma: 5.0, heading_offset_deg: 30}}]}}
headings: {{waves_deg: [0, 45]}}
conditions: {{intact: true}}
seeds: "1-3"
""")
    spec = load_campaign(c)
    ss = spec.sea_states[0]
    assert ss.hs == pytest.approx(math.hypot(14.0, 4.0)) and ss.tp == 16.0
    case = next(x for x in build_matrix(spec) if x.wave_heading_deg == 45.0)
    scene, _ = case_scene(floatmoor.load_scene(base), case)
    w = scene.environment.waves
    assert isinstance(w, WaveSystems) and len(w.systems) == 2
    assert [math.degrees(s.heading) for s in w.systems] == pytest.approx([45.0, 75.0])
    with pytest.raises(SceneError, match="sea states given as systems"):
        case_scene(scene, replace(case, sea_state=replace(ss, systems=(), system_names=())))
    bad = tmp_path / "bad.yaml"
    bad.write_text(c.read_text().replace("{hs: 14.0, tp: 16.0}", "{hs: 14.0, tp: 16.0, "
                                         "heading_deg: 10}"))
    with pytest.raises(SceneError) as e:
        load_campaign(bad)
    assert "heading_deg" in str(e.value)


def test_correction_formula_needs_one_sea_state(tmp_path):
    """Eq. 6.6 (the viscous-drift correction formula) is written with the Hs of one sea: a sea
    of several systems is refused in both domains, naming the key."""
    p = _scene(tmp_path, "cf", {"systems": [WIND_SEA, SWELL]})
    sc = yaml.safe_load(p.read_text())
    sc["forces"] = {"viscous_drift": {"model": "correction_formula",
                                      "column_diameters": [12.5] * 4}}
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    with pytest.raises(SceneError, match="forces.viscous_drift.model"):
        floatmoor.frequency_domain(p)
    with pytest.raises(SceneError, match="forces.viscous_drift.model"):
        floatmoor.simulate(p, seed=1, duration=20.0)
