"""``rotordyn bearing --model-file MODEL --bearing NAME`` without a tilt: a model file's
tilting-pad or fixed-geometry bearing aligned with the journal, as the system solves it
(issue 20; docs/bearings.md, "One bearing of a model file"). A model's plain bearing takes
the dimensions path's own code (:func:`rotordyn.cli.bearing._aligned`).

- isothermal, ``--load-n``: the bearing's equilibrium under the load and its 2×2 K, C
  (:meth:`coefficient_table` at the one speed: tilting pads condensed at the synchronous
  whirl, as in the system's coefficient tables), with the pads' tilts (tilting pads) or the
  film's force and minimum film (fixed geometry);
- isothermal, ``--x-m --y-m`` (fixed geometry only: a tilting-pad bearing's pads find their
  tilts in the equilibrium under a load): the film's force and K, C at that position;
- thermal (``--supply-temperature-c`` and an ``--oil-*`` law, with ``--load-n``): the
  bearing's ``thermal_equilibrium`` (THD or effective), its ``total`` row and one row per pad
  or lobe, K, C at the frozen field.

A failed equilibrium is a status record (``status``, ``message``) with exit 1: no film
outputs or coefficients at a failed point."""

from __future__ import annotations

import argparse

import numpy as np

from rotordyn.cli.common import json_text, speeds as _speeds, table_text
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.results.equilibrium import CONVERGED


def _numbers(row: dict) -> dict:
    return {k: (float(v) if isinstance(v, (int, float, np.floating)) else v)
            for k, v in row.items()}


def _failed(rec: dict, args: argparse.Namespace, status: str, message: str) -> int:
    rec.update(status=status, message=message)
    if args.json:
        print(json_text(rec))
    else:
        print(f"equilibrium: {status} ({message}); no film outputs or coefficients at a "
              "failed equilibrium")
    return 1


def _isothermal(b, rec: dict, args: argparse.Namespace) -> int:
    from rotordyn.bearings import TiltingPadBearing

    pads = isinstance(b, TiltingPadBearing)
    if args.load_n is None:
        if pads:
            raise InputError("--load-n: a tilting-pad bearing's aligned operating point is "
                             "its equilibrium under a load (the pads' tilts follow from it); "
                             "--x-m/--y-m is for the fixed-geometry bearing")
        if args.x_m is None or args.y_m is None:
            raise InputError("--x-m/--y-m: journal position required (or give --load-n)")
        x, y = args.x_m, args.y_m
        vx, vy = args.vx_m_s, args.vy_m_s
    else:
        if args.x_m is not None or args.y_m is not None:
            raise InputError("--load-n: give either --load-n or --x-m/--y-m, not both")
        t = b.coefficient_table([args.speed_hz], tuple(args.load_n))
        row = _numbers(t.to_frame().iloc[0].to_dict())
        rec["equilibrium"] = {"load_n": list(args.load_n), "status": t.status[0],
                              "message": t.message[0], "x_m": row["journal_x_m"],
                              "y_m": row["journal_y_m"],
                              "eccentricity_ratio": row["eccentricity_ratio"]}
        if t.status[0] not in CONVERGED:
            return _failed(rec, args, t.status[0], t.message[0])
        x, y, vx, vy = float(t.x_m[0]), float(t.y_m[0]), 0.0, 0.0
        K, C = t.K[0], t.C[0]
    rec.update(journal_x_m=x, journal_y_m=y, journal_vx_m_s=vx, journal_vy_m_s=vy)
    if pads:
        r = b.full_coefficients(args.speed_hz, tuple(args.load_n))[0]
        rec["pad_tilts_rad"] = np.asarray(b.pad_tilts_rad(r)).tolist()
        rec["coefficient_whirl"] = "synchronous"
    else:
        if args.load_n is None:
            K, C = b.coefficients(x_m=x, y_m=y, speed_hz=args.speed_hz)
        f = b.forces(x_m=x, y_m=y, speed_hz=args.speed_hz, vx_m_s=vx, vy_m_s=vy)
        rec.update(force_n=np.asarray(f).tolist(), h_min_m=float(b.edge_film(x, y, 0.0, 0.0)[0]))
    rec.update(k_n_per_m=np.asarray(K).tolist(), c_n_s_per_m=np.asarray(C).tolist(),
               coefficient_method="perturbation")
    if args.json:
        print(json_text(rec))
        return 0
    if "equilibrium" in rec:
        print(f"equilibrium ({rec['equilibrium']['status']}): x = {x:.6g} m, y = {y:.6g} m, "
              f"eps = {rec['equilibrium']['eccentricity_ratio']:.4g}")
    if pads:
        print("pad tilts [rad] =", np.array2string(np.asarray(rec["pad_tilts_rad"]),
                                                   precision=5))
        print("K, C: the pads condensed at the synchronous whirl")
    else:
        print(f"force on journal: Fx = {rec['force_n'][0]:.6g} N, Fy = {rec['force_n'][1]:.6g} N")
        print(f"h_min = {rec['h_min_m']:.6g} m")
    print("K [N/m] =", np.array2string(np.asarray(K), precision=5))
    print("C [N s/m] =", np.array2string(np.asarray(C), precision=5))
    return 0


def _thermal(b, oil, rec: dict, args: argparse.Namespace) -> int:
    from rotordyn.cli.bearing_thermal import thermal_kwargs

    kw = thermal_kwargs(args)
    try:
        r = b.thermal_equilibrium(oil=oil, tilt=False, **kw)
    except ConvergenceError as exc:
        return _failed(rec, args, getattr(exc, "status", "error"),
                       getattr(exc, "detail", str(exc)))
    if r.status not in CONVERGED:
        return _failed(rec, args, r.status, r.message)
    df = r.to_frame()
    rows = [_numbers(row) for row in df.to_dict(orient="records")]
    rec["thermal"], rec["pads"] = rows[-1], rows[:-1]
    rec.update(status=r.status, journal_x_m=r.x_m, journal_y_m=r.y_m,
               eccentricity_ratio=r.eccentricity_ratio, k_n_per_m=np.asarray(r.K).tolist(),
               c_n_s_per_m=np.asarray(r.C).tolist(), coefficient_method="perturbation")
    if args.json:
        print(json_text(rec))
        return 0
    print(f"thermal equilibrium ({r.thermal_model} model, {r.status}): T_max = "
          f"{r.max_temperature_c_total:.2f} degC, power loss {r.power_loss_w_total:.5g} W, "
          f"supply flow {r.supply_flow_m3_s_total:.5g} m3/s")
    cols = ("pad", "max_temperature_c", "mean_temperature_c", "inlet_temperature_c",
            "power_loss_w", "film_flow_m3_s", "side_flow_m3_s", "supply_flow_m3_s",
            "pad_tilt_rad", "unloaded")
    print(table_text(df[[c for c in cols if c in df]]))
    print(f"equilibrium: x = {r.x_m:.6g} m, y = {r.y_m:.6g} m, eps = {r.eccentricity_ratio:.4g}")
    print("K [N/m] =", np.array2string(np.asarray(r.K), precision=5))
    print("C [N s/m] =", np.array2string(np.asarray(r.C), precision=5))
    return 0


def run_model_aligned(b, oil, rec: dict, args: argparse.Namespace) -> int:
    """The aligned operating point of a model's tilting-pad or fixed-geometry bearing ``b``
    (see the module): a coefficient table over ``--speeds-hz``, the thermal equilibrium
    (``oil`` given) or the isothermal one."""
    if args.speeds_hz is not None:
        if oil is not None:
            raise InputError("--speeds-hz: a coefficient table is the isothermal film's (the "
                             "model bearing's viscosity); the thermal model runs at one "
                             "--speed-hz")
        return table(b, args)
    if oil is not None:
        return _thermal(b, oil, rec, args)
    return _isothermal(b, rec, args)


def table(b, args: argparse.Namespace) -> int:
    """The coefficient table of ``b`` (any film bearing) over ``--speeds-hz`` under
    ``--load-n``: CSV, JSON records or text; exit 1 when a row did not converge."""
    if args.load_n is None:
        raise InputError("--load-n: a coefficient table (--speeds-hz) needs the static load")
    t = b.coefficient_table(_speeds(args.speeds_hz), tuple(args.load_n), n_threads=args.threads)
    if args.csv:
        print(t.to_csv(), end="")
    elif args.json:
        print(t.to_frame().to_json(orient="records", indent=2))
    else:
        print(table_text(t.to_frame()))
    return 0 if all(s in CONVERGED for s in t.status) else 1


__all__ = ["run_model_aligned", "table"]
