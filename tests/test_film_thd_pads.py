"""Thermo-hydrodynamic films of tilting-pad and fixed-geometry bearings (issue 20;
docs/film-physics.md §"THD pad bearings"): per pad the plain film's energy equation, each pad's
inlet mixing supply oil with the hot oil of the upstream pad (Ettles' hot-oil carry-over),
iterated with the pad equilibrium in one C++ call; K, C with the temperature field frozen.

What is compared, and why the tolerances:
* a temperature-independent viscosity (exponential law, β = 1e-300: μ(T) = μ_ref exactly)
  gives the isothermal bearing: at the THD equilibrium the film forces and K_H, D_H of the
  frozen-field films equal the isoviscous films' bit for bit (the field's face factors are
  exactly 1), and the equilibrium equals the isothermal one to round-off (1e-9 of the
  clearance: two Newton paths to the same polished root);
* energy balance per pad, recomputed here from the returned face flows and field: the heat the
  flows carry out of the pad (through its ends, into the gap at its trailing edge, and the
  mass a prescribed-pressure or cavitated cell does not pass on, at that cell's temperature)
  minus what they bring in (from the inlet gap, side inflow at the supply temperature) equals
  the dissipation of the pad's cells to 1e-9 (the discrete equations, solved directly); and in
  the pad's reported flows and temperatures alone (Q_in at T_in in, Q_out at T_out and the
  side leakage out) to 1e-9 where the pad conserves mass — which failed by 10–20 % of the
  pad's power while the trailing edge's two end cells drew ambient oil (before 2026-12-04);
* the mixing: each pad's inlet temperature equals Ettles' balance with the upstream pad's
  outlet flow and temperature (1e-9);
* the hot oil a pad passes on is its own mass balance: Q_out = Q_in − Q_s from the returned
  face flows (1e-12 Q_in, round-off), equal to the trailing-edge cells' inflow where the film
  conserves mass, at that flow's mixing-cup temperature (1e-9 K); with λ = 0.5 every pad draws
  fresh oil and T_max lies near the effective-temperature pads' (a stated band);
* the compressor of tests/data/models on two 5-pad tilting-pad bearings with the THD film in a
  system: equilibrium, stability, the frozen fields in the returned system (its equilibrium
  reproduces the thermal one), the model file's ``[thermal] model = "thd"`` round trip;
* bad input names the field.
Coarse grids (12 intervals per 60° pad, 6 axially): each test a few seconds.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import FixedGeometryBearing, Oil, TiltingPadBearing
from rotordyn.errors import InputError
from thd_balance import pad_balance as _pad_balance
from thd_balance import upwind_faces

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
LOAD = (0.0, -4000.0)
SPEED = 100.0
TS = 45.0


def _tp(**kw):
    base = dict(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                viscosity_pa_s=0.02, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                preload=0.3, n_circ=72, n_axial=6)
    base.update(kw)
    return TiltingPadBearing(**base)


def _linear(films, r, w):
    m = _core.SystemModel()
    n = len(r)
    z = np.zeros((n, n))
    m.M, m.K, m.C, m.G = z, z, z, z
    m.Q, m.chamber = np.zeros(n), np.zeros(n)
    m.films = [f.coupling for f in films]
    s = _core.SystemSolver(m)
    lin = s.linearize(np.asarray(r), np.zeros(n), w)
    return np.asarray(s.film_forces(np.asarray(r), np.zeros(n), w)), np.asarray(lin.KH), \
        np.asarray(lin.DH)


def test_temperature_independent_viscosity_is_the_isothermal_bearing_bit_for_bit():
    mu = 0.02
    flat = Oil(viscosity_law="exponential", mu_ref_pa_s=mu, t_ref_c=40.0, beta_1_per_k=1e-300)
    tp = _tp(viscosity_pa_s=mu)
    res = tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=flat,
                                 supply_temperature_c=TS, carry_over=0.5)
    assert res.status == "ok"
    assert res.max_temperature_c_total > TS + 1.0        # the film heats ...
    for f in res.viscosity_pa_s:                          # ... the viscosity does not change
        assert np.all(f == mu)
    w = 2 * np.pi * SPEED
    hot = dataclasses.replace(tp, viscosity_field_pa_s=res.viscosity_pa_s)
    fa, ka, ca = _linear(hot.pad_films(), res.r, w)
    fb, kb, cb = _linear(tp.pad_films(), res.r, w)
    assert np.array_equal(fa, fb) and np.array_equal(ka, kb) and np.array_equal(ca, cb)
    assert np.array_equal(res.K_full, kb + tp.system_parts(0, 1, 2, "b").K)
    r_iso, _, _, _ = tp.full_coefficients(SPEED, LOAD)
    np.testing.assert_allclose(res.r, r_iso, atol=1e-9 * tp.clearance_m)


def test_heat_carried_out_equals_dissipation_per_pad_and_the_carry_over_mixing():
    tp = _tp()
    lam = 0.6
    res = tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                 supply_temperature_c=TS, carry_over=lam)
    assert res.status == "ok"
    rc = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
    for k in range(tp.n_pads):
        D = res.inlet_mask[k] > 0
        out, diss, _ = _pad_balance(res.temperature_c[k], D, res.flows[k], rc, TS)
        assert out == pytest.approx(diss, rel=1e-9)
        assert diss == pytest.approx(res.power_loss_w[k], rel=1e-12)
        # Ettles' mixing with the upstream pad (k − 1 in the direction of rotation)
        u = (k - 1) % tp.n_pads
        # (when λ Q_out exceeds the pad's inflow, the pad draws carried-over oil only)
        carried = min(lam * res.outlet_flow_m3_s[u], res.film_flow_m3_s[k])
        qf = res.film_flow_m3_s[k] - carried
        assert res.supply_flow_m3_s[k] == pytest.approx(qf, rel=1e-12, abs=1e-15)
        t_mix = (qf * TS + carried * res.outlet_temperature_c[u]) / res.film_flow_m3_s[k]
        assert res.inlet_temperature_c[k] == pytest.approx(t_mix, abs=1e-9)
    # the loaded pads (below the journal: pivots at 270 ± 36 deg) run hottest
    hot = np.argsort(res.max_temperature_c)[-2:]
    assert set(np.asarray(tp.pivot_angles_deg())[hot].round()) == {234.0, 306.0}
    fr = res.to_frame()
    assert list(fr["pad"]) == ["0", "1", "2", "3", "4", "total"]
    assert fr["power_loss_w"].iloc[-1] == pytest.approx(res.power_loss_w.sum())
    # walls: heat to journal and pads cools the film
    cool = tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                  supply_temperature_c=TS, carry_over=lam,
                                  bush_htc_w_m2k=3000.0)
    assert cool.max_temperature_c_total < res.max_temperature_c_total


def test_fixed_geometry_lobes_thd():
    """Two-axial-groove bearing: the THD lobes' balance and mixing as for the pads; the loaded
    (lower) lobe runs hotter and the whole bearing hotter than the supply."""
    b = FixedGeometryBearing(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                             viscosity_pa_s=0.02, kind="two_axial_groove", n_circ=48, n_axial=6)
    res = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                                carry_over=0.5)
    assert res.status == "ok" and len(res.max_temperature_c) == 2
    rc = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
    for k in range(2):
        out, diss, _ = _pad_balance(res.temperature_c[k], res.inlet_mask[k] > 0, res.flows[k],
                                    rc, TS)
        assert out == pytest.approx(diss, rel=1e-9)
    assert res.max_temperature_c[0] > res.max_temperature_c[1]   # lobe 0 centred at 270 deg
    assert res.K.shape == (2, 2) and np.all(np.isfinite(res.K))


def _compressor_tp():
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    th = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    th = dataclasses.replace(th, model="thd", films=())
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=72, n_axial=6) for b in s.bearings), thermal=th)


def test_compressor_on_tilting_pads_with_thd_in_a_system(tmp_path):
    s = _compressor_tp()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0)
    assert res.status == "ok", res.message
    assert res.thermal_model == "thd" and len(res.bearing_names) == 10
    assert res.bearing_names[0] == "NDE bearing.pad0"
    assert np.all(res.max_temperature_c > s.thermal.supply_temperature_c)
    # the returned system carries the frozen fields: its equilibrium is the thermal one
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    assert e.status == "ok"
    np.testing.assert_allclose(e.r, res.r, atol=1e-6 * s.bearings[0].clearance_m)
    st = rotordyn.stability(res.system, speed_hz=150.0)
    assert st.status == "ok"
    # hotter, thinner oil: the journals sit lower than in the isothermal model at 0.018 Pa s
    iso = rotordyn.equilibrium(s, speed_hz=150.0)
    assert np.all(e.journal_y_m < iso.journal_y_m)
    # the model file: [thermal] model = "thd" on a tilting-pad model round-trips
    p = tmp_path / "m.toml"
    p.write_text(s.to_toml())
    back = rotordyn.System.from_toml(p)
    assert back.thermal == s.thermal
    b = rotordyn.system_thermal_equilibrium(back, speed_hz=150.0)
    np.testing.assert_array_equal(b.max_temperature_c, res.max_temperature_c)


def test_pad_thd_bad_input_names_the_field():
    tp = _tp()
    with pytest.raises(InputError, match="carry_over"):
        tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                               carry_over=1.5)
    with pytest.raises(InputError, match="bush_htc_w_m2k"):
        tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                               bush_htc_w_m2k=-1.0)
    with pytest.raises(InputError, match="viscosity_field_pa_s"):
        dataclasses.replace(tp, viscosity_field_pa_s=[np.ones((3, 3))] * 5).pad_films()
    s = _compressor_tp()
    with pytest.raises(InputError, match="effective_factor"):  # the effective model per pad
        rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, model="effective", bearings=[0],
                                            effective_factor=1.5)
    with pytest.raises(InputError, match="carry_over"):
        dataclasses.replace(s.thermal, carry_over=-0.1)


def _ross_example(ross, n_grid):
    """ROSS 2.3's TiltingPad example (5 pads of 60°, preload 0.5, D = 101.6 mm, c = 74.9 µm,
    L = 50.8 mm, 3000 rpm, ISO VG 32 supplied at 40 °C) at its journal position ε = 0.35,
    287.5°, adiabatic film, hot-oil carry-over 0 (ROSS solves its equilibrium with the inlets at
    the supply temperature and applies the carry-over only afterwards; with 0 both stages see
    the same inlets), n_grid volumes per pad both ways."""
    import contextlib
    import io
    import warnings

    Q_ = ross.Q_
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        return ross.TiltingPad(
            n=1, frequency=Q_([3000], "RPM"), equilibrium_type="match_eccentricity",
            journal_diameter=101.6e-3, radial_clearance=74.9e-6, pad_thickness=12.7e-3,
            pivot_angle=Q_([18.0, 90.0, 162.0, 234.0, 306.0], "deg"),
            pad_arc=Q_([60] * 5, "deg"), pad_axial_length=Q_([50.8e-3] * 5, "m"),
            pre_load=[0.5] * 5, offset=[0.5] * 5, lubricant="ISOVG32",
            oil_supply_temperature=Q_(40, "degC"), eccentricity=0.35,
            attitude_angle=Q_(287.5, "deg"), load=[884.05, -2670.4],
            thermal_type="adiabatic", nx=n_grid, nz=n_grid, hot_oil_carry_over=0.0)


@pytest.mark.ross
def test_thd_tilting_pad_against_ross():
    """Side by side with ROSS's thermal TiltingPad on equal inputs: geometry, speed, oil (ROSS's
    own exponential law μ = a e^{bT}, its density and specific heat), supply temperature,
    carry-over 0, grid (12 volumes per pad around and along ↔ 12 intervals per pad, 12
    axially). ROSS is given the journal position (ε = 0.35 at 287.5°) and balances the pads;
    ours is given the load ROSS's film carries there and finds the journal and the pads.

    Tolerances (what differs between the two models, and the measured differences):
    ROSS keeps heat conduction in the film plane (ours neglects it: Péclet ≫ 1) and holds one
    axial edge at the journal temperature through it, stops its temperature iteration at
    0.1 °C and its pad balance at Nelder–Mead's xtol = 1e-3, and places its unknowns at volume
    centres (ours at nodes). So: the journal position within 0.02 in ε and 2° in attitude, the
    pads' outlet temperature rises within 15 % of the largest rise, and the synchronous K, C
    (ROSS's force differences of the full THD problem, ours the perturbation of the frozen
    field) within 25 % of their largest entry."""
    ross = pytest.importorskip("ross")
    rb = _ross_example(ross, 12)
    f_ross = np.array([float(np.ravel(rb.force_x_total_list[-1])[0]),
                       float(np.ravel(rb.force_y_total_list[-1])[0])])
    a, b = float(rb.a_a), float(rb.b_b)          # μ = a exp(b T), T in degC
    oil = Oil(viscosity_law="exponential", mu_ref_pa_s=a * np.exp(b * 40.0), t_ref_c=40.0,
              beta_1_per_k=-b, density_kg_m3=float(rb.rho),
              specific_heat_j_per_kg_k=float(rb.cp))
    tp = TiltingPadBearing(station=0, diameter_m=101.6e-3, length_m=50.8e-3,
                           clearance_m=74.9e-6, viscosity_pa_s=oil.viscosity_pa_s(40.0),
                           n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5, preload=0.5,
                           orientation_deg=18.0, pad_thickness_m=12.7e-3, n_circ=72, n_axial=12)
    res = tp.thermal_equilibrium(load_n=-f_ross, speed_hz=50.0, oil=oil,
                                 supply_temperature_c=40.0, carry_over=0.0)
    assert res.status == "ok"
    att = np.degrees(np.arctan2(res.y_m, res.x_m)) % 360.0
    assert res.eccentricity_ratio == pytest.approx(0.35, abs=0.02)
    assert att == pytest.approx(287.5, abs=2.0)
    rise_ross = np.asarray(rb.T_outlet, dtype=float) - 40.0
    rise_ours = res.outlet_temperature_c - 40.0
    assert np.max(np.abs(rise_ours - rise_ross)) < 0.15 * np.max(rise_ross)
    k_ross = np.array([[rb.kxx[0], rb.kxy[0]], [rb.kyx[0], rb.kyy[0]]], dtype=float)
    c_ross = np.array([[rb.cxx[0], rb.cxy[0]], [rb.cyx[0], rb.cyy[0]]], dtype=float)
    assert np.max(np.abs(res.K - k_ross)) < 0.25 * np.abs(k_ross).max()
    assert np.max(np.abs(res.C - c_ross)) < 0.25 * np.abs(c_ross).max()


def _pad_flows(T, D, fl):
    """From one pad's returned face flows (m³/s): the inflow Q_in from the inlet gap, the side
    leakage Q_s (end cells' surplus), the flow the trailing-edge cells receive from the pad
    (their energy equations' inflow) with its mixing-cup temperature, and the largest mass
    imbalance of an interior non-inlet cell relative to Q_in (0 unless cavitated)."""
    qp, qz = fl["q_phi_m3_s"], fl["q_z_m3_s"]
    n, k1 = T.shape
    inflow, outflow = np.zeros_like(T), np.zeros_like(T)
    te = np.zeros(T.shape, bool)
    q_in = 0.0
    for a, b, F in upwind_faces(qp, qz):
        inflow[b] += F
        outflow[a] += F
        if D[a] and not D[b]:
            q_in += F
    for j in range(n):                        # trailing-edge cells: the gap downstream
        te[j] = ~D[j] & D[(j + 1) % n]
    B = inflow - outflow
    ends = np.zeros(T.shape, bool)
    ends[:, [0, k1 - 1]] = True
    q_s = B[~D & ends & (B > 0)].sum()
    q_te = inflow[te].sum()
    t_te = (inflow[te] * T[te]).sum() / q_te
    imb = np.abs(B[~D & ~ends & ~te]).max() / q_in
    return q_in, q_s, q_te, t_te, imb


def test_the_hot_oil_passed_on_is_the_pads_own_mass_balance():
    """Q_out = Q_in − Q_s per pad (not the trailing-edge cells' flux into the gap, whose face
    thickness averages in the gap: 2.3–5.8 Q_in before 2026-12-03). Recomputed here from the
    returned face flows: Q_in and Q_s, Q_out ≤ Q_in, Q_in − Q_s − Q_out = 0 to 1e-12 Q_in
    (round-off of the sums); where the film conserves mass (no cavitated cell: interior
    imbalance ≤ 1e-12) the trailing-edge cells' inflow equals Q_out to 1e-12 too, so the pad's
    cells balance exactly; T_out is that flow's mixing-cup temperature (1e-9 K)."""
    tp = _tp()
    res = tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                 supply_temperature_c=TS, carry_over=0.5)
    assert res.status == "ok"
    conserving = 0
    for k in range(tp.n_pads):
        q_in, q_s, q_te, t_te, imb = _pad_flows(res.temperature_c[k], res.inlet_mask[k] > 0,
                                                res.flows[k])
        q_out = res.outlet_flow_m3_s[k]
        assert res.film_flow_m3_s[k] == pytest.approx(q_in, rel=1e-12)
        assert res.side_flow_m3_s[k] == pytest.approx(q_s, rel=1e-12, abs=1e-12 * q_in)
        assert 0.0 < q_out <= q_in
        assert abs(q_in - q_s - q_out) <= 1e-12 * q_in
        assert res.outlet_temperature_c[k] == pytest.approx(t_te, abs=1e-9)
        if imb <= 1e-12:
            conserving += 1
            assert abs(q_te - q_out) <= 1e-12 * q_in
        else:   # the unloaded pad's cavitated cells: the excess the film does not conserve
            assert abs(q_te - q_out) <= 0.05 * q_in
    assert conserving >= 4


def test_the_trailing_edge_corners_draw_no_ambient_oil():
    """The trailing-edge column holds the prescribed pressure; the flux of its face into the gap
    (thickness averaged with the gap's 4 C_p) exceeds what the pad brings it, in every row. Its
    two end cells counted that imbalance as ambient oil drawn in at T_s (0.12–0.30 Q_in here,
    the corners 8–9 K below the cell upstream of them, T_out 1.4 K low on the loaded pads, λ =
    0) until 2026-12-04; the inner cells never did. Now every trailing-edge cell passes on
    just what the pad brings it, so (adiabatic, λ = 0.5):
    * the pad's heat balance in its reported quantities, ρ c (Q_out T_out + Σ_ends q_s T −
      Q_in T_in) = P, holds to 1e-9 of P on every pad that conserves mass (interior imbalance
      ≤ 1e-12 Q_in; before: −135 of 786 W on the loaded pads, 10–20 % of P on all);
    * no trailing-edge cell is colder than the coldest cell it receives oil from (mixing of
      inflows plus dissipation; before: the corners 8 K below).
    The corners' viscosity enters no face between free pressure nodes, so the pressure and the
    position do not change at λ = 0 (ε to 1e-10); with λ > 0 the hotter T_out reaches the next
    pad's inlet."""
    tp = _tp()
    res = tp.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                 supply_temperature_c=TS, carry_over=0.5)
    assert res.status == "ok"
    rc = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
    checked = 0
    for k in range(tp.n_pads):
        T, D, fl = res.temperature_c[k], res.inlet_mask[k] > 0, res.flows[k]
        n, k1 = T.shape
        qp, qz = fl["q_phi_m3_s"], fl["q_z_m3_s"]
        inflow, outflow = np.zeros_like(T), np.zeros_like(T)
        sources = {}
        for a, b, F in upwind_faces(qp, qz):
            inflow[b] += F
            outflow[a] += F
            if F > 0:
                sources.setdefault(b, []).append(a)
        te = [(j, kk) for j in range(n) for kk in range(k1) if not D[j, kk] and D[(j + 1) % n, kk]]
        assert len(te) == k1
        for c in te:  # a mixing cell with heating only: not below all it receives
            assert T[c] >= min(T[a] for a in sources[c]) - 1e-9
        B = inflow - outflow
        side = sum(B[j, kk] * T[j, kk] for j in range(n) for kk in (0, k1 - 1)
                   if not D[j, kk] and not D[(j + 1) % n, kk] and B[j, kk] > 0)
        _, _, _, _, imb = _pad_flows(T, D, fl)
        if imb > 1e-12:
            continue  # the unloaded pad's cavitated cells create mass (not this balance)
        checked += 1
        heat = rc * (res.outlet_flow_m3_s[k] * res.outlet_temperature_c[k] + side
                     - res.film_flow_m3_s[k] * res.inlet_temperature_c[k])
        assert heat == pytest.approx(res.power_loss_w[k], rel=1e-9)
    assert checked >= 4


def test_carry_over_half_every_pad_draws_fresh_oil_near_the_effective_pads():
    """λ = 0.5 on the 5-pad bearing: each pad draws fresh oil (before 2026-12-03 none did:
    T_max 86.0 °C, ε 0.750), and T_max is near the effective-temperature pads' (which pass on
    the same Q − Q_s): the rises over the supply within 15 % (at λ = 0 the two models' rises
    differ by 5 %, 10.8 vs 11.3 K — the effective pad's uniform T_eff — and the ring carries
    that difference round once more), the THD rise raised by the carry-over at least half as
    much as the effective one's, and ε within 0.06 with the effective pads more eccentric
    (as at λ = 0, docs/film-physics.md: the THD pad's cooler leading part carries more)."""
    tp = _tp()
    kw = dict(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS)
    h = tp.thermal_equilibrium(**kw, carry_over=0.5)
    e = tp.thermal_equilibrium(**kw, carry_over=0.5, model="effective")
    h0 = tp.thermal_equilibrium(**kw, carry_over=0.0)
    e0 = tp.thermal_equilibrium(**kw, carry_over=0.0, model="effective")
    assert h.status == e.status == "ok"
    assert np.all(h.supply_flow_m3_s > 0.05 * h.film_flow_m3_s)
    rise_h, rise_e = h.max_temperature_c_total - TS, e.max_temperature_c_total - TS
    assert rise_h == pytest.approx(rise_e, rel=0.15)
    gain_h = h.max_temperature_c_total - h0.max_temperature_c_total
    gain_e = e.max_temperature_c_total - e0.max_temperature_c_total
    assert 0.5 * gain_e < gain_h < 1.5 * gain_e
    assert 0.0 < e.eccentricity_ratio - h.eccentricity_ratio < 0.06
