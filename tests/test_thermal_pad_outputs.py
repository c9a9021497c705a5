"""Every pad's state at a system's thermal equilibrium (SystemThermalResult.pads /
pads_frame(), `rotordyn thermal`'s pad table and JSON): the isothermal equilibrium's pad
outputs (pivot, tilt, peak pressure, minimum film, unloaded; tests/test_pad_outputs.py) at the
hot equilibrium, and each pad's temperatures, viscosity, power loss and fresh flow.

Checks: the pad outputs equal those of the isothermal equilibrium of the returned system
(which carries the frozen pad viscosities: its equilibrium is the thermal one, to 1e-6 c in
position, so the tilts agree to 1e-9 rad and the peak pressures to 1e-5 relative); the
thermal columns are the per-pad rows of to_frame() (exactly); on the turbo-generator
(tests/data/models/generator_tilting_pad.toml, 18.79 Hz) the top pads carry no pressure and
run coolest, the loaded bottom pads hottest; the THD film's pads on the compressor report
their mean, maximum and hottest surface; a failed equilibrium has no pad rows."""

import json
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
PAD_COLS = ["bearing", "pad", "pivot_deg", "tilt_rad", "p_max_pa", "h_min_m", "unloaded"]
THERMAL_COLS = ["effective_temperature_c", "max_temperature_c", "inlet_temperature_c",
                "temperature_rise_k", "viscosity_pa_s", "power_loss_w", "supply_flow_m3_s",
                "max_wall_temperature_c"]


@pytest.fixture(scope="module")
def gen():
    return rd.System.from_toml(MODELS / "generator_tilting_pad.toml")


@pytest.fixture(scope="module")
def gen_thermal(gen):
    return rd.system_thermal_equilibrium(gen, speed_hz=18.79)


def test_generator_pads_at_the_thermal_equilibrium(gen_thermal):
    r = gen_thermal
    assert r.status == "ok"
    df = r.pads_frame()
    assert list(df.columns) == PAD_COLS + THERMAL_COLS and len(df) == 10
    # the thermal columns are the per-pad film rows of to_frame (same order: pad films)
    rows = r.to_frame()
    for c in THERMAL_COLS[:-1]:
        np.testing.assert_array_equal(df[c].to_numpy(), rows[c].to_numpy())
    assert df.max_wall_temperature_c.isna().all()  # the effective model has no walls
    # the pad outputs are those of the returned (hot, frozen) system's own equilibrium
    iso = rd.equilibrium(r.system, 18.79).pads_frame()
    assert list(iso.bearing) == list(df.bearing) and list(iso.pivot_deg) == list(df.pivot_deg)
    np.testing.assert_allclose(df.tilt_rad, iso.tilt_rad, rtol=0, atol=1e-9)
    np.testing.assert_allclose(df.p_max_pa, iso.p_max_pa, rtol=1e-5, atol=1e-3)
    np.testing.assert_allclose(df.h_min_m, iso.h_min_m, rtol=1e-5)
    assert list(df.unloaded) == list(iso.unloaded)
    # the bearing's minimum film is its thinnest pad's
    for name in ("DE bearing", "NDE bearing"):
        d = df[df.bearing == name]
        own = [k for k, n in enumerate(r.bearing_names) if n.startswith(name.split()[0] + " ")]
        assert d.h_min_m.min() == pytest.approx(np.min(r.h_min_m[own]), rel=1e-12)
        # the hottest pad carries at least half the bearing's peak pressure; an unloaded pad
        # runs with the smallest rise
        assert d.p_max_pa[d.max_temperature_c.idxmax()] >= 0.5 * d.p_max_pa.max()
        assert d.unloaded[d.temperature_rise_k.idxmin()]
    # DE load between pads 306/234 deg: its top pad (90 deg) is pressure-free; NDE load on
    # the 270 deg pad: its two top pads (54, 126 deg) are
    assert set(df.pivot_deg[df.unloaded].astype(int)) == {90, 54, 126}


def test_cli_prints_and_records_the_pads(gen_thermal, capsys):
    model = str(MODELS / "generator_tilting_pad.toml")
    assert main(["thermal", model, "--speed-hz", "18.79", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    pads = out["pads"]
    assert len(pads) == 10 and set(pads[0]) == set(PAD_COLS + THERMAL_COLS)
    df = gen_thermal.pads_frame()
    np.testing.assert_allclose([p["max_temperature_c"] for p in pads], df.max_temperature_c,
                               rtol=1e-12)
    assert [p["unloaded"] for p in pads] == list(df.unloaded)
    assert main(["thermal", model, "--speed-hz", "18.79"]) == 0
    text = capsys.readouterr().out
    assert "p_max_pa" in text and "unloaded" in text and "pivot_deg" in text


def test_thd_pads_report_mean_max_and_wall():
    """The compressor on tilting pads with the THD film (72 x 6 pads, 150 Hz, adiabatic):
    each pad's mean ≤ its maximum, the hottest surface finite and no hotter than the film's
    maximum (the adiabatic film's surfaces take the film's temperature at the wall)."""
    import dataclasses

    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    th = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=72, n_axial=6)
                                              for b in s.bearings),
                            thermal=dataclasses.replace(th, model="thd"))
    r = rd.system_thermal_equilibrium(s, speed_hz=150.0)
    assert r.status == "ok" and r.thermal_model == "thd"
    df = r.pads_frame()
    assert len(df) == 10
    assert (df.effective_temperature_c < df.max_temperature_c).all()
    assert np.isfinite(df.max_wall_temperature_c).all()
    assert (df.max_wall_temperature_c <= df.max_temperature_c + 1e-9).all()
    np.testing.assert_array_equal(df.power_loss_w.to_numpy(), r.to_frame().power_loss_w)


def test_no_pad_rows_without_a_converged_equilibrium(gen):
    r = rd.system_thermal_equilibrium(gen, speed_hz=1e-3)  # too slow to float the rotor
    assert r.status not in ("ok", "contact")
    assert r.pads == {} and len(r.pads_frame()) == 0
    plain = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    p = rd.system_thermal_equilibrium(plain, speed_hz=100.0)
    assert p.status == "ok" and p.pads == {} and len(p.pads_frame()) == 0
