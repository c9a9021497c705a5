"""The unbalance response's grid refinement reads the half-power bands as ``peaks()`` does:
a side whose walk climbs into another resonance has no half-power speed (its AF is
"unresolved", issue qa21), so no band is refined there — the refinement had walked on past
the neighbouring resonance and refined a band on its far side that no AF reads."""

from __future__ import annotations

import sys

import numpy as np

from rotordyn.results.unbalance import UnbalanceResult

ub_mod = sys.modules["rotordyn.analysis.unbalance"]


def _sdof(s, fn, zeta, scale):
    r = s / fn
    return scale * r**2 / np.sqrt((1 - r**2) ** 2 + (2 * zeta * r) ** 2)


def _result(s, amp):
    x = amp.astype(complex)[:, None]
    return UnbalanceResult(s, (0,), x, -1j * x, np.array(["ok"] * len(s)), ((0, 1e-4, 0.0),))


def test_a_band_cut_by_a_larger_resonance_is_not_refined():
    s = np.arange(20.0, 101.0, 1.0)
    # a well-damped resonance near 40 Hz (ζ = 0.2) whose skirt runs into a lightly damped one
    # at 60 Hz before falling to its half power: its upper half-power speed does not exist
    amp = _sdof(s, 40.0, 0.2, 1.0) + _sdof(s, 60.0, 0.02, 0.3)
    u = _result(s, amp)
    peaks = u.peaks()
    assert list(peaks["af_kind"]) == ["unresolved", "half_power"]
    bands = sorted(ub_mod._unresolved_bands(u))
    # the lower band of the first (35–36 Hz) and both of the 60 Hz one (a 1 Hz grid is
    # coarser than 0.2 % of N_c); the former walk went on past 60 Hz to where the response
    # falls below the first peak's half power and refined (78, 79) Hz, which no AF reads
    assert bands == [(35.0, 36.0), (58.0, 59.0), (61.0, 62.0)], bands


def test_isolated_resonance_bands_unchanged():
    s = np.arange(20.0, 101.0, 1.0)
    u = _result(s, _sdof(s, 50.0, 0.03, 1.0))
    bands = ub_mod._unresolved_bands(u)
    # both half-power speeds of a ζ = 0.03 mode at 50 Hz: N ≈ 50 (1 ∓ 0.03)
    assert len(bands) == 2
    (lo1, hi1), (lo2, hi2) = sorted(bands)
    assert lo1 <= 50 * 0.97 <= hi1 and lo2 <= 50 * 1.03 <= hi2
