"""``rotordyn bearing --theta-x-rad/--theta-y-rad``: one operating point of a fluid-film
bearing with the journal tilted relative to the bearing (issue 20; docs/film-physics.md,
"Journal tilt and bearing misalignment"): forces, moments, the edge film and the 4×4 K, C
over (x, y, θx, θy) of the isothermal film (:func:`run_tilted`) — a plain journal bearing
given by its dimensions, or a model file's plain, tilting-pad or fixed-geometry bearing
(``--model-file``). With a thermal model: :mod:`rotordyn.cli.bearing_thermal`. The record's
names are the system's (:mod:`rotordyn.bearings.tilt_names`): ``journal_theta_x_rad``,
``journal_theta_y_rad``, ``film_moment_n_m``."""

from __future__ import annotations

import argparse

import numpy as np

from rotordyn.errors import InputError
from rotordyn.units import TILT_COORDINATES, tilt_units


def add_tilt_arguments(s: argparse.ArgumentParser) -> None:
    s.add_argument("--theta-x-rad", type=float, default=None, metavar="RAD",
                   help="journal tilt about x relative to the bearing, rad (a misaligned "
                        "bearing: prints the moments, the edge film and 4x4 K, C)")
    s.add_argument("--theta-y-rad", type=float, default=None, metavar="RAD",
                   help="journal tilt about y relative to the bearing, rad")


def wants_tilt(args: argparse.Namespace) -> bool:
    return args.theta_x_rad is not None or args.theta_y_rad is not None


def tilt_of(args: argparse.Namespace) -> tuple[float, float]:
    """The tilt options (θx, θy) rad, 0 where not given."""
    return (0.0 if args.theta_x_rad is None else args.theta_x_rad,
            0.0 if args.theta_y_rad is None else args.theta_y_rad)


def print_tilt(tx, ty, moment, h_min, h_angle, h_z, K, C, where: str = "") -> None:
    """The tilt block of the text output: the tilt, the film's moments, the edge film and
    the 4×4 K, C with their units (:func:`rotordyn.units.tilt_units`, one per block)."""
    print(f"journal tilt relative to the bearing: theta_x = {tx:.6g} rad, theta_y = {ty:.6g} rad")
    print(f"moment: Mx = {moment[0]:.6g} N m, My = {moment[1]:.6g} N m")
    print(f"h_min = {h_min:.6g} m at {h_angle:.2f} deg, z = {h_z:.6g} m (mid-plane 0)")
    tail = f" ({where})" if where else ""
    for name, A, kind in (("K", K, "k"), ("C", C, "c")):
        units = ", ".join(tilt_units(kind)[i][j] for i, j in ((0, 0), (0, 2), (2, 0), (2, 2)))
        print(f"{name} over (x, y, theta_x, theta_y) [{units}]{tail} =\n"
              + np.array2string(np.asarray(A), precision=5))


def run_tilted(b, args: argparse.Namespace, rec: dict) -> int:
    """The tilted operating point of the isothermal film (``--load-n``: the misaligned
    equilibrium first; a failed one is reported and not linearised, exit 1)."""
    from rotordyn.bearings.tilt import misaligned_equilibrium, tilted_coefficients, tilted_forces
    from rotordyn.cli.common import journal_pose, json_text

    if args.speeds_hz is not None:
        raise InputError("--theta-x-rad/--theta-y-rad: a tilted journal is available at one "
                         "operating point (--speed-hz), not in a coefficient table "
                         "(--speeds-hz: the aligned film's)")
    tx, ty = tilt_of(args)
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
               force_n=np.asarray(t.force_n).tolist(),
               film_moment_n_m=np.asarray(t.film_moment_n_m).tolist(),
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
    print_tilt(tx, ty, t.film_moment_n_m, t.h_min_m, t.h_min_angle_deg, t.h_min_z_m, K, C)
    return 0


COORDINATES = TILT_COORDINATES


def coefficient_record(K, C) -> dict:
    """The tilted film's coefficients as JSON fields named as the aligned command's: the
    translational 2×2 block as ``k_n_per_m``, ``c_n_s_per_m`` (the same meaning and units
    as there), the whole 4×4 over ``coordinates`` as ``k_4x4_si``, ``c_4x4_si`` with each
    entry's unit in ``k_4x4_units``, ``c_4x4_units`` (4×4 strings)."""
    K, C = np.asarray(K, dtype=float), np.asarray(C, dtype=float)
    return {"k_n_per_m": K[:2, :2].tolist(), "c_n_s_per_m": C[:2, :2].tolist(),
            "k_4x4_si": K.tolist(), "c_4x4_si": C.tolist(),
            "k_4x4_units": tilt_units("k"), "c_4x4_units": tilt_units("c")}


__all__ = ["COORDINATES", "add_tilt_arguments", "coefficient_record", "print_tilt",
           "run_tilted", "tilt_of", "wants_tilt"]
