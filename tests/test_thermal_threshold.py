"""Which way a thermal film moves the onset of instability (issue 20), on the three-impeller
compressor on two plain journal bearings (tests/data/models/compressor_plain_thermal.toml,
36 x 8 grid; not the paper rig), against the isothermal film at the supply temperature (45 °C,
μ = 0.0224 Pa s).

Expectation: the films run hotter than the supply oil (T_eff 61-77 °C at 100-150 Hz), so
μ(T_eff) lies below μ(45 °C) in both bearings. For this flexible rotor the isothermal
threshold speed *rises* with μ (measured here as the premise: 122.7 Hz at 0.008 Pa s,
124.5 Hz at 0.012 Pa s, 127.0 Hz at 0.0224 Pa s; docs/calibration/compressor_thermal_dynamics.py),
so the thermal threshold must lie *below* the
isothermal one at the supply temperature, and the stability margin near the threshold is
smaller (a less negative max Re λ). That is not the rigid-rotor rule "thinner oil, more
eccentric, more stable": the test checks the direction this rotor's own isothermal trend
predicts.

Independent check (effective-temperature model): the thermal point is the isoviscous film
at μ(T_eff) (docs/film-physics.md), so (1) the eigenvalues at a speed equal those of the
isothermal model whose bearings' viscosity_pa_s is set by hand to the oil law μ(T_eff) of
each film (Python's Oil.viscosity_pa_s, not the frozen system the thermal call returns;
tolerance 1e-9 relative: T_eff converged to 1e-6 K changes μ by 2e-8 at most); (2) the
isothermal threshold speed of the model frozen at μ(T_eff(f_th)) — found by
rotordyn.threshold's own scan and Brent refinement — equals the thermal threshold f_th
(found by Brent's method on the thermal max Re λ) to 1e-6 Hz (both refined to 1e-7 Hz).
Measured: eigenvalues equal bit for bit; f_th = 123.975 Hz (T_eff 63.9 and 71.5 °C, μ 0.0115
and 0.0092 Pa s) against 126.993 Hz isothermal at 45 °C; |f1 - f_th| = 7.7e-10 Hz;
max Re λ at 120 Hz -6.10 1/s thermal against -8.72 1/s isothermal at 45 °C.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def compressor():
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def _iso(s, mus):
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, viscosity_pa_s=float(m)) for b, m in zip(s.bearings, mus)))


def _mu_eff(s, t):
    return [s.thermal.oil.viscosity_pa_s(float(x)) for x in t.effective_temperature_c]


def test_thermal_point_is_the_isoviscous_film_at_mu_of_t_eff(compressor):
    s = compressor
    for f in (100.0, 150.0):
        th = rd.stability(s, f, thermal=True)
        iso = rd.stability(_iso(s, _mu_eff(s, th.thermal)), f, warm_start=False)
        np.testing.assert_allclose(th.eigenvalues, iso.eigenvalues, rtol=1e-9)
        assert th.thermal.effective_temperature_c.min() > s.thermal.supply_temperature_c + 10


def test_thermal_threshold_below_the_supply_temperature_one(compressor):
    s = compressor
    oil, t_s = s.thermal.oil, s.thermal.supply_temperature_c
    mu_s = oil.viscosity_pa_s(t_s)
    # premise: this rotor's isothermal threshold rises with the viscosity
    f0 = rd.threshold(_iso(s, [mu_s] * 2), "speed_hz", bounds=(100.0, 150.0), xtol=1e-7)
    f_thin = rd.threshold(_iso(s, [0.012] * 2), "speed_hz", bounds=(100.0, 150.0), xtol=1e-7)
    assert f0.status == f_thin.status == "ok"
    assert f_thin.value < f0.value - 1.0
    # the thermal threshold: Brent on the thermal max Re λ
    f_th = brentq(lambda f: rd.stability(s, f, thermal=True).max_real_1_per_s, 110.0, 140.0,
                  xtol=1e-7)
    t = rd.system_thermal_equilibrium(s, speed_hz=f_th)
    mus = _mu_eff(s, t)
    assert max(mus) < mu_s  # hotter films, thinner oil in both bearings
    assert f_th < f0.value - 1.0  # the direction (measured 3.0 Hz below)
    # independent: the isothermal threshold of the model frozen at μ(T_eff(f_th))
    f1 = rd.threshold(_iso(s, mus), "speed_hz", bounds=(110.0, 140.0), xtol=1e-7)
    assert f1.status == "ok"
    assert f1.value == pytest.approx(f_th, abs=1e-6)
    # the stability margin just below the threshold: smaller with the thermal film
    m_th = rd.stability(s, 120.0, thermal=True).max_real_1_per_s
    m_iso = rd.stability(_iso(s, [mu_s] * 2), 120.0, warm_start=False).max_real_1_per_s
    assert m_iso < m_th < 0.0


def test_threshold_takes_thermal_true_like_stability(compressor):
    """``thermal=True`` (the model's ``[thermal]`` as it is) is accepted by ``threshold`` as by
    ``stability``, ``campbell`` and ``unbalance_response`` (before: an InputError "expected
    None or a dict", so the call the docs pair with ``stability(..., thermal=True)`` failed);
    it is the empty dict's answer bit for bit, and ``False`` the isothermal one.

    Each found speed is checked where it is defined, not against a number read from the
    output: the max Re λ of its own kind (thermal, each point at its thermal equilibrium;
    isothermal) is < 0 at ``value - D`` and > 0 at ``value + D``, D = 2 xtol (the refined
    bracket). Direction: both films run hotter than the oil the bearings' own 0.018 Pa s stands
    for (μ(T_eff) below it at the thermal threshold), and this rotor's threshold rises with μ
    (the premise checked above), so the thermal threshold lies below the isothermal one."""
    xtol = 1e-3
    kw = dict(bounds=(120.0, 130.0), n_scan=3, xtol=xtol)
    a = rd.threshold(compressor, "speed_hz", thermal=True, **kw)
    b = rd.threshold(compressor, "speed_hz", thermal={}, **kw)
    assert a.status == "ok" and a.value == b.value
    iso = rd.threshold(compressor, "speed_hz", thermal=False, **kw)
    # (the isothermal scan continues equilibria warm from the process's last state: the same
    # threshold to round-off, observed 1.5e-12 Hz)
    assert iso.value == pytest.approx(rd.threshold(compressor, "speed_hz", **kw).value,
                                      rel=1e-12)
    d = 2 * xtol

    def thermal_re(f):
        return rd.stability(compressor, f, thermal=True).max_real_1_per_s

    def iso_re(f):
        return rd.stability(compressor, f, warm_start=False).max_real_1_per_s

    assert thermal_re(a.value - d) < 0.0 < thermal_re(a.value + d)
    assert iso_re(iso.value - d) < 0.0 < iso_re(iso.value + d)
    t = rd.system_thermal_equilibrium(compressor, speed_hz=a.value)
    assert max(_mu_eff(compressor, t)) < min(b.viscosity_pa_s for b in compressor.bearings)
    assert a.value < iso.value - 1.0  # measured 2.6 Hz below


def test_threshold_with_a_failed_thermal_point_is_a_row_not_a_crash(compressor, monkeypatch):
    """A scan point whose thermal equilibrium returns a status other than ok/contact (e.g.
    "not_converged": the fixed point did not settle) is a failed row (NaN, status "thermal
    not_converged", ``stable`` NA) and the scan goes on; before, its 3-tuple against the
    4-value unpacking raised ValueError out of ``rd.threshold``. The failure is injected (a
    real one needs a case where the thermal iteration cycles)."""
    import sys
    import types

    thr = sys.modules["rotordyn.analysis.threshold"]  # (the package's name is the function)

    real = thr.thermal_point

    def failing(system, speed_hz, *a, **k):
        if speed_hz > 127.0:
            return types.SimpleNamespace(status="not_converged", system=system)
        return real(system, speed_hz, *a, **k)

    monkeypatch.setattr(thr, "thermal_point", failing)
    r = rd.threshold(compressor, "speed_hz", bounds=(100.0, 130.0), n_scan=3, thermal=True)
    sc = r.scan
    bad = sc[sc["speed_hz"] > 127.0]
    assert len(bad) == 1 and bad["status"].iloc[0] == "thermal not_converged"
    assert np.isnan(bad["max_real_1_per_s"].iloc[0]) and bad["stable"].isna().all()
    assert sc["stable"].notna().sum() == 2


def test_threshold_refuses_a_thermal_keyword_of_the_other_model(compressor):
    """A THD-only keyword with the model's effective-temperature films is bad input named as
    ``thermal.<key>`` (as ``rd.stability(..., thermal=...)``), not a failed point at every
    scanned value ("no_equilibrium")."""
    with pytest.raises(rd.InputError, match=r"^thermal\.journal_htc_w_m2k"):
        rd.stability(compressor, 120.0, thermal={"journal_htc_w_m2k": 10.0})
    with pytest.raises(rd.InputError, match=r"^thermal\.journal_htc_w_m2k"):
        rd.threshold(compressor, "speed_hz", bounds=(100.0, 130.0), n_scan=3,
                     thermal={"journal_htc_w_m2k": 10.0})
