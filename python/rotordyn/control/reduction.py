"""Model-order reduction of a :class:`~rotordyn.control.plant.Plant` by modal truncation:
keep the modes below a frequency (the rotor modes), drop the fast sleeve and film modes,
with the error stated as ‖G − G_r‖∞ over a frequency grid (G: command → measurements)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control.plant import as_plant
from rotordyn.errors import InputError


def _check_grid(check_hz, n_check):
    """The error grid: (low, high) Hz with 0 < low < high, 2 .. 100000 points."""
    lo, hi = v.bounds("check_hz", check_hz)
    if not lo > 0:
        raise InputError(f"check_hz: expected 0 < low < high (Hz), got {check_hz!r}")
    return (lo, hi), v.integer("n_check", n_check, lo=2, hi=100_000)


def _freqresp(A, B, C, w):
    n = A.shape[0]
    return np.array([C @ np.linalg.solve(1j * wi * np.eye(n) - A, B) for wi in w])


def modal_truncation(p, max_frequency_hz: float = 500.0, *, keep_actuator: bool = True,
                     check_hz=(1.0, 2000.0), n_check: int = 400):
    """A real reduced plant keeping the modes with |Im λ|/2π ≤ ``max_frequency_hz`` and
    |λ| ≤ 2π·max_frequency_hz·10 (slow real modes) — plus the actuator's, when
    ``keep_actuator`` — with the dropped modes' static contribution kept (residualisation of
    their DC gain, so the low-frequency response is exact). Returns (plant_r, info) with
    info["hinf_error"], info["hinf_full"] (max over a log grid in ``check_hz``) and the kept
    eigenvalues."""
    from scipy.linalg import eig
    as_plant(p)
    v.in_range("max_frequency_hz", max_frequency_hz, 0.0, 1e7, lo_open=True)
    v.boolean("keep_actuator", keep_actuator)
    check_hz, n_check = _check_grid(check_hz, n_check)
    A, B, C, Bd = p.A, p.B, p.C, p.Bd
    lam, V = eig(A)
    W = np.linalg.inv(V)
    wmax = 2 * np.pi * max_frequency_hz
    keep = (np.abs(lam.imag) <= wmax) & (np.abs(lam) <= 10 * wmax)
    if keep_actuator and A.shape[0] > 2 * p.n_mech:
        wa = (2 * np.pi * p.actuator.natural_frequency_hz if p.actuator.order == 2
              else 1.0 / p.actuator.time_constant_s)
        keep |= np.isclose(np.abs(lam), wa, rtol=0.2)
    if not keep.any():  # issue 21 (fuzzing): an empty basis was a numpy ValueError
        raise InputError(f"max_frequency_hz: no mode of the plant at or below "
                         f"{max_frequency_hz:g} Hz (the slowest is at "
                         f"{np.abs(lam.imag).min() / (2 * np.pi):.4g} Hz, |λ| = "
                         f"{np.abs(lam).min():.4g} 1/s); raise it, or keep_actuator=True")
    # Real basis for the kept invariant subspace.
    cols, seen = [], set()
    for i in np.where(keep)[0]:
        if i in seen:
            continue
        if abs(lam[i].imag) > 1e-9 * max(1.0, abs(lam[i])):
            j = int(np.argmin(np.abs(lam - lam[i].conj()) + (np.arange(len(lam)) == i) * 1e30))
            seen.update((i, j))
            cols += [V[:, i].real, V[:, i].imag]
        else:
            seen.add(i)
            cols.append(V[:, i].real)
    T = np.column_stack(cols)
    # Oblique projector onto span(T) along the dropped modes.
    drop = ~keep
    Wk = W[keep]
    Vk = V[:, keep]
    P = (Vk @ Wk).real  # projector
    Tp = np.linalg.pinv(T)
    Ar = Tp @ A @ T
    Br, Bdr = Tp @ P @ B, Tp @ P @ Bd
    Cr = C @ T
    # DC correction of the dropped modes: D_r = C_d (−A_d)⁻¹ B_d (static residual).
    Vd, Wd, ld = V[:, drop], W[drop], lam[drop]
    Dr = np.real(C @ Vd @ np.diag(-1.0 / ld) @ Wd @ B) if drop.any() else np.zeros((C.shape[0], 1))
    # the same static residual for every input (command, disturbances) to every output
    # (measurements, performance): Plant.matrices() / to_control() keep it
    Call, Ball = np.vstack([C, p.C_perf]), np.hstack([B, Bd])
    Dall = (np.real(Call @ Vd @ np.diag(-1.0 / ld) @ Wd @ Ball) if drop.any()
            else np.zeros((Call.shape[0], Ball.shape[1])))
    Cp = p.C_perf @ T
    red = replace(p, A=Ar, B=Br, C=Cr, Bd=Bdr, C_perf=Cp,
                  state_names=tuple(f"modal_{i}" for i in range(Ar.shape[0])),
                  info=dict(p.info, reduced_from=A.shape[0], feedthrough=Dr, feedthrough_all=Dall,
                            T=T))
    w = 2 * np.pi * np.logspace(np.log10(check_hz[0]), np.log10(check_hz[1]), n_check)
    G = _freqresp(A, B, C, w)
    Gr = _freqresp(Ar, Br, Cr, w) + Dr
    err = max(np.linalg.norm(G[k] - Gr[k], 2) for k in range(len(w)))
    full = max(np.linalg.norm(G[k], 2) for k in range(len(w)))
    return red, {"hinf_error": float(err), "hinf_full": float(full),
                 "relative_error": float(err / full), "order": Ar.shape[0],
                 "full_order": A.shape[0], "kept_eigenvalues": lam[keep]}


def balanced_truncation(p, order: int, *, check_hz=(1.0, 2000.0), n_check: int = 400):
    """Balanced truncation (square-root method) of the plant's stable part, keeping its
    unstable part whole: A is split by an ordered real Schur form and a Sylvester equation
    into stable ⊕ unstable; the stable part's Hankel singular values σ_i give the a-priori
    bound ‖G − G_r‖∞ ≤ 2 Σ_{i > order_s} σ_i (Glover 1984; Zhou, Doyle & Glover, *Robust and
    Optimal Control*, 1996, Thm 7.9), reported beside the error measured on a frequency grid.
    ``order``: total states kept (unstable ones included). Inputs: command and disturbances;
    outputs: measurements (the performance output follows the same projection).
    Returns (plant_r, info)."""
    from scipy.linalg import cholesky, schur, solve_continuous_lyapunov, solve_sylvester, svd

    from rotordyn.control.lqr import state_scales

    as_plant(p)
    check_hz, n_check = _check_grid(check_hz, n_check)
    S = state_scales(p)
    A = p.A * (1 / S)[:, None] * S[None, :]
    Ball = np.hstack([p.B, p.Bd]) / S[:, None]
    Call = np.vstack([p.C, p.C_perf]) * S[None, :]
    n = A.shape[0]
    T, Z, ns = schur(A, output="real", sort="lhp")
    nu = n - ns
    v.integer("order", order, lo=nu + 1, hi=n)
    X = solve_sylvester(T[:ns, :ns], -T[ns:, ns:], -T[:ns, ns:]) if nu else np.zeros((ns, 0))
    Sm = np.eye(n)
    Sm[:ns, ns:] = X
    V = Z @ Sm                       # x = V ξ, ξ = [stable; unstable]
    Vi = np.linalg.solve(Sm, Z.T)
    Ab = Vi @ A @ V
    Bb, Cb = Vi @ Ball, Call @ V
    As, Bs, Cs = Ab[:ns, :ns], Bb[:ns], Cb[:, :ns]
    P = solve_continuous_lyapunov(As, -Bs @ Bs.T)
    Q = solve_continuous_lyapunov(As.T, -Cs.T @ Cs)

    def sqrt_psd(M):
        M = 0.5 * (M + M.T)
        try:
            return cholesky(M + 1e-300 * np.eye(M.shape[0]), lower=True)
        except np.linalg.LinAlgError:
            w, U = np.linalg.eigh(M)
            return U * np.sqrt(np.clip(w, 0, None))

    Lc, Lo = sqrt_psd(P), sqrt_psd(Q)
    U, hsv, Vt = svd(Lo.T @ Lc)
    ks = order - nu
    if hsv[ks - 1] <= 0:
        raise InputError(f"order: the stable part has only {int(np.sum(hsv > 0))} non-zero "
                         "Hankel singular values")
    sr = hsv[:ks] ** -0.5
    Tr = Lc @ Vt[:ks].T * sr[None, :]
    Wr = Lo @ U[:, :ks] * sr[None, :]
    Ar_s, Br_s, Cr_s = Wr.T @ As @ Tr, Wr.T @ Bs, Cs @ Tr
    Ar = np.block([[Ar_s, np.zeros((ks, nu))], [np.zeros((nu, ks)), Ab[ns:, ns:]]])
    Br = np.vstack([Br_s, Bb[ns:]])
    Cr = np.hstack([Cr_s, Cb[:, ns:]])
    Tmap = S[:, None] * (V @ np.block([[Tr, np.zeros((ns, nu))], [np.zeros((nu, ks)), np.eye(nu)]]))
    ny, nb = p.C.shape[0], p.B.shape[1]
    red = replace(p, A=Ar, B=Br[:, :nb], Bd=Br[:, nb:], C=Cr[:ny], C_perf=Cr[ny:],
                  state_names=tuple(f"balanced_{i}" for i in range(order)),
                  info=dict(p.info, reduced_from=n, T=Tmap, feedthrough=None,
                            feedthrough_all=None))
    w = 2 * np.pi * np.logspace(np.log10(check_hz[0]), np.log10(check_hz[1]), n_check)
    # errors in the original units, command -> measurements
    G = _freqresp(p.A, p.B, p.C, w)
    Gr = _freqresp(Ar, Br[:, :nb], Cr[:ny], w)
    err = max(np.linalg.norm(G[k] - Gr[k], 2) for k in range(len(w)))
    full = max(np.linalg.norm(G[k], 2) for k in range(len(w)))
    # the a-priori bound is for the scaled system with all inputs and outputs
    Gs = _freqresp(A, Ball, Call, w)
    Gsr = _freqresp(Ar, Br, Cr, w)
    err_scaled = max(np.linalg.norm(Gs[k] - Gsr[k], 2) for k in range(len(w)))
    return red, {"order": order, "full_order": n, "unstable_states": nu,
                 "hankel_singular_values": hsv, "bound_scaled": float(2 * hsv[ks:].sum()),
                 "hinf_error_scaled": float(err_scaled), "hinf_error": float(err),
                 "hinf_full": float(full), "relative_error": float(err / full)}
