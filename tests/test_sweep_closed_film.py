"""A sweep point whose bearing misalignment closes a film is a row, not a refused sweep
(issue 20; project rule: a failed point in a sweep is a row with a status).

The compressor of tests/data/models on plain bearings with ``tilt = true`` (L = 50 mm,
c = 0.1 mm: a misalignment |θ|·L/2 >= c, i.e. |θ| >= 4 mrad, closes the film at an edge for a
journal on the housing's axis). Before this change a grid value of 5 mrad refused the whole
spec at load (InputError naming the point); now that point is a row with status ``error`` and
the closing message, the other points are computed and equal the direct calls. A spec whose
every value closes the film, or a malformed value, is still refused at load.
"""

import dataclasses
from pathlib import Path

import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.errors import ClosedFilmError, InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.spec import SweepSpec

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0
AXIS = "bearings.DE bearing.config_theta_y_rad"


def _model(tmp_path):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=36, n_axial=6) for b in s.bearings))
    s.to_toml(tmp_path / "m.toml")
    return s


def _spec(tmp_path, values, name="mis"):
    p = tmp_path / f"{name}.toml"
    p.write_text(f'schema = "rotordyn/sweep/1"\nname = "{name}"\nmodel = "m.toml"\n'
                 f'analysis = "equilibrium"\n[grid]\nspeed_hz = [{F_HZ}]\n'
                 f'"{AXIS}" = {values!r}\n')
    return p


def test_closed_film_point_is_a_row(tmp_path):
    s = _model(tmp_path)
    vals = [-1e-3, 5e-3, 1e-3]  # 5 mrad: |θ|·L/2 = 125 µm > c = 100 µm
    with pytest.raises(ClosedFilmError, match="config_theta_x_rad, config_theta_y_rad"):
        dataclasses.replace(s, bearings=(s.bearings[0], dataclasses.replace(
            s.bearings[1], config_theta_y_rad=5e-3)))
    res = run_sweep(_spec(tmp_path, vals), tmp_path / "out", threads=1)
    assert res.complete
    f = sw.open(tmp_path / "out").frame
    assert sorted(set(f[AXIS])) == sorted(vals)  # every point has its rows
    bad = f[f[AXIS] == 5e-3]
    assert (bad["status"] == "error").all()
    assert bad["message"].str.contains("closes the film at an edge").all()
    assert bad["message"].str.contains("config_theta_y_rad").all()
    assert bad["journal_x_m"].isna().all()
    for val in (-1e-3, 1e-3):  # the other points computed, equal to the direct calls
        rows = f[f[AXIS] == val].sort_values("bearing")
        assert (rows["status"] == "ok").all()
        sv = dataclasses.replace(s, bearings=(s.bearings[0], dataclasses.replace(
            s.bearings[1], config_theta_y_rad=val)))
        e = rotordyn.equilibrium(sv, speed_hz=F_HZ)
        for i, b in enumerate(sv.bearings):
            row = rows[rows["bearing"] == b.name].iloc[0]
            assert row["journal_y_m"] == pytest.approx(e.journal_y_m[i], rel=1e-9, abs=1e-15)
            assert row["film_moment_x_n_m"] == pytest.approx(
                e.tilt[i]["film_moment_x_n_m"], rel=1e-8, abs=1e-12)


def test_every_value_closing_or_malformed_is_refused_at_load(tmp_path):
    _model(tmp_path)
    with pytest.raises(InputError, match=r"grid\.bearings\.DE bearing\.config_theta_y_rad\[0\]"
                       r".*every checked value of the axis is refused"):
        SweepSpec.from_toml(_spec(tmp_path, [5e-3, -6e-3], "all"))
    with pytest.raises(InputError, match=r"config_theta_y_rad.*expected a finite number"):
        SweepSpec.from_toml(_spec(tmp_path, [1e-3, float("nan")], "nan"))
    # a value invalid on its own (not a closed film) still refuses the spec
    p = tmp_path / "neg.toml"
    p.write_text('schema = "rotordyn/sweep/1"\nname = "neg"\nmodel = "m.toml"\n'
                 'analysis = "equilibrium"\n[grid]\nspeed_hz = [150.0]\n'
                 '"bearings.DE bearing.clearance_m" = [1e-4, -1e-4]\n')
    with pytest.raises(InputError, match=r"clearance_m\[1\]") as exc:
        SweepSpec.from_toml(p)
    assert not isinstance(exc.value, ClosedFilmError)


def test_transition_pair_axes_refuse_only_their_bad_combinations(tmp_path):
    """Review 2026-12-05: sweeping both ends of a turbulence transition, onset [1000, 1500] x
    full [1300, 2000], was refused at load (onset 1500 was checked against the model's full
    1300), although three of its four points are valid. The pair's order is a combination's
    fault (FieldCombinationError): the (1500, 1300) point is an error row, the others run."""
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, turbulence="ng_pan", density_kg_m3=870.0,
                            turbulence_onset_re=1000.0, turbulence_full_re=1300.0,
                            n_circ=36, n_axial=6) for b in s.bearings))
    s.to_toml(tmp_path / "m.toml")
    on, full = "bearings.DE bearing.turbulence_onset_re", "bearings.DE bearing.turbulence_full_re"
    p = tmp_path / "tr.toml"
    p.write_text(f'schema = "rotordyn/sweep/1"\nname = "tr"\nmodel = "m.toml"\n'
                 f'analysis = "equilibrium"\n[grid]\nspeed_hz = [{F_HZ}]\n'
                 f'"{on}" = [1000.0, 1500.0]\n"{full}" = [1300.0, 2000.0]\n')
    res = run_sweep(p, tmp_path / "out", threads=1)
    assert res.complete
    f = sw.open(tmp_path / "out").frame
    bad = f[(f[on] == 1500.0) & (f[full] == 1300.0)]
    assert len(bad) and (bad["status"] == "error").all()
    assert bad["message"].str.contains("turbulence_full_re").all()
    good = f[~((f[on] == 1500.0) & (f[full] == 1300.0))]
    assert (good["status"] == "ok").all() and good["journal_x_m"].notna().all()
