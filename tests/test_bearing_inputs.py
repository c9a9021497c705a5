"""Guards the bearing elements' input checks of issue 21 ("Resources and elements"), each with
the call as the issue writes it: an element ``name`` that is not a string, numbers given as
text, a CSV that is not UTF-8 or names a column twice, a coefficient table's own ``contact``
rows read back, pad and lobe arcs too short for a film, a tilting-pad table beyond the speed its
mapped pad grids allow, and a damper orbit too small to have coefficients. Each is an
InputError naming the field (never a ZeroDivisionError, a pybind11 TypeError, a UnicodeDecodeError
or a NaN with status ok)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.bearings import (FixedGeometryBearing, SqueezeFilmDamper, TableBearing,
                               TiltingPadBearing)

MODELS = Path(__file__).parent / "data" / "models"
BASE = dict(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.02)

ROTOR = """schema = "rotordyn/model/1"
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.1e11
poisson = 0.3
[rotor]
[[rotor.section]]
length_m = 0.5
outer_diameter_m = 0.05
material = "steel"
n_elements = 4
[[rotor.section]]
length_m = 0.5
outer_diameter_m = 0.05
material = "steel"
n_elements = 4
"""


@pytest.mark.parametrize("cls", [FixedGeometryBearing, TiltingPadBearing, SqueezeFilmDamper])
def test_element_name_must_be_text(cls):
    with pytest.raises(rd.InputError, match=r"\.name: expected a string, got 3"):
        cls(**BASE, name=3)


@pytest.mark.parametrize("kind", ["tilting_pad", "journal", "fixed_geometry", "table"])
def test_toml_bearing_name_must_be_text(kind):
    extra = ("speeds_hz = [10.0, 100.0]\nkxx_n_per_m = [1e7, 1e7]\nkyy_n_per_m = [1e7, 1e7]\n"
             if kind == "table" else
             "diameter_m = 0.05\nlength_m = 0.03\nclearance_m = 5e-5\nviscosity_pa_s = 0.02\n")
    text = ROTOR + f'[[bearing]]\ntype = "{kind}"\nstation = 1\n{extra}name = 3\n'
    with pytest.raises(rd.InputError, match=r"name: expected a string, got 3"):
        rd.System.from_toml(text, is_text=True)


@pytest.mark.parametrize("make", [
    lambda: rd.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                              viscosity_pa_s=0.02, n_circ=36, n_axial=8),
    lambda: FixedGeometryBearing(**BASE, n_circ=36, n_axial=8),
])
def test_coefficient_table_refuses_text_for_numbers(make):
    b = make()
    with pytest.raises(rd.InputError, match="speeds_hz: expected (a sequence of )?numbers"):
        b.coefficient_table("50", ("0", "-100"))
    with pytest.raises(rd.InputError, match="load_n: expected (a sequence of )?numbers"):
        b.coefficient_table([50.0], ("0", "-100"))
    with pytest.raises(rd.InputError, match="speeds_hz: expected (a sequence of )?numbers"):
        b.coefficient_table([True], (0.0, -100.0))


def test_csv_not_utf8_is_an_input_error(tmp_path):
    p = tmp_path / "t.csv"
    p.write_bytes("speed_hz,kxx_n_per_m,kyy_n_per_m,note\n10,1e7,1e7,caf\xe9\n"
                  .encode("latin-1"))
    with pytest.raises(rd.InputError, match="not UTF-8"):
        TableBearing.from_csv(p, station=0)


def test_csv_duplicated_column_is_refused(tmp_path):
    p = tmp_path / "t.csv"
    p.write_text("speed_hz,kxx_n_per_m,kyy_n_per_m,kxx_n_per_m\n10,1e7,1e7,2e7\n")
    with pytest.raises(rd.InputError, match="'kxx_n_per_m' more than once"):
        TableBearing.from_csv(p, station=0)


def test_coefficient_table_csv_with_contact_rows_reads_back(tmp_path):
    """CoefficientTable.to_csv writes every converged row, contact ones included; from_csv
    reads them (a contact row is a converged equilibrium with a thin film)."""
    b = rd.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.02,
                          n_circ=36, n_axial=8)
    t = b.coefficient_table([20.0, 50.0], (0.0, -2000.0))
    assert t.status == ("ok", "ok")
    p = tmp_path / "t.csv"
    text = t.to_csv().splitlines()
    text[1] = text[1].replace(",ok,", ",contact,")  # as a table with a thin-film row writes it
    p.write_text("\n".join(text) + "\n")
    tb = TableBearing.from_csv(p, station=0)
    np.testing.assert_allclose(tb.kxx_n_per_m, t.K[:, 0, 0], rtol=1e-9)
    text[2] = text[2].replace(",ok,", ",not_converged,")
    p.write_text("\n".join(text) + "\n")
    with pytest.raises(rd.InputError, match="row 2 .* has status 'not_converged'"):
        TableBearing.from_csv(p, station=0)


@pytest.mark.parametrize("arc", [5e-324, 0.01, 1e-9])
def test_tiny_pad_arc_names_the_arc(arc):
    with pytest.raises(rd.InputError, match="pad_arc_deg: expected an arc of more than"):
        TiltingPadBearing(**BASE, pad_arc_deg=arc)


def test_tiny_partial_arc_names_the_arc():
    with pytest.raises(rd.InputError, match="arc_deg: expected an arc of more than"):
        FixedGeometryBearing(**BASE, kind="partial_arc", arc_deg=1e-9)


def test_short_arc_that_fits_is_accepted():
    """The bound is the film's own (arc length > ~4π c), not an arbitrary minimum: a 5° pad
    of a bearing with c/R = 2e-3 is a valid (if odd) pad."""
    TiltingPadBearing(**BASE, n_pads=4, pad_arc_deg=5.0)


def test_tilting_pad_table_speed_limit_in_user_units():
    tp = TiltingPadBearing(**BASE, n_circ=36, n_axial=8)
    with pytest.raises(rd.InputError) as exc:
        tp.coefficient_table([1e6], (0.0, -100.0))
    msg = str(exc.value)
    assert msg.startswith("speeds_hz: expected |speed| <=") and "got 1000000.0" in msg
    assert "4e+06" not in msg  # never the internal, mapped speed


def test_damper_orbit_too_small_is_an_input_error():
    sfd = SqueezeFilmDamper(station=0, diameter_m=0.1, length_m=0.02, clearance_m=1e-4,
                            viscosity_pa_s=0.02)
    with pytest.raises(rd.InputError, match="eccentricity_ratio"):
        sfd.orbit_coefficients(eccentricity_ratio=5e-324, whirl_hz=50.0)
    r = sfd.orbit_coefficients(eccentricity_ratio=1e-6, whirl_hz=50.0)
    assert all(np.isfinite(x) for x in r.values())


# -- issue 18: ``modes`` on a model with bearing elements ---------------------------------------
def test_modes_refuses_a_system_with_bearings_and_points_to_stability():
    """ROSS's run_modal includes the bearings; ``rd.modes`` used to show the rotor without them,
    silently (345, 741 Hz … on a compressor on plain bearings). Now it refuses unless asked for
    the rotor alone, and says where the system's modes are."""
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    for call in (lambda: rd.modes(s, 100.0), lambda: rd.rotor_campbell(s, [10.0, 20.0])):
        with pytest.raises(rd.InputError, match="without_bearings: .*rotordyn.stability"):
            call()
    free = rd.modes(s, 100.0, without_bearings=True)
    bare = rd.modes(dataclasses.replace(s, bearings=()), 100.0)
    np.testing.assert_array_equal(free.eigenvalues, bare.eigenvalues)


def test_cli_modes_without_bearings_flag(capsys):
    from rotordyn.cli import main

    path = str(MODELS / "compressor_plain.toml")
    assert main(["modes", path]) == 2
    assert "without_bearings" in capsys.readouterr().err
    assert main(["modes", path, "--without-bearings", "--json"]) == 0
    # a bad speed is named first (it named the missing --without-bearings)
    assert main(["modes", path, "--speed-hz", "nan"]) == 2
    assert "speed_hz" in capsys.readouterr().err
    s = rd.System.from_toml(path)
    with pytest.raises(rd.InputError, match="^speeds_hz"):
        rd.rotor_campbell(s, [20.0, 10.0])


# -- issue 18: the model file keeps a disk's geometry ---------------------------------------
def test_disk_geometry_round_trips_and_a_toml_disk_may_give_only_geometry(tmp_path):
    steel = rd.STEEL
    d = rd.Disk.from_geometry(2, steel, width_m=0.07, outer_diameter_m=0.28,
                              inner_diameter_m=0.05, name="impeller 1")
    assert (d.outer_diameter_m, d.inner_diameter_m, d.width_m, d.material) == \
        (0.28, 0.05, 0.07, "steel")
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    s2 = dataclasses.replace(s, rotor=rd.Rotor(s.rotor.sections, (d,)))
    text = s2.to_toml()
    assert "outer_diameter_m = 0.28" in text and 'name = "impeller 1"' in text
    assert rd.System.from_toml(text, is_text=True) == s2  # to_toml dropped the geometry
    only = text.replace(f"mass_kg = {d.mass_kg!r}\n", "").replace(
        f"ip_kg_m2 = {d.ip_kg_m2!r}\n", "").replace(f"id_kg_m2 = {d.id_kg_m2!r}\n", "")
    assert "mass_kg" not in only.split("[[disk]]")[1].split("[")[0]
    back = rd.System.from_toml(only, is_text=True).rotor.disks[0]
    assert back.mass_kg == pytest.approx(d.mass_kg, rel=1e-12)
    with pytest.raises(rd.InputError, match=r"disk\[0\]: expected mass_kg.*missing"):
        rd.System.from_toml(only.replace("width_m = 0.07\n", ""), is_text=True)
    with pytest.raises(rd.InputError, match="inner_diameter_m: expected a value below"):
        rd.Disk.from_geometry(2, steel, width_m=0.07, outer_diameter_m=0.2,
                              inner_diameter_m=0.3)


def test_table_speeds_in_the_analyses_range():
    with pytest.raises(rd.InputError, match=r"speeds_hz: expected speeds in \[-100000, 100000\]"):
        TableBearing(station=0, speeds_hz=(-1e7, 0.0), kxx_n_per_m=(1e7, 1e7),
                     kyy_n_per_m=(1e7, 1e7))
