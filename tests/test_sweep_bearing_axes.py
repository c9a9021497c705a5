"""Bearing-element fields as sweep axes (issue 12: "its fields usable as sweep axes").

Every numeric field of every element of :mod:`rotordyn.bearings` is addressable by a dotted
model path (``bearings.<index|name|*>.<field>``, table columns by entry:
``bearings.0.kxx_n_per_m.1``); text and boolean fields are refused with an InputError. Real
sweeps over a fixed-geometry bearing's preload and lobe offset, a squeeze-film damper's
clearance and end-seal conductance and a table entry give rows equal to direct calls on the model changed the same way (same solver, same inputs: 1e-9 relative; the
sweep continues the equilibrium along its innermost axis, the direct call starts cold, and the
polished equilibrium agrees to round-off).
"""

import dataclasses
import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.bearings import FixedGeometryBearing, SqueezeFilmDamper, TableBearing
from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.paths import get_field, set_field

sys.path.insert(0, str(Path(__file__).parent))
from test_bearing_elements_system import FILM, ROTOR_TOML, _bearings  # noqa: E402

# explicit values for fields whose default is None (the element's own default then applies)
NONE_VALUES = {"preload": 0.4, "offset": 0.5, "orientation_deg": 270.0,
               "end_seal_conductance_m3_per_pa_s_per_m": 1e-10, "density_kg_m3": 870.0,
               "pitch_inertia_kg_m2": 2e-4}
# the turbulent film's transition: a pair (both or neither) on a turbulent film
TRANSITION = {"turbulence_onset_re": 500.0, "turbulence_full_re": 1000.0}


def _base():
    return rotordyn.System.from_toml(ROTOR_TOML, is_text=True)


@pytest.mark.parametrize("kind", ["fixed_geometry", "tilting_pad", "squeeze_film_damper",
                                  "table"])
def test_every_element_field_is_a_model_path(kind):
    s = dataclasses.replace(_base(), bearings=tuple(_bearings(kind)))
    b = s.bearings[0]
    for f in dataclasses.fields(b):
        if f.name == "tilt_stiffness_nm_per_rad":
            continue  # the deprecated spelling (moved to tilt_stiffness_n_m_per_rad on construction)
        path = f"bearings.0.{f.name}"
        cur = getattr(b, f.name)
        if isinstance(cur, (str, bool)) or f.name == "viscosity_field_pa_s":  # the THD's
            with pytest.raises(InputError, match="not a numeric field"):     # frozen field
                set_field(s, path, 1.0)
            continue
        if isinstance(cur, tuple):  # a table column: one entry per speed
            if not cur:
                continue
            val = cur[1] * 1.5 if cur[1] else 1.0
            if f.name == "speeds_hz":
                val = 0.5 * (cur[0] + cur[1])
            s2 = set_field(s, f"{path}.1", val)
            assert get_field(s2, f"{path}.1") == [val]
            assert getattr(s2.bearings[0], f.name)[1] == val
            continue
        if f.name in TRANSITION:  # set on a turbulent film that has the pair
            t = dataclasses.replace(s, bearings=(dataclasses.replace(
                b, turbulence="ng_pan", density_kg_m3=870.0, **TRANSITION),))
            s2 = set_field(t, path, 1.1 * TRANSITION[f.name])
            assert get_field(s2, path) == [1.1 * TRANSITION[f.name]]
            continue
        val = NONE_VALUES[f.name] if cur is None else cur
        s2 = set_field(s, path, val)
        assert s2.bearings[0] == dataclasses.replace(b, **{f.name: type(val)(val)})
        assert get_field(s2, path) == [val]
    if kind == "tilting_pad":
        with pytest.raises(InputError, match="n_pads: expected an integer"):
            set_field(s, "bearings.0.n_pads", 4.5)
        with pytest.raises(InputError, match="pivot_offset"):
            set_field(s, "bearings.0.pivot_offset", 1.0)
    if kind == "table":
        with pytest.raises(InputError, match="speeds_hz: expected strictly increasing"):
            set_field(s, "bearings.0.speeds_hz.1", 5.0)


def _write(tmp_path, system, grid: str, analysis: str):
    system.to_toml(tmp_path / "m.toml")
    p = tmp_path / "s.toml"
    p.write_text(f'schema = "rotordyn/sweep/1"\nname = "b"\nmodel = "m.toml"\n'
                 f'analysis = "{analysis}"\nchunk_size = 4\n[grid]\n{grid}')
    return p


def _changed(system, row, axes):
    for a in axes:
        system = set_field(system, a, float(row[a]))
    return system


def test_stability_sweep_over_preload_and_damper_clearance(tmp_path):
    s = dataclasses.replace(_base(), bearings=(
        FixedGeometryBearing(station=0, kind="elliptical", name="left", **FILM),
        SqueezeFilmDamper(station=2, cavitation="gumbel", centring_spring_n_per_m=2e6,
                          name="damper", **FILM)))
    axes = ["bearings.left.preload", "bearings.damper.clearance_m",
            "bearings.damper.end_seal_conductance_m3_per_pa_s_per_m"]
    grid = ('"bearings.left.preload" = [0.2, 0.5]\n'
            '"bearings.damper.clearance_m" = [4e-5, 8e-5]\n'
            '"bearings.damper.end_seal_conductance_m3_per_pa_s_per_m" = [1e-12, 1e-9]\n'
            'speed_hz = 60.0\n')
    res = run_sweep(_write(tmp_path, s, grid, "stability"), tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert fr["point_id"].nunique() == 8 and (fr["status"] == "ok").all()
    maxre = []
    for pid, g in fr.groupby("point_id"):
        st = rotordyn.stability(_changed(s, g.iloc[0], axes), speed_hz=60.0)
        lam = st.eigenvalues
        np.testing.assert_allclose(g["max_real_1_per_s"].iloc[0], lam.real.max(), rtol=1e-9)
        got = np.sort(g["eig_real_1_per_s"].to_numpy() + 1j * 2 * np.pi * g["freq_hz"].to_numpy())
        np.testing.assert_allclose(got, np.sort(lam)[:len(got)], rtol=1e-9)
        maxre.append(lam.real.max())
    assert np.ptp(maxre) > 1.0  # the axes really change the model (1/s)


def test_equilibrium_sweep_over_table_entry_and_bearing_fields(tmp_path):
    """Equilibrium rows per bearing (a table entry, a fixed-geometry lobe offset, a damper's
    centring spring; the damper's film carries no static load) against direct calls. (Tilting pads have their own sweep-vs-API
    check in tests/test_tilting_pad_equilibrium.py: both start from the C++ pad assembly.)"""
    fg = FixedGeometryBearing(station=0, kind="offset_halves", name="fg", **FILM)
    tb = TableBearing(station=1, speeds_hz=(10.0, 60.0, 110.0), kxx_n_per_m=(2e6, 3e6, 4e6),
                      kyy_n_per_m=(3e6, 4e6, 5e6), name="tab")
    sd = SqueezeFilmDamper(station=2, cavitation="gumbel", centring_spring_n_per_m=3e5,
                           name="sfd", **FILM)
    s = dataclasses.replace(_base(), bearings=(fg, tb, sd))
    axes = ["bearings.fg.offset", "bearings.tab.kyy_n_per_m.1",
            "bearings.sfd.centring_spring_n_per_m"]
    grid = ('"bearings.fg.offset" = [0.6, 1.0]\n'
            '"bearings.tab.kyy_n_per_m.1" = [2e6, 8e6]\n'
            '"bearings.sfd.centring_spring_n_per_m" = [3e5, 1e6]\n'
            'speed_hz = 60.0\n')
    res = run_sweep(_write(tmp_path, s, grid, "equilibrium"), tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    assert fr["point_id"].nunique() == 8 and (fr["status"] == "ok").all()
    assert fr[fr["bearing"] == "tab"]["h_min_m"].isna().all()  # no film
    assert fr[fr["bearing"] == "tab"]["x_over_c"].isna().all()  # no clearance
    ys = []
    for pid, g in fr.groupby("point_id"):
        e = rotordyn.equilibrium(_changed(s, g.iloc[0], axes), speed_hz=60.0)
        for _, row in g.iterrows():
            i = list(e.bearing_names).index(row["bearing"])
            np.testing.assert_allclose([row["journal_x_m"], row["journal_y_m"]],
                                       [e.journal_x_m[i], e.journal_y_m[i]], rtol=1e-9,
                                       atol=1e-9 * np.abs(e.journal_y_m).max())
            if row["bearing"] != "tab":
                assert row["h_min_m"] == pytest.approx(e.h_min_m[i], rel=1e-9)
        ys.append(tuple(g["journal_y_m"]))
    assert len(set(ys)) == 8  # every axis moves the equilibrium
