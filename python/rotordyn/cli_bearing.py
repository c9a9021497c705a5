"""``rotordyn bearing``: one operating point of a fluid-film journal bearing.

Either a journal position (``--x-m --y-m``, optional ``--vx-m-s --vy-m-s``) or a static load
(``--load-n FX FY``, then the static equilibrium is solved first). Prints the film force,
friction torque, flows, minimum film and the K, C coefficients; ``--json`` for a machine-
readable record. Exit 2 on bad input (the message names the field).
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

from rotordyn.bearing import CAVITATION_MODELS, Groove, JournalBearing
from rotordyn.errors import InputError


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
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    s.add_argument("--diameter-m", type=float, required=True)
    s.add_argument("--length-m", type=float, required=True)
    s.add_argument("--clearance-m", type=float, required=True)
    s.add_argument("--viscosity-pa-s", type=float, required=True)
    s.add_argument("--n-circ", type=int, default=72)
    s.add_argument("--n-axial", type=int, default=16)
    s.add_argument("--cavitation", choices=CAVITATION_MODELS, default="reynolds")
    s.add_argument("--groove", action="append", default=[], metavar="C[,W[,P]]",
                   help="axial groove: centre deg, width deg, pressure Pa (repeatable)")
    s.add_argument("--speed-hz", type=float, required=True)
    s.add_argument("--x-m", type=float, default=None)
    s.add_argument("--y-m", type=float, default=None)
    s.add_argument("--vx-m-s", type=float, default=0.0)
    s.add_argument("--vy-m-s", type=float, default=0.0)
    s.add_argument("--load-n", type=float, nargs=2, metavar=("FX", "FY"), default=None,
                   help="static load on the journal, N: solve the equilibrium first")
    s.add_argument("--method", choices=("perturbation", "finite_difference"),
                   default="perturbation", help="how K and C are computed")
    s.add_argument("--json", action="store_true", help="print one JSON record")
    s.set_defaults(func=run)


def _finite_or_none(value: float):
    return value if math.isfinite(value) else None


def run(args: argparse.Namespace) -> int:
    grooves = [_groove(g) for g in args.groove]
    b = JournalBearing(
        diameter_m=args.diameter_m, length_m=args.length_m, clearance_m=args.clearance_m,
        viscosity_pa_s=args.viscosity_pa_s, n_circ=args.n_circ, n_axial=args.n_axial,
        cavitation=args.cavitation, grooves=grooves,
    )
    rec: dict = {"bearing": {k: v for k, v in b.__getstate__().items() if k != "grooves"}}
    rec["bearing"]["grooves"] = [[g.center_deg, g.width_deg, g.pressure_pa] for g in grooves]
    rec["speed_hz"] = args.speed_hz
    if args.load_n is not None:
        if args.x_m is not None or args.y_m is not None:
            raise InputError("--load-n: give either --load-n or --x-m/--y-m, not both")
        eq = b.static_equilibrium(load_n=tuple(args.load_n), speed_hz=args.speed_hz)
        x, y, vx, vy = eq.x_m, eq.y_m, 0.0, 0.0
        rec["equilibrium"] = {
            "load_n": list(eq.load_n), "x_m": eq.x_m, "y_m": eq.y_m,
            "eccentricity_ratio": eq.eccentricity_ratio,
            # zero load: no load direction and no Sommerfeld number (null, not NaN/inf)
            "attitude_angle_deg": _finite_or_none(eq.attitude_angle_deg),
            "sommerfeld": _finite_or_none(eq.sommerfeld),
            "residual_rel": eq.residual_rel, "iterations": eq.iterations,
        }
    else:
        if args.x_m is None or args.y_m is None:
            raise InputError("--x-m/--y-m: journal position required (or give --load-n)")
        x, y, vx, vy = args.x_m, args.y_m, args.vx_m_s, args.vy_m_s
    r = b.solve(x_m=x, y_m=y, speed_hz=args.speed_hz, vx_m_s=vx, vy_m_s=vy)
    K, C = b.coefficients(x_m=x, y_m=y, speed_hz=args.speed_hz, method=args.method)
    rec.update(
        journal_x_m=x, journal_y_m=y, journal_vx_m_s=vx, journal_vy_m_s=vy,
        force_n=np.asarray(r.force_n).tolist(), friction_torque_nm=r.friction_torque_nm,
        inlet_flow_m3_s=r.inlet_flow_m3_s, side_flow_m3_s=r.side_flow_m3_s,
        h_min_m=r.h_min_m, h_min_angle_deg=r.h_min_angle_deg,
        k_n_per_m=K.tolist(), c_n_s_per_m=C.tolist(), coefficient_method=args.method,
    )
    if args.json:
        print(json.dumps(rec, indent=2))
    else:
        if "equilibrium" in rec:
            e = rec["equilibrium"]
            print(f"equilibrium: x = {x:.6g} m, y = {y:.6g} m, eps = {e['eccentricity_ratio']:.4g},"
                  f" attitude = {eq.attitude_angle_deg:.2f} deg, S = {eq.sommerfeld:.4g}")
        print(f"force on journal: Fx = {r.force_n[0]:.6g} N, Fy = {r.force_n[1]:.6g} N")
        print(f"friction torque: {r.friction_torque_nm:.6g} N m; inlet flow {r.inlet_flow_m3_s:.6g}"
              f" m3/s, side flow {r.side_flow_m3_s:.6g} m3/s")
        print(f"h_min = {r.h_min_m:.6g} m at {r.h_min_angle_deg:.2f} deg")
        print("K [N/m] =", np.array2string(K, precision=5))
        print("C [N s/m] =", np.array2string(C, precision=5))
    return 0
