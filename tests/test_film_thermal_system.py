"""Effective-temperature thermal equilibrium of a system (issue 20): the compressor of
tests/data/models on two plain journal bearings.

The rotor on two bearings is statically determinate: each bearing carries its share of the
weight whatever its viscosity, so the system's thermal equilibrium must equal, bearing by
bearing, the standalone thermal equilibrium of that bearing under the load its film carries
(JournalBearing.thermal_equilibrium, itself checked against closed forms in
tests/test_film_thermal.py): temperatures to 1e-5 K, positions to 1e-6 of the clearance.
The returned system (viscosities at μ(T_eff), temperature frozen) linearises and its
stability runs; bad input names the field.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import Oil
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)


def _compressor():
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def test_system_thermal_equals_standalone_bearings():
    s = _compressor()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil=VG32,
                                              supply_temperature_c=45.0)
    assert res.status == "ok", res.message
    assert np.all(res.effective_temperature_c > 46.0)
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    assert e.status == "ok"
    for k, b in enumerate(s.bearings):
        jb = b.journal_bearing()
        # the load this bearing's film carries at the system's thermal equilibrium
        ff = np.asarray(e.film_force_n)
        bc = rotordyn.analysis.assembly.assembled(res.system).bearings[k]
        ld = (-ff[bc.jx], -ff[bc.jy])
        r = jb.thermal_equilibrium(load_n=ld, speed_hz=150.0, oil=VG32, supply_temperature_c=45.0)
        assert r.effective_temperature_c == pytest.approx(res.effective_temperature_c[k], abs=1e-5)
        assert r.power_loss_w == pytest.approx(res.power_loss_w[k], rel=1e-6)
        assert (r.x_m, r.y_m) == pytest.approx((res.journal_x_m[k], res.journal_y_m[k]),
                                               abs=1e-6 * b.clearance_m)
    df = res.to_frame()
    assert list(df["bearing"]) == list(res.bearing_names) and len(df) == 2
    assert rotordyn.stability(res.system, speed_hz=150.0).status == "ok"


def test_system_thermal_bad_input():
    s = _compressor()
    with pytest.raises(InputError, match="oil"):
        rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil="VG32",
                                            supply_temperature_c=45.0)
    with pytest.raises(InputError, match="supply_temperature_c"):
        rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil=VG32,
                                            supply_temperature_c=-60.0)
    # no film bearing at all (pad bearings take either model: test_thermal_pad_effective.py)
    lin = rotordyn.System.from_toml(MODELS / "compressor_linear.toml")
    with pytest.raises(InputError, match="^bearings: "):
        rotordyn.system_thermal_equilibrium(lin, speed_hz=150.0, oil=VG32,
                                            supply_temperature_c=45.0)


def test_cli_thermal_command(capsys):
    """``rotordyn thermal MODEL`` prints one row per plain bearing (``--json``: records) equal
    to the Python API's; a missing supply temperature exits 2 naming it."""
    import json

    from rotordyn.cli import main

    path = str(MODELS / "compressor_plain.toml")
    assert main(["thermal", path, "--speed-hz", "150", "--supply-temperature-c", "45",
                 "--oil-walther", "40", "32", "100", "5.4", "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, oil=VG32,
                                              supply_temperature_c=45.0)
    got = [b["effective_temperature_c"] for b in rec["bearings"]]
    np.testing.assert_allclose(got, res.effective_temperature_c, rtol=1e-12)
    assert main(["thermal", path, "--oil-walther", "40", "32", "100", "5.4"]) == 2
    assert "supply-temperature-c" in capsys.readouterr().err
