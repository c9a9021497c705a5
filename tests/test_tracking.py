"""Mode tracking by eigenvector continuity (MAC, Allemang & Brown 1982).

Guards: (1) through a *crossing* of two uncoupled modes the tracked ids follow the shapes (the
frequency-sorted slots swap); (2) through a *veering* (weak coupling) the ids follow the
continuous branches, whose frequencies stay apart while the shapes exchange; (3) on a real
rotor (Friswell et al. 2010, Example 5.9.1, gyroscopic) every tracked mode keeps one whirl
direction over 1-1500 Hz, while frequency-sorted slots change whirl at the crossings; (4) a mode
leaving a truncated set is not joined to the one entering it.
"""

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.tracking import mac, track_modes
from rotordyn.errors import InputError


def _two_dof(s, coupling):
    """Undamped 2-DOF, M = I, K = [[1, κ], [κ, s]]: eigenvalues ±i√λ sorted by frequency."""
    K = np.array([[1.0, coupling], [coupling, s]])
    w2, vec = np.linalg.eigh(K)
    return 1j * np.sqrt(w2), vec.astype(complex)


def _line(coupling, s_values):
    lam, shp = zip(*(_two_dof(s, coupling) for s in s_values))
    return np.array(lam), np.array(shp)


def test_mac_is_scale_invariant_and_bounded():
    rng = np.random.default_rng(0)
    a = rng.standard_normal((5, 3)) + 1j * rng.standard_normal((5, 3))
    m = mac(a, a * (2 - 3j))
    np.testing.assert_allclose(np.diag(m), 1.0, atol=1e-14)
    assert np.all((m >= 0) & (m <= 1))
    # forward and backward circular whirl of one planar shape are MAC-orthogonal
    assert mac(np.array([[1], [1j]]), np.array([[1], [-1j]]))[0, 0] == pytest.approx(0, abs=1e-15)


def test_crossing_follows_the_shapes():
    s = np.linspace(0.5, 1.5, 21)  # k22 passes k11 = 1: the frequencies cross at s = 1
    lam, shp = _line(0.0, s)
    ids = track_modes(lam, shp)
    f = np.where(ids == 0, lam.imag, 0).sum(1)  # frequency of tracked mode 0
    # mode 0 starts as the softer DOF 2 (s < 1); it must stay DOF 2 after the crossing
    np.testing.assert_allclose(f, np.sqrt(s), rtol=1e-12)
    assert np.any(ids[:, 0] != ids[0, 0])  # the sorted slots did swap


def test_veering_follows_the_branches():
    s = np.linspace(0.5, 1.5, 201)  # weak coupling: the curves veer (no crossing)
    lam, shp = _line(0.05, s)
    ids = track_modes(lam, shp)
    np.testing.assert_array_equal(ids, np.tile([0, 1], (s.size, 1)))
    # ... while the shapes exchange: the lower branch is DOF 2 before and DOF 1 after
    assert abs(shp[0, 1, 0]) > 0.99 and abs(shp[-1, 0, 0]) > 0.99


def test_gap_and_new_mode():
    lam = np.array([[1j, 2j], [np.nan, np.nan], [1.01j, 5j]])
    ids = track_modes(lam)
    assert ids[1].tolist() == [-1, -1]
    assert ids[2, 0] == 0 and ids[2, 1] == 2  # 5j is too far from 2j: a new id


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="eigenvalues"):
        track_modes(np.zeros(3))
    with pytest.raises(InputError, match="shapes"):
        track_modes(np.zeros((3, 2)), np.zeros((3, 4, 5)))


def test_friswell_campbell_tracked_modes_keep_their_whirl():
    rotor = rd.models.friswell_5_9_1()
    c = rd.campbell(rotor, np.linspace(1.0, 1500.0, 31), n_modes=6)
    wh = c.tracked(c.whirl.astype(float))
    for j in range(wh.shape[1]):
        w = wh[:, j][np.isfinite(wh[:, j])]
        assert np.all(w == w[0]), f"tracked mode {j} changes whirl: {w}"
    # the sorted slots do change whirl (modes cross), so the test above can fail
    assert any(len(set(c.whirl[:, j])) > 1 for j in range(c.whirl.shape[1]))
    df = c.to_frame()
    assert "mode_id" in df and df["mode_id"].dtype == np.int64
    # the first forward critical speed (no crossing below it, so frequency-sorted slots are
    # right there) equals the one of the independent batched rotor Campbell (C++ campbell)
    ref = rd.rotor_campbell(rotor, np.linspace(1.0, 1500.0, 31), n_modes=6, reduction="none")
    cs = c.critical_speeds()
    assert cs.speed_hz.iloc[0] == pytest.approx(ref.critical_speeds().speed_hz.iloc[0], rel=1e-6)
