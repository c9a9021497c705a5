"""``UnbalanceResult.peaks`` on responses with film-coefficient ripple.

The films' coefficients are only piecewise smooth in speed (a film node changes its cavitation
state between two speeds), so a computed response carries a ripple of ~0.1–1 % that the
adaptive speed grid resolves. Found on an overhung pump rotor on an elliptical and a three-lobe
bearing (72×16 films): 42 "critical speeds" with a half-power band at one station, where the
response has two humps. A local maximum that rises less than ``RIPPLE_PROMINENCE`` (2 %) of its
height above the valley that separates it from a higher one (its topographic prominence) is
not a resonance of that response; the reference here is the closed-form single-degree-of-freedom
response (peak at N_c √(1 − 2ζ²), AF ≈ 1/(2ζ) by the half-power method, API 684 §2.8.2).
"""

from __future__ import annotations

import numpy as np
import pytest

from rotordyn.results.unbalance import RIPPLE_PROMINENCE, UnbalanceResult


def sdof(s, nc, zeta):
    """|x| / (m e / M) of a single-degree-of-freedom rotor under unbalance, r = s / nc."""
    r = s / nc
    return r ** 2 / np.sqrt((1 - r ** 2) ** 2 + (2 * zeta * r) ** 2)


def response(s, a):
    return UnbalanceResult(s, (0,), a[:, None] + 0j, 1j * a[:, None],
                           np.array(["ok"] * s.size), ((0, 1e-4, 0.0),), None)


@pytest.mark.parametrize("ripple", [0.0, 0.002, 0.008])
def test_ripple_does_not_make_peaks(ripple):
    s = np.arange(10.0, 160.0, 0.05)
    a = 1e-6 * (sdof(s, 40.0, 0.05) + 0.3 * sdof(s, 110.0, 0.08))
    a *= 1 + ripple * np.sin(2 * np.pi * s / 0.37)  # a local maximum every 0.37 Hz
    pk = response(s, a).peaks(0)
    assert len(pk) == 2, pk
    # the smooth curve's peaks: an unbalance response (force ∝ Ω²) peaks at N_c / √(1 − 2ζ²);
    # within 0.3 % with the other mode's tail added, + half the ripple's size (the ripple moves
    # the top of the broad second peak: 0.32 % at 0.8 % ripple)
    want = [40.0 / np.sqrt(1 - 2 * 0.05 ** 2), 110.0 / np.sqrt(1 - 2 * 0.08 ** 2)]
    np.testing.assert_allclose(pk["critical_speed_hz"], want, rtol=3e-3 + 0.5 * ripple)
    assert (pk["af_kind"] == "half_power").all()
    # AF by the half-power method ≈ 1/(2ζ) = 10 for the isolated first mode (9.90 on this grid,
    # 9.86 with the second mode's tail), within 3 % + the ripple's own shift of the band edges
    assert pk["amplification_factor"].iloc[0] == pytest.approx(10.0, rel=0.03 + 2 * ripple)


def test_a_small_separate_resonance_is_kept():
    """A weak, lightly damped mode riding on the flank of a larger one: a dip of several % of
    its height on each side, so it stays a peak (prominence well above 2 %)."""
    s = np.arange(10.0, 160.0, 0.05)
    a = sdof(s, 40.0, 0.05) + 0.02 * sdof(s, 70.0, 0.01)
    pk = response(s, a).peaks(0)
    assert len(pk) == 2
    assert pk["critical_speed_hz"].iloc[1] == pytest.approx(70.0, rel=1e-3)
    assert RIPPLE_PROMINENCE == 0.02


def test_bode_legend_names_only_what_is_drawn():
    """No half-power band in the legend of a response without one; the labels of many peaks
    do not pile up (the smaller ones hidden, their number said in the legend)."""
    import matplotlib
    matplotlib.use("Agg")
    s = np.arange(10.0, 160.0, 0.05)
    mono = response(s, 1e-6 * s / 160.0)  # rising, no peak
    a1, _ = mono.plot(station=0)
    names = [t.get_text() for t in a1.figure.legends[0].get_texts()]
    assert not any("half-power" in n or "critical speed" in n for n in names), names
    # six well separated sharp modes of falling height on a figure a third of a page wide
    a = sum(h * sdof(s, nc, 0.01) for h, nc in zip((6, 5, 4, 3, 2, 1), (30, 36, 42, 48, 54, 60)))
    many = response(s, 1e-6 * a)
    assert len(many.peaks(0)) == 6
    a1, _ = many.plot(station=0)
    names = [t.get_text() for t in a1.figure.legends[0].get_texts()]
    assert any("half-power" in n for n in names)
    shown = [t for t in a1.texts if t.get_visible() and t.get_text().startswith("N_c")]
    r = a1.figure.canvas.get_renderer()
    boxes = [t.get_window_extent(r) for t in shown]
    assert all(not b.overlaps(c) for i, b in enumerate(boxes) for c in boxes[i + 1:])
    if len(shown) < 6:
        assert any(f"{6 - len(shown)} smaller not labelled" in n for n in names), names


def test_refinement_skips_ripple():
    """The compressor on 5-pad tilting-pad bearings has no resonance in 10–200 Hz (a broad
    hump at ~161 Hz stands 1.9 % above the response at 200 Hz): the adaptive grid added 60
    speeds around its ripple before; now none, and the response has no peak."""
    from pathlib import Path

    import rotordyn as rd
    s = rd.System.from_toml(Path(__file__).parent / "data" / "models" /
                            "compressor_tilting_pad.toml")
    sp = np.linspace(10, 200, 40)
    u = rd.unbalance_response(s, [(3, 1e-4, 0.0)], sp, stations=[1, 3])
    np.testing.assert_array_equal(u.speeds_hz, sp)
    assert u.peaks(1).empty and u.peaks(3).empty


def test_no_separation_margin_check_for_a_peak_without_resonance():
    """A hump with AF < 1 (its half-power band wider than its speed) stays in the peaks table
    but is no critical speed: the report adds no separation-margin check for it (it added a
    PASS row "separation margin, N_c = …: AF < 1 (no resonance)")."""
    from rotordyn.report.criteria import Checks, separation_checks

    s = np.arange(5.0, 200.0, 0.25)
    # a broad hump at 40 Hz (half-power band 47 Hz: AF ≈ 0.85) and a sharp mode (AF ≈ 25)
    a = np.exp(-((s - 40.0) / 40.0) ** 2) + 0.1 * sdof(s, 120.0, 0.02)
    u = UnbalanceResult(s, (0,), 1e-6 * a[:, None] + 0j, 1e-6j * a[:, None],
                        np.array(["ok"] * s.size), ((0, 1e-4, 0.0),), (60.0, 70.0))
    pk = u.peaks(0)
    assert len(pk) == 2 and pk["amplification_factor"].iloc[0] < 1.0
    checks = Checks()
    rows = separation_checks(checks, u, 0)
    assert len(rows) == 2  # the peaks table keeps both
    names = [r[0] for r in checks.rows]
    assert len(names) == 1 and "N_c = 120" in names[0], names
