"""Speed-scheduled 1× chamber-pressure commands and the synchronous bound
(rotordyn.control.synchronous).

- Harmonic tables over the speed: constant tables reproduce the constant 1×-locked harmonic
  bit for bit (same arithmetic: the interpolation of equal values returns the value); a
  scheduled table gives command = p₀ + A(Ω) sin(θ + φ(Ω)) at every stored sample (to 1e-6 Pa).
- The bound at one speed against an independent computation: the unbalance map from
  :func:`rotordyn.unbalance_response`, the command map from the plant with the valve
  (:func:`rotordyn.control.plant.plant`, C (iΩ − A)⁻¹ B), and a brute-force 401 × 401 grid
  over p̂ in the allowed disk (with the valve's limits far and near: optimum inside / on
  the limit): the golden-section optimum is at most the grid's minimum and
  at least the grid's minimum less the grid's resolution times the objective's slope bound.
- Linear 1× prediction vs the nonlinear model: a slow run-up (5 Hz/s, 55 → 65 Hz, between the
  critical speeds; as test_transient_operation) with a 1× command of 0.1 MPa locked to the
  rotor angle gives the linear model's orbit semi-major axis at the journal within 3 % (the
  quasi-steady lag is ≈ 0.5 %), while the command changes that axis by more than 20 % —
  which checks the phase convention p(t) ∋ Re(p̂ e^{iθ}) = |p̂| sin(θ + arg p̂ + 90°).
"""

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.control import Actuator, PressureSchedule, SpeedProfile
from rotordyn.control.plant import plant
from rotordyn.control.synchronous import SynchronousBound, semi_major, synchronous_bound
from rotordyn.units import hz_to_rad_s

UB = [(6, 2e-5, 0.0)]
P0 = 0.5e6


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_constant_harmonic_tables_are_bit_for_bit(rig):
    kw = dict(unbalances=UB, speed=SpeedProfile.ramp(50.0, 55.0, 100.0), n_out=101)
    const = PressureSchedule.constant(P0).with_harmonic(2e4, order=1.0, phase_deg=30.0)
    table = PressureSchedule.constant(P0).with_harmonic_schedule(
        [40.0, 50.0, 52.0, 60.0], [2e4] * 4, [30.0] * 4, order=1.0)
    a = rd.transient(rig, 0.05, 50.0, config_ay_m=0.0, pressure=const, **kw)
    b = rd.transient(rig, 0.05, 50.0, config_ay_m=0.0, pressure=table, **kw)
    assert a.status == b.status == "ok"
    assert np.array_equal(a.r, b.r) and np.array_equal(a.v, b.v)
    assert np.array_equal(a.chamber_pressure_command_pa, b.chamber_pressure_command_pa)
    assert np.ptp(a.speed_hz_t) > 4.9  # the speed (the table's abscissa) did move


def test_scheduled_harmonic_follows_its_tables(rig):
    f, A, ph = [49.0, 51.0, 53.0, 56.0], [1e4, 3e4, 0.0, 5e4], [0.0, 90.0, 400.0, -30.0]
    sched = PressureSchedule.constant(P0).with_harmonic_schedule(f, A, ph)
    tr = rd.transient(rig, 0.05, 50.0, config_ay_m=0.0, pressure=sched,
                      speed=SpeedProfile.ramp(50.0, 55.0, 100.0), n_out=201)
    assert tr.status == "ok", tr.message
    s = tr.speed_hz_t
    ref = P0 + np.interp(s, f, A) * np.sin(tr.angle_rad + np.radians(np.interp(s, f, ph)))
    assert np.abs(tr.chamber_pressure_command_pa - ref).max() < 1e-6
    with pytest.raises(rd.InputError, match="harmonic schedule"):
        PressureSchedule.constant(P0).with_harmonic_schedule([50.0, 49.0], [1.0, 1.0], [0, 0])
    with pytest.raises(rd.InputError, match="harmonic schedule"):
        PressureSchedule.constant(P0).with_harmonic_schedule([50.0, 51.0], [1.0], [0, 0])
    with pytest.raises(rd.InputError, match="order"):
        PressureSchedule.constant(P0).with_harmonic_schedule([50.0], [1.0], [0], order=0.0)
    # the core checks the tables too (a direct call with mismatched lengths)
    from rotordyn import _core

    asm = assembled(rig)
    inp = _core.TransientInput()
    inp.a = inp.r0 = inp.v0 = np.zeros(asm.n)
    inp.t_out = np.array([0.0, 1e-3])
    pc = sched.to_core()
    pc.harmonic_table_phase = np.zeros(2)
    inp.pressure = pc
    with pytest.raises(rd.InputError, match="harmonic tables"):
        _core.integrate(asm.solver, inp, _core.CvodeOptions())


@pytest.mark.parametrize("p_lim", [(0.0, 1e6), (0.49e6, 0.51e6)])  # limit inactive / active
def test_synchronous_bound_against_brute_force(rig, p_lim):
    f, stations = 38.5, [4, 6]
    act = Actuator(p_min_pa=p_lim[0], p_max_pa=p_lim[1])
    sb = synchronous_bound(rig, UB, [f], [P0], stations=stations, config_ay_m=0.0, actuator=act)
    assert isinstance(sb, SynchronousBound) and sb.status[0, 0] == "ok"
    # independent maps: unbalance_response (a) and the plant with the valve (b)
    u = rd.unbalance_response(rig, UB, [f], stations=stations, chamber_pressure_pa=P0,
                              config_ay_m=0.0)
    a = np.stack([u.x[0], u.y[0]], axis=-1)  # (n_st, 2)
    p = plant(rig, f, P0, 0.0, measurements=[("displacement", s) for s in stations],
              actuator=act)
    w = hz_to_rad_s(f)
    b = (p.C @ np.linalg.solve(1j * w * np.eye(p.A.shape[0]) - p.A, p.B))[:, 0].reshape(-1, 2)
    assert np.allclose(sb.a[0, 0], a, rtol=1e-6, atol=1e-6 * np.abs(a).max())
    assert np.allclose(sb.b[0, 0], b, rtol=1e-6, atol=1e-6 * np.abs(b).max())
    lim = min(P0 - act.p_min_pa, act.p_max_pa - P0)
    g = np.linspace(-lim, lim, 401)
    P = (g[:, None] + 1j * g[None, :]).ravel()
    P = P[np.abs(P) <= lim]
    Z = a[None] + b[None] * P[:, None, None]
    obj = semi_major(Z[..., 0], Z[..., 1]).max(axis=1)
    slope = (np.abs(b[:, 0]) + np.abs(b[:, 1])).max()
    h = g[1] - g[0]
    assert sb.objective[0, 0] <= obj.min() * (1 + 1e-9)
    assert sb.objective[0, 0] >= obj.min() - slope * h
    assert abs(sb.p_hat_pa[0, 0]) <= lim * (1 + 1e-9)
    if p_lim[1] - p_lim[0] < 1e5:
        assert abs(sb.p_hat_pa[0, 0]) == pytest.approx(lim, rel=1e-6)  # on the limit
        assert sb.objective[0, 0] < 0.95 * sb.objective_passive[0, 0]
    else:
        assert abs(sb.p_hat_pa[0, 0]) < 0.9 * lim  # inside
        assert sb.objective[0, 0] < 0.5 * sb.objective_passive[0, 0]  # the 1× command helps
    assert sb.objective_passive[0, 0] == pytest.approx(semi_major(a[:, 0], a[:, 1]).max())
    # re-optimised for the journal alone (the disk's reference 1e6 times larger)
    sj = sb.with_references([1e-6, 1.0])
    objj = semi_major(Z[:, 0, 0], Z[:, 0, 1])
    assert objj.min() - slope * h <= sj.optimal_m[0, 0, 0] <= objj.min() * (1 + 1e-9)
    with pytest.raises(rd.InputError, match="references_m"):
        synchronous_bound(rig, UB, [f], [P0], stations=stations, config_ay_m=0.0,
                          references_m=[1.0, 0.0])
    with pytest.raises(rd.InputError, match="pressures_pa"):
        synchronous_bound(rig, UB, [f], [2e6], stations=stations, config_ay_m=0.0)


def test_linear_1x_prediction_matches_the_nonlinear_run_up(rig):
    f0, f1, rate = 55.0, 65.0, 5.0
    p_hat = 0.1e6 * np.exp(1j * np.radians(40.0))
    sp = np.arange(f0 + 0.5, f1 - 0.4, 1.0)
    sb = synchronous_bound(rig, UB, sp, [P0], stations=[4], config_ay_m=0.0)
    Zlin = sb.a[:, 0, 0] + sb.b[:, 0, 0] * p_hat  # (n_s, 2)
    lin = semi_major(Zlin[:, 0], Zlin[:, 1])
    assert np.all(np.abs(lin / sb.passive_m[:, 0, 0] - 1) > 0.2)
    sched = PressureSchedule.constant(P0).with_harmonic(
        abs(p_hat), order=1.0, phase_deg=float(SynchronousBound.harmonic_phase_deg(p_hat)))
    asm = assembled(rig)
    lm = rd.linearize(rig, f0, P0, 0.0)
    w = hz_to_rad_s(f0)
    Zs = lm.K - w**2 * lm.M + 1j * w * lm.D
    L = asm.station_load_matrix(6)
    num, den = Actuator().transfer_function()
    H = np.polyval(num, 1j * w) / np.polyval(den, 1j * w)
    q = np.linalg.solve(Zs, w**2 * 2e-5 * (L[:, 0] - 1j * L[:, 1]) + H * p_hat * lm.chamber)
    T = (f1 - f0) / rate
    tr = rd.transient(rig, T, f0, config_ay_m=0.0, unbalances=UB, pressure=sched,
                      actuator=Actuator(), r0=lm.equilibrium.r + q.real, v0=(1j * w * q).real,
                      n_out=int(T * f1 * 40) + 1, rtol=1e-7, atol_m=1e-11,
                      speed=SpeedProfile.ramp(f0, f1, rate))
    assert tr.status == "ok", tr.message
    Co = asm.station_output_matrix(4)
    z = tr.r @ Co.T
    for k, f in enumerate(sp):
        tc = (f - f0) / rate
        win = np.abs(tr.t - tc) < 4 / f
        th, tt = tr.angle_rad[win], tr.t[win] - tc
        A = np.column_stack([np.ones_like(tt), tt, np.cos(th), np.sin(th)])
        c = np.linalg.lstsq(A, z[win], rcond=None)[0]
        X, Y = c[2] - 1j * c[3]  # x = Re(X e^{iθ})
        assert semi_major(X, Y) == pytest.approx(lin[k], rel=0.03), f


def test_synchronous_bound_refuses_bad_unbalances(rig):
    """A NaN or missing unbalance is an InputError naming it (it came back as status ok with a
    NaN objective and an arbitrary p̂)."""
    with pytest.raises(rd.InputError, match=r"unbalances\[0\]\.mass_kg_m"):
        synchronous_bound(rig, [(6, float("nan"), 0.0)], [38.5], [0.5e6], stations=[4])
    with pytest.raises(rd.InputError, match="unbalances: expected at least one"):
        synchronous_bound(rig, [], [38.5], [0.5e6], stations=[4])
