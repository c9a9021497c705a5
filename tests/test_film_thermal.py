"""Effective-temperature thermal model (issue 20): viscosity laws, the heat balance and its
iteration with the Reynolds equilibrium (C++ ``thermal_equilibrium``).

Model (docs/film-physics.md; the Raimondi–Boyd/Shigley heat balance): all friction power P
goes into the oil; the film draws Q across its line of maximum thickness, the side leakage Q_s
leaves at the mean rise ΔT/2 and Q − Q_s at ΔT: P = ρ c_p ΔT (Q − Q_s/2); the film inlet is
the supply at T_s mixed with the carried-over fraction λ of Q − Q_s at T_max; T_eff = T_in +
k ΔT (k = 0.5: Shigley's average film temperature).

Checks: the Walther (ASTM D341) law through its two points and its closed form at a third
temperature; the exponential law; the whole iteration on the short (Ocvirk) bearing against
an independent solution from the closed forms (load W(ε), friction torque 2πμωR³L/(c√(1−ε²))
+ eW sin ψ/2, side flow ωReL, Q = ωRc(1+ε)L/2; Hamrock, Fundamentals of Fluid Film
Lubrication, ch. 10 for the short bearing); the isothermal limit; the heat balance closing in
the outputs; K, C at the thermal equilibrium equal the isothermal ones at μ(T_eff); bad input.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Oil
from rotordyn.errors import InputError

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def walther_nu(t, t1=40.0, n1=32.0, t2=100.0, n2=5.4):
    W = lambda n: math.log10(math.log10(n + 0.7))  # noqa: E731
    l1, l2 = math.log10(t1 + 273.15), math.log10(t2 + 273.15)
    B = (W(n1) - W(n2)) / (l2 - l1)
    A = W(n1) + B * l1
    return 10 ** 10 ** (A - B * math.log10(t + 273.15)) - 0.7


def test_walther_law_through_its_points_and_closed_form():
    """ASTM D341: log10 log10(ν + 0.7) = A − B log10 T_K through (40 °C, 32 mm²/s),
    (100 °C, 5.4 mm²/s); μ = ρν. At 70 °C the closed form gives ν ≈ 11.0 mm²/s."""
    np.testing.assert_allclose(VG32.viscosity_pa_s([40.0, 100.0]), [870 * 32e-6, 870 * 5.4e-6],
                               rtol=1e-12)
    assert VG32.viscosity_pa_s(70.0) == pytest.approx(870e-6 * walther_nu(70.0), rel=1e-12)
    assert 10.5 < walther_nu(70.0) < 11.5
    ex = Oil(viscosity_law="exponential", mu_ref_pa_s=0.03, t_ref_c=40.0, beta_1_per_k=0.03)
    assert ex.viscosity_pa_s(60.0) == pytest.approx(0.03 * math.exp(-0.6), rel=1e-14)


R, L, C, F_HZ, LOAD = 0.05, 0.02, 1e-4, 50.0, 1500.0


def _short_solver(n_circ=720, n_axial=64):
    g = _core.JournalBearingGeometry()
    g.diameter_m, g.length_m, g.clearance_m, g.viscosity_pa_s = 2 * R, L, C, 0.02
    g.short_bearing = True
    return _core.ReynoldsSolver(g, _core.FilmGrid(n_circ, n_axial), "reynolds")


def _short_reference(oil, ts):
    """Independent solution from the short-bearing closed forms (π film)."""
    w = 2 * math.pi * F_HZ
    rc = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k

    def state(t):
        mu = oil.viscosity_pa_s(t)
        load = lambda e: mu * w * R * L ** 3 / (4 * C ** 2) * e * math.sqrt(  # noqa: E731
            16 * e ** 2 + math.pi ** 2 * (1 - e ** 2)) / (1 - e ** 2) ** 2 - LOAD
        eps = brentq(load, 1e-9, 1 - 1e-9, xtol=1e-15)
        psi = math.atan(math.pi * math.sqrt(1 - eps ** 2) / (4 * eps))
        torque = 2 * math.pi * mu * w * R ** 3 * L / (C * math.sqrt(1 - eps ** 2)) \
            + 0.5 * eps * C * LOAD * math.sin(psi)
        q = 0.5 * w * R * C * (1 + eps) * L
        qs = w * R * eps * C * L
        dt = torque * w / (rc * (q - 0.5 * qs))
        return eps, dt, torque * w, q, qs

    t_eff = brentq(lambda t: t - ts - 0.5 * state(t)[1], ts, ts + 200.0, xtol=1e-12)
    return (t_eff,) + state(t_eff)


def test_short_bearing_thermal_equilibrium_against_closed_forms():
    """The C++ iteration on the core's short-bearing film (720 × 64 nodes: its discretisation
    error ~1e-4) against the closed-form solution of the same heat balance: T_eff − T_s, ε, P,
    Q and Q_s to 3e-4 (observed: 4e-5)."""
    opts = _core.ThermalOptions()
    opts.supply_temperature_c = 40.0
    r = _core.thermal_equilibrium(_short_solver(), VG32.to_core(), opts, 0.0, -LOAD,
                                  2 * math.pi * F_HZ)
    t_eff, eps, dt, p, q, qs = _short_reference(VG32, 40.0)
    assert r.effective_temperature_c - 40.0 == pytest.approx(t_eff - 40.0, rel=3e-4)
    e = r.equilibrium
    assert math.hypot(e.x_m, e.y_m) / C == pytest.approx(eps, rel=3e-4)
    assert r.power_loss_w == pytest.approx(p, rel=3e-4)
    assert r.film_flow_m3_s == pytest.approx(q, rel=3e-4)
    assert r.side_flow_m3_s == pytest.approx(qs, rel=3e-4)
    assert r.max_temperature_c == pytest.approx(40.0 + dt, rel=3e-4)
    assert t_eff - 40.0 > 5.0  # a real rise (so the check is not trivially the isothermal one)


def _bearing():
    return rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                   viscosity_pa_s=0.02, n_circ=36, n_axial=8)


def test_heat_balance_closes_and_coefficients_are_isothermal_at_t_eff():
    """Outputs satisfy P = ρ c_p ΔT (Q − Q_s/2) and T_eff = T_in + k ΔT, T_in = T_s + λ Q_r ΔT/Q_f
    to round-off; the equilibrium and K, C equal the isothermal film's at μ(T_eff) (the
    temperature is frozen for the perturbation) to the iteration's tolerance."""
    b = _bearing()
    r = b.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                              supply_temperature_c=45.0, carry_over=0.3, effective_factor=0.6)
    assert r.status == "ok" and r.effective_temperature_c > 50.0
    rc = 870.0 * 2000.0
    dT = r.temperature_rise_k
    assert r.power_loss_w == pytest.approx(rc * dT * (r.film_flow_m3_s - 0.5 * r.side_flow_m3_s),
                                           rel=1e-12)
    qr = r.film_flow_m3_s - r.side_flow_m3_s
    assert r.inlet_temperature_c == pytest.approx(45.0 + 0.3 * qr * dT / r.supply_flow_m3_s,
                                                  rel=1e-12)
    assert r.effective_temperature_c == pytest.approx(r.inlet_temperature_c + 0.6 * dT, abs=1e-5)
    assert r.max_temperature_c == pytest.approx(r.inlet_temperature_c + dT, rel=1e-12)
    assert r.viscosity_pa_s == pytest.approx(VG32.viscosity_pa_s(r.effective_temperature_c),
                                             rel=1e-12)
    iso = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                  viscosity_pa_s=r.viscosity_pa_s, n_circ=36, n_axial=8)
    e = iso.static_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0)
    assert (r.x_m, r.y_m) == pytest.approx((e.x_m, e.y_m), rel=1e-7, abs=1e-12)
    K, Cc = iso.coefficients(x_m=r.x_m, y_m=r.y_m, speed_hz=100.0)
    np.testing.assert_allclose(r.K, K, rtol=1e-6, atol=1e-6 * np.abs(K).max())
    np.testing.assert_allclose(r.C, Cc, rtol=1e-6, atol=1e-6 * np.abs(Cc).max())
    df = r.to_frame()
    assert df.loc[0, "effective_temperature_c"] == r.effective_temperature_c
    assert {"kxy_n_per_m", "power_loss_w", "max_temperature_c"} <= set(df.columns)


def test_isothermal_limit():
    """A huge heat capacity: the film stays at the supply temperature (ΔT → 0)."""
    oil = Oil(viscosity_law="exponential", mu_ref_pa_s=0.02, t_ref_c=40.0, beta_1_per_k=0.03,
              specific_heat_j_per_kg_k=1e12)
    r = _bearing().thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=oil,
                                       supply_temperature_c=40.0)
    assert r.temperature_rise_k < 1e-6
    e = _bearing().static_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0)
    assert r.y_m == pytest.approx(e.y_m, rel=1e-6)


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="specific_heat_j_per_kg_k"):
        Oil(specific_heat_j_per_kg_k=-1.0)
    with pytest.raises(InputError, match="nu2_mm2_s"):  # viscosity rising with temperature
        Oil(nu1_mm2_s=5.0, nu2_mm2_s=30.0)
    with pytest.raises(InputError, match="beta_1_per_k"):
        Oil(viscosity_law="exponential", beta_1_per_k=-0.01)
    with pytest.raises(InputError, match="viscosity_law"):
        Oil(viscosity_law="vogel")
    b = _bearing()
    with pytest.raises(InputError, match="supply_temperature_c"):
        b.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                              supply_temperature_c=-40.0)
    with pytest.raises(InputError, match="carry_over"):
        b.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                              supply_temperature_c=40.0, carry_over=1.5)


def test_cli_thermal_and_turbulent_output(capsys):
    """``rotordyn bearing`` with the thermal model prints (and --json records) the effective
    and maximum temperatures, the power loss, flows and K, C of the thermal equilibrium, equal
    to the Python API's; a viscosity law rising with temperature exits 2 naming the field."""
    import json

    from rotordyn.cli import main

    base = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
            "--n-circ", "36", "--n-axial", "8", "--speed-hz", "100", "--load-n", "0", "-5000"]
    assert main(base + ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100",
                        "5.4", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    r = _bearing().thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                                       supply_temperature_c=45.0)
    assert rec["thermal"]["effective_temperature_c"] == pytest.approx(r.effective_temperature_c,
                                                                       rel=1e-12)
    assert rec["thermal"]["power_loss_w"] == pytest.approx(r.power_loss_w, rel=1e-12)
    np.testing.assert_allclose(rec["k_n_per_m"], r.K, rtol=1e-12)
    assert main(base + ["--supply-temperature-c", "45", "--oil-walther", "40", "5", "100",
                        "30"]) == 2
    assert "nu2_mm2_s" in capsys.readouterr().err
    assert main(base + ["--viscosity-pa-s", "0.003", "--turbulence", "ng_pan",
                        "--density-kg-m3", "870", "--json"]) == 0
    t = json.loads(capsys.readouterr().out)
    assert t["bearing"]["turbulence"] == "ng_pan"
    tb = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                 viscosity_pa_s=0.003, n_circ=36, n_axial=8, turbulence="ng_pan",
                                 density_kg_m3=870.0)
    e = tb.static_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0)
    assert t["equilibrium"]["eccentricity_ratio"] == pytest.approx(e.eccentricity_ratio, rel=1e-12)


@pytest.mark.parametrize("l_over_d, eps, q_rb", [(0.25, 0.6, 4.99), (0.25, 0.9, 5.91),
                                                 (0.5, 0.6, 4.85)])
def test_heat_balance_flow_against_raimondi_boyd(l_over_d, eps, q_rb):
    """The heat balance's film flow Q of a grooveless film (the flux into the film just
    downstream of its maximum thickness) against Raimondi & Boyd's flow variable Q/(R c N L)
    (ASLE Trans. 1 (1958) 159–209, full bearing; the supply line at the maximum film): within
    0.5 % at L/D = 1/4 and 2 % at L/D = 1/2 (144 × 32; the grooveless Swift–Stieber film
    draws slightly more than one with a p = 0 supply line: +5 % at L/D = 1, documented)."""
    D, C, N = 0.05, 1e-4, 20.0
    b = rotordyn.JournalBearing(diameter_m=D, length_m=l_over_d * D, clearance_m=C,
                                viscosity_pa_s=0.02, n_circ=144, n_axial=32)
    s = b.solver()
    sol = s.rigid(0.0, -eps * C, 0.0, 0.0, 2 * math.pi * N)
    q = _core.max_film_flow(s, sol, 2 * math.pi * N) / (0.5 * D * C * N * l_over_d * D)
    assert q == pytest.approx(q_rb, rel=0.005 if l_over_d == 0.25 else 0.02)
    assert q >= q_rb * 0.999


def test_grooved_bearing_draws_the_groove_flow():
    """With a supply groove (at 150°, near the maximum film of this load, whose attitude is
    ~50°) the heat balance takes the flow the groove delivers into the film
    (FilmResult.inlet_flow_m3_s at the thermal equilibrium), and the fresh flow a given supply
    (below the film's demand, with carry-over) mixes hotter oil in: T_in > T_s. (The supply
    was 0.5 Q, below the side leakage Q_s: a starved film since 2026-12-06, docs/film-physics.md
    "A metered supply below the film's demand"; now Q_s + (Q − Q_s)/4, fed.)"""
    b = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                viscosity_pa_s=0.02, n_circ=36, n_axial=8,
                                grooves=[rotordyn.Groove(center_deg=150.0, width_deg=20.0)])
    r = b.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                              supply_temperature_c=45.0)
    hot = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                  viscosity_pa_s=r.viscosity_pa_s, n_circ=36, n_axial=8,
                                  grooves=[rotordyn.Groove(center_deg=150.0, width_deg=20.0)])
    f = hot.solve(x_m=r.x_m, y_m=r.y_m, speed_hz=100.0)
    assert r.film_flow_m3_s == pytest.approx(f.inlet_flow_m3_s, rel=1e-9)
    assert r.inlet_temperature_c == 45.0
    r2 = b.thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32,
                               supply_temperature_c=45.0, carry_over=0.5,
                               supply_flow_m3_s=r.side_flow_m3_s + 0.25 * (
                                   r.film_flow_m3_s - r.side_flow_m3_s))
    assert r2.inlet_temperature_c > 45.0 + 1.0
    assert r2.effective_temperature_c > r.effective_temperature_c


def test_thermal_with_turbulent_film():
    """A turbulent film (Ng–Pan–Elrod, ρ from the oil) in the thermal iteration: P is no longer
    proportional to μ at a fixed position, the outer iteration still converges and the heat
    balance closes; the turbulent film loses more power than the laminar one."""
    kw = dict(diameter_m=0.2, length_m=0.1, clearance_m=2e-4, viscosity_pa_s=0.02, n_circ=36,
              n_axial=8)
    lam = rotordyn.JournalBearing(**kw)
    tur = rotordyn.JournalBearing(**kw, turbulence="ng_pan", density_kg_m3=870.0)
    args = dict(load_n=(0.0, -20000.0), speed_hz=150.0, oil=VG32, supply_temperature_c=45.0)
    rl, rt = lam.thermal_equilibrium(**args), tur.thermal_equilibrium(**args)
    rc = 870.0 * 2000.0
    assert rt.power_loss_w == pytest.approx(
        rc * rt.temperature_rise_k * (rt.film_flow_m3_s - 0.5 * rt.side_flow_m3_s), rel=1e-12)
    assert rt.power_loss_w > 1.05 * rl.power_loss_w


def test_thermal_iteration_converges_on_a_coarse_grid():
    """On a 36 × 8 grid the node of the maximum film jumps as the journal moves; the heat
    balance's Q interpolates between the faces around the true maximum, so it is continuous in
    the position and the iteration settles (it cycled between two states 0.14 K apart when Q
    was taken at the node's face). Loads from light to heavy; at most 8 outer steps."""
    b = rotordyn.JournalBearing(diameter_m=0.2, length_m=0.1, clearance_m=2e-4,
                                viscosity_pa_s=0.02, n_circ=36, n_axial=8)
    temps = []
    for w in (2e3, 5e3, 1e4, 2e4, 5e4):
        r = b.thermal_equilibrium(load_n=(0.0, -w), speed_hz=150.0, oil=VG32,
                                  supply_temperature_c=45.0)
        assert r.iterations <= 8
        temps.append(r.effective_temperature_c)
    assert np.all(np.diff(temps) > 0)  # more load, more heat


def test_reverse_rotation_mirrors():
    """Reverse rotation mirrors the thermal equilibrium (x → −x; temperatures, power and
    flows equal to round-off): the power P = torque·ω and the flow downstream of the maximum
    film follow the sense of rotation."""
    b = _bearing()
    args = dict(load_n=(0.0, -5000.0), oil=VG32, supply_temperature_c=45.0)
    f, r = b.thermal_equilibrium(speed_hz=100.0, **args), b.thermal_equilibrium(speed_hz=-100.0,
                                                                               **args)
    assert r.effective_temperature_c == pytest.approx(f.effective_temperature_c, rel=1e-12)
    assert r.power_loss_w == pytest.approx(f.power_loss_w, rel=1e-10)
    assert r.film_flow_m3_s == pytest.approx(f.film_flow_m3_s, rel=1e-10)
    assert (r.x_m, r.y_m) == pytest.approx((-f.x_m, f.y_m), rel=1e-9)
