"""Anti-windup by back-calculation for the valve's saturation and rate limit.

A continuous law ẋ = A x + B y, u = C x + D y whose command the valve cannot follow (the
command beyond [p_min, p_max], or a pressure rate beyond the rate limit) keeps integrating
an error it cannot act on: its states wind up and the loop overshoots and recovers slowly
once the limit is left. Back-calculation (K. J. Åström and T. Hägglund, *Advanced PID
Control*, ISA 2006, §3.5; for state-space laws the observer form of K. J. Åström and
B. Wittenmark, *Computer-Controlled Systems*, 3rd ed. 1997, §9.4) feeds the part of the
command that is not delivered back into the states:

    ẋ = A x + B y + L (û − u),

û − u = clip(cmd) − cmd for the magnitude limit and, while the rate is limited, the command
the valve's unlimited lag would follow at the limited rate minus the requested one (first
order: p + τ ṗ_lim; second order, a steady ramp: p + 2ζ/ω_n ṗ_lim). Inside the limits
û − u is exactly 0 and the right-hand side takes the same arithmetic as without anti-windup
(the linear closed loop unchanged bit for bit). While limited, the law's states obey
ẋ = (A − L C) x + (B − L D) y + L û: A − L C must be stable (checked here).

Default gain: L in the span of the law's modes a decade slower than the tracking rate ω_t
(|λ| < ω_t/10:
the integrators and slow states, which wind up — a fast derivative filter does not), the
least-norm such L with C L = ω_t: the law's output relaxes to the delivered command at the
rate ω_t (the classic tracking time constant T_t = 1/ω_t of the PID form, where this L acts
on the integrator alone: ẋ_i ∋ −(û − u)/(k_i T_t)). ω_t defaults to the law's mid-band
frequency (:func:`law_bandwidth_hz`: where |K(iω)| is least, = 1/√(T_i T_d) for a PID —
Åström and Hägglund's rule T_t = √(T_i T_d)). A much faster tracking lets the integrator
absorb the proportional and derivative terms while saturated and then overshoot (measured:
docs/control.md §2.4).
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.controller import Controller

# Tracking rates allowed, Hz: from far below any rotor mode to far above any valve.
MIN_TRACKING_HZ, MAX_TRACKING_HZ = 1e-3, 1e6


def law_bandwidth_hz(controller: Controller) -> float:
    """The law's tracking frequency, Hz: where |K(iω)| is least between its integral and its
    derivative action — for a PID k_p + k_i/s + k_d s exactly ω = √(k_i/k_d) = 1/√(T_i T_d),
    Åström and Hägglund's rule T_t = √(T_i T_d) for the tracking time constant. Found on a
    log grid from 10⁻⁴ of the slowest non-zero pole to 10× the fastest, refined by Brent on log ω;
    a law whose |K| has no interior minimum (a pure low- or high-pass): the geometric mean of
    the magnitudes of its non-zero poles. No states, or integrators only: NaN."""
    from scipy.optimize import minimize_scalar

    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    if controller.n_states == 0:
        return math.nan
    lam = np.abs(np.linalg.eigvals(controller.A))
    scale = max(float(lam.max()), 1e-300)
    lam = lam[lam > 1e-9 * scale]
    if lam.size == 0:
        return math.nan
    A, B, C, D = controller.A, controller.B, controller.C, controller.D
    eye = np.eye(controller.n_states)

    def mag(logw):
        K = C @ np.linalg.solve(1j * 10.0 ** logw * eye - A, B) + D
        return float(np.linalg.norm(K))

    lo, hi = math.log10(lam.min()) - 4, math.log10(lam.max()) + 1
    grid = np.linspace(lo, hi, 201)
    vals = np.array([mag(x) for x in grid])
    i = int(np.argmin(vals))
    if 0 < i < grid.size - 1:
        r = minimize_scalar(mag, bracket=(grid[i - 1], grid[i], grid[i + 1]), method="brent",
                            options={"xtol": 1e-10})
        return float(10.0 ** r.x / (2 * math.pi))
    return float(np.exp(np.mean(np.log(lam))) / (2 * math.pi))


def tracking_matrix(controller: Controller, gain) -> np.ndarray:
    """A − L C: the law's state matrix while the valve is limited (the output tracking the
    delivered command)."""
    L = np.asarray(gain, dtype=float).reshape(-1, 1)
    return controller.A - L @ controller.C


def _slow_mode_gain(controller: Controller, w: float) -> np.ndarray:
    """L in the span of the law's modes a decade slower than the tracking rate (|λ| < ω_t/10: the
    integrators and slow states, which wind up; a fast filter state does not), the least-norm
    one with C L = ω_t. No slow mode: the span of all states."""
    lam, V = np.linalg.eig(controller.A)
    slow = np.abs(lam) < 0.1 * w  # a decade below the tracking rate
    if not slow.any():
        slow[:] = True
    Vs = V[:, slow]
    g = controller.C[0] @ Vs
    if not np.vdot(g, g).real > 0:
        Vs, g = np.eye(controller.n_states), controller.C[0]
    L = np.real(Vs @ (w * g.conj() / np.vdot(g, g).real))
    return L * (w / float(controller.C[0] @ L))  # exact C L = ω_t after taking the real part


def with_anti_windup(controller: Controller, tracking_rate_hz: float | None = None, *,
                     gain=None) -> Controller:
    """The continuous ``controller`` with back-calculation anti-windup on in the transient
    (module docstring). ``gain`` (n_k,) gives L directly; otherwise L on the law's slow modes
    with C L = ω_t, ω_t = 2π·``tracking_rate_hz`` (default :func:`law_bandwidth_hz`). The tracking rate used
    and the largest real part of A − L C (1/s) are stated in ``info``. Refused: a discrete
    or stateless law (nothing winds up), C = 0, or A − L C not stable."""
    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    if controller.discrete:
        raise InputError("controller.sample_time_s: anti-windup is built for a continuous law "
                         f"(got sample time {controller.sample_time_s:g} s)")
    nk = controller.n_states
    if nk == 0:
        raise InputError("controller: a static law (no states) has nothing to wind up")
    if gain is not None:
        if tracking_rate_hz is not None:
            raise InputError("tracking_rate_hz/gain: give one of them, not both")
        L = v.vector("gain", gain, nk)
        rate_hz = float(controller.C[0] @ L) / (2 * math.pi)
    else:
        cc = float(controller.C[0] @ controller.C[0])
        if not cc > 0:
            raise InputError("controller.C: the law's output does not depend on its states "
                             "(C = 0); nothing to track")
        if tracking_rate_hz is None:
            rate_hz = law_bandwidth_hz(controller)
            if not math.isfinite(rate_hz):
                raise InputError("tracking_rate_hz: the law has no non-zero pole to take a "
                                 "bandwidth from; give a tracking rate in Hz")
            rate_hz = min(max(rate_hz, MIN_TRACKING_HZ), MAX_TRACKING_HZ)
        rate_hz = v.in_range("tracking_rate_hz", tracking_rate_hz if tracking_rate_hz
                             is not None else rate_hz, MIN_TRACKING_HZ, MAX_TRACKING_HZ)
        L = _slow_mode_gain(controller, 2 * math.pi * rate_hz)
    lam = np.linalg.eigvals(tracking_matrix(controller, L))
    worst = float(lam.real.max())
    if not worst < 0:
        field = "gain" if gain is not None else "tracking_rate_hz"
        raise InputError(f"{field}: the law's states while the valve is limited (A − L C) are "
                         f"not stable (max Re λ = {worst:.4g} 1/s); choose another tracking "
                         f"rate or gain")
    info = dict(controller.info, anti_windup="back-calculation",
                tracking_rate_hz=rate_hz, tracking_max_real_1_per_s=worst)
    return controller.with_options(anti_windup_gain=L, info=info,
                                   name=controller.name + "+aw")
