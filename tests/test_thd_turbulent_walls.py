"""The turbulent THD film's heat transfer to its walls (issue 20; docs/film-physics.md
"Turbulent films with a temperature field"; C++ thd_wall_turbulence.hpp).

Model: the film-side coefficients of ``wall_htc = "film"`` (the laminar film's parabola,
q_J = θ k/h (6 T − 4 T_J − 2 T_w)) written as a symmetric part 6 θ k/h and an across-film part
θ k/h, each raised by an eddy conductivity k (1 + (Pr/Pr_t) ε_m/ν): Reichardt's wall law
ε_m/ν = κ [y⁺ − δ_l⁺ tanh(y⁺/δ_l⁺)], κ = 0.4, δ_l⁺ = 10.7 (Reichardt 1951, ZAMM 31, 208–219;
the law of Ng & Pan's turbulent lubrication theory and of the turbulent THD analyses of
Suganami & Szeri 1979, J. Lubr. Technol. 101, 21–27, and Taniguchi et al. 1990, J. Tribol.
112, 542–550), Pr_t = 0.9, wall units from the film's own Couette wall shear C_f μU/h
(h⁺ = √(C_f Re_h)), the heat source across the film the turbulent dissipation τ du/dy. In wall
units (a = h⁺/2, F(y) = ∫₀^y dy'/(1 + ε_m/ν), t = 1 + (Pr/Pr_t) ε_m/ν):
    G_c = a / ∫₀^a dy/t,   G_s = a² F(a) / (3 ∫₀^a (a − y)(F(a) − F(y))/t dy).

Checks:
* the factors against an independent quadrature (scipy ``quad``, nested) of the same formulas
  at a few (Re_h, Pr), 1e-7; exactly 1 for the laminar model and Re_h = 0; → 1 as Re_h → 0;
* the eddy model's own Couette shear factor (the same integral for momentum: Re_h = 4 a F(a),
  C_f = a/F(a)) against scipy and against the film's Ng–Pan C_f = 1 + 0.0012 Re_h^0.94
  (Taylor & Dowson 1974): within 6 % over Re_h 1e3–1e4, 10 % low at 3e4, 22 % low at 1e5 (the
  wall law's logarithmic core against the fit's power law);
* the turbulent THD film of a large bearing with its walls (journal from its balance,
  conducting bush) conserves energy: dissipation = heat the flows carry + heat to the walls
  (1e-9), each cell's film-side flux recomputed from the returned fields with the factors at
  its Re_h and Pr equals the conduction through the bush (1e-9);
* the same bearing (D 0.3 m, 100 Hz, 60 kN) with and without the eddy conductivity: the
  walls take more heat, the film runs cooler, the bush surface hotter; the same on a large
  tilting-pad bearing (every pad's film takes the factors): the loaded pads cooler, the
  journal cooler;
* a turbulent film's density is the thermal oil's (one oil), else an InputError naming it;
* bad input names the field.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Groove, Oil, TiltingPadBearing
from rotordyn.bearings.pad_thd import pad_model_options, pad_thd_equilibrium
from rotordyn.bearings.thd import run_thd_equilibrium, thd_options
from rotordyn.errors import InputError
from thd_balance import balance

KAPPA, DELTA, PR_T = 0.4, 10.7, 0.9
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=0.13)
RC = VG32.density_kg_m3 * VG32.specific_heat_j_per_kg_k
BIG = dict(diameter_m=0.3, length_m=0.15, clearance_m=4.5e-4)   # as tests/test_thd_turbulent
SPEED, TS, LOAD = 100.0, 45.0, (0.0, -60e3)
W = 2.0 * math.pi * SPEED
PAD = dict(bush_wall="conduction", bush_thickness_m=0.03, bush_conductivity_w_per_m_k=50.0,
           back_htc_w_m2k=1000.0)   # a steel bush, 30 mm, cooled by oil at its back
FILM = dict(wall_htc="film", journal_wall="balance", **PAD)
U = 1.0 / (PAD["bush_thickness_m"] / PAD["bush_conductivity_w_per_m_k"]
           + 1.0 / PAD["back_htc_w_m2k"])


def _eddy(y):
    return KAPPA * (y - DELTA * math.tanh(y / DELTA))


def _F(y):
    return quad(lambda s: 1.0 / (1.0 + _eddy(s)), 0.0, y, epsabs=0.0, epsrel=1e-13,
                limit=200)[0]


def _factors(re, pr):
    """(G_s, G_c) by nested adaptive quadrature of the module docstring's formulas."""
    cf = 1.0 + 0.0012 * re ** 0.94             # the film's Ng–Pan (Taylor & Dowson) C_f
    a, P = 0.5 * math.sqrt(cf * re), pr / PR_T
    Fa = _F(a)
    brk = [x for x in (1.0, 5.0, DELTA, 30.0) if x < a]
    R = quad(lambda y: 1.0 / (1.0 + P * _eddy(y)), 0.0, a, points=brk, epsabs=0.0,
             epsrel=1e-12, limit=400)[0]
    J = quad(lambda y: (a - y) * (Fa - _F(y)) / (1.0 + P * _eddy(y)), 0.0, a, points=brk,
             epsabs=0.0, epsrel=1e-11, limit=400)[0]
    return a * a * Fa / (3.0 * J), a / R


@pytest.mark.parametrize("re,pr", [(300.0, 50.0), (2000.0, 200.0), (1e4, 1000.0),
                                   (5e4, 20.0), (1000.0, 5000.0)])
def test_factors_against_an_independent_quadrature(re, pr):
    gs, gc = _core.turbulent_wall_factors("ng_pan", re, pr)
    ref = _factors(re, pr)
    assert gs == pytest.approx(ref[0], rel=1e-7)
    assert gc == pytest.approx(ref[1], rel=1e-7)
    assert 1.0 < gs < gc    # heat generated near the walls: less of it crosses the sublayer


def test_factors_are_one_without_turbulence_and_grow_with_re_and_pr():
    assert _core.turbulent_wall_factors("ng_pan", 0.0, 300.0) == (1.0, 1.0)
    assert _core.turbulent_wall_factors("laminar", 5000.0, 300.0) == (1.0, 1.0)
    assert _core.eddy_wall_factors(0.0, 300.0) == (1.0, 1.0)
    # Re_h → 0: G − 1 ∝ P ε_m/ν at mid-film ∝ a³ ∝ Re_h^(3/2) (Reichardt's ε_m ∝ y⁺³ at the
    # wall): a factor 1000 per two decades of Re_h
    g3, g5 = (np.array(_core.turbulent_wall_factors("ng_pan", re, 300.0)) - 1.0
              for re in (1e-3, 1e-5))
    assert np.all(g3 > 0.0) and np.all(g3 < 1e-6)
    np.testing.assert_allclose(g3 / g5, 1000.0, rtol=1e-3)
    # the laminar parabola: G_s = G_c = 1 to quadrature accuracy where the eddy term is
    # negligible (P ε_m/ν ~ 1e-15 over the film)
    gs, gc = _core.eddy_wall_factors(1e-4, 1.0)
    assert gs == pytest.approx(1.0, abs=1e-14) and gc == pytest.approx(1.0, abs=1e-14)
    last = (1.0, 1.0)
    for re in (100.0, 1000.0, 3000.0, 1e4):
        g = _core.turbulent_wall_factors("ng_pan", re, 200.0)
        assert g[0] > last[0] and g[1] > last[1]
        last = g
    # oils: Pr ~ 100–1000 gives an order of magnitude at Re_h ~ 2000 (the large bearing's)
    g1, g2 = (_core.turbulent_wall_factors("ng_pan", 2000.0, pr) for pr in (100.0, 1000.0))
    assert 4.0 < g1[0] < g2[0] and 10.0 < g1[1] < g2[1]
    # fully turbulent: G_s → G_c/3 from above (each wall's coefficient the half film's
    # resistance from the mid-film; the heat generated inside the sublayer keeps it above)
    for re in (1e4, 1e5):
        gs, gc = _core.turbulent_wall_factors("ng_pan", re, 1000.0)
        assert 1.0 / 3.0 < gs / gc < 0.36


def test_couette_shear_of_the_eddy_model_against_ng_pan():
    for re, lo, hi in ((1e3, 0.94, 1.06), (2e3, 0.94, 1.06), (5e3, 0.94, 1.06),
                       (1e4, 0.94, 1.06), (3e4, 0.85, 0.95), (1e5, 0.74, 0.82)):
        cf = _core.eddy_couette_shear_factor(re)
        a = brentq(lambda a: 4.0 * a * _F(a) - re, 0.5 * math.sqrt(re), 50.0 * math.sqrt(re),
                   xtol=1e-13, rtol=1e-14)
        assert cf == pytest.approx(a / _F(a), rel=1e-8)
        assert lo < cf / (1.0 + 0.0012 * re ** 0.94) < hi, re
    assert _core.eddy_couette_shear_factor(0.0) == 1.0


def _bearing(rho=870.0, **kw):
    return rotordyn.JournalBearing(turbulence="ng_pan", density_kg_m3=rho, n_circ=36,
                                   n_axial=8, viscosity_pa_s=0.02, **BIG, **kw)


def _film_h(b, r):
    phi = 2.0 * np.pi * np.arange(b.n_circ) / b.n_circ
    h = b.clearance_m - r.x_m * np.cos(phi) - r.y_m * np.sin(phi)
    return np.repeat(h[:, None], b.n_axial + 1, axis=1)


def _run(b, eddy=True, **kw):
    g, grid = b.to_core()
    s = _core.ReynoldsSolver(g, grid, b.cavitation)
    o = thd_options(supply_temperature_c=TS, **kw)
    o.wall_eddy_conductivity = eddy
    return run_thd_equilibrium(s, VG32, o, LOAD, SPEED, b.clearance_m)


def test_turbulent_film_with_walls_conserves_energy():
    b = _bearing(cavitation="jfo", grooves=[Groove(center_deg=90.0, width_deg=20.0)])
    r = _run(b, carry_over=0.5, **FILM)
    out, diss, _, mass = balance(r.temperature_c, r.inlet_mask, r.flows, RC, TS)
    assert mass < 1e-8
    assert out + r.heat_to_journal_w + r.heat_to_bush_w == pytest.approx(diss, rel=1e-9)
    assert abs(r.heat_to_journal_w) < 1e-9 * diss
    assert r.heat_to_bush_w > 0.01 * diss         # 1.3 % through the bush here
    # each cell's film-side fluxes from the returned fields and the factors at its Re_h, Pr
    film = r.inlet_mask == 0
    T, Tw, TJ = r.temperature_c, r.wall_temperature_c, r.journal_temperature_c
    h, th, A, mu = _film_h(b, r), r.flows["fill"], r.flows["area_m2"], r.viscosity_pa_s
    re = VG32.density_kg_m3 * W * 0.5 * BIG["diameter_m"] * h / mu
    pr = mu * VG32.specific_heat_j_per_kg_k / VG32.conductivity_w_per_m_k
    G = np.array([_core.turbulent_wall_factors("ng_pan", x, p)
                  for x, p in zip(re.ravel(), pr.ravel())]).reshape(*re.shape, 2)
    assert G[..., 0][film].min() > 2.0        # the eddy conductivity matters here
    c = th * VG32.conductivity_w_per_m_k / h
    Hs, Kc = 6.0 * c * G[..., 0], c * G[..., 1]
    q_j = Hs * (T - 0.5 * (TJ + Tw)) + Kc * (Tw - TJ)
    q_b = Hs * (T - 0.5 * (TJ + Tw)) - Kc * (Tw - TJ)
    np.testing.assert_allclose(q_b[film], U * (Tw[film] - TS), rtol=1e-9,
                               atol=1e-9 * np.abs(q_b).max())
    assert (A * q_b)[film].sum() == pytest.approx(r.heat_to_bush_w, rel=1e-9)
    assert abs((A * q_j)[film].sum()) < 1e-8 * diss
    # the whole bearing: side leakage + the flow not carried over + the walls = the power
    # loss (the film's cells' dissipation; a groove's nodes are not film)
    conv = RC * (r.side_flow_m3_s * (r.side_temperature_c - TS) + 0.5
                 * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - TS))
    assert conv + r.heat_to_journal_w + r.heat_to_bush_w == pytest.approx(r.power_loss_w,
                                                                          rel=1e-9)


def test_large_turbulent_bearing_runs_cooler_with_the_eddy_conductivity():
    b = _bearing()
    lam = _run(b, eddy=False, **FILM)   # the laminar film's wall coefficients (before)
    tur = _run(b, **FILM)
    # the public entry point is the run with the eddy conductivity
    pub = b.thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32, supply_temperature_c=TS,
                                model="thd", **FILM)
    assert pub.status == "ok", pub.message
    assert pub.max_temperature_c == tur.max_temperature_c
    assert tur.heat_to_bush_w > 1.5 * lam.heat_to_bush_w       # the walls take more heat
    assert tur.max_temperature_c < lam.max_temperature_c - 1.0  # the film runs cooler
    assert tur.mean_temperature_c < lam.mean_temperature_c
    # ... and closer to its walls: the bush surface hotter (what a thermocouple reads)
    assert tur.max_wall_temperature_c > lam.max_wall_temperature_c
    assert tur.max_wall_temperature_c < tur.max_temperature_c


def test_tilting_pads_pass_the_eddy_conductivity_to_every_pad():
    # a large tilting-pad bearing (5 pads on 60°, load between pads 0 and 4), one journal
    # from its heat balance over the pads, each pad conducting to oil at its back
    tp = TiltingPadBearing(station=0, diameter_m=0.3, length_m=0.15, clearance_m=3e-4,
                           viscosity_pa_s=0.02, n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5,
                           preload=0.3, n_circ=60, n_axial=6, turbulence="ng_pan",
                           density_kg_m3=870.0)
    res = {}
    for eddy in (False, True):
        o = pad_model_options("thd", supply_temperature_c=TS, supply_flow_m3_s=0.0,
                              carry_over=0.5, effective_factor=0.5, tol_k=1e-6, **FILM)
        o.wall_eddy_conductivity = eddy
        r = pad_thd_equilibrium(tp.system_parts(0, 1, 2, "bearing"), oil=VG32, opts=o,
                                load_n=LOAD, speed_hz=SPEED, clearance_m=tp.clearance_m,
                                whirl_ratio=None, tilts=tp.pad_tilts_rad)
        assert r.status == "ok", r.message
        res[eddy] = r
    lam, tur = res[False], res[True]
    t_lam, t_tur = np.asarray(lam.max_temperature_c), np.asarray(tur.max_temperature_c)
    loaded = [0, 4]
    assert np.all(t_tur[loaded] < t_lam[loaded] - 1.0)            # the loaded pads cooler
    assert np.sum(tur.heat_to_bush_w) > 1.3 * np.sum(lam.heat_to_bush_w)
    # the journal, better coupled, runs cooler and carries more heat from the loaded pads
    # to the unloaded ones (whose films it warms: their bush heat rises)
    assert tur.journal_temperature_c[0] < lam.journal_temperature_c[0] - 1.0
    assert np.all(np.asarray(tur.heat_to_bush_w)[1:4] > np.asarray(lam.heat_to_bush_w)[1:4])


def test_the_turbulent_film_and_the_thermal_oil_are_one_oil():
    """A turbulent film's density (its Re_h) must be the thermal oil's (the heat balance, the
    Walther law's μ = ρν): a film at 860 kg/m³ under the VG 32 oil's 870 is refused, naming
    the field, in the standalone THD film, the effective-temperature film and a system's
    thermal equilibrium. (Re_h → 0 through the density alone, which this refusal rules out
    at the THD level, is checked on the factors:
    test_factors_are_one_without_turbulence_and_grow_with_re_and_pr.)"""
    with pytest.raises(InputError, match=r"density_kg_m3: a turbulent film's density .* "
                       r"oil.density_kg_m3 = 870 .* got 860"):
        _run(_bearing(rho=860.0), **FILM)
    with pytest.raises(InputError, match="density_kg_m3: a turbulent film's density"):
        _bearing(rho=860.0).thermal_equilibrium(load_n=LOAD, speed_hz=SPEED, oil=VG32,
                                                supply_temperature_c=TS)
    assert _run(_bearing(rho=870.0), **FILM).max_temperature_c > TS  # the same oil runs


@pytest.mark.parametrize("args,field", [((-1.0, 100.0), "reynolds_number"),
                                        ((math.nan, 100.0), "reynolds_number"),
                                        ((100.0, 0.0), "prandtl_number"),
                                        ((100.0, -5.0), "prandtl_number"),
                                        ((100.0, math.inf), "prandtl_number")])
def test_bad_input_names_the_field(args, field):
    with pytest.raises(InputError, match=field):
        _core.turbulent_wall_factors("ng_pan", *args)
    with pytest.raises(InputError, match="turbulence"):
        _core.turbulent_wall_factors("k_epsilon", 100.0, 100.0)
    with pytest.raises(InputError, match="prandtl_ratio"):
        _core.eddy_wall_factors(10.0, 0.0)
    with pytest.raises(InputError, match="reynolds_number"):
        _core.eddy_couette_shear_factor(-1.0)
