"""Amplification factor of a resonance peak whose half-power band runs into a larger peak
(QA pass qa21, an overhung fan on speed-dependent bearing tables).

The half-power method (API 684 2nd ed. §2.8: AF = N_c / (N_2 − N_1)) needs both speeds where
the response falls to 1/√2 of the peak. When the response climbs into a larger resonance
before it falls that far, N_2 does not exist: the band is cut by another mode, not by the end
of the computed speeds. `UnbalanceResult.peaks` used the end of the range as N_2 and reported
"AF ≤ 1.2, critically damped, no separation margin required" for a backward-whirl resonance
of damping ratio ≈ 0.02 (its own AF ≈ 25) inside the fan's operating range. Such a peak's AF
is not resolved (NaN, ``af_kind = "unresolved"``, required margin NaN): the margin cannot be
judged, rather than judged passed.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.results.unbalance import UnbalanceResult

MODELS = Path(__file__).parent / "data" / "models"


def _sdof(s, fn, zeta):
    r = s / fn
    return 1.0 / np.abs(1.0 - r**2 + 2j * zeta * r)


def _synthetic(speeds):
    """A small resonance (28 Hz, ζ = 0.025) on the skirt of a large one (46 Hz, ζ = 0.002):
    between them the response never falls below the small peak's half-power level."""
    x = 0.6 * _sdof(speeds, 46.0, 0.002) + 0.03 * _sdof(speeds, 28.0, 0.025)
    n = speeds.size
    return UnbalanceResult(speeds, (3,), (x * 1e-6).astype(complex).reshape(n, 1),
                           np.zeros((n, 1), complex), np.array(["ok"] * n, dtype=object),
                           ((3, 1e-4, 0.0),), operating_speed_hz=(20.0, 30.0))


def test_band_cut_by_a_larger_peak_is_unresolved_not_critically_damped():
    speeds = np.round(np.arange(10.0, 50.0 + 1e-9, 0.01), 6)
    pk = _synthetic(speeds).peaks(3)
    assert len(pk) == 2
    small, large = pk.iloc[0], pk.iloc[1]
    assert small["critical_speed_hz"] == pytest.approx(28.0, abs=0.2)
    # the response between the peaks stays above the small peak's half-power level
    x = np.abs(_synthetic(speeds).x[:, 0])
    band = (speeds > small["critical_speed_hz"]) & (speeds < 46.0)
    assert x[band].min() > small["peak_m"] / np.sqrt(2)
    assert small["af_kind"] == "unresolved"
    assert np.isnan(small["amplification_factor"])
    assert not small["critically_damped"]
    assert np.isnan(small["required_margin_pct"])
    # the large peak keeps its half-power AF, 1/(2ζ) = 250 for the SDOF (within 2 %: the
    # other mode's skirt and the 0.01 Hz grid)
    assert large["af_kind"] == "half_power"
    assert large["amplification_factor"] == pytest.approx(250.0, rel=0.02)


def test_band_cut_by_the_range_end_keeps_its_upper_bound():
    """The bound stays where it is a bound: a single heavily damped peak whose upper
    half-power speed lies beyond the computed range (ζ = 0.4: AF ≤ range bound < 2.5)."""
    speeds = np.round(np.arange(10.0, 36.0 + 1e-9, 0.05), 6)
    x = _sdof(speeds, 30.0, 0.4) * 1e-6
    n = speeds.size
    u = UnbalanceResult(speeds, (1,), x.astype(complex).reshape(n, 1), np.zeros((n, 1), complex),
                        np.array(["ok"] * n, dtype=object), ((1, 1e-4, 0.0),))
    pk = u.peaks(1)
    assert len(pk) == 1
    assert pk.iloc[0]["af_kind"] == "upper_bound"
    assert pk.iloc[0]["critically_damped"]


def test_overhung_fan_backward_resonance_in_the_operating_range():
    """The machine where it showed: 180 kg overhung fan on two anisotropic bearing tables;
    the unbalance excites a lightly damped backward mode at ≈ 27.9 Hz (inside the 20–30 Hz
    operating range) on the skirt of the forward critical at ≈ 46.4 Hz."""
    s = rd.System.from_toml(MODELS / "fan_overhung_table.toml")
    u = rd.unbalance_response(s, [(3, 2e-4, 0.0)], np.arange(10.0, 50.1, 1.0), stations=[3],
                              operating_speed_hz=(20.0, 30.0))
    pk = u.peaks(3)
    back = pk[(pk.critical_speed_hz > 25) & (pk.critical_speed_hz < 31)]
    assert len(back) == 1
    row = back.iloc[0]
    assert row["af_kind"] == "unresolved"
    assert not row["critically_damped"]
    assert np.isnan(row["required_margin_pct"])
    fwd = pk[pk.critical_speed_hz > 40].iloc[0]
    assert fwd["af_kind"] == "half_power" and fwd["amplification_factor"] > 100
