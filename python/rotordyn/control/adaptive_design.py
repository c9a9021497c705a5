"""Design and check of the adaptive 1× law (:mod:`rotordyn.control.adaptive`) on the linear
plant: the averaged adaptive loop, its modal shares and the adaptation gain scheduled over the
speed (docs/control.md §2.6).

**Averaged loop.** With the plant's complex 1× envelope x (real state Re(x e^{iθ})) the law
Ṗ = −γ T̂⁺ 2y e^{−iθ} − σP averages over a revolution (the 2Ω terms dropped) to the linear
time-invariant loop at each speed Ω

    ẋ = (A − iΩ I) x + B P,   Ṗ = −γ T̂⁺ (C x + D P) − σ P,

whose eigenvalues are the plant's shifted by −iΩ (their real parts unchanged) and the
adaptation pole, all moved by the coupling. Its characteristic equation is
s + σ + γ T̂⁺ T(s + iΩ) = 0 with T(s) = C(sI − A)⁻¹B + D.

**Modal shares.** With T(iΩ) = Σ_k R_k/(iΩ − λ_k) + D (R_k = C v_k u_kᵀ B) the shares
w_k = T̂⁺ R_k/(iΩ − λ_k) sum (with T̂⁺D) to T̂⁺T (= 1 when T̂ = T). To first order in γ the
adaptation moves the pole p_k = λ_k − iΩ of the averaged loop by δ_k = γ w_k (from
(s − p_k)(s + σ + γ T̂⁺T_rest) + γ T̂⁺R_k = 0 for |p_k| ≫ γ), so mode k keeps a fraction
(1 − κ) of its decay rate a_k = −Re λ_k as long as

    γ ≤ κ a_k / Re w_k   (every k with Re w_k > 0),

which is the rule "γ below a fraction of the slowest decay rate of the modes near the rotor
frequency" with the band replaced by each mode's share of the 1× response. A mode far from Ω
has a small share and does not limit γ; at a critical speed the lightly damped mode carries
almost all of T and caps γ at ≈ κ a_k. Re(T̂⁺T) > 0 (the classic LMS condition, phase error
below 90°) is the small-γ limit of the same loop (the adaptation pole ≈ −γ T̂⁺T − σ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.adaptive import MAX_GAIN_1_PER_S, AdaptiveRejection, _leak
from rotordyn.operation.measurement import parse_measurements


def _linear_plants(system, speeds_hz, measurements, chamber_pressure_pa, config_ay_m,
                   actuator):
    """Per speed (balanced (A, B, C, D) command → measurements, T(iΩ) (n_y,))."""
    from rotordyn.control import lti
    from rotordyn.control.plant import plant

    out = []
    for f in speeds_hz:
        pc = chamber_pressure_pa(float(f)) if callable(chamber_pressure_pa) \
            else chamber_pressure_pa
        p = plant(system, float(f), pc, config_ay_m, measurements=measurements,
                  actuator=actuator)
        A, B, C, D = p.matrices()
        ny = p.C.shape[0]
        ss = lti.balanced(lti.SS(A, B[:, :1], C[:ny], D[:ny, :1]))
        T = lti.freqresp(ss, 2 * np.pi * np.array([float(f)]))[0][:, 0]
        out.append((ss, T))
    return out


def averaged_poles(ss, omega_rad_s: float, update, gain_1_per_s: float,
                   leak_1_per_s: float = 0.0) -> np.ndarray:
    """Eigenvalues (1/s) of the averaged adaptive loop (module docstring) at one speed:
    ``ss`` the plant command → measurements (A, B, C, D with one input), ``update`` T̂⁺
    (n_y,) complex."""
    A, B, C, D = ss.A, ss.B[:, 0], ss.C, ss.D[:, 0]
    G = np.asarray(update, dtype=complex)
    n = A.shape[0]
    M = np.zeros((n + 1, n + 1), dtype=complex)
    M[:n, :n] = A - 1j * omega_rad_s * np.eye(n)
    M[:n, n] = B
    M[n, :n] = -gain_1_per_s * (G @ C)
    M[n, n] = -gain_1_per_s * (G @ D) - leak_1_per_s
    return np.linalg.eigvals(M)


def modal_shares(ss, omega_rad_s: float, update):
    """(λ_k, w_k, T̂⁺D): the plant's eigenvalues and their shares w_k of T̂⁺T(iΩ) (module
    docstring); Σ w_k + T̂⁺D = T̂⁺T."""
    lam, V = np.linalg.eig(ss.A)
    U = np.linalg.solve(V, ss.B[:, :1])[:, 0]  # u_kᵀ B
    G = np.asarray(update, dtype=complex)
    w = (G @ (ss.C @ V)) * U / (1j * omega_rad_s - lam)
    return lam, w, complex(G @ ss.D[:, 0])


@dataclass(frozen=True)
class AdaptiveDesign:
    """The adaptive law designed on the linear plant over ``speeds_hz`` (n_g,):
    ``influence`` T (n_g, n_y), ``gain_1_per_s`` γ(Ω) of the share rule, ``limit_hz`` the
    frequency of the mode that sets it (NaN: γ_max), ``share_sum`` Σ w_k + T̂⁺D (= 1 check),
    ``averaged_max_real_1_per_s`` max Re of the averaged loop at γ(Ω), ``passive_max_real_1_per_s``
    max Re of the plant, and the law itself (``law``)."""

    speeds_hz: np.ndarray
    influence: np.ndarray
    gain_1_per_s: np.ndarray
    limit_hz: np.ndarray
    share_sum: np.ndarray
    averaged_max_real_1_per_s: np.ndarray
    passive_max_real_1_per_s: np.ndarray
    law: AdaptiveRejection
    fraction: float

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame({
            "speed_hz": self.speeds_hz, "gain_1_per_s": self.gain_1_per_s,
            "limit_mode_freq_hz": self.limit_hz, "share_sum_re": self.share_sum.real,
            "share_sum_im": self.share_sum.imag,
            "averaged_max_real_1_per_s": self.averaged_max_real_1_per_s,
            "passive_max_real_1_per_s": self.passive_max_real_1_per_s})

    def __repr__(self) -> str:
        g = self.gain_1_per_s
        return (f"AdaptiveDesign({self.speeds_hz.size} speeds {self.speeds_hz[0]:g}–"
                f"{self.speeds_hz[-1]:g} Hz, κ = {self.fraction:g}, γ {g.min():.3g}–"
                f"{g.max():.3g} 1/s)")


def share_rule_gain(lam, w, fraction: float, gain_max: float) -> tuple[float, float]:
    """γ = min(γ_max, κ min_k a_k / Re w_k) over the modes with Re w_k > 0 (module
    docstring); an unstable mode with a positive share gives 0. Returns (γ, the limiting
    mode's frequency in Hz or NaN)."""
    g, at = gain_max, math.nan
    for lk, wk in zip(lam, w):
        if wk.real <= 0:
            continue
        lim = fraction * max(-lk.real, 0.0) / wk.real
        if lim < g:
            g, at = lim, abs(lk.imag) / (2 * math.pi)
    return g, at


def adaptive_design(system, speeds_hz, measurements, *, fraction: float = 0.5,
                    gain_max_1_per_s: float = 20.0, leak_1_per_s: float = 0.0,
                    freeze_at_limits: bool = False, chamber_pressure_pa=0.0,
                    config_ay_m=None, actuator=None,
                    washout_hz: float = 0.0) -> AdaptiveDesign:
    """Influence coefficients and the scheduled gain γ(Ω) = min(γ_max, κ min_k a_k/Re w_k)
    on the grid ``speeds_hz`` (κ = ``fraction`` ∈ (0, 1]: the share of each mode's decay rate
    the adaptation may take, to first order), with the exact averaged loop's max Re at that
    gain as the check; ``washout_hz`` the law's measurement washout (Hz; 0: none, see
    :mod:`rotordyn.control.adaptive`; the averaged loop is the same with it)."""
    sp = v.speeds("speeds_hz", speeds_hz)
    meas = parse_measurements(measurements)
    kappa = v.in_range("fraction", fraction, 0.0, 1.0, lo_open=True)
    gmax = v.in_range("gain_max_1_per_s", gain_max_1_per_s, 0.0, MAX_GAIN_1_PER_S,
                      lo_open=True)
    sigma = _leak(leak_1_per_s)
    if sp.size > 1 and np.any(np.diff(sp) <= 0):
        raise InputError(f"speeds_hz: expected strictly increasing speeds, got {sp!r}")
    plants = _linear_plants(system, sp, meas, chamber_pressure_pa, config_ay_m, actuator)
    T = np.array([t for _, t in plants])
    upd = T.conj() / np.sum(np.abs(T) ** 2, axis=1, keepdims=True)
    gam, at, ssum, amax, pmax = (np.empty(sp.size) for _ in range(5))
    ssum = ssum.astype(complex)
    for i, ((ss, _), f) in enumerate(zip(plants, sp)):
        w0 = 2 * np.pi * f
        lam, w, d = modal_shares(ss, w0, upd[i])
        gam[i], at[i] = share_rule_gain(lam, w, kappa, gmax)
        ssum[i] = w.sum() + d
        pmax[i] = lam.real.max()
        amax[i] = averaged_poles(ss, w0, upd[i], gam[i], sigma).real.max()
    law = AdaptiveRejection(meas, sp, T, (sp, gam), leak_1_per_s=sigma,
                            freeze_at_limits=freeze_at_limits, washout_hz=washout_hz)
    return AdaptiveDesign(sp, T, gam, at, ssum, amax, pmax, law, kappa)


def averaged_stability(system, law: AdaptiveRejection, *, speeds_hz=None,
                       chamber_pressure_pa=0.0, config_ay_m=None, actuator=None):
    """Max Re (1/s) of the averaged loop of ``law`` (its T̂⁺, γ(Ω) and σ) closed around the
    linear plant at each speed (default: the law's grid), (n,) array."""
    if not isinstance(law, AdaptiveRejection):
        raise InputError(f"law: expected an AdaptiveRejection, got {type(law).__name__}")
    sp = law.speeds_hz if speeds_hz is None else v.speeds("speeds_hz", speeds_hz)
    plants = _linear_plants(system, sp, law.measurements, chamber_pressure_pa, config_ay_m,
                            actuator)
    G = law.update
    out = np.empty(sp.size)
    for i, ((ss, _), f) in enumerate(zip(plants, sp)):
        gi = np.array([np.interp(f, law.speeds_hz, G[:, j].real)
                       + 1j * np.interp(f, law.speeds_hz, G[:, j].imag)
                       for j in range(G.shape[1])])
        out[i] = averaged_poles(ss, 2 * np.pi * f, gi, float(law.gain_at(f)),
                                law.leak_1_per_s).real.max()
    return out


__all__ = ["AdaptiveDesign", "adaptive_design", "averaged_poles", "averaged_stability",
           "modal_shares", "share_rule_gain"]
