"""Thermal equilibrium of a fixed-geometry bearing with a tilted (misaligned) journal (issue 20;
docs/film-physics.md, "Thermal films with a tilted journal").

The journal is held at the tilt (θx, θy) relative to the bearing (the bearing's misalignment
seen by a journal parallel to the shaft line, as :func:`rotordyn.bearings.tilt.
misaligned_equilibrium`); every lobe's film thickness carries the tilt in its base thickness,
h(φ, z) = C_p − (C_p − C_b) cos(φ − φ_p) − (x + θy z) cos φ − (y − θx z) sin φ, and the
thermal model (THD: the energy equation on each lobe's full (φ, z) grid; or the
effective-temperature model per lobe) is iterated with the force balance on (x, y) under the
load in the C++ call of the untilted bearing (:func:`rotordyn.bearings.pad_thd.
pad_thd_equilibrium`). A tilted film is not symmetric in z: its grid is solved whole, and its
temperature field is not symmetrised.

At that thermal equilibrium, with the temperature (viscosity) field **frozen**, the lobes'
four-coordinate films give the moments on the journal, the edge film and the 4×4 K, C over
(x, y, θx, θy) (ΔH = −K Δr − C Δṙ, the convention of :mod:`rotordyn.bearings.tilt`)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import SystemParts, imposed_tilt, min_film
from rotordyn.bearings.pad_thd import pad_fields, pad_thd_equilibrium
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi


def tilted_thermal_equilibrium(bearing, *, theta_x_rad: float, theta_y_rad: float, oil, opts,
                               load_n, speed_hz: float):
    """The thermal equilibrium of ``bearing`` (a :class:`rotordyn.bearings.
    FixedGeometryBearing`) under ``load_n`` (N) with the journal tilted by (θx, θy) rad
    relative to it; ``opts``: the checked options (:func:`rotordyn.bearings.pad_thd.
    pad_model_options`). A :class:`rotordyn.bearings.pad_thd.PadThdResult` with the tilt,
    the moments (N·m), the edge film and K4, C4 at the frozen field."""
    tx, ty = v.finite("theta_x_rad", theta_x_rad), v.finite("theta_y_rad", theta_y_rad)
    h, z = bearing.edge_film(0.0, 0.0, tx, ty)
    if not h > 0.0:
        raise InputError(f"theta_x_rad, theta_y_rad: the tilted journal closes a lobe's film at "
                         f"the edge z = {z:+g} m (minimum film {h:.6g} m of a centred journal); "
                         "expected a tilt whose edge film stays > 0 over the lobes at z = ±L/2")
    name = bearing.name or "bearing"
    lobes = bearing.films(0, 1, name, rot=(2, 3))
    for p in lobes:
        imposed_tilt(p.coupling, tx, ty)
    res = pad_thd_equilibrium(SystemParts(films=lobes, tables=[]), oil=oil, opts=opts,
                              load_n=load_n, speed_hz=speed_hz,
                              clearance_m=bearing.clearance_m, whirl_ratio=None)
    # the frozen field on the lobes' four-coordinate films: moments, edge film, K4, C4
    four = bearing.films(0, 1, name, rot=(2, 3))
    pad_fields(res.viscosity_pa_s, four, "viscosity_field_pa_s")
    model = _core.SystemModel()
    z = np.zeros((4, 4))
    model.M, model.K, model.C, model.G = z, z, z, z
    model.Q, model.chamber = np.zeros(4), np.zeros(4)
    model.films = [p.coupling for p in four]
    solver = _core.SystemSolver(model)
    r4 = np.array([res.x_m, res.y_m, tx, ty])
    w = TWO_PI * float(speed_hz)
    H = np.asarray(solver.film_forces(r4, np.zeros(4), w))
    h_min, _, h_z = min_film(solver, [p.phi for p in four])
    lin = solver.linearize(r4, np.zeros(4), w)
    return dataclasses.replace(res, theta_x_rad=tx, theta_y_rad=ty, moment_n_m=H[2:].copy(),
                               h_min_m=h_min, h_min_z_m=h_z, K4=np.array(lin.KH),
                               C4=np.array(lin.DH))


__all__ = ["tilted_thermal_equilibrium"]
