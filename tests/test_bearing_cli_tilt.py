"""``rotordyn bearing --theta-x-rad/--theta-y-rad`` (issue 20: the CLI shows the edge film
and the moments): the command-line record of a tilted journal equals the API
(`tilted_forces`, `tilted_coefficients`, `misaligned_equilibrium`) to round-off; zero tilt
gives today's 2×2 K, C in the translational block; bad input names the field."""

import json

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_coefficients, tilted_forces
from rotordyn.cli import main

D, L, C, MU = 0.1, 0.05, 1e-4, 0.018
GEO = ["--diameter-m", str(D), "--length-m", str(L), "--clearance-m", str(C),
       "--viscosity-pa-s", str(MU), "--n-circ", "36", "--n-axial", "8", "--speed-hz", "100"]
TH = dict(theta_x_rad=0.2 * C / L, theta_y_rad=-0.4 * C / L)


def _b():
    return rotordyn.JournalBearing(diameter_m=D, length_m=L, clearance_m=C, viscosity_pa_s=MU,
                                   n_circ=36, n_axial=8)


def _run(capsys, *extra):
    code = main(["bearing", *GEO, *extra, "--json"])
    return code, json.loads(capsys.readouterr().out)


def test_tilted_point_equals_the_api(capsys):
    x, y = 0.3 * C, -0.4 * C
    code, r = _run(capsys, "--x-m", str(x), "--y-m", str(y),
                   "--theta-x-rad", repr(TH["theta_x_rad"]),
                   "--theta-y-rad", repr(TH["theta_y_rad"]))
    assert code == 0
    t = tilted_forces(_b(), x_m=x, y_m=y, speed_hz=100.0, **TH)
    K, Cm = tilted_coefficients(_b(), x_m=x, y_m=y, speed_hz=100.0, **TH)
    np.testing.assert_allclose(r["force_n"], t.force_n, rtol=1e-12)
    np.testing.assert_allclose(r["film_moment_n_m"], t.film_moment_n_m, rtol=1e-12)
    assert r["h_min_z_m"] == pytest.approx(t.h_min_z_m) and abs(r["h_min_z_m"]) == L / 2
    np.testing.assert_allclose(r["k_4x4_si"], K, rtol=1e-12, atol=1e-12 * np.abs(K).max())
    np.testing.assert_allclose(r["c_4x4_si"], Cm, rtol=1e-12, atol=1e-12 * np.abs(Cm).max())
    assert np.shape(r["k_4x4_si"]) == (4, 4)
    assert r["coordinates"] == ["x", "y", "theta_x", "theta_y"]


def test_misaligned_equilibrium_and_zero_tilt(capsys):
    code, r = _run(capsys, "--load-n", "0", "-2000", "--theta-y-rad", repr(TH["theta_y_rad"]))
    assert code == 0 and r["equilibrium"]["status"] == "ok"
    e = misaligned_equilibrium(_b(), load_n=(0.0, -2000.0), speed_hz=100.0,
                               theta_y_rad=TH["theta_y_rad"])
    assert (r["journal_x_m"], r["journal_y_m"]) == pytest.approx((e.x_m, e.y_m), rel=1e-12)
    np.testing.assert_allclose(r["film_moment_n_m"], e.film_moment_n_m, rtol=1e-9)
    # zero tilt given: the translational block is today's 2x2 bearing
    code, z = _run(capsys, "--load-n", "0", "-2000", "--theta-x-rad", "0")
    assert code == 0
    b = _b()
    eq = b.static_equilibrium(load_n=(0.0, -2000.0), speed_hz=100.0)
    K, Cm = b.coefficients(x_m=eq.x_m, y_m=eq.y_m, speed_hz=100.0)
    np.testing.assert_allclose(np.array(z["k_4x4_si"])[:2, :2], K, rtol=1e-8,
                               atol=1e-8 * abs(K).max())
    np.testing.assert_allclose(np.array(z["c_4x4_si"])[:2, :2], Cm, rtol=1e-8,
                               atol=1e-8 * abs(Cm).max())


def test_text_output_and_bad_input(capsys):
    assert main(["bearing", *GEO, "--x-m", "0", "--y-m", "0", "--theta-y-rad", "1e-3"]) == 0
    out = capsys.readouterr().out
    assert "moment: Mx" in out and "z = " in out and "theta_y" in out
    # a tilt that closes the film at an edge: theta L/2 >= c
    assert main(["bearing", *GEO, "--x-m", "0", "--y-m", "0", "--theta-y-rad", "5e-3"]) == 2
    assert "theta" in capsys.readouterr().err
    assert main(["bearing", *GEO[:-2], "--speeds-hz", "50:100:50", "--load-n", "0", "-1000",
                 "--theta-x-rad", "1e-4"]) == 2
    assert "--theta-x-rad" in capsys.readouterr().err


def test_json_keys_match_the_aligned_command(capsys):
    """The tilted record names its coefficients as the aligned `rotordyn bearing` does
    (`k_n_per_m`, `c_n_s_per_m`: the translational 2×2 block, N/m and N·s/m), the 4×4 under
    unit-suffixed names with every entry's unit given; at zero tilt the 2×2 equals the aligned
    command's own to 1e-8 (the same film, the tilted film's full-grid solve against the
    aligned half grid: round-off apart)."""
    x, y = 0.3 * C, -0.4 * C
    pose = ["--x-m", str(x), "--y-m", str(y)]
    code, t = _run(capsys, *pose, "--theta-y-rad", repr(TH["theta_y_rad"]))
    assert code == 0
    assert "k" not in t and "c" not in t
    K4, C4 = np.array(t["k_4x4_si"]), np.array(t["c_4x4_si"])
    np.testing.assert_array_equal(t["k_n_per_m"], K4[:2, :2])
    np.testing.assert_array_equal(t["c_n_s_per_m"], C4[:2, :2])
    assert t["k_4x4_units"][0] == ["N/m", "N/m", "N/rad", "N/rad"]
    assert t["k_4x4_units"][3] == ["N·m/m", "N·m/m", "N·m/rad", "N·m/rad"]
    assert t["c_4x4_units"][2][2] == "N·m·s/rad" and t["c_4x4_units"][1][0] == "N·s/m"
    code, z = _run(capsys, *pose, "--theta-x-rad", "0")
    code0, a = _run(capsys, *pose)
    assert code == code0 == 0
    for key in ("k_n_per_m", "c_n_s_per_m"):
        ref = np.array(a[key])
        np.testing.assert_allclose(z[key], ref, rtol=1e-8, atol=1e-8 * abs(ref).max())
    # the one pose resolution of both paths: the same refusals, word for word
    for extra in (["--load-n", "0", "-1000", "--x-m", "0"], []):
        assert main(["bearing", *GEO, *extra]) == 2
        e0 = capsys.readouterr().err
        assert main(["bearing", *GEO, *extra, "--theta-x-rad", "1e-4"]) == 2
        assert capsys.readouterr().err == e0 and ("--load-n" in e0 or "--x-m" in e0)
