"""The two eigen-solvers agree: dense LAPACK (all modes) and shift-invert Arnoldi on the sparse
quadratic pencil (used for large models and few modes), against NumPy's eigvals of the
explicitly formed state matrix — on supported and free-free rotors, spinning, with damping.
Tolerance 1e-7 relative: both are backward stable; the Arnoldi residual is held to 1e-9."""

import numpy as np
import pytest

import rotordyn as rd
import rotordyn._core as core


def reference(M, D, K, n):
    A = np.block([[np.zeros_like(M), np.eye(len(M))],
                  [-np.linalg.solve(M, K), -np.linalg.solve(M, D)]])
    w = np.linalg.eigvals(A)
    scale = np.sqrt(np.abs(np.diag(K)).max() / np.abs(np.diag(M)).max())
    w = w[(w.imag > 0) & (np.abs(w) > 1e-7 * scale)]
    return w[np.argsort(w.imag)][:n]


@pytest.mark.parametrize("supported", [True, False])
@pytest.mark.parametrize("speed", [0.0, 300.0])
def test_sparse_path_matches_dense_reference(supported, speed):
    secs = tuple(rd.ShaftSection(0.015, 0.05) for _ in range(100))  # 404 DOF: sparse path
    sups = ((rd.Support(0, "linear", kxx_n_per_m=1e7, kyy_n_per_m=2e7, cxx_n_s_per_m=200.0,
                        cyy_n_s_per_m=400.0),
             rd.Support(100, "linear", kxx_n_per_m=1e7, kyy_n_per_m=1e7, kxy_n_per_m=2e6))
            if supported else ())
    s = rd.System(rotor=rd.Rotor(secs), supports=sups, reduction=rd.Reduction(method="none"))
    c = core.constrain(s.to_core())
    D = c.C + speed * c.G
    r = core.modal(c.M, D, c.K, list(c.xy), 10, True)
    ref = reference(c.M, D, c.K, 10)
    lam = np.asarray(r.eigenvalues)
    # The free-free spinning rotor's nutation root (≈ Ω Ip/Id ≈ 0.5 rad/s) sits next to the
    # defective zero cluster of the rigid-body modes: ill-conditioned, so NumPy's reference is
    # itself only good to ~1e-5 there; the closed form of the rigid rotor checks it instead.
    elastic = ref.imag > 1.0
    np.testing.assert_allclose(lam[elastic], ref[elastic], rtol=1e-7, atol=1e-9)
    if not supported and speed > 0:
        L, d = 1.5, 0.05
        ip, id_ = d**2 / 8, L**2 / 12 + d**2 / 16  # per unit mass
        np.testing.assert_allclose(lam[0].imag, speed * ip / id_, rtol=1e-4)
    # eigenvectors: normwise backward error of the quadratic eigenproblem (Tisseur 2000)
    nM, nD, nK = (np.linalg.norm(X, 2) for X in (c.M, D, c.K))
    for j, lam in enumerate(np.asarray(r.eigenvalues)):
        x = np.asarray(r.modes)[:, j]
        res = (lam**2 * c.M + lam * D + c.K) @ x
        eta = np.linalg.norm(res) / ((abs(lam) ** 2 * nM + abs(lam) * nD + nK) * np.linalg.norm(x))
        # The Arnoldi stopping test is 1e-9 on the shift-inverted Ritz residual; the backward
        # error of the original pencil is a few times larger for the nutation root.
        assert eta < 1e-8, eta


def test_campbell_batch_equals_pointwise_modes():
    s = rd.models.friswell_5_9_1()
    speeds = np.linspace(0, 100, 11)
    c = rd.rotor_campbell(s, speeds, reduction="none", n_modes=6)
    for i in (0, 5, 10):
        m = rd.modes(s, speeds[i], reduction="none", n_modes=6)
        np.testing.assert_allclose(c.eigenvalues[i], m.eigenvalues, rtol=1e-10)
    df = c.to_frame()
    assert len(df) == 66 and df["speed_hz"].is_monotonic_increasing


def test_campbell_critical_speed_of_friswell_rotor_matches_crossing():
    """The first forward critical speed from the 1× crossing, checked by evaluating the forward
    mode exactly at the interpolated speed (within the interpolation error ~ 0.05 %)."""
    s = rd.models.friswell_5_9_1()
    c = rd.rotor_campbell(s, np.linspace(1, 100, 100), reduction="none", n_modes=6)
    cs = c.critical_speeds()
    first = cs.iloc[0]
    m = rd.modes(s, first.speed_hz, reduction="none", n_modes=6)
    fw = m.frequencies_hz[m.whirl == "forward"]
    assert np.min(np.abs(fw - first.speed_hz)) / first.speed_hz < 5e-4


def test_campbell_rejects_decreasing_speeds():
    with pytest.raises(rd.InputError, match="speeds_hz"):
        rd.rotor_campbell(rd.models.friswell_5_9_1(), [10.0, 5.0])


@pytest.fixture(scope="module")
def large_rotor():
    """The 244-DOF rotor of the test below, its twelve speeds and the dense LAPACK solver's
    eigenvalues (``n_modes`` <= 0 selects it: all of them, whatever the sparse request) at
    three of them: computed once for the module, as they do not depend on ``n_modes``."""
    secs = tuple(rd.ShaftSection(0.025, 0.05) for _ in range(60))
    sups = (rd.Support(0, "linear", kxx_n_per_m=1e7, kyy_n_per_m=2e7, cxx_n_s_per_m=200.0,
                       cyy_n_s_per_m=400.0),
            rd.Support(60, "linear", kxx_n_per_m=1e7, kyy_n_per_m=1e7))
    s = rd.System(rotor=rd.Rotor(secs), supports=sups, reduction=rd.Reduction(method="none"))
    c = core.constrain(s.to_core())
    speeds_hz = np.linspace(0.0, 300.0, 12)
    dense = {}
    for i in (0, 6, 11):
        w = 2 * np.pi * speeds_hz[i]
        dense[i] = np.asarray(core.modal(c.M, c.C + w * c.G, c.K, list(c.xy), 0,
                                         False).eigenvalues)
    return s, c, speeds_hz, dense


@pytest.mark.parametrize("n_modes", [2, 6, 8, 12])
def test_sparse_campbell_matches_dense_on_a_large_rotor(large_rotor, n_modes):
    """rotor_campbell on a 244-DOF rotor (sparse shift-invert Arnoldi, each speed started from
    the previous speed's Ritz vectors, the Krylov basis extended when its test fails) against
    the dense LAPACK solver at three of the twelve speeds (fixture ``large_rotor``), for
    several requests (6 modes used to fail its first basis and restart from scratch). 1e-7
    relative, as above: both backward stable, the Arnoldi residual held to 1e-9."""
    s, c, speeds_hz, dense = large_rotor
    assert len(c.M) > 200
    camp = rd.rotor_campbell(s, speeds_hz, reduction="none", n_modes=n_modes)
    for i in (0, 6, 11):
        np.testing.assert_allclose(camp.eigenvalues[i], dense[i][:n_modes], rtol=1e-7,
                                   atol=1e-9)
