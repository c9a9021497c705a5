"""`rotordyn thermal` / `system_thermal_equilibrium(...).to_frame()` on a model with a tilting
film (issue 20: "the sweep machinery, the report and the CLI show the new outputs"): the
frame had the edge film (h_min_m, h_min_z_m) but not the journal's rotations or the film
moments. Now per film: ``journal_theta_x_rad``, ``journal_theta_y_rad``,
``film_moment_x_n_m``, ``film_moment_y_n_m`` — NaN for an untilted film, no columns when no
film tilts. Checked against an independent path: the isothermal equilibrium of the returned
hot system (each film frozen at its thermal field), which is the thermal equilibrium's pose.
"""

from pathlib import Path

import numpy as np

import rotordyn as rd

MODEL = Path(__file__).parent / "data" / "models" / "compressor_plain_thermal.toml"
SPEED = 100.0


def _tilted():
    text = MODEL.read_text().replace(
        'name = "DE bearing"', 'name = "DE bearing"\ntilt = true\nconfig_theta_x_rad = 3e-4', 1)
    return rd.System.from_toml(text, is_text=True)


def test_thermal_frame_carries_rotations_and_moments_of_tilting_films():
    r = rd.system_thermal_equilibrium(_tilted(), speed_hz=SPEED)
    assert r.status == "ok"
    f = r.to_frame().set_index("bearing")
    cols = ["journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
            "film_moment_y_n_m"]
    assert f.loc["NDE bearing", cols].isna().all()  # untilted film
    e = rd.equilibrium(r.system, SPEED)
    assert e.status == "ok"
    ef = e.to_frame().set_index("bearing")
    for c in cols:
        got, ref = f.loc["DE bearing", c], ef.loc["DE bearing", c]
        assert np.isfinite(got) and abs(got - ref) <= 1e-6 * abs(ref) + 1e-12, (c, got, ref)
    assert abs(f.loc["DE bearing", "film_moment_x_n_m"]) > 0.1  # the misalignment's moment


def test_untilted_thermal_frame_has_no_tilt_columns():
    r = rd.system_thermal_equilibrium(rd.System.from_toml(MODEL), speed_hz=SPEED)
    assert "journal_theta_x_rad" not in r.to_frame().columns
