"""The example rotor of Friswell, Penny, Garvey & Lees, Dynamics of Rotating Machines
(Cambridge University Press, 2010), Example 5.9.1: a uniform 1.5 m steel shaft (Ø50 mm,
E = 211 GPa, G = 81.2 GPa, ρ = 7810 kg/m³) in six Timoshenko elements, rigid disks at nodes 2
(OD 0.28 m) and 4 (OD 0.35 m), 70 mm wide, isotropic 1 MN/m bearings at the ends.

Published natural frequencies (rad/s) at 0 and 4000 rev/min, including the forward/backward
split, as printed to three decimals; tolerance 1.5e-3 rad/s (half a unit of the last printed
digit plus rounding of the disk inertias from geometry).
"""

import numpy as np
import pytest

import rotordyn as rd

AT_0_RPM = [86.658, 86.658, 274.313, 274.313, 716.786, 716.786]
AT_4000_RPM = [85.389, 87.796, 251.785, 294.713, 600.179, 827.075]
WHIRL_4000 = ["backward", "forward", "backward", "forward", "backward", "forward"]


@pytest.fixture(scope="module")
def rotor():
    return rd.models.friswell_5_9_1()


def test_natural_frequencies_at_rest(rotor):
    r = rd.modes(rotor, 0.0, reduction="none", n_modes=6)
    np.testing.assert_allclose(r.eigenvalues.imag, AT_0_RPM, rtol=0, atol=1.5e-3)
    np.testing.assert_allclose(r.damping_ratio, 0.0, atol=1e-9)


def test_forward_backward_split_at_4000_rpm(rotor):
    r = rd.modes(rotor, 4000 / 60, reduction="none", n_modes=6)
    np.testing.assert_allclose(r.eigenvalues.imag, AT_4000_RPM, rtol=0, atol=1.5e-3)
    assert list(r.whirl) == WHIRL_4000


def test_frame_columns_are_tidy(rotor):
    df = rd.modes(rotor, 4000 / 60, reduction="none", n_modes=6).to_frame()
    assert list(df.columns[:4]) == ["model", "speed_hz", "mode", "freq_hz"]
    assert {"eig_real_1_per_s", "damping_ratio", "log_dec", "whirl", "status", "message"} <= set(df)
    np.testing.assert_allclose(df["freq_hz"] * 2 * np.pi, AT_4000_RPM, atol=1.5e-3)
