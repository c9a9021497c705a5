"""Model-order reduction of a :class:`~rotordyn.control.plant.Plant` by modal truncation:
keep the modes below a frequency (the rotor modes), drop the fast sleeve and film modes,
with the error stated as ‖G − G_r‖∞ over a frequency grid (G: command → measurements)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy.linalg import eig

from rotordyn import _validate as v


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
    v.positive("max_frequency_hz", max_frequency_hz)
    A, B, C, Bd = p.A, p.B, p.C, p.Bd
    lam, V = eig(A)
    W = np.linalg.inv(V)
    wmax = 2 * np.pi * max_frequency_hz
    keep = (np.abs(lam.imag) <= wmax) & (np.abs(lam) <= 10 * wmax)
    if keep_actuator and A.shape[0] > 2 * p.n_mech:
        wa = (2 * np.pi * p.actuator.natural_frequency_hz if p.actuator.order == 2
              else 1.0 / p.actuator.time_constant_s)
        keep |= np.isclose(np.abs(lam), wa, rtol=0.2)
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
    Cp = p.C_perf @ T
    red = replace(p, A=Ar, B=Br, C=Cr, Bd=Bdr, C_perf=Cp,
                  state_names=tuple(f"modal_{i}" for i in range(Ar.shape[0])),
                  info=dict(p.info, reduced_from=A.shape[0], feedthrough=Dr, T=T))
    w = 2 * np.pi * np.logspace(np.log10(check_hz[0]), np.log10(check_hz[1]), n_check)
    G = _freqresp(A, B, C, w)
    Gr = _freqresp(Ar, Br, Cr, w) + Dr
    err = max(np.linalg.norm(G[k] - Gr[k], 2) for k in range(len(w)))
    full = max(np.linalg.norm(G[k], 2) for k in range(len(w)))
    return red, {"hinf_error": float(err), "hinf_full": float(full),
                 "relative_error": float(err / full), "order": Ar.shape[0],
                 "full_order": A.shape[0], "kept_eigenvalues": lam[keep]}
