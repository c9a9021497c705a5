"""A rotor without a static load: gravity 0 (a vertical machine), no offsets.

The 4.3 t turbine rotor of tests/data/models on two two-axial-groove bearings with 1 bar
supply pressure: the centred journal is the equilibrium by the bore's two-fold symmetry, and
the films' net force there is round-off (2e-13 N). The residual was scaled by the load alone
(floored at 1e-12 N), so Newton's line search failed at a relative residual of 0.23 and every
analysis of the model (equilibrium, stability, threshold) had no equilibrium. The scale is now
floored at 1e-3 of the largest film's Sommerfeld load μΩRL(R/C)² for every film (it was for
tilting pads only). Unloaded journal bearings are unstable above a low speed (oil whirl at
about half the speed): checked at 20 Hz.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.model.paths import set_field

TURBINE = Path(__file__).parent / "data" / "models" / "turbine_two_axial_groove.toml"


def _unloaded():
    s = rd.System.from_toml(TURBINE)
    return set_field(s, "gravity_m_s2", 0.0)


def test_unloaded_rotor_sits_at_the_centre():
    s = _unloaded()
    eq = rd.equilibrium(s, 50.0)
    assert eq.status == "ok", eq.message
    c = 3.0e-4
    assert np.abs(eq.r).max() < 1e-9 * c
    st = rd.stability(s, 20.0)
    assert st.status == "ok" and not st.stable
    j = int(np.argmax(st.eigenvalues.real))
    assert 0.3 < st.frequencies_hz[j] / 20.0 < 0.55  # sub-synchronous whirl


def test_failed_point_prints_no_empty_table(capsys):
    # at 0.05 Hz the turbine's films cannot carry its weight: no equilibrium, a status line
    code = main(["stability", str(TURBINE), "--speed-hz", "0.05"])
    out = capsys.readouterr()
    assert code == 1 and "no_equilibrium" in out.err
    assert "Empty DataFrame" not in out.out + out.err and out.out.strip() == ""
