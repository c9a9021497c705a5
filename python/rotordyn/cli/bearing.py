"""``rotordyn bearing``: one operating point of a fluid-film journal bearing.

Either a journal position (``--x-m --y-m``, optional ``--vx-m-s --vy-m-s``) or a static load
(``--load-n FX FY``, then the static equilibrium is solved first). Prints the film force,
friction torque, flows, minimum film and the K, C coefficients; ``--json`` for a machine-
readable record. Exit 2 on bad input (the message names the field). ``--theta-x-rad``,
``--theta-y-rad``: the journal tilted relative to the bearing, with its moments, edge film and
4×4 K, C (:mod:`rotordyn.cli.bearing_tilt`). ``--model-file MODEL [--bearing NAME]``: a model
file's plain, tilting-pad or fixed-geometry bearing instead of the dimensions, aligned (as
the system's film: :mod:`rotordyn.cli.bearing_aligned`) or at a tilt
(:mod:`rotordyn.cli.bearing_model`).

Film physics (docs/film-physics.md): ``--turbulence ng_pan --density-kg-m3 RHO`` for the
turbulent film (``--turbulence-onset-re RE0 --turbulence-full-re RE1``: its transition); ``--supply-temperature-c T`` with ``--load-n`` and an oil law
(``--oil-walther T1 NU1 T2 NU2``, ``--oil-exponential MU_REF T_REF BETA`` or
``--oil-power T1 MU1 T2 MU2``) for the
effective-temperature equilibrium (then ``--viscosity-pa-s`` may be omitted): it prints the
effective and maximum temperatures, the power loss and flows, and K, C at the thermal
equilibrium (temperature frozen).
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from rotordyn.bearings._film import TURBULENCE_MODELS
from rotordyn.bearings.journal import CAVITATION_MODELS, Groove, JournalBearing
from rotordyn.bearings.thermal import Oil
from rotordyn.cli.common import add_thermal_arguments, json_text, oil_from_args
from rotordyn.cli.bearing_aligned import run_model_aligned, table
from rotordyn.cli.bearing_model import add_model_arguments, model_bearing
from rotordyn.cli.bearing_thermal import (failed_aligned, least_feeding_supply,
                                          print_effective, print_thd, run_thermal_tilted,
                                          thermal_kwargs, thermal_row)
from rotordyn.cli.bearing_tilt import add_tilt_arguments, run_tilted, wants_tilt
from rotordyn.cli.common import add_thd_arguments, journal_pose
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.results.equilibrium import CONVERGED


def _groove(text: str) -> Groove:
    parts = text.split(",")
    if not 1 <= len(parts) <= 3:
        raise InputError(f"--groove: expected CENTER_DEG[,WIDTH_DEG[,PRESSURE_PA]], got {text!r}")
    try:
        vals = [float(p) for p in parts]
    except ValueError:
        raise InputError(
            f"--groove: expected numbers CENTER_DEG[,WIDTH_DEG[,PRESSURE_PA]], got {text!r}"
        ) from None
    return Groove(*vals)


def register(sub: argparse._SubParsersAction) -> None:
    s = sub.add_parser("bearing", help="fluid-film journal bearing at one operating point",
                       description=__doc__)
    s.add_argument("--diameter-m", type=float, default=None, metavar="M",
                   help="journal diameter D, m (50 mm = 0.05)")
    s.add_argument("--length-m", type=float, default=None, metavar="M",
                   help="bearing length L, m")
    s.add_argument("--clearance-m", type=float, default=None, metavar="M",
                   help="radial clearance c, m (0.3 mm = 3e-4)")
    s.add_argument("--viscosity-pa-s", type=float, default=None, metavar="PA_S",
                   help="dynamic viscosity of the lubricant, Pa s (required unless the "
                        "thermal model gives it: --supply-temperature-c)")
    s.add_argument("--turbulence", choices=TURBULENCE_MODELS, default=None,
                   help="turbulent film model (ng_pan: Ng-Pan-Elrod, needs --density-kg-m3)")
    s.add_argument("--density-kg-m3", type=float, default=None, metavar="RHO",
                   help="oil density, kg/m3 (turbulence; the thermal oil's density)")
    s.add_argument("--turbulence-onset-re", type=float, default=None, metavar="RE",
                   help="transition: Re_h at which the turbulent corrections start (with "
                        "--turbulence-full-re; default: none, turbulent at every Re_h)")
    s.add_argument("--turbulence-full-re", type=float, default=None, metavar="RE",
                   help="transition: Re_h at which the turbulent corrections are full")
    add_thermal_arguments(s)
    add_thd_arguments(s)
    s.add_argument("--n-circ", type=int, default=None, metavar="N",
                   help="film grid cells around the circumference (default 72; "
                        "--model-file: the bearing's)")
    s.add_argument("--n-axial", type=int, default=None, metavar="N",
                   help="film grid cells along the length (default 16; --model-file: the "
                        "bearing's)")
    s.add_argument("--cavitation", choices=CAVITATION_MODELS, default=None,
                   help="cavitation model (gumbel: half-Sommerfeld; reynolds: Swift-Stieber)")
    s.add_argument("--groove", action="append", default=[], metavar="C[,W[,P]]",
                   help="axial groove: centre deg, width deg, pressure Pa (repeatable)")
    s.add_argument("--speed-hz", type=float, default=None, metavar="HZ",
                   help="journal spin speed, Hz (or --speeds-hz for a coefficient table)")
    s.add_argument("--speeds-hz", default=None, metavar="START:STOP:STEP",
                   help="coefficient table over speeds (STOP included), with --load-n")
    s.add_argument("--csv", action="store_true",
                   help="with --speeds-hz: print the table as CSV (TableBearing.from_csv reads it)")
    s.add_argument("--threads", type=int, default=1, metavar="N",
                   help="threads over speeds (0: all cores)")
    s.add_argument("--x-m", type=float, default=None, metavar="M",
                   help="journal centre x (horizontal) from the bearing centre, m")
    s.add_argument("--y-m", type=float, default=None, metavar="M",
                   help="journal centre y (vertical, up) from the bearing centre, m")
    s.add_argument("--vx-m-s", type=float, default=0.0, metavar="M_S",
                   help="journal centre velocity x, m/s")
    s.add_argument("--vy-m-s", type=float, default=0.0, metavar="M_S",
                   help="journal centre velocity y, m/s")
    s.add_argument("--load-n", type=float, nargs=2, metavar=("FX", "FY"), default=None,
                   help="static load on the journal, N: solve the equilibrium first")
    add_tilt_arguments(s)
    add_model_arguments(s)
    s.add_argument("--method", choices=("perturbation", "finite_difference"),
                   default="perturbation", help="how K and C are computed")
    s.add_argument("--json", action="store_true", help="print one JSON record")
    s.set_defaults(func=run)


def _finite_or_none(value: float):
    return value if math.isfinite(value) else None


def run(args: argparse.Namespace) -> int:
    from rotordyn._common import plausibility

    if args.model_file is not None:
        return _model_file(args)
    for k in ("diameter_m", "length_m", "clearance_m"):
        if getattr(args, k) is None:
            raise InputError(f"--{k.replace('_', '-')}: required (or --model-file MODEL)")
    if args.bearing is not None:
        raise InputError("--bearing: an option of --model-file")
    args.n_circ = 72 if args.n_circ is None else args.n_circ
    args.n_axial = 16 if args.n_axial is None else args.n_axial
    args.cavitation = "reynolds" if args.cavitation is None else args.cavitation
    args.turbulence = "laminar" if args.turbulence is None else args.turbulence
    grooves = [_groove(g) for g in args.groove]
    if args.diameter_m > 0 and args.clearance_m > 0:
        plausibility.length("--diameter-m", args.diameter_m)
        plausibility.clearance("--clearance-m", args.clearance_m, args.diameter_m)
    oil = oil_from_args(args)
    if oil is None and args.thermal_model is not None:
        raise InputError("--model: the thermal model needs --supply-temperature-c, --load-n "
                         "and an --oil-* law")
    if args.viscosity_pa_s is None:
        if oil is None:
            raise InputError("--viscosity-pa-s: required (or the thermal model: "
                             "--supply-temperature-c with an --oil-* law)")
        args.viscosity_pa_s = oil.viscosity_pa_s(args.supply_temperature_c)
    if args.viscosity_pa_s > 0:
        plausibility.viscosity("--viscosity-pa-s", args.viscosity_pa_s)
    film = dict(
        diameter_m=args.diameter_m, length_m=args.length_m, clearance_m=args.clearance_m,
        n_circ=args.n_circ, n_axial=args.n_axial, cavitation=args.cavitation, grooves=grooves,
        turbulence=args.turbulence, density_kg_m3=args.density_kg_m3,
        turbulence_onset_re=args.turbulence_onset_re, turbulence_full_re=args.turbulence_full_re)
    b = JournalBearing(viscosity_pa_s=args.viscosity_pa_s, **film)
    rec: dict = {"bearing": {k: v for k, v in b.__getstate__().items() if k != "grooves"}}
    rec["bearing"]["grooves"] = [[g.center_deg, g.width_deg, g.pressure_pa] for g in grooves]
    if wants_tilt(args):
        if args.speed_hz is None and args.speeds_hz is None:
            raise InputError("--speed-hz: required")
        if args.speed_hz is not None:
            rec["speed_hz"] = args.speed_hz
        if oil is not None and args.speeds_hz is None:  # the tilted thermal equilibrium
            return run_thermal_tilted(b, oil, rec, args)
        return run_tilted(b, args, rec)
    return _aligned(b, oil, rec, args)


def _aligned(b: JournalBearing, oil: Oil | None, rec: dict, args: argparse.Namespace) -> int:
    """The aligned plain film ``b`` (given by its dimensions, or a model file's plain bearing):
    a coefficient table, the thermal equilibrium or the isothermal operating point."""
    if args.speeds_hz is not None:
        return table(b, args)
    if args.speed_hz is None:
        raise InputError("--speed-hz: required (or --speeds-hz START:STOP:STEP for a table)")
    rec["speed_hz"] = args.speed_hz
    if oil is not None:
        return _thermal(b, oil, rec, args)
    x, y, vx, vy, eq = journal_pose(
        args, lambda load: b.static_equilibrium(load_n=load, speed_hz=args.speed_hz))
    if eq is not None:
        rec["equilibrium"] = {
            "load_n": list(eq.load_n), "x_m": eq.x_m, "y_m": eq.y_m,
            "eccentricity_ratio": eq.eccentricity_ratio,
            # zero load: no load direction and no Sommerfeld number (null, not NaN/inf)
            "attitude_angle_deg": _finite_or_none(eq.attitude_angle_deg),
            "sommerfeld": _finite_or_none(eq.sommerfeld),
            "residual_rel": eq.residual_rel, "iterations": eq.iterations,
        }
    r = b.solve(x_m=x, y_m=y, speed_hz=args.speed_hz, vx_m_s=vx, vy_m_s=vy)
    K, C = b.coefficients(x_m=x, y_m=y, speed_hz=args.speed_hz, method=args.method)
    rec.update(
        journal_x_m=x, journal_y_m=y, journal_vx_m_s=vx, journal_vy_m_s=vy,
        force_n=np.asarray(r.force_n).tolist(), friction_torque_n_m=r.friction_torque_n_m,
        inlet_flow_m3_s=r.inlet_flow_m3_s, side_flow_m3_s=r.side_flow_m3_s,
        h_min_m=r.h_min_m, h_min_angle_deg=r.h_min_angle_deg,
        k_n_per_m=K.tolist(), c_n_s_per_m=C.tolist(), coefficient_method=args.method,
    )
    if args.json:
        print(json_text(rec))
    else:
        if b.turbulence != "laminar":
            print(f"film: turbulent ({b.turbulence}), " + (
                "at every Re_h" if b.turbulence_onset_re is None else
                f"transition Re_h {b.turbulence_onset_re:g} to {b.turbulence_full_re:g}"))
        if "equilibrium" in rec:
            e = rec["equilibrium"]
            print(f"equilibrium: x = {x:.6g} m, y = {y:.6g} m, eps = {e['eccentricity_ratio']:.4g},"
                  f" attitude = {eq.attitude_angle_deg:.2f} deg, S = {eq.sommerfeld:.4g}")
        print(f"force on journal: Fx = {r.force_n[0]:.6g} N, Fy = {r.force_n[1]:.6g} N")
        print(f"friction torque: {r.friction_torque_n_m:.6g} N m; inlet flow {r.inlet_flow_m3_s:.6g}"
              f" m3/s, side flow {r.side_flow_m3_s:.6g} m3/s")
        print(f"h_min = {r.h_min_m:.6g} m at {r.h_min_angle_deg:.2f} deg")
        print("K [N/m] =", np.array2string(K, precision=5))
        print("C [N s/m] =", np.array2string(C, precision=5))
    return 0


def _thermal(b: JournalBearing, oil: Oil, rec: dict, args: argparse.Namespace) -> int:
    """Effective-temperature or THD equilibrium of the aligned film: temperatures, power,
    flows, K, C (temperature frozen); the tilted one: :func:`rotordyn.cli.bearing_thermal.
    run_thermal_tilted`. A film without a thermal equilibrium (a metered supply below what it
    leaks: status "starved"; no settled temperature) is a status record with exit 1
    (:func:`rotordyn.cli.bearing_thermal.failed_aligned`), as a tilted or pad bearing's is."""
    kw = thermal_kwargs(args)
    try:
        r = b.thermal_equilibrium(oil=oil, **kw)
    except ConvergenceError as exc:  # e.g. StarvedFilmError: a failed status, not an error
        status = getattr(exc, "status", "error")
        least = None
        if status == "starved":
            least = least_feeding_supply(
                lambda q: b.thermal_equilibrium(oil=oil, **{**kw, "supply_flow_m3_s": q}),
                kw["supply_flow_m3_s"], str(exc))
        return failed_aligned(rec, args, status, getattr(exc, "detail", str(exc)), least)
    rec["thermal"] = thermal_row(r)
    rec.update(journal_x_m=r.x_m, journal_y_m=r.y_m, k_n_per_m=r.K.tolist(),
               c_n_s_per_m=r.C.tolist(), coefficient_method="perturbation")
    if kw["model"] == "effective":  # the hot film's forces, minimum film and torque
        f = JournalBearing(**{**b.__getstate__(), "viscosity_pa_s": r.viscosity_pa_s}).solve(
            x_m=r.x_m, y_m=r.y_m, speed_hz=args.speed_hz)
        rec.update(force_n=np.asarray(f.force_n).tolist(), h_min_m=f.h_min_m,
                   h_min_angle_deg=f.h_min_angle_deg,
                   friction_torque_n_m=f.friction_torque_n_m)
    code = 0 if r.status in CONVERGED else 1
    if args.json:
        print(json_text(rec))
        return code
    if kw["model"] == "thd":
        print_thd(r, args)
    else:
        print_effective(r, args, rec["h_min_m"], rec["h_min_angle_deg"])
    print("K [N/m] =", np.array2string(r.K, precision=5))
    print("C [N s/m] =", np.array2string(r.C, precision=5))
    return code


def _model_file(args: argparse.Namespace) -> int:
    """A model file's bearing (:mod:`rotordyn.cli.bearing_model`): with a tilt its tilted
    operating point, isothermal or at its thermal equilibrium; without one the aligned
    bearing as the system solves it (a plain bearing through the dimensions path's own
    code, a tilting-pad or fixed-geometry one: :mod:`rotordyn.cli.bearing_aligned`)."""
    from rotordyn.bearings import FluidFilmBearing

    if args.speed_hz is None and (wants_tilt(args) or args.speeds_hz is None):
        raise InputError("--speed-hz: required" + (
            "" if wants_tilt(args) else " (or --speeds-hz START:STOP:STEP for a table)"))
    b, brec = model_bearing(args)
    rec: dict = {"bearing": brec}
    if args.speed_hz is not None:
        rec["speed_hz"] = args.speed_hz
    oil = oil_from_args(args)
    if oil is None and args.thermal_model is not None:
        raise InputError("--model: the thermal model needs --supply-temperature-c, --load-n "
                         "and an --oil-* law")
    if oil is None and args.density_kg_m3 is not None:
        raise InputError("--density-kg-m3: with --model-file only the thermal oil's density "
                         "(give an --oil-* law); the model's bearing has its own")
    if not wants_tilt(args):
        if isinstance(b, FluidFilmBearing):
            return _aligned(b.journal_bearing(), oil, rec, args)
        return run_model_aligned(b, oil, rec, args)
    if oil is not None and args.speeds_hz is None:
        return run_thermal_tilted(b, oil, rec, args)
    return run_tilted(b, args, rec)
