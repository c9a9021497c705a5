"""The turbulent film's optional laminar-to-turbulent transition (issue 20; docs/film-physics.md
"Transition").

Model: between ``turbulence_onset_re`` and ``turbulence_full_re`` an intermittency weight
γ(Re_h) = t²(3 − 2t), t = (Re_h − onset)/(full − onset) (the cubic smoothstep: C1, γ' = 0 at
both ends; the ramp of the eddy viscosity in Suganami & Szeri, J. Lubr. Technol. 101 (1979)
21–27, as ROSS applies it over 500 < Re < 1000, is continuous but not C1) multiplies the
turbulent increments of the Ng–Pan–Elrod coefficients (Taylor & Dowson 1974 fits):
k_x = 12 + γ 0.0136 Re^0.90, k_z = 12 + γ 0.0043 Re^0.96, C_f = 1 + γ 0.0012 Re^0.94, and
the excess G − 1 of the THD walls' eddy-conductivity factors.

Checks: the closed forms of γ and the blended coefficients below, inside and above the ramp;
below the onset the laminar film (turbulence = "laminar") and above the full value today's
turbulent film, bit for bit, by a different code path (plain film, fixed-geometry lobes,
THD film with its walls); K, C against central differences of the force on a film whose Re_h
spans the ramp; the compressor of tests/data on plain bearings with a ramp its films straddle
(equilibrium between the laminar and the turbulent one, stability, TOML round trip, the onset
as a sweep axis); the CLI; bad input.
"""

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.bearings import FixedGeometryBearing, Oil
from rotordyn.errors import InputError
from rotordyn.sweep.paths import get_field, set_field

MODELS = Path(__file__).parent / "data" / "models"
RAMP = dict(turbulence_onset_re=1500.0, turbulence_full_re=4000.0)
ST = dict(x_m=1.5e-5, y_m=-5e-5, speed_hz=300.0)   # Re_h 1.29e3 ... 4.11e3 over the film


def _gamma(re, on, full):
    t = min(max((re - on) / (full - on), 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def _bearing(**kw):
    base = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.003,
                n_circ=36, n_axial=8, turbulence="ng_pan", density_kg_m3=860.0)
    return rotordyn.JournalBearing(**{**base, **kw})


@pytest.mark.parametrize("re", [0.0, 500.0, 1000.0, 1250.0, 2000.0, 2900.0, 3000.0, 1e4])
def test_weight_and_blended_coefficients_are_the_closed_forms(re):
    on, full = 1000.0, 3000.0
    g, rg = _core.turbulence_weight(re, on, full)
    assert g == pytest.approx(_gamma(re, on, full), rel=1e-15, abs=0.0)
    t = (re - on) / (full - on)
    assert rg == pytest.approx(re * 6.0 * t * (1.0 - t) / (full - on) if 0 < t < 1 else 0.0,
                               rel=1e-14, abs=0.0)
    got = _core.turbulence_factors("ng_pan", re, on, full)
    want = (12.0 + g * 0.0136 * re ** 0.90, 12.0 + g * 0.0043 * re ** 0.96,
            1.0 + g * 0.0012 * re ** 0.94)
    np.testing.assert_allclose(got, want, rtol=1e-15)
    if re <= on:        # exactly laminar
        assert got == (12.0, 12.0, 1.0)
    if re >= full:      # exactly today's turbulent coefficients
        assert got == _core.turbulence_factors("ng_pan", re)
    if re == 2000.0:    # t = 1/2: γ = 1/2, k_x = 12 + 0.0068 · 2000^0.9 = 18.36
        assert got[0] == pytest.approx(18.3597, abs=1e-4)


def test_wall_factors_take_the_weight():
    on, full, pr = 1000.0, 3000.0, 300.0
    assert _core.turbulent_wall_factors("ng_pan", 900.0, pr, on, full) == (1.0, 1.0)
    assert (_core.turbulent_wall_factors("ng_pan", 3500.0, pr, on, full)
            == _core.turbulent_wall_factors("ng_pan", 3500.0, pr))
    g = _gamma(1500.0, on, full)   # 0.15625
    gs, gc = _core.turbulent_wall_factors("ng_pan", 1500.0, pr)
    np.testing.assert_allclose(_core.turbulent_wall_factors("ng_pan", 1500.0, pr, on, full),
                               (1.0 + g * (gs - 1.0), 1.0 + g * (gc - 1.0)), rtol=1e-15)


def test_below_onset_laminar_and_above_full_turbulent_bit_for_bit():
    lam = _bearing(turbulence="laminar")
    below = _bearing(turbulence_onset_re=1e5, turbulence_full_re=2e5)
    turb = _bearing()
    above = _bearing(turbulence_onset_re=0.0, turbulence_full_re=1000.0)
    for a, b in ((below, lam), (above, turb)):
        ra, rb = a.solve(**ST), b.solve(**ST)
        assert np.array_equal(ra.force_n, rb.force_n)
        assert ra.friction_torque_n_m == rb.friction_torque_n_m
        for x, y in zip(a.coefficients(**ST), b.coefficients(**ST)):
            assert np.array_equal(x, y)
    # the ramp inside the film's range: neither
    mid = _bearing(**RAMP)
    f = [np.hypot(*b.forces(**ST)) for b in (lam, mid, turb)]
    assert f[0] < f[1] < f[2]
    # fixed-geometry lobes (pad_film path), two-axial-groove bearing
    fg = dict(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.003,
              n_circ=36, n_axial=8, density_kg_m3=860.0)
    fl = FixedGeometryBearing(**fg)
    fb = FixedGeometryBearing(**fg, turbulence="ng_pan", turbulence_onset_re=1e5,
                              turbulence_full_re=2e5)
    assert np.array_equal(fl.forces(**ST), fb.forces(**ST))


def test_thd_film_and_walls_below_onset_are_laminar_bit_for_bit():
    """The THD film (μ(T) per node, the walls' film coefficients with their eddy factors):
    with the ramp above every cell's Re_h, the laminar film's equilibrium exactly; with the
    ramp below every cell's, today's turbulent film exactly."""
    oil = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
              density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=0.13)
    big = dict(diameter_m=0.3, length_m=0.15, clearance_m=4.5e-4, viscosity_pa_s=0.02,
               n_circ=24, n_axial=6, density_kg_m3=870.0)
    run = dict(load_n=(0.0, -60e3), speed_hz=100.0, oil=oil, supply_temperature_c=45.0,
               model="thd", wall_htc="film", journal_wall="balance", bush_wall="conduction",
               bush_thickness_m=0.03, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=1000.0)

    def thd(**kw):
        r = rotordyn.JournalBearing(**big, **kw).thermal_equilibrium(**run)
        assert r.status == "ok", r.message
        return r

    for a, b in ((thd(turbulence="ng_pan", turbulence_onset_re=1e6, turbulence_full_re=2e6),
                  thd()),
                 (thd(turbulence="ng_pan", turbulence_onset_re=0.0, turbulence_full_re=1.0),
                  thd(turbulence="ng_pan"))):
        assert a.max_temperature_c == b.max_temperature_c
        assert a.heat_to_bush_w == b.heat_to_bush_w
        assert np.array_equal(a.K, b.K) and np.array_equal(a.C, b.C)


@pytest.mark.parametrize("cavitation", ["reynolds", "gumbel"])
def test_coefficients_match_finite_differences_inside_the_ramp(cavitation):
    """Re dk/dRe includes Re γ'(Re) a Re^b: K, C by perturbation equal central differences of
    the force (steps 1e-6 c, 1e-6 c|ω|) on a film whose faces span the ramp (Re_h 1.29e3 to
    4.11e3 over 1.5e3–4e3), to 1e-8 (K) and 1e-9 (C) of the largest entry (measured 1.3e-10
    and 4.6e-11; the ramp-free turbulent film: 1.8e-10, 2.0e-11)."""
    b = _bearing(cavitation=cavitation, **RAMP)
    Kp, Cp = b.coefficients(**ST)
    Kf, Cf = b.coefficients(**ST, method="finite_difference")
    np.testing.assert_allclose(Kp, Kf, atol=1e-8 * np.abs(Kf).max())
    np.testing.assert_allclose(Cp, Cf, atol=1e-9 * np.abs(Cf).max())
    # central differences of the force by hand, step 1e-10 m (the pressure-dam test's)
    d = 1e-10
    x, y, f = ST["x_m"], ST["y_m"], ST["speed_hz"]
    fd = np.column_stack([
        -(b.forces(x_m=x + d, y_m=y, speed_hz=f) - b.forces(x_m=x - d, y_m=y, speed_hz=f)) / (2 * d),
        -(b.forces(x_m=x, y_m=y + d, speed_hz=f) - b.forces(x_m=x, y_m=y - d, speed_hz=f)) / (2 * d)])
    np.testing.assert_allclose(Kp, fd, atol=1e-8 * np.abs(fd).max())


def _compressor(**kw):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, viscosity_pa_s=0.006, n_circ=36, n_axial=8, **kw)
        for b in s.bearings))


def test_compressor_with_a_ramp_equilibrium_stability_toml_and_sweep_axis():
    """The compressor of tests/data on plain bearings (μ = 6 mPa·s, ρ = 860 kg/m³, 250 Hz: Re_h
    at the clearance ≈ 1.1e3, the films' Re_h ≈ 0.85e3–1.4e3 at the equilibrium) with the ramp
    1000–1300 straddled by each film (faces laminar, on the ramp and fully turbulent): the
    journals sit between the laminar and the fully turbulent ones; stability runs; the fields
    survive the TOML round trip; the onset is a sweep axis, and moved above every film's Re_h
    it gives the laminar equilibrium exactly."""
    turb = dict(turbulence="ng_pan", density_kg_m3=860.0)
    lam, full = _compressor(), _compressor(**turb)
    ramp = _compressor(**turb, turbulence_onset_re=1000.0, turbulence_full_re=1300.0)
    e = [rotordyn.equilibrium(s, speed_hz=250.0) for s in (lam, ramp, full)]
    assert all(x.status == "ok" for x in e)
    ecc = [np.abs(np.asarray(x.r)[:4]).max() for x in e]
    assert ecc[2] < ecc[1] < ecc[0]
    st = rotordyn.stability(ramp, speed_hz=250.0)
    assert st.status == "ok"
    assert np.all(np.isfinite(np.asarray(rotordyn.linearize(ramp, speed_hz=250.0).K)))
    text = ramp.to_toml()
    assert "turbulence_onset_re = 1000.0" in text and "turbulence_full_re = 1300.0" in text
    assert rotordyn.System.from_toml(text, is_text=True).bearings == ramp.bearings
    s2 = set_field(ramp, "bearings.*.turbulence_full_re", 2e5)
    s2 = set_field(s2, "bearings.*.turbulence_onset_re", 1e5)
    assert get_field(s2, "bearings.*.turbulence_onset_re") == [1e5, 1e5]
    e2 = rotordyn.equilibrium(s2, speed_hz=250.0)
    assert e2.status == "ok" and np.array_equal(e2.r, e[0].r)
    with pytest.raises(InputError, match="turbulence_full_re"):
        set_field(ramp, "bearings.0.turbulence_onset_re", 1400.0)   # above the full value


@pytest.mark.parametrize("model, grid", [("compressor_tilting_pad.toml", dict(n_axial=6)),
                                         ("compressor_active.toml", dict(n_axial=8))])
def test_tilting_pad_and_active_bearings_carry_the_transition(model, grid):
    """The compressor on tilting pads, and with its active journal bearing (μ = 6 mPa·s,
    250 Hz): a ramp above every face gives the laminar equilibrium bit for bit (every pad's
    and the sleeve bearing's film takes the fields); the ramp 1000–1300 moves the journals
    away from both the laminar and the transition-free turbulent equilibrium."""
    s = rotordyn.System.from_toml(MODELS / model)

    def mk(**kw):
        return dataclasses.replace(s, bearings=tuple(
            dataclasses.replace(b, viscosity_pa_s=0.006, n_circ=36, **grid, **kw)
            for b in s.bearings))

    turb = dict(turbulence="ng_pan", density_kg_m3=860.0)
    r = [rotordyn.equilibrium(x, speed_hz=250.0) for x in (
        mk(), mk(**turb, turbulence_onset_re=1e6, turbulence_full_re=2e6),
        mk(**turb, turbulence_onset_re=1000.0, turbulence_full_re=1300.0), mk(**turb))]
    assert all(x.status == "ok" for x in r)
    assert np.array_equal(r[0].r, r[1].r)
    assert not np.allclose(r[2].r, r[0].r, rtol=1e-9, atol=0.0)
    assert not np.allclose(r[2].r, r[3].r, rtol=1e-9, atol=0.0)


def test_cli_prints_and_records_the_transition(capsys):
    from rotordyn.cli import main

    base = ["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
            "--viscosity-pa-s", "0.003", "--n-circ", "36", "--n-axial", "8", "--speed-hz",
            "300", "--x-m", "1.5e-5", "--y-m", "-5e-5", "--turbulence", "ng_pan",
            "--density-kg-m3", "860", "--turbulence-onset-re", "1500",
            "--turbulence-full-re", "4000"]
    assert main(base + ["--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["bearing"]["turbulence_onset_re"] == 1500.0
    assert rec["bearing"]["turbulence_full_re"] == 4000.0
    np.testing.assert_allclose(rec["force_n"], _bearing(**RAMP).forces(**ST), rtol=1e-12)
    assert main(base) == 0
    assert "transition Re_h 1500 to 4000" in capsys.readouterr().out
    assert main(base[:-2]) == 2
    assert "turbulence_full_re" in capsys.readouterr().err


@pytest.mark.parametrize("kw, field", [
    (dict(turbulence_onset_re=500.0), "turbulence_full_re"),
    (dict(turbulence_full_re=500.0), "turbulence_onset_re"),
    (dict(turbulence_onset_re=-1.0, turbulence_full_re=500.0), "turbulence_onset_re"),
    (dict(turbulence_onset_re=500.0, turbulence_full_re=500.0), "turbulence_full_re"),
    (dict(turbulence_onset_re=500.0, turbulence_full_re=math.inf), "turbulence_full_re"),
    (dict(turbulence_onset_re=math.nan, turbulence_full_re=500.0), "turbulence_onset_re"),
    (dict(turbulence="laminar", turbulence_onset_re=500.0, turbulence_full_re=1000.0),
     "turbulence_onset_re"),
])
def test_bad_input_names_the_field(kw, field):
    with pytest.raises(InputError, match=field):
        _bearing(**kw)
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    b = dataclasses.replace(s.bearings[0], **{"turbulence": "ng_pan", "density_kg_m3": 860.0,
                                              **kw})
    with pytest.raises(InputError, match=field):
        dataclasses.replace(s, bearings=(b, s.bearings[1]))
    g = _core.JournalBearingGeometry()
    g.turbulence, g.density_kg_m3 = kw.get("turbulence", "ng_pan"), 860.0
    g.turbulence_onset_re = kw.get("turbulence_onset_re", math.nan)
    g.turbulence_full_re = kw.get("turbulence_full_re", math.nan)
    with pytest.raises(InputError, match="turbulence_"):
        g.validate()
    # the core's functions check the pair too (no NaN from a half-given ramp)
    if "turbulence" not in kw:
        on, full = g.turbulence_onset_re, g.turbulence_full_re
        for call in (lambda: _core.turbulence_weight(100.0, on, full),
                     lambda: _core.turbulence_factors("ng_pan", 100.0, on, full),
                     lambda: _core.turbulent_wall_factors("ng_pan", 100.0, 300.0, on, full)):
            with pytest.raises(InputError, match=field):
                call()
