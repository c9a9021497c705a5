"""Periodic orbits by harmonic balance with alternating frequency–time
(``rd.periodic_orbit(..., method="harmonic_balance")``, cpp/src/harmonic_balance.cpp) against
the shooting of the same system (docs/nonlinear.md "Harmonic balance").

References: the shooting (CVODES, tests/test_periodic.py) — an independent method on the
same C++ right-hand side — at tight tolerances; on a smooth (uncavitated) film the Fourier
coefficients decay geometrically, so a dozen harmonics reach the shooting's own accuracy.
"""

from __future__ import annotations


import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.periodic import periodic_orbit
from rotordyn.errors import InputError
import coarse_models  # noqa: E402

HB = "harmonic_balance"


def smooth_rotor_system():
    """A short rotor on two plain journal bearings with a full (uncavitated) film: the
    system of tests/test_periodic.py::test_nonlinear_forced_orbit_equals_harmonic_balance
    (15 Hz, 8e-3 kg·m: orbit 0.15 c, second harmonic 5 % of the first)."""
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9,
                        shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.1, outer_diameter_m=0.1) for _ in range(4))
    films = tuple(rd.FluidFilmBearing(s, diameter_m=0.05, length_m=0.025, clearance_m=1e-4,
                                      viscosity_pa_s=0.03, n_circ=36, n_axial=6,
                                      cavitation="none") for s in (0, 4))
    return rd.System(rotor=rd.Rotor(shaft, ()), materials=(steel,), bearings=films,
                     reduction=rd.Reduction(master_stations=(0, 4), method="guyan"))


@pytest.fixture(scope="module")
def smooth_rotor():
    return smooth_rotor_system()


def test_forced_orbit_on_a_smooth_film_equals_shooting(smooth_rotor):
    """The unbalance-forced orbit (unstable: |μ_c| = 1.025, so no transient reaches it) by
    harmonic balance from the static equilibrium against shooting at rtol 1e-10: every
    sample of every coordinate within 1e-6 of the orbit amplitude for H = 12 (M = 48;
    measured below), and the error falls with H (H = 4 is worse by orders: the test can
    fail); the multipliers from the HB samples (the former interpolated Magnus product,
    floquet_tol=0) equal the shooting's to 1e-4, and the refined default's |μ_c| within its
    error estimate (its other multipliers are not in the estimate: 8.0e-4 measured)."""
    f, ub = 15.0, [(2, 8e-3, 0.0)]
    sh = periodic_orbit(smooth_rotor, f, kind="forced", unbalances=ub, rtol=1e-10,
                        atol_m=1e-15, tol=1e-9, n_out=97)
    assert sh.ok, sh.message
    amp = np.abs(sh.r - sh.r.mean(0)).max()
    errs = {}
    for h in (4, 12):
        hb = periodic_orbit(smooth_rotor, f, kind="forced", unbalances=ub, method=HB,
                            harmonics=h, tol=1e-12, n_out=97)
        assert hb.ok, hb.message
        assert hb.period_s == pytest.approx(1 / f, rel=1e-14)
        errs[h] = np.abs(hb.r - sh.r).max() / amp
    assert errs[12] < 1e-6, errs
    assert errs[4] > 10 * errs[12], errs
    old = periodic_orbit(smooth_rotor, f, kind="forced", unbalances=ub, method=HB,
                         harmonics=12, tol=1e-12, n_out=97, floquet_tol=0)
    mu_sh = np.sort_complex(sh.multipliers)
    assert np.abs(mu_sh - np.sort_complex(old.multipliers)).max() < 1e-4
    assert (abs(abs(hb.critical_multiplier) - abs(sh.critical_multiplier))
            <= hb.stats["floquet_error"])
    assert hb.stable == sh.stable == old.stable


@pytest.fixture(scope="module")
def coarse_rig_cycle():
    """The paper rig on a 36 × 6 active film and its stable cycle at a_y = −1.85 mm, 50 Hz,
    0.05 MPa by shooting at rtol 1e-8, tol 1e-7 from a 0.6 s transient (the reference)."""
    rig = coarse_models.paper_rig()
    tr = rd.transient(rig, 0.6, 50.0, 0.05e6, -1.85e-3, disturbance_m=(0.0, 3e-5), n_out=6001)
    cyc = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=tr, rtol=1e-8, tol=1e-7,
                            sensitivity_rtol=1e-4, n_out=401)
    assert cyc.ok, cyc.message
    return rig, tr, cyc


def _shape_error(o, ref):
    """Largest distance of the orbit's journal points from the reference curve (dense
    polyline), relative to the reference amplitude."""
    P = np.column_stack([o.journal_x_m[:, 0], o.journal_y_m[:, 0]])
    A = np.column_stack([ref.journal_x_m[:, 0], ref.journal_y_m[:, 0]])
    d = np.sqrt(((P[:, None, :] - A[None, :, :]) ** 2).sum(-1)).min(1)
    return d.max() / ref.amplitude()


def test_rig_cycle_from_the_equilibrium_equals_shooting(coarse_rig_cycle):
    """The rig's autonomous cycle by harmonic balance from the cheap start (the equilibrium
    plus its least-damped whirl mode at 0.3 c, no transient) against the shooting
    reference: H = 12 within 1e-3 in amplitude and period and 2e-3 in shape (relative; the
    cavitated film's spectrum decays algebraically, see docs/nonlinear.md); stability and
    the critical multiplier from the HB samples within 1e-2 of the shooting's; the trivial
    multiplier near 1."""
    rig, _, ref = coarse_rig_cycle
    hb = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, method=HB, harmonics=12, tol=1e-8,
                           n_out=401)
    assert hb.ok, hb.message
    a, ar = hb.amplitude(), ref.amplitude()
    assert abs(a - ar) / ar < 1e-3
    assert abs(hb.period_s - ref.period_s) / ref.period_s < 1e-3
    assert _shape_error(hb, ref) < 2e-3
    assert hb.stable and ref.stable
    assert abs(abs(hb.critical_multiplier) - abs(ref.critical_multiplier)) < 1e-2
    assert abs(hb.trivial_multiplier - 1) < 1e-2


def test_rig_cycle_from_a_transient_and_from_a_state(coarse_rig_cycle):
    """The same cycle from the 0.6 s transient (its last period resampled) and from a state
    with a period guess (one flow gives the samples): the same orbit as from the
    equilibrium start within 1e-4 in the period and 1e-3 of the amplitude (measured 2.4e-5
    in the period on this 36 × 6 film: the discrete cavitated film force is only piecewise
    smooth, so Newton stops on slightly different points from different starts; on the
    rig as built the three starts agree to the printed digits)."""
    rig, tr, ref = coarse_rig_cycle
    kw = dict(method=HB, harmonics=8, tol=1e-9, n_out=201)
    a = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, **{**kw, "n_out": 2001})
    b = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=tr, **kw)
    c = rd.periodic_orbit(rig, 50.0, 0.05e6, -1.85e-3, start=(ref.r[0], ref.v[0]),
                          period_s=ref.period_s * 1.01, **kw)
    for o in (a, b, c):
        assert o.ok, o.message
    amp = ref.amplitude()
    for o in (b, c):
        assert abs(o.period_s - a.period_s) < 1e-4 * a.period_s
        assert abs(o.amplitude() - a.amplitude()) < 1e-3 * amp
        assert _shape_error(o, a) < 2e-3  # against a's 2001-point curve (spacing 3e-3 A)


@pytest.mark.parametrize("kw, field", [
    (dict(harmonics=0), "harmonics"),
    (dict(harmonics=8, time_points=16), "time_points"),
    (dict(period_s=-1.0), "period_s"),
    (dict(period_s=0.0), "period_s"),
    (dict(floquet="magnus"), "floquet"),
    (dict(method="collocation"), "method"),
])
def test_bad_input_names_the_field(smooth_rotor, kw, field):
    """H < 1, M < 2H + 1, a period ≤ 0, an unknown Floquet route or method: InputError
    naming the field, before any solve."""
    args = dict(method=HB, start=(np.zeros(4), np.zeros(4)), period_s=0.01)
    args.update(kw)
    with pytest.raises(InputError, match=field):
        periodic_orbit(smooth_rotor, 15.0, **args)


def test_core_checks_harmonics_and_time_points(smooth_rotor):
    """The C++ entry checks H ≥ 1 and M ≥ 2H + 1 itself (InputError naming the field), and
    a start with fewer than 2H + 1 samples."""
    from rotordyn import _core
    from rotordyn.analysis.assembly import assembled

    asm = assembled(smooth_rotor)
    inp = _core.PeriodicInput()
    inp.kind = _core.OrbitKind.autonomous
    inp.omega = 2 * np.pi * 15
    inp.a = np.zeros(asm.n)
    inp.r0, inp.v0 = np.zeros(asm.n), np.zeros(asm.n)
    inp.period = 0.01
    for h, m, field in ((0, 0, "harmonics"), (4, 8, "time_points")):
        o = _core.HarmonicBalanceOptions()
        o.harmonics, o.time_points = h, m
        with pytest.raises(InputError, match=field):
            _core.harmonic_balance(asm.solver, inp, np.zeros((0, asm.n)), o)
    o = _core.HarmonicBalanceOptions()
    with pytest.raises(InputError, match="start_samples"):
        _core.harmonic_balance(asm.solver, inp, np.zeros((5, asm.n)), o)
    inp.period = -1.0
    with pytest.raises(InputError, match="period"):
        _core.harmonic_balance(asm.solver, inp, np.zeros((0, asm.n)), o)
