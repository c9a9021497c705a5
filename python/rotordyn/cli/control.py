"""``rotordyn control``: control-law synthesis with the active journal bearing.

``rotordyn control schedule MODEL --unbalance ST ME PH ...``: the open-loop chamber-pressure
schedule p_c(Ω) minimising the unbalance response at ``--stations`` under a stability
margin and the actuator limits; writes grid.csv, schedule.csv, schedule.png under --out.

``rotordyn control closed-loop MODEL --speed-hz F --chamber-pressure-pa P ...``: designs a
feedback law (``--law pd`` tuned on the active bearing's vertical journal displacement, ``lqg``
or ``hinf`` on a modal truncation, all measuring that journal), prints the linear closed loop
(eigenvalues, margins), runs the nonlinear transient open and closed loop from a disturbance
(or a run-up with ``--run-up-hz``),
writes summary.json, timeseries.csv and closed_loop.png under --out.
Exit 2 on bad input (the message names the field), 1 on a failed run.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from rotordyn.cli.common import FIGURE_DPI, json_text, out_dir
from rotordyn.errors import InputError

MAX_AXIS = 10_000  # points of one --speed-hz or --pressure-pa axis


def _axis(name, vals):
    lo, hi, step = vals
    if not (np.isfinite([lo, hi, step]).all() and step > 0 and hi >= lo):
        raise InputError(f"{name}: expected finite START STOP STEP with STEP > 0 and "
                         f"STOP >= START, got {lo:g} {hi:g} {step:g}")
    count = math.floor((hi - lo) / step + 0.5) + 1  # counted before allocating
    if count > MAX_AXIS:
        raise InputError(f"{name}: expected at most {MAX_AXIS} grid points, got {count:.3g}")
    return np.arange(lo, hi + 0.5 * step, step)


def _actuator(args):
    from rotordyn.control import Actuator

    if not args.valve_hz >= 0:
        raise InputError(f"--valve-hz: expected >= 0 Hz (0: ideal valve), got {args.valve_hz}")
    return Actuator(order=2 if args.valve_hz else 0,
                    natural_frequency_hz=args.valve_hz or 100.0, damping=args.valve_damping,
                    p_min_pa=args.p_min_pa, p_max_pa=args.p_max_pa)


def register(sub: argparse._SubParsersAction) -> None:
    s = sub.add_parser("control", help="control-law synthesis with the active bearing",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    csub = s.add_subparsers(dest="control_command", required=True,
                            parser_class=type(s))

    def common(c):
        c.add_argument("model", help="TOML path or a built-in name (paper-rig)")
        c.add_argument("--config-ay-m", type=float, default=None,
                       help="active bearing's vertical housing offset a_y, m (default: the "
                            "model's)")
        c.add_argument("--p-min-pa", type=float, default=0.0,
                       help="lower chamber-pressure limit of the valve, Pa")
        c.add_argument("--p-max-pa", type=float, default=1.0e6,
                       help="upper chamber-pressure limit of the valve, Pa")
        c.add_argument("--valve-hz", type=float, default=100.0,
                       help="servo-valve natural frequency (2nd order); 0: ideal")
        c.add_argument("--valve-damping", type=float, default=0.7,
                       help="servo-valve damping ratio ζ")
        c.add_argument("--out", default="out/control", help="output directory")
        c.add_argument("--json", action="store_true", help="print the summary as JSON")

    c = csub.add_parser("schedule", help="open-loop p_c(Ω) schedule from the linear model")
    common(c)
    c.add_argument("--unbalance", type=float, nargs=3, action="append", required=True,
                   metavar=("STATION", "MASS_KG_M", "PHASE_DEG"),
                   help="rotating unbalance (repeatable)")
    c.add_argument("--stations", type=int, nargs="+", default=None,
                   help="output stations of the objective (default: the unbalanced ones)")
    c.add_argument("--speed-hz", type=float, nargs=3, default=[10.0, 120.0, 1.0],
                   metavar=("START", "STOP", "STEP"), help="speed grid, Hz")
    c.add_argument("--pressure-pa", type=float, nargs=3, default=[0.0, 1.0e6, 0.05e6],
                   metavar=("START", "STOP", "STEP"), help="chamber-pressure grid, Pa")
    c.add_argument("--min-damping", type=float, default=2e-4,
                   help="least damping ratio of every mode")
    c.add_argument("--smooth-pa-per-hz", type=float, default=None,
                   help="largest schedule slope, Pa/Hz (default: none, pointwise choice)")
    c.set_defaults(func=run_schedule)

    c = csub.add_parser("closed-loop", help="design a feedback law and run it (linear + nonlinear)")
    common(c)
    c.add_argument("--speed-hz", type=float, default=50.0,
                   help="design (and run) speed, Hz")
    c.add_argument("--chamber-pressure-pa", type=float, default=0.05e6,
                   help="base chamber pressure (operating point), Pa")
    c.add_argument("--law", choices=("pd", "lqg", "hinf"), default="pd",
                   help="feedback law: tuned PD on the active bearing's vertical journal "
                        "displacement, LQG, or "
                        "H∞ (needs the optional slycot: pip install 'rotordyn[hinf]')")
    c.add_argument("--t-end-s", type=float, default=1.0, help="simulated time, s")
    c.add_argument("--disturbance-c", type=float, default=0.1,
                   help="initial vertical displacement of the active bearing's journal, units "
                        "of its clearance")
    c.add_argument("--unbalance", type=float, nargs=3, action="append", default=[],
                   metavar=("STATION", "MASS_KG_M", "PHASE_DEG"),
                   help="rotating unbalance (repeatable; default: none)")
    c.add_argument("--run-up-hz", type=float, nargs=3, default=None,
                   metavar=("START", "STOP", "RATE_HZ_S"),
                   help="run up instead of a constant speed (design at --speed-hz)")
    c.add_argument("--n-out", type=int, default=4001, help="stored time samples")
    c.add_argument("--computation-delay-s", type=float, default=0.0,
                   help="delay between measurement and command, s (linear loop and transient "
                        "through its Padé approximant)")
    c.add_argument("--pade-order", type=int, default=6,
                   help="order of the Padé approximant of --computation-delay-s (1..20)")
    c.set_defaults(func=run_closed_loop)


def _station(flag, value) -> int:
    """A station read as a float by argparse: a whole number, else an InputError."""
    if not (math.isfinite(value) and value == int(value)):
        raise InputError(f"{flag}: expected a whole station number, got {value:g}")
    return int(value)


def _peak(values) -> float:
    """Largest finite value, NaN (JSON null) when there is none."""
    finite = np.asarray(values, float)[np.isfinite(values)]
    return float(finite.max()) if finite.size else math.nan


def _margins_text(cl) -> str:
    """The margins of the linear closed loop in one line (or why there are none)."""
    if cl.margins is None:
        return f"margins {cl.margins_message}"
    m = cl.margins.input
    lo_db, hi_db = m.disk.gain_db
    return (f"gain margins {m.gain_margin_lower:.4g} ({m.gain_margin_lower_hz:.4g} Hz) and "
            f"{m.gain_margin_upper:.4g} ({m.gain_margin_upper_hz:.4g} Hz), phase margin "
            f"{m.phase_margin_deg:.2f}° ({m.phase_margin_hz:.4g} Hz), delay margin "
            f"{m.delay_margin_s * 1e3:.4g} ms, peak |S| {m.peak_sensitivity:.4g} "
            f"({m.peak_sensitivity_hz:.4g} Hz), disk margin {m.disk.alpha:.4g} "
            f"([{lo_db:.2f}, {hi_db:.2f}] dB, ±{m.disk.phase_deg:.2f}°)")


def _load(model):
    from rotordyn.model import builtin as models

    return models.load(model)


def run_schedule(args) -> int:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from rotordyn.control.schedule import pressure_schedule

    out = Path(out_dir("--out", args.out))  # before the grid is solved
    system = _load(args.model)
    act = _actuator(args)
    ub = [(_station("--unbalance", s), m, p) for s, m, p in args.unbalance]
    res = pressure_schedule(system, ub, _axis("--speed-hz", args.speed_hz),
                            _axis("--pressure-pa", args.pressure_pa), stations=args.stations,
                            config_ay_m=args.config_ay_m, min_damping=args.min_damping,
                            p_min_pa=act.p_min_pa, p_max_pa=act.p_max_pa,
                            smooth_pa_per_hz=args.smooth_pa_per_hz)
    res.grid.to_csv(out / "grid.csv", index=False)
    res.to_frame().to_csv(out / "schedule.csv", index=False)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].plot(res.speeds_hz, res.pressures_pa / 1e6, "o-", ms=2, label="schedule")
    if np.isfinite(res.best_constant_pa):
        ax[0].axhline(res.best_constant_pa / 1e6, color="k", lw=0.7, label="best constant")
    ax[0].set_xlabel("speed (Hz)")
    ax[0].set_ylabel("p_c (MPa)")
    ax[0].legend()
    ax[1].semilogy(res.speeds_hz, res.objective_m * 1e6, label="schedule")
    ax[1].semilogy(res.speeds_hz, res.best_constant_objective_m * 1e6, label="best constant")
    ax[1].set_xlabel("speed (Hz)")
    ax[1].set_ylabel("largest amplitude (µm)")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(out / "schedule.png", dpi=FIGURE_DPI)
    plt.close(fig)
    summary = {"best_constant_pa": res.best_constant_pa,
               "peak_schedule_m": _peak(res.objective_m),
               "peak_best_constant_m": _peak(res.best_constant_objective_m),
               "speeds_without_feasible_pressure": int(np.sum(~np.isfinite(res.pressures_pa))),
               "files": ["grid.csv", "schedule.csv", "schedule.png"]}
    print(json_text(summary) if args.json else
          f"best constant p_c = {res.best_constant_pa:g} Pa; largest amplitude "
          f"{summary['peak_best_constant_m']:.4g} m -> {summary['peak_schedule_m']:.4g} m with "
          f"the schedule; wrote {out}/grid.csv, schedule.csv, schedule.png")
    return 0


def run_closed_loop(args) -> int:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd

    from rotordyn._common import validate as v
    from rotordyn.analysis import transient
    from rotordyn.analysis.assembly import assembled
    from rotordyn.control import SpeedProfile
    from rotordyn.control import _checks as chk
    from rotordyn.control.closedloop import closed_loop
    from rotordyn.control.lqr import lqg
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.plant import active_bearing_index, plant
    from rotordyn.control.reduction import modal_truncation

    if not args.t_end_s > 0 or not math.isfinite(args.t_end_s):
        raise InputError(f"--t-end-s: expected a finite time > 0 s, got {args.t_end_s}")
    if not math.isfinite(args.disturbance_c):
        raise InputError(f"--disturbance-c: expected a finite displacement (clearances), got "
                         f"{args.disturbance_c}")
    v.integer("--n-out (n_out)", args.n_out, lo=2)
    from rotordyn.control.delay import MAX_DELAY_S, MAX_ORDER

    v.in_range("--computation-delay-s", args.computation_delay_s, 0.0, MAX_DELAY_S)
    v.integer("--pade-order", args.pade_order, lo=1, hi=MAX_ORDER)
    out = Path(out_dir("--out", args.out))  # before the design and the transients
    if args.law == "hinf":
        from rotordyn.control.hinf import _slycot

        try:
            _slycot()
        except ImportError as exc:
            raise InputError(f"--law hinf: {exc}") from None
    system = _load(args.model)
    act = _actuator(args)
    chk.operating_point(system, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m)
    unbalances = [(_station("--unbalance", s), m, ph) for s, m, ph in args.unbalance]
    if unbalances:
        try:
            chk.unbalances(system, unbalances)
        except InputError as exc:
            raise InputError(f"--unbalance: {exc}") from None
    profile = SpeedProfile.ramp(*args.run_up_hz) if args.run_up_hz else None
    # the active bearing's journal: the one the transient disturbs and the law acts at (on a
    # model whose active bearing is not bearings[0], journal 0 is another bearing's)
    ia = active_bearing_index(system)
    p = plant(system, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
              measurements=[("journal", ia)], actuator=act)
    if args.law == "pd":
        k, cl = tune_pd(p)
        if args.computation_delay_s:
            cl = closed_loop(p, k, computation_delay_s=args.computation_delay_s,
                             pade_order=args.pade_order)
    else:
        pr, _ = modal_truncation(p, 500.0)
        if args.law == "hinf":
            from rotordyn.control.hinf import hinf

            k = hinf(pr)
        else:
            k = lqg(pr)
        cl = closed_loop(p, k, computation_delay_s=args.computation_delay_s,
                         pade_order=args.pade_order)
    if args.computation_delay_s:  # the transient runs the same delayed law
        from rotordyn.control.delay import with_pade_delay

        k = with_pade_delay(k, args.computation_delay_s, args.pade_order)
    ol_lam = p.poles
    asm = assembled(system)
    c = asm.bearings[ia].clearance_m if asm.bearings else 1.0
    kw = dict(n_out=args.n_out, actuator=act, unbalances=unbalances)
    t_end = args.t_end_s
    if profile is not None:
        f0, f1, rate = args.run_up_hz
        kw["speed"] = profile
        t_end = abs(f1 - f0) / rate
        speed0 = f0
    else:
        kw["disturbance_m"] = (0.0, args.disturbance_c * c)
        speed0 = args.speed_hz
    ol = transient(system, t_end, speed0, args.chamber_pressure_pa, args.config_ay_m, **kw)
    cln = transient(system, t_end, speed0, args.chamber_pressure_pa, args.config_ay_m,
                       controller=k, **kw)

    def dev(tr):
        return np.hypot(tr.journal_x_m[:, ia] - tr.equilibrium_r[asm.bearings[ia].jx],
                        tr.journal_y_m[:, ia] - tr.equilibrium_r[asm.bearings[ia].jy])

    pd.DataFrame({"t_s": cln.t, "speed_hz": cln.speed_hz_t,
                  "open_loop_journal_x_m": ol.journal_x_m[:, ia],
                  "open_loop_journal_y_m": ol.journal_y_m[:, ia],
                  "closed_loop_journal_x_m": cln.journal_x_m[:, ia],
                  "closed_loop_journal_y_m": cln.journal_y_m[:, ia],
                  "chamber_pressure_command_pa": cln.chamber_pressure_command_pa,
                  "chamber_pressure_pa": cln.chamber_pressure_actual_pa,
                  "controller_output_pa": cln.controller_output_pa}).to_csv(
        out / "timeseries.csv", index=False)
    last = cln.t >= 0.8 * t_end
    summary = {"law": args.law, "journal_bearing": system.bearings[ia].name or str(ia),
               "controller_states": k.n_states,
               "computation_delay_s": args.computation_delay_s,
               "pade_order": args.pade_order if args.computation_delay_s else None,
               "hinf_gamma": k.info.get("gamma") if args.law == "hinf" else None,
               "open_loop_max_real_1_per_s": float(ol_lam.real.max()),
               "closed_loop_max_real_1_per_s": cl.max_real,
               "closed_loop_min_damping": cl.min_damping,
               "margins": cl.margins.summary() if cl.margins is not None else None,
               "margins_message": cl.margins_message,
               "open_loop_status": ol.status, "closed_loop_status": cln.status,
               "open_loop_final_amplitude_m": _peak(dev(ol)[last]),
               "closed_loop_final_amplitude_m": _peak(dev(cln)[last]),
               "chamber_pressure_range_pa": [-_peak(-cln.chamber_pressure_actual_pa),
                                             _peak(cln.chamber_pressure_actual_pa)],
               "files": ["summary.json", "timeseries.csv", "closed_loop.png"]}
    (out / "summary.json").write_text(json_text(summary))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].semilogy(ol.t, dev(ol) / c, lw=0.6, label="open loop")
    ax[0].semilogy(cln.t, dev(cln) / c, lw=0.6, label=f"closed loop ({args.law})")
    ax[0].set_xlabel("t (s)")
    ax[0].set_ylabel("|journal − equilibrium| / c")
    ax[0].legend()
    ax[1].plot(cln.t, cln.chamber_pressure_actual_pa / 1e6, lw=0.7)
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("p_c (MPa)")
    fig.tight_layout()
    fig.savefig(out / "closed_loop.png", dpi=FIGURE_DPI)
    plt.close(fig)
    if args.json:
        print(json_text(summary))
    else:
        print(f"{args.law}: open loop max Re λ = {summary['open_loop_max_real_1_per_s']:.3f} 1/s, "
              f"closed loop {cl.max_real:.3f} 1/s (min ζ {cl.min_damping:.4f}); "
              f"{_margins_text(cl)}; nonlinear final amplitude "
              f"{summary['open_loop_final_amplitude_m']:.3g} m open, "
              f"{summary['closed_loop_final_amplitude_m']:.3g} m closed; wrote {out}")
    return 0 if ol.status == "ok" and cln.status == "ok" else 1
