"""The tilted film of a plain journal bearing (issue 20; :mod:`rotordyn.bearings.tilt` for the
convention): its four-coordinate film coupling over (x, y, θx, θy) and the check of a pose's
edge film. Below the bearing classes (it takes a :class:`rotordyn.JournalBearing` or a model's
:class:`rotordyn.FluidFilmBearing` by what they have), so the bearings' own thermal
equilibria (:mod:`rotordyn.bearings.tilt_thermal`) use it without an import circle."""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi


def axial_positions(bearing) -> np.ndarray:
    """z of the grid's node rows, m, (n_axial + 1,), z = 0 the bearing's mid-plane."""
    return np.linspace(-0.5 * bearing.length_m, 0.5 * bearing.length_m, bearing.n_axial + 1)


def tilt_coupling(bearing, coords: Sequence[int],
                  name: str = "", base_h: np.ndarray | None = None) -> _core.FilmCoupling:
    """The film of ``bearing`` on four system coordinates (x, y, θx, θy) = ``coords``:
    shape (n_circ, 4) = (−cos φ, −sin φ, sin φ, −cos φ), axial weights (4, n_axial + 1) =
    (1, 1, z, z). ``base_h`` (n_circ, n_axial + 1) replaces the clearance (misalignment
    imposed through the thickness). A :class:`FluidFilmBearing`'s frozen viscosity field
    (``viscosity_field_pa_s``) is the film's, as in a system."""
    film = bearing.journal_bearing() if hasattr(bearing, "journal_bearing") else bearing
    g, grid = film.to_core()
    f = _core.FilmCoupling()
    f.name = name or "bearing"
    f.geometry, f.grid, f.cavitation = g, grid, bearing.cavitation
    f.coords = [int(c) for c in coords]
    phi = TWO_PI * np.arange(bearing.n_circ) / bearing.n_circ
    c, s = np.cos(phi), np.sin(phi)
    f.shape = np.ascontiguousarray(np.column_stack([-c, -s, s, -c]))
    z = axial_positions(bearing)
    f.axial_weight = np.ascontiguousarray(np.vstack([np.ones_like(z), np.ones_like(z), z, z]))
    if base_h is not None:
        f.base_h = np.ascontiguousarray(base_h, dtype=float)
    vf = getattr(bearing, "viscosity_field_pa_s", None)
    if vf is not None:
        f.viscosity_field = np.asarray(vf, dtype=float)
    return f


def edge_eccentricity(bearing, x: float, y: float, theta_x: float,
                      theta_y: float) -> float:
    """Largest eccentricity ratio of the journal axis over the bearing length (at an edge:
    the axis is straight, so the largest one is at z = ±L/2)."""
    hl = 0.5 * bearing.length_m
    return max(math.hypot(x + theta_y * z, y - theta_x * z) for z in (-hl, hl)) \
        / bearing.clearance_m


def check_plain_pose(bearing, x: float, y: float, tx: float, ty: float,
                     names=("x_m", "y_m", "theta_x_rad", "theta_y_rad")) -> tuple[float, ...]:
    """(x, y, θx, θy) (finite, checked by the caller) whose journal axis stays inside the
    plain bearing's clearance at both edges; InputError otherwise, naming the position where
    the journal's centre alone closes the film, else the rotations."""
    e0 = math.hypot(x, y) / bearing.clearance_m
    if not e0 < 1.0:
        raise InputError(
            f"{names[0]}, {names[1]}: the journal's centre closes the film (eccentricity "
            f"ratio {e0:.6g}); expected |(x, y)| < clearance_m = {bearing.clearance_m:g} m, "
            f"and |(x + theta_y z, y - theta_x z)| < clearance_m at z = ±L/2")
    hl = 0.5 * bearing.length_m
    for z in (-hl, hl):
        e = math.hypot(x + ty * z, y - tx * z) / bearing.clearance_m
        if not e < 1.0:
            raise InputError(
                f"{names[2]}, {names[3]}: the tilted journal closes the film at the edge "
                f"z = {z:+g} m (edge eccentricity ratio {e:.6g}); expected an edge eccentricity"
                f" ratio < 1, i.e. |(x + theta_y z, y - theta_x z)| < clearance_m ="
                f" {bearing.clearance_m:g} m at z = ±L/2")
    return x, y, tx, ty


__all__ = ["axial_positions", "check_plain_pose", "edge_eccentricity", "tilt_coupling"]
