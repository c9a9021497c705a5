"""The films' moments on a tilted journal as outputs (issue 20: "the sweep machinery, the
report and the CLI show the new outputs (… edge film, moments)").

Checks, on the compressor of tests/data/models (not the paper rig) on plain bearings with
`tilt = true` and housings misaligned, and on its 5-pad tilting-pad bearings:
* `EquilibriumResult.tilt[i]["film_moment_x_n_m"/"_y_"]` (and the columns of `to_frame()`)
  equal the standalone film's moments (`tilted_forces`) at the equilibrium's journal pose
  relative to the housing (1e-9), and change sign with the misalignment;
* the equilibrium sweep's rows carry NaN moments for an untilted film (the tilted rows:
  tests/test_film_tilt_system.py);
* `rotordyn equilibrium` prints the columns; the report's film table has the edge film and
  the moments.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.bearings.tilt import tilted_forces
from rotordyn.cli import main
from rotordyn.sweep import run_sweep

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0
AL = 3e-4  # rad: housing misalignment about y, α L/2 = 0.075 c


def compressor(tilt=True, **fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=tilt, n_circ=48, n_axial=12, **fields)
        for b in s.bearings))


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_equilibrium_moments_are_the_standalone_films(sign):
    s = compressor(config_theta_y_rad=sign * AL)
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    assert e.status == "ok", e.message
    fr = e.to_frame()
    for i, b in enumerate(s.bearings):
        t = e.tilt[i]
        ref = tilted_forces(b.journal_bearing(), x_m=e.journal_x_m[i], y_m=e.journal_y_m[i],
                            speed_hz=F_HZ, theta_x_rad=t["journal_theta_x_rad"],
                            theta_y_rad=t["journal_theta_y_rad"])
        got = np.array([t["film_moment_x_n_m"], t["film_moment_y_n_m"]])
        np.testing.assert_allclose(got, ref.film_moment_n_m, rtol=1e-9,
                                   atol=1e-9 * np.abs(ref.film_moment_n_m).max())
        assert abs(got).max() > 0.01  # N·m: the misaligned films carry a moment
        assert fr.loc[i, "film_moment_x_n_m"] == t["film_moment_x_n_m"]
        assert fr.loc[i, "film_moment_y_n_m"] == t["film_moment_y_n_m"]
    if sign < 0:  # the opposite misalignment: the moment about y changes sign
        ep = rotordyn.equilibrium(compressor(config_theta_y_rad=AL), speed_hz=F_HZ)
        assert np.sign(ep.tilt[0]["film_moment_y_n_m"]) == -np.sign(e.tilt[0]["film_moment_y_n_m"])


def test_tilting_pad_moments_are_reported():
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6, tilt=True, config_theta_y_rad=AL)
        for b in s.bearings))
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    assert e.status == "ok"
    for i in (0, 1):
        m = np.array([e.tilt[i]["film_moment_x_n_m"], e.tilt[i]["film_moment_y_n_m"]])
        assert np.all(np.isfinite(m)) and abs(m).max() > 0.01


def test_untilted_sweep_rows_have_no_moments(tmp_path):
    """(The tilted rows equal the direct calls: tests/test_film_tilt_system.py's sweep over
    the misalignment checks the moment columns with the other tilt columns.)"""
    # untilted films: NaN (not applicable), not 0
    s0 = compressor(tilt=False)
    s0.to_toml(tmp_path / "m0.toml")
    p0 = tmp_path / "s0.toml"
    p0.write_text('schema = "rotordyn/sweep/1"\nname = "flat"\nmodel = "m0.toml"\n'
                  'analysis = "equilibrium"\n[grid]\nspeed_hz = [100.0, 150.0]\n')
    assert run_sweep(p0, tmp_path / "o0", threads=1).complete
    f0 = sw.open(tmp_path / "o0").frame
    assert f0["film_moment_x_n_m"].isna().all() and (f0["status"] == "ok").all()


def test_cli_equilibrium_prints_the_moments(tmp_path, capsys):
    compressor(config_theta_y_rad=AL).to_toml(tmp_path / "m.toml")
    assert main(["equilibrium", str(tmp_path / "m.toml"), "--speed-hz", "150", "--json"]) == 0
    import json

    out = json.loads(capsys.readouterr().out)
    text = json.dumps(out)
    assert "film_moment_x_n_m" in text and "film_moment_y_n_m" in text


def test_report_film_table(tmp_path):
    from rotordyn.report.films import film_frame, film_text_lines

    from rotordyn.analysis.bearing_coefficients import bearing_coefficients

    def frame(system, speeds):
        eqs: list = []
        bearing_coefficients(system, speeds, equilibria=eqs)
        return film_frame(system, eqs)

    s = compressor(config_theta_y_rad=AL)
    fr = frame(s, [60.0, 150.0])
    assert list(fr["bearing"]) == ["NDE bearing", "DE bearing"] * 2
    e = rotordyn.equilibrium(s, speed_hz=150.0)
    row = fr[(fr["speed_hz"] == 150.0) & (fr["bearing"] == "NDE bearing")].iloc[0]
    assert row["h_min_m"] == pytest.approx(e.h_min_m[0], rel=1e-9)
    assert row["film_moment_y_n_m"] == pytest.approx(e.tilt[0]["film_moment_y_n_m"], rel=1e-9)
    assert abs(row["h_min_z_m"]) == pytest.approx(s.bearings[0].length_m / 2)
    text = "\n".join(film_text_lines(fr, {b_.name: b_.length_m for b_ in s.bearings}))
    assert "edge" in text and "M_y (N·m)" in text
    # untilted films: the table keeps h_min and drops the tilt columns
    fu = frame(compressor(tilt=False), [150.0])
    assert fu["h_min_m"].notna().all() and "film_moment_y_n_m" not in fu
    assert isinstance(fu, pd.DataFrame)


def test_report_tables_mark_a_missing_value_alike():
    """The film table of a failed speed and the thermal table's missing values print the one
    marker of the report's tables (rotordyn.report.tables.MISSING, "n/a"); the film table
    printed "–" where the thermal and coefficient tables print "n/a"."""
    from rotordyn.report.films import film_frame, film_text_lines
    from rotordyn.report.tables import MISSING
    from rotordyn.report.thermal import thermal_rows

    s = compressor(config_theta_y_rad=AL)
    fr = film_frame(s, [(150.0, "no_equilibrium", None)])
    body = film_text_lines(fr, {b_.name: b_.length_m for b_ in s.bearings})[3:]
    assert len(body) == 2 and "–" not in "".join(body)
    for line in body:  # ε, h_min, φ, z, tilt, M_x, M_y: missing; the status kept
        assert line.split().count(MISSING) == 7 and line.rstrip().endswith("no_equilibrium")
    nan = float("nan")
    th = pd.DataFrame([dict(bearing="NDE bearing", speed_hz=150.0, max_temperature_c=nan,
                            effective_temperature_c=nan, inlet_temperature_c=nan,
                            power_loss_w=nan, film_flow_m3_s=nan, supply_flow_m3_s=nan,
                            journal_y_m=nan, h_min_m=nan, status="no_equilibrium")])
    assert thermal_rows(th)[0][2:-1] == (MISSING,) * 8
