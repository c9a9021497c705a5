"""LQR state feedback and LQG output feedback (Kalman estimator from the chosen
measurements) on a :class:`~rotordyn.control.plant.Plant`; the LQG law is a
:class:`~rotordyn.control.Controller` usable in the linear closed loop and in the nonlinear
transient."""

from __future__ import annotations

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control._checks import keywords
from rotordyn.control.plant import as_plant
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.operation.controller import Controller

# Ranges of the design scales: beyond them the squares and inverses the Riccati equations are
# built from leave float64 (1/p_s² of 1e-300 Pa is a division by zero, d₀² of 1e300 N an
# overflow), and none is a physical size for this rig class (clearances 0.1 µm .. 1 m,
# command scales 1 Pa .. 1 GPa, forces 1 nN .. 1 GN, sensor noise 1 fm .. 1 m).
SCALE_RANGES = {"clearance_m": (1e-7, 1.0), "pressure_scale_pa": (1.0, 1e9),
                "frequency_hz": (1e-3, 1e6), "state_weight": (0.0, 1e12),
                "regularisation": (0.0, 1e6), "disturbance_force_n": (1e-9, 1e9),
                "measurement_noise_m": (1e-15, 1.0), "process_noise": (1e-12, 1e12),
                "performance_weight": (1e-9, 1e9)}
WEIGHT_OPTIONS = ("clearance_m", "pressure_scale_pa", "state_weight", "regularisation")


def scale(field: str, value) -> float:
    """A design scale or weight within :data:`SCALE_RANGES` (zero excluded for scales)."""
    lo, hi = SCALE_RANGES[field]
    return v.in_range(field, value, lo, hi)


def _riccati(where, *args):
    """scipy's CARE solution, a failure (no stabilising solution, a singular pencil) or a
    non-finite one as a ConvergenceError (a numerical failure, not an input error)."""
    from scipy.linalg import solve_continuous_are
    try:
        X = solve_continuous_are(*args)
    except (np.linalg.LinAlgError, ValueError) as exc:
        raise ConvergenceError(f"{where}: the Riccati equation has no stabilising solution "
                               f"for these weights ({exc})") from None
    if not np.all(np.isfinite(X)):
        raise ConvergenceError(f"{where}: the Riccati solution is not finite for these weights")
    return X


def design_clearance(p, clearance_m: float | None) -> float:
    """The design's length scale c (m): ``clearance_m``, or (None) the clearance of the
    plant's performance journal — the active bearing's, wherever it sits in the model
    (:func:`rotordyn.control.plant.plant`). It had been the paper rig's 0.3 mm on every
    model: on a 0.1 mm bearing the journal's weight was 9× too small against the command."""
    if clearance_m is not None:
        return scale("clearance_m", clearance_m)
    c = p.info.get("performance_clearance_m")
    if c is None:
        raise InputError("clearance_m: the plant does not carry its bearing's clearance "
                         "(not built by rotordyn.control.plant.plant); give clearance_m (m)")
    return scale("clearance_m", c)


def state_scales(p, *, clearance_m: float | None = None, pressure_scale_pa: float = 1e5,
                 frequency_hz: float = 100.0) -> np.ndarray:
    """Typical size of each plant state: c for positions (``clearance_m``, default the
    performance journal's clearance: :func:`design_clearance`), 2π f c for velocities,
    ``pressure_scale_pa`` for the actuator pressure (× its bandwidth for its rate); for a
    reduced plant (x_full = T x_r) the size of a modal coordinate that keeps every physical
    state within its typical size."""
    as_plant(p)
    clearance_m = design_clearance(p, clearance_m)
    scale("pressure_scale_pa", pressure_scale_pa)
    scale("frequency_hz", frequency_hz)
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


def default_weights(p, *, clearance_m: float | None = None, pressure_scale_pa: float = 1e5,
                    state_weight: float = 1.0, regularisation: float = 1e-6):
    """Q = C_perfᵀ C_perf / c² + ε diag(1/s²) (s: :func:`state_scales`, so every state is
    weighted by its typical size and the Riccati equation stays well posed),
    R = 1/p_s²: one clearance of journal motion costs as much as ``pressure_scale_pa`` of
    command."""
    scale("state_weight", state_weight)
    scale("regularisation", regularisation)
    # before c² and 1/p_s² (issue 21, fuzzing: clearance_m = 1e300 was an OverflowError)
    clearance_m = design_clearance(as_plant(p), clearance_m)
    scale("pressure_scale_pa", pressure_scale_pa)
    Q = state_weight * (p.C_perf.T @ p.C_perf) / clearance_m**2
    s = state_scales(p, clearance_m=clearance_m, pressure_scale_pa=pressure_scale_pa)
    Q = Q + regularisation * np.diag(1.0 / s**2)
    R = np.array([[1.0 / pressure_scale_pa**2]])
    return Q, R


def lqr(p, Q=None, R=None, **kw):
    """Continuous LQR: K = R⁻¹ Bᵀ X with X the stabilising solution of the Riccati
    equation; u = −K x. Returns (K (1, n_x), closed-loop eigenvalues of A − B K)."""
    as_plant(p)
    keywords("lqr", kw, WEIGHT_OPTIONS)
    n = p.A.shape[0]
    Q0, R0 = default_weights(p, **kw)  # checks the scales even when Q and R are given
    Q = Q0 if Q is None else v.psd_matrix("Q", Q, n)
    if R is None:
        R = R0
    else:
        R = np.atleast_2d(R) if np.ndim(R) == 0 else R
        R = v.psd_matrix("R", R, 1, definite=True)
    # Solved in scaled states x = S x̃ (S: typical state sizes) for conditioning.
    S = state_scales(p, clearance_m=kw.get("clearance_m"))  # the design's own scale
    As = p.A * (1 / S)[:, None] * S[None, :]
    Bs = p.B / S[:, None]
    Qs = Q * S[:, None] * S[None, :]
    Xs = _riccati("lqr", As, Bs, Qs, R)
    K = np.linalg.solve(R, Bs.T @ Xs) / S[None, :]
    if not np.all(np.isfinite(K)):
        raise ConvergenceError("lqr: the gain is not finite for these weights")
    eig = np.linalg.eigvals(p.A - p.B @ K)
    # The Riccati solution is stabilising by definition: a closed loop that is not stable is
    # a solution float64 did not resolve (issue 21, fuzzing: R = 1e-300 gave max Re λ = 8e268
    # and was returned as a design).
    if not (np.all(np.isfinite(eig)) and np.all(eig.real < 0)):
        raise ConvergenceError(f"lqr: the closed loop A − B K is not stable (max Re λ = "
                               f"{np.max(eig.real):.3g} 1/s): the weights (R = "
                               f"{float(R[0, 0]):.3g}) are beyond what the Riccati solution "
                               f"resolves in float64")
    return K, eig


def lqg(p, Q=None, R=None, *, process_noise: float = 1.0, measurement_noise_m: float = 1e-7,
        disturbance_force_n: float = 1.0, name: str = "lqg", **kw) -> Controller:
    """LQG controller: the LQR gain K on a Kalman estimate x̂ from the plant's measurements,
    ẋ̂ = A x̂ + B u + L (y − C x̂), u = −K x̂. Noise model: white forces of intensity
    ``disturbance_force_n``² on the plant's disturbance inputs (or the command input when
    there are none) scaled by ``process_noise``, white measurement noise of intensity
    ``measurement_noise_m``² per signal. Returns a Controller (n_k = plant order)."""
    as_plant(p)
    scale("process_noise", process_noise)
    scale("measurement_noise_m", measurement_noise_m)
    scale("disturbance_force_n", disturbance_force_n)
    v.text("name", name)
    K, _ = lqr(p, Q, R, **kw)
    G = p.Bd if p.Bd.shape[1] else p.B * 1e4  # 1e4 Pa of command noise as a stand-in
    Wn = process_noise * disturbance_force_n**2 * np.eye(G.shape[1])
    Vn = measurement_noise_m**2 * np.eye(p.C.shape[0])
    S = state_scales(p, clearance_m=kw.get("clearance_m"))  # the design's own scale
    As = p.A * (1 / S)[:, None] * S[None, :]
    Gs, Cs = G / S[:, None], p.C * S[None, :]
    Ys = _riccati("lqg (Kalman filter)", As.T, Cs.T, Gs @ Wn @ Gs.T, Vn)
    L = S[:, None] * (Ys @ Cs.T @ np.linalg.inv(Vn))
    if not np.all(np.isfinite(L)):
        raise ConvergenceError("lqg: the Kalman gain is not finite for these noise intensities")
    Ak = p.A - p.B @ K - L @ p.C
    return Controller(Ak, L, -K, np.zeros((1, p.C.shape[0])), p.measurements, name=name,
                      info={"K": K, "L": L, "plant_order": p.A.shape[0]})
