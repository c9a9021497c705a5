"""Anti-windup for the valve's saturation and rate limit (issue 24): back-calculation and
conditioning, continuous and discrete laws.

References and tolerances:
- Inside the limits the correction û − u is exactly 0, and with conditioning clip(ff) = ff:
  the right-hand side takes the same arithmetic and the transient with anti-windup equals
  the one without bit for bit (r, v, controller states), on runs whose command never leaves
  [p_min, p_max] and whose rate never reaches the limit (a varying schedule inside the
  limits for conditioning; the sample-and-hold law too).
- The law saturates (a speed dip moves the equilibrium beyond what a ±1 kPa valve can hold,
  so the PID's integrator winds up): with anti-windup the command leaves saturation at least
  50 ms sooner and the integrated squared error after the episode is less than half
  (Åström & Hägglund, Advanced PID Control, 2006, §3.5 shows the same comparison), with and
  without a rate limit and for the law discretised (Tustin: the ZOH law of this PID closes
  an unstable loop at T ≥ 0.5 ms).
- The schedule saturates (a 0.6 MPa pulse on a valve stopping at 0.2 MPa; continuous and
  sampled at 1 kHz): back-calculation is worse than none (it drives the law's output to the
  schedule's unrealisable part), and conditioning better than both (less than half the
  error of none after the pulse on the rig; on the compressor, where the pulse hardly winds
  the law up, within 10 % of none while back-calculation is 10× worse).
- Default gains: C L = 2π · bandwidth (continuous) or 1 − e^{−ω_t T} (discrete) to
  round-off; Hanus's gain B D⁺ puts the eigenvalues of A − L C on the PID's zeros (closed
  form, 1e-9); A − L C is stable or refused.
"""
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import Actuator, PressureSchedule
from rotordyn.control.antiwindup import (hanus_gain, law_bandwidth_hz, tracking_matrix,
                                         with_anti_windup)
from rotordyn.control.export import discretise
from rotordyn.control.pid import pid
from rotordyn.errors import InputError

C_RIG, AY, F = 3e-4, -1.85e-3, 50.0
MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def rig_pid():
    return pid(KP, KD, KP / TI)


KP, KD, TI = 1.0e9, 2.5e6, 0.05
PC = 0.15e6


def error_after(tr, t0, jx, jy, clearance):
    m = tr.t >= t0
    e = np.hypot(tr.r[m, jx] - tr.equilibrium_r[jx], tr.r[m, jy] - tr.equilibrium_r[jy])
    ise = float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t[m])))
    big = tr.t[m][e > 0.01 * clearance]
    return ise, float(big.max()) if big.size else t0


def test_default_gain_and_refusals():
    k = rig_pid()
    aw = with_anti_windup(k)
    assert math.isclose(float(k.C[0] @ aw.anti_windup_gain),
                        2 * math.pi * law_bandwidth_hz(k), rel_tol=1e-14)
    assert np.linalg.eigvals(tracking_matrix(k, aw.anti_windup_gain)).real.max() < 0
    # Åström–Hägglund: ω_t = 1/√(T_i T_d) = √(k_i/k_d) for the ideal PID (the derivative
    # filter τ_d = 0.2 ms moves it by 3.6 %)
    assert aw.info["tracking_rate_hz"] == pytest.approx(math.sqrt(KP / TI / KD) / (2 * math.pi),
                                                        rel=5e-2)
    assert np.count_nonzero(aw.anti_windup_gain) == 1  # on the integrator only
    with pytest.raises(InputError, match="static law"):
        with_anti_windup(rd.control.Controller.static([[1e9, 0.0]], [("journal", 0)]))
    for bad in (math.nan, math.inf, -5.0, 0.0):
        with pytest.raises(InputError, match="tracking_rate_hz"):
            with_anti_windup(k, bad)
    with pytest.raises(InputError, match="mode"):
        with_anti_windup(k, mode="hanus")
    with pytest.raises(InputError, match="gain"):
        with_anti_windup(k, gain="observer")
    with pytest.raises(InputError, match="controller.anti_windup_mode"):
        k.with_options(anti_windup_mode="clamping")
    with pytest.raises(InputError, match="controller.anti_windup_mode"):
        k.with_options(anti_windup_mode="conditioning")  # no gain
    with pytest.raises(InputError, match="gain"):
        with_anti_windup(pid(0.0, 0.0, 1e9), gain="hanus")  # D = 0: no realisable input
    with pytest.raises(InputError, match="controller.anti_windup_gain"):
        discretise(aw, 1e-4)  # the continuous gain does not carry over
    # the mode travels with the gain: kept by scaled(), dropped with it by with_washout()
    cond = with_anti_windup(k, mode="conditioning")
    assert cond.to_core(np.zeros((2, 2)), np.zeros(2)).realise_schedule
    assert not aw.to_core(np.zeros((2, 2)), np.zeros(2)).realise_schedule
    assert cond.scaled(2.0).anti_windup_mode == "conditioning"
    assert float(cond.scaled(2.0).C[0] @ cond.scaled(2.0).anti_windup_gain) == pytest.approx(
        float(k.C[0] @ cond.anti_windup_gain), rel=1e-15)
    w = cond.with_washout(1.0)
    assert w.anti_windup_gain is None and w.anti_windup_mode == "back-calculation"
    with pytest.raises(InputError, match="gain"):
        with_anti_windup(k, gain=[0.0, 1.0])  # A − L C: ẋ_i gains +k_i x_i, unstable


def test_discrete_and_hanus_gains():
    k = rig_pid()
    T = 5e-4
    kd = discretise(k, T, "tustin")
    aw = with_anti_windup(kd)
    w = 2 * math.pi * aw.info["tracking_rate_hz"]
    assert w == pytest.approx(2 * math.pi * law_bandwidth_hz(kd), rel=1e-14)
    assert float(kd.C[0] @ aw.anti_windup_gain) == pytest.approx(-math.expm1(-w * T), rel=1e-12)
    assert aw.info["tracking_max_abs"] < 1
    # on the integrator (z = 1) only: the gain is orthogonal to the filter's left eigenvector
    lam, W = np.linalg.eig(kd.A.T)
    filt = W[:, np.argmin(np.abs(lam))]
    assert abs(filt @ aw.anti_windup_gain) < 1e-12 * np.linalg.norm(aw.anti_windup_gain)
    # Hanus: A − B D⁺ C has the law's zeros, (k_p τ + k_d) s² + (k_p + k_i τ) s + k_i = 0
    tau, ki = k.info["tau_d_s"], KP / TI
    L = hanus_gain(k)
    assert np.allclose(L, k.B @ k.D[0] / (k.D[0] @ k.D[0]), rtol=1e-15)
    zeros = np.sort_complex(np.roots([KP * tau + KD, KP + ki * tau, ki]))
    got = np.sort_complex(np.linalg.eigvals(tracking_matrix(k, L)))
    assert np.allclose(got, zeros, rtol=1e-9)
    h = with_anti_windup(k, gain="hanus", mode="conditioning")
    assert h.info["anti_windup"] == "conditioning" and h.info["anti_windup_gain"] == "hanus"
    assert h.info["tracking_rate_hz"] == pytest.approx(np.abs(zeros).min() / (2 * math.pi))


@pytest.mark.parametrize("order", [1, 2])
def test_inside_the_limits_bit_for_bit(rig, order):
    act = Actuator(order=order, p_min_pa=0.0, p_max_pa=1e6, rate_limit_pa_s=1e9)
    k = rig_pid()
    kw = dict(disturbance_m=(0.0, 0.02 * C_RIG), n_out=101, actuator=act)
    a = rd.transient(rig, 0.05, F, PC, AY, controller=k, **kw)
    b = rd.transient(rig, 0.05, F, PC, AY, controller=with_anti_windup(k), **kw)
    assert a.status == b.status == "ok"
    cmd = a.chamber_pressure_command_pa
    assert cmd.min() > act.p_min_pa and cmd.max() < act.p_max_pa
    assert np.array_equal(a.r, b.r) and np.array_equal(a.v, b.v)
    assert np.array_equal(a.controller_states, b.controller_states)


@pytest.mark.parametrize("discrete", [False, True], ids=["continuous", "discrete"])
def test_conditioning_inside_the_limits_bit_for_bit(rig, discrete):
    """A schedule that varies inside the limits (clip(ff) = ff exactly) and a sample-and-hold
    law: none, back-calculation and conditioning give the same run bit for bit."""
    act = Actuator(order=1, p_min_pa=0.0, p_max_pa=1e6, rate_limit_pa_s=1e9)
    k = discretise(rig_pid(), 5e-4, "tustin") if discrete else rig_pid()
    sched = PressureSchedule.time_table([0.0, 0.01, 0.03], [PC, 1.2 * PC, PC])
    kw = dict(disturbance_m=(0.0, 0.02 * C_RIG), n_out=101, actuator=act, pressure=sched)
    runs = [rd.transient(rig, 0.04, F, config_ay_m=AY, controller=law, **kw) for law in
            (k, with_anti_windup(k), with_anti_windup(k, mode="conditioning"))]
    assert all(r.status == "ok" for r in runs)
    cmd = runs[0].chamber_pressure_command_pa
    assert cmd.min() > act.p_min_pa and cmd.max() < act.p_max_pa
    assert np.ptp(cmd) > 0.1 * PC  # the schedule did move
    for r in runs[1:]:
        assert np.array_equal(runs[0].r, r.r) and np.array_equal(runs[0].v, r.v)
        assert np.array_equal(runs[0].controller_states, r.controller_states)


@pytest.mark.parametrize("rate_limit,sample_time", [(math.inf, None), (1e5, None),
                                                   (math.inf, 5e-4)],
                         ids=["continuous", "rate-limited", "discrete"])
def test_recovers_faster_after_saturation(rig, rate_limit, sample_time):
    """The speed drops from 50 to 30 Hz for 0.1 s: the equilibrium moves and the PID, holding
    the journal where it was, needs more pressure than a valve with ±1 kPa of authority
    gives; its integrator winds up while saturated. Back at 50 Hz the law with anti-windup
    leaves saturation sooner and its error after the episode is smaller (measured: command
    saturated until 0.2975 s without and 0.142 s with; ∫e² dt 4.8e-13 and 1.4e-13 m² s)."""
    from rotordyn.analysis.assembly import assembled
    from rotordyn.control import SpeedProfile

    act = Actuator(p_min_pa=PC - 1e3, p_max_pa=PC + 1e3, rate_limit_pa_s=rate_limit)
    prof = SpeedProfile.table([0, 0.02, 0.03, 0.12, 0.13], [50, 50, 30, 30, 50])
    k = pid(KP, KD, KP / 0.02)
    if sample_time:
        from rotordyn.control.closedloop import closed_loop
        from rotordyn.control.plant import plant

        k = discretise(k, sample_time, "tustin")
        # the premise: a stable sampled-data loop (the ZOH law is not: +27.6 1/s)
        assert closed_loop(plant(rig, F, PC, AY, actuator=Actuator()), k,
                           with_margins=False).max_real < 0
    bc = [b for b in assembled(rig).bearings if b.active][0]
    res = {}
    for lab, law in (("plain", k), ("aw", with_anti_windup(k))):
        tr = rd.transient(rig, 0.5, chamber_pressure_pa=PC, config_ay_m=AY, speed=prof,
                          controller=law, actuator=act, n_out=1001, max_step_s=5e-4)
        assert tr.status == "ok", tr.message
        cmd = tr.chamber_pressure_command_pa
        sat = (cmd <= act.p_min_pa) | (cmd >= act.p_max_pa)
        ise, _ = error_after(tr, 0.13, bc.jx, bc.jy, C_RIG)
        res[lab] = (float(tr.t[sat].max()), ise)
    assert res["plain"][0] > 0.13  # saturated beyond the episode: wound up
    assert res["aw"][0] < res["plain"][0] - 0.05, res
    assert res["aw"][1] < 0.5 * res["plain"][1], res


def pulse_runs(system, t_end, speed_hz, pc, t_pulse, hi, p_max, law, jx, jy, **kw):
    """∫e² dt of the journal after a schedule pulse to ``hi`` over t_pulse (on, off) beyond a
    valve stopping at ``p_max``, for none / back-calculation / conditioning."""
    t0, t1 = t_pulse
    sched = PressureSchedule.time_table([0.0, t0, t0 + 0.005, t1, t1 + 0.005],
                                        [pc, pc, hi, hi, pc])
    act = Actuator(p_min_pa=0.0, p_max_pa=p_max)
    out = {}
    for lab, k in (("none", law), ("back-calculation", with_anti_windup(law)),
                   ("conditioning", with_anti_windup(law, mode="conditioning"))):
        tr = rd.transient(system, t_end, speed_hz, pressure=sched, controller=k, actuator=act,
                          **kw)
        assert tr.status == "ok", tr.message
        assert np.any(tr.chamber_pressure_command_pa >= p_max) or lab == "conditioning"
        m = tr.t >= t1 + 0.005
        e = np.hypot(tr.r[m, jx] - tr.equilibrium_r[jx], tr.r[m, jy] - tr.equilibrium_r[jy])
        out[lab] = float(np.sum(0.5 * (e[1:] ** 2 + e[:-1] ** 2) * np.diff(tr.t[m])))
    return out


@pytest.mark.parametrize("sample_time", [None, 1e-3], ids=["continuous", "discrete"])
def test_schedule_saturates_conditioning_not_worse(rig, sample_time):
    """A 0.6 MPa pulse of the schedule (0.02–0.13 s) on a valve stopping at 0.2 MPa, the PID
    holding the journal: back-calculation winds the law's output down to p_max − ff and
    recovers worse than none; conditioning (the schedule clipped before the law's increment)
    recovers best (measured, continuous over 0.5 s: ∫e² after the pulse 3.19e-10 none,
    1.64e-9 back-calculation, 2.31e-11 m² s conditioning; the law sampled at 1 kHz (Tustin)
    over 0.3 s — kept short, a restart per sample: 3.06e-10, 1.61e-9, 2.28e-11)."""
    from rotordyn.analysis.assembly import assembled

    k = pid(KP, KD, KP / 0.02)
    t_end = 0.5
    if sample_time:
        k, t_end = discretise(k, sample_time, "tustin"), 0.3
    bc = [b for b in assembled(rig).bearings if b.active][0]
    ise = pulse_runs(rig, t_end, F, PC, (0.02, 0.125), 0.6e6, 0.2e6, k, bc.jx, bc.jy,
                     config_ay_m=AY, n_out=int(2000 * t_end) + 1, max_step_s=5e-4)
    assert ise["back-calculation"] > ise["none"], ise
    assert ise["conditioning"] < 0.5 * ise["none"], ise


def test_not_the_rig_compressor_with_an_active_bearing():
    """The compressor with an active DE bearing: inside the limits bit for bit; with a
    ±200 Pa valve (saturated) the anti-windup run differs and stays finite (the recovery
    comparison is on the rig only)."""
    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    k = pid(2e9, 2e5, 2e9 / 0.02)
    aw = with_anti_windup(k)
    kw = dict(disturbance_m=(0.0, 5e-6), n_out=101)
    wide = Actuator(p_min_pa=0.0, p_max_pa=1e6)
    a = rd.transient(s, 0.05, 60.0, 0.2e6, controller=k, actuator=wide, **kw)
    b = rd.transient(s, 0.05, 60.0, 0.2e6, controller=aw, actuator=wide, **kw)
    assert a.status == b.status == "ok"
    assert np.array_equal(a.r, b.r) and np.array_equal(a.controller_states, b.controller_states)
    narrow = Actuator(p_min_pa=0.2e6 - 200, p_max_pa=0.2e6 + 200)
    c = rd.transient(s, 0.05, 60.0, 0.2e6, controller=k, actuator=narrow, **kw)
    d = rd.transient(s, 0.05, 60.0, 0.2e6, controller=aw, actuator=narrow, **kw)
    assert c.status == d.status == "ok"
    assert not np.array_equal(c.controller_states, d.controller_states)
    assert np.all(np.isfinite(d.r))
    # a discrete law: bit for bit inside the limits too
    kd = discretise(k, 5e-4)
    e = rd.transient(s, 0.05, 60.0, 0.2e6, controller=kd, actuator=wide, **kw)
    f = rd.transient(s, 0.05, 60.0, 0.2e6, controller=with_anti_windup(kd), actuator=wide, **kw)
    assert e.status == f.status == "ok"
    assert np.array_equal(e.r, f.r) and np.array_equal(e.controller_states, f.controller_states)


def test_compressor_schedule_pulse():
    """The compressor: a 0.6 MPa schedule pulse (5–30 ms) on a valve stopping at 0.25 MPa.
    The pulse hardly winds the PID up (its output stays below 1 kPa without anti-windup),
    back-calculation drives it to p_max − ff and recovers 10× worse; conditioning stays
    within 10 % of none (measured: 2.02e-12 none, 3.2e-10 back-calculation, 2.12e-12 m² s
    conditioning after the pulse; over the whole run conditioning is 1.7 % better)."""
    from rotordyn.analysis.assembly import assembled

    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    bc = [b for b in assembled(s).bearings if b.active][0]
    ise = pulse_runs(s, 0.1, 60.0, 0.2e6, (0.005, 0.03), 0.6e6, 0.25e6,
                     pid(2e9, 2e5, 2e9 / 0.02), bc.jx, bc.jy, n_out=401)
    assert ise["back-calculation"] > 10 * ise["none"], ise
    assert ise["conditioning"] < 1.1 * ise["none"], ise
