"""System equilibrium (paper eq. 14-16) on the paper's rig and on reduced cases with known
answers.

- Newton and the paper's successive substitution (eq. 16, P_m chosen automatically) reach the
  same equilibrium to 1e-9 c, the force-balance residual is below 1e-8 of the load (issue 4).
- A rigid rotor of weight W on one journal bearing reaches the standalone bearing's static
  equilibrium (same Reynolds solver; agreement to 1e-9 c is round-off of two Newton paths).
- An active bearing with a very stiff sleeve and p_c = 0 reproduces the plain bearing (1e-6).
- Equilibria are continuous in p_c, a_y and speed: each grid midpoint lies within 2 % of c of
  the chord between its neighbours (a jump or branch switch breaks this by far; the smooth
  loci bend by at most ~0.6 % of c over a 25 kPa step, where the sleeve lifts off).
"""

import dataclasses

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled

C = 3e-4


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_newton_and_successive_substitution_agree(rig):
    n = rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3, method="newton", warm_start=False)
    s = rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3, method="successive", warm_start=False)
    assert n.status == "ok" and s.status == "ok", (n.message, s.message)
    assert np.abs(n.r - s.r).max() < 1e-9 * C
    assert n.residual < 1e-8 and s.residual < 1e-8
    assert n.iterations < 20 < s.iterations  # reported side by side in docs/paper-rig.md
    assert s.pm > 0


def test_force_balance_residual_is_independent(rig):
    """Recompute K(r + a) − H − Q − p_c c_s from the returned state."""
    e = rd.equilibrium(rig, 50.0, 0.2e6, -1.85e-3)
    asm = assembled(rig)
    a = asm.config_vector(-1.85e-3)
    H = np.asarray(asm.solver.film_forces(e.r, np.zeros(asm.n), 2 * np.pi * 50.0))
    R = asm.model.K @ (e.r + a) - H - asm.model.Q - 0.2e6 * asm.model.chamber
    scale = max(np.abs(asm.model.K @ a).max(), np.abs(asm.model.Q).max())
    assert np.abs(R).max() < 1e-8 * scale


def _single_bearing_system(bearing):
    """Rigid short rotor of two stations: both ends tied together by a very stiff shaft, one
    film bearing at station 0, a rigid support at station 2 far away takes the rest."""
    rotor = rd.Rotor((rd.ShaftSection(0.05, 0.05), rd.ShaftSection(0.05, 0.05)),
                     disks=(rd.Disk(0, 5.0, 0.0, 0.0),))
    return rd.System(rotor=rotor, bearings=(bearing,), supports=(rd.Support(2),),
                     reduction=rd.Reduction(master_stations=(0, 1)))


def test_single_journal_bearing_matches_standalone_equilibrium():
    b = rd.FluidFilmBearing(0, 0.05, 0.04, C, 0.04, n_circ=72, n_axial=16)
    s = _single_bearing_system(b)
    asm = assembled(s)
    e = rd.equilibrium(s, 50.0)
    assert e.status == "ok"
    F = e.film_force_n[[asm.bearings[0].jx, asm.bearings[0].jy]]
    ref = b.journal_bearing().static_equilibrium(load_n=(-F[0], -F[1]), speed_hz=50.0)
    assert abs(ref.x_m - e.journal_x_m[0]) < 1e-9 * C
    assert abs(ref.y_m - e.journal_y_m[0]) < 1e-9 * C
    assert F[1] > 0  # the film carries part of the weight: it pushes the journal up


def test_stiff_sleeve_reproduces_plain_bearing(rig):
    """Sleeve 10⁶ times stiffer (the difference falls as 1/E: 1.75e-3 at 10², 1.75e-7 here), p_c = 0: forces and the journal's effective K, C as the plain
    bearing's to 1e-6 relative."""
    ab = rig.bearings[0]
    stiff = dataclasses.replace(ab, sleeve=dataclasses.replace(ab.sleeve, young_pa=1e17))
    plain = rd.FluidFilmBearing(ab.station, ab.diameter_m, ab.length_m, ab.clearance_m,
                                ab.viscosity_pa_s, cavitation=ab.cavitation, n_circ=ab.n_circ,
                                n_axial=ab.n_axial, grooves=ab.grooves)
    sa = dataclasses.replace(rig, bearings=(stiff,))
    sp = dataclasses.replace(rig, bearings=(plain,))
    ea = rd.equilibrium(sa, 50.0, 0.0, -0.5e-3, warm_start=False)
    ep = rd.equilibrium(sp, 50.0, 0.0, -0.5e-3, warm_start=False)
    np.testing.assert_allclose([ea.journal_x_m[0], ea.journal_y_m[0]],
                               [ep.journal_x_m[0], ep.journal_y_m[0]], rtol=1e-6, atol=1e-12)
    w = 2 * np.pi * 50.0
    la = assembled(sa).solver.linearize(ea.r, np.zeros(len(ea.r)), w)
    lp = assembled(sp).solver.linearize(ep.r, np.zeros(len(ep.r)), w)
    j = [2, 3]
    s = [6, 7, 8]
    Kss = np.asarray(la.KH)[np.ix_(s, s)] + np.asarray(assembled(sa).model.K)[np.ix_(s, s)]
    Keff = np.asarray(la.KH)[np.ix_(j, j)] - np.asarray(la.KH)[np.ix_(j, s)] @ np.linalg.solve(
        Kss, np.asarray(la.KH)[np.ix_(s, j)])
    Kp = np.asarray(lp.KH)[np.ix_(j, j)]
    np.testing.assert_allclose(Keff, Kp, rtol=1e-6, atol=1e-6 * np.abs(Kp).max())
    np.testing.assert_allclose(np.asarray(la.DH)[np.ix_(j, j)], np.asarray(lp.DH)[np.ix_(j, j)],
                               rtol=1e-6, atol=1e-6 * np.abs(np.asarray(lp.DH)).max())


def _smooth(values, mids):
    chord = 0.5 * (values[:-1] + values[1:])
    return np.abs(mids - chord).max() / C


@pytest.mark.parametrize("ay", [-1.0e-3, 0.5e-3, 2.5e-3])
def test_continuous_in_chamber_pressure(rig, ay):
    pcs = np.linspace(0, 0.25e6, 11)
    mid = 0.5 * (pcs[:-1] + pcs[1:])
    xy = np.array([[e.journal_x_m[0], e.journal_y_m[0]]
                   for e in (rd.equilibrium(rig, 50.0, p, ay) for p in pcs)])
    xm = np.array([[e.journal_x_m[0], e.journal_y_m[0]]
                   for e in (rd.equilibrium(rig, 50.0, p, ay) for p in mid)])
    assert _smooth(xy[:, 0], xm[:, 0]) < 0.02 and _smooth(xy[:, 1], xm[:, 1]) < 0.02


def test_continuous_in_speed(rig):
    f = np.array([10.0, 20.0, 30.0, 40.0, 50.0])
    mid = 0.5 * (f[:-1] + f[1:])
    pts = np.array([rd.equilibrium(rig, s, 0.1e6, 0.0).r[2:4] for s in f])
    mids = np.array([rd.equilibrium(rig, s, 0.1e6, 0.0).r[2:4] for s in mid])
    assert _smooth(pts[:, 0], mids[:, 0]) < 0.02 and _smooth(pts[:, 1], mids[:, 1]) < 0.02


def test_bad_input(rig):
    with pytest.raises(rd.InputError, match="chamber_pressure_pa"):
        rd.equilibrium(rig, 50.0, -1.0)
    with pytest.raises(rd.InputError, match="method"):
        rd.equilibrium(rig, 50.0, method="bisection")
    with pytest.raises(rd.InputError, match="arc_deg"):
        dataclasses.replace(rig.bearings[0].sleeve, arc_deg=400.0)
    with pytest.raises(rd.InputError, match="speed_hz"):
        rd.equilibrium(rig, float("nan"))


def test_forced_contact_is_a_status_not_a_crash(rig):
    """Housing 50 mm off the line: no equilibrium with an open film exists. The failed solve
    (residual ~0.4 of the load) is "no_equilibrium", never the converged status "contact"
    (issue 13)."""
    e = rd.equilibrium(rig, 5.0, 0.0, 0.05, warm_start=False)
    assert e.status == "no_equilibrium" and not e.converged
    assert "film" in e.message and "no equilibrium" in e.message
    assert e.residual > 1e-3
    assert e.to_frame()["status"].iloc[0] == "no_equilibrium"
