"""Rotating (internal) shaft damping with housing offsets (docs/model-file.md, "Rotating
damping"). r is relative to the housings and the shaft's displacement is r + a, so the
circulatory force of the rotating damping is −Ω K_c (r + a): the core's H carries −Ω K_c r and
the offsets' part −Ω K_c a is a load beside −K a (SystemModel::offset_load). Before, any offset
with rotating damping was refused.

Checks, none on the paper rig:
* the compressor on two plain bearings: offsetting both housings by the same (a_x, a_y) moves
  the rotor rigidly (K and K_c annihilate a rigid translation), so the journals relative to
  their housings, the film forces and K_c (r + a) are the unshifted ones (1e-9);
* the motor–fan train on three plain bearings (statically indeterminate: a raised middle
  housing bends the shaft): the equilibrium satisfies K (r + a) + Ω K_c (r + a) = H_films + Q
  assembled here from the model's matrices (1e-9 of the load); the circulatory load moves the
  journals against a stationary β; a transient started at the equilibrium stays there, and a
  harmonic-balance orbit under a vanishing unbalance has the equilibrium as its mean;
* an equilibrium branch over a_y of the active-bearing compressor equals rd.equilibrium at
  its points.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled

MODELS = Path(__file__).parent / "data" / "models"


def _rotating(s, beta, rotating=True):
    return dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, damping_beta_s=beta, damping_rotating=rotating))


def _offsets(s, **by_bearing):
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, **by_bearing.get(b.name, {})) for b in s.bearings))


def test_a_uniform_offset_moves_the_rotor_rigidly():
    from coarse_models import compressor_plain

    s = _rotating(compressor_plain(), 4e-5)
    shift = {"config_ax_m": -1e-5, "config_ay_m": 2e-5}
    off = _offsets(s, **{b.name: shift for b in s.bearings})
    e0, e1 = rd.equilibrium(s, 100.0), rd.equilibrium(off, 100.0)
    assert e0.status == e1.status == "ok", (e0.message, e1.message)
    c = e0.clearance_m
    np.testing.assert_allclose(e1.journal_x_m / c, e0.journal_x_m / c, rtol=0, atol=1e-9)
    np.testing.assert_allclose(e1.journal_y_m / c, e0.journal_y_m / c, rtol=0, atol=1e-9)
    load = np.abs(e0.film_force_n).max()
    np.testing.assert_allclose(e1.film_force_n, e0.film_force_n, rtol=0, atol=1e-9 * load)
    asm0, asm1 = assembled(s), assembled(off)
    Kc = np.asarray(asm0.model.Kc)
    u0 = e0.r + asm0.config_vector()
    u1 = e1.r + asm1.config_vector()
    np.testing.assert_allclose(Kc @ u1, Kc @ u0, rtol=0, atol=1e-9 * np.abs(Kc @ u0).max())


@pytest.fixture(scope="module")
def train():
    """The train (5 Guyan masters), B2 raised by 40 µm, β = 4e-5 s rotating, at 50 Hz."""
    s = rd.System.from_toml(MODELS / "motor_fan_train_guyan.toml")
    return _offsets(_rotating(s, 4e-5), B2={"config_ay_m": 4e-5})


def test_train_equilibrium_carries_the_offsets_circulatory_load(train):
    f = 50.0
    w = 2 * np.pi * f
    e = rd.equilibrium(train, f)
    assert e.status == "ok", e.message
    m = assembled(train).model
    a = assembled(train).config_vector()
    K, Kc, Q = (np.asarray(x) for x in (m.K, m.Kc, m.Q))
    u = e.r + a
    res = K @ u + w * (Kc @ u) - e.film_force_n - Q
    scale = max(np.abs(Q).max(), np.abs(K @ a).max())
    assert np.abs(res).max() <= 1e-9 * scale, np.abs(res).max() / scale
    # against stationary β the journals move by the circulatory load −Ω K_c (r + a) through
    # the stiffness K + Ω K_c + K_H, to first order (measured: 2.5e-4 to 3.7e-4 c; the
    # offsets' part K_c a is about half of K_c (r + a) here)
    still_sys = _rotating(train, 4e-5, rotating=False)
    still = rd.equilibrium(still_sys, f)
    asm = assembled(train)
    J = K + np.asarray(asm.solver.linearize(still.r, np.zeros(len(u)), w).KH)  # has Ω K_c
    pred = -np.linalg.solve(J, w * (Kc @ (still.r + a)))
    bc = asm.bearings
    for i, b in enumerate(bc):
        d = np.array([e.r[b.jx] - still.r[b.jx], e.r[b.jy] - still.r[b.jy]])
        p = np.array([pred[b.jx], pred[b.jy]])
        assert np.linalg.norm(d) > 1e-4 * b.clearance_m
        assert np.linalg.norm(d - p) <= 0.02 * np.linalg.norm(d), (d, p)
    assert np.abs(Kc @ a).max() > 0.2 * np.abs(Kc @ u).max()


def test_train_transient_and_orbit_start_at_the_equilibrium(train):
    f = 50.0
    e = rd.equilibrium(train, f)
    tr = rd.transient(train, 0.02, f, n_out=5)
    assert tr.status == "ok", tr.message
    drift = np.abs(np.asarray(tr.r) - e.r[None, :]).max()
    assert drift <= 1e-7 * e.clearance_m.max(), drift
    hb = rd.periodic_orbit(train, f, kind="forced", unbalances=[(2, 1e-9, 0.0)],
                           method="harmonic_balance", harmonics=2)
    assert hb.ok, hb.message
    mean = np.asarray(hb.r).mean(axis=0)
    assert np.abs(mean - e.r).max() <= 1e-7 * e.clearance_m.max()


def test_equilibrium_branch_over_the_offset_with_rotating_damping():
    s = _rotating(rd.System.from_toml(MODELS / "compressor_active.toml"), 4e-5)
    br = rd.continuation(s, "config_ay_m", (0.0, 4e-5), speed_hz=100.0, max_points=6,
                         refine=False)
    assert br.ok, br.message
    df = br.to_frame()
    name = "DE active bearing"
    pts = df[df.bearing == name]
    assert len(pts) >= 4 and pts.config_ay_m.max() > 0
    for _, row in pts.iloc[1:4].iterrows():
        e = rd.equilibrium(s, 100.0, config_ay_m=float(row.config_ay_m))
        i = e.bearing_names.index(name)
        c = e.clearance_m[i]
        assert row.journal_x_m == pytest.approx(e.journal_x_m[i], abs=1e-7 * c)
        assert row.journal_y_m == pytest.approx(e.journal_y_m[i], abs=1e-7 * c)


def test_static_analysis_carries_the_circulatory_force():
    """rotordyn.static with rotating damping (refused before). The Jeffcott rotor of
    tests/test_rotor_damping.py (rigid supports, 9.9 kg disk at mid-span, β = 1e-4 s,
    c_i = βk): its disk sits where K r + Ω K_c r = Q puts it, y = y₀k²/(k² + Ω²c_i²),
    x = −y₀kΩc_i/(k² + Ω²c_i²) (1e-9), and its deflection at the disk equals
    rotordyn.equilibrium's; the reactions carry the weight and no sideways resultant (K_c has
    none: 1e-9 of the weight) and stay vertical, and the internal shear and moment in yz are
    the stationary-damping rotor's (1e-9) and vanish in xz (1e-9 of yz's) though the shaft is
    bent sideways: its elastic and damping stresses balance there."""
    import math

    from test_rotor_damping import _jeffcott, _jeffcott_constants

    c_e, beta = 20.0, 1e-4
    s = _jeffcott(c_e, beta)
    m, k, c_i, w_th = _jeffcott_constants(c_e, beta)
    y0 = rd.equilibrium(s, 0.0).r[1]  # the sag at rest (the consistent gravity load)
    for f in (0.5 * w_th / (2 * math.pi), 2.0 * w_th / (2 * math.pi)):
        w = 2 * math.pi * f
        st = rd.static(s, f)
        assert st.status == "ok"
        d = k * k + (w * c_i) ** 2
        mid = int(np.argmin(np.abs(st.node_positions_m - 0.3)))
        x, y = st.deflection_x_m[mid], st.deflection_y_m[mid]
        np.testing.assert_allclose([x, y], [-y0 * k * w * c_i / d, y0 * k * k / d], rtol=1e-9)
        e = rd.equilibrium(s, f)
        np.testing.assert_allclose([x, y], e.r[:2], rtol=1e-9, atol=1e-12 * abs(y0))
        assert x > 0  # towards the motion of the bottom of the shaft
        R = st.reactions
        assert R.force_y_n.sum() == pytest.approx(st.weight_n, rel=1e-9)
        assert abs(R.force_x_n.sum()) <= 1e-9 * st.weight_n
        rigid = R[R.kind == "rigid"]
        # the bend turns sideways but the reactions do not: the elastic and the internal
        # damping stresses balance each other in the xz plane, so the total internal moment
        # there (end forces with (K_e + Ω K_c,e) u_e) vanishes while the shaft's curvature in
        # xz does not; in yz it is the reaction's moment
        assert abs(rigid.force_x_n).max() <= 1e-9 * st.weight_n
        still = rd.static(_jeffcott(c_e, beta, rotating=False), f)
        np.testing.assert_allclose(st.moment_yz_n_m, still.moment_yz_n_m, rtol=1e-9,
                                   atol=1e-9 * abs(still.moment_yz_n_m).max())
        np.testing.assert_allclose(st.shear_y_n, still.shear_y_n, rtol=1e-9,
                                   atol=1e-9 * abs(still.shear_y_n).max())
        assert abs(st.moment_xz_n_m).max() <= 1e-9 * abs(st.moment_yz_n_m).max()
        assert abs(still.deflection_x_m).max() <= 1e-12 * abs(y0)


def test_static_on_plain_bearings_with_guyan_masters():
    """The compressor on plain bearings (Guyan masters), β = 4e-5 s rotating, 100 Hz, the NDE
    housing offset: the slaves are recovered with K + Ω K_c, so every free node is in
    equilibrium — the shear and moment vanish at the rotor's free ends (1e-9 of the weight,
    1e-9 of the largest moment), the films carry the weight and no sideways resultant."""
    s = _rotating(rd.System.from_toml(MODELS / "compressor_plain.toml"), 4e-5)
    s = _offsets(s, **{s.bearings[0].name: {"config_ay_m": 2e-5}})
    st = rd.static(s, 100.0)
    assert st.status == "ok", st.message
    W = st.weight_n
    assert st.reactions.force_y_n.sum() == pytest.approx(W, rel=1e-9)
    assert abs(st.reactions.force_x_n.sum()) <= 1e-9 * W
    Mmax = max(abs(st.moment_yz_n_m).max(), abs(st.moment_xz_n_m).max())
    for k in (0, -1):
        assert abs(st.shear_x_n[k]) <= 1e-9 * W and abs(st.shear_y_n[k]) <= 1e-9 * W
        assert abs(st.moment_xz_n_m[k]) <= 1e-9 * Mmax
        assert abs(st.moment_yz_n_m[k]) <= 1e-9 * Mmax
