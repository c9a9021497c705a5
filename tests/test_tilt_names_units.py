"""One output vocabulary for a tilted journal and one definition of the 4×4 units (issue 20).

Names: the standalone results (``tilted_forces``, ``misaligned_equilibrium`` of plain and
tilting-pad bearings, the tilted thermal equilibria) carry the journal's tilt and the film's
moments under the names of the system's equilibrium (``EquilibriumResult.tilt``), the sweep
rows and the thermal frames — ``journal_theta_x_rad``, ``journal_theta_y_rad``,
``film_moment_n_m`` (field) / ``film_moment_x_n_m``, ``film_moment_y_n_m`` (columns) — so a
standalone frame and a system table join on them; before 2026-12-05 the standalone names
were ``theta_*_rad``, ``moment_n_m``, ``moment_*_n_m`` (now read-only aliases that warn).

Units: the 4×4 K, C units over (x, y, θx, θy) come from one definition
(``rotordyn.units.TILT_UNIT_STEMS``): the coefficient frame's column suffixes, the report's
headers and ``rotordyn bearing``'s ``k_4x4_units``; each is force or moment over translation
or rotation (closed form below). Before, the three were written out separately, and
``unit_of`` read the coupling columns' suffix ``_n_per_rad`` as "rad".

Model: the compressor of tests/data/models on plain bearings with ``tilt = true``, the DE
housing misaligned by 0.3 mrad about y (not the paper rig), 36 × 8."""

import dataclasses
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn
from rotordyn.analysis.bearing_coefficients import TILT_COLUMNS
from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_forces
from rotordyn.bearings.tilt_pads import pad_tilted_forces
from rotordyn.cli import main
from rotordyn.errors import RotordynDeprecationWarning
from rotordyn.report.tables import _tilt_cells
from rotordyn.units import TILT_UNIT_STEMS, tilt_units, unit_of

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0
NAMES = {"journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
         "film_moment_y_n_m"}
OLD = {"theta_x_rad", "theta_y_rad", "moment_x_n_m", "moment_y_n_m"}


def _compressor():
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    bs = [dataclasses.replace(b, tilt=True, n_circ=36, n_axial=8) for b in s.bearings]
    bs[1] = dataclasses.replace(bs[1], config_theta_y_rad=3e-4)
    return dataclasses.replace(s, bearings=tuple(bs))


def test_standalone_frames_join_the_system_equilibrium_on_the_names():
    s = _compressor()
    e = rotordyn.equilibrium(s, F_HZ)
    assert e.status == "ok"
    sys_rows = pd.DataFrame([{"bearing": s.bearings[i].name, **e.tilt[i]} for i in e.tilt])
    assert NAMES <= set(sys_rows)
    frames = []
    for i, b in enumerate(s.bearings):
        t = e.tilt[i]
        f = tilted_forces(b, x_m=e.journal_x_m[i], y_m=e.journal_y_m[i], speed_hz=F_HZ,
                          theta_x_rad=t["journal_theta_x_rad"],
                          theta_y_rad=t["journal_theta_y_rad"]).to_frame()
        assert NAMES - {"journal_theta_x_rad", "journal_theta_y_rad"} <= set(f)
        assert not OLD & set(f)
        f["bearing"] = b.name
        frames.append(f)
    joined = sys_rows.merge(pd.concat(frames), on="bearing", suffixes=("", "_standalone"))
    for c in ("film_moment_x_n_m", "film_moment_y_n_m"):  # the same film at the same pose
        np.testing.assert_allclose(joined[f"{c}_standalone"], joined[c], rtol=1e-9,
                                   atol=1e-9 * np.abs(joined[c]).max())
    m = misaligned_equilibrium(s.bearings[1], load_n=(0.0, -500.0), speed_hz=F_HZ,
                               theta_y_rad=3e-4).to_frame()
    assert NAMES <= set(m) and not OLD & set(m)


def test_pad_and_thermal_frames_use_the_names():
    pads = dataclasses.replace(
        rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings[0],
        n_circ=24, n_axial=4)
    f = pad_tilted_forces(pads, x_m=0.0, y_m=-2e-5, speed_hz=F_HZ, theta_y_rad=2e-4)
    fr = f.to_frame()
    assert {"film_moment_x_n_m", "film_moment_y_n_m"} <= set(fr) and not OLD & set(fr)
    oil = rotordyn.bearings.Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0,
                                nu2_mm2_s=5.4, density_kg_m3=870.0,
                                specific_heat_j_per_kg_k=2000.0)
    for b, load in ((pads, (0.0, -1500.0)), (_compressor().bearings[0], (0.0, -4000.0))):
        r = b.thermal_equilibrium(load_n=load, speed_hz=F_HZ, oil=oil, model="effective",
                                  supply_temperature_c=45.0, theta_y_rad=2e-4)
        fr = r.to_frame()
        assert NAMES <= set(fr) and not OLD & set(fr)
        assert fr["journal_theta_y_rad"].iloc[0] == r.journal_theta_y_rad == 2e-4
        assert fr["film_moment_x_n_m"].iloc[0] == r.film_moment_n_m[0]


def test_former_field_names_are_aliases_that_warn():
    b = _compressor().bearings[0]
    e = misaligned_equilibrium(b, load_n=(0.0, -500.0), speed_hz=F_HZ, theta_y_rad=2e-4)
    with pytest.warns(RotordynDeprecationWarning, match="journal_theta_y_rad"):
        assert e.theta_y_rad == e.journal_theta_y_rad == 2e-4
    with pytest.warns(RotordynDeprecationWarning, match="film_moment_n_m"):
        assert e.moment_n_m is e.film_moment_n_m
    with pytest.raises(AttributeError, match="no attribute 'moment_z_n_m'"):
        e.moment_z_n_m  # noqa: B018 (only the renamed names are aliases)
    assert dataclasses.replace(e, status="ok") == e  # the dataclass machinery is unchanged


def test_4x4_units_have_one_definition():
    force = {0: "N", 1: "N·m"}  # rows: forces Fx, Fy; moments Mx, My
    coord = {0: "m", 1: "rad"}  # columns: translations x, y; rotations θx, θy
    for kind, per in (("k", ""), ("c", "·s")):
        U = tilt_units(kind)
        for i in range(4):
            for j in range(4):
                assert U[i][j] == f"{force[i // 2]}{per}/{coord[j // 2]}", (kind, i, j)
    # the coefficient frame's columns: their suffix names the same unit
    for col in TILT_COLUMNS:
        kind, rest = col[0], col[1:]
        q = ("x", "y", "tx", "ty")
        i, j = next((a, b) for a in range(4) for b in range(4)
                    if rest.startswith(q[a] + q[b] + "_") and (a >= 2 or b >= 2))
        assert col.endswith("_" + TILT_UNIT_STEMS[kind][i // 2][j // 2])
        assert unit_of(col) == tilt_units(kind)[i][j], col
    # the report's headers: its scale's prefix on the same unit
    for col, header, scale in _tilt_cells():
        kind = col[0]
        prefix = {1e3: "k", 1.0: ""}[scale]
        assert header.endswith(f"({prefix}{unit_of(col)})"), (col, header)


def test_cli_4x4_units_are_the_definition(capsys):
    assert main(["bearing", "--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m",
                 "1e-4", "--viscosity-pa-s", "0.02", "--n-circ", "24", "--n-axial", "4",
                 "--speed-hz", "100", "--x-m", "0", "--y-m", "-3e-5", "--theta-y-rad", "2e-4",
                 "--json"]) == 0
    r = json.loads(capsys.readouterr().out)
    assert r["k_4x4_units"] == tilt_units("k") and r["c_4x4_units"] == tilt_units("c")
    assert {"journal_theta_x_rad", "journal_theta_y_rad", "film_moment_n_m"} <= set(r)
    assert "moment_n_m" not in r
