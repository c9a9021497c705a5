"""Periodic orbits of eq. 12 by harmonic balance with alternating frequency–time (the C++
``_core.harmonic_balance``; docs/nonlinear.md "Harmonic balance"): the starts and the call.
:func:`rotordyn.periodic_orbit` with ``method="harmonic_balance"`` is the public entry."""

from __future__ import annotations

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.results.transient import TransientResult

FLOQUET = ("samples", "hill", "flow", "none")


def time_points_for(harmonics: int, time_points: int | None) -> int:
    """M for H harmonics: ``time_points`` checked (M ≥ 2H + 1), or 4H by default."""
    h = v.integer("harmonics", harmonics, lo=1, hi=1000)
    if time_points is None:
        return max(4 * h, 2 * h + 1)
    m = v.integer("time_points", time_points, lo=1, hi=100_000)
    if m < 2 * h + 1:
        raise InputError(f"time_points: expected M >= 2H + 1 = {2 * h + 1} for harmonics = "
                         f"{h}, got {m}")
    return m


def samples_from_transient(tr: TransientResult, period_s: float, m: int) -> np.ndarray:
    """(m, n) positions of the transient's last period resampled at τ_j = 2πj/m (linear
    interpolation between its output samples), and the time of the first sample, s."""
    t = np.asarray(tr.t, dtype=float)
    t0 = float(t[-1]) - period_s
    if t0 < t[0]:
        raise InputError(f"start: the transient ({t[-1] - t[0]:.4g} s) is shorter than one "
                         f"period ({period_s:.4g} s)")
    ts = t0 + period_s * np.arange(m) / m
    r = np.asarray(tr.r, dtype=float)
    return np.column_stack([np.interp(ts, t, r[:, i]) for i in range(r.shape[1])]), t0


def samples_from_equilibrium(asm, omega: float, r_e: np.ndarray, amplitude_c: float,
                             m: int) -> tuple[np.ndarray, float]:
    """The cheap start of a limit cycle: the equilibrium r_e (n,) plus the least-damped
    whirl mode of its linearisation (first-order system matrix A = [[0, I], [−M⁻¹(K + K_H),
    −M⁻¹(C + ΩG + D_H)]], the eigenvalue of largest real part with Im > 0), scaled so the
    journal that moves most for its clearance moves ``amplitude_c`` of it (the semi-major
    axis; on a multi-bearing rotor the first bearing's scale could close another's film).
    Returns the (m, n) position samples and the period guess 2π/Im λ, s."""
    md = asm.model
    n = asm.n
    lin = asm.solver.linearize(r_e, np.zeros(n), omega)
    M = np.asarray(md.mass_at(omega))
    K, C, G = (np.asarray(x) for x in (md.K, md.C, md.G))
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -np.linalg.solve(M, K + np.asarray(lin.KH))
    A[n:, n:] = -np.linalg.solve(M, C + omega * G + np.asarray(lin.DH))
    lam, vec = np.linalg.eig(A)
    up = np.nonzero(lam.imag > 1e-9 * np.abs(lam).max())[0]
    if up.size == 0:
        raise InputError("start: the equilibrium's linearisation has no oscillating mode to "
                         "start a limit cycle from")
    k = up[np.argmax(lam.real[up])]
    q = vec[:n, k]
    tau = 2 * np.pi * np.arange(m) / m
    d = np.real(np.outer(np.exp(1j * tau), q))  # (m, n)
    ratio = max((np.hypot(d[:, bc.jx], d[:, bc.jy]).max() / bc.clearance_m
                 for bc in asm.bearings if bc.clearance_m > 0), default=0.0)
    if not ratio > 0:
        raise InputError("start: the least-damped mode does not move the journals")
    s = amplitude_c / ratio
    return r_e[None, :] + s * d, float(2 * np.pi / lam.imag[k])


def linear_forced_response(asm, omega: float, r_e: np.ndarray, uc: np.ndarray,
                           us: np.ndarray) -> tuple[np.ndarray, float]:
    """The complex amplitude q (n,) of the linearised system's unbalance response at the
    equilibrium r_e: (K + K_H − Ω² M(Ω) + iΩ(C + ΩG + D_H)) q = Ω² (u_c − i u_s), with K_H,
    D_H the films' stiffness and damping there (every coordinate: rotor, tilt, pads, sleeve),
    so r(t) = r_e + Re(q e^{iΩt}) is the first harmonic of the forced orbit at small
    unbalance (docs/nonlinear.md, "Forced orbits from the linear response"); and the
    largest real part of the linearisation's eigenvalues, 1/s (< 0: a transient settles
    as e^{σt})."""
    md = asm.model
    n = asm.n
    lin = asm.solver.linearize(r_e, np.zeros(n), omega)
    M = np.asarray(md.mass_at(omega))
    K, C, G = (np.asarray(x) for x in (md.K, md.C, md.G))
    KK, DD = K + np.asarray(lin.KH), C + omega * G + np.asarray(lin.DH)
    q = np.linalg.solve(KK - omega**2 * M + 1j * omega * DD, omega**2 * (uc - 1j * us))
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -np.linalg.solve(M, KK)
    A[n:, n:] = -np.linalg.solve(M, DD)
    return q, float(np.linalg.eigvals(A).real.max())


def forced_start(asm, omega: float, r_e: np.ndarray, q: np.ndarray, subharmonic: int, m: int,
                 keep_fraction: float = 0.1) -> tuple[np.ndarray, float]:
    """The start of a forced orbit from the linear response q (:func:`linear_forced_response`):
    (m, n) position samples r_e + s Re(q e^{ikτ_j}) at τ_j = 2πj/m (k = ``subharmonic``: the
    forcing is the k-th harmonic of the period), and s: 1, halved (at most 20 times) while a
    film's thickness at a sample falls below ``keep_fraction`` of its clearance (a linear
    response larger than the clearance is no start; its shape and phase still are)."""
    tau = 2 * np.pi * np.arange(m) / m
    d = np.real(np.outer(np.exp(1j * subharmonic * tau), q))  # (m, n)
    c = np.array([f.geometry.clearance_m for f in asm.model.films])
    s = 1.0
    for _ in range(20):
        h = np.array([asm.solver.film_h_min(r_e + s * dj) for dj in d])
        if c.size == 0 or np.all(h >= keep_fraction * c[None, :]):
            break
        s *= 0.5
    return r_e[None, :] + s * d, s


def solve(asm, inp, samples: np.ndarray | None, *, harmonics: int, time_points: int,
          tol: float, max_iter: int, floquet: str, cvode, sensitivity_rtol: float | None,
          magnus_substeps: int = 4, floquet_tol: float = 1e-3, floquet_max_steps: int = 0):
    """The C++ harmonic balance on the prepared :class:`_core.PeriodicInput` ``inp`` from
    position samples (m0, n) over one period (or None: one flow from inp.r0, inp.v0)."""
    opt = _core.HarmonicBalanceOptions()
    opt.harmonics = int(harmonics)
    opt.time_points = int(time_points)
    opt.tol = float(tol)
    opt.max_iter = int(max_iter)
    opt.floquet = getattr(_core.HbFloquet, v.choice("floquet", floquet, FLOQUET))
    opt.magnus_substeps = v.integer("magnus_substeps", magnus_substeps, lo=1, hi=1000)
    opt.floquet_tol = v.in_range("floquet_tol", floquet_tol, 0.0, 0.5)
    opt.floquet_max_steps = v.integer("floquet_max_steps", floquet_max_steps, lo=0, hi=1000000)
    opt.cvode = cvode
    if sensitivity_rtol is not None:
        opt.sensitivity_rtol = float(sensitivity_rtol)
    z = np.zeros((0, asm.n)) if samples is None else np.ascontiguousarray(samples, dtype=float)
    return _core.harmonic_balance(asm.solver, inp, z, opt)


def hb_stats(res) -> dict:
    """The harmonic-balance entries of ``PeriodicOrbitResult.stats``."""
    return {"method": "harmonic_balance", "harmonics": int(res.harmonics),
            "time_points": int(res.time_points), "linearizations": int(res.linearizations),
            "evaluations": int(res.evaluations),
            "harmonic_amplitudes": tuple(float(x) for x in res.harmonic_amplitudes),
            "coefficients": np.asarray(res.coefficients), **floquet_stats(res)}


def floquet_stats(res) -> dict:
    """The refined samples route's entries (empty for the other routes): the error estimate
    | |μ_c| − |μ_c|_previous level |, whether it met floquet_tol, the verdict's resolution
    (converged and | |μ_c| − 1 | > the error), steps, levels and film linearisations."""
    if res.floquet_levels < 1 or res.orbit.status != "ok":
        return {}
    return {**refined_entries(res.orbit.floquet, res),
            "floquet_levels": int(res.floquet_levels),
            "floquet_trivial_error": float(res.floquet_trivial_error),
            "floquet_moduli": tuple(float(x) for x in res.floquet_moduli)}


def refined_entries(fq, res) -> dict:
    """The refined product's error estimate, whether it met floquet_tol, the verdict's
    resolution (converged and | |μ_c| − 1 | > the error), steps and film linearisations, from
    the Floquet classification ``fq`` and a core result ``res`` carrying floquet_error,
    floquet_converged, floquet_steps and floquet_linearizations (harmonic balance's or
    shooting's)."""
    err = float(res.floquet_error)
    mc = float(fq.critical_modulus) if fq.critical >= 0 else 0.0
    return {"floquet_error": err, "floquet_converged": bool(res.floquet_converged),
            "floquet_resolved": bool(res.floquet_converged and abs(mc - 1.0) > err),
            "floquet_steps": int(res.floquet_steps),
            "floquet_linearizations": int(res.floquet_linearizations)}
