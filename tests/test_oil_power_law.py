"""The power viscosity law μ = a T^b (T in °C) of the oil model (issue 20).

It is the law of ROSS's thermo-hydrodynamic bearings (ROSS 2.3 ``THDCylindrical`` and
``TiltingPad``: a and b fitted through the lubricant's viscosities at two temperatures, T in
°C), so that a side-by-side with ROSS compares equal physics without a substitute law.

Checks: the law through its two points and against the closed form a T^b at other
temperatures (a, b computed here as ROSS does: b = ln(μ2/μ1)/ln(T2/T1), a = μ1/T1^b); the
thermal equilibrium of the short (Ocvirk) bearing against the closed forms with this law (the
same independent solution as tests/test_film_thermal.py's); the THD film through the law; a
TOML round trip; the CLI's ``--oil-power`` equals the Python API; bad input names the field.
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import Oil
from rotordyn.errors import InputError

from test_film_thermal import C, F_HZ, LOAD, _short_reference, _short_solver

# a VG 68-like mineral oil: dynamic viscosities at 40 and 100 °C (any two points define the law)
VG68 = dict(t1_c=40.0, mu1_pa_s=0.0570, t2_c=100.0, mu2_pa_s=0.00754)


def _power(**kw):
    return Oil(viscosity_law="power", t_min_c=1.0, density_kg_m3=870.0,
               specific_heat_j_per_kg_k=2000.0, **{**VG68, **kw})


def test_power_law_through_its_points_and_closed_form():
    oil = _power()
    np.testing.assert_allclose(oil.viscosity_pa_s([40.0, 100.0]), [0.0570, 0.00754],
                               rtol=1e-14)
    b = math.log(0.00754 / 0.0570) / math.log(100.0 / 40.0)
    a = 0.0570 / 40.0 ** b
    assert -2.3 < b < -2.1  # the exponent of a VG 68 mineral oil (docs: ROSS's b = −2.19)
    t = np.array([1.0, 25.0, 55.5, 70.0, 150.0])
    np.testing.assert_allclose(oil.viscosity_pa_s(t), a * t ** b, rtol=1e-13)
    # strictly falling: a law, not a fit artefact
    assert np.all(np.diff(oil.viscosity_pa_s(np.linspace(1.0, 200.0, 400))) < 0.0)


def test_short_bearing_thermal_equilibrium_with_the_power_law():
    """The C++ iteration with the power law against the closed-form heat balance of the short
    bearing (same tolerance 3e-4 as for the Walther law, test_film_thermal.py)."""
    oil = _power()
    opts = _core.ThermalOptions()
    opts.supply_temperature_c = 40.0
    r = _core.thermal_equilibrium(_short_solver(), oil.to_core(), opts, 0.0, -LOAD,
                                  2 * math.pi * F_HZ)
    t_eff, eps, dt, p, q, qs = _short_reference(oil, 40.0)
    assert t_eff - 40.0 > 5.0
    assert r.effective_temperature_c - 40.0 == pytest.approx(t_eff - 40.0, rel=3e-4)
    e = r.equilibrium
    assert math.hypot(e.x_m, e.y_m) / C == pytest.approx(eps, rel=3e-4)
    assert r.power_loss_w == pytest.approx(p, rel=3e-4)
    assert r.viscosity_pa_s == pytest.approx(oil.viscosity_pa_s(r.effective_temperature_c),
                                             rel=1e-12)


def _bearing():
    return rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                   viscosity_pa_s=0.02, n_circ=36, n_axial=8)


def test_thd_film_uses_the_power_law_at_every_node():
    """The THD film's viscosity field against the closed form a T^b at each node's
    temperature (a, b computed here): within 1e-8 relative — the field is the law at the
    temperatures of the iteration's last step, which the reported field differs from by the
    iteration's tolerance: tol_k = 1e-8 K here, |b| ΔT/T ≤ 5e-10. (At the default 1e-6 K the
    bound is 4e-8: the last step's |ΔT| landed at ~1e-8 K before the inlet cells heated the
    supply, 9.8e-10 measured, and at ~1e-6 K after, 2.4e-8 measured, 2026-12-05.)"""
    r = _bearing().thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=_power(),
                                       supply_temperature_c=45.0, model="thd", tol_k=1e-8)
    assert r.status == "ok"
    T, mu = np.asarray(r.temperature_c), np.asarray(r.viscosity_pa_s)
    assert T.shape == mu.shape and T.max() > 50.0  # a real rise above the 45 °C supply
    b = math.log(VG68["mu2_pa_s"] / VG68["mu1_pa_s"]) / math.log(100.0 / 40.0)
    a = VG68["mu1_pa_s"] / 40.0 ** b
    np.testing.assert_allclose(mu, a * T ** b, rtol=1e-8)


def test_power_law_oil_round_trips_through_the_model_file():
    """The compressor on plain bearings with its oil system (not the paper rig): the power-law
    oil written and read back equal; a rising law in the file names its TOML path; the
    system's thermal equilibrium runs on it."""
    import dataclasses
    import pathlib

    from rotordyn.analysis import system_thermal_equilibrium

    path = pathlib.Path(__file__).parent / "data" / "models" / "compressor_plain_thermal.toml"
    s0 = rotordyn.System.from_toml(path)
    s = dataclasses.replace(s0, thermal=dataclasses.replace(s0.thermal, oil=_power()))
    text = s.to_toml()
    assert 'viscosity_law = "power"' in text and "mu1_pa_s = 0.057" in text
    back = rotordyn.System.from_toml(text, is_text=True)
    assert back == s and back.thermal.oil.viscosity_law == "power"
    with pytest.raises(InputError, match=r"^thermal\.oil\."):
        rotordyn.System.from_toml(text.replace("mu2_pa_s = 0.00754", "mu2_pa_s = 0.5"),
                                  is_text=True)
    r = system_thermal_equilibrium(back, speed_hz=150.0)
    assert r.status == "ok"


def test_cli_oil_power_equals_python(capsys):
    import json

    from rotordyn.cli import main

    base = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
            "--n-circ", "36", "--n-axial", "8", "--speed-hz", "100", "--load-n", "0", "-5000",
            "--supply-temperature-c", "45"]
    assert main(base + ["--oil-power", "40", "0.057", "100", "0.00754", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    r = _bearing().thermal_equilibrium(load_n=(0.0, -5000.0), speed_hz=100.0, oil=_power(),
                                       supply_temperature_c=45.0)
    assert rec["thermal"]["effective_temperature_c"] == pytest.approx(
        r.effective_temperature_c, rel=1e-12)
    assert main(base + ["--oil-power", "40", "0.005", "100", "0.05"]) == 2
    assert "mu2_pa_s" in capsys.readouterr().err
    assert main(base + ["--oil-power", "40", "0.057", "100", "0.00754",
                        "--oil-walther", "40", "32", "100", "5.4"]) == 2
    assert "exactly one" in capsys.readouterr().err


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="mu2_pa_s"):  # rising with temperature
        _power(mu1_pa_s=0.005, mu2_pa_s=0.05)
    with pytest.raises(InputError, match="mu1_pa_s"):
        _power(mu1_pa_s=-0.01)
    with pytest.raises(InputError, match="t1_c"):  # T^b needs T > 0 °C
        _power(t1_c=0.0)
    with pytest.raises(InputError, match="t2_c"):
        _power(t2_c=30.0)
    with pytest.raises(InputError, match="t_min_c"):  # the range must stay above 0 °C
        Oil(viscosity_law="power", **VG68)  # default t_min_c = −20 °C
