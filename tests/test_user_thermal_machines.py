"""Issue 20's film physics used end to end on a user's own machine (2026-12-05): a five-stage
compressor (1.34 m, 209 kg, Guyan on five masters) on 5-pad tilting-pad bearings with its
THD oil system (VG 46 at 50 degC), tilting journals, the DE housing misaligned by 0.2 mrad and
Ng-Pan films with a transition ramp (tests/data/models/compressor5_tilting_pad_thd.toml), and
the same rotor on plain bearings (compressor5_plain_thermal.toml, effective temperature).

What a user relies on, each with an assertion that can fail: the thermal equilibrium
converges with every pad above the supply temperature and a finite K, C of the frozen system
whose own equilibrium is the thermal one; the answer does not depend on what ran before; the
turbulence ramp's limits are the laminar and the fully turbulent film bit for bit; the CLI's
`thermal` JSON carries the pads and the tilt outputs, and a failed thermal point (a film past
the oil's t_max_c) is a status with exit 1, never a linearised row; bad input is an
InputError naming the field."""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"
TP = MODELS / "compressor5_tilting_pad_thd.toml"
PLAIN = MODELS / "compressor5_plain_thermal.toml"


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "rotordyn", *map(str, args)],
                          capture_output=True, text=True, timeout=300)


def _fingerprint(system, speed_hz=150.0):
    r = rd.system_thermal_equilibrium(system, speed_hz=speed_hz)
    st = rd.stability(r.system, speed_hz)
    return np.concatenate([r.r, r.max_temperature_c, np.sort_complex(st.eigenvalues).view(float)])


def test_tilting_pad_compressor_thermal_equilibrium_is_usable():
    s = rd.System.from_toml(TP)
    r = rd.system_thermal_equilibrium(s, speed_hz=150.0)
    assert r.status == "ok" and r.thermal_model == "thd"
    assert len(r.bearing_names) == 10  # five pads per bearing
    assert np.all(r.max_temperature_c > s.thermal.supply_temperature_c + 1.0)
    assert np.all(r.max_temperature_c < s.thermal.oil.t_max_c)
    assert np.all(r.power_loss_w > 0.0)
    # the frozen system's own equilibrium is the thermal one; its K, C are finite
    e = rd.equilibrium(r.system, 150.0)
    assert e.status == "ok"
    np.testing.assert_allclose(np.asarray(e.r), r.r, rtol=0, atol=1e-12)
    lm = rd.linearize(r.system, 150.0)
    assert np.all(np.isfinite(lm.KH)) and np.all(np.isfinite(lm.DH))
    st = rd.stability(r.system, 150.0)
    assert np.all(np.isfinite(st.eigenvalues)) and st.stable
    # tilt outputs: the misaligned DE pads carry a moment, the DE journal sits at ~ -theta
    de = [i for i, n in enumerate(r.bearing_names) if n.startswith("DE")]
    assert np.all(np.abs(np.asarray(r.tilt["film_moment_y_n_m"])[de]) > 0.1)
    np.testing.assert_allclose(np.asarray(r.tilt["journal_theta_y_rad"])[de], -2e-4, rtol=0.05)


def test_answers_do_not_depend_on_what_ran_before():
    tp, pl = rd.System.from_toml(TP), rd.System.from_toml(PLAIN)
    first = _fingerprint(tp)
    _fingerprint(pl)
    rd.campbell(pl, [100.0, 160.0], n_modes=4, thermal=True)
    np.testing.assert_array_equal(_fingerprint(tp), first)


def test_turbulence_ramp_limits_are_laminar_and_fully_turbulent_bit_for_bit():
    s = rd.System.from_toml(PLAIN)
    s = dataclasses.replace(s, thermal=None)

    def r_of(**kw):
        b = tuple(dataclasses.replace(x, viscosity_pa_s=0.004, **kw) for x in s.bearings)
        return np.asarray(rd.equilibrium(dataclasses.replace(s, bearings=b), 200.0).r)

    lam = r_of(turbulence="laminar", density_kg_m3=None, turbulence_onset_re=None,
               turbulence_full_re=None)
    full = r_of(turbulence_onset_re=None, turbulence_full_re=None)
    above = r_of(turbulence_onset_re=1e7, turbulence_full_re=2e7)  # Re_h ~ 1100 here
    below = r_of(turbulence_onset_re=0.0, turbulence_full_re=1e-6)
    ramp = r_of(turbulence_onset_re=500.0, turbulence_full_re=1500.0)
    np.testing.assert_array_equal(above, lam)
    np.testing.assert_array_equal(below, full)
    # the turbulent film is stiffer: the journal sits higher; the ramp lies between
    assert full[1] > ramp[1] > lam[1]


def test_cli_thermal_json_has_pads_and_tilt(tmp_path):
    p = _cli("thermal", TP, "--speed-hz", 150, "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert d["status"] == "ok" and d["thermal_model"] == "thd"
    rows = d["bearings"]
    assert len(rows) == 10
    assert all(r["max_temperature_c"] > 50.0 for r in rows)
    assert all("film_moment_y_n_m" in r for r in rows)
    assert len(d["pads"]) == 10


def test_failed_thermal_points_are_statuses_never_linearised(tmp_path):
    hot = tmp_path / "hot.toml"
    hot.write_text(PLAIN.read_text().replace("supply_temperature_c = 50.0",
                                             "supply_temperature_c = 197.0"))
    s = rd.System.from_toml(hot)
    with pytest.raises(rd.ConvergenceError, match="t_max_c"):
        rd.stability(s, 300.0, thermal=True)
    c = rd.campbell(s, [150.0, 300.0], n_modes=4, thermal=True)
    assert list(c.point_status) == ["error", "error"]
    assert np.all(np.isnan(c.to_frame().freq_hz))
    assert all("t_max_c" in m for m in c.point_message)
    p = _cli("campbell", hot, "--speeds-hz", "150,300", "--thermal", "--json")
    assert p.returncode == 1
    assert json.loads(p.stdout)["point_status"] == ["error", "error"]
    p = _cli("thermal", hot, "--speed-hz", 300)
    assert p.returncode == 1 and "t_max_c" in p.stderr


@pytest.mark.parametrize("old,new,field", [
    ("specific_heat_j_per_kg_k = 1950.0", "specific_heat_j_per_kg_k = -1950.0",
     "thermal.oil.specific_heat_j_per_kg_k"),
    ("nu2_mm2_s = 6.8", "nu2_mm2_s = 60.0", "thermal.oil.nu2_mm2_s"),
    ("config_theta_y_rad = 2.0e-4", "config_theta_y_rad = 5.0e-3", "config_theta_y_rad"),
    ("turbulence_full_re = 200.0", "turbulence_full_re = 20.0", "turbulence_full_re"),
    ("carry_over = 0.5", "carry_over = 0.5\ncarryover = 0.5", "thermal.carryover"),
])
def test_bad_input_names_the_field(tmp_path, old, new, field):
    text = PLAIN.read_text()
    assert old in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace(old, new, 1))
    with pytest.raises(rd.InputError, match=field.replace(".", r"\.")):
        rd.system_thermal_equilibrium(rd.System.from_toml(bad), speed_hz=150.0)
    p = _cli("thermal", bad, "--speed-hz", 150)
    assert p.returncode == 2 and field in p.stderr
