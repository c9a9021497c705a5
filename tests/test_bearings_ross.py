"""ROSS interoperability (issue 12; needs ross-rotordynamics, skipped otherwise).

* A ROSS rotor imported into a System has ROSS's own natural frequencies: ROSS's example
  rotor (ross.rotor_example(): uniform steel shaft of 6 Timoshenko elements, two disks,
  two 1e6 N/m bearings) at 0 and 500 rad/s: our six lowest lateral damped frequencies are
  among ROSS's within 0.1 % (the same
  Timoshenko/Cowper formulation on the same mesh; the tolerance covers the two codes'
  different element integrations of the shear coefficient).
* A ROSS BearingElement exported from a bearing carries this solver's coefficients at its
  frequencies (rad/s), and a ROSS rotor with it runs.
"""

import math
import warnings

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import TiltingPadBearing, to_ross_bearing
from rotordyn.model import system_from_ross

pytestmark = pytest.mark.ross


def _ross():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return pytest.importorskip("ross")


def test_ross_rotor_imported_has_ross_frequencies():
    rs = _ross()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rotor = rs.rotor_example()
        s = system_from_ross(rotor)
        for w in (0.0, 500.0):
            wd_ross = np.sort(np.asarray(rotor.run_modal(w, num_modes=24).wd))
            m = rotordyn.modes(s, speed_hz=w / (2 * math.pi), n_modes=12, without_bearings=True)
            wd = np.sort(np.asarray(m.eigenvalues).imag)
            wd = wd[wd > 1e-6][:6]
            assert len(wd) == 6
            # ROSS 2 elements also carry axial and torsional DOFs, whose modes appear in its
            # list: every lateral frequency of ours must be one of ROSS's.
            rel = np.min(np.abs(wd[:, None] / wd_ross[None, :] - 1), axis=1)
            assert np.all(rel < 1e-3), (wd, wd_ross)


def test_export_tilting_pad_to_ross_bearing():
    rs = _ross()
    tp = TiltingPadBearing(station=0, diameter_m=0.05, length_m=0.025, clearance_m=1e-4,
                           viscosity_pa_s=0.02, preload=0.3, n_circ=48, n_axial=8)
    speeds = [20.0, 40.0, 60.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        be = to_ross_bearing(tp, n=0, speeds_hz=speeds, load_n=(0.0, -500.0))
        t = tp.coefficient_table(speeds, (0.0, -500.0))
        np.testing.assert_allclose(np.asarray(be.frequency), 2 * np.pi * np.asarray(speeds))
        np.testing.assert_allclose(np.asarray(be.kxx), t.K[:, 0, 0])
        np.testing.assert_allclose(np.asarray(be.cyx), t.C[:, 1, 0])
        np.testing.assert_allclose(be.kxx_interpolated(2 * np.pi * 40.0), t.K[1, 0, 0])


def test_ross_bearing_mass_coefficients_round_trip():
    """A ROSS rotor whose bearings carry mass coefficients (ROSS 2: M = [[mxx, mxy], [myx,
    myy]] at the bearing node, in Rotor.M): imported, the bearings become TableBearings with
    mass columns, and our damped frequencies (rotordyn.stability, where table masses enter
    the mass matrix) are among ROSS's own within 0.1 % (as the import test above); the mass
    really moves them (> 1 % without it). Exported back, the BearingElement carries them."""
    rs = _ross()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ex = rs.rotor_example()
        brg = [rs.BearingElement(n=b.n, kxx=1e6, kyy=1.5e6, cxx=200.0, cyy=200.0, mxx=4.0,
                                 myy=6.0, tag=f"b{k}")
               for k, b in enumerate(ex.bearing_elements)]
        rotor = rs.Rotor(ex.shaft_elements, ex.disk_elements, brg)
        s = system_from_ross(rotor)
        assert all(b.has_mass for b in s.bearings)
        for w in (0.0, 500.0):
            wd_ross = np.sort(np.asarray(rotor.run_modal(w, num_modes=24).wd))
            lam = rotordyn.stability(s, speed_hz=w / (2 * math.pi)).eigenvalues
            wd = np.sort(lam.imag[lam.imag > 1e-6])[:6]
            rel = np.min(np.abs(wd[:, None] / wd_ross[None, :] - 1), axis=1)
            assert np.all(rel < 1e-3), (wd, wd_ross)
        s0 = system_from_ross(rs.Rotor(ex.shaft_elements, ex.disk_elements, [
            rs.BearingElement(n=b.n, kxx=1e6, kyy=1.5e6, cxx=200.0, cyy=200.0)
            for b in ex.bearing_elements]))
        lam0 = rotordyn.stability(s0, speed_hz=0.0).eigenvalues
        wd0 = np.sort(lam0.imag[lam0.imag > 1e-6])[:6]
        lam1 = rotordyn.stability(s, speed_hz=0.0).eigenvalues
        wd1 = np.sort(lam1.imag[lam1.imag > 1e-6])[:6]
        assert np.max(np.abs(wd1 / wd0 - 1)) > 0.01
        be = to_ross_bearing(s.bearings[0], n=0)
        assert float(np.ravel(be.mxx)[0]) == 4.0 and float(np.ravel(be.myy)[0]) == 6.0
