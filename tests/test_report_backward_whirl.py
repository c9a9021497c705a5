"""A backward resonance in the report's critical-speed table and mode shapes
(docs/api-criteria.md, "Backward resonances"; rotordyn.report.critical_whirl).

Found by QA (qa21, 2026-12-06) on an overhung fan on anisotropic table bearings
(tests/data/models/fan_overhung_table.toml, not the paper rig): the API unbalance excites a
lightly damped backward mode near 27.9 Hz (ζ ≈ 0.03). The report's table knew forward and
planar modes only, so it drew and named the forward mode at 40.9 Hz for that peak.

Checks, each against a quantity computed here independently of the report code:
* at the peak's responding station the backward circular component of the response
  (UnbalanceResult.backward_m) has a local maximum within ±3 % of the peak and the forward one
  none (the orbit itself still runs forward there: the other modes' forward response is
  larger), and the table's ``whirl`` is "backward";
* the mode drawn is a rotor mode of the stability analysis at that speed whose orbit at the
  responding station runs backward (Im(x ȳ) < 0 from the eigenvector), within 5 % of the
  speed in frequency (a resonance of a mode crossing 1×), and it is named backward in the
  text report line;
* the backward peak is matched with the backward 1× crossing of the damped Campbell diagram
  (within the table's 5 % merge rule), whose δ the table carries: δ = 2πζ/√(1 − ζ²) with
  ζ ≈ 0.03 within a factor 2 (the QA figure);
* the forward critical above it (≈ 46 Hz, on a 10–50 Hz range) keeps forward whirl and a
  forward mode, as before.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.report.criteria import SpeedRange
from rotordyn.report.sections import (BACKWARD_NOTE, api_response, critical_speed_table,
                                      critical_text_lines, shapes_for)

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def fan():
    s = rd.System.from_toml(MODELS / "fan_overhung_table.toml")
    sp = np.arange(10.0, 50.0 + 1e-9, 0.5)
    c = rd.campbell(s, sp, 0.0, None)
    u, *_ = api_response(s, sp, 30.0, 0.0, None)
    crit = critical_speed_table(c, u)
    shapes = shapes_for(s, crit, 30.0, 75.0, 0.0, None)
    return s, sp, c, u, crit, shapes


def _row(crit, lo, hi):
    rows = crit[(crit.speed_hz > lo) & (crit.speed_hz < hi)]
    assert len(rows) == 1, crit.to_string()
    return rows.index[0], rows.iloc[0]


def test_backward_peak_is_named_by_its_response_orbit(fan):
    s, sp, c, u, crit, _ = fan
    _, row = _row(crit, 25.0, 31.0)
    at = int(row["whirl_station"])
    k = list(u.stations).index(at)
    # at the responding station the backward circular component has a local maximum within
    # ±3 % of the peak and the forward one has none (it falls through the peak)
    w = np.flatnonzero(np.abs(u.speeds_hz - row["peak_hz"]) <= 0.03 * row["peak_hz"])
    b, f = u.backward_m[w, k], u.forward_m[w, k]
    assert 0 < int(np.argmax(b)) < w.size - 1
    assert int(np.argmax(f)) in (0, w.size - 1)
    assert row["whirl"] == "backward"
    # the responding station: the largest orbit of the stations that peak there
    i = int(np.argmin(np.abs(u.speeds_hz - row["peak_hz"])))
    majors = {st: u.major_m[i, list(u.stations).index(st)]
              for st in (int(x) for x in row["stations"].split(", "))}
    assert at == max(majors, key=majors.get)
    # matched with the backward 1× crossing and its δ (ζ ≈ 0.03: δ ≈ 0.19)
    back = c.critical_speeds(whirl="backward")
    near = back[(back.speed_hz - row["peak_hz"]).abs() <= 0.05 * row["peak_hz"]]
    assert len(near) >= 1
    assert row["source"].startswith("damped Campbell crossing (1×, backward) + ")
    assert row["campbell_hz"] == pytest.approx(float(near.speed_hz.iloc[0]))
    zeta = 0.03
    assert 0.5 < row["log_dec"] / (2 * np.pi * zeta / np.sqrt(1 - zeta**2)) < 2.0


def test_backward_peak_draws_a_backward_mode(fan):
    s, sp, c, u, crit, shapes = fan
    n, row = _row(crit, 25.0, 31.0)
    m = shapes[n]
    assert m.figure is not None, m.why
    assert m.whirl.endswith("backward")
    assert abs(m.freq_hz - m.speed_hz) <= 0.05 * m.speed_hz  # the mode crossing 1× there
    # independently: that mode's eigenvector orbit at the responding station runs backward
    st = rd.stability(s, float(row["speed_hz"]), 0.0, None)
    j = int(np.argmin(np.abs(st.frequencies_hz - m.freq_hz)))
    assert st.frequencies_hz[j] == pytest.approx(m.freq_hz, rel=1e-9)
    node = int(s.rotor.station_nodes()[int(row["whirl_station"])])
    x, y = st.rotor_shapes[node, 0, j], st.rotor_shapes[node, 1, j]
    assert np.imag(x * np.conj(y)) < 0
    # the text report names it so, with the API treatment of a backward resonance
    rng = SpeedRange(sp, 30.0, "test range")
    lines = critical_text_lines(crit, shapes, rng, 0.0, False)
    text = "\n".join(lines)
    assert f"{m.whirl} mode at {m.freq_hz:.4g} Hz" in text
    assert BACKWARD_NOTE in text
    assert "forward mode at 40." not in text  # the mode drawn before


def test_forward_critical_keeps_its_forward_mode(fan):
    s, sp, c, u, crit, shapes = fan
    n, row = _row(crit, 40.0, 50.0)
    assert row["whirl"] in ("forward", "planar")
    assert shapes[n].whirl in ("forward", "planar")
    assert abs(shapes[n].freq_hz - shapes[n].speed_hz) <= 0.05 * shapes[n].speed_hz
