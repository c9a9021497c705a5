"""Journal tilt and misalignment used as an engineer would (issue 20, a user's pass).

Not the paper rig: the compressor of tests/data/models on plain bearings, and a 1 m shaft on
three plain bearings written here (statically indeterminate: the middle housing is offset, so
the shaft crosses the outer bearings at a slope). Checks:
* the standalone tilt functions take a model file's plain bearing (``system.bearings[i]``, a
  ``FluidFilmBearing``) and give, bit for bit, the answers of a ``JournalBearing`` written
  from the model file's numbers in the test; any other object is an
  InputError naming ``bearing`` (it was an AttributeError from inside the film code);
* a speed whose misaligned equilibrium fails is a Campbell or unbalance row with its status
  and no verdict: no whirl, no mode kind, no stability flag, NaN (not ±inf, not 0) damping
  (they said "planar", "rotor", point_stable True, log_dec inf, damping ratio 0);
* the three-bearing line: a misalignment at one end and the opposite one at the other end
  mirror each other (z → −z), the Guyan model with the rotations kept as masters reaches the
  unreduced model's equilibrium, and the middle bearing (zero slope by symmetry) with
  ``tilt = true`` gives the untilted equilibrium to round-off.
"""

import dataclasses
import math

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_coefficients, tilted_forces
from rotordyn.model.rotor import Reduction
from rotordyn.results.modes import damping_ratio, log_dec

from pathlib import Path

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0


def compressor(**fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=48, n_axial=6, **fields) for b in s.bearings))


THREE = """
schema = "rotordyn/model/1"
name = "three-bearing-line"
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.07e11
poisson = 0.29
[rotor]
{sections}
[[disk]]
station = 1
mass_kg = 15.0
ip_kg_m2 = 0.10
id_kg_m2 = 0.05
[[disk]]
station = 3
mass_kg = 15.0
ip_kg_m2 = 0.10
id_kg_m2 = 0.05
{bearings}
"""


def three_bearing_line(config=((0.0, 0.0), (0.0, 0.0), (0.0, 0.0)), tilt=(True, True, True),
                       offset_b_m=3e-5):
    sections = "".join("[[rotor.section]]\nlength_m = 0.25\nouter_diameter_m = 0.06\n"
                       "n_elements = 3\n" for _ in range(4))
    bearings = ""
    for name, st, (tx, ty), t in zip("ABC", (0, 2, 4), config, tilt):
        bearings += (f'[[bearing]]\ntype = "journal"\nname = "{name}"\nstation = {st}\n'
                     "diameter_m = 0.06\nlength_m = 0.04\nclearance_m = 8.0e-5\n"
                     "viscosity_pa_s = 0.02\nn_circ = 48\nn_axial = 8\n"
                     f"tilt = {'true' if t else 'false'}\n")
        if t:
            bearings += f"config_theta_x_rad = {tx!r}\nconfig_theta_y_rad = {ty!r}\n"
        if name == "B":
            bearings += f"config_ay_m = {offset_b_m!r}\n"
    return rotordyn.System.from_toml(THREE.format(sections=sections, bearings=bearings),
                                     is_text=True)


def test_standalone_tilt_functions_take_a_model_files_plain_bearing():
    b = compressor().bearings[1]
    # the DE film as the model file and compressor() state it, built here (not through
    # b.journal_bearing(), which the functions call themselves)
    jb = rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1.0e-4,
                                 viscosity_pa_s=0.018, n_circ=48, n_axial=6)
    kw = dict(speed_hz=F_HZ, theta_x_rad=2e-4, theta_y_rad=-1e-4)
    m, mj = (misaligned_equilibrium(x, load_n=(0.0, -1500.0), **kw) for x in (b, jb))
    assert m.status == "ok" and (m.x_m, m.y_m) == (mj.x_m, mj.y_m)
    assert np.array_equal(m.film_moment_n_m, mj.film_moment_n_m) and m.h_min_z_m == mj.h_min_z_m
    f, fj = (tilted_forces(x, x_m=m.x_m, y_m=m.y_m, **kw) for x in (b, jb))
    assert np.array_equal(f.force_n, fj.force_n)
    assert np.array_equal(f.film_moment_n_m, fj.film_moment_n_m)
    (K, C), (Kj, Cj) = (tilted_coefficients(x, x_m=m.x_m, y_m=m.y_m, **kw) for x in (b, jb))
    assert np.array_equal(K, Kj) and np.array_equal(C, Cj)
    table = rotordyn.System.from_toml(MODELS / "compressor_table.toml").bearings[0]
    for bad in (table, "journal", None):
        for fn, extra in ((tilted_forces, dict(x_m=0.0, y_m=0.0)),
                          (tilted_coefficients, dict(x_m=0.0, y_m=0.0)),
                          (misaligned_equilibrium, dict(load_n=(0.0, -1.0)))):
            with pytest.raises(rotordyn.InputError, match=r"^bearing: expected"):
                fn(bad, speed_hz=F_HZ, **extra)
    # a frozen viscosity field is the film's (tests/test_tilt_system_bearing.py): a uniform one
    # equal to the bearing's viscosity is the isoviscous film
    frozen = dataclasses.replace(b, viscosity_field_pa_s=np.full((48, 7), b.viscosity_pa_s))
    ff = tilted_forces(frozen, x_m=m.x_m, y_m=m.y_m, **kw)
    np.testing.assert_allclose(ff.force_n, f.force_n, rtol=1e-12)
    np.testing.assert_allclose(ff.film_moment_n_m, f.film_moment_n_m, rtol=1e-12)


def test_failed_misaligned_speeds_carry_no_verdict():
    """0.00395 rad at both housings (edge gap 1.25 µm for an aligned shaft): no equilibrium
    at either speed."""
    s = compressor(config_theta_y_rad=3.95e-3)
    c = rotordyn.campbell(s, [100.0, F_HZ])
    assert list(c.point_status) == ["no_equilibrium"] * 2
    fr = c.to_frame()
    assert len(fr) and (fr["status"] == "no_equilibrium").all()
    assert fr["whirl"].isna().all() and fr["kind"].isna().all()
    assert fr["log_dec"].isna().all() and fr["freq_hz"].isna().all()
    u = rotordyn.unbalance_response(s, [(3, 1e-4, 0.0)], [100.0, F_HZ], stations=[1, 3])
    fu = u.to_frame()
    assert (fu["status"] == "no_equilibrium").all() and fu["major_m"].isna().all()
    # point_message, one type and wording on every path (isothermal here; thermal in
    # tests/test_thermal_dynamics.py): the equilibrium's message per failed speed, a str
    for res in (c, u):
        assert res.point_message.dtype == object and len(res.point_message) == 2
        assert all(isinstance(m, str) and "minimum film thickness" in m
                   for m in res.point_message)
    ok = rotordyn.campbell(compressor(), [F_HZ], n_modes=2)
    ou = rotordyn.unbalance_response(compressor(), [(3, 1e-4, 0.0)], [F_HZ], refine=False)
    assert list(ok.point_message) == list(ou.point_message) == [None]  # converged: None
    assert fu["whirl"].isna().all() and fu["point_stable"].isna().all()
    assert not u.stable.any()  # no stable verdict without an equilibrium (the attribute too)
    assert "above the threshold" not in repr(u)
    # the helpers: an eigenvalue that was not computed has no damping
    lam = np.array([complex(math.nan, math.nan), -1.0 + 10.0j, -3.0 + 0.0j])
    assert np.isnan(log_dec(lam)[0]) and np.isnan(damping_ratio(lam)[0])
    assert log_dec(lam)[2] == math.inf and damping_ratio(lam)[2] == 1.0  # unchanged
    np.testing.assert_allclose(log_dec(lam)[1], 2 * math.pi / 10.0, rtol=1e-15)


def test_three_bearing_line_mirror_guyan_and_zero_slope():
    th = 5e-4
    ea = rotordyn.equilibrium(three_bearing_line(config=((0.0, th), (0.0, 0.0), (0.0, 0.0))), 60.0)
    ec = rotordyn.equilibrium(three_bearing_line(config=((0.0, 0.0), (0.0, 0.0), (0.0, -th))),
                              60.0)
    assert ea.status == ec.status == "ok"
    fa, fc = ea.to_frame(), ec.to_frame()
    scale = {"journal_x_m": 8e-5, "journal_y_m": 8e-5, "h_min_m": 8e-5, "h_min_z_m": 0.02,
             "journal_theta_x_rad": th, "journal_theta_y_rad": th, "film_moment_x_n_m": 1.0,
             "film_moment_y_n_m": 1.0}
    for col, sign in (("journal_x_m", 1), ("journal_y_m", 1), ("h_min_m", 1), ("h_min_z_m", -1),
                      ("journal_theta_x_rad", -1), ("journal_theta_y_rad", -1),
                      ("film_moment_x_n_m", -1), ("film_moment_y_n_m", -1)):
        a, c = fa[col].to_numpy(), fc[col].to_numpy()[::-1]
        np.testing.assert_allclose(a, sign * c, rtol=0, atol=1e-9 * scale[col], err_msg=col)
    # the misaligned end: the shaft hardly follows its housing, the edge film thins
    e0 = rotordyn.equilibrium(three_bearing_line(tilt=(False, False, False)), 60.0)
    assert fa.loc[0, "journal_theta_y_rad"] < -0.8 * th
    assert fa.loc[0, "h_min_m"] < e0.h_min_m[0] - 5e-6
    # Guyan with the bearing rotations as masters: the static condensation is exact there
    s = three_bearing_line(config=((0.0, th), (0.0, 0.0), (0.0, 0.0)))
    eg = rotordyn.equilibrium(dataclasses.replace(
        s, reduction=Reduction((0, 1, 2, 3, 4), "guyan")), 60.0)
    assert eg.status == "ok"
    np.testing.assert_allclose(eg.journal_y_m, ea.journal_y_m, rtol=0, atol=1e-9 * 8e-5)
    for i in range(3):
        for k in ("journal_theta_x_rad", "journal_theta_y_rad"):
            assert abs(eg.tilt[i][k] - ea.tilt[i][k]) < 1e-9 * th
    # the middle bearing sits at zero slope (symmetric line): tilt = true changes nothing
    e1 = rotordyn.equilibrium(three_bearing_line(tilt=(False, True, False)), 60.0)
    np.testing.assert_allclose(e1.journal_x_m, e0.journal_x_m, rtol=0, atol=1e-12 * 8e-5)
    np.testing.assert_allclose(e1.journal_y_m, e0.journal_y_m, rtol=0, atol=1e-12 * 8e-5)
    assert abs(e1.tilt[1]["film_moment_x_n_m"]) < 1e-12


def test_cli_reports_failed_speeds(tmp_path, capsys):
    """`rotordyn campbell` / `unbalance` on a model whose every speed fails: each failed speed
    named on stderr with its status (and Campbell's reason), exit 1 (they printed an empty
    table and exited 0)."""
    from rotordyn.cli import main

    path = tmp_path / "m.toml"
    compressor(config_theta_y_rad=3.95e-3).to_toml(path)
    assert main(["campbell", str(path), "--speeds-hz", "100,150"]) == 1
    err = capsys.readouterr().err
    assert "100 Hz: no_equilibrium" in err and "150 Hz: no_equilibrium" in err
    assert "minimum film thickness" in err  # the equilibrium's own message
    assert main(["unbalance", str(path), "--unbalance", "3,1e-4,0", "--speeds-hz",
                 "100,150"]) == 1
    err = capsys.readouterr().err
    assert "100 Hz: no_equilibrium" in err and "150 Hz: no_equilibrium" in err
    path2 = tmp_path / "ok.toml"  # every speed solved: exit 0, nothing named
    compressor(config_theta_y_rad=3e-4).to_toml(path2)
    assert main(["campbell", str(path2), "--speeds-hz", "100,150"]) == 0
    assert "no_equilibrium" not in capsys.readouterr().err


def test_static_of_a_reduced_tilting_model_keeps_the_rotation_masters():
    """`rotordyn.static` of the compressor with its DE housing misaligned by 3 mrad (film
    moment ≈ 10 N·m): the Guyan model with the rotations as masters gives the unreduced
    model's deflection and bending moments (its static condensation is exact at the masters).
    The slave recovery used the translations only and took the rotations for slaves free of
    the film moments: M_xz 9.41 against 10.14 N·m, the DE end deflection 0.35 % off."""
    from rotordyn.model.rotor import Reduction

    s = compressor()
    s = dataclasses.replace(s, bearings=(s.bearings[0], dataclasses.replace(
        s.bearings[1], config_theta_y_rad=3e-3)))
    rg = rotordyn.static(s, F_HZ)
    rn = rotordyn.static(dataclasses.replace(s, reduction=Reduction(method="none")), F_HZ)
    assert rg.status == rn.status == "ok"
    assert np.max(np.abs(rn.moment_xz_n_m)) > 5.0  # the film moment bends the shaft in x-z
    for k in ("moment_xz_n_m", "moment_yz_n_m", "shear_x_n", "shear_y_n"):
        a, b = getattr(rg, k), getattr(rn, k)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-6 * np.max(np.abs(b)), err_msg=k)
    for k in ("deflection_x_m", "deflection_y_m"):
        a, b = getattr(rg, k), getattr(rn, k)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-6 * np.max(np.abs(b)), err_msg=k)
    # the reactions carry the tilting films' moments: the equilibrium's film moments
    e = rotordyn.equilibrium(s, F_HZ)
    for i in range(2):
        row = rg.reactions.iloc[i]
        assert row["film_moment_x_n_m"] == pytest.approx(e.tilt[i]["film_moment_x_n_m"], rel=1e-9)
        assert row["film_moment_y_n_m"] == pytest.approx(e.tilt[i]["film_moment_y_n_m"], rel=1e-9)
    assert "film_moment_x_n_m" not in rotordyn.static(
        rotordyn.System.from_toml(MODELS / "compressor_plain.toml"), F_HZ).reactions


def test_cli_stability_of_a_failed_equilibrium_gives_no_verdict(tmp_path, capsys):
    """`rotordyn stability` where the misaligned equilibrium fails: exit 1 with the reason, no
    verdict (it printed "UNSTABLE: largest Re λ = nan 1/s", and --json "stable": false)."""
    import json

    from rotordyn.cli import main

    path = tmp_path / "m.toml"
    compressor(config_theta_y_rad=3.95e-3).to_toml(path)
    assert main(["stability", str(path), "--speed-hz", "150"]) == 1
    err = capsys.readouterr().err
    assert "UNSTABLE" not in err and "stable:" not in err and "no_equilibrium" in err
    assert main(["stability", str(path), "--speed-hz", "150", "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "no_equilibrium" and out["stable"] is None
    st = rotordyn.stability(compressor(config_theta_y_rad=3.95e-3), F_HZ)
    assert repr(st).startswith("<StabilityResult no verdict (no_equilibrium)")
