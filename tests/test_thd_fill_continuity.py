"""The fill of a Swift–Stieber film's cavitated cells is continuous in the film's inputs
(docs/film-physics.md, "Thermal films with a tilted journal", "Fill of a cavitated cell next
to the full film"), and with it the THD map, whose fixed point was not unique before.

Before: the streamer fill of a node jumped θ_s ↔ 1 (0.35 on the compressor's NDE film) as the
node changed between cavitated and full, and the compressor's NDE plain bearing misaligned by
0.27–0.30 mrad had two THD fixed points (the system's and the standalone call's T_max 0.54 K
apart at 0.30 mrad, 0.64 K at 0.27 mrad). Now a cavitated node next to the full film takes
θ_s + (1 − θ_s) s, s the complementarity front between it and its full neighbour.

Checks:
* on a plain film (36 × 8, Swift–Stieber, no groove) the load's direction is bisected to
  1e-7 rad across each change of the cavitated set as the zone turns through one cell: the
  fill, the face flows (relative to the Couette scale) and the dissipation on either side
  agree to 1e-3 while the set differs — the fill jumped by up to 0.69 before;
* the compressor (``compressor_plain_thermal.toml``, 36 × 6, 150 Hz, THD) with both plain
  bearings misaligned by 0.27 and 0.30 mrad: the system's thermal equilibrium and the
  standalone tilted one at the NDE journal's tilt and film load are one fixed point (fields
  1e-5 K).
"""

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core

GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)


def _state(solver, a, w):
    e, c = 0.55, GEO["clearance_m"]
    sol = solver.rigid(e * c * math.sin(a), -e * c * math.cos(a), 0.0, 0.0, w)
    p = np.asarray(sol.p_pa)
    f = solver.film_flows()
    cav = p[:, 1:-1] <= 0.0
    return cav, np.array(f.fill), np.array(f.q_phi_m3_s), np.array(f.dissipation_w)


def test_fill_is_continuous_where_a_node_changes_between_cavitated_and_full():
    """The load turned through one cell (10°) at ε = 0.55 moves both ends of the cavitated
    zone across a node; each change of the set is bisected to 1e-7 rad (wider than the
    solver's degenerate band, |multiplier| <= 1e-12 of its scale, inside which a node counts
    as full): the fill, face flows and dissipation on either side agree to 1e-3 (before:
    the fill of the node jumped by up to 0.69 there, the reformation's θ_s ≈ 0.31 -> 1)."""
    b = rotordyn.JournalBearing(viscosity_pa_s=0.02, n_circ=36, n_axial=8, **GEO)
    g, grid = b.to_core()
    s = _core.ReynoldsSolver(g, grid, "reynolds")
    w, c = 2.0 * math.pi * 100.0, GEO["clearance_m"]
    angles = np.linspace(0.0, 2.0 * math.pi / 36, 21)
    sets = [_state(s, a, w)[0] for a in angles]
    switches = [i for i in range(len(angles) - 1) if not np.array_equal(sets[i], sets[i + 1])]
    assert len(switches) >= 4, "the cavitated set should change at both ends of the zone"
    qscale = 0.5 * w * GEO["diameter_m"] / 2 * c * GEO["length_m"] / 8  # U c Δz / 2
    worst = 0.0
    for i in switches:
        a, bb = angles[i], angles[i + 1]
        ca = sets[i]
        while bb - a > 1e-7:  # bisect: the two ends hold different sets
            m = 0.5 * (a + bb)
            if np.array_equal(_state(s, m, w)[0], ca):
                a = m
            else:
                bb = m
        sa, sb = _state(s, a, w), _state(s, bb, w)
        assert not np.array_equal(sa[0], sb[0])
        dfill = np.max(np.abs(sa[1] - sb[1]))
        dq = np.max(np.abs(sa[2] - sb[2])) / qscale
        dd = abs(sa[3].sum() - sb[3].sum()) / sa[3].sum()
        worst = max(worst, dfill, dq, dd)
        assert dfill < 1e-5 and dq < 1e-5 and dd < 1e-6, (a, dfill, dq, dd)
    assert worst < 1e-5


def _scan_script():
    """docs/calibration/thd_tilt_scan.py (its system-against-standalone solve)."""
    path = Path(__file__).resolve().parents[1] / "docs" / "calibration" / "thd_tilt_scan.py"
    spec = importlib.util.spec_from_file_location("thd_tilt_scan", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("theta_y_mrad", [0.27, 0.30])
def test_tilted_compressor_system_and_standalone_meet_one_fixed_point(theta_y_mrad):
    k = 0  # the NDE bearing, the film of the two fixed points
    res, sa, b = _scan_script().system_and_standalone(theta_y_mrad * 1e-3, k)
    assert res.status == "ok"
    diff = np.max(np.abs(np.asarray(res.temperature_c[k]) - np.asarray(sa.temperature_c)))
    assert diff < 1e-5, (res.max_temperature_c[k], sa.max_temperature_c, diff)
    assert abs(res.journal_x_m[k] - sa.x_m) < 1e-6 * b.clearance_m
