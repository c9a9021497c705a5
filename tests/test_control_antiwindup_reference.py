"""Anti-windup in the C++ transient against an independent integration (issue 24).

A linear plant — a 2-DOF Jeffcott rotor m r̈ + c ṙ + k r = b p_c e_y with no film, the chamber
pressure p_c = clip(cmd) of a valve without dynamics (order 0) — closed by a PID on y, once
with the continuous law and once with its ZOH discretisation (sample-and-hold). The reference
is SciPy: solve_ivp (DOP853, rtol 1e-10) of the same equations written here from the module
docstring of rotordyn.control.antiwindup —

    cmd = ff(t) + u           (back-calculation, and no anti-windup)
    cmd = clip(ff(t)) + u     (conditioning: the schedule realised first)
    ẋ = A x + B y + L (clip(cmd) − cmd)
    x_{k+1} = A x_k + B y_k + L (clip(cmd_k) − cmd_k)   (discrete, cmd_k when u_k is
                                                        applied: at t_k, or t_k + 0.4 T
                                                        with a computation delay)

for two episodes: the law's own saturation (a 0.8 mm initial displacement against a
±20 kPa valve) and the schedule's (a pressure pulse to 4 p_0 on a valve that stops at 1.5 p_0).
Tolerance: 1e-6 of the largest displacement error (both integrators at rtol 1e-10; the
clip's kinks are where the two step sequences differ most), while the runs with and without
anti-windup (and back-calculation against conditioning) differ by more than 1e-2 of it, so
the comparison can tell the equations apart.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rotordyn import _core
from rotordyn.control.antiwindup import with_anti_windup
from rotordyn.control.export import discretise
from rotordyn.control.pid import pid

M_KG, F_N_HZ, ZETA, B_M2 = 10.0, 20.0, 0.05, 1e-3  # plant; chamber force b p_c along y
K_N_M = M_KG * (2 * math.pi * F_N_HZ) ** 2
C_N_S_M = 2 * ZETA * math.sqrt(K_N_M * M_KG)
P0 = 1e5  # Pa, the base pressure; the plant's equilibrium y_eq = b p_0 / k
Y_EQ = B_M2 * P0 / K_N_M
T_END, T_SAMPLE = 0.3, 1e-3
KP = 2 * K_N_M / B_M2  # Pa/m: the loop doubles the stiffness
LAW = pid(KP, 0.6 * math.sqrt(K_N_M * M_KG) / B_M2, KP / 0.05, tau_d_s=1e-3)
CM = np.zeros((2, 4))
CM[0, 0] = CM[1, 1] = 1.0  # journal x, y
OFFSET = np.array([0.0, Y_EQ])

# (name, schedule times, schedule pressures, p_min, p_max, initial y offset)
EPISODES = {
    "law saturates": ([0.0, T_END], [P0, P0], P0 - 2e4, P0 + 2e4, 8e-4),
    "schedule saturates": ([0.0, 0.05, 0.06, 0.15, 0.16], [P0, P0, 4 * P0, 4 * P0, P0],
                           0.0, 1.5 * P0, 0.0),
}


def _core_run(law, episode, t_out):
    tt, pp, lo, hi, dy = EPISODES[episode]
    s = _core.SystemModel()
    s.M, s.K, s.C = M_KG * np.eye(2), K_N_M * np.eye(2), C_N_S_M * np.eye(2)
    s.G, s.Q, s.chamber, s.films = np.zeros((2, 2)), np.zeros(2), np.array([0.0, B_M2]), []
    inp = _core.TransientInput()
    inp.omega = 0.0
    inp.a = np.zeros(2)
    inp.unbalance_cos, inp.unbalance_sin = np.zeros(0), np.zeros(0)
    inp.r0, inp.v0 = np.array([0.0, Y_EQ + dy]), np.zeros(2)
    inp.t_out = t_out
    inp.chamber_pressure = P0
    pr = _core.PressureCommand()
    pr.source = _core.PressureSource.time_table
    pr.table_x, pr.table_p = np.array(tt, float), np.array(pp, float)
    inp.pressure = pr
    act = _core.Actuator()
    act.order, act.p_min, act.p_max = 0, lo, hi
    inp.actuator = act
    inp.controller = law.to_core(CM, OFFSET)
    opt = _core.CvodeOptions()
    opt.rtol, opt.atol_position, opt.atol_velocity = 1e-10, 1e-13, 1e-11
    opt.atol_controller, opt.atol_pressure = 1e-13, 1e-6
    opt.max_step = 1e-3
    res = _core.integrate(_core.SystemSolver(s), inp, opt)
    assert res.status == "ok", res.message
    return np.asarray(res.r)


def _reference(law, episode, t_out):
    """SciPy: the same closed loop from the module docstring's equations."""
    tt, pp, lo, hi, dy = EPISODES[episode]
    A, B, C, D = law.A, law.B, law.C[0], law.D[0]
    L = law.anti_windup_gain
    cond = law.anti_windup_mode == "conditioning"

    def command(t, y, xk):
        ff = float(np.interp(t, tt, pp))
        ym = CM @ y[:4] - OFFSET
        u = float(C @ xk + D @ ym)
        cmd = (min(max(ff, lo), hi) if cond else ff) + u
        return cmd, min(max(cmd, lo), hi), ym

    def plant(y, pc):
        r, v = y[:2], y[2:4]
        acc = (np.array([0.0, B_M2 * pc]) - K_N_M * r - C_N_S_M * v) / M_KG
        return np.concatenate([v, acc])

    y0 = np.array([0.0, Y_EQ + dy, 0.0, 0.0])
    tol = dict(rtol=1e-10, atol=np.array([1e-13, 1e-13, 1e-11, 1e-11]))
    if not law.discrete:
        def f(t, z):
            xk = z[4:]
            cmd, sat, ym = command(t, z, xk)
            dx = A @ xk + B @ ym
            if L is not None:
                dx = dx + L * (sat - cmd)
            return np.concatenate([plant(z, sat), dx])

        atol = np.concatenate([tol["atol"], np.full(law.n_states, 1e-13)])
        sol = solve_ivp(f, (0.0, t_out[-1]), np.concatenate([y0, np.zeros(law.n_states)]),
                        method="DOP853", t_eval=t_out, rtol=1e-10, atol=atol, max_step=1e-3)
        assert sol.success, sol.message
        return sol.y[:2].T
    T = law.sample_time_s
    tau = law.computation_delay_s  # u_k applied at t_k + tau, the correction made then
    base = (lambda t: min(max(float(np.interp(t, tt, pp)), lo), hi)) if cond else \
        (lambda t: float(np.interp(t, tt, pp)))
    xk = np.zeros(law.n_states)
    y = y0.copy()
    out = np.empty((t_out.size, 2))
    n = int(round(t_out[-1] / T))
    u_old = 0.0  # before the first application: no increment

    def piece(ta, tb, y, u):
        sol = solve_ivp(lambda t, z: plant(z, min(max(base(t) + u, lo), hi)), (ta, tb), y,
                        method="DOP853", dense_output=True, **tol)
        assert sol.success, sol.message
        sel = (t_out >= ta) & ((t_out < tb) if tb < t_out[-1] else (t_out <= tb))
        if sel.any():
            out[sel] = sol.sol(t_out[sel])[:2].T
        return sol.y[:, -1]

    for k in range(n):
        t0 = k * T
        ym = CM @ y[:4] - OFFSET
        u = float(C @ xk + D @ ym)
        xn = A @ xk + B @ ym
        if tau > 0:
            y = piece(t0, t0 + tau, y, u_old)
        cmd = base(t0 + tau) + u  # at the application
        if L is not None:
            xn = xn + L * (min(max(cmd, lo), hi) - cmd)
        y = piece(t0 + tau, t0 + T, y, u)
        xk, u_old = xn, u
    return out


def _laws(discrete):
    k = discretise(LAW, T_SAMPLE) if discrete else LAW
    if discrete == "delayed":
        k = k.with_options(computation_delay_s=0.4 * T_SAMPLE)
    return {"none": k, "back-calculation": with_anti_windup(k),
            "conditioning": with_anti_windup(k, mode="conditioning")}


@pytest.mark.parametrize("discrete", [False, True, "delayed"],
                         ids=["continuous", "discrete", "discrete-delayed"])
@pytest.mark.parametrize("episode", list(EPISODES))
def test_transient_matches_an_independent_integration(episode, discrete):
    t_out = np.arange(0.0, T_END + T_SAMPLE / 2, 5 * T_SAMPLE)
    runs, refs = {}, {}
    for name, law in _laws(discrete).items():
        runs[name] = _core_run(law, episode, t_out)
        refs[name] = _reference(law, episode, t_out)
    scale = max(np.abs(r[:, 1] - Y_EQ).max() for r in refs.values())
    for name in runs:
        err = np.abs(runs[name] - refs[name]).max()
        assert err < 1e-6 * scale, (name, err / scale)
    # the comparison tells the equations apart
    assert np.abs(refs["none"] - refs["back-calculation"]).max() > 1e-2 * scale
    if episode == "schedule saturates":
        assert np.abs(refs["conditioning"] - refs["back-calculation"]).max() > 1e-2 * scale
    else:  # the schedule inside the limits: conditioning is back-calculation, bit for bit
        assert np.array_equal(runs["conditioning"], runs["back-calculation"])
