"""Speed-dependent coefficient tables (issue 12).

Reference: a table sampled from a plain bearing (``JournalBearing.coefficient_table`` at the
bearing's static reaction) gives the same Campbell diagram as the bearing itself, within the
interpolation error. The error is measured, not assumed: the table's linear interpolation of
the coefficients between 10-Hz rows is compared with the bearing's exact coefficients at the
mid-speeds (the worst place for linear interpolation, |e| ≤ h²/8·max|K''|), and the Campbell
frequencies and real parts may differ by no more than that relative coefficient error
(eigenvalues depend smoothly on K and C with sensitivities below 1 in relative terms here:
frequencies scale like √K).
"""

import dataclasses

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import TableBearing
from rotordyn.errors import InputError
from rotordyn.bearings import FluidFilmBearing

from test_bearing_elements_system import ROTOR_TOML

FILM = dict(diameter_m=0.03, length_m=0.015, clearance_m=5e-5, viscosity_pa_s=0.02,
            n_circ=48, n_axial=8)


def _plain_system():
    base = rotordyn.System.from_toml(ROTOR_TOML, is_text=True)
    return dataclasses.replace(base, bearings=tuple(FluidFilmBearing(station=s, **FILM)
                                                    for s in (0, 2)))


def test_table_from_plain_bearing_gives_its_campbell(tmp_path):
    s = _plain_system()
    e = rotordyn.equilibrium(s, speed_hz=50.0)
    reaction = e.film_force_n[[1, 5]]  # vertical film forces (gravity load is speed-independent)
    jb = rotordyn.JournalBearing(**FILM)
    speeds = np.arange(20.0, 111.0, 10.0)
    tables = []
    for st, w in zip((0, 2), reaction):
        t = jb.coefficient_table(speeds, (0.0, -w), n_threads=2)
        assert all(x == "ok" for x in t.status)
        path = tmp_path / f"b{st}.csv"
        t.to_csv(path)
        tables.append(TableBearing.from_csv(path, station=st))
    # interpolation error at the mid-speeds, measured
    mids = speeds[:-1] + 5.0
    exact = jb.coefficient_table(mids, (0.0, -reaction[0]))
    err = 0.0
    for i, f in enumerate(mids):
        K, C = tables[0].coefficients(f)
        err = max(err, np.abs(K - exact.K[i]).max() / np.abs(exact.K[i]).max(),
                  np.abs(C - exact.C[i]).max() / np.abs(exact.C[i]).max())
    assert 0 < err < 0.05, err
    st = dataclasses.replace(s, bearings=tuple(tables))
    cf = rotordyn.campbell(s, mids)
    ct = rotordyn.campbell(st, mids)
    lf, lt = np.asarray(cf.eigenvalues), np.asarray(ct.eigenvalues)
    ok = np.isfinite(lf)  # modes the diagram reports (overdamped ones are NaN in both)
    assert lf.shape == lt.shape and np.array_equal(ok, np.isfinite(lt)) and ok.sum() >= 4 * len(mids)
    lf, lt = lf[ok], lt[ok]
    np.testing.assert_allclose(np.abs(lt.imag), np.abs(lf.imag), rtol=err)
    np.testing.assert_allclose(lt.real, lf.real, atol=err * np.abs(lf).max())


def test_speed_outside_the_table_is_named():
    s = _plain_system()
    t = TableBearing(station=0, speeds_hz=(20.0, 40.0), kxx_n_per_m=(1e6, 2e6),
                     kyy_n_per_m=(1e6, 2e6), cxx_n_s_per_m=(1e3, 1e3), cyy_n_s_per_m=(1e3, 1e3))
    s2 = dataclasses.replace(s, bearings=(t, dataclasses.replace(t, station=2)))
    with pytest.raises(InputError, match="55 Hz is outside"):
        rotordyn.stability(s2, speed_hz=55.0)
    with pytest.raises(InputError, match="55 Hz is outside"):
        t.coefficients(55.0)
    te = dataclasses.replace(t, extrapolate=True)
    K, _ = te.coefficients(60.0)
    assert K[0, 0] == pytest.approx(3e6)  # linear extension of the last interval
    assert rotordyn.stability(dataclasses.replace(s2, bearings=(te, dataclasses.replace(
        te, station=2))), speed_hz=55.0).status == "ok"


def test_cli_table_csv(tmp_path, capsys):
    from rotordyn.cli import main

    rc = main(["bearing", "--diameter-m", "0.03", "--length-m", "0.015", "--clearance-m", "5e-5",
               "--viscosity-pa-s", "0.02", "--n-circ", "48", "--n-axial", "8", "--load-n", "0",
               "-40", "--speeds-hz", "10:200:10", "--csv"])
    assert rc == 0
    out = capsys.readouterr().out
    p = tmp_path / "t.csv"
    p.write_text(out)
    tb = TableBearing.from_csv(p, station=0)
    assert tb.speeds_hz == tuple(np.arange(10.0, 201.0, 10.0))
    jb = rotordyn.JournalBearing(**FILM)
    e = jb.static_equilibrium(load_n=(0.0, -40.0), speed_hz=70.0)
    K, C = jb.coefficients(x_m=e.x_m, y_m=e.y_m, speed_hz=70.0)
    Kt, Ct = tb.coefficients(70.0)
    np.testing.assert_allclose(Kt, K, rtol=1e-8, atol=1e-8 * np.abs(K).max())


def test_contact_rows_are_linearised_like_the_system():
    """A heavily loaded slow row converges with a thin film (status ``contact``: converged,
    h_min < 0.02 c). Like every system analysis, the table linearises it: finite K, C equal to
    a perturbation linearisation at the same equilibrium (JournalBearing.coefficients) to
    1e-9. (Found by the element fuzz case: contact rows came back as NaN.)"""
    from rotordyn.bearings import FixedGeometryBearing

    geo = dict(station=0, diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
               viscosity_pa_s=0.03, n_circ=36, n_axial=6)
    b = FixedGeometryBearing(kind="partial_arc", arc_deg=360.0, **geo)
    t = b.coefficient_table([1.0, 50.0], (0.0, -1.0e4))
    assert t.status == ("contact", "ok"), t.message
    assert "below 0.02 c" in t.message[0]
    assert np.all(np.isfinite(t.K)) and np.all(np.isfinite(t.C))
    # the 360° arc is the plain bearing: its coefficients at the table's equilibrium
    jb = rotordyn.JournalBearing(**{k: v for k, v in geo.items() if k != "station"})
    K, C = jb.coefficients(x_m=t.x_m[0], y_m=t.y_m[0], speed_hz=1.0)
    assert np.allclose(t.K[0], K, rtol=1e-9, atol=1e-9 * np.abs(K).max())
    assert np.allclose(t.C[0], C, rtol=1e-9, atol=1e-9 * np.abs(C).max())


@pytest.mark.parametrize("bad, message", [
    ({"a": 1}, r"cxx_n_s_per_m: expected a sequence of numbers"),   # make fuzz: ValueError
    ({1.0}, r"cxx_n_s_per_m: expected a sequence of numbers"),
    (["1"], r"cxx_n_s_per_m\[0\]: expected a number"),
    ([None], r"cxx_n_s_per_m\[0\]: expected a number"),
    ([True], r"cxx_n_s_per_m\[0\]: expected a number"),
    ([10**400], r"cxx_n_s_per_m\[0\]: expected a finite number"),
])
def test_table_entries_that_are_not_numbers_are_named(bad, message):
    with pytest.raises(InputError, match=message):
        TableBearing(station=0, speeds_hz=(1.0,), kxx_n_per_m=(0.0,), kyy_n_per_m=(0.0,),
                     cxx_n_s_per_m=bad)
