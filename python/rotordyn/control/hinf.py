"""H∞ output feedback on a :class:`~rotordyn.control.plant.Plant` (needs the optional
``slycot``: ``pip install 'rotordyn[hinf]'``), returning the same
:class:`~rotordyn.control.Controller` as LQG and PD, so it closes the linear loop and runs in
the nonlinear transient.

The design is a standard LFT (Zhou, Doyle & Glover, *Robust and Optimal Control*, 1996,
ch. 14–16; Glover & Doyle, Syst. Control Lett. 11 (1988) 167): minimise the H∞ norm from
w = [d; n] to z = [z_1; z_2] of

    ẋ   = A x + B_d d₀ d + B p_s u
    z_1 = w_z C_perf x / c            (the active journal's displacement, clearances)
    z_2 = u                            (command, units of p_s)
    y   = C x / c + (n₀ / c) n         (measurements, clearances, with sensor noise)

with d the disturbance forces on the plant's disturbance inputs (N, scale d₀; a plant
without disturbance inputs gets a disturbance on the command, d₀ Pa per newton), n the
sensor noise (scale n₀ m per signal), p_s the command scale (Pa). These are the weights of
:func:`rotordyn.control.lqr.lqg` in H∞ form: the H₂ design minimises the same map's H₂
norm. States are scaled by :func:`rotordyn.control.lqr.state_scales` before SLICOT's
``SB10AD`` (Glover–Doyle formulas with γ iteration) is called; a reduced plant's feedthrough
D₂₂ is handled by loop shifting (K = K₀ (I + D₂₂ K₀)⁻¹, positive feedback u = K y).
"""

from __future__ import annotations

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control._checks import frequencies
from rotordyn.control.lqr import design_clearance, scale, state_scales
from rotordyn.control.plant import as_plant
from rotordyn.errors import InputError
from rotordyn.operation.controller import Controller

SLYCOT_HINT = ("H∞ synthesis needs the optional package slycot (SLICOT's SB10AD): install "
               "the extra with pip install 'rotordyn[hinf]' (or pip install slycot)")


def _slycot():
    try:
        import slycot
    except ImportError as exc:
        raise ImportError(SLYCOT_HINT) from exc
    return slycot


def generalized_plant(p, *, disturbance_force_n: float = 1.0, measurement_noise_m: float = 1e-5,
                      pressure_scale_pa: float = 1e5, clearance_m: float | None = None,
                      performance_weight: float = 1.0):
    """The scaled generalized plant of the module docstring: (A, B, C, D, sizes, scales) with
    B = [B₁ | B₂], C = [C₁; C₂], D = [[D₁₁, D₁₂], [D₂₁, D₂₂]]; sizes = (n_w, n_u=1, n_z,
    n_y); scales = (S (state scales), c, p_s)."""
    as_plant(p)
    clearance_m = design_clearance(p, clearance_m)  # default: the performance journal's
    for field, val in (("disturbance_force_n", disturbance_force_n),
                       ("measurement_noise_m", measurement_noise_m),
                       ("pressure_scale_pa", pressure_scale_pa),
                       ("performance_weight", performance_weight)):
        scale(field, val)
    S = state_scales(p, clearance_m=clearance_m)
    c, ps = clearance_m, pressure_scale_pa
    A = p.A / S[:, None] * S[None, :]
    B2 = p.B / S[:, None] * ps
    Bd = p.Bd if p.Bd.shape[1] else p.B
    Bd = Bd / S[:, None] * disturbance_force_n
    Cy = p.C * S[None, :] / c
    Cz = performance_weight * p.C_perf * S[None, :] / c
    n, ny, nd, nz = A.shape[0], Cy.shape[0], Bd.shape[1], Cz.shape[0]
    B1 = np.hstack([Bd, np.zeros((n, ny))])
    C1 = np.vstack([Cz, np.zeros((1, n))])
    D11 = np.zeros((nz + 1, nd + ny))
    D12 = np.vstack([np.zeros((nz, 1)), [[1.0]]])
    D21 = np.hstack([np.zeros((ny, nd)), (measurement_noise_m / c) * np.eye(ny)])
    Dr = p.info.get("feedthrough")
    D22 = (np.asarray(Dr, float) * ps / c) if Dr is not None else np.zeros((ny, 1))
    Bg = np.hstack([B1, B2])
    Cg = np.vstack([C1, Cy])
    Dg = np.block([[D11, D12], [D21, D22]])
    return A, Bg, Cg, Dg, (nd + ny, 1, nz + 1, ny), (S, c, ps)


def lower_lft_response(A, B, C, D, sizes, K, freqs_hz) -> np.ndarray:
    """Largest singular value of the closed loop F_l(P, K)(iω) = P₁₁ + P₁₂ K (I − P₂₂ K)⁻¹
    P₂₁ at each frequency (positive feedback u = K y), from the generalized plant's and the
    controller's frequency responses — independent of SLICOT's closed-loop matrices.
    ``K`` = (A_k, B_k, C_k, D_k) in the plant's scaled units. Returns (n_f,)."""
    nw, nu, nz, ny = sizes
    Ak, Bk, Ck, Dk = K
    n, nk = A.shape[0], Ak.shape[0]
    freqs_hz = frequencies("freqs_hz", freqs_hz)
    out = np.empty(len(freqs_hz))
    for i, f in enumerate(freqs_hz):
        s = 2j * np.pi * f
        P = C @ np.linalg.solve(s * np.eye(n) - A, B) + D
        Kw = Dk + (Ck @ np.linalg.solve(s * np.eye(nk) - Ak, Bk) if nk else 0)
        P11, P12 = P[:nz, :nw], P[:nz, nw:]
        P21, P22 = P[nz:, :nw], P[nz:, nw:]
        T = P11 + P12 @ Kw @ np.linalg.solve(np.eye(ny) - P22 @ Kw, P21)
        out[i] = np.linalg.norm(T, 2)
    return out


def hinf(p, *, disturbance_force_n: float = 1.0, measurement_noise_m: float = 1e-5,
         pressure_scale_pa: float = 1e5, clearance_m: float | None = None,
         performance_weight: float = 1.0, gamma_tol: float = 1e-4,
         name: str = "hinf") -> Controller:
    """H∞ output-feedback law on plant ``p`` (full or reduced, with the valve) for the LFT of
    the module docstring: SB10AD's γ iteration (bisection, then a scan to the least γ whose
    closed loop stays stable, relative accuracy ``gamma_tol``) gives γ and the controller.
    Returns a Controller (n_k = plant order) reading the plant's measurements; its ``info``
    has ``gamma`` (the achieved bound on the scaled closed loop's H∞ norm), the generalized
    plant (``generalized_plant``) and the scaled controller (``controller_scaled``). Raises ImportError naming the ``hinf`` extra without slycot,
    InputError on bad weights or when SB10AD finds no admissible controller."""
    as_plant(p)
    v.in_range("gamma_tol", gamma_tol, 1e-12, 0.5)
    v.text("name", name)
    sl = _slycot()
    A, B, C, D, sizes, (S, c, ps) = generalized_plant(
        p, disturbance_force_n=disturbance_force_n, measurement_noise_m=measurement_noise_m,
        pressure_scale_pa=pressure_scale_pa, clearance_m=clearance_m,
        performance_weight=performance_weight)
    nw, nu, nz, ny = sizes
    n = A.shape[0]
    m, np_ = B.shape[1], C.shape[0]
    D22 = D[nz:, nw:].copy()
    D0 = D.copy()
    D0[nz:, nw:] = 0.0  # loop shifting: design for D22 = 0, then close the shift
    try:
        out = sl.sb10ad(n, m, np_, nu, ny, 1e100, A, B, C, D0, job=3, gtol=gamma_tol)
    except (ValueError, ArithmeticError) as exc:  # slycot's SlycotArithmeticError/ParameterError
        raise InputError(f"hinf: SB10AD found no admissible H∞ controller for these weights "
                         f"({exc})") from None
    Ak, Bk, Ck, Dk = (np.atleast_2d(np.asarray(x, float)) for x in out[1:5])
    if np.any(D22):
        M = np.linalg.inv(np.eye(nu) + Dk @ D22)
        Ck, Dk = M @ Ck, M @ Dk
        Ak = Ak - Bk @ D22 @ Ck
        Bk = Bk @ (np.eye(ny) - D22 @ Dk)
    # scaled: y_s = y / c, u_s = u / p_s  ->  physical u = p_s K(y / c)
    k = Controller(Ak, Bk / c, ps * Ck, ps * Dk / c, p.measurements, name=name,
                   info={"gamma": float(out[0]), "rcond": np.asarray(out[9]),
                         "plant_order": n,
                         "generalized_plant": (A, B, C, D, sizes),
                         "controller_scaled": (Ak, Bk, Ck, Dk),
                         "weights": {"disturbance_force_n": disturbance_force_n,
                                     "measurement_noise_m": measurement_noise_m,
                                     "pressure_scale_pa": pressure_scale_pa,
                                     "clearance_m": c,
                                     "performance_weight": performance_weight}})
    return k
