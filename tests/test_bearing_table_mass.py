"""Mass coefficients of a bearing table (force −M(Ω) q̈, interpolated like K and C).

References
----------
* A constant isotropic table mass m at a station is a point mass m there: with the station a
  master of the Guyan reduction (T = I on its translations) the reduced mass matrices are the
  same, and the bearings are linear, so the Campbell eigenvalues and the unbalance response
  must agree to round-off (1e-8 relative; the point mass's weight only moves the static
  position, which a linear table does not see).
* Linear interpolation in Ω is exact for data linear in Ω: M(Ω) between rows equals the
  straight line through them (1e-12), in the table and in the system's linear model.
* The transient at a constant speed between rows is the linear system with M(Ω) at that
  speed: x(t) = expm(A t) x0 within the CVODE tolerance (1e-3 of the peak), and measurably
  not the one with the mass of another row.
"""

import dataclasses
import math

import numpy as np
import pytest
import scipy.linalg

import rotordyn
from rotordyn.bearings import TableBearing
from rotordyn.errors import InputError
from rotordyn.model.rotor import Disk

from test_bearing_elements_system import ROTOR_TOML

SPEEDS = (10.0, 60.0, 110.0)
KT = dict(kxx_n_per_m=(2e6, 3e6, 4e6), kyy_n_per_m=(3e6, 4e6, 5e6),
          kxy_n_per_m=(1e5, 2e5, 3e5), kyx_n_per_m=(-1e5, -2e5, -3e5),
          cxx_n_s_per_m=(2e3, 1.5e3, 1e3), cyy_n_s_per_m=(2e3, 1.5e3, 1e3))


def _system(mass0=None, disk_kg=0.0):
    base = rotordyn.System.from_toml(ROTOR_TOML, is_text=True)
    b0 = TableBearing(station=0, speeds_hz=SPEEDS, **KT, **(mass0 or {}))
    b2 = TableBearing(station=2, speeds_hz=SPEEDS, **KT)
    s = dataclasses.replace(base, bearings=(b0, b2))
    if disk_kg:
        disks = s.rotor.disks + (Disk(station=0, mass_kg=disk_kg, ip_kg_m2=0.0, id_kg_m2=0.0),)
        s = dataclasses.replace(s, rotor=dataclasses.replace(s.rotor, disks=disks))
    return s


def _const_mass(m):
    return dict(mxx_kg=(m,) * 3, mxy_kg=(0.0,) * 3, myx_kg=(0.0,) * 3, myy_kg=(m,) * 3)


def test_constant_table_mass_is_a_point_mass():
    m = 0.7
    st, sp = _system(_const_mass(m)), _system(disk_kg=m)
    speeds = [15.0, 40.0, 75.0, 100.0]
    ct, cp = rotordyn.campbell(st, speeds), rotordyn.campbell(sp, speeds)
    lt, lp = np.asarray(ct.eigenvalues), np.asarray(cp.eigenvalues)
    assert np.all(np.isfinite(lt)) and lt.shape == lp.shape
    for a, b in zip(lt, lp):  # same modes (sorted: the order of equal-frequency pairs may differ)
        np.testing.assert_allclose(np.sort_complex(a), np.sort_complex(b), rtol=1e-8, atol=0)
    # the mass really entered: without it the lowest mode differs by more than 1 %
    c0 = np.asarray(rotordyn.campbell(_system(), speeds).eigenvalues)
    low = lambda lam: np.nanmin(np.abs(lam), axis=1)  # noqa: E731
    assert np.all(np.abs(low(c0) / low(lt) - 1) > 0.01)
    ut = rotordyn.unbalance_response(st, [(1, 1e-5, 0.0)], [30.0, 70.0], stations=[0, 1])
    up = rotordyn.unbalance_response(sp, [(1, 1e-5, 0.0)], [30.0, 70.0], stations=[0, 1])
    np.testing.assert_allclose(np.asarray(ut.x), np.asarray(up.x), rtol=1e-8, atol=0)


def test_speed_dependent_mass_is_interpolated_everywhere():
    mass = dict(mxx_kg=(0.2, 0.5, 1.1), mxy_kg=(0.0, 0.05, 0.1), myx_kg=(0.0, -0.05, -0.1),
                myy_kg=(0.3, 0.6, 0.9))
    b = TableBearing(station=0, speeds_hz=SPEEDS, **KT, **mass)
    f = 35.0  # halfway between 10 and 60 Hz
    M = b.mass(f)
    np.testing.assert_allclose(M, [[0.35, 0.025], [-0.025, 0.45]], rtol=1e-12)
    assert np.all(TableBearing(station=0, speeds_hz=SPEEDS, **KT).mass(f) == 0)
    lm, l0 = rotordyn.linearize(_system(mass), f), rotordyn.linearize(_system(), f)
    dM = lm.M - l0.M
    j = [lm.labels.index("station0.x"), lm.labels.index("station0.y")]
    np.testing.assert_allclose(dM[np.ix_(j, j)], M, rtol=1e-12, atol=0)
    dM[np.ix_(j, j)] = 0
    assert np.all(dM == 0)
    with pytest.raises(InputError, match="120 Hz"):
        b.mass(120.0)


def test_transient_uses_the_mass_at_the_current_speed():
    mass = dict(mxx_kg=(0.5, 3.0, 6.0), mxy_kg=(0.0,) * 3, myx_kg=(0.0,) * 3,
                myy_kg=(0.5, 3.0, 6.0))
    s = _system(mass)
    f = 35.0
    lm = rotordyn.linearize(s, speed_hz=f)
    n = lm.M.shape[0]

    def expm_response(M, t):
        A = np.block([[np.zeros((n, n)), np.eye(n)],
                      [-np.linalg.solve(M, lm.K), -np.linalg.solve(M, lm.D)]])
        return np.array([(scipy.linalg.expm(A * ti) @ x0)[:n] for ti in t])

    tr = rotordyn.transient(s, t_end_s=0.01, speed_hz=f, disturbance_m=(1e-6, 0.0), n_out=21,
                            rtol=1e-8, atol_m=1e-13)
    assert tr.status == "ok", tr.message
    x0 = np.concatenate([tr.r[0] - lm.equilibrium.r, np.zeros(n)])
    dev = tr.r - lm.equilibrium.r
    lin = expm_response(lm.M, tr.t)
    scale = np.abs(lin[:, 0]).max()
    assert np.abs(dev[:, 0] - lin[:, 0]).max() < 1e-3 * scale
    M_other = rotordyn.linearize(s, speed_hz=60.0).M  # the mass of the 60-Hz row
    other = expm_response(M_other, tr.t)
    assert np.abs(dev[:, 0] - other[:, 0]).max() > 0.05 * scale


def test_mass_columns_all_four_or_none(tmp_path):
    with pytest.raises(InputError, match=r"mxy_kg, myx_kg: .*all four"):
        TableBearing(station=0, speeds_hz=SPEEDS, **KT, mxx_kg=(1.0,) * 3, myy_kg=(1.0,) * 3)
    with pytest.raises(InputError, match="myy_kg: expected 3 values"):
        TableBearing(station=0, speeds_hz=SPEEDS, **KT, **{**_const_mass(1.0),
                                                           "myy_kg": (1.0, 1.0)})
    p = tmp_path / "t.csv"
    p.write_text("speed_hz,kxx_n_per_m,kyy_n_per_m,mxx_kg,myy_kg\n10,1e6,1e6,1,1\n20,2e6,2e6,2,2\n")
    with pytest.raises(InputError, match="mxy_kg, myx_kg"):
        TableBearing.from_csv(p, station=0)
    p.write_text("speed_hz,kxx_n_per_m,kyy_n_per_m,mxx_kg,mxy_kg,myx_kg,myy_kg\n"
                 "10,1e6,1e6,1,0,0,1\n20,2e6,2e6,2,0.1,-0.1,3\n")
    b = TableBearing.from_csv(p, station=0)
    np.testing.assert_allclose(b.mass(15.0), [[1.5, 0.05], [-0.05, 2.0]], rtol=1e-12)


def test_table_mass_toml_round_trip():
    s = _system(_const_mass(0.7))
    text = s.to_toml()
    assert "mxx_kg" in text
    s2 = rotordyn.System.from_toml(text, is_text=True)
    assert s2 == s
    assert math.isclose(s2.bearings[0].mass(20.0)[0, 0], 0.7)
