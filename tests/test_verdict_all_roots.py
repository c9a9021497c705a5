"""A stability verdict covers every root of the linearised system.

Two holes found in an engineer's pass on a three-bearing motor-fan train (84 DOF, not the
paper rig):
* with ``n_modes`` (API and sweeps) the verdict and max Re λ covered only the kept modes:
  ``stability(train, 25 Hz, n_modes=12)`` said "least damped ... Re λ = -22.7 1/s" where
  the point's max Re λ is -0.582 1/s (a 1254 Hz bending mode above the cut);
* a growing real root (a divergence: static instability, e.g. the negative stiffness of an
  electric machine's unbalanced magnetic pull) was dropped as "overdamped" by the root
  picker, so such a rotor was reported stable.
"""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.sweep import run_sweep
import rotordyn.sweep as sw

MODELS = Path(__file__).parent / "data" / "models"
TRAIN = MODELS / "motor_fan_train.toml"


def test_a_growing_real_root_is_kept():
    """M = I, D = 0.01 I, K = diag(-1, 4): λ² + 0.01 λ - 1 = 0 has the root
    (-0.01 + √(0.0001 + 4))/2 = 0.99501..., kept beside the oscillating pair."""
    r = _core.modal(np.eye(2), 0.01 * np.eye(2), np.diag([-1.0, 4.0]), [(0, 1)], 0, True, [])
    lam = np.asarray(r.eigenvalues)
    assert lam[0] == pytest.approx((-0.01 + np.sqrt(1e-4 + 4.0)) / 2, rel=1e-12)
    assert lam[1] == pytest.approx(-0.005 + 1j * np.sqrt(4 - 0.005**2), rel=1e-12)
    # decaying real roots are still left out (overdamped: no natural frequency)
    r = _core.modal(np.eye(2), 3.0 * np.eye(2), np.diag([1.0, 4.0]),
                    [(0, 1)], 0, True, [])
    assert np.asarray(r.eigenvalues) == pytest.approx([-1.5 + 1j * np.sqrt(4 - 2.25)], rel=1e-12)


def _rotor(k_n_per_m=1e6, c_n_s_per_m=100.0, pull_n_per_m=None):
    """A disk on a 1.5 m shaft on two linear supports (k, c); ``pull_n_per_m``: the rotor
    core's unbalanced magnetic pull at the disk, a negative stiffness."""
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.25, outer_diameter_m=0.05) for _ in range(6))
    disks = (rd.Disk.from_geometry(3, steel, width_m=0.07, outer_diameter_m=0.28,
                                   inner_diameter_m=0.05),)
    damp = {"cxx_n_s_per_m": c_n_s_per_m, "cyy_n_s_per_m": c_n_s_per_m} if c_n_s_per_m else {}
    sup = tuple(rd.Support(s, "linear", kxx_n_per_m=k_n_per_m, kyy_n_per_m=k_n_per_m, **damp)
                for s in (0, 6))
    if pull_n_per_m is not None:
        sup += (rd.Support(3, "linear", kxx_n_per_m=pull_n_per_m, kyy_n_per_m=pull_n_per_m),)
    return rd.System(rotor=rd.Rotor(shaft, disks), materials=(steel,), supports=sup)


def _magnetic_pull_rotor():
    return _rotor(pull_n_per_m=-3e6)  # larger than the shaft's stiffness


@pytest.mark.parametrize("n_modes", [None, 4])
def test_a_divergence_is_unstable(n_modes):
    s = _magnetic_pull_rotor()
    st = rd.stability(s, 0.0, n_modes=n_modes)
    lm = rd.linearize(s, 0.0)
    A = np.asarray(lm.state_matrix() if callable(lm.state_matrix) else lm.state_matrix)
    want = np.linalg.eigvals(A).real.max()  # numpy's dense eigenvalues, the closed reference
    assert want > 100.0
    assert not st.stable
    assert st.max_real_1_per_s == pytest.approx(want, rel=1e-9)
    assert st.log_dec[int(np.argmax(st.eigenvalues.real))] == -np.inf  # grows, never "inf"


def test_n_modes_cut_keeps_the_verdict_over_every_root(tmp_path):
    s = rd.System.from_toml(TRAIN)
    full = rd.stability(s, 25.0)
    cut = rd.stability(s, 25.0, n_modes=12)
    assert len(cut.eigenvalues) == 12 and len(full.eigenvalues) > 12
    # the least damped mode lies above the cut (the test can fail)
    assert full.max_real_1_per_s > cut.eigenvalues.real.max() + 10.0
    assert cut.max_real_1_per_s == pytest.approx(full.max_real_1_per_s, rel=1e-9)
    assert cut.stable == full.stable
    # the sweep's rows (the C++ batch) carry the same point verdict and max Re λ
    spec = tmp_path / "s.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "cut"\nmodel = "{TRAIN}"\n'
                    'analysis = "stability"\n[grid]\nspeed_hz = 25.0\n[options]\nn_modes = 3\n')
    run_sweep(spec, tmp_path / "o", threads=1)
    df = sw.open(tmp_path / "o").frame
    assert len(df) == 3
    assert df.max_real_1_per_s.iloc[0] == pytest.approx(full.max_real_1_per_s, rel=1e-9)
    assert bool(df.point_stable.iloc[0]) == full.stable


def test_an_undamped_rotor_keeps_its_verdict_with_n_modes():
    """A conservative gyroscopic rotor (linear springs, no damping): its roots are refined from
    their vectors to exactly imaginary; the verdict's eigenvalues-only solve past an n_modes
    cut skipped that and dgeev's rounding (+3.5e-8 1/s) made the point unstable with
    n_modes = 4 and stable without (found by the review of this change)."""
    s = _rotor(k_n_per_m=1e4, c_n_s_per_m=0.0)
    full, cut = rd.stability(s, 1.0), rd.stability(s, 1.0, n_modes=4)
    assert full.stable and cut.stable
    assert full.max_real_1_per_s == 0.0 and cut.max_real_1_per_s == 0.0
