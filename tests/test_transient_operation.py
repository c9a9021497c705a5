"""Time-varying operation of the nonlinear transient (issue 8): speed profiles, pressure
commands, actuator limits, controllers in the loop, and their input checks.

References and tolerances:
- A table p_c(t) equal to a constant takes the same arithmetic path as the constant: the
  runs agree bit for bit.
- Saturation and rate limit: p_c inside [p_min, p_max] exactly (clipped output), and
  |Δp_c| ≤ R Δt between stored samples up to CVODE's interpolation error (1 Pa).
- Slow run-up (5 Hz/s, 55 → 65 Hz, between the rig's critical speeds 38 and 88 Hz): the 1×
  component (least squares on [1, t, cos θ, sin θ] over ±4 revolutions, θ the integrated
  rotor angle) equals the steady linear unbalance response at that speed within 3 %
  (the ramp's quasi-steady lag is O(Ω̇/(ζ ω_n²)) ≈ 0.5 % here; the free vibrations of the
  rig's lightly damped 38 Hz modes, which a max-min amplitude would include, are rejected
  by the fit).
- Ω̇ term: a 2-DOF Jeffcott rotor accelerated from rest through its critical speed at
  100 Hz/s (Ω̇/ω_n² = 0.16) against
  SciPy solve_ivp (DOP853, rtol 1e-11) of m ẍ + c ẋ + k x = m e (Ω² cos θ + Ω̇ sin θ),
  m ÿ + c ẏ + k y = m e (Ω² sin θ − Ω̇ cos θ): agreement to 1e-5 of the peak amplitude,
  while dropping the Ω̇ term changes the response by more than 10 % of the peak.
- Zero-gain controllers: a static one reproduces the open loop bit for bit; one with states
  (integrated by CVODE, changing its step sequence) within 1e-3 of the disturbance.
- A ZOH-discretised controller with a sample time of 1/40 000 s matches its continuous
  counterpart within 3 % of the disturbance (ZOH delay T/2 = 12.5 µs against a 0.1 s decay).
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.control import Actuator, Controller, PressureSchedule, SpeedProfile
from rotordyn.units import hz_to_rad_s

C_RIG = 3e-4
AY = -1.85e-3


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_table_equal_to_constant_is_bit_for_bit(rig):
    kw = dict(disturbance_m=(0.1 * C_RIG, 0.0), n_out=51)
    a = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, **kw)
    b = rd.transient(rig, 0.05, 50.0, 0.15e6, AY,
                     pressure=PressureSchedule.time_table([0.0, 0.02, 0.05], [0.15e6] * 3), **kw)
    assert a.status == b.status == "ok"
    assert np.array_equal(a.r, b.r) and np.array_equal(a.v, b.v)
    assert np.all(b.chamber_pressure_actual_pa == 0.15e6)
    assert np.all(b.speed_hz_t == 50.0)


def test_slow_runup_passes_the_steady_unbalance_response(rig):
    pc, ub = 0.4e6, [(6, 2e-5, 0.0)]
    f0, f1, rate = 55.0, 65.0, 5.0
    asm = assembled(rig)
    lm = rd.linearize(rig, f0, pc, 0.0)
    w = hz_to_rad_s(f0)
    L = asm.station_load_matrix(6)
    q = np.linalg.solve(lm.K - w**2 * lm.M + 1j * w * lm.D, w**2 * 2e-5 * (L[:, 0] - 1j * L[:, 1]))
    T = (f1 - f0) / rate
    tr = rd.transient(rig, T, f0, pc, 0.0, unbalances=ub, r0=lm.equilibrium.r + q.real,
                      v0=(1j * w * q).real, n_out=int(T * f1 * 40) + 1, rtol=1e-7,
                      atol_m=1e-11, speed=SpeedProfile.ramp(f0, f1, rate))
    assert tr.status == "ok", tr.message
    assert tr.speed_hz_t[-1] == pytest.approx(f1)
    # θ is the exact integral of the ramp
    assert tr.angle_rad[-1] == pytest.approx(hz_to_rad_s(0.5 * (f0 + f1) * T), rel=1e-12)
    sp = np.arange(f0 + 0.5, f1 - 0.4, 1.0)
    u = rd.unbalance_response(rig, ub, sp, stations=[4], chamber_pressure_pa=pc, config_ay_m=0.0)
    for k, f in enumerate(sp):
        tc = (f - f0) / rate
        win = np.abs(tr.t - tc) < 4 / f
        th, tt = tr.angle_rad[win], tr.t[win] - tc
        A = np.column_stack([np.ones_like(tt), tt, np.cos(th), np.sin(th)])
        for z, ref in ((tr.journal_x_m[win, 0], u.x[k, 0]), (tr.journal_y_m[win, 0], u.y[k, 0])):
            c = np.linalg.lstsq(A, z, rcond=None)[0]
            assert np.hypot(c[2], c[3]) == pytest.approx(abs(ref), rel=0.03), f


def _jeffcott_core(m, k, c):
    s = _core.SystemModel()
    s.M, s.K, s.C = m * np.eye(2), k * np.eye(2), c * np.eye(2)
    s.G = np.zeros((2, 2))
    s.Q = np.zeros(2)
    s.chamber = np.zeros(2)
    s.films = []
    return _core.SystemSolver(s)


def test_angular_acceleration_term_on_a_jeffcott_rotor():
    m, k, zeta, me = 10.0, 10.0 * (2 * np.pi * 10.0) ** 2, 0.02, 1e-4
    c = 2 * zeta * math.sqrt(k * m)
    alpha = hz_to_rad_s(100.0)  # rad/s²: 0 -> 25 Hz in 0.25 s, through the 10 Hz critical
    T = 0.25
    inp = _core.TransientInput()
    inp.omega = 0.0
    inp.a = np.zeros(2)
    inp.unbalance_cos = me * np.array([1.0, 0.0])  # F = Ω²(u_c cos θ + u_s sin θ) − Ω̇(...)
    inp.unbalance_sin = me * np.array([0.0, 1.0])
    inp.r0, inp.v0 = np.zeros(2), np.zeros(2)
    inp.t_out = np.linspace(0, T, 401)
    sp = _core.SpeedProfile()
    sp.t, sp.omega = np.array([0.0, T]), np.array([0.0, alpha * T])
    inp.speed = sp
    opt = _core.CvodeOptions()
    opt.rtol, opt.atol_position, opt.atol_velocity = 1e-10, 1e-14, 1e-12
    res = _core.integrate(_jeffcott_core(m, k, c), inp, opt)
    assert res.status == "ok", res.message
    assert np.allclose(res.angle, 0.5 * alpha * inp.t_out**2, rtol=1e-14, atol=1e-15)

    def ref(with_tangential):
        def f(t, y):
            th, W = 0.5 * alpha * t * t, alpha * t
            Wd = alpha if with_tangential else 0.0
            fx = me * (W * W * np.cos(th) + Wd * np.sin(th))
            fy = me * (W * W * np.sin(th) - Wd * np.cos(th))
            return [y[2], y[3], (fx - c * y[2] - k * y[0]) / m, (fy - c * y[3] - k * y[1]) / m]
        return solve_ivp(f, (0, T), np.zeros(4), method="DOP853", t_eval=inp.t_out,
                         rtol=1e-11, atol=1e-15).y[:2].T

    full, radial_only = ref(True), ref(False)
    peak = np.abs(full).max()
    assert np.abs(np.asarray(res.r) - full).max() < 1e-5 * peak
    assert np.abs(radial_only - full).max() > 0.05 * peak  # the term matters here


def test_zero_gain_controllers_reproduce_the_open_loop(rig):
    kw = dict(disturbance_m=(0.1 * C_RIG, 0.0), n_out=51, rtol=1e-8, atol_m=1e-12)
    ol = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, **kw)
    k0 = Controller.static(np.zeros((1, 4)), [("journal", 0), ("journal_velocity", 0)])
    cl = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, controller=k0, **kw)
    assert np.array_equal(ol.r, cl.r)
    assert np.all(cl.controller_output_pa == 0.0)
    kd = Controller(-100.0 * np.eye(2), 1e3 * np.eye(2), np.zeros((1, 2)), np.zeros((1, 2)),
                    [("journal", 0)])
    cl2 = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, controller=kd, **kw)
    assert cl2.status == "ok"
    assert np.abs(cl2.controller_states).max() > 0  # its states did run
    assert np.abs(ol.r - cl2.r).max() < 1e-3 * 0.1 * C_RIG


def test_discrete_controller_with_tiny_sample_time_matches_continuous(rig):
    import control

    # A low-passed proportional feedback on the journal's vertical motion: u = -kp/(τ s + 1) y.
    kp, tau = 2e9, 5e-4  # Pa/m, s
    kc = control.ss(control.tf([-kp], [tau, 1.0]))
    meas = [("journal", 0)]
    Bc = np.hstack([np.zeros((1, 1)), np.asarray(kc.B)])
    Dc = np.hstack([np.zeros((1, 1)), np.asarray(kc.D)])
    cont = Controller(np.asarray(kc.A), Bc, np.asarray(kc.C), Dc, meas)
    Ts = 2.5e-5
    kz = control.c2d(kc, Ts, method="zoh")
    disc = Controller(np.asarray(kz.A), np.hstack([np.zeros((1, 1)), np.asarray(kz.B)]),
                      np.asarray(kz.C), np.hstack([np.zeros((1, 1)), np.asarray(kz.D)]), meas,
                      sample_time_s=Ts)
    kw = dict(disturbance_m=(0.0, 0.05 * C_RIG), n_out=41, rtol=1e-8, atol_m=1e-12)
    # the continuous law given as the python-control system itself, with its measurements
    a = rd.transient(rig, 0.02, 50.0, 0.15e6, AY, controller=cont.to_control(),
                     measurements=meas, **kw)
    b = rd.transient(rig, 0.02, 50.0, 0.15e6, AY, controller=disc, **kw)
    ol = rd.transient(rig, 0.02, 50.0, 0.15e6, AY, **kw)
    assert a.status == b.status == "ok"
    d = 0.05 * C_RIG
    assert np.abs(a.r - ol.r).max() > 0.05 * d  # the feedback acts
    assert np.abs(a.r - b.r).max() < 0.03 * d
    with pytest.raises(rd.InputError, match="measurements"):
        rd.transient(rig, 0.02, 50.0, 0.15e6, AY, controller=cont.to_control(), **kw)


def test_saturation_and_rate_limits_hold_in_every_sample(rig):
    act = Actuator(order=2, natural_frequency_hz=100.0, damping=0.5, p_min_pa=0.1e6,
                   p_max_pa=0.2e6, rate_limit_pa_s=2e7)
    sched = PressureSchedule.constant(0.15e6).with_harmonic(0.1e6, frequency_hz=60.0)
    tr = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, pressure=sched, actuator=act, n_out=2001)
    assert tr.status == "ok", tr.message
    p, cmd = tr.chamber_pressure_actual_pa, tr.chamber_pressure_command_pa
    assert cmd.max() > 0.24e6 and cmd.min() < 0.06e6  # the command leaves the limits
    assert p.min() >= 0.1e6 and p.max() <= 0.2e6
    # |Δp| ≤ R Δt between stored samples, up to the integration tolerance (atol_pa = 1 Pa)
    dp, dt = np.abs(np.diff(p)), np.diff(tr.t)
    assert np.all(dp <= 2e7 * dt + 1.0)
    assert (dp / dt).max() > 0.9 * 2e7  # the rate limit is active, not idle
    assert p.max() > 0.199e6  # and the saturation


@pytest.mark.parametrize("order", [1, 2])
def test_rate_limit_holds_exactly_on_a_fast_command(rig, order):
    """Issue 21: a 200 Hz harmonic command (±0.1 MPa, peak rate 1.3e8 Pa/s) through a 1e7 Pa/s
    limit: before the switched formulation the clipped derivative let p_c overshoot the bound
    by 7.13 Pa. Now |Δp_c| ≤ R Δt + 1e-3 Pa between stored samples (the limit is exact while
    active; the free segments stay below it up to the integration error)."""
    act = Actuator(order=order, natural_frequency_hz=100.0, damping=0.7,
                   time_constant_s=1 / (2 * math.pi * 50), p_min_pa=0.0, p_max_pa=1e6,
                   rate_limit_pa_s=1e7)
    sched = PressureSchedule.constant(0.15e6).with_harmonic(0.1e6, frequency_hz=200.0)
    tr = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, pressure=sched, actuator=act, n_out=2001)
    assert tr.status == "ok", tr.message
    p, dt = tr.chamber_pressure_actual_pa, np.diff(tr.t)
    excess = np.abs(np.diff(p)) - 1e7 * dt
    assert excess.max() <= 1e-3, excess.max()
    assert (np.abs(np.diff(p)) / dt).max() > 0.99e7  # the limit is active


@pytest.mark.parametrize("order", [1, 2])
def test_a_vanishing_rate_limit_freezes_the_pressure(rig, order):
    """Issue 21: with rate_limit_pa_s = 1e-300 p_c must stay at its start (it moved by more
    than 18 Pa: Newton corrections through a Jacobian of the other branch)."""
    act = Actuator(order=order, rate_limit_pa_s=1e-300)
    sched = PressureSchedule.constant(0.15e6).with_harmonic(0.1e6, frequency_hz=200.0)
    tr = rd.transient(rig, 0.05, 50.0, 0.15e6, AY, pressure=sched, actuator=act, n_out=501)
    assert tr.status == "ok", tr.message
    p = tr.chamber_pressure_actual_pa
    assert np.abs(p - 0.15e6).max() <= 1e-6, np.abs(p - 0.15e6).max()


def test_one_per_rev_harmonic_is_locked_to_the_rotor_angle(rig):
    sched = PressureSchedule.constant(0.15e6).with_harmonic(1e3, order=1.0, phase_deg=90.0)
    tr = rd.transient(rig, 0.01, 50.0, 0.15e6, AY, pressure=sched, n_out=21)
    assert np.allclose(tr.chamber_pressure_command_pa,
                       0.15e6 + 1e3 * np.cos(tr.angle_rad), rtol=0, atol=1e-6)


def test_bad_operation_inputs_name_the_field(rig):
    with pytest.raises(rd.InputError, match="actuator.time_constant_s"):
        Actuator(order=1, time_constant_s=-1e-3)
    with pytest.raises(rd.InputError, match="actuator.natural_frequency_hz"):
        Actuator(order=2, natural_frequency_hz=0.0)
    with pytest.raises(rd.InputError, match="actuator.p_min_pa"):
        Actuator(p_min_pa=2e5, p_max_pa=1e5)
    with pytest.raises(rd.InputError, match="actuator.rate_limit_pa_s"):
        Actuator(order=0, rate_limit_pa_s=1e6)
    for st in (0.0, -1e-3):
        with pytest.raises(rd.InputError, match="controller.sample_time_s"):
            Controller.static([[1.0, 0.0]], [("journal", 0)], sample_time_s=st)
    with pytest.raises(rd.InputError, match="measurements"):
        rd.transient(rig, 0.01, 50.0, 0.15e6, AY,
                     controller=Controller.static([[1.0, 0.0]], [("displacement", 99)]))
    with pytest.raises(rd.InputError, match="measurements"):
        rd.transient(rig, 0.01, 50.0, 0.15e6, AY,
                     controller=Controller.static([[1.0, 0.0]], [("journal", 7)]))
    with pytest.raises(rd.InputError, match="controller: expected 2 inputs"):
        rd.transient(rig, 0.01, 50.0, 0.15e6, AY,
                     controller=Controller.static([[1.0, 0.0, 0.0]], [("journal", 0)]))
    with pytest.raises(rd.InputError, match="controller: expected 1 output"):
        Controller.static(np.ones((2, 2)), [("journal", 0)])
    with pytest.raises(rd.InputError, match="rate_hz_per_s"):
        SpeedProfile.ramp(10.0, 120.0, -1.0)
    with pytest.raises(rd.InputError, match="speed_profile"):
        SpeedProfile.table([0.0, 0.0], [10.0, 20.0])
    with pytest.raises(rd.InputError, match="controller"):
        rd.transient(rig, 0.01, controller="pd")
    # The core checks shapes too (a direct call with a wrong measurement matrix).
    asm = assembled(rig)
    inp = _core.TransientInput()
    inp.a = inp.r0 = inp.v0 = np.zeros(asm.n)
    inp.t_out = np.array([0.0, 1e-3])
    kc = _core.Controller()
    kc.enabled = True
    kc.A, kc.B, kc.C, kc.D = np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), np.ones((1, 1))
    kc.measurement, kc.offset = np.ones((1, 3)), np.zeros(1)
    inp.controller = kc
    with pytest.raises(rd.InputError, match="controller.measurement"):
        _core.integrate(asm.solver, inp, _core.CvodeOptions())


def test_sensor_noise_is_seeded_and_has_the_stated_spread(rig):
    """A discrete law u = 1 Pa/m · y_x (negligible feedback) with σ = 1 µm noise: its output
    at the 200 samples is the noise itself (mean 0, std σ within 15 %, the 95 % band of a
    200-sample estimate is ±10 %); the same seed repeats it, another seed does not."""
    k = Controller.static([[1.0, 0.0]], [("journal", 0)], sample_time_s=1e-3, noise_std=1e-6,
                          seed=7)
    kw = dict(n_out=201, controller=k)
    a = rd.transient(rig, 0.2, 50.0, 0.15e6, AY, **kw)
    b = rd.transient(rig, 0.2, 50.0, 0.15e6, AY, **kw)
    c = rd.transient(rig, 0.2, 50.0, 0.15e6, AY, n_out=201, controller=k.with_options(seed=8))
    u = a.controller_output_pa[1:]
    assert np.array_equal(a.controller_output_pa, b.controller_output_pa)
    assert not np.array_equal(a.controller_output_pa, c.controller_output_pa)
    assert abs(u.mean()) < 3 * 1e-6 / np.sqrt(u.size)
    assert u.std() == pytest.approx(1e-6, rel=0.15)
    df = a.to_frame()
    for col in ("speed_hz", "chamber_pressure_pa", "chamber_pressure_command_pa",
                "controller_output_pa"):
        assert col in df.columns
