"""PD/PID on the active journal's displacement: u = −(k_p + k_i/s + k_d s/(τ_d s + 1)) y_d
with y_d the journal displacement along a direction (default vertical), tuned on the
linear closed loop to maximise the least damping ratio."""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control.plant import as_plant
from rotordyn.errors import InputError
from rotordyn.operation.controller import Controller

# |gain| bound, Pa/m (Pa·s/m, Pa/(m·s)): 1e15 Pa/m is 1 GPa of command per micron, far beyond
# any valve; with τ_d ≥ 0.1 µs every entry of the law (k_d / τ_d ≤ 1e22) stays finite.
MAX_GAIN = 1e15


def pid(kp: float, kd: float, ki: float = 0.0, *, tau_d_s: float = 2e-4,
        direction_deg: float = 90.0, bearing: int = 0, name: str = "pid") -> Controller:
    """The controller from the gains (Pa/m, Pa·s/m, Pa/(m·s)) on ("journal", bearing)."""
    for f, val in (("kp", kp), ("kd", kd), ("ki", ki)):
        v.in_range(f, val, -MAX_GAIN, MAX_GAIN)
    v.in_range("tau_d_s", tau_d_s, 1e-7, 1.0)
    v.in_range("direction_deg", direction_deg, -360.0, 360.0)
    v.integer("bearing", bearing, lo=0)
    v.text("name", name)
    kp, kd, ki, tau_d_s = float(kp), float(kd), float(ki), float(tau_d_s)
    c, s = math.cos(math.radians(direction_deg)), math.sin(math.radians(direction_deg))
    d = np.array([[c, s]])
    # states: derivative filter x_f (ẋ_f = (y_d − x_f)/τ, derivative = (y_d − x_f)/τ),
    # integral x_i (ẋ_i = y_d)
    A = [[-1.0 / tau_d_s]]
    B = [d[0] / tau_d_s]
    C = [[kd / tau_d_s]]
    D = -(kp + kd / tau_d_s) * d
    if ki:
        A = [[-1.0 / tau_d_s, 0.0], [0.0, 0.0]]
        B = [d[0] / tau_d_s, d[0]]
        C = [[kd / tau_d_s, -ki]]
    return Controller(np.array(A), np.array(B), np.array(C), D, [("journal", bearing)],
                      name=name, info={"kp": kp, "kd": kd, "ki": ki, "tau_d_s": tau_d_s,
                                       "direction_deg": direction_deg})


def tune_pd(p, *, kp0: float = 1e9, kd0: float = 1e6, ki: float = 0.0, tau_d_s: float = 2e-4,
            direction_deg: float = 90.0, max_iter: int = 200):
    """Maximise the least damping ratio of the linear closed loop over (k_p, k_d) by
    Nelder–Mead on log-gains with signs free (the start's signs); returns (controller,
    ClosedLoopResult)."""
    from scipy.optimize import minimize
    from rotordyn.control.closedloop import closed_loop_matrix
    from rotordyn.results.modes import damping_ratio

    as_plant(p)
    meas = tuple(tuple(m) for m in p.measurements)
    if len(meas) != 1 or meas[0][0] != "journal":
        raise InputError(f"plant.measurements: tune_pd tunes a law on one journal's "
                         f"displacement; expected a plant measuring [('journal', b)], got "
                         f"{list(p.measurements)}")
    bearing = int(meas[0][1])  # the law reads what the plant measures (any bearing's journal)
    for f, val in (("kp0", kp0), ("kd0", kd0)):
        val = v.in_range(f, val, -MAX_GAIN, MAX_GAIN)
        if abs(val) < 1e-3:
            raise InputError(f"{f}: expected a starting gain with |{f}| in [1e-3, {MAX_GAIN:g}] "
                             f"(the search scales it; its sign is tried both ways), got {val!r}")
    v.in_range("ki", ki, -MAX_GAIN, MAX_GAIN)
    v.in_range("tau_d_s", tau_d_s, 1e-7, 1.0)
    v.in_range("direction_deg", direction_deg, -360.0, 360.0)
    v.integer("max_iter", max_iter, lo=1, hi=100_000)
    kp0, kd0 = float(kp0), float(kd0)

    def cost(z):
        if not np.all(np.abs(z) <= MAX_GAIN):
            return np.inf  # the search left the gains' range: not a candidate
        k = pid(z[0], z[1], ki, tau_d_s=tau_d_s, direction_deg=direction_deg,
                bearing=bearing)
        Acl = closed_loop_matrix(p, k)
        if not np.all(np.isfinite(Acl)):
            return np.inf
        lam = np.linalg.eigvals(Acl)
        lam = lam[np.abs(lam) < 2 * np.pi * 2000]  # modes the law is meant to shape
        if lam.size == 0:
            return np.inf
        return -damping_ratio(lam).min()

    best = None
    for s1 in (1, -1):
        for s2 in (1, -1):
            z0 = np.array([s1 * kp0, s2 * kd0])
            res = minimize(lambda q: cost(q * z0), np.ones(2), method="Nelder-Mead",
                           options={"maxiter": max_iter, "xatol": 1e-3, "fatol": 1e-6})
            if best is None or res.fun < best[0]:
                best = (res.fun, res.x * z0)
    from rotordyn.control.closedloop import closed_loop

    k = pid(best[1][0], best[1][1], ki, tau_d_s=tau_d_s, direction_deg=direction_deg,
            bearing=bearing, name="pd" if not ki else "pid")
    return k, closed_loop(p, k)
