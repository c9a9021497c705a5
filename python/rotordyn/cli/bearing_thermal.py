"""``rotordyn bearing`` with a thermal model (``--supply-temperature-c`` and an oil law): the
options of the film's heat balance (:func:`thermal_kwargs`), the text lines of the plain
film's results (:func:`print_effective`, :func:`print_thd`) and the tilted thermal
equilibrium of any fluid-film bearing (:func:`run_thermal_tilted`): a plain journal bearing
given by its dimensions, or a model file's plain, tilting-pad or fixed-geometry bearing
(``--model-file``, :mod:`rotordyn.cli.bearing_model`); docs/film-physics.md, "Plain and
tilting-pad bearings, standalone".

A thermal equilibrium that fails, tilted or aligned (no equilibrium within the iteration
caps, a load the film cannot carry, a metered supply below what the film draws: "starved") is
a status record — ``status``, ``message`` and the point's inputs, text
or ``--json`` — with exit 1, as a failed misaligned equilibrium is (no film outputs or
coefficients at a failed point)."""

from __future__ import annotations

import argparse
import re

import numpy as np

from rotordyn.cli.bearing_tilt import (COORDINATES, coefficient_record, print_tilt, tilt_of,
                                       wants_tilt)
from rotordyn.cli.common import json_text, table_text
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.results.equilibrium import CONVERGED

THD_WALLS = ("journal_htc_w_m2k", "bush_htc_w_m2k", "journal_temperature_c",
             "bush_temperature_c")


def _or(value, default):
    """``value`` unless None (an option not given: the film model's default)."""
    return default if value is None else value


def thermal_model(args: argparse.Namespace) -> str:
    """The film model of the command: ``thd`` or ``effective`` (the default)."""
    return "thd" if args.thermal_model == "thd" else "effective"


def thermal_kwargs(args: argparse.Namespace) -> dict:
    """The keywords of a bearing's ``thermal_equilibrium`` from the command's options (the
    load, speed, supply, carry-over, the model and its own options); an option of the other
    model is an InputError naming it."""
    if args.load_n is None or args.x_m is not None or args.y_m is not None:
        raise InputError("--load-n: the thermal model solves the equilibrium under a load "
                         "(give --load-n, not --x-m/--y-m)")
    kw = dict(load_n=tuple(args.load_n), speed_hz=args.speed_hz,
              supply_temperature_c=args.supply_temperature_c,
              supply_flow_m3_s=_or(args.supply_flow_m3_s, 0.0),
              carry_over=_or(args.carry_over, 0.0), model=thermal_model(args))
    from rotordyn.analysis.thermal import refuse_other_model_options

    # the API's one rule, named as the flags
    refuse_other_model_options(kw["model"], {k: getattr(args, k, None) for k in (
        *THD_WALLS, "effective_factor")}, flags=True)
    if kw["model"] == "thd":
        kw.update({k: getattr(args, k) for k in THD_WALLS if getattr(args, k) is not None})
    else:
        kw["effective_factor"] = _or(args.effective_factor, 0.5)
    return kw


def thermal_row(r) -> dict:
    """A plain film's thermal result as its ``to_frame()`` row (numbers as floats)."""
    row = r.to_frame().iloc[0].to_dict()
    return {k: (float(v) if isinstance(v, (int, float, np.floating)) else v)
            for k, v in row.items()}


def print_effective(r, args: argparse.Namespace, h_min_m: float, h_min_angle_deg: float) -> None:
    """The effective-temperature result's text lines (temperatures, power, flows, pose)."""
    print(f"thermal equilibrium: T_eff = {r.effective_temperature_c:.2f} degC, T_max = "
          f"{r.max_temperature_c:.2f} degC, T_in = {r.inlet_temperature_c:.2f} degC "
          f"(supply {args.supply_temperature_c:g} degC), mu = {r.viscosity_pa_s:.4g} Pa s")
    print(f"power loss {r.power_loss_w:.5g} W; film flow {r.film_flow_m3_s:.5g} m3/s, side flow "
          f"{r.side_flow_m3_s:.5g} m3/s, fresh supply {r.supply_flow_m3_s:.5g} m3/s")
    print(f"equilibrium: x = {r.x_m:.6g} m, y = {r.y_m:.6g} m, eps = {r.eccentricity_ratio:.4g}; "
          f"h_min = {h_min_m:.6g} m at {h_min_angle_deg:.2f} deg")


def print_thd(r, args: argparse.Namespace) -> None:
    """The THD result's text lines (temperatures, power, flows, heat paths, pose)."""
    print(f"THD equilibrium ({r.status}): T_max = {r.max_temperature_c:.2f} degC, T_mean = "
          f"{r.mean_temperature_c:.2f} degC, T_in = {r.inlet_temperature_c:.2f} degC "
          f"(supply {args.supply_temperature_c:g} degC)")
    print(f"power loss {r.power_loss_w:.5g} W; film flow {r.film_flow_m3_s:.5g} m3/s, side flow "
          f"{r.side_flow_m3_s:.5g} m3/s, recirculation {r.recirculation_flow_m3_s:.5g} m3/s, "
          f"fresh supply {r.supply_flow_m3_s:.5g} m3/s; heat to journal "
          f"{r.heat_to_journal_w:.4g} W, to bush {r.heat_to_bush_w:.4g} W")
    print(f"equilibrium: x = {r.x_m:.6g} m, y = {r.y_m:.6g} m, eps = {r.eccentricity_ratio:.4g}")


# the per-pad (lobe) columns the text shows of a pad bearing's thermal frame
_PAD_TEXT = ("pad", "max_temperature_c", "mean_temperature_c", "inlet_temperature_c",
             "power_loss_w", "film_flow_m3_s", "side_flow_m3_s", "supply_flow_m3_s",
             "pad_tilt_rad")


def _pad_rows(r) -> tuple[dict, list[dict]]:
    """A pad bearing's thermal frame as its ``total`` row and its per-pad rows (the pad
    columns and the tilt columns; JSON numbers)."""
    df = r.to_frame()
    rows = [{k: (float(v) if isinstance(v, (int, float, np.floating)) else v)
             for k, v in row.items()} for row in df.to_dict(orient="records")]
    return rows[-1], rows[:-1]


def _failed(rec: dict, args: argparse.Namespace, status: str, message: str) -> int:
    """The status record of a failed tilted thermal equilibrium (exit 1): status, message
    and the point's inputs; no film outputs or coefficients."""
    tx, ty = tilt_of(args)
    rec.update(load_n=list(args.load_n), supply_temperature_c=args.supply_temperature_c,
               thermal_model=thermal_model(args), journal_theta_x_rad=tx,
               journal_theta_y_rad=ty, status=status, message=message)
    if args.json:
        print(json_text(rec))
    else:
        print(f"tilted thermal equilibrium ({rec['thermal_model']} model): {status} "
              f"({message}) at load ({args.load_n[0]:g}, {args.load_n[1]:g}) N, "
              f"{args.speed_hz:g} Hz, supply {args.supply_temperature_c:g} degC, tilt "
              f"theta_x = {tx:.6g} rad, theta_y = {ty:.6g} rad; no film outputs or "
              "coefficients at a failed equilibrium")
    return 1


_DEMAND = re.compile(r"Q - Q_r = ([0-9.eE+-]+) m\^3/s")
LEAST_SUPPLY_RTOL = 0.01  # the bracket of the least supply that feeds a starved film


def least_feeding_supply(solve, supply: float, message: str) -> float | None:
    """The least metered supply (m³/s) at which ``solve(q)`` (a thermal equilibrium at supply
    ``q``) converges fed (status ok), bracketed to :data:`LEAST_SUPPLY_RTOL` between a starved
    and a fed supply (the fed end returned). None when not determined: 40 steps find no fed
    supply, or a supply on the way fails otherwise (no equilibrium there: neither end of a
    bracket). The C++ message's shortfall "Q − Q_r" at the starved iterate's flows is only an
    estimate, a start for the walk (the compressor's DE bearing from 1e-7 m³/s: effective
    model 3.44e-5 named, still starved, the bracket 7.26e-5; THD 1.33e-4 named, the bracket
    6.77e-5)."""
    from rotordyn.errors import StarvedFilmError

    def starved(q):
        """True (starved), False (fed: converged), None (another failure)."""
        try:
            r = solve(q)
        except StarvedFilmError as exc:
            return True, str(exc)
        except ConvergenceError:
            return None, ""
        if r.status == "starved":
            return True, getattr(r, "message", "")
        return (False if r.status in CONVERGED else None), ""

    lo, msg, hi = supply, message, None
    for _ in range(40):  # walk up from the starved supply: the iterate's estimate, else 2×
        m = _DEMAND.search(msg)
        est = float(m.group(1)) if m is not None else 0.0
        q = est if est > 1.05 * lo else max(2.0 * lo, 1e-12)
        bad, msg = starved(q)
        if bad is None:
            return None
        if not bad:
            hi = q
            break
        lo = q
    if hi is None:
        return None
    while hi - lo > LEAST_SUPPLY_RTOL * hi:
        mid = 0.5 * (lo + hi)
        bad = starved(mid)[0]
        if bad is None:
            return None
        if bad:
            lo = mid
        else:
            hi = mid
    return hi


def failed_aligned(rec: dict, args: argparse.Namespace, status: str, message: str,
                   least_supply_m3_s: float | None = None) -> int:
    """The status record of a failed aligned thermal equilibrium of a plain film (exit 1):
    ``status`` (e.g. "starved": the metered supply below what the film draws), ``message``
    (for a starved film also the least supply that feeds it, ``least_supply_m3_s``, from
    :func:`least_feeding_supply`) and the point's inputs; no film outputs or coefficients."""
    if status == "starved":
        message += ("; the least supply that feeds the film: " + (
            f"{least_supply_m3_s:.4g} m^3/s (bracketed to {100 * LEAST_SUPPLY_RTOL:g} %)"
            if least_supply_m3_s is not None else "not determined (no fed equilibrium found "
            "above it without another failure)"))
        rec["least_supply_m3_s"] = least_supply_m3_s
    rec.update(load_n=list(args.load_n), supply_temperature_c=args.supply_temperature_c,
               supply_flow_m3_s=_or(args.supply_flow_m3_s, 0.0),
               carry_over=_or(args.carry_over, 0.0), thermal_model=thermal_model(args),
               status=status, message=message)
    if args.json:
        print(json_text(rec))
    else:
        print(f"thermal equilibrium ({rec['thermal_model']} model): {status} ({message}) at "
              f"load ({args.load_n[0]:g}, {args.load_n[1]:g}) N, {args.speed_hz:g} Hz, supply "
              f"{args.supply_temperature_c:g} degC, {rec['supply_flow_m3_s']:g} m3/s; no film "
              "outputs or coefficients at a failed equilibrium")
    return 1


def run_thermal_tilted(b, oil, rec: dict, args: argparse.Namespace) -> int:
    """The tilted thermal equilibrium of ``b`` (a JournalBearing, or a model file's plain,
    tilting-pad or fixed-geometry bearing) under ``--load-n`` with the journal held at the
    tilt: the thermal outputs (``thermal``: the result's ``to_frame()`` row; pad bearings:
    its ``total`` row and ``pads``, one row per pad or lobe), the pose, the film's force and
    moments, the edge film and the 4×4 K, C at the frozen field (exit 1 with a status record
    when it fails)."""
    kw = thermal_kwargs(args)
    tx, ty = tilt_of(args)
    try:
        r = b.thermal_equilibrium(oil=oil, theta_x_rad=tx, theta_y_rad=ty, tilt=True, **kw)
    except ConvergenceError as exc:
        return _failed(rec, args, getattr(exc, "status", "error"),
                       getattr(exc, "detail", str(exc)))
    if r.status not in CONVERGED:
        return _failed(rec, args, r.status, r.message)
    pads = hasattr(r, "pad_tilts_rad")
    if pads:
        rec["thermal"], rec["pads"] = _pad_rows(r)
    else:
        rec["thermal"] = thermal_row(r)
    rec.update(journal_x_m=r.x_m, journal_y_m=r.y_m, k_n_per_m=np.asarray(r.K).tolist(),
               c_n_s_per_m=np.asarray(r.C).tolist(), coefficient_method="perturbation")
    rec.update(journal_theta_x_rad=r.journal_theta_x_rad,
               journal_theta_y_rad=r.journal_theta_y_rad,
               force_n=np.asarray(r.force_n).tolist(),
               film_moment_n_m=np.asarray(r.film_moment_n_m).tolist(), h_min_m=r.h_min_m,
               h_min_angle_deg=r.h_min_angle_deg, h_min_z_m=r.h_min_z_m,
               coordinates=list(COORDINATES), **coefficient_record(r.K4, r.C4))
    if args.json:
        print(json_text(rec))
        return 0
    if pads:
        print(f"thermal equilibrium ({r.thermal_model} model, {r.status}): T_max = "
              f"{r.max_temperature_c_total:.2f} degC, power loss {r.power_loss_w_total:.5g} W, "
              f"supply flow {r.supply_flow_m3_s_total:.5g} m3/s")
        print(table_text(r.to_frame()[[c for c in _PAD_TEXT if c in r.to_frame()]]))
        print(f"equilibrium: x = {r.x_m:.6g} m, y = {r.y_m:.6g} m, "
              f"eps = {r.eccentricity_ratio:.4g}")
    elif kw["model"] == "thd":
        print_thd(r, args)
    else:
        print_effective(r, args, r.h_min_m, r.h_min_angle_deg)
    print(f"force on journal: Fx = {r.force_n[0]:.6g} N, Fy = {r.force_n[1]:.6g} N")
    print_tilt(r.journal_theta_x_rad, r.journal_theta_y_rad, r.film_moment_n_m, r.h_min_m,
               r.h_min_angle_deg, r.h_min_z_m, r.K4, r.C4,
               "at the thermal equilibrium, temperature frozen")
    return 0


__all__ = ["failed_aligned", "least_feeding_supply", "print_effective", "print_thd",
           "run_thermal_tilted", "thermal_kwargs",
           "thermal_model", "thermal_row"]
