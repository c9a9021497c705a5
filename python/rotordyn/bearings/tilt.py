"""Journal tilt and bearing misalignment of a plain journal bearing (issue 20).

Coordinates of the journal at the bearing centre: translations (x, y) and rotations (θx, θy)
about the bearing frame's x and y axes, right-hand rule, z along the shaft axis (the rotor
FEM's convention, ``rotor.hpp``: dx/dz = θy, dy/dz = −θx). At the axial position z
(z = 0 the bearing's mid-plane, −L/2 ≤ z ≤ L/2) the journal centre sits at
(x + θy z, y − θx z), so the film thickness is

    h(φ, z) = c − (x + θy z) cos φ − (y − θx z) sin φ.

By virtual work the generalised film forces on the four coordinates are
H_k = ∫∫ p ∂h/∂r_k dA: the forces (Fx, Fy) = −∫∫ p (cos φ, sin φ) dA and the moments about
the bearing centre Mx = ∫∫ p z sin φ dA, My = −∫∫ p z cos φ dA (= (r × dF) with dF the
pressure force on the journal surface). Linear coefficients over (x, y, θx, θy) are
defined by ΔH = −K Δr − C Δṙ (4×4; each entry's unit from :data:`rotordyn.units.
TILT_UNIT_STEMS`: N/m, N/rad, N·m/m, N·m/rad, and per m/s or rad/s for C). A bearing's own
angular misalignment (housing rotated by (αx, αy)) is the same film seen by a journal at
rotation θ − α relative to the housing.

Names: the keyword arguments ``theta_x_rad``, ``theta_y_rad`` are *inputs* (the tilt imposed
on the journal, relative to the bearing); the results name the tilt and the film's moments
as the system's outputs do, ``journal_theta_x_rad``, ``journal_theta_y_rad``,
``film_moment_n_m`` (frames: ``film_moment_x_n_m``, ``film_moment_y_n_m``;
:mod:`rotordyn.bearings.tilt_names`).

A :class:`rotordyn.bearings.FixedGeometryBearing` (partial arc, lobed, offset halves,
pressure dam) takes the same functions: its lobes' films with the rotations' shapes on their
nodes (``FixedGeometryBearing.films(..., rot=...)``), the forces and moments summed over the
lobes, the minimum film the thinnest lobe's.

The numerical work is the system film of the C++ core (``_core.SystemSolver``: one Reynolds
solve on the full (φ, z) grid, the perturbation linearisation reusing its factorisation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
import threading

from rotordyn.bearings._film import imposed_tilt, lobe_angle
from rotordyn.bearings.active import ActiveJournalBearing
from rotordyn.bearings.fixed_geometry import FixedGeometryBearing
from rotordyn.bearings.fluid_film import FluidFilmBearing
from rotordyn.bearings.journal import MAX_SPEED_HZ, JournalBearing
from rotordyn.bearings.tilt_film import (axial_positions, check_plain_pose,  # noqa: F401
                                         edge_eccentricity, tilt_coupling)
from rotordyn.bearings.tilt_pads import (pad_misaligned_equilibrium, pad_tilted_coefficients,
                                         pad_tilted_forces)
from rotordyn.bearings.tilting_pad import TiltingPadBearing
from rotordyn.bearings.tilt_names import RenamedTiltOutputs
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi
FilmBearing = JournalBearing | FixedGeometryBearing | TiltingPadBearing | FluidFilmBearing
COORDINATES = ("x", "y", "theta_x", "theta_y")
MAX_ANGULAR_VELOCITY_RAD_S = 1e5


def check_pose(bearing: JournalBearing, x_m, y_m, theta_x_rad, theta_y_rad,
               names=("x_m", "y_m", "theta_x_rad", "theta_y_rad")) -> tuple[float, ...]:
    """Finite coordinates whose journal axis stays inside the clearance at both edges;
    InputError naming the field otherwise."""
    vals = tuple(v.finite(n, val) for n, val in zip(names, (x_m, y_m, theta_x_rad, theta_y_rad)))
    x, y, tx, ty = vals
    if isinstance(bearing, FixedGeometryBearing):
        h0 = bearing.edge_film(x, y, 0.0, 0.0)[0]
        if not h0 > 0.0:
            raise InputError(
                f"{names[0]}, {names[1]}: the journal's centre closes a lobe's film (minimum "
                f"film {h0:.6g} m); expected a position whose film stays > 0 over the lobes, "
                f"and with the tilt at z = ±L/2")
        h, z = bearing.edge_film(x, y, tx, ty)
        if not h > 0.0:
            raise InputError(
                f"{names[2]}, {names[3]}: the tilted journal closes a lobe's film at the edge "
                f"z = {z:+g} m (minimum film {h:.6g} m); expected a pose whose film stays > 0 "
                f"over the lobes at z = ±L/2")
        return vals
    return check_plain_pose(bearing, x, y, tx, ty, names)


def film_bearing(bearing):
    """The standalone film of ``bearing``: a :class:`JournalBearing`,
    :class:`FixedGeometryBearing` or :class:`TiltingPadBearing` as it is, or a model's plain
    bearing (``type = "journal"``, :class:`FluidFilmBearing`, e.g. ``System.bearings[i]`` or
    the frozen one of a thermal equilibrium's ``system``, whose viscosity field the film
    keeps). Anything else (an active bearing, whose sleeve is a system's coordinates, a
    table, a string) is an InputError naming ``bearing``, not an AttributeError from inside."""
    if isinstance(bearing, ActiveJournalBearing):
        raise InputError("bearing: an active journal bearing's tilted film includes its "
                         "sleeve, a system's coordinates: use tilt = true in a system")
    if not isinstance(bearing, (JournalBearing, FixedGeometryBearing, TiltingPadBearing,
                                FluidFilmBearing)):
        raise InputError(f"bearing: expected a JournalBearing, FluidFilmBearing, "
                         f"FixedGeometryBearing or TiltingPadBearing, got "
                         f"{type(bearing).__name__}")
    return bearing


def _speed(speed_hz) -> float:
    f = v.finite("speed_hz", speed_hz)
    if abs(f) > MAX_SPEED_HZ:
        raise InputError(f"speed_hz: expected |speed_hz| <= {MAX_SPEED_HZ:g}, got {f!r}")
    return f


_lobes_local = threading.local()


def _lobe_solver(bearing: FixedGeometryBearing):
    """This thread's four-coordinate lobe films of ``bearing`` (a few bearings kept) and the
    lobes' physical node angles (rad; NaN on the gap nodes)."""
    cache = getattr(_lobes_local, "cache", None)
    if cache is None:
        cache = _lobes_local.cache = {}
    hit = cache.get(bearing)
    if hit is None:
        pads = bearing.films(0, 1, bearing.name or "bearing", rot=(2, 3))
        model = _core.SystemModel()
        z = np.zeros((4, 4))
        model.M, model.K, model.C, model.G = z, z, z, z
        model.Q, model.chamber = np.zeros(4), np.zeros(4)
        model.films = [p.coupling for p in pads]
        if len(cache) >= 8:
            cache.pop(next(iter(cache)))
        hit = cache[bearing] = (_core.SystemSolver(model), [p.phi for p in pads])
    return hit


def _solver(bearing) -> _core.SystemSolver:
    """This thread's four-coordinate film of ``bearing`` (built on first use)."""
    if isinstance(bearing, FixedGeometryBearing):
        return _lobe_solver(bearing)[0]
    local = getattr(bearing, "_local", None)  # a FluidFilmBearing (slots) keeps no solver
    s = None if local is None else getattr(local, "tilt_solver", None)
    if s is None:
        model = _core.SystemModel()
        z = np.zeros((4, 4))
        model.M, model.K, model.C, model.G = z, z, z, z
        model.Q, model.chamber = np.zeros(4), np.zeros(4)
        model.films = [tilt_coupling(bearing, [0, 1, 2, 3])]
        s = _core.SystemSolver(model)
        if local is not None:
            local.tilt_solver = s
    return s


@dataclass(frozen=True)
class TiltedFilm(RenamedTiltOutputs):
    """Film of a tilted journal: forces (Fx, Fy) N and moments (Mx, My) N·m on the journal
    about the bearing centre; minimum film (m) and where it is (φ deg from +x, z m)."""

    force_n: np.ndarray
    film_moment_n_m: np.ndarray
    h_min_m: float
    h_min_angle_deg: float
    h_min_z_m: float

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame([{
            "force_x_n": self.force_n[0], "force_y_n": self.force_n[1],
            "film_moment_x_n_m": self.film_moment_n_m[0],
            "film_moment_y_n_m": self.film_moment_n_m[1],
            "h_min_m": self.h_min_m, "h_min_angle_deg": self.h_min_angle_deg,
            "h_min_z_m": self.h_min_z_m}])


def tilted_forces(bearing: FilmBearing, *,
                  x_m: float, y_m: float,
                  speed_hz: float,
                  theta_x_rad: float = 0.0, theta_y_rad: float = 0.0, vx_m_s: float = 0.0,
                  vy_m_s: float = 0.0, wx_rad_s: float = 0.0, wy_rad_s: float = 0.0
                  ) -> TiltedFilm:
    """Forces and moments on a rigid journal at (x, y) tilted by (θx, θy) rad, moving at
    (vx, vy) m/s and (ωx, ωy) rad/s (the squeeze term ∂h/∂t of the same thickness).

    A :class:`TiltingPadBearing`: the journal held at rest at the pose, every pad at its
    equilibrium (:func:`rotordyn.bearings.tilt_pads.pad_tilted_forces`; a
    :class:`~rotordyn.bearings.tilt_pads.PadTiltedFilm` with the pads' tilts, pitches and
    films); velocities are refused (the pads' motion is a state of the system transient)."""
    kind = type(bearing)
    if (kind is JournalBearing or kind is FixedGeometryBearing) and _fast_inputs(
            bearing, x_m, y_m, theta_x_rad, theta_y_rad, vx_m_s, vy_m_s, wx_rad_s, wy_rad_s,
            speed_hz):
        r = (x_m, y_m, theta_x_rad, theta_y_rad)
        rd = (vx_m_s, vy_m_s, wx_rad_s, wy_rad_s)
        f = speed_hz
    else:
        bearing = film_bearing(bearing)
        if isinstance(bearing, TiltingPadBearing):
            for name, val in (("vx_m_s", vx_m_s), ("vy_m_s", vy_m_s), ("wx_rad_s", wx_rad_s),
                              ("wy_rad_s", wy_rad_s)):
                if v.finite(name, val) != 0.0:
                    raise InputError(f"{name}: expected 0 for a tilting-pad bearing (the pads' "
                                     f"velocities are states of the system transient), got "
                                     f"{val!r}")
            return pad_tilted_forces(bearing, x_m=x_m, y_m=y_m, speed_hz=speed_hz,
                                     theta_x_rad=theta_x_rad, theta_y_rad=theta_y_rad)
        r = check_pose(bearing, x_m, y_m, theta_x_rad, theta_y_rad)
        rd = (v.in_range("vx_m_s", vx_m_s, -1e3, 1e3),
              v.in_range("vy_m_s", vy_m_s, -1e3, 1e3),
              v.in_range("wx_rad_s", wx_rad_s, -MAX_ANGULAR_VELOCITY_RAD_S,
                         MAX_ANGULAR_VELOCITY_RAD_S),
              v.in_range("wy_rad_s", wy_rad_s, -MAX_ANGULAR_VELOCITY_RAD_S,
                         MAX_ANGULAR_VELOCITY_RAD_S))
        f = _speed(speed_hz)
    if isinstance(bearing, FixedGeometryBearing):
        s, phis = _lobe_solver(bearing)
    else:
        s, phis = _solver(bearing), None
    # the forces and the thinnest film in one core call
    H, i, hm, ha, hz = s.film_point(r, rd, TWO_PI * f)
    if phis is not None:
        ha = lobe_angle(ha, phis[i])
    return TiltedFilm(force_n=H[:2].copy(), film_moment_n_m=H[2:].copy(), h_min_m=hm,
                      h_min_angle_deg=ha, h_min_z_m=hz)


def _fast_inputs(bearing, x, y, tx, ty, vx, vy, wx, wy, f) -> bool:
    """True when the full path's checks pass unchanged (the hot path of a plain or
    fixed-geometry bearing, a few number checks instead of nine validations): every input a
    Python float, all finite (their sum finite: a NaN or an infinity makes it non-finite,
    an overflow only sends the call to the full path), the velocities and the speed in
    their ranges and the journal axis inside the clearance at both edges (check_pose's
    arithmetic). False sends the call to the full path, whose checks raise the InputError
    naming the field."""
    if not (type(x) is float and type(y) is float and type(tx) is float and type(ty) is float
            and type(vx) is float and type(vy) is float and type(wx) is float
            and type(wy) is float and type(f) is float
            and math.isfinite(x + y + tx + ty + vx + vy + wx + wy + f)
            and -1e3 <= vx <= 1e3 and -1e3 <= vy <= 1e3
            and -MAX_ANGULAR_VELOCITY_RAD_S <= wx <= MAX_ANGULAR_VELOCITY_RAD_S
            and -MAX_ANGULAR_VELOCITY_RAD_S <= wy <= MAX_ANGULAR_VELOCITY_RAD_S
            and abs(f) <= MAX_SPEED_HZ):
        return False
    if type(bearing) is FixedGeometryBearing:
        return bearing.edge_film(x, y, tx, ty)[0] > 0.0
    hl, c = 0.5 * bearing.length_m, bearing.clearance_m
    for z in (-hl, hl):
        if not math.hypot(x + ty * z, y - tx * z) / c < 1.0:
            return False
    return True


def tilted_coefficients(bearing: FilmBearing,
                        *, x_m: float,
                        y_m: float, speed_hz: float,
                        theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                        method: str = "perturbation", rel_step: float = 1e-6
                        ) -> tuple[np.ndarray, np.ndarray]:
    """K, C (4×4 over x, y, θx, θy) with ΔH = −K Δr − C Δṙ at a tilted journal.

    ``method="perturbation"``: the linearised Reynolds solves on the film's factorisation;
    ``"finite_difference"``: central differences of (F, M), steps rel_step·c on x, y and
    rel_step·c (rad) on the rotations, rel_step·c·|ω| on the velocities.

    A :class:`TiltingPadBearing`: the pads at their equilibrium for the pose and their
    coordinates condensed at the synchronous frequency
    (:func:`rotordyn.bearings.tilt_pads.pad_tilted_coefficients` takes the whirl ratio)."""
    bearing = film_bearing(bearing)
    if isinstance(bearing, TiltingPadBearing):
        return pad_tilted_coefficients(bearing, x_m=x_m, y_m=y_m, speed_hz=speed_hz,
                                       theta_x_rad=theta_x_rad, theta_y_rad=theta_y_rad,
                                       method=method, rel_step=rel_step)
    r = np.array(check_pose(bearing, x_m, y_m, theta_x_rad, theta_y_rad))
    w = TWO_PI * _speed(speed_hz)
    s = _solver(bearing)
    if method == "perturbation":
        lin = s.linearize(r, np.zeros(4), w)
    elif method == "finite_difference":
        lin = s.linearize_fd(r, w, v.in_range("rel_step", rel_step, 1e-10, 0.1, hi_open=True))
    else:
        raise InputError(f"method: expected 'perturbation' or 'finite_difference', got {method!r}")
    return np.array(lin.KH), np.array(lin.DH)


@dataclass(frozen=True)
class MisalignedEquilibrium(RenamedTiltOutputs):
    """Journal position under a static load at an imposed tilt (θx, θy) relative to the
    bearing (the bearing's misalignment seen by a journal held parallel to the shaft line):
    position (m), eccentricity ratio and attitude at the mid-plane, the film's forces (N) and
    moments (N·m) on the journal, the minimum film and where it is."""

    x_m: float
    y_m: float
    journal_theta_x_rad: float
    journal_theta_y_rad: float
    eccentricity_ratio: float
    attitude_angle_deg: float
    force_n: np.ndarray
    film_moment_n_m: np.ndarray
    h_min_m: float
    h_min_angle_deg: float
    h_min_z_m: float
    status: str
    message: str
    iterations: int

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame([{
            "x_m": self.x_m, "y_m": self.y_m, "journal_theta_x_rad": self.journal_theta_x_rad,
            "journal_theta_y_rad": self.journal_theta_y_rad,
            "eccentricity_ratio": self.eccentricity_ratio,
            "attitude_angle_deg": self.attitude_angle_deg,
            "force_x_n": self.force_n[0], "force_y_n": self.force_n[1],
            "film_moment_x_n_m": self.film_moment_n_m[0],
            "film_moment_y_n_m": self.film_moment_n_m[1],
            "h_min_m": self.h_min_m, "h_min_angle_deg": self.h_min_angle_deg,
            "h_min_z_m": self.h_min_z_m, "status": self.status, "message": self.message}])


def misaligned_equilibrium(bearing: FilmBearing,
                           *,
                           load_n: Sequence[float],
                           speed_hz: float, theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                           tol: float = 1e-10) -> MisalignedEquilibrium:
    """(x, y) where the film force balances ``load_n`` (N, on the journal) with the journal
    tilted by (θx, θy) rad: the C++ Newton equilibrium of the film on (x, y) whose thickness
    at zero (x, y) is c + θx z sin φ − θy z cos φ; then the moments at that point.
    A :class:`TiltingPadBearing`: the pads free
    (:func:`rotordyn.bearings.tilt_pads.pad_misaligned_equilibrium`)."""
    bearing = film_bearing(bearing)
    if isinstance(bearing, TiltingPadBearing):
        return pad_misaligned_equilibrium(bearing, load_n=load_n, speed_hz=speed_hz,
                                          theta_x_rad=theta_x_rad, theta_y_rad=theta_y_rad,
                                          tol=tol)
    if isinstance(load_n, (str, bytes)) or len(np.atleast_1d(load_n)) != 2:
        raise InputError(f"load_n: expected two numbers (Fx, Fy) in N, got {load_n!r}")
    lx, ly = v.finite("load_n[0]", load_n[0]), v.finite("load_n[1]", load_n[1])
    _, _, tx, ty = check_pose(bearing, 0.0, 0.0, theta_x_rad, theta_y_rad)
    f = _speed(speed_hz)
    if f == 0.0:
        raise InputError("speed_hz: a static equilibrium needs 0 < |speed_hz|, got 0")
    if isinstance(bearing, FixedGeometryBearing):
        films = [imposed_tilt(p.coupling, tx, ty)
                 for p in bearing.films(0, 1, bearing.name or "bearing", rot=(2, 3))]
    else:
        films = [imposed_tilt(tilt_coupling(bearing, [0, 1, 2, 3]), tx, ty)]
    model = _core.SystemModel()
    z2 = np.zeros((2, 2))
    model.M, model.K, model.C, model.G = z2, z2, z2, z2
    model.Q, model.chamber = np.array([lx, ly]), np.zeros(2)
    model.films = films
    opt = _core.EquilibriumOptions()
    opt.tol = v.in_range("tol", tol, 1e-14, 1e-2)
    opt.polish = True
    e = _core.SystemSolver(model).equilibrium(TWO_PI * f, 0.0, np.zeros(2), np.zeros(0), opt)
    x, y = (float(q) for q in e.r)
    status, message = str(e.status), str(e.message)
    nan2 = np.full(2, np.nan)
    if status not in ("ok", "contact"):
        return MisalignedEquilibrium(x, y, tx, ty, math.nan, math.nan, nan2, nan2, math.nan,
                                     math.nan, math.nan, status, message, int(e.iterations))
    film_at = tilted_forces(bearing, x_m=x, y_m=y, speed_hz=f, theta_x_rad=tx,
                            theta_y_rad=ty)
    W = math.hypot(lx, ly)
    if W > 0.0 and (x != 0.0 or y != 0.0):
        dx, dy = lx / W, ly / W
        att = math.degrees(math.atan2(dx * y - dy * x, dx * x + dy * y))
        att = -att if f < 0 else att
    else:
        att = math.nan
    return MisalignedEquilibrium(
        x_m=x, y_m=y, journal_theta_x_rad=tx, journal_theta_y_rad=ty,
        eccentricity_ratio=math.hypot(x, y) / bearing.clearance_m, attitude_angle_deg=att,
        force_n=film_at.force_n, film_moment_n_m=film_at.film_moment_n_m, h_min_m=film_at.h_min_m,
        h_min_angle_deg=film_at.h_min_angle_deg, h_min_z_m=film_at.h_min_z_m, status=status,
        message=message, iterations=int(e.iterations))


__all__ = [
    "TiltedFilm",
    "MisalignedEquilibrium",
    "tilted_forces",
    "tilted_coefficients",
    "misaligned_equilibrium",
    "tilt_coupling",
    "imposed_tilt",
]
