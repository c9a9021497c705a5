"""Computation delay in the linear loop (issue 24): the controller's output reaches the valve
τ seconds after the measurement it was computed from.

* A **continuous** law: the delay e^{−sτ} is replaced by its diagonal Padé approximant of a
  stated order N, P_N(s) = Σ c_k (−sτ)^k / Σ c_k (sτ)^k, c_k = (2N − k)! N! / ((2N)! k!
  (N − k)!) (G. A. Baker & P. Graves-Morris, *Padé Approximants*, 2nd ed., 1996, §1.2). It is
  all-pass (|P_N(iω)| = 1 exactly), so its whole error is a phase error,
  ε(ω) = arg P_N(iω) + ωτ, given by :func:`pade_phase_error` (≈ −(ωτ)^{2N+1}·(N!)²/((2N)!
  (2N+1)!) for small ωτ; the function computes it exactly).
* A **discrete** law (sample time T, zero-order hold) whose computation takes τ ∈ [0, T]
  (sample-and-hold of the computation: the command computed from y[k] is applied at
  kT + τ and held until (k+1)T + τ) — exact, no approximation: over one sample the plant
  sees u[k−1] for τ and u[k] for T − τ, so
  x[k+1] = Φ x[k] + Γ₁ u[k−1] + Γ₀ u[k], Φ = e^{AT}, Γ₀ = ∫₀^{T−τ} e^{As} ds B,
  Γ₁ = e^{A(T−τ)} ∫₀^{τ} e^{As} ds B (Franklin, Powell & Workman, *Digital Control of Dynamic
  Systems*, 3rd ed., 1998, §4.3.4), with u[k−1] a state of the sampled plant.

In the nonlinear transient: a continuous law with its Padé delay (:func:`with_pade_delay`) is
an ordinary controller and runs as it is; a discrete law with ``computation_delay_s`` (a field
of :class:`~rotordyn.operation.controller.Controller`) has its command applied at kT + τ by
the C++ loop (a second restart per sample), exactly as in the linear loop;
:func:`with_sample_delay` is the one-sample delay as extra law state.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control import lti
from rotordyn.errors import InputError

MAX_ORDER = 20
MAX_DELAY_S = 1.0


def check_delay(field: str, value) -> float:
    """A delay in [0, 1] s."""
    return v.in_range(field, value, 0.0, MAX_DELAY_S)


def check_order(value) -> int:
    return v.integer("pade_order", value, lo=1, hi=MAX_ORDER)


def pade(delay_s: float, order: int = 6) -> lti.SS:
    """The diagonal Padé approximant of e^{−s·delay_s} of ``order`` N as a SISO state space
    (N states; D = (−1)^N). The realisation is built for the normalised variable sτ (companion
    form of the denominator, coefficients of order one) and then time-scaled, so it stays
    well-conditioned for any delay. ``delay_s`` = 0: the identity (no states)."""
    tau = check_delay("delay_s", delay_s)
    n = check_order(order)
    if tau == 0:
        return lti.SS(np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), np.ones((1, 1)))
    c = np.array([math.factorial(2 * n - k) * math.factorial(n)
                  / (math.factorial(2 * n) * math.factorial(k) * math.factorial(n - k))
                  for k in range(n + 1)])
    num = c * (-1.0) ** np.arange(n + 1)  # in powers of x = sτ, ascending
    den = c
    # monic denominator in descending powers: x^n + a_{n-1} x^{n-1} + ... + a_0
    a = den[:n] / den[n]
    b = num[:n] / den[n]
    d = num[n] / den[n]
    A = np.zeros((n, n))
    A[:-1, 1:] = np.eye(n - 1)
    A[-1, :] = -a
    B = np.zeros((n, 1))
    B[-1, 0] = 1.0
    C = (b - d * a)[None, :]
    # x = sτ: states of the normalised system, time scaled by 1/τ
    return lti.balanced(lti.SS(A / tau, B / tau, C, np.array([[d]])))


def pade_phase_error(delay_s: float, order: int, freqs_hz) -> np.ndarray:
    """ε(f) = arg P_N(i2πf) + 2πfτ (rad), the Padé approximant's whole error (it is
    all-pass), at each frequency; arg P_N = −2 Σ arctan of the zeros' angles, computed
    exactly from the numerator's roots (no unwrapping)."""
    tau = check_delay("delay_s", delay_s)
    n = check_order(order)
    f = np.atleast_1d(np.asarray(v.vector("freqs_hz", np.atleast_1d(freqs_hz)), float))
    if np.any(f < 0):
        raise InputError(f"freqs_hz: expected frequencies >= 0 Hz, got {float(f.min())!r}")
    w = 2 * np.pi * f
    if tau == 0:
        return np.zeros_like(w)
    c = np.array([math.factorial(2 * n - k) * math.factorial(n)
                  / (math.factorial(2 * n) * math.factorial(k) * math.factorial(n - k))
                  for k in range(n + 1)])
    roots = np.roots(c[::-1])  # denominator roots in x = sτ (left half plane)
    # P = Π (−x − r̄...) : the numerator's roots are −roots; arg P(iωτ) = Σ[arg(iωτ + r) −
    # arg(iωτ − r)] over the denominator roots r (left half plane)
    x = 1j * w * tau
    ph = np.full_like(w, n * np.pi)  # P = (−1)^N Π (x + r)/(x − r)
    for r in roots:
        ph += np.angle((x + r) / (x - r))
    # the sum is the continuous phase −2Σ arctan(...): add ωτ and wrap to (−π, π]
    return (ph + w * tau + np.pi) % (2 * np.pi) - np.pi


def with_pade_delay(k, delay_s: float, order: int = 6):
    """The continuous controller ``k`` followed by the Padé delay of :func:`pade` (the
    command it computes reaches the valve ``delay_s`` later). States [x_k; x_delay];
    ``info["computation_delay"]`` = {delay_s, pade_order}."""
    from rotordyn.control._checks import controller

    controller(k, continuous=True)
    P = pade(delay_s, order)
    if P.n == 0:
        return k
    nk = k.n_states
    A = np.block([[k.A, np.zeros((nk, P.n))], [P.B @ k.C, P.A]])
    B = np.vstack([k.B, P.B @ k.D])
    C = np.hstack([P.D @ k.C, P.C])
    D = P.D @ k.D
    return k.with_options(A=A, B=B, C=C, D=D, name=f"{k.name}+delay",
                          info=dict(k.info, computation_delay={"delay_s": float(delay_s),
                                                               "pade_order": int(order)}))


def delayed_zoh(A: np.ndarray, B: np.ndarray, T: float, delay_s: float):
    """(Φ, Γ₀, Γ₁) of the module docstring for a plant (A, B) sampled at T with the input
    applied ``delay_s`` ∈ [0, T] after each sample."""
    from scipy.linalg import expm

    n, m = A.shape[0], B.shape[1]

    def phi_gamma(h):
        E = expm(np.block([[A, B], [np.zeros((m, n + m))]]) * h)
        return E[:n, :n], E[:n, n:]

    Phi, _ = phi_gamma(T)
    P0, G0 = phi_gamma(T - delay_s)
    _, Gt = phi_gamma(delay_s)
    return Phi, G0, P0 @ Gt


def computation_delay_for(k, value) -> float:
    """``computation_delay_s`` for controller ``k``: None takes the law's own
    (``k.computation_delay_s``); else in [0, 1] s, for a discrete law at most its sample time
    (a longer computation is a different sample time), and not contradicting the law's own."""
    if value is None:
        return float(k.computation_delay_s)
    tau = check_delay("computation_delay_s", value)
    if k.discrete and tau > k.sample_time_s:
        raise InputError(f"computation_delay_s: expected a delay in [0, {k.sample_time_s:g}] s "
                         f"(the discrete law's sample time), got {value!r}")
    if k.computation_delay_s and tau != k.computation_delay_s:
        raise InputError(f"computation_delay_s: the controller has its own computation delay "
                         f"{k.computation_delay_s!r} s; got {value!r} (give None)")
    return tau


def with_sample_delay(k):
    """The discrete law ``k`` whose command is applied one full sample late (a computation
    that takes the whole sample time: u applied at (k+1)T is the one computed from y[k]),
    exactly, as a discrete :class:`Controller` with one more state (the command waiting to
    be applied): x' = [A 0; C 0] x + [B; D] y, u = [0 1] x. It runs in the nonlinear
    transient like any discrete law; its linear loop equals ``closed_loop(p, k,
    computation_delay_s=k.sample_time_s)``."""
    from rotordyn.control._checks import controller

    controller(k)
    if not k.discrete:
        raise InputError("controller.sample_time_s: expected a discrete law (a one-sample "
                         "delay needs a sample time); for a continuous law use "
                         "with_pade_delay()")
    nk, ny = k.n_states, k.n_inputs
    A = np.block([[k.A, np.zeros((nk, 1))], [k.C, np.zeros((1, 1))]])
    B = np.vstack([k.B, k.D])
    C = np.hstack([np.zeros((1, nk)), [[1.0]]])
    return k.with_options(A=A, B=B, C=C, D=np.zeros((1, ny)), name=f"{k.name}+1 sample",
                          info=dict(k.info, computation_delay={
                              "delay_s": k.sample_time_s, "samples": 1}))
