"""LQR state feedback and LQG output feedback (Kalman estimator from the chosen
measurements) on a :class:`~rotordyn.control.plant.Plant`; the LQG law is a
:class:`~rotordyn.control.Controller` usable in the linear closed loop and in the nonlinear
transient."""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_continuous_are

from rotordyn._common import validate as v
from rotordyn.operation.controller import Controller
from rotordyn.errors import InputError


def state_scales(p, *, clearance_m: float = 3e-4, pressure_scale_pa: float = 1e5,
                 frequency_hz: float = 100.0) -> np.ndarray:
    """Typical size of each plant state: c for positions, 2π f c for velocities,
    ``pressure_scale_pa`` for the actuator pressure (× its bandwidth for its rate); for a
    reduced plant (x_full = T x_r) the size of a modal coordinate that keeps every physical
    state within its typical size."""
    n = p.n_mech
    w = 2 * np.pi * frequency_hz
    s = np.concatenate([np.full(n, clearance_m), np.full(n, w * clearance_m)])
    na = p.actuator.order
    wa = 2 * np.pi * p.actuator.natural_frequency_hz if na == 2 else 1.0
    s = np.concatenate([s, [pressure_scale_pa, pressure_scale_pa * wa][:na]])
    T = p.info.get("T")
    if T is not None:
        s = 1.0 / np.max(np.abs(T) / s[:, None], axis=0)
    return s


def default_weights(p, *, clearance_m: float = 3e-4, pressure_scale_pa: float = 1e5,
                    state_weight: float = 1.0, regularisation: float = 1e-6):
    """Q = C_perfᵀ C_perf / c² + ε diag(1/s²) (s: :func:`state_scales`, so every state is
    weighted by its typical size and the Riccati equation stays well posed),
    R = 1/p_s²: one clearance of journal motion costs as much as ``pressure_scale_pa`` of
    command."""
    Q = state_weight * (p.C_perf.T @ p.C_perf) / clearance_m**2
    s = state_scales(p, clearance_m=clearance_m, pressure_scale_pa=pressure_scale_pa)
    Q = Q + regularisation * np.diag(1.0 / s**2)
    R = np.array([[1.0 / pressure_scale_pa**2]])
    return Q, R


def lqr(p, Q=None, R=None, **kw):
    """Continuous LQR: K = R⁻¹ Bᵀ X with X the stabilising solution of the Riccati
    equation; u = −K x. Returns (K (1, n_x), closed-loop eigenvalues of A − B K)."""
    if Q is None or R is None:
        Q0, R0 = default_weights(p, **kw)
        Q = Q0 if Q is None else Q
        R = R0 if R is None else R
    Q, R = np.atleast_2d(np.asarray(Q, float)), np.atleast_2d(np.asarray(R, float))
    n = p.A.shape[0]
    if Q.shape != (n, n):
        raise InputError(f"Q: expected shape ({n}, {n}), got {Q.shape}")
    if R.shape != (1, 1) or not R[0, 0] > 0:
        raise InputError("R: expected a positive 1x1 weight")
    # Solved in scaled states x = S x̃ (S: typical state sizes) for conditioning.
    S = state_scales(p)
    As = p.A * (1 / S)[:, None] * S[None, :]
    Bs = p.B / S[:, None]
    Qs = Q * S[:, None] * S[None, :]
    Xs = solve_continuous_are(As, Bs, Qs, R)
    K = np.linalg.solve(R, Bs.T @ Xs) / S[None, :]
    return K, np.linalg.eigvals(p.A - p.B @ K)


def lqg(p, Q=None, R=None, *, process_noise: float = 1.0, measurement_noise_m: float = 1e-7,
        disturbance_force_n: float = 1.0, name: str = "lqg", **kw) -> Controller:
    """LQG controller: the LQR gain K on a Kalman estimate x̂ from the plant's measurements,
    ẋ̂ = A x̂ + B u + L (y − C x̂), u = −K x̂. Noise model: white forces of intensity
    ``disturbance_force_n``² on the plant's disturbance inputs (or the command input when
    there are none) scaled by ``process_noise``, white measurement noise of intensity
    ``measurement_noise_m``² per signal. Returns a Controller (n_k = plant order)."""
    v.positive("process_noise", process_noise)
    v.positive("measurement_noise_m", measurement_noise_m)
    K, _ = lqr(p, Q, R, **kw)
    G = p.Bd if p.Bd.shape[1] else p.B * 1e4  # 1e4 Pa of command noise as a stand-in
    Wn = process_noise * disturbance_force_n**2 * np.eye(G.shape[1])
    Vn = measurement_noise_m**2 * np.eye(p.C.shape[0])
    S = state_scales(p)
    As = p.A * (1 / S)[:, None] * S[None, :]
    Gs, Cs = G / S[:, None], p.C * S[None, :]
    Ys = solve_continuous_are(As.T, Cs.T, Gs @ Wn @ Gs.T, Vn)
    L = S[:, None] * (Ys @ Cs.T @ np.linalg.inv(Vn))
    Ak = p.A - p.B @ K - L @ p.C
    return Controller(Ak, L, -K, np.zeros((1, p.C.shape[0])), p.measurements, name=name,
                      info={"K": K, "L": L, "plant_order": p.A.shape[0]})
