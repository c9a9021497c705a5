"""``rotordyn hopf``: the Hopf point on the stability boundary, its first Lyapunov
coefficient and type (docs/nonlinear.md)."""

from __future__ import annotations

from rotordyn import analysis
from rotordyn._common import validate as v
from rotordyn.analysis.assembly import OPERATING
from rotordyn.analysis.hopf_cycles import check_amplitudes
from rotordyn.cli import branches
from rotordyn.cli.common import (JSON_HELP, MODEL_HELP, add_dpi, add_operating_point,
                                 check_figure, default_vary, json_text, save_figure,
                                 table_text)
from rotordyn.errors import InputError
from rotordyn.model import builtin as models


def register(sub) -> None:
    """The ``hopf`` subcommand on the ``rotordyn`` parser's subparsers ``sub``."""
    s = sub.add_parser("hopf", help="Hopf point of the stability threshold: first Lyapunov "
                                    "coefficient, sub/supercritical, leading-order cycle")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    s.add_argument("--vary", default=None,
                   help="the parameter whose threshold is the Hopf point: chamber_pressure_pa "
                        "(Pa), speed_hz (Hz), config_ay_m (m), or a numeric model field path "
                        "(e.g. bearings.*.clearance_m, SI unit of the field: the model "
                        "re-assembled at each value, the operating point fixed); default "
                        "chamber_pressure_pa with an active journal bearing, else speed_hz")
    s.add_argument("--bounds", type=float, nargs=2, default=None, metavar=("LO", "HI"),
                   help="search the threshold in this range (unit of --vary)")
    s.add_argument("--at", type=float, default=None,
                   help="the threshold value itself (instead of --bounds)")
    s.add_argument("--n-scan", type=int, default=25, help="threshold scan points")
    s.add_argument("--fd-step", type=float, default=5e-2,
                   help="half-width of the film-force polynomial fits (scaled: fraction of "
                        "the clearance)")
    s.add_argument("--grid-check", action="store_true",
                   help="compute l1 again with every film grid refined twice (n_circ and "
                        "n_axial x 2, the same point and fits): l1_refined, and a type that "
                        "changes with the grid is degenerate (docs/nonlinear.md)")
    s.add_argument("--cycles", type=float, nargs="+", default=None, metavar="A",
                   help="also the cycles of the branch born at the point at these amplitudes "
                        "(fractions of the smallest film clearance, increasing, each in "
                        "(0, 0.9]), by harmonic balance with the parameter free: their side, "
                        "stability and the onset (soft/hard) they show (docs/nonlinear.md)")
    s.add_argument("--floquet", default="samples", choices=["samples", "hill", "flow"],
                   help="with --cycles: the cycles' Floquet multipliers from the samples, by "
                        "Hill's method or by a CVODES flow (default: samples)")
    s.add_argument("--floquet-margin", type=float, default=None, metavar="F",
                   help="with --cycles: recheck by the flow where |mu_c| is within F of 1 "
                        "(default 0.01; near a Hopf point that is every cycle: 0 with --floquet "
                        "hill skips the flow, which on a stiff model takes minutes)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="write the leading-order bifurcation diagram")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    add_dpi(s)
    s.set_defaults(func=_cmd_hopf)


def _cmd_hopf(args) -> int:
    check_figure(args.plot)
    if args.cycles is not None:
        check_amplitudes("--cycles", args.cycles)
        if args.floquet_margin is not None:
            v.in_range("--floquet-margin", args.floquet_margin, 0.0, 0.5)
    elif args.floquet != "samples" or args.floquet_margin is not None:
        raise InputError("--floquet, --floquet-margin: apply only with --cycles")
    s = models.load(args.model)
    args.vary = args.vary or default_vary(s)
    if args.cycles is not None and args.vary not in OPERATING:  # before the Hopf solve
        raise InputError(f"--cycles: the cycles at given amplitudes vary an operating "
                         f"variable ({', '.join(OPERATING)}), not the model field "
                         f"{args.vary} (its cycles: rotordyn continuation --start hopf)")
    try:
        res = analysis.hopf(s, args.vary, bounds=None if args.bounds is None else
                            tuple(args.bounds), at=args.at, speed_hz=args.speed_hz,
                            chamber_pressure_pa=args.chamber_pressure_pa,
                            config_ay_m=args.config_ay_m, n_scan=args.n_scan,
                            fd_step=args.fd_step, grid_check=args.grid_check)
    except InputError as exc:  # the API's keyword as the command line's flag
        raise branches.flagged(exc, {"at": "--at"}) from None
    cyc = None
    if args.cycles is not None and res.ok:
        margin = {} if args.floquet_margin is None else {"floquet_margin": args.floquet_margin}
        cyc = analysis.hopf_cycles(s, res, tuple(args.cycles), floquet=args.floquet, **margin)
    if args.json:
        rec = {"status": res.status, "message": res.message, "vary": res.vary,
               "value": res.value, "whirl_frequency_hz": res.whirl_frequency_hz,
               "l1": res.l1, "l1_error": res.l1_error, "type": res.type,
               "grid_check": args.grid_check, "l1_refined": res.l1_refined,
               "alpha_prime": res.alpha_prime, "stable_side": res.stable_side,
               "cycle_side": res.cycle_side,
               "amplitude_coefficient_m2": res.amplitude_coefficient}
        if cyc is not None:
            rec["cycles"] = {"onset": cyc.onset, "l1_side_confirmed": cyc.l1_side_confirmed,
                             "rows": cyc.to_frame().to_dict(orient="records")}
        print(json_text(rec))
    else:
        print(repr(res))
        if res.ok:
            print(table_text(res.to_frame()))
        if cyc is not None:
            print(repr(cyc))
            cols = ["amplitude_c", res.vary, "distance", "side", "stable", "max_multiplier",
                    "period_s", "leading_order_ratio", "status"]
            print(table_text(cyc.to_frame()[cols]))
    if args.plot and res.ok:
        save_figure(res.plot(), args.plot, args.dpi)
    return 0 if res.ok else 1
