"""The standalone tilt functions (``rotordyn.bearings.tilt``: ``tilted_forces``,
``tilted_coefficients``, ``misaligned_equilibrium``) on a system's own plain bearing
(``System.bearings[i]``, a :class:`FluidFilmBearing`), as they already took a system's
fixed-geometry and tilting-pad bearings (docs/film-physics.md, "Journal tilt").

Before: an AttributeError from inside (``'FluidFilmBearing' object has no attribute
'_local'`` / ``'to_core'``) once the pose passed its check; the tests passed
``b.journal_bearing()``, which drops a frozen THD viscosity field, so the standalone film of a
thermal equilibrium's bearing silently was the isoviscous one. Now the system bearing is its
film model with its field. Checked on the compressor of tests/data/models (not the paper rig)
on two misaligned turbulent plain bearings with its oil system (THD):
* the plain bearing of the model file equals, bit for bit, a ``JournalBearing`` written here
  from the model file's numbers (not through ``journal_bearing()``, which the functions call
  themselves: comparing with it compared a path with itself), and its forces and moments at
  the system's own equilibrium pose equal the system's film (assembly's coupling, 1e-9);
* the THD-frozen bearing of ``system_thermal_equilibrium(...).system``: the films' moments of
  the frozen system's equilibrium equal ``tilted_forces`` of that bearing at the
  equilibrium's pose (1e-9; the system's film, the same field), and differ from the
  ``journal_bearing()`` film (which has no field) by more than 1 %;
* the same on the compressor's two 5-pad rocker bearings (THD, misaligned, turbulent): the
  pads' held-pose films (``tilt_pads._Layout.baked``) dropped the pads' frozen fields, so
  ``tilted_forces`` of the frozen bearing at the system's own equilibrium pose gave moments
  9 % and a force 9 % off (952.7 N where the film carries 1043 N); now 1e-9;
* an active bearing or a table bearing: InputError naming ``bearing``.
48 × 6 grids (60 × 6 for the pads): about two seconds.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_coefficients, tilted_forces
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0


def _compressor():
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    th = dataclasses.replace(s.thermal, model="thd")
    bs = tuple(dataclasses.replace(b, n_circ=48, n_axial=6, tilt=True, config_theta_y_rad=3e-4,
                                   turbulence="ng_pan", density_kg_m3=860.0)
               for b in s.bearings)
    return dataclasses.replace(s, bearings=bs, thermal=th)


def test_a_system_plain_bearing_is_its_film_model():
    s = _compressor()
    b = s.bearings[0]
    # the film as the model file and _compressor() state it, built here
    ref = rd.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1.0e-4,
                            viscosity_pa_s=0.018, n_circ=48, n_axial=6, turbulence="ng_pan",
                            density_kg_m3=860.0)
    pose = dict(x_m=2e-5, y_m=-1e-5, speed_hz=F_HZ, theta_x_rad=1e-4, theta_y_rad=-2e-4)
    a, r = tilted_forces(b, **pose), tilted_forces(ref, **pose)
    assert np.array_equal(a.force_n, r.force_n)
    assert np.array_equal(a.film_moment_n_m, r.film_moment_n_m)
    for x, y in zip(tilted_coefficients(b, **pose), tilted_coefficients(ref, **pose)):
        assert np.array_equal(x, y)
    e = misaligned_equilibrium(b, load_n=(0.0, -1000.0), speed_hz=F_HZ, theta_y_rad=3e-4)
    e0 = misaligned_equilibrium(ref, load_n=(0.0, -1000.0), speed_hz=F_HZ, theta_y_rad=3e-4)
    assert e.status == "ok" and (e.x_m, e.y_m) == (e0.x_m, e0.y_m)
    # the system's own film (assembly's coupling) at its isothermal equilibrium pose
    eq = rd.equilibrium(s, F_HZ)
    assert eq.status == "ok"
    for i, bi in enumerate(s.bearings):
        tt = eq.tilt[i]
        f = tilted_forces(bi, x_m=eq.journal_x_m[i], y_m=eq.journal_y_m[i], speed_hz=F_HZ,
                          theta_x_rad=tt["journal_theta_x_rad"],
                          theta_y_rad=tt["journal_theta_y_rad"])
        got = np.array([tt["film_moment_x_n_m"], tt["film_moment_y_n_m"]])
        np.testing.assert_allclose(got, f.film_moment_n_m, rtol=1e-9,
                                   atol=1e-9 * np.abs(f.film_moment_n_m).max())
        bc = assembled(s).bearings[i]
        np.testing.assert_allclose(f.force_n, np.asarray(eq.film_force_n)[[bc.jx, bc.jy]],
                                   rtol=1e-9)


def test_a_thd_frozen_bearing_keeps_its_field():
    s = _compressor()
    t = rd.system_thermal_equilibrium(s, speed_hz=F_HZ)
    assert t.status == "ok"
    hot = t.system
    e = rd.equilibrium(hot, F_HZ)
    assert e.status == "ok"
    for i, b in enumerate(hot.bearings):
        assert b.viscosity_field_pa_s is not None
        tt = e.tilt[i]
        pose = dict(x_m=e.journal_x_m[i], y_m=e.journal_y_m[i], speed_hz=F_HZ,
                    theta_x_rad=tt["journal_theta_x_rad"], theta_y_rad=tt["journal_theta_y_rad"])
        got = np.array([tt["film_moment_x_n_m"], tt["film_moment_y_n_m"]])
        ref = tilted_forces(b, **pose).film_moment_n_m
        np.testing.assert_allclose(got, ref, rtol=1e-9, atol=1e-9 * np.abs(ref).max())
        iso = tilted_forces(b.journal_bearing(), **pose).film_moment_n_m
        assert np.abs(iso - ref).max() > 0.01 * np.abs(ref).max()


def test_thd_frozen_tilting_pads_keep_their_fields():
    s = _compressor()
    pads = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml").bearings
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(p, n_circ=60, n_axial=6, tilt=True, config_theta_y_rad=3e-4,
                            turbulence="ng_pan", density_kg_m3=860.0) for p in pads))
    t = rd.system_thermal_equilibrium(s, speed_hz=F_HZ)
    assert t.status == "ok"
    e = rd.equilibrium(t.system, F_HZ)
    for i, b in enumerate(t.system.bearings):
        tt = e.tilt[i]
        pose = dict(x_m=e.journal_x_m[i], y_m=e.journal_y_m[i], speed_hz=F_HZ,
                    theta_x_rad=tt["journal_theta_x_rad"], theta_y_rad=tt["journal_theta_y_rad"])
        got = np.array([tt["film_moment_x_n_m"], tt["film_moment_y_n_m"]])
        f = tilted_forces(b, **pose)
        np.testing.assert_allclose(got, f.film_moment_n_m, rtol=1e-9,
                                   atol=1e-9 * np.abs(f.film_moment_n_m).max())
        # the held journal's film carries the bearing's share of the weight (its pads at
        # their equilibrium, the same fields): the system's film force at the same pose
        bc = assembled(t.system).bearings[i]
        np.testing.assert_allclose(f.force_n, np.asarray(e.film_force_n)[[bc.jx, bc.jy]],
                                   rtol=1e-9)


def test_bearings_without_a_standalone_tilted_film_name_the_argument():
    paper = rd.models.load("paper-rig")
    active = next(b for b in paper.bearings if type(b).__name__ == "ActiveJournalBearing")
    with pytest.raises(InputError, match="^bearing: an active journal bearing"):
        tilted_forces(active, x_m=0.0, y_m=0.0, speed_hz=50.0)
    table = rd.System.from_toml(MODELS / "compressor_table.toml").bearings[0]
    with pytest.raises(InputError, match="^bearing: expected a JournalBearing.*TableBearing"):
        misaligned_equilibrium(table, load_n=(0.0, -1.0), speed_hz=50.0)
