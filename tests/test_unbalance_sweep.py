"""Unbalance response of systems with bearing elements in one C++ call (issue 22).

References and tolerances:
- The per-speed path built from the public analyses: the equilibrium continued along the
  speeds (``rotordyn.linearize`` from the last converged equilibrium, as the unbalance
  response continues it), K_H, D_H there, and the dense complex solve (numpy/LAPACK) of
  (K − Ω²M + iΩD) q = Ω² F₁ seen at the output stations. Both sides solve the same polished
  equilibrium (Newton to round-off) and the same linear system, directly; away from an
  undamped resonance the solves agree to ~cond × 1e-16: 1e-10 relative to the largest
  response (the acceptance of issue 22).
- The largest real part of the eigenvalues against numpy's eigenvalues of the first-order
  form [[0, I], [−M⁻¹K, −M⁻¹D]] at the same matrices: 1e-8 relative to the spectral radius
  (two different dense eigensolvers).
- Splitting the speeds over two threads (each block continued from the same start) gives the
  same response to 1e-10: the polished equilibrium does not depend on its start.
Models: a compressor on plain journal bearings and on tilting pads (tests/data/models), and
the paper rig with its active bearing at p_c = 0.4 MPa.
"""

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.units import hz_to_rad_s

MODELS = "tests/data/models"


def per_speed(system, ub, speeds, stations, pc):
    """Response (n_s, n_out) x, y, statuses and max real parts speed by speed."""
    asm = assembled(system)
    F1 = asm.unbalance_load(ub)
    X = np.full((len(speeds), len(stations)), np.nan + 0j)
    Y = X.copy()
    mr = np.full(len(speeds), np.nan)
    rho = np.full(len(speeds), np.nan)
    status, r0 = [], None
    for i, s in enumerate(speeds):
        lm = rd.linearize(system, float(s), pc, r0=r0, warm_start=r0 is None)
        status.append(lm.equilibrium.status)
        if lm.equilibrium.status not in ("ok", "contact"):
            continue
        r0 = lm.equilibrium.r
        w = hz_to_rad_s(float(s))
        q = np.linalg.solve(lm.K - w**2 * lm.M + 1j * w * lm.D, w**2 * F1)
        for k, st in enumerate(stations):
            X[i, k], Y[i, k] = asm.station_output_matrix(st) @ q
        n = lm.M.shape[0]
        Minv = np.linalg.inv(lm.M)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ lm.K, -Minv @ lm.D]])
        lam = np.linalg.eigvals(A)
        mr[i], rho[i] = lam.real.max(), np.abs(lam).max()
    return X, Y, status, mr, rho


CASES = {
    "compressor_plain": (lambda: rd.System.from_toml(f"{MODELS}/compressor_plain.toml"),
                         [(3, 1e-4, 0.0), (2, 5e-5, 90.0)], np.linspace(20.0, 200.0, 19),
                         [2, 3, 4], 0.0),
    "compressor_tilting_pad": (lambda: rd.System.from_toml(
        f"{MODELS}/compressor_tilting_pad.toml"), [(3, 1e-4, 0.0)],
        np.linspace(30.0, 180.0, 6), [1, 3], 0.0),
    "rig": (rd.models.paper_rig, [(4, 1e-4, 0.0)], np.arange(10.0, 121.0, 10.0), [4, 6], 4e5),
}


@pytest.mark.parametrize("name", list(CASES))
def test_one_call_equals_the_per_speed_path(name):
    make, ub, sp, st, pc = CASES[name]
    X, Y, status, mr, rho = per_speed(make(), ub, sp, st, pc)
    assert all(s == "ok" for s in status), status
    u = rd.unbalance_response(make(), ub, sp, stations=st, chamber_pressure_pa=pc,
                              refine=False)
    assert list(u.point_status) == status
    scale = max(np.abs(X).max(), np.abs(Y).max())
    assert np.abs(u.x - X).max() <= 1e-10 * scale
    assert np.abs(u.y - Y).max() <= 1e-10 * scale
    assert u.max_real_1_per_s is not None
    assert np.all(np.abs(u.max_real_1_per_s - mr) <= 1e-8 * rho)


@pytest.mark.parametrize("name", ["compressor_plain", "rig"])
def test_two_threads_equal_one(name):
    make, ub, sp, st, pc = CASES[name]
    one = rd.unbalance_response(make(), ub, sp, stations=st, chamber_pressure_pa=pc,
                                refine=False)
    two = rd.unbalance_response(make(), ub, sp, stations=st, chamber_pressure_pa=pc,
                                refine=False, threads=2)
    scale = np.abs(one.x).max()
    assert list(two.point_status) == list(one.point_status)
    assert np.abs(two.x - one.x).max() <= 1e-10 * scale
    assert np.abs(two.y - one.y).max() <= 1e-10 * scale


def test_threads_is_validated():
    s = rd.System.from_toml(f"{MODELS}/compressor_plain.toml")
    with pytest.raises(rd.InputError, match="threads"):
        rd.unbalance_response(s, [(3, 1e-4, 0.0)], [50.0], threads=0)
    with pytest.raises(rd.InputError, match="method"):
        rd.unbalance_response(s, [(3, 1e-4, 0.0)], [50.0], method="secant")
