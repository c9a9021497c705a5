"""``tilted_forces``' fast path (issue 20, speed): Python-float inputs that pass the full
checks go straight to one core call (``SystemSolver.film_point``: the forces and the thinnest
film). Checked here against the full path and the separate core calls, bit for bit:

* the same pose given as numpy scalars (the full path: every validation, check_pose) gives
  the same forces, moments and minimum film, bit for bit, for a plain and an elliptical
  bearing, both senses of rotation, with and without velocities;
* ``film_point`` equals ``film_forces`` followed by the argmin of ``last_h_min`` (and its
  angle, mapped to the lobe's physical angle, and z) — the former wrapper's arithmetic;
* at every range limit the fast gate agrees with the full checks: a value on the limit
  passes, the next float beyond it is refused by the gate and raises the full path's
  InputError naming the field (the message of the full path's own validator).

Reference: the full path, unchanged from before the fast path (tests/test_tilt_use.py pins its
messages and answers).
"""

import math

import numpy as np
import pytest

import rotordyn
from rotordyn.bearings import FixedGeometryBearing
from rotordyn.bearings._film import min_film
from rotordyn._common import validate as v
from rotordyn.bearings.tilt import (MAX_ANGULAR_VELOCITY_RAD_S, _fast_inputs, _lobe_solver,
                                    _solver, _speed, tilted_forces)
from rotordyn.errors import InputError

D, L, C, MU = 0.05, 0.04, 1e-4, 0.02
GEO = dict(diameter_m=D, length_m=L, clearance_m=C, viscosity_pa_s=MU, n_circ=72, n_axial=16)
POSES = [(0.3, -0.5, 0.2, -0.3, 0.0, 0.0, 0.0, 0.0),
         (-0.4, 0.2, 0.4, 0.3, 0.01, -0.02, 0.5, -0.3),
         (0.1, 0.45, -0.3, 0.1, 0.0, 0.0, 0.0, 0.0)]
NAMES = ("x_m", "y_m", "theta_x_rad", "theta_y_rad", "vx_m_s", "vy_m_s", "wx_rad_s",
         "wy_rad_s")


def _bearings():
    return [rotordyn.JournalBearing(**GEO),
            FixedGeometryBearing(station=0, kind="elliptical", **GEO)]


def _kw(pose, speed, cast=float):
    x, y, tx, ty, vx, vy, wx, wy = pose
    vals = (x * C, y * C, tx * C / L, ty * C / L, vx, vy, wx, wy)
    return dict(zip(NAMES, (cast(q) for q in vals)), speed_hz=cast(speed))


def _same(a, b):
    assert np.array_equal(a.force_n, b.force_n)
    assert np.array_equal(a.film_moment_n_m, b.film_moment_n_m)
    assert (a.h_min_m, a.h_min_z_m) == (b.h_min_m, b.h_min_z_m)
    assert a.h_min_angle_deg == b.h_min_angle_deg or (
        math.isnan(a.h_min_angle_deg) and math.isnan(b.h_min_angle_deg))


@pytest.mark.parametrize("speed", [50.0, -30.0])
def test_fast_path_equals_full_path_and_separate_core_calls(speed):
    for b in _bearings():
        for pose in POSES:
            kw = _kw(pose, speed)
            assert _fast_inputs(b, *(kw[n] for n in NAMES), kw["speed_hz"])
            fast = tilted_forces(b, **kw)
            full = tilted_forces(b, **_kw(pose, speed, np.float64))  # not Python floats
            _same(fast, full)
            # the former wrapper: film_forces, then the thinnest film from last_h_min
            if isinstance(b, FixedGeometryBearing):
                s, phis = _lobe_solver(b)
            else:
                s, phis = _solver(b), None
            r = np.array([kw[n] for n in NAMES[:4]])
            rd = np.array([kw[n] for n in NAMES[4:]])
            s.forget_state()
            H = np.asarray(s.film_forces(r, rd, 2 * math.pi * speed))
            hm, ha, hz = min_film(s, phis)
            assert np.array_equal(H[:2], fast.force_n)
            assert np.array_equal(H[2:], fast.film_moment_n_m)
            assert (hm, hz) == (fast.h_min_m, fast.h_min_z_m)
            assert ha == fast.h_min_angle_deg
            assert fast.h_min_m > 0.0 and np.all(np.isfinite(H))


LIMITS = [("vx_m_s", 1e3), ("vx_m_s", -1e3), ("vy_m_s", 1e3), ("vy_m_s", -1e3),
          ("wx_rad_s", MAX_ANGULAR_VELOCITY_RAD_S), ("wx_rad_s", -MAX_ANGULAR_VELOCITY_RAD_S),
          ("wy_rad_s", MAX_ANGULAR_VELOCITY_RAD_S), ("wy_rad_s", -MAX_ANGULAR_VELOCITY_RAD_S),
          ("speed_hz", 1e5), ("speed_hz", -1e5)]


@pytest.mark.parametrize("field,limit", LIMITS)
def test_gate_agrees_with_the_full_checks_at_each_limit(field, limit):
    b = rotordyn.JournalBearing(**GEO)
    kw = _kw(POSES[0], 50.0)
    kw[field] = limit
    args = [kw[n] for n in NAMES] + [kw["speed_hz"]]
    assert _fast_inputs(b, *args)
    tilted_forces(b, **kw)  # on the limit: accepted by both
    kw[field] = float(np.nextafter(limit, math.copysign(math.inf, limit)))
    args = [kw[n] for n in NAMES] + [kw["speed_hz"]]
    assert not _fast_inputs(b, *args)
    with pytest.raises(InputError, match=f"^{field}: expected") as fast:
        tilted_forces(b, **kw)
    # the full path's own validator on the same value says the same
    with pytest.raises(InputError) as full:
        if field == "speed_hz":
            _speed(kw[field])
        else:
            v.in_range(field, kw[field], -abs(limit), abs(limit))
    assert str(fast.value) == str(full.value)


@pytest.mark.parametrize("bearing", _bearings())
def test_gate_refuses_what_the_full_checks_refuse(bearing):
    base = _kw(POSES[0], 50.0)
    bad = [("x_m", math.nan), ("y_m", math.inf), ("theta_x_rad", -math.inf),
           ("wy_rad_s", math.nan), ("speed_hz", math.nan), ("x_m", True), ("y_m", 1),
           ("theta_y_rad", 4.0 * C / L), ("x_m", 2.5 * C), ("vx_m_s", 1e308)]
    for field, val in bad:
        kw = dict(base, **{field: val})
        assert not _fast_inputs(bearing, *(kw[n] for n in NAMES), kw["speed_hz"])
        if field == "y_m" and val == 1:  # an int is valid, only not the fast path's float
            continue
        # a pose that closes the film names the rotations, or the position where the
        # journal's centre alone closes it
        closes = field in ("theta_y_rad", "x_m") and type(val) is float and abs(val) > C
        named = field if not closes else (
            "theta_x_rad, theta_y_rad" if field == "theta_y_rad" else "x_m, y_m")
        with pytest.raises(InputError, match=f"^{named}: "):
            tilted_forces(bearing, **kw)
    # the edge film: just inside the clearance at an edge passes both, just outside neither
    hl = 0.5 * L
    ty_in = (C * (1 - 1e-9)) / hl
    kw = dict(base, x_m=0.0, y_m=0.0, theta_x_rad=0.0, theta_y_rad=ty_in)
    if isinstance(bearing, FixedGeometryBearing):
        ok = bearing.edge_film(0.0, 0.0, 0.0, ty_in)[0] > 0.0
    else:
        ok = True
    assert _fast_inputs(bearing, *(kw[n] for n in NAMES), kw["speed_hz"]) == ok
