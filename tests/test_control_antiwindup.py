"""Back-calculation anti-windup for the valve's saturation and rate limit (issue 24).

References and tolerances:
- Inside the limits the correction û − u is exactly 0 and the right-hand side takes the same
  arithmetic: the transient with anti-windup equals the one without bit for bit (r, v,
  controller states), checked on a run whose command never leaves [p_min, p_max] and whose
  rate never reaches the limit.
- After a long saturation (a speed dip moves the equilibrium beyond what a ±1 kPa valve can
  hold, so the PID's integrator winds up) the law with anti-windup leaves saturation at least
  50 ms sooner and its integrated squared error after the episode is less than half
  (Åström & Hägglund, Advanced PID Control, 2006, §3.5 shows the same comparison), with and
  without a rate limit.
- The default tracking gain has C L = 2π · bandwidth exactly; A − L C is stable or refused.
"""

import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import Actuator, PressureSchedule
from rotordyn.control.antiwindup import law_bandwidth_hz, tracking_matrix, with_anti_windup
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
    with pytest.raises(InputError, match="sample_time_s"):
        with_anti_windup(k.with_options(sample_time_s=1e-4))
    with pytest.raises(InputError, match="tracking_rate_hz"):
        with_anti_windup(k, math.nan)
    with pytest.raises(InputError, match="gain"):
        with_anti_windup(k, gain=[0.0, 1.0])  # A − L C: ẋ_i gains +k_i x_i, unstable


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


@pytest.mark.parametrize("rate_limit", [math.inf, 1e5])
def test_recovers_faster_after_saturation(rig, rate_limit):
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
