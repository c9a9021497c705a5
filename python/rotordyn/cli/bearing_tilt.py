"""``rotordyn bearing --theta-x-rad/--theta-y-rad``: one operating point of a plain journal
bearing with the journal tilted relative to the bearing (issue 20; docs/film-physics.md,
"Journal tilt and bearing misalignment"): forces, moments, the edge film and the 4×4 K, C
over (x, y, θx, θy) — of the isothermal film (:func:`run_tilted`) or at the thermal
equilibrium with the tilted journal (``--supply-temperature-c`` with an oil law, effective or
THD: :func:`thermal_tilt`, :func:`thermal_tilt_record`, :func:`print_thermal_tilt`, called by
the thermal paths of :mod:`rotordyn.cli.bearing`)."""

from __future__ import annotations

import argparse

import numpy as np

from rotordyn.bearings import JournalBearing
from rotordyn.errors import InputError


def add_tilt_arguments(s: argparse.ArgumentParser) -> None:
    s.add_argument("--theta-x-rad", type=float, default=None, metavar="RAD",
                   help="journal tilt about x relative to the bearing, rad (a misaligned "
                        "bearing: prints the moments, the edge film and 4x4 K, C)")
    s.add_argument("--theta-y-rad", type=float, default=None, metavar="RAD",
                   help="journal tilt about y relative to the bearing, rad")


def wants_tilt(args: argparse.Namespace) -> bool:
    return args.theta_x_rad is not None or args.theta_y_rad is not None


def _tilt(args: argparse.Namespace) -> tuple[float, float]:
    return (0.0 if args.theta_x_rad is None else args.theta_x_rad,
            0.0 if args.theta_y_rad is None else args.theta_y_rad)


def thermal_tilt(args: argparse.Namespace) -> dict:
    """The keywords of ``JournalBearing.thermal_equilibrium`` for the tilt options (none
    without them; ``tilt=True``: the tilted film's outputs even at a zero tilt given)."""
    if not wants_tilt(args):
        return {}
    tx, ty = _tilt(args)
    return {"theta_x_rad": tx, "theta_y_rad": ty, "tilt": True}


def thermal_tilt_record(r, rec: dict, hot: JournalBearing | None = None) -> None:
    """The tilted thermal equilibrium ``r``'s tilt outputs into ``rec`` under the isothermal
    tilted record's names (moments, edge film and its z, the 4×4 K, C at the frozen field);
    with ``hot`` (the effective model's film, isoviscous at μ(T_eff)) the film's forces at
    the tilted pose as ``force_n`` (the THD record, tilted or not, has none)."""
    from rotordyn.bearings.tilt import tilted_forces

    rec.update(journal_theta_x_rad=r.theta_x_rad, journal_theta_y_rad=r.theta_y_rad,
               moment_n_m=np.asarray(r.moment_n_m).tolist(), h_min_m=r.h_min_m,
               h_min_angle_deg=r.h_min_angle_deg, h_min_z_m=r.h_min_z_m,
               coordinates=list(COORDINATES), **coefficient_record(r.K4, r.C4))
    if hot is not None:
        t = tilted_forces(hot, x_m=r.x_m, y_m=r.y_m, speed_hz=r.speed_hz,
                          theta_x_rad=r.theta_x_rad, theta_y_rad=r.theta_y_rad)
        rec["force_n"] = np.asarray(t.force_n).tolist()


def print_thermal_tilt(r, rec: dict) -> int:
    """The text lines of :func:`thermal_tilt_record`'s outputs."""
    if "force_n" in rec:
        print(f"force on journal: Fx = {rec['force_n'][0]:.6g} N, Fy = {rec['force_n'][1]:.6g} N")
    _print_tilt(r.theta_x_rad, r.theta_y_rad, r.moment_n_m, r.h_min_m, r.h_min_angle_deg,
                r.h_min_z_m, r.K4, r.C4, "at the thermal equilibrium, temperature frozen")
    return 0


def _print_tilt(tx, ty, moment, h_min, h_angle, h_z, K, C, where: str = "") -> None:
    print(f"journal tilt relative to the bearing: theta_x = {tx:.6g} rad, theta_y = {ty:.6g} rad")
    print(f"moment: Mx = {moment[0]:.6g} N m, My = {moment[1]:.6g} N m")
    print(f"h_min = {h_min:.6g} m at {h_angle:.2f} deg, z = {h_z:.6g} m (mid-plane 0)")
    tail = f" ({where})" if where else ""
    print(f"K over (x, y, theta_x, theta_y) [N/m, N/rad, N m/m, N m/rad]{tail} =\n"
          + np.array2string(np.asarray(K), precision=5))
    print(f"C over (x, y, theta_x, theta_y) [N s/m, N s/rad, N m s/m, N m s/rad]{tail} =\n"
          + np.array2string(np.asarray(C), precision=5))


def run_tilted(b: JournalBearing, args: argparse.Namespace, rec: dict) -> int:
    """The tilted operating point of the isothermal film (``--load-n``: the misaligned
    equilibrium first; a failed one is reported and not linearised, exit 1)."""
    from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_coefficients, tilted_forces
    from rotordyn.cli.common import journal_pose, json_text

    if args.speeds_hz is not None:
        raise InputError("--theta-x-rad/--theta-y-rad: a tilted journal is available at one "
                         "operating point (--speed-hz), not in a coefficient table "
                         "(--speeds-hz: the aligned film's)")
    tx, ty = _tilt(args)
    rec.update(journal_theta_x_rad=tx, journal_theta_y_rad=ty)
    x, y, vx, vy, e = journal_pose(args, lambda load: misaligned_equilibrium(
        b, load_n=load, speed_hz=args.speed_hz, theta_x_rad=tx, theta_y_rad=ty))
    if e is not None:
        rec["equilibrium"] = {"load_n": list(args.load_n), "status": e.status,
                              "message": e.message, "x_m": e.x_m, "y_m": e.y_m,
                              "eccentricity_ratio": e.eccentricity_ratio,
                              "attitude_angle_deg": e.attitude_angle_deg,
                              "iterations": e.iterations}
        if e.status != "ok":
            if args.json:
                print(json_text(rec))
            else:
                print(f"misaligned equilibrium: {e.status} ({e.message}); no film outputs "
                      "or coefficients at a failed equilibrium")
            return 1
        t = e  # its film outputs at (x, y): forces, moments, minimum film and where
    else:
        t = tilted_forces(b, x_m=x, y_m=y, speed_hz=args.speed_hz, theta_x_rad=tx,
                          theta_y_rad=ty, vx_m_s=vx, vy_m_s=vy)
    K, C = tilted_coefficients(b, x_m=x, y_m=y, speed_hz=args.speed_hz, theta_x_rad=tx,
                               theta_y_rad=ty, method=args.method)
    rec.update(journal_x_m=x, journal_y_m=y, journal_vx_m_s=vx, journal_vy_m_s=vy,
               force_n=np.asarray(t.force_n).tolist(), moment_n_m=np.asarray(t.moment_n_m).tolist(),
               h_min_m=t.h_min_m, h_min_angle_deg=t.h_min_angle_deg, h_min_z_m=t.h_min_z_m,
               coordinates=list(COORDINATES), **coefficient_record(K, C),
               coefficient_method=args.method)
    if args.json:
        print(json_text(rec))
        return 0
    if "equilibrium" in rec:
        e = rec["equilibrium"]
        print(f"misaligned equilibrium: x = {x:.6g} m, y = {y:.6g} m, eps (mid-plane) = "
              f"{e['eccentricity_ratio']:.4g}, attitude = {e['attitude_angle_deg']:.2f} deg")
    print(f"force on journal: Fx = {t.force_n[0]:.6g} N, Fy = {t.force_n[1]:.6g} N")
    _print_tilt(tx, ty, t.moment_n_m, t.h_min_m, t.h_min_angle_deg, t.h_min_z_m, K, C)
    return 0


COORDINATES = ("x", "y", "theta_x", "theta_y")
# SI units of K[i, j] = -dH_i/dr_j over (x, y, θx, θy): forces on translations and
# rotations, moments on translations and rotations; C the same per unit velocity
_K_UNITS = (("N/m", "N/m", "N/rad", "N/rad"),) * 2 + (("N m/m", "N m/m", "N m/rad",
                                                      "N m/rad"),) * 2
_C_UNITS = (("N s/m", "N s/m", "N s/rad", "N s/rad"),) * 2 + (("N m s/m", "N m s/m",
                                                              "N m s/rad", "N m s/rad"),) * 2


def coefficient_record(K, C) -> dict:
    """The tilted film's coefficients as JSON fields named as the aligned command's: the
    translational 2×2 block as ``k_n_per_m``, ``c_n_s_per_m`` (the same meaning and units
    as there), the whole 4×4 over ``coordinates`` as ``k_4x4_si``, ``c_4x4_si`` with each
    entry's unit in ``k_4x4_units``, ``c_4x4_units`` (4×4 strings)."""
    K, C = np.asarray(K, dtype=float), np.asarray(C, dtype=float)
    return {"k_n_per_m": K[:2, :2].tolist(), "c_n_s_per_m": C[:2, :2].tolist(),
            "k_4x4_si": K.tolist(), "c_4x4_si": C.tolist(),
            "k_4x4_units": [list(r) for r in _K_UNITS],
            "c_4x4_units": [list(r) for r in _C_UNITS]}


__all__ = ["add_tilt_arguments", "print_thermal_tilt", "run_tilted", "thermal_tilt",
           "thermal_tilt_record", "wants_tilt"]
