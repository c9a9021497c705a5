"""The report's mode choices on heavily damped films (an overhung pump on tilting pads).

Stiff, heavily damped tilting pads make the pump's rigid-body roots overdamped: at 60 Hz the
lowest "forward rotor" roots are -329 ± 0.82i 1/s (damping ratio 0.999997, δ ≈ 2500) — no
resonance peak. The report took them for modes: the API 684 unbalance went to the NDE end
(station 0) "for the first forward mode (0.1303 Hz)", the stability screening printed
"minimum δ = 1.47e+03", and the drawn "least damped forward mode" was the δ = 2520 root.
API 617 Level I (`rotordyn.level1`) already judged only modes with a resonance (damping
ratio below 1/√2, δ < 2π); the report now uses the same rule: the unbalance goes to the
station of the first forward mode with a resonance (131 Hz: the impeller, station 3, where
the mode's deflection is largest), the screening says no mode has a resonance below its
window, and the drawn mode is that 131 Hz mode (δ ≈ 1).
"""

from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn.cli import main

PUMP = Path(__file__).parent / "data" / "models" / "pump_overhung_tilting_pad.toml"


def test_overdamped_roots_are_not_the_reports_modes(tmp_path):
    s = rd.System.from_toml(PUMP)
    st = rd.stability(s, 60.0)
    fwd = [j for j in range(len(st.eigenvalues)) if st.whirl[j] == "forward"
           and st.kind[j] == "rotor" and st.eigenvalues[j].imag > 0]
    # the premise: the lowest forward rotor root has no resonance, a higher one has
    assert st.damping_ratio[fwd[0]] > 0.99
    first = next(j for j in fwd if st.damping_ratio[j] < 1 / np.sqrt(2))
    assert 100.0 < st.frequencies_hz[first] < 200.0
    d = tmp_path / "rep"
    assert main(["report", str(PUMP), "--out", str(d), "--operating-speed-hz", "40", "60",
                 "--speeds-hz", "10:70:20"]) == 0
    text = (d / "report.txt").read_text()
    nodes = s.rotor.station_nodes()
    amp = np.abs(st.rotor_shapes[nodes, 0, first]) + np.abs(st.rotor_shapes[nodes, 1, first])
    k = int(np.argmax(amp))
    assert k == 3  # the overhung impeller, not the NDE end (station 0) of the overdamped root
    assert (f"at station {k}, the largest deflection of the first forward mode "
            f"({st.frequencies_hz[first]:.4g} Hz at 60 Hz)") in text
    assert "minimum δ = 1.4" not in text and "log dec 2.5" not in text
    assert "no forward rotor mode with a resonance below" in text
    shape = next(ln for ln in text.splitlines() if "critical_mode_1.png" in ln)
    assert f"forward mode at {st.frequencies_hz[first]:.4g} Hz" in shape, shape


def test_duplicate_bearing_names_are_refused():
    """Two bearings of one name made bearing_coefficients take both bearings' pad coordinates
    for each (it looks them up by name): kxx 4.4950e7 for 4.4919e7 and cxy 7.6e-12 for
    243.6 N·s/m on this pump before its bearings were named apart; now an InputError."""
    import pytest

    text = PUMP.read_text().replace('name = "DE"', 'name = "NDE"')
    with pytest.raises(rd.InputError, match=r"bearing\[1\]\.name"):
        rd.System.from_toml(text, is_text=True)


TURBINE = Path(__file__).parent / "data" / "models" / "turbine_two_axial_groove.toml"


def test_overdamped_crossings_are_not_critical_speeds():
    """A steam-turbine rotor (4.3 t) on turbulent two-axial-groove bearings: at 3–5 Hz its
    heavy bearing modes cross 1× with δ ≈ 10–12 (damping ratio ≈ 0.85, no resonance); the
    report listed them as its first three critical speeds. They are named below the table
    instead; the 25 Hz crossing (δ ≈ 1.8, a resonance) stays a critical speed."""
    from rotordyn.report.criteria import RESONANT_LOG_DEC
    from rotordyn.report.sections import _crossings, critical_speed_table, not_resonance_note

    s = rd.System.from_toml(TURBINE)
    c = rd.campbell(s, np.concatenate([np.linspace(1.0, 8.0, 8), np.linspace(20.0, 30.0, 5)]))
    cross, ld = _crossings(c)
    flat = cross[ld >= RESONANT_LOG_DEC]
    keep = cross[ld < RESONANT_LOG_DEC]
    assert flat.size >= 1 and keep.size >= 1  # the premise, read off the Campbell diagram
    assert np.all(flat < 6.0) and np.any((keep > 20.0) & (keep < 30.0))
    table = critical_speed_table(c)
    np.testing.assert_allclose(np.sort(table["speed_hz"].to_numpy()), np.sort(keep))
    listed = table.attrs["overdamped_crossings"]
    np.testing.assert_allclose(sorted(f for f, _ in listed), np.sort(flat))
    note = not_resonance_note(table)
    assert "1× crossings not counted" in note
    assert all(f"{f:.4g} Hz" in note for f in flat)
    # the Campbell result's own table flags them, and its figure draws them apart
    cs = c.critical_speeds()
    np.testing.assert_allclose(np.sort(cs.loc[~cs["resonant"], "speed_hz"]), np.sort(flat))
    assert f"{keep[0]:.4g}" in repr(c) and f"{flat[0]:.4g}" not in repr(c)
