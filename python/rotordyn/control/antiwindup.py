"""Anti-windup for the valve's saturation and rate limit: back-calculation and conditioning,
for continuous and discrete (sample-and-hold) laws.

A law ẋ = A x + B y, u = C x + D y whose command the valve cannot follow (the command
beyond [p_min, p_max], or a pressure rate beyond the rate limit) keeps integrating an error
it cannot act on: its states wind up and the loop overshoots and recovers slowly once the
limit is left. Back-calculation (K. J. Åström and T. Hägglund, *Advanced PID Control*, ISA
2006, §3.5; for state-space laws the observer form of K. J. Åström and B. Wittenmark,
*Computer-Controlled Systems*, 3rd ed. 1997, §9.4) feeds the part of the command that is not
delivered back into the states:

    ẋ = A x + B y + L (û − u)                       (continuous)
    x_{k+1} = A x_k + B y_k + L (û_k − u_k)         (discrete, û_k − u_k when u_k is applied)

û − u = clip(cmd) − cmd for the magnitude limit and, while the rate is limited, the command
the valve's unlimited lag would follow at the limited rate minus the requested one (first
order: p + τ ṗ_lim; second order, a steady ramp: p + 2ζ/ω_n ṗ_lim). Inside the limits
û − u is exactly 0 and the right-hand side takes the same arithmetic as without anti-windup
(the linear closed loop unchanged bit for bit). While limited, the law's states obey
ẋ = (A − L C) x + (B − L D) y + L û: A − L C must be stable (continuous: Re λ < 0; discrete:
|λ| < 1; checked here).

**Conditioning** (``mode="conditioning"``; R. Hanus, M. Kinnaert and J.-L. Henrotte,
"Conditioning technique, a general anti-windup and bumpless transfer method", Automatica 23
(1987) 729–739: the *realisable reference*). The command is cmd = ff + u, ff the open-loop
part (the pressure schedule p_c(t) or p_c(Ω) and its harmonic). When ff itself leaves the
valve's range, back-calculation drives the law's output to p_max − ff, the schedule's
unrealisable part, which the loop then has to unwind after the episode. Conditioning
realises the open-loop part first — the command is clip(ff) + u — so that û − u is the
law's own share of the saturation only: zero while the law's increment fits in the range
the schedule leaves. Inside the limits clip(ff) = ff exactly (bit for bit). The gain is the
one of back-calculation (the same tracking rule), or Hanus's own L = B D⁺ (``gain="hanus"``:
the states see the measurement that would have produced the delivered command, y^r =
y + D⁺(û − u); A − B D⁺ C has the law's zeros as eigenvalues, so a non-minimum-phase law is
refused; D⁺ = Dᵀ/(D Dᵀ) is scale dependent when the measurements mix units).

Default gain: L in the span of the law's modes a decade slower than the tracking rate ω_t
(continuous |λ| < ω_t/10, discrete |ln z|/T < ω_t/10: the integrators and slow states,
which wind up — a fast derivative filter does not), the least-norm such L with C L = ω_t
(continuous: the law's output relaxes to the delivered command at the rate ω_t) or
C L = 1 − e^{−ω_t T} (discrete: the same relaxation over one sample). This is the classic
tracking time constant T_t = 1/ω_t of the PID form, where this L acts on the integrator
alone: ẋ_i ∋ −(û − u)/(k_i T_t). ω_t defaults to the law's mid-band frequency
(:func:`law_bandwidth_hz`: where |K(iω)| (discrete: |K(e^{iωT})|) is least, = 1/√(T_i T_d)
for a PID — Åström and Hägglund's rule T_t = √(T_i T_d)). A much faster tracking lets the
integrator absorb the proportional and derivative terms while saturated and then overshoot
(measured: docs/control.md §2.4).
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.controller import ANTI_WINDUP_MODES, Controller

# Tracking rates allowed, Hz: from far below any rotor mode to far above any valve.
MIN_TRACKING_HZ, MAX_TRACKING_HZ = 1e-3, 1e6


def _poles_1_per_s(controller: Controller) -> np.ndarray:
    """|λ| of the law's poles, 1/s: continuous eig(A); discrete |ln z|/T (a pole at z = 0,
    deadbeat: the Nyquist rate π/T)."""
    lam = np.linalg.eigvals(controller.A)
    if not controller.discrete:
        return np.abs(lam)
    T = controller.sample_time_s
    with np.errstate(divide="ignore"):
        s = np.abs(np.log(lam.astype(complex))) / T
    return np.where(np.abs(lam) > 0, s, math.pi / T)


def _response(controller: Controller, w: float):
    """K at the frequency w (rad/s): C (sI − A)⁻¹ B + D, s = iω or z = e^{iωT}."""
    s = np.exp(1j * w * controller.sample_time_s) if controller.discrete else 1j * w
    eye = np.eye(controller.n_states)
    return controller.C @ np.linalg.solve(s * eye - controller.A, controller.B) + controller.D


def law_bandwidth_hz(controller: Controller) -> float:
    """The law's tracking frequency, Hz: where |K(iω)| (discrete: |K(e^{iωT})|) is least
    between its integral and its derivative action — for a PID k_p + k_i/s + k_d s exactly
    ω = √(k_i/k_d) = 1/√(T_i T_d), Åström and Hägglund's rule T_t = √(T_i T_d) for the
    tracking time constant. Found on a log grid from 10⁻⁴ of the slowest non-zero pole to 10×
    the fastest (discrete: at most the Nyquist frequency π/T; poles |ln z|/T), refined by Brent
    on log ω; a law whose |K| has no interior minimum (a pure low- or high-pass): the geometric
    mean of the magnitudes of its non-zero poles. No states, or integrators only: NaN."""
    from scipy.optimize import minimize_scalar

    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    if controller.n_states == 0:
        return math.nan
    lam = _poles_1_per_s(controller)
    scale = max(float(lam.max()), 1e-300)
    lam = lam[lam > 1e-9 * scale]
    if lam.size == 0:
        return math.nan

    def mag(logw):
        return float(np.linalg.norm(_response(controller, 10.0 ** logw)))

    lo, hi = math.log10(lam.min()) - 4, math.log10(lam.max()) + 1
    if controller.discrete:
        hi = min(hi, math.log10(math.pi / controller.sample_time_s))
        lo = min(lo, hi - 1)
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
    delivered command; discrete: the map from x_k to x_{k+1})."""
    L = np.asarray(gain, dtype=float).reshape(-1, 1)
    return controller.A - L @ controller.C


def tracking_target(controller: Controller, w: float) -> float:
    """C L of the default gain at the tracking rate w (rad/s): w (continuous), or
    1 − e^{−w T} (discrete: the output's relaxation to the delivered command per sample)."""
    if controller.discrete:
        return -math.expm1(-w * controller.sample_time_s)
    return w


def _slow_mode_gain(controller: Controller, w: float) -> np.ndarray:
    """L in the span of the law's modes a decade slower than the tracking rate (|λ| < ω_t/10,
    discrete |ln z|/T: the integrators and slow states, which wind up; a fast filter state
    does not), the least-norm one with C L = tracking_target. No slow mode: the span of all
    states."""
    lam, V = np.linalg.eig(controller.A)
    slow = _poles_1_per_s(controller) < 0.1 * w  # a decade below the tracking rate
    if not slow.any():
        slow[:] = True
    target = tracking_target(controller, w)
    Vs = V[:, slow]
    g = controller.C[0] @ Vs
    if not np.vdot(g, g).real > 0:
        Vs, g = np.eye(controller.n_states), controller.C[0]
    L = np.real(Vs @ (target * g.conj() / np.vdot(g, g).real))
    return L * (target / float(controller.C[0] @ L))  # exact C L after taking the real part


def hanus_gain(controller: Controller) -> np.ndarray:
    """Hanus's conditioning gain L = B D⁺, D⁺ = Dᵀ/(D Dᵀ) (n_k,): the law's states driven by
    the realisable measurement y + D⁺(û − u), which would have produced the delivered command.
    Refused when D = 0 (a strictly proper law has no realisable measurement)."""
    D = controller.D[0]
    dd = float(D @ D)
    if not dd > 0:
        raise InputError("gain: 'hanus' needs a law with direct feedthrough (controller.D ≠ 0); "
                         "give a tracking rate or a gain instead")
    return controller.B @ D / dd


GAINS = ("hanus",)


def with_anti_windup(controller: Controller, tracking_rate_hz: float | None = None, *,
                     gain=None, mode: str = "back-calculation") -> Controller:
    """The ``controller`` (continuous or discrete) with anti-windup on in the transient
    (module docstring): ``mode`` "back-calculation" (the whole undelivered command fed back)
    or "conditioning" (the schedule realised first, clip(ff) + u: only the law's own share
    fed back). ``gain``: L (n_k,) directly, or "hanus" (L = B D⁺); otherwise L on the law's
    slow modes with C L = ω_t (discrete 1 − e^{−ω_t T}), ω_t = 2π·``tracking_rate_hz``
    (default :func:`law_bandwidth_hz`). ``info`` states the mode, the gain's origin, the
    tracking rate (a given or Hanus gain: the slowest mode of A − L C, Hz) and the largest real
    part of A − L C (1/s; discrete: its spectral radius). Refused (InputError
    naming the field): a stateless law (nothing winds up), C = 0, a tracking rate outside
    [1e-3, 1e6] Hz or not finite, an unknown mode or gain name, or A − L C not stable."""
    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    mode = v.choice("mode", mode, ANTI_WINDUP_MODES)
    nk = controller.n_states
    if nk == 0:
        raise InputError("controller: a static law (no states) has nothing to wind up")
    disc = controller.discrete
    if gain is not None and tracking_rate_hz is not None:
        raise InputError("tracking_rate_hz/gain: give one of them, not both")
    if isinstance(gain, str):
        v.choice("gain", gain, GAINS)
        L = hanus_gain(controller)
        gain_kind = "hanus"
    elif gain is not None:
        L = v.vector("gain", gain, nk)
        gain_kind = "given"
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
        else:
            rate_hz = v.in_range("tracking_rate_hz", tracking_rate_hz, MIN_TRACKING_HZ,
                                 MAX_TRACKING_HZ)
        L = _slow_mode_gain(controller, 2 * math.pi * rate_hz)
        gain_kind = "slow modes"
    lam = np.linalg.eigvals(tracking_matrix(controller, L))
    if gain is not None:
        # the slowest mode of A − L C, Hz (discrete |ln z|/T): how fast the law's states
        # settle on the delivered command while limited
        with np.errstate(divide="ignore"):
            mags = (np.abs(np.log(lam.astype(complex))) / controller.sample_time_s if disc
                    else np.abs(lam))
        rate_hz = float(mags.min()) / (2 * math.pi)
    worst = float(np.abs(lam).max()) if disc else float(lam.real.max())
    if not (worst < 1 if disc else worst < 0):
        field = "gain" if gain is not None else "tracking_rate_hz"
        what = f"max |λ| = {worst:.4g}" if disc else f"max Re λ = {worst:.4g} 1/s"
        raise InputError(f"{field}: the law's states while the valve is limited (A − L C) are "
                         f"not stable ({what}); choose another tracking rate or gain")
    info = dict(controller.info, anti_windup=mode, anti_windup_gain=gain_kind,
                tracking_rate_hz=rate_hz)
    info["tracking_max_abs" if disc else "tracking_max_real_1_per_s"] = worst
    return controller.with_options(anti_windup_gain=L, anti_windup_mode=mode, info=info,
                                   name=controller.name + ("+cond" if mode == "conditioning"
                                                           else "+aw"))
