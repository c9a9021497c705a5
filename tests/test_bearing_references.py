"""New bearing elements against references (issue 12).

Sources
-------
* Plain bearing limit: a partial arc of 360° without preload is the plain bearing (same
  Reynolds core, same grid): forces and coefficients equal to round-off.
* J. W. Lund & K. K. Thomsen, "A calculation method and data for the dynamic coefficients of
  oil-lubricated journal bearings", ASME Topics in Fluid Film Bearing and Rotor Bearing System
  Design and Optimization (1978) 1–28: two axial grooves of 20° at the horizontal split, L/D = 1,
  Reynolds conditions (table frame x down, y horizontal; conversion and tolerances as in
  tests/test_reynolds_tables.py: 5 % + 0.02 on the dimensionless coefficients).
* Short squeeze-film damper, circular centred orbit, open ends (J. M. Vance, *Rotordynamics of
  Turbomachinery*, Wiley 1988, ch. 6; L. San Andrés, *Squeeze Film Dampers*, Texas A&M
  lecture notes): π film F_r = −2μRL³νε²/(c²(1−ε²)²), F_t = −πμRL³νε/(2c²(1−ε²)^{3/2});
  full film F_r = 0, F_t twice the π film's. Within 1 % at L/D = 1/40 (n_axial = 32: the
  trapezoidal rule on the parabolic axial profile errs by 1/n_axial² = 0.1 %), and the
  finite-length error falls as L/D → 0.
* J. W. Lund, "Spring and damping coefficients for the tilting-pad journal bearing", ASLE
  Trans. 7 (1964) 342–352: pad assembly. Each pad's 2×2 impedance Z_k = K_k + iνC_k (from the
  fixed pad at the journal's position relative to the tilted pad) is condensed over its tilt,
  Z_red = Σ_k [Z_k − ℓ² Z_k t_k t_kᵀ Z_k / (k_t − ν² I_p + ℓ² t_kᵀ Z_k t_k)], t_k the unit
  tangent at the pivot, ℓ the pivot lever; compared with the system reduction (pad tilts as
  coordinates, condensed at ν) to 1e-6 (both from the same film solver; the check is of the
  kinematics and the condensation). Tilted-pad equilibrium: each pad's moment vanishes.
* Someya's journal-bearing databook (1989) tables (tilting pad and two-lobe) and Lund &
  Thomsen's elliptical-bearing rows are NOT tested: the tables were not available to us.
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import (FixedGeometryBearing, SqueezeFilmDamper, TiltingPadBearing,
                               short_damper_orbit_forces)
from rotordyn.errors import InputError

D, C_RAD, MU, N_HZ = 0.05, 1e-4, 0.02, 20.0
R = D / 2


def test_partial_arc_360_is_the_plain_bearing():
    kw = dict(diameter_m=D, length_m=0.8 * D, clearance_m=C_RAD, viscosity_pa_s=MU, n_circ=72,
              n_axial=12)
    arc = FixedGeometryBearing(station=0, kind="partial_arc", arc_deg=360.0, **kw)
    plain = rotordyn.JournalBearing(**kw)
    for x, y, vx, vy in [(1e-5, -4e-5, 0.0, 0.0), (-3e-5, -6e-5, 1e-3, -2e-3)]:
        fa = arc.forces(x_m=x, y_m=y, speed_hz=N_HZ, vx_m_s=vx, vy_m_s=vy)
        fp = plain.forces(x_m=x, y_m=y, speed_hz=N_HZ, vx_m_s=vx, vy_m_s=vy)
        np.testing.assert_allclose(fa, fp, rtol=1e-12, atol=1e-12 * np.abs(fp).max())
    Ka, Ca = arc.coefficients(x_m=2e-5, y_m=-5e-5, speed_hz=N_HZ)
    Kp, Cp = plain.coefficients(x_m=2e-5, y_m=-5e-5, speed_hz=N_HZ)
    np.testing.assert_allclose(Ka, Kp, rtol=0, atol=1e-10 * np.abs(Kp).max())
    np.testing.assert_allclose(Ca, Cp, rtol=0, atol=1e-10 * np.abs(Cp).max())
    ta = arc.coefficient_table([10.0, 40.0], (0.0, -800.0))
    tp = plain.coefficient_table([10.0, 40.0], (0.0, -800.0))
    np.testing.assert_allclose(ta.K, tp.K, rtol=1e-9)
    e = plain.static_equilibrium(load_n=(0.0, -800.0), speed_hz=40.0)
    assert ta.y_m[1] == pytest.approx(e.y_m, rel=1e-8)


LUND_THOMSEN_LD1 = [  # S, eps, attitude, Kxx, Kxy, Kyx, Kyy, Bxx, Bxy=Byx, Byy (table frame)
    (0.991, 0.150, 70.58, 1.56, 7.29, -2.16, 1.52, 14.66, 1.58, 4.49),
    (0.635, 0.224, 63.54, 1.62, 5.33, -1.57, 1.56, 10.80, 1.70, 3.41),
    (0.235, 0.460, 49.27, 2.19, 3.57, -0.80, 1.55, 7.36, 1.89, 2.19),
    (0.159, 0.559, 44.33, 2.73, 3.36, -0.48, 1.48, 6.94, 1.78, 1.74),
    (0.108, 0.650, 39.72, 3.45, 3.34, -0.23, 1.44, 6.89, 1.72, 1.43),
]


def test_two_axial_groove_lund_thomsen_ld1():
    L = D
    omega = 2 * math.pi * N_HZ
    b = FixedGeometryBearing(station=0, kind="two_axial_groove", groove_width_deg=20.0,
                             diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
                             n_circ=144, n_axial=32)
    for S, eps, att, kxx, kxy, kyx, kyy, bxx, bxy, byy in LUND_THOMSEN_LD1:
        W = MU * N_HZ * L * D * (R / C_RAD) ** 2 / S
        t = b.coefficient_table([N_HZ], (0.0, -W))
        assert t.status[0] == "ok"
        x, y = t.x_m[0], t.y_m[0]
        assert math.hypot(x, y) / C_RAD == pytest.approx(eps, rel=0.01, abs=0.002)
        assert math.degrees(math.atan2(x, -y)) == pytest.approx(att, abs=1.0)
        K, C = t.K[0], t.C[0]
        k_tab = np.array([[K[1, 1], -K[1, 0]], [-K[0, 1], K[0, 0]]]) * C_RAD / W
        b_tab = np.array([[C[1, 1], -C[1, 0]], [-C[0, 1], C[0, 0]]]) * C_RAD * omega / W
        k_ref = np.array([[kxx, kxy], [kyx, kyy]])
        b_ref = np.array([[bxx, bxy], [bxy, byy]])
        assert np.all(np.abs(k_tab - k_ref) <= 0.05 * np.abs(k_ref) + 0.02), (S, k_tab, k_ref)
        assert np.all(np.abs(b_tab - b_ref) <= 0.05 * np.abs(b_ref) + 0.02), (S, b_tab, b_ref)


@pytest.mark.parametrize("cav, film", [("gumbel", "pi"), ("none", "full")])
def test_squeeze_film_damper_short_closed_forms(cav, film):
    Dd, c, mu, whirl = 0.1, 1e-4, 0.01, 50.0
    errs = []
    for ld in (0.2, 0.1, 0.05, 0.025):
        d = SqueezeFilmDamper(station=0, diameter_m=Dd, length_m=ld * Dd, clearance_m=c,
                              viscosity_pa_s=mu, cavitation=cav, n_circ=144, n_axial=32)
        for eps in (0.3, 0.6):
            o = d.orbit_coefficients(eccentricity_ratio=eps, whirl_hz=whirl)
            fr, ft = short_damper_orbit_forces(diameter_m=Dd, length_m=ld * Dd, clearance_m=c,
                                               viscosity_pa_s=mu, eccentricity_ratio=eps,
                                               whirl_hz=whirl, film=film)
            err_t = abs(o["f_t_n"] / ft - 1)
            err_r = abs(o["f_r_n"] / fr - 1) if fr else abs(o["f_r_n"]) / abs(ft)
            errs.append((ld, eps, max(err_t, err_r)))
    by_ld = {}
    for ld, eps, e in errs:
        by_ld[ld] = max(by_ld.get(ld, 0.0), e)
    lds = sorted(by_ld, reverse=True)
    assert all(by_ld[a] > by_ld[b] for a, b in zip(lds, lds[1:])), by_ld  # → closed form
    assert by_ld[0.025] < 0.01, by_ld


def test_tilting_pad_reduction_equals_lund_pad_assembly():
    tp = TiltingPadBearing(station=0, diameter_m=D, length_m=0.5 * D, clearance_m=C_RAD,
                           viscosity_pa_s=MU, n_pads=4, pad_arc_deg=72.0, pivot_offset=0.6,
                           preload=0.25, pad_inertia_kg_m2=3e-5, pad_thickness_m=0.01,
                           n_circ=90, n_axial=12)
    W = 600.0
    r, Kf, Cf, M = tp.full_coefficients(N_HZ, (0.0, -W))
    nu = 2 * math.pi * N_HZ
    t = tp.coefficient_table([N_HZ], (0.0, -W))
    Zsys = t.K[0] + 1j * nu * t.C[0]
    lever = R + tp.pad_thickness_m
    arc = tp.pad_arc_deg
    Zl = np.zeros((2, 2), dtype=complex)
    for k, psi_deg in enumerate(tp.pivot_angles_deg()):
        psi = math.radians(psi_deg)
        tk = np.array([-math.sin(psi), math.cos(psi)])
        centre = psi_deg - tp.pivot_offset * arc + 0.5 * arc
        pad = FixedGeometryBearing(station=0, kind="partial_arc", arc_deg=arc,
                                   orientation_deg=centre, preload=tp.preload,
                                   offset=tp.pivot_offset, diameter_m=D, length_m=0.5 * D,
                                   clearance_m=C_RAD, viscosity_pa_s=MU, n_circ=90, n_axial=12)
        q = r[:2] + lever * tp.pad_tilts_rad(r)[k] * tk  # journal relative to the tilted pad
        F = pad.forces(x_m=q[0], y_m=q[1], speed_hz=N_HZ)
        assert abs(tk @ F) < 1e-7 * W  # pad moment vanishes at the equilibrium
        Kk, Ck = pad.coefficients(x_m=q[0], y_m=q[1], speed_hz=N_HZ)
        Z = Kk + 1j * nu * Ck
        den = -nu ** 2 * tp.pad_inertia_kg_m2 + lever ** 2 * tk @ Z @ tk
        Zl += Z - lever ** 2 * np.outer(Z @ tk, tk @ Z) / den
    np.testing.assert_allclose(Zsys, Zl, rtol=1e-6, atol=1e-6 * np.abs(Zl).max())
    # statically condensed (ν → 0), every pad's force passes through its pivot along the
    # pivot's radius: K = Σ f_k' n_k n_kᵀ is symmetric (no destabilising cross-coupling)
    ts = tp.coefficient_table([N_HZ], (0.0, -W), whirl_ratio=None)
    Ks = ts.K[0]
    assert abs(Ks[0, 1] - Ks[1, 0]) < 1e-6 * np.abs(Ks).max(), Ks


@pytest.mark.parametrize("make, field", [
    (lambda: TiltingPadBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                               viscosity_pa_s=MU, n_pads=0), "n_pads"),
    (lambda: TiltingPadBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                               viscosity_pa_s=MU, preload=1.0), "preload"),
    (lambda: FixedGeometryBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                                  viscosity_pa_s=MU, kind="elliptical", preload=1.2), "preload"),
    (lambda: TiltingPadBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                               viscosity_pa_s=MU, pivot_offset=1.0), "pivot_offset"),
    (lambda: TiltingPadBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                               viscosity_pa_s=MU, pivot_offset=0.0), "pivot_offset"),
    (lambda: rotordyn.bearings.TableBearing(station=0, speeds_hz=(10.0, 30.0, 20.0),
                                            kxx_n_per_m=(1.0, 2.0, 3.0),
                                            kyy_n_per_m=(1.0, 2.0, 3.0)), "speeds_hz"),
    (lambda: FixedGeometryBearing(station=0, diameter_m=D, length_m=D, clearance_m=C_RAD,
                                  viscosity_pa_s=MU, kind="five_lobe"), "kind"),
])
def test_bad_input_names_the_field(make, field):
    with pytest.raises(InputError, match=field):
        make()
