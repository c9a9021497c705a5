"""Rigid-body roots of a rotor without supports (`modes --without-bearings`).

A free-free rotor has four rigid-body motions (two translations, two tilts), so K is singular
and the pencil λ²M + λΩG + K has defective zero roots. The dense eigensolver spreads them to
|λ| ~ √ε ω_max; on the overhung pump (a 25 kg impeller beyond the drive-end bearing, so its
heaviest DOF is far from its stiffest) that spread (1.5e-3 rad/s) exceeded the old threshold
(1.4e-3) and two of them came out as a "mode" at 0.00015 Hz with damping ratio −0.75, an
unstable verdict on a free rotor. Reference: the generalized symmetric eigenproblem
K φ = ω² M φ (scipy `eigh`), whose zero eigenvalues are separated from the first bending one
by ~12 orders of magnitude here.
"""

from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as sl

import rotordyn as rd

PUMP = Path(__file__).parent / "data" / "models" / "pump_overhung.toml"


def _undamped_hz(system):
    M, K = system.M().toarray(), system.K().toarray()
    w2 = sl.eigh(K, M, eigvals_only=True)
    return np.sqrt(np.clip(w2, 0.0, None)) / (2 * np.pi), w2


def test_free_free_pump_at_rest_has_no_rigid_body_mode():
    s = rd.System.from_toml(PUMP)
    f_ref, w2 = _undamped_hz(s)
    assert np.sum(np.abs(w2) < 1e-3) == 4 and w2[4] > 1e6  # four rigid-body motions
    flex = f_ref[4:]
    m = rd.modes(s, without_bearings=True, n_modes=6).to_frame()
    assert len(m) == 6
    assert (m["freq_hz"] > 1.0).all(), m[["freq_hz", "damping_ratio"]]
    assert np.isfinite(m["damping_ratio"]).all() and (m["damping_ratio"].abs() < 1e-9).all()
    # the first three bending pairs (x and y planes), to 1e-9 relative
    np.testing.assert_allclose(m["freq_hz"].to_numpy(), flex[:6], rtol=1e-9)


def test_free_free_pump_at_speed_keeps_the_nutation_and_drops_the_zero_roots():
    """At 1 Hz the gyroscopic coupling turns one conical rigid-body pair into a forward
    nutation at Ω·I_p/I_d of the whole rotor — a regular root, kept; the six zero roots
    (two translations in Jordan pairs, the conical pair's zero) are dropped."""
    s = rd.System.from_toml(PUMP)
    m1 = rd.modes(s, without_bearings=True, n_modes=3, speed_hz=1.0).to_frame()
    m2 = rd.modes(s, without_bearings=True, n_modes=3, speed_hz=2.0).to_frame()
    nut1, nut2 = m1["freq_hz"].iloc[0], m2["freq_hz"].iloc[0]
    assert m1["whirl"].iloc[0] == "forward"
    assert 0.05 < nut1 < 0.5
    np.testing.assert_allclose(nut2 / nut1, 2.0, rtol=1e-4)  # ∝ speed (measured 3.6e-6 off)
    assert (m1["freq_hz"].iloc[1:] > 100.0).all()


def test_soft_supports_low_modes_are_kept():
    """K regular (soft linear supports, 200 N/m): the rigid-body-like modes at ~0.3 Hz are
    physical and stay, equal to the undamped eigenvalues."""
    text = PUMP.read_text()
    for st in (1, 2):
        text += (f'\n[[support]]\nstation = {st}\ntype = "linear"\nname = "soft {st}"\n'
                 'kxx_n_per_m = 200.0\nkyy_n_per_m = 200.0\n')
    s = rd.System.from_toml(text, is_text=True)
    f_ref, w2 = _undamped_hz(s)
    assert w2[0] > 0 and f_ref[3] < 1.0  # four low support modes, K regular
    m = rd.modes(s, without_bearings=True, n_modes=6).to_frame()
    np.testing.assert_allclose(m["freq_hz"].to_numpy()[:4], f_ref[:4], rtol=1e-6)
