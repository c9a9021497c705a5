"""Tilting-pad equilibrium by pad assembly (issue 12; C++ ``pad_equilibrium.cpp``).

Checks (no published table: the checks are the equations themselves and independent paths):

* At the equilibrium every pad's residual (film moment about the pivot, and the pivot force
  against the pivot spring) and the journal's force balance vanish to round-off: the full
  residual K r − H(r) − Q, recomputed here from the film forces, is below 1e-11 of the load.
* The pad assembly (each pad on its loaded branch, J. W. Lund, ASLE Trans. 7 (1964) 342-352)
  and the older tilt homotopy (artificial tilt stiffness released over ten decades) reach the
  same equilibrium (1e-8 of the clearance) on the 4-pad load-on-pad bearing where a plain
  Newton from the centre had jumped onto pressure-free side pads (K_xx ≈ 0); here the side
  pads stay pressured and K_xx is a few per cent of K_yy.
* Warm and cold starts agree to 1e-12 of the largest coordinate (polished roots), in a
  System (rotor on two 5-pad bearings) with rigid pivots; with very soft pivots (k_p = 1e5
  N/m, the journals sink 6 clearances) the rotor to 1e-12 and the nearly unloaded upper pads'
  tilts to 1e-9 of the clearance (their film tilt stiffness is almost zero).
* Pivot stiffness k_p: as k_p → ∞ the rigid-pivot answer (tests/test_bearing_geometry.py);
  as k_p → 0 (here 300 and 3000× below the film's stiffness) the pivots carry the load in
  series with the films: the journal sinks by W/(k_p Σ n_y²) over the loaded pads (two pads
  at ±45° under the load: Σ n_y² = 1) on top of the rigid-pivot film deflection, and the
  statically condensed K_yy tends to 1/(1/K_rigid + 1/k_p): both within 1 %.
* Zero load: the journal stays centred (4- and 5-pad bearings with preload).
* Sweeps: the sweep worker's equilibrium equals ``rotordyn.equilibrium`` (1e-9) over tilting-
  pad preload and pivot offset (both now start from the C++ pad assembly).
* Upper pads under a heavy load: each pad is either pressured with a restoring tilt stiffness
  or, when no tilt gives it pressure, at the documented defined position (the boundary of
  its pressure-free set: pressure-free there, pressured just towards the loaded side).
"""

import dataclasses
import math

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import TiltingPadBearing

D, C, MU, HZ = 0.05, 1e-4, 0.02, 40.0
KW = dict(diameter_m=D, length_m=0.5 * D, clearance_m=C, viscosity_pa_s=MU)


def _model(tp, W):
    parts = tp.system_parts(0, 1, 2, "b")
    n = 2 + parts.n_extra
    m = _core.SystemModel()
    m.M, m.K, m.C, m.G = parts.M, parts.K, parts.C, np.zeros((n, n))
    Q = np.zeros(n)
    Q[:2] = W
    m.Q, m.chamber = Q, np.zeros(n)
    m.films = [p.coupling for p in parts.films]
    m.tables = []
    m.pad_coords = parts.pad_groups
    return m, parts


def _solve(tp, W, r0=np.zeros(0)):
    m, parts = _model(tp, W)
    s = _core.SystemSolver(m)
    opt = _core.EquilibriumOptions()
    opt.polish = True
    e = s.equilibrium(2 * math.pi * HZ, 0.0, np.zeros(m.K.shape[0]), r0, opt)
    return s, m, parts, e


CASES = {
    "ross_5pad_preload_0.5": (dict(n_pads=5, pad_arc_deg=60.0, preload=0.5, orientation_deg=18.0,
                                   n_circ=180, n_axial=8), (884.05 / 4, -2670.4 / 4)),
    "4pad_on_heavy": (dict(n_pads=4, pad_arc_deg=72.0, preload=0.3, load="on", n_circ=72,
                           n_axial=8), (0.0, -3000.0)),
    "4pad_between": (dict(n_pads=4, pad_arc_deg=72.0, preload=0.5, load="between", n_circ=72,
                          n_axial=8), (0.0, -600.0)),
    "4pad_flexible_pivot": (dict(n_pads=4, pad_arc_deg=72.0, preload=0.3, load="on", n_circ=72,
                                 n_axial=8, pivot_stiffness_n_per_m=5e7, pad_mass_kg=0.05),
                            (0.0, -600.0)),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_every_pad_and_the_journal_balance_to_round_off(case):
    kw, W = CASES[case]
    tp = TiltingPadBearing(station=0, pad_inertia_kg_m2=2e-5, **KW, **kw)
    s, m, parts, e = _solve(tp, W)
    assert e.status == "ok" and e.path == "pad_assembly", (e.status, e.path, e.message)
    r = np.asarray(e.r)
    H = np.asarray(s.film_forces(r, np.zeros_like(r), 2 * math.pi * HZ))
    R = np.asarray(m.K) @ r - H - np.asarray(m.Q)
    Wn = math.hypot(*W)
    assert np.abs(R[:2]).max() < 1e-11 * Wn, R[:2]          # journal force balance
    assert np.abs(R[2:]).max() < 1e-11 * Wn, R[2:]          # every pad's moment (and pivot)
    assert e.reynolds_solves < 2000


def test_pad_assembly_equals_the_homotopy_path_load_on_pad():
    tp = TiltingPadBearing(station=0, n_pads=4, pad_arc_deg=72.0, preload=0.3, load="on",
                           pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    W = (0.0, -600.0)
    s, m, parts, e = _solve(tp, W)
    assert e.path == "pad_assembly"
    opt = _core.EquilibriumOptions()
    opt.polish = True
    w = 2 * math.pi * HZ
    n = m.K.shape[0]
    start = _core.homotopy_start(m, w, 0.0, np.zeros(n), np.zeros(0), opt, parts.penalty)
    mh = _core.SystemModel()  # the same model without pad groups: the plain Newton path
    for f in ("M", "K", "C", "G", "Q", "chamber", "films", "tables"):
        setattr(mh, f, getattr(m, f))
    eh = _core.SystemSolver(mh).equilibrium(w, 0.0, np.zeros(n), start, opt)
    assert eh.status == "ok" and eh.path == "newton"
    np.testing.assert_allclose(e.r, eh.r, rtol=0, atol=1e-8 * C)
    # the side pads (pivots at 0° and 180°) are pressured, with a restoring tilt stiffness
    lin = s.linearize(e.r, np.zeros(n), w)
    KH = np.asarray(lin.KH)
    for k in (1, 3):
        assert np.asarray(s.last_pressure(k)).max() > 0
        assert KH[2 + k, 2 + k] > 0
    t = tp.coefficient_table([HZ], W)
    assert t.K[0, 0, 0] > 5e-3 * t.K[0, 1, 1], t.K[0]


@pytest.mark.parametrize("pivot", [{}, dict(pivot_stiffness_n_per_m=1e5, pad_mass_kg=0.02)])
def test_warm_and_cold_starts_agree_in_a_system(pivot):
    from test_bearing_elements_system import ROTOR_TOML, FILM

    base = rotordyn.System.from_toml(ROTOR_TOML, is_text=True)
    sys_ = dataclasses.replace(base, bearings=tuple(
        TiltingPadBearing(station=s, n_pads=5, pad_arc_deg=60.0, preload=0.5,
                          pad_inertia_kg_m2=2e-5, **FILM, **pivot) for s in (0, 2)))
    # on soft pivots the upper pads' tilts are fixed only loosely by the residual: solve
    # tighter than the default 1e-10 so that the two starts agree within the bound below
    kw = {"tol": 1e-12} if pivot else {}
    cold = rotordyn.equilibrium(sys_, 40.0, warm_start=False, **kw)
    other = rotordyn.equilibrium(sys_, 70.0, **kw)  # a different start
    warm = rotordyn.equilibrium(sys_, 40.0, r0=other.r, **kw)
    assert cold.status == warm.status == "ok"
    assert cold.path == warm.path == "pad_assembly"
    scale = np.abs(cold.r).max()
    d = np.abs(warm.r - cold.r)
    n_rotor = 6  # three master stations: x, y
    assert d[:n_rotor].max() <= 1e-12 * scale, d[:n_rotor].max() / scale
    if not pivot:
        assert d.max() <= 1e-12 * scale, d.max() / scale
    else:
        # the journals sink ~6 clearances onto the soft pivots: the upper pads' films are then
        # thick and their tilt stiffness almost zero, so a residual at 1e-14 of the load fixes
        # their tilts only to ~1e-9 of the clearance at the default tol (1.3e-9 c measured),
        # 6.7e-10 c at tol 1e-12
        assert d.max() <= 1e-9 * FILM["clearance_m"], d.max()


def test_soft_pivot_tends_to_the_pivot_springs():
    kw = dict(station=0, n_pads=4, pad_arc_deg=72.0, preload=0.3, load="between",
              pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    W = 600.0
    rigid = TiltingPadBearing(**kw).coefficient_table([HZ], (0.0, -W), whirl_ratio=None)
    k_film = rigid.K[0, 1, 1]
    for kp in (1e5, 1e4):
        assert kp <= 1e-2 * k_film  # two and three orders of magnitude below the film
        t = TiltingPadBearing(pivot_stiffness_n_per_m=kp, pad_mass_kg=0.05,
                              **kw).coefficient_table([HZ], (0.0, -W), whirl_ratio=None)
        assert t.status[0] == "ok" and t.path[0] == "pad_assembly", (t.status, t.message)
        # the journal sinks by the rigid bearing's film deflection plus the pivots' W/k_p
        # (the two lower pivots at ±45°: W/(2 cos²45° k_p)), and the static stiffness is film
        # and pivot in series — both exact here to the equilibrium's round-off (observed
        # 2e-13 c and 2e-13); a 1 % tolerance could not see the film part (0.03-0.3 %)
        sink = rigid.y_m[0] - W / kp
        assert t.y_m[0] == pytest.approx(sink, rel=0, abs=1e-9 * KW["clearance_m"])
        series = 1.0 / (1.0 / k_film + 1.0 / kp)
        assert t.K[0, 1, 1] == pytest.approx(series, rel=1e-9), (t.K[0, 1, 1], series)
        assert abs(t.K[0, 1, 1] / kp - 1) > 1e-2 * kp / k_film  # the film part is visible


@pytest.mark.parametrize("n_pads, arc", [(4, 72.0), (5, 60.0)])
def test_zero_load_keeps_the_journal_centred(n_pads, arc):
    tp = TiltingPadBearing(station=0, n_pads=n_pads, pad_arc_deg=arc, preload=0.5,
                           pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    s, m, parts, e = _solve(tp, (0.0, 0.0))
    assert e.status == "ok" and e.path == "pad_assembly", (e.status, e.message)
    assert np.abs(np.asarray(e.r)[:2]).max() < 1e-12 * C


def test_upper_pads_under_heavy_load_are_pressured_or_at_the_defined_tilt():
    tp = TiltingPadBearing(station=0, n_pads=4, pad_arc_deg=72.0, preload=0.3, load="between",
                           pad_inertia_kg_m2=2e-5, n_circ=72, n_axial=8, **KW)
    s, m, parts, e = _solve(tp, (0.0, -3000.0))
    assert e.status == "ok" and e.path == "pad_assembly"
    w = 2 * math.pi * HZ
    r = np.asarray(e.r)
    n = r.size
    KH = np.asarray(s.linearize(r, np.zeros(n), w).KH)
    pressured = 0
    for k in range(4):
        p = np.asarray(s.last_pressure(k))
        if p.max() > 0:
            assert KH[2 + k, 2 + k] > 0  # restoring tilt stiffness
            pressured += 1
            continue
        # defined position: the boundary of the pressure-free set
        found = False
        for sgn in (1.0, -1.0):
            rr = r.copy()
            rr[2 + k] += sgn * 1e-6 * C
            s.film_forces(rr, np.zeros(n), w)
            found |= np.asarray(s.last_pressure(k)).max() > 0
        assert found
    assert pressured + e.unloaded_pads == 4


def test_sweep_equilibrium_equals_the_api_with_tilting_pads(tmp_path):
    """The sweep worker and ``rotordyn.equilibrium`` now share the C++ pad start: the same
    equilibrium (1e-9) over a preload and pivot-offset grid of two 3-pad bearings (the case
    that had differed by 2.7 µm while the API alone used the homotopy)."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from test_bearing_elements_system import ROTOR_TOML, FILM

    base = rotordyn.System.from_toml(ROTOR_TOML, is_text=True)
    sys_ = dataclasses.replace(base, bearings=tuple(
        TiltingPadBearing(station=s, n_pads=3, pad_arc_deg=100.0, preload=0.3,
                          pad_inertia_kg_m2=2e-5, name=f"tp{s}", **FILM) for s in (0, 2)))
    sys_.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "s.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "b"\nmodel = "m.toml"\n'
                    'analysis = "equilibrium"\nchunk_size = 4\n[grid]\n'
                    '"bearings.*.preload" = [0.2, 0.4]\n'
                    '"bearings.*.pivot_offset" = [0.5, 0.6]\nspeed_hz = 60.0\n')
    res = run_sweep(spec, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert (fr["status"] == "ok").all() and fr["point_id"].nunique() == 4
    assert len(set(fr["journal_y_m"].round(15))) > 2  # the axes move the equilibrium
    for _, g in fr.groupby("point_id"):
        row0 = g.iloc[0]
        pre, off = row0["bearings.*.preload"], row0["bearings.*.pivot_offset"]
        s2 = dataclasses.replace(sys_, bearings=tuple(
            dataclasses.replace(b, preload=pre, pivot_offset=off) for b in sys_.bearings))
        e = rotordyn.equilibrium(s2, speed_hz=60.0, warm_start=False)
        assert e.path == "pad_assembly"
        for _, row in g.iterrows():
            i = list(e.bearing_names).index(row["bearing"])
            np.testing.assert_allclose([row["journal_x_m"], row["journal_y_m"]],
                                       [e.journal_x_m[i], e.journal_y_m[i]], rtol=1e-9,
                                       atol=1e-9 * np.abs(e.journal_y_m).max())
