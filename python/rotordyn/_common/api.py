"""API 684 / API 617 criteria shared by the results, their figures and the report: the
amplification factor by the half-power method (with a bound when a half-power speed lies
outside the computed range), the separation margins they require, and how an AF is written.

Sources: API Standard 684, *Tutorial on rotordynamics: lateral critical speeds, unbalance
response, stability, train torsionals and rotor balancing*, 2nd ed. (2005), §2.8.2 (AF by the
half-power method, critically damped below 2.5, required separation margins); API Standard
617, 8th ed. (2014), §4.8.2 / 2.6.2 (the same margins and the amplitude limit)."""

from __future__ import annotations

import numpy as np

RESONANT_ZETA = 1.0 / np.sqrt(2.0)
"""A root damped beyond this damping ratio has no resonance peak (the response of a single
mode |H(ω)| peaks only for ζ < 1/√2); API 617 Level I, the report and the Campbell critical
speeds use it to tell a mode with a resonance from an overdamped root."""
RESONANT_LOG_DEC = 2.0 * np.pi * RESONANT_ZETA / np.sqrt(1.0 - RESONANT_ZETA ** 2)
"""The log decrement of :data:`RESONANT_ZETA`: δ = 2π."""

API_CRITICALLY_DAMPED_AF = 2.5
"""API 684 (2nd ed., §2.8.2; API 617 §2.6.2.10): a response with AF < 2.5 is critically damped
and needs no separation margin."""

def api_required_margin(af: float, below_operating: bool) -> float:
    """Separation margin (%) API 617/684 requires of a critical speed with amplification factor
    ``af``: none below AF 2.5 (critically damped); otherwise 17 (1 − 1/(AF − 1.5)) % below the
    operating range (at most 16 %) and 10 + 17 (1 − 1/(AF − 1.5)) % above it (at most 26 %).
    NaN for an AF that is not known (not resolved): the margin cannot be judged."""
    if np.isnan(af):
        return float("nan")
    if af < API_CRITICALLY_DAMPED_AF:
        return 0.0
    base = 17.0 * (1.0 - 1.0 / (af - 1.5))
    return min(16.0, base) if below_operating else min(26.0, 10.0 + base)


def amplification_factor(nc: float, n1: float, n2: float, s_lo: float, s_hi: float
                         ) -> tuple[float, str]:
    """(AF, kind) by the half-power method, AF = N_c / (N_2 − N_1) (API 684). ``kind``:
    ``"half_power"`` both half-power speeds found; ``"upper_bound"`` one or both lie outside
    the computed speeds [s_lo, s_hi], so N_2 − N_1 is at least the band up to the range's end
    and AF is at most the value given — reported only when that bound is below 2.5 (the
    response is then critically damped whatever the missing point); ``"unresolved"`` (AF
    NaN) when the bound says nothing (extend the speed range)."""
    if np.isfinite(n1) and np.isfinite(n2) and n2 > n1:
        return nc / (n2 - n1), "half_power"
    lo = n1 if np.isfinite(n1) else s_lo
    hi = n2 if np.isfinite(n2) else s_hi
    if hi > lo:
        bound = nc / (hi - lo)
        if bound < API_CRITICALLY_DAMPED_AF:
            return bound, "upper_bound"
    return float("nan"), "unresolved"


def af_text(af: float, kind: str) -> str:
    """AF for tables and figures: ``AF = 3.1``; ``AF ≤ 1.8`` (a bound, see
    :func:`amplification_factor`); ``AF < 1`` (a half-power band wider than N_c: no resonance,
    critically damped); ``AF not resolved``."""
    if kind == "unresolved" or not np.isfinite(af):
        return "AF not resolved"
    if af < 1.0:
        return "AF < 1 (no resonance)"
    return f"AF {'≤' if kind == 'upper_bound' else '='} {af:.2g}"
