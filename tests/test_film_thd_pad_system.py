"""Thermo-hydrodynamic films of fixed-geometry and tilting-pad bearings in a system (issue 20;
docs/film-physics.md §"THD pad bearings"): the compressor of tests/data/models (not the paper
rig) with its oil system (compressor_plain_thermal.toml's ``[thermal]``, ``model = "thd"``,
the DE bearing with its own carry-over and metered supply flow) on fixed-geometry bearings
(two-axial-groove, three-lobe, pressure dam) and on two 5-pad tilting-pad bearings.

What is compared, and why the tolerances:
* the rotor on two bearings is statically determinate, so each bearing carries its share of the
  weight whatever its temperature field: the system's THD equilibrium equals, lobe by lobe, the
  standalone :meth:`FixedGeometryBearing.thermal_equilibrium` (tested on its own in
  tests/test_film_thd_pads.py) under the load its film carries, with that bearing's
  ``[[thermal.film]]`` options. Both iterate to max |ΔT| <= 1e-6 K by different outer loops
  (system Newton vs the bearing's own): temperatures to 1e-5 K, positions to 1e-6 c;
* the returned system carries the frozen fields: its equilibrium reproduces the thermal one
  (1e-6 c), its Campbell diagram at the thermal speed has the eigenvalues of its stability
  (the same linearisation, 1e-9 relative) and differs from the isothermal model's;
* its transient follows the linear model of the same frozen fields at small amplitude: a
  0.2 µm disturbance (0.2 % of the clearance) integrated to rtol 1e-8, atol 1e-13 m (at the
  default 1e-9 m the integration error alone is several % of so small a motion), 1 % of the
  peak (observed 0.08 % three-lobe, the difference falling with the amplitude: the nonlinear
  terms, not a mismatch of fields);
* ``[thermal] model = "thd"`` on a fixed-geometry model round-trips through the model file and
  gives the same answer bit for bit;
* the ``thermal`` sweep over a thermal field (the supply temperature on tilting pads; the DE
  bearing's carry-over on three-lobe bearings) gives, row by row (``<bearing>.pad<k>``,
  ``<bearing>.lobe<k>``), the direct calls (1e-9; same inputs, same C++ call).
Coarse grids (48 around × 6 axially per fixed-geometry bearing, 72 × 6 for the pads, i.e. 12
intervals per 60° pad): each test a second or two.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

import rotordyn
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import FixedGeometryBearing
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
SPEED = 150.0  # Hz


def _oil_system():
    th = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    return dataclasses.replace(th, model="thd")


def compressor_fixed(kind="three_lobe"):
    """The compressor on two fixed-geometry bearings of ``kind`` with the THD oil system."""
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    extra = {"dam_depth_m": 2e-4} if kind == "pressure_dam" else {}
    bs = tuple(FixedGeometryBearing(station=b.station, name=b.name, diameter_m=b.diameter_m,
                                    length_m=b.length_m, clearance_m=b.clearance_m,
                                    viscosity_pa_s=b.viscosity_pa_s, kind=kind, n_circ=48,
                                    n_axial=6, **extra) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs, thermal=_oil_system())


def compressor_tilting_pad():
    """The compressor on two 5-pad tilting-pad bearings with the THD oil system."""
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=72, n_axial=6) for b in s.bearings), thermal=_oil_system())


@pytest.mark.parametrize("kind", ["two_axial_groove", "three_lobe", "pressure_dam"])
def test_fixed_geometry_thd_system_equals_standalone_lobes_and_its_dynamics(kind):
    s = compressor_fixed(kind)
    th = s.thermal
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED)
    assert res.status == "ok", res.message
    assert res.thermal_model == "thd"
    n_lobes = {"two_axial_groove": 2, "three_lobe": 3, "pressure_dam": 2}[kind]
    assert res.bearing_names == tuple(f"{b.name}.lobe{k}" for b in s.bearings
                                      for k in range(n_lobes))
    # every lobe heats (the coolest three-lobe lobe rises 8.8 K since the hot oil passed on
    # is the lobe's own mass balance Q − Q_s, 2026-12-03; it rose > 10 K with the overstated
    # trailing-edge flux)
    assert np.all(res.max_temperature_c > th.supply_temperature_c + 5.0)
    e = rotordyn.equilibrium(res.system, speed_hz=SPEED)
    assert e.status == "ok"
    c = s.bearings[0].clearance_m
    np.testing.assert_allclose(e.r, res.r, atol=1e-6 * c)
    ff = np.asarray(e.film_force_n)
    asm = assembled(res.system)
    for k, b in enumerate(s.bearings):
        own = th.film(b.name)
        bc = asm.bearings[k]
        rows = [i for i, n in enumerate(res.bearing_names) if n.startswith(b.name + ".")]
        sa = b.thermal_equilibrium(
            load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=SPEED, oil=th.oil,
            supply_temperature_c=th.supply_temperature_c,
            carry_over=own.carry_over if own else th.carry_over,
            supply_flow_m3_s=own.supply_flow_m3_s if own else th.supply_flow_m3_s)
        assert sa.status == "ok"
        np.testing.assert_allclose(sa.max_temperature_c, res.max_temperature_c[rows], atol=1e-5)
        np.testing.assert_allclose(sa.mean_temperature_c, res.effective_temperature_c[rows],
                                   atol=1e-5)
        np.testing.assert_allclose(sa.power_loss_w, res.power_loss_w[rows], rtol=1e-6)
        for a, i in zip(sa.temperature_c, rows):
            np.testing.assert_allclose(a, res.temperature_c[i], atol=1e-5)
        assert (sa.x_m, sa.y_m) == pytest.approx((res.journal_x_m[rows[0]],
                                                  res.journal_y_m[rows[0]]), abs=1e-6 * c)
    # the DE bearing's metered supply flow (3e-4 m3/s) is shared by its lobes
    de = [i for i, n in enumerate(res.bearing_names) if n.startswith("DE bearing.")]
    assert res.supply_flow_m3_s[de].sum() == pytest.approx(3e-4, rel=1e-12)
    # stability and the Campbell diagram of the frozen fields: the same eigenvalues at the
    # thermal speed, and not those of the isothermal model (viscosity_pa_s = 0.018 Pa s)
    st = rotordyn.stability(res.system, speed_hz=SPEED)
    assert st.status == "ok"
    cb = rotordyn.campbell(res.system, [SPEED])
    assert np.all(np.asarray(cb.point_status) == "ok")
    ev = np.asarray(cb.eigenvalues[0])
    ev = ev[np.isfinite(ev)]  # (slots past the modes found are NaN)
    for lam in np.asarray(st.eigenvalues):  # every mode stability reports is in the diagram
        assert np.min(np.abs(ev - lam)) <= 1e-9 * abs(lam)
    iso = np.asarray(rotordyn.campbell(s, [SPEED]).eigenvalues[0])
    iso = iso[np.isfinite(iso)]
    assert max(np.min(np.abs(iso - lam)) for lam in ev) > 1e-2 * np.max(np.abs(ev))


@pytest.mark.parametrize("make", [compressor_fixed, compressor_tilting_pad],
                         ids=["three_lobe", "tilting_pad"])
def test_thd_transient_follows_the_linear_model_at_the_frozen_field(make):
    """The frozen fields reach the transient: a 0.2 µm disturbance of the THD equilibrium (the
    pads' tilts included) follows expm(A t) of the linear model at the same fields; the run
    starts from the THD equilibrium, not the isothermal one (> 2 µm away)."""
    s = make()
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED)
    assert res.status == "ok", res.message
    hot = res.system
    lm = rotordyn.linearize(hot, speed_hz=SPEED)
    np.testing.assert_allclose(lm.equilibrium.r, res.r, atol=1e-6 * s.bearings[0].clearance_m)
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    d = 0.2e-6
    tr = rotordyn.transient(hot, t_end_s=0.004, speed_hz=SPEED, disturbance_m=(d, 0.0), n_out=9,
                            rtol=1e-8, atol_m=1e-13)
    assert tr.status == "ok", tr.message
    np.testing.assert_allclose(tr.r[0, 0], res.r[0] + d, atol=1e-12)
    iso = rotordyn.equilibrium(s, speed_hz=SPEED)
    assert np.max(np.abs(iso.r[:n] - res.r[:n])) > 2e-6
    x0 = np.concatenate([tr.r[0] - lm.equilibrium.r, np.zeros(n)])
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - lm.equilibrium.r
    err = np.max(np.abs(dev[:, 0] - lin[:, 0])) / np.max(np.abs(lin[:, 0]))
    assert err < 0.01, err


def test_fixed_geometry_thd_model_file_round_trip_and_bad_input(tmp_path):
    s = compressor_fixed("three_lobe")
    p = tmp_path / "m.toml"
    s.to_toml(p)
    text = p.read_text()
    assert 'type = "fixed_geometry"' in text and 'model = "thd"' in text
    back = rotordyn.System.from_toml(p)
    assert back == s
    a = rotordyn.system_thermal_equilibrium(back, speed_hz=SPEED)
    b = rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED)
    np.testing.assert_array_equal(a.max_temperature_c, b.max_temperature_c)
    np.testing.assert_array_equal(a.r, b.r)
    # the effective model per lobe: its factor's range named
    for kw in ({}, {"bearings": [1]}):
        with pytest.raises(InputError, match=r"^effective_factor"):
            rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED, model="effective",
                                                effective_factor=0.2, **kw)
    with pytest.raises(InputError, match="carry_over"):
        rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED, carry_over=1.5)

def _sweep(tmp_path, s, grid):
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    s.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "s.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "thd-pads"\nmodel = "m.toml"\n'
                    f'analysis = "thermal"\nchunk_size = 2\n[grid]\n{grid}speed_hz = {SPEED}\n')
    res = run_sweep(spec, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    return sw.open(tmp_path / "o").frame


COLUMNS = ("effective_temperature_c", "max_temperature_c", "inlet_temperature_c",
           "power_loss_w", "film_flow_m3_s", "supply_flow_m3_s", "journal_x_m", "journal_y_m")


@pytest.mark.parametrize("make,axis,values", [
    (compressor_tilting_pad, "thermal.supply_temperature_c", (40.0, 55.0)),
    (compressor_fixed, "thermal.films.DE_bearing.carry_over", (0.1, 0.8)),
], ids=["tilting_pad.supply_temperature", "three_lobe.carry_over"])
def test_thermal_sweep_over_a_thermal_field_equals_direct_calls(tmp_path, make, axis, values):
    from rotordyn.sweep.paths import set_field

    s = make()
    fr = _sweep(tmp_path, s, f'"{axis}" = [{values[0]}, {values[1]}]\n')
    n_films = len(assembled(s).model.films)
    assert len(fr) == 2 * n_films and (fr["status"] == "ok").all()
    tmax = []
    for _, g in fr.groupby("point_id"):
        m = set_field(s, axis, float(g.iloc[0][axis]))
        r = rotordyn.system_thermal_equilibrium(m, speed_hz=SPEED)
        assert list(g["bearing"]) == list(r.bearing_names)
        for c in COLUMNS:
            np.testing.assert_allclose(g[c].to_numpy(), getattr(r, c), rtol=1e-9, atol=1e-15)
        tmax.append(r.max_temperature_c)
    # the axis reaches the film: hotter supply oil, or more hot oil carried over on the DE
    # bearing, runs its film hotter
    assert np.all(tmax[1][n_films // 2:] > tmax[0][n_films // 2:])


@pytest.mark.parametrize("make", [compressor_tilting_pad, compressor_fixed],
                         ids=["tilting_pad", "three_lobe"])
def test_cli_thermal_on_pad_and_lobe_bearings_equals_the_python_call(tmp_path, capsys, make):
    """``rotordyn thermal MODEL --speed-hz F`` on a model whose ``[thermal] model = "thd"``
    (and with the wall option given on the command line): one record per pad or lobe, the
    numbers of :func:`rotordyn.system_thermal_equilibrium` on the same inputs (1e-9)."""
    import json

    from rotordyn.cli import main

    s = make()
    path = tmp_path / "m.toml"
    s.to_toml(path)
    r = rotordyn.system_thermal_equilibrium(s, speed_hz=SPEED, bush_htc_w_m2k=500.0,
                                            supply_temperature_c=50.0)
    assert main(["thermal", str(path), "--speed-hz", str(SPEED), "--bush-htc-w-m2k", "500",
                 "--supply-temperature-c", "50", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "ok" and out["thermal_model"] == "thd"
    assert [row["bearing"] for row in out["bearings"]] == list(r.bearing_names)
    for col in ("max_temperature_c", "effective_temperature_c", "inlet_temperature_c",
                "power_loss_w", "film_flow_m3_s", "supply_flow_m3_s", "journal_y_m"):
        np.testing.assert_allclose([row[col] for row in out["bearings"]], getattr(r, col),
                                   rtol=1e-9)
    assert main(["thermal", str(path), "--speed-hz", str(SPEED)]) == 0
    text = capsys.readouterr().out
    assert "thermal model thd: ok" in text
    assert f"{r.bearing_names[0]}: T_max = " in text and "power loss" in text


@pytest.mark.parametrize("extra,option", [
    (["--model", "effective", "--effective-factor", "2"], "effective_factor"),
    (["--effective-factor", "0.7"], "--effective-factor"),   # THD: no effective temperature
    (["--carry-over", "1.5"], "carry_over"),
    (["--bush-htc-w-m2k", "-1"], "bush_htc_w_m2k"),
])
def test_cli_thermal_on_pads_bad_input_exits_2_naming_the_option(tmp_path, capsys, extra,
                                                                 option):
    from rotordyn.cli import main

    path = tmp_path / "m.toml"
    compressor_tilting_pad().to_toml(path)
    assert main(["thermal", str(path), "--speed-hz", str(SPEED), *extra]) == 2
    assert option in capsys.readouterr().err
