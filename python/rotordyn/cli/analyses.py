"""The single-point analyses on the command line: ``info``, ``validate``, ``modes``,
``equilibrium``, ``thermal``, ``stability``, ``campbell``, ``threshold``, ``unbalance``."""

from __future__ import annotations

import dataclasses
import sys

import numpy as np

from rotordyn import analysis
from rotordyn._common.info import __version__, build_info
from rotordyn._common.status import CONVERGED
from rotordyn.cli import sleeve
from rotordyn.cli.common import (JSON_HELP, MODEL_HELP, add_dpi, add_operating_point,
                                 add_thermal_arguments, check_figure, json_text, oil_from_args,
                                 save_figure, table_text)
from rotordyn.cli.common import add_thd_arguments, default_vary
from rotordyn.cli.common import speeds as parse_speeds
from rotordyn.errors import InputError
from rotordyn.model import builtin as models


def register(sub) -> None:
    """The subcommands of this module on the ``rotordyn`` parser's subparsers ``sub``."""
    _register(sub)
    for name in ("validate", "modes", "static", "campbell", "unbalance"):
        add_dpi(sub.choices[name])


def _register(sub) -> None:
    s = sub.add_parser("info", help="package and library versions")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_info)

    s = sub.add_parser("validate", help="check a model file")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also draw the rotor (sections, disks, bearings) to FIG.png/.svg")
    s.set_defaults(func=_cmd_validate)

    s = sub.add_parser("modes", help="natural frequencies of the rotor (full or reduced)")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--speed-hz", type=float, default=0.0, metavar="HZ",
                   help="spin speed for the gyroscopic coupling, Hz")
    s.add_argument("--reduction", choices=["none", "guyan", "irs", "craig-bampton"], default=None,
                   help="model reduction (default: the model's [reduction] method)")
    s.add_argument("--n-modes", type=int, default=None, metavar="N",
                   help="number of modes (default: all of a reduced model, 12 of a full one)")
    s.add_argument("--part", choices=["rotor", "sleeve"], default="rotor",
                   help="rotor, or the active bearing's flexible sleeve")
    s.add_argument("--without-bearings", action="store_true",
                   help="the rotor on its supports without the model's bearing elements (a model "
                        "with bearings is refused otherwise: use `rotordyn stability` for its modes)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the mode shapes (full FE model) to FIG.png/.svg")
    s.add_argument("--mode", type=int, default=None, metavar="K",
                   help="with --plot: the 3-D whirl orbits of mode K (1-based) along the rotor "
                        "(default: all modes' shapes in the x plane)")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_modes)

    s = sub.add_parser("equilibrium", help="static equilibrium of the system (eq. 14)")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    s.add_argument("--method", choices=["newton", "successive"], default="newton",
                   help="equilibrium iteration")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_equilibrium)

    s = sub.add_parser("thermal", help="thermal equilibrium of the fluid-film bearings: "
                       "effective-temperature or THD film of plain and active journal "
                       "bearings, THD film of tilting-pad and fixed-geometry bearings (one row "
                       "per pad or lobe; docs/film-physics.md)")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    add_thermal_arguments(s)
    add_thd_arguments(s)
    s.add_argument("--density-kg-m3", type=float, default=None, metavar="RHO",
                   help="oil density, kg/m3 (default: the model's [thermal.oil], else 870)")
    s.add_argument("--tol-k", type=float, default=1e-6, metavar="K",
                   help="the films' temperatures settled to |dT| <= K, kelvin (default: 1e-6)")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_thermal)

    s = sub.add_parser("static", help="static deflection, shear, bending moment and the "
                                      "reactions at the equilibrium")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the deflection, shear and moment diagrams to FIG.png/.svg")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_static)

    s = sub.add_parser("stability", help="eigenvalues of the linearised system (eq. 19)")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    _add_mode_window(s)
    _add_thermal_flag(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_stability)

    s = sub.add_parser("campbell", help="natural frequencies against speed; critical speeds")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--speeds-hz", default=None, metavar="SPEC",
                   help="speeds, Hz: start:stop:step (inclusive) or a comma-separated list "
                        "(default: " + DEFAULT_SPEEDS_TEXT + ")")
    add_operating_point(s, speed=False)
    s.add_argument("--harmonic", type=float, default=1.0, metavar="N",
                   help="excitation order: critical speeds where f = N x speed")
    s.add_argument("--all-whirl", action="store_true",
                   help="report backward-whirl crossings too (default: forward and "
                        "planar whirl, the modes an unbalance drives)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the Campbell diagram to FIG.png or FIG.svg")
    _add_mode_window(s, n_default=None)
    _add_thermal_flag(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_campbell)

    s = sub.add_parser("threshold", help="threshold of instability (max Re λ = 0)")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--vary", choices=["chamber_pressure_pa", "config_ay_m", "speed_hz"],
                   default=None, help="the input scanned for the threshold (default: "
                   "chamber_pressure_pa with an active journal bearing, else speed_hz)")
    s.add_argument("--bounds", type=float, nargs=2, default=None, metavar=("LO", "HI"),
                   help="scan interval of --vary, in its unit (Pa, m or Hz); default 0 0.5e6 "
                        "for chamber_pressure_pa, required for the others")
    s.add_argument("--n-scan", type=int, default=11, metavar="N",
                   help="points of the bracketing scan")
    add_operating_point(s)
    _add_thermal_flag(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_threshold)

    s = sub.add_parser("unbalance", help="unbalance response, critical speeds, API 684 margins")
    s.add_argument("model", help=MODEL_HELP)
    _add_thermal_flag(s)
    s.add_argument("--unbalance", action="append", required=True,
                   metavar="STATION,MASS_KG_M,PHASE_DEG",
                   help="unbalance m·e (kg m) at a station with its phase (deg); repeatable")
    s.add_argument("--speeds-hz", default=None, metavar="SPEC",
                   help="speeds, Hz: start:stop:step or a list; refined near each peak "
                        "(default: " + DEFAULT_SPEEDS_TEXT + ")")
    s.add_argument("--station", type=int, action="append", default=None, metavar="K",
                   help="output station, repeatable (default: the unbalanced stations)")
    s.add_argument("--operating-speed-hz", type=float, nargs=2, default=None,
                   metavar=("MIN", "MAX"),
                   help="operating speed range, Hz, for the API 684 separation margins")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the response figure to FIG.png/.svg")
    s.add_argument("--plot-kind", choices=["bode", "polar"], default="bode",
                   help="figure for --plot: Bode (amplitude/phase, AF, margins) or polar")
    add_operating_point(s, speed=False)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_unbalance)


def _cmd_info(args) -> int:
    info = build_info()
    if args.json:
        print(json_text(info))
    else:
        print(f"rotordyn {__version__}")
        for key in ("eigen", "sundials", "suitesparse", "compiler"):
            if key in info:
                print(f"  {key}: {info[key]}")
    return 0


def _cmd_validate(args) -> int:
    check_figure(args.plot)
    s = models.load(args.model)
    print(f"{args.model}: ok ({s.rotor.n_elements} elements, {s.rotor.n_stations} stations, "
          f"{s.mass_kg:.4f} kg)")
    if args.plot:
        from rotordyn.plot import rotor_drawing

        save_figure(rotor_drawing(s), args.plot, args.dpi)
    return 0


# -- modes ------------------------------------------------------------------------------
def _modes_payload(r) -> dict:
    out = {
        "model": r.model,
        "speed_hz": r.speed_hz,
        "frequencies_hz": r.frequencies_hz,
        "damping_ratio": r.damping_ratio,
        "whirl": list(r.whirl),
    }
    if r.full is not None:
        out["full_frequencies_hz"] = r.full.frequencies_hz
        out["frequency_errors"] = r.frequency_errors()
    return out


def _cmd_modes(args) -> int:
    if args.part == "sleeve":
        return sleeve.modes(args)
    check_figure(args.plot)
    s = models.load(args.model)
    r = analysis.modes(s, args.speed_hz, reduction=args.reduction, n_modes=args.n_modes,
                       without_bearings=args.without_bearings)
    if args.json:
        print(json_text(_modes_payload(r)))
    else:
        print(table_text(r.to_frame()))
    if args.plot:
        shown = r.full if r.full is not None else r  # shapes of the full FE model
        if args.mode is not None:
            if not 1 <= args.mode <= len(shown.eigenvalues):
                raise InputError(f"--mode: expected 1..{len(shown.eigenvalues)}, got "
                                          f"{args.mode}")
            save_figure(shown.plot(args.mode - 1, system=s), args.plot, args.dpi)
        else:
            save_figure(shown.plot(), args.plot, args.dpi)
    return 0


# -- equilibrium ------------------------------------------------------------------------
def _cmd_equilibrium(args) -> int:
    s = models.load(args.model)
    e = analysis.equilibrium(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
                             method=args.method, warm_start=False)
    if args.json:
        print(json_text({
            "status": e.status, "message": e.message, "method": e.method,
            "speed_hz": e.speed_hz, "chamber_pressure_pa": e.chamber_pressure_pa,
            "bearings": e.per_bearing(),  # keyed by bearing name, numbers not arrays
            "iterations": e.iterations, "reynolds_solves": e.reynolds_solves,
            "residual": e.residual,
        }))
    else:
        print(table_text(e.to_frame()))
        pads = e.pads_frame()
        if len(pads):  # tilting pads: every pad's tilt, peak pressure, film and load state
            print(table_text(pads))
    return 0 if e.converged else 1


def _cmd_thermal(args) -> int:
    s = models.load(args.model)
    if s.thermal is not None and all(x is None for x in (args.oil_walther, args.oil_exponential,
                                                       args.oil_power)):
        # the model's [thermal] oil (--supply-temperature-c may still override), with the
        # properties given on the command line (they were silently ignored before)
        props = {f: getattr(args, f) for f in ("density_kg_m3", "specific_heat_j_per_kg_k")
                 if getattr(args, f) is not None}
        oil = dataclasses.replace(s.thermal.oil, **props) if props else None
    else:  # a law of its own: the model's density and specific heat unless given
        oil = oil_from_args(args, base=s.thermal.oil if s.thermal is not None else None)
    if oil is None and s.thermal is None:
        raise InputError("--supply-temperature-c: required (the oil's supply temperature, "
                         "degC) when the model has no [thermal] table")
    _check_thermal_model(s, args)
    r = analysis.system_thermal_equilibrium(
        s, speed_hz=args.speed_hz, oil=oil, supply_temperature_c=args.supply_temperature_c,
        carry_over=args.carry_over, effective_factor=args.effective_factor,
        supply_flow_m3_s=args.supply_flow_m3_s, chamber_pressure_pa=args.chamber_pressure_pa,
        config_ay_m=args.config_ay_m, model=args.thermal_model,
        journal_htc_w_m2k=args.journal_htc_w_m2k,
        bush_htc_w_m2k=args.bush_htc_w_m2k, journal_temperature_c=args.journal_temperature_c,
        bush_temperature_c=args.bush_temperature_c, tol_k=args.tol_k)
    df = r.to_frame()
    if args.json:
        print(json_text({"status": r.status, "message": r.message, "iterations": r.iterations,
                         "thermal_model": r.thermal_model,
                         "bearings": df.to_dict(orient="records"),
                         "pads": r.pads_frame().to_dict(orient="records")}))
    else:
        mean = "T_mean" if r.thermal_model == "thd" else "T_eff"
        print(f"thermal model {r.thermal_model}: {r.status} after {r.iterations} iterations")
        for k, name in enumerate(r.bearing_names):
            print(f"{name}: T_max = {r.max_temperature_c[k]:.2f} degC, {mean} = "
                  f"{r.effective_temperature_c[k]:.2f} degC, power loss "
                  f"{r.power_loss_w[k]:.5g} W, film flow {r.film_flow_m3_s[k]:.5g} m3/s, "
                  f"side flow {r.side_flow_m3_s[k]:.5g} m3/s, supply flow "
                  f"{r.supply_flow_m3_s[k]:.5g} m3/s")
        print(table_text(df))
        pads = r.pads_frame()
        if len(pads):  # tilting pads: every pad's tilt, peak pressure, film, temperatures
            print(table_text(pads))
    return 0 if r.status in CONVERGED else 1


def _check_thermal_model(s, args) -> None:
    """The option that contradicts the thermal model chosen (``--model``, else the model
    file's ``[thermal] model``), named before any solve: ``--effective-factor`` with the THD
    film (it has no effective temperature to weight), a wall option with the adiabatic
    effective-temperature model. (Every thermal bearing, plain, active,
    tilting-pad or fixed-geometry, takes either model.)"""
    from rotordyn.analysis.thermal import THD_ONLY_OPTIONS, refuse_other_model_options

    chosen = args.thermal_model or getattr(s.thermal, "model", None) or "effective"
    refuse_other_model_options(chosen, {k: getattr(args, k, None) for k in (
        *THD_ONLY_OPTIONS, "effective_factor")}, flags=True)


MODE_TABLE_ROWS = 12  # modes a table shows without --n-modes / --max-freq-hz


def _add_mode_window(s, n_default: int | None = None) -> None:
    s.add_argument("--n-modes", type=int, default=n_default, metavar="N",
                   help="the N lowest modes (table default: the first 12 shown, all in --json)")
    s.add_argument("--max-freq-hz", type=float, default=None, metavar="HZ",
                   help="only modes whose damped frequency is at most HZ (a frequency window)")


def _window(freqs, args, table: bool) -> np.ndarray:
    """Indices of the modes in the window of --n-modes / --max-freq-hz (a table without
    either shows the first MODE_TABLE_ROWS)."""
    keep = np.arange(len(freqs))
    if args.max_freq_hz is not None:
        if not args.max_freq_hz > 0:
            raise InputError(f"--max-freq-hz: expected a frequency > 0 Hz, got "
                             f"{args.max_freq_hz!r}")
        keep = keep[np.asarray(freqs)[keep] <= args.max_freq_hz]
    if args.n_modes is None and args.max_freq_hz is None and table:
        keep = keep[:MODE_TABLE_ROWS]
    return keep


def _cmd_static(args) -> int:
    check_figure(args.plot)
    s = models.load(args.model)
    r = analysis.static(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m)
    if args.json:
        print(json_text({"status": r.status, "message": r.message, "speed_hz": r.speed_hz,
                         "weight_n": r.weight_n, "reactions": _by_name(r.reactions),
                         "along": r.to_frame().drop(columns="status").to_dict("list")}))
    else:
        print(table_text(r.reactions))
        print(repr(r), file=sys.stderr)
    if args.plot and r.status in CONVERGED:
        save_figure(r.plot(system=s), args.plot, args.dpi)
    if r.status not in CONVERGED:
        print(f"rotordyn: failed: {r.status}: {r.message}", file=sys.stderr)
        return 1
    return 0


def _by_name(frame) -> dict:
    """Rows of a (name, station, …) table keyed by name (``station <k>`` for an unnamed
    support), the other columns as plain values."""
    out = {}
    for rec in frame.to_dict("records"):
        name = rec.pop("name") or f"station {rec['station']}"
        out[name if name not in out else f"{name} (station {rec['station']})"] = rec
    return out


def _add_thermal_flag(s) -> None:
    s.add_argument("--thermal", action="store_true",
                   help="each speed at its own thermal equilibrium of the model's [thermal] "
                        "oil system, the temperature field frozen for K_H, D_H "
                        "(docs/film-physics.md)")
    s.add_argument("--thermal-model", choices=["effective", "thd"], default=None,
                   help="with --thermal: the thermal film model (default: the model's "
                        "[thermal] model)")


def _thermal(args, s):
    """The ``thermal=`` keyword of the analyses from --thermal/--thermal-model (None:
    isothermal); InputError naming the option when the model has no oil system."""
    if not args.thermal:
        if args.thermal_model is not None:
            raise InputError("--thermal-model: needs --thermal")
        return None
    if s.thermal is None:
        raise InputError("--thermal: the model has no [thermal] table (its oil system, "
                         "docs/model-file.md)")
    return {} if args.thermal_model is None else {"model": args.thermal_model}


def _thermal_json(t, message: str = ""):
    """A point's thermal equilibrium for --json; one that raised (None): its status and why
    (the result's ``point_message``)."""
    if t is None:
        return {"status": "error", "message": message} if message else None
    return {"model": t.thermal_model, "status": t.status, "film": list(t.bearing_names),
            "effective_temperature_c": t.effective_temperature_c,
            "max_temperature_c": t.max_temperature_c, "power_loss_w": t.power_loss_w}


def _messages(res) -> list:
    """Why each speed failed (the result's ``point_message``: a str, None where it
    converged)."""
    return list(res.point_message)


def _thermal_summary(speeds, thermal, messages=None) -> None:
    """Per speed at its own thermal equilibrium: the hottest film and the power loss, or why
    it failed (stderr; nothing for isothermal films)."""
    if not thermal:
        return
    print("each speed at its own thermal equilibrium (field frozen):", file=sys.stderr)
    for i, (f, t) in enumerate(zip(speeds, thermal)):
        if t is None or t.status not in CONVERGED:
            why = (f" ({t.status}: {t.message})" if t is not None else
                   f" ({messages[i]})" if messages is not None and messages[i] else "")
            print(f"  {f:g} Hz: thermal equilibrium failed" + why, file=sys.stderr)
            continue
        print(f"  {f:g} Hz: T_max {float(np.max(t.max_temperature_c)):.4g} degC, "
              f"{float(np.sum(t.power_loss_w)):.4g} W", file=sys.stderr)


def _cmd_stability(args) -> int:
    s = models.load(args.model)
    st = analysis.stability(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
                            n_modes=args.n_modes, thermal=_thermal(args, s))
    df = st.to_frame()
    keep = _window(st.frequencies_hz, args, table=not args.json)
    if args.json:
        cols = ["mode", "freq_hz", "eig_real_1_per_s", "damping_ratio", "log_dec",
                "mode_stable"]
        verdict = st.stable if st.status in CONVERGED else None  # none without equilibrium
        print(json_text({"status": st.status, "message": st.message, "stable": verdict,
                         "speed_hz": st.speed_hz, "max_real_1_per_s": st.max_real_1_per_s,
                         "modes": df.iloc[keep][cols].to_dict("list")
                         | {"whirl": list(st.whirl[keep]), "kind": list(st.kind[keep])},
                         "thermal": _thermal_json(st.thermal),
                         "pad_load_note": st.pad_load_note}))
    else:
        if len(df):  # a failed equilibrium has no modes: its status line below, no empty table
            print(table_text(df.iloc[keep]))
        if len(keep) < len(df):
            print(f"({len(keep)} of {len(df)} modes shown; --n-modes N or --max-freq-hz HZ for "
                  "others; the least damped mode and the verdict cover all)", file=sys.stderr)
        if st.status in CONVERGED:  # a failed equilibrium has no verdict (below: why)
            print(f"{'stable' if st.stable else 'UNSTABLE'}: largest Re λ = "
                  f"{st.max_real_1_per_s:.4g} 1/s", file=sys.stderr)
            if st.pad_load_note:  # a verdict at the onset of pad loading: sensitive
                print(f"note: {st.pad_load_note}", file=sys.stderr)
        if st.thermal is not None:
            t = st.thermal
            print(f"at the thermal equilibrium ({t.thermal_model} model, field frozen): "
                  + "; ".join(f"{n}: T_eff {a:.4g} degC, T_max {b:.4g} degC, {p:.4g} W"
                              for n, a, b, p in zip(t.bearing_names, t.effective_temperature_c,
                                                    t.max_temperature_c, t.power_loss_w)),
                  file=sys.stderr)
    if st.status not in CONVERGED:  # a failed equilibrium: no eigenvalues, exit 1
        print(f"rotordyn: failed: {st.status}: {st.message}", file=sys.stderr)
        return 1
    return 0


def _failed_speeds(speeds_hz, status, messages=()) -> int:
    """Name every speed without a converged equilibrium on stderr (its status and, where
    known, why); the exit code: 1 when no speed converged, else 0."""
    if status is None:
        return 0
    status = [str(x) for x in status]
    for i, (f, stt) in enumerate(zip(speeds_hz, status)):
        if stt not in CONVERGED:
            why = messages[i] if i < len(messages) and messages[i] else ""
            print(f"rotordyn: {f:g} Hz: {stt}" + (f": {why}" if why else ""), file=sys.stderr)
    return 1 if status and not any(x in CONVERGED for x in status) else 0


PAPER_MODELS = ("paper-rig", "paper-rig-hs")
DEFAULT_SPEEDS_TEXT = ("5:120:1 on the paper's rig; else the report's range: 2 %%…125 %% of "
                       "the maximum operating speed, or up to 125 %% of the second undamped "
                       "critical speed on stiff bearings, within any bearing tables")


def _speeds(args, s, operating_speed_hz=None) -> np.ndarray:
    """``--speeds-hz`` as given; else the paper's 5–120 Hz for its rig, or the report's range
    for the model (rotordyn.report.criteria.speed_range: from the operating speed or the
    undamped criticals, within the bearing tables), said on stderr. A rig-only default (5–120
    Hz) on another machine would miss its criticals or leave its bearing tables."""
    if args.speeds_hz is not None:
        return parse_speeds(args.speeds_hz)
    if operating_speed_hz is not None and not all(np.isfinite(f) and f > 0
                                                  for f in operating_speed_hz):
        raise InputError(f"--operating-speed-hz: expected speeds > 0 Hz, got "
                         f"{list(operating_speed_hz)!r}")
    if s.name in PAPER_MODELS and operating_speed_hz is None:
        return parse_speeds("5:120:1")
    from rotordyn.report.criteria import speed_range

    rng = speed_range(s, operating_speed_hz, paper=s.name in PAPER_MODELS)
    print(f"speeds: {len(rng.speeds_hz)} from {rng.speeds_hz[0]:.4g} to {rng.speeds_hz[-1]:.4g} "
          f"Hz ({rng.why}; --speeds-hz to choose)", file=sys.stderr)
    return rng.speeds_hz


def _cmd_campbell(args) -> int:
    check_figure(args.plot)
    s = models.load(args.model)
    speeds = _speeds(args, s)
    th = _thermal(args, s)
    if s.bearings:
        c = analysis.campbell(s, speeds, args.chamber_pressure_pa, args.config_ay_m,
                              n_modes=args.n_modes, thermal=th)
    else:
        c = analysis.rotor_campbell(s, speeds, **({} if args.n_modes is None
                                                  else {"n_modes": args.n_modes}))
    crit = c.critical_speeds(harmonic=args.harmonic, whirl=None if args.all_whirl else "forward")
    if args.json:
        # critical speeds: the crossings of modes with a resonance; every crossing in the records
        print(json_text({"critical_speeds_hz": crit.loc[crit["resonant"], "speed_hz"].to_numpy(),
                     "critical_speeds": crit.to_dict("records"),
                     "speeds_hz": c.speeds_hz, "frequencies_hz": c.frequencies_hz,
                     "point_status": list(c.point_status) if c.point_status is not None
                     else None, "point_message": _messages(c)}
                    | ({"thermal": [_thermal_json(t, m) for t, m in
                                    zip(c.thermal, _messages(c))]} if c.thermal
                       else {})))
    else:
        if len(crit):
            print(table_text(crit))
        else:  # say what was looked for, not pandas' "(no rows)"
            which = "" if args.all_whirl else "forward "
            print(f"no {args.harmonic:g}× crossing of a {which}mode between "
                  f"{c.speeds_hz[0]:g} and {c.speeds_hz[-1]:g} Hz: no critical speed there "
                  "(--json or --plot for the modes' frequencies)")
        if len(crit) and not crit["resonant"].all():
            print("(resonant False: the mode is damped beyond ζ = 1/√2 there, δ ≥ 2π: it crosses "
                  "the line without a resonance peak and is not a critical speed)",
                  file=sys.stderr)
        _thermal_summary(c.speeds_hz, c.thermal, _messages(c))
    if args.plot:
        ax = c.plot()
        if args.max_freq_hz is not None:
            ax.set_ylim(0, args.max_freq_hz)
        save_figure(ax, args.plot, args.dpi)
    return _failed_speeds(c.speeds_hz, c.point_status, _messages(c))


def _cmd_threshold(args) -> int:
    s = models.load(args.model)
    args.vary = args.vary or default_vary(s)
    if args.bounds is None and args.vary != "chamber_pressure_pa":
        unit = {"speed_hz": "Hz", "config_ay_m": "m"}[args.vary]
        raise InputError(f"--bounds: required with --vary {args.vary} (LO HI in {unit}; only "
                         "chamber_pressure_pa has a default range, 0 0.5e6 Pa)")
    lo, hi = args.bounds or (0.0, 0.5e6)
    t = analysis.threshold(s, args.vary, bounds=(lo, hi), speed_hz=args.speed_hz,
                           chamber_pressure_pa=args.chamber_pressure_pa,
                           config_ay_m=args.config_ay_m, n_scan=args.n_scan,
                           thermal=_thermal(args, s))
    payload = {args.vary: t.value, "whirl_frequency_hz": t.whirl_frequency_hz,
               "whirl_ratio": t.whirl_ratio, "stable_side": t.stable_side,
               "crossings": list(t.crossings), "status": t.status, "message": t.message,
               "evaluations": t.evaluations}
    print(json_text(payload) if args.json else table_text(t.to_frame()))
    return 0


def _cmd_unbalance(args) -> int:
    check_figure(args.plot)
    s = models.load(args.model)
    ub = []
    for text in args.unbalance:
        try:
            st, me, ph = text.split(",")
            ub.append((int(st), float(me), float(ph)))
        except ValueError:
            raise InputError(
                f"--unbalance: expected STATION,MASS_KG_M,PHASE_DEG, got {text!r}") from None
    speeds = _speeds(args, s, tuple(args.operating_speed_hz) if args.operating_speed_hz
                     else None)
    u = analysis.unbalance_response(s, ub, speeds, stations=args.station,
                                    chamber_pressure_pa=args.chamber_pressure_pa,
                                    config_ay_m=args.config_ay_m,
                                    operating_speed_hz=args.operating_speed_hz,
                                    thermal=_thermal(args, s))
    peaks = {int(st): u.peaks(st).to_dict("records") for st in u.stations}
    if args.json:
        print(json_text({"stations": list(u.stations), "peaks": peaks,
                     "response": u.to_frame().to_dict("list"),
                     "point_status": [str(x) for x in u.point_status],
                     "point_message": _messages(u)}
                    | ({"thermal": [_thermal_json(t, m) for t, m in
                                    zip(u.thermal, _messages(u))]} if u.thermal
                       else {})))
    else:
        print(repr(u).strip("<>"))  # largest orbit, speeds above the threshold, failed speeds
        sp = np.asarray(u.speeds_hz)
        conv = np.isin(np.asarray(u.point_status, dtype=object), CONVERGED)
        for st in u.stations:
            pk = u.peaks(st)
            if pk.empty and not conv.any():
                print(f"station {st}: no converged speed (below, why each failed)")
            elif pk.empty:
                print(f"station {st}: no resonance peak over {sp.min():g}–{sp.max():g} Hz")
            else:
                print(f"station {st}: {len(pk)} resonance peak(s)")
                print(table_text(pk))
        _thermal_summary(u.speeds_hz, u.thermal, _messages(u))
    if args.plot:  # one figure per output station (FIG_station<k>.png when several)
        from pathlib import Path

        for st in u.stations:
            path = args.plot if len(u.stations) == 1 else str(
                Path(args.plot).with_name(f"{Path(args.plot).stem}_station{st}"
                                          f"{Path(args.plot).suffix}"))
            save_figure(u.plot(station=st, kind=args.plot_kind), path, args.dpi)
    return _failed_speeds(u.speeds_hz, u.point_status, _messages(u))
