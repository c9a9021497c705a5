"""Nonlinear dynamics on the command line: ``periodic-orbit`` (a limit cycle or an
unbalance-forced orbit by shooting or harmonic balance, with its Floquet multipliers) and
``continuation`` (its branch over p_c, speed, a_y or — harmonic-balance correctors only — a
model field by pseudo-arclength continuation, with shooting or harmonic-balance correctors,
from an orbit or from the Hopf point in the bounds (``--start hopf``), or with ``--start
equilibrium`` the branch of static equilibria: :mod:`.branches`; docs/nonlinear.md)."""

from __future__ import annotations

import numpy as np

from rotordyn import analysis
from rotordyn.analysis.assembly import OPERATING
from rotordyn.analysis.continuation import CLI_NEWTON, DEFAULT_NEWTON
from rotordyn.analysis.continuation import SHOOTING_FLOQUET as SHOOTING_BRANCH_FLOQUET
from rotordyn.analysis.field_axis import field_parameter
from rotordyn.analysis.hopf import hopf_branch
from rotordyn.analysis.periodic import SHOOTING_FLOQUET
from rotordyn._common import validate as v
from rotordyn.cli import branches
from rotordyn.cli.common import (JSON_HELP, MODEL_HELP, add_dpi, add_operating_point,
                                 check_figure, json_text, out_dir, save_figure, table_text)
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.model import builtin as models


def register(sub) -> None:
    """The subcommands of this module on the ``rotordyn`` parser's subparsers ``sub``."""
    s = sub.add_parser("periodic-orbit",
                       help="limit cycle or unbalance-forced orbit by shooting or harmonic "
                            "balance, with its Floquet multipliers")
    _orbit_arguments(s)
    _hb_arguments(s, shooting_floquet=True)
    s.add_argument("--bdf-max-order", type=int, default=5, metavar="Q",
                   help="highest BDF order of the CVODES flows, 1..5 (default 5); 2 can "
                        "pay on a flexible rotor whose undamped bending modes hold orders "
                        "3-5 at their stability limit, at loose tolerances "
                        "(docs/nonlinear.md)")
    s.add_argument("--floquet-tol", type=float, default=None, metavar="TOL",
                   help="--floquet samples: refine the multipliers (sub-steps doubled) "
                        "until |μ_c| moves by at most TOL·max(1, |μ_c|), in [0, 0.5] "
                        "(default 1e-3; harmonic balance 0: the single product from the "
                        "samples, no error estimate; shooting: > 0)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="write the orbit and the multipliers in the unit circle")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    add_dpi(s)
    s.set_defaults(func=_cmd_periodic_orbit)

    c = sub.add_parser("continuation",
                       help="branch of limit cycles or forced orbits, or of static "
                            "equilibria (--start equilibrium), over p_c, speed, a_y or a "
                            "model field, by pseudo-arclength continuation, with stability "
                            "and bifurcations")
    _orbit_arguments(c)
    c.add_argument("--vary", required=True,
                   help="the continued parameter: chamber_pressure_pa (Pa), speed_hz (Hz), "
                        "config_ay_m (m), or a numeric model field path (SI unit of the "
                        "field, e.g. bearings.0.viscosity_pa_s, supports.0.kyy_n_per_m: the "
                        "model re-assembled at every value) with --start equilibrium or, "
                        "for orbits, --method harmonic_balance")
    c.add_argument("--bounds", type=float, nargs=2, required=True, metavar=("LO", "HI"),
                   help="parameter range (unit of --vary); must contain the start's value")
    c.add_argument("--ds", type=float, default=None,
                   help="first arclength step (scaled: clearance, period, bounds' span; "
                        "default 0.05 for orbits, 0.02 for equilibria)")
    c.add_argument("--max-points", type=int, default=None,
                   help="points on the branch (default 50 for orbits, 200 for equilibria)")
    c.add_argument("--direction", type=int, choices=[1, -1], default=1,
                   help="leave the start towards growing (1) or falling (-1) parameter")
    _hb_arguments(c, floquet=("samples", "hill", "flow"), shooting_floquet="branch")
    c.add_argument("--floquet-margin", type=float, default=None, metavar="F",
                   help="--floquet samples (harmonic balance: also hill): the multipliers "
                        "from the samples are recomputed by "
                        "one CVODES sensitivity flow where |mu_c| is within F of 1 or the "
                        "trivial multiplier is off 1 by more than F/2, in [0, 0.5] (default "
                        "0.01)")
    c.add_argument("--floquet-tol", type=float, default=None, metavar="TOL",
                   help="--floquet samples (either method): where the screen calls a "
                        "point's verdict close (--floquet-margin), refine its multipliers "
                        "(Magnus steps doubled) until |mu_c| moves by at most "
                        "TOL·max(1, |mu_c|) before any flow, in [0, 0.5] (default 0: the "
                        "flow at every close point)")
    c.add_argument("--newton", choices=list(CLI_NEWTON), default=None,
                   help=f"--method shooting: the correctors (default {DEFAULT_NEWTON}): "
                        "exact = Newton with the monodromy from CVODES sensitivities and "
                        "dR/dp by central differences at every iteration, every point's multipliers at "
                        "--rtol; fast = Broyden updates from the previous point's matrix, "
                        "dR/dp from a CVODES parameter sensitivity (p_c, a_y; the speed "
                        "keeps the central difference), each point's monodromy screened "
                        "at 1e-4 and redone at --rtol where |mu_c| is within 0.005 of 1 "
                        "(docs/nonlinear.md)")
    branches.add_arguments(c)
    c.add_argument("--plot", default=None, metavar="FIG",
                   help="write the bifurcation diagram (orbits: amplitude, equilibria: "
                        "eccentricity ratio against the parameter)")
    c.add_argument("--json", action="store_true", help=JSON_HELP)
    add_dpi(c)
    # None: not given (orbit-only flags are refused with --start equilibrium; each start
    # fills its own defaults: ORBIT_DEFAULTS, branches.EQ_DEFAULTS)
    c.set_defaults(func=_cmd_continuation, kind=None, rtol=None, tol=None,
                   disturbance_c=None, subharmonic=None, speed_hz=None,
                   chamber_pressure_pa=None)


def _orbit_arguments(s) -> None:
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    s.add_argument("--kind", choices=["autonomous", "forced"], default="autonomous",
                   help="autonomous: self-excited limit cycle (period unknown); forced: the "
                        "orbit forced by --unbalance (period --subharmonic / speed)")
    s.add_argument("--unbalance", action="append", default=None,
                   metavar="STATION,MASS_KG_M,PHASE_DEG",
                   help="unbalance m·e (kg m) at a station with its phase (deg); repeatable "
                        "(forced orbits)")
    s.add_argument("--subharmonic", type=int, default=1, metavar="K",
                   help="forced orbits: period K revolutions (default 1)")
    s.add_argument("--settle-s", type=float, default=None, metavar="S",
                   help="simulated seconds of transient before the orbit solve, from the "
                        "equilibrium disturbed by --disturbance-c (default: 1.0 s for a limit "
                        "cycle by shooting, else 0: a forced orbit starts from the linear "
                        "unbalance response at the equilibrium, a limit cycle by harmonic "
                        "balance from the equilibrium displaced along its least-damped whirl "
                        "mode)")
    s.add_argument("--forced-start", choices=["linear", "equilibrium"], default="linear",
                   help="forced orbit without --settle-s: start from the linear unbalance "
                        "response at the equilibrium (linear, default) or from the "
                        "equilibrium itself (equilibrium)")
    s.add_argument("--disturbance-c", type=float, default=0.1, metavar="F",
                   help="vertical disturbance of the active journal (without one: of the "
                        "first bearing's), fraction of the smallest film clearance (default 0.1)")
    s.add_argument("--rtol", type=float, default=1e-8,
                   help="CVODES relative tolerance (default 1e-8)")
    s.add_argument("--tol", type=float, default=1e-6,
                   help="residual tolerance, fraction of the smallest clearance (default "
                        "1e-6; harmonic balance: the scaled AFT residual)")


# The harmonic-balance flags: (argparse dest, flag, default); None in args = not given.
HB_FLAGS = (("harmonics", "--harmonics", 8), ("samples", "--samples", None),
            ("floquet", "--floquet", "samples"), ("start_amplitude_c", "--start-amplitude-c", None))


def _hb_arguments(s, floquet=("samples", "hill", "flow", "none"),
                  shooting_floquet: bool | str = False) -> None:
    s.add_argument("--method", choices=["shooting", "harmonic_balance"], default="shooting",
                   help="shooting (default): Newton on the CVODES flow over one period; "
                        "harmonic_balance: Newton on the Fourier coefficients of the orbit "
                        "with the film forces at --samples points per period (AFT; "
                        "docs/nonlinear.md); a branch's correctors likewise")
    s.add_argument("--harmonics", type=int, default=None, metavar="H",
                   help="harmonic balance: harmonics H of the orbit, 1..1000 (default 8)")
    s.add_argument("--samples", type=int, default=None, metavar="M",
                   help="harmonic balance: time samples per period M >= 2H + 1, at most "
                        "100000 (default 4H)")
    s.add_argument("--floquet", choices=list(floquet), default=None,
                   help="harmonic balance: the Floquet multipliers from the M samples' "
                        "linearisations (samples: Magnus, no film solve), by Hill's method "
                        "on the harmonic-balance Jacobian (hill: no film solve), from one "
                        "CVODES sensitivity flow at --rtol (flow)"
                        + (", or none" if "none" in floquet else "")
                        + ("; shooting: flow (default: every point's converged orbit once "
                           "more with the sensitivities in the error test) or samples (from "
                           "the orbit's samples, the flow only where the verdict is within "
                           "--floquet-margin: cheaper with --newton exact; docs/nonlinear.md)"
                           if shooting_floquet == "branch" else
                           "; shooting: flow (default: the converged orbit once more with "
                           "the sensitivities in the error test), samples (Magnus on the "
                           "orbit's 200 samples, refined: fast on flexible rotors) or "
                           "none" if shooting_floquet else ""))
    s.add_argument("--start-amplitude-c", type=float, default=None, metavar="F",
                   help="harmonic balance, autonomous cycle started at the equilibrium "
                        "(--settle-s 0, the default with harmonic balance): the journal's "
                        "amplitude along the least-damped whirl mode, fraction of its "
                        "clearance in [1e-06, 0.99] (default: 0.3, then 0.6, then 0.9 until "
                        "one converges)")


def _hb_options(args, shooting_floquet: bool = False) -> dict:
    """The periodic_orbit keywords of --method (the HB flags checked, defaults filled in);
    ``shooting_floquet``: --floquet flow/samples/none also with shooting (one orbit)."""
    given = [flag for dest, flag, _ in HB_FLAGS if getattr(args, dest) is not None]
    if args.method != "harmonic_balance":
        fq = args.floquet
        if shooting_floquet and fq is not None:
            given.remove("--floquet")
            if fq not in SHOOTING_FLOQUET:
                raise InputError(f"--floquet: with --method shooting expected one of "
                                 f"{', '.join(SHOOTING_FLOQUET)}, got {fq!r}")
        if given:
            raise InputError(f"{given[0]}: applies only to --method harmonic_balance")
        return {"method": "shooting", **({"floquet": fq} if shooting_floquet else {})}
    opt = {dest: (default if getattr(args, dest) is None else getattr(args, dest))
           for dest, _, default in HB_FLAGS}
    h = _int_in("--harmonics", opt["harmonics"], 1, 1000)
    m = opt["samples"]
    if m is not None:
        m = _int_in("--samples", m, 2 * h + 1, 100_000, f" (2H + 1 with --harmonics {h})")
    if args.start_amplitude_c is not None:
        if args.kind != "autonomous" or (args.settle_s or 0.0) > 0:
            raise InputError("--start-amplitude-c: applies only to an autonomous cycle "
                             "started at the equilibrium (--kind autonomous, --settle-s 0)")
    amp = opt["start_amplitude_c"]  # None: 0.3, 0.6, 0.9 in turn (rotordyn.periodic_orbit)
    if amp is not None:
        amp = v.in_range("--start-amplitude-c", amp, 1e-6, 0.99)
    return {"method": "harmonic_balance", "harmonics": h, "time_points": m,
            "floquet": opt["floquet"], "start_amplitude_c": amp}


def _int_in(flag: str, value: int, lo: int, hi: int, why: str = "") -> int:
    """An integer flag in lo..hi, the error naming the flag and the whole range."""
    if not lo <= value <= hi:
        raise InputError(f"{flag}: expected an integer in {lo}{why}..{hi}, got {value}")
    return value


def _unbalances(texts) -> list:
    ub = []
    for text in texts or ():
        try:
            st, me, ph = text.split(",")
            ub.append((int(st), float(me), float(ph)))
        except ValueError:
            raise InputError(
                f"--unbalance: expected STATION,MASS_KG_M,PHASE_DEG, got {text!r}") from None
    return ub


def _settled_start(args, s, ub):
    """The settling transient of --settle-s (None: start at the equilibrium), or False when it
    failed (printed). Default: 1 s for a limit cycle by shooting, else 0."""
    hb = getattr(args, "method", "shooting") == "harmonic_balance"
    settle = args.settle_s if args.settle_s is not None else (
        1.0 if args.kind == "autonomous" and not hb else 0.0)
    v.non_negative("--settle-s", settle)
    v.finite("--disturbance-c", args.disturbance_c)
    start = None
    if settle > 0:
        bs = list(s.bearings)
        c = min((b.clearance_m for b in bs if hasattr(b, "clearance_m")), default=1e-3)
        start = analysis.transient(s, settle, args.speed_hz, args.chamber_pressure_pa,
                                   args.config_ay_m, unbalances=ub,
                                   disturbance_m=(0.0, args.disturbance_c * c),
                                   n_out=int(round(settle * 10_000)) + 1)
        if start.status not in ("ok", "contact"):
            print(f"rotordyn: the settling transient ended with status {start.status}: "
                  f"{start.message}")
            return False
    return start


def _start_hint(args, start) -> str:
    """What to try when a harmonic-balance limit cycle started from the equilibrium failed."""
    if (getattr(args, "method", "shooting") == "harmonic_balance" and start is None
            and args.kind == "autonomous"):
        return ("\nrotordyn: harmonic balance started from the equilibrium's whirl mode at "
                "--start-amplitude-c of the clearance (without it: 0.3, 0.6 and 0.9 in "
                "turn); a cycle of another size needs a settled start: add --settle-s 1, or "
                "set --start-amplitude-c near its size")
    return ""


def _cmd_periodic_orbit(args) -> int:
    check_figure(args.plot)
    hb = _hb_options(args, shooting_floquet=True)
    if args.floquet_tol is not None:
        if hb["floquet"] != "samples":
            raise InputError("--floquet-tol: applies only to --floquet samples")
        hb["floquet_tol"] = v.in_range("--floquet-tol", args.floquet_tol, 0.0, 0.5,
                                       lo_open=False)
        if hb["method"] != "harmonic_balance" and hb["floquet_tol"] == 0:
            raise InputError("--floquet-tol: with --method shooting expected a value in "
                             "(0, 0.5] (0, the single product, is harmonic balance's), got 0")
    s = models.load(args.model)
    ub = _unbalances(args.unbalance)
    start = _settled_start(args, s, ub)
    if start is False:
        return 1
    res = analysis.periodic_orbit(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
                                  kind=args.kind, start=start, unbalances=ub,
                                  subharmonic=args.subharmonic, rtol=args.rtol, tol=args.tol,
                                  forced_start=args.forced_start,
                                  bdf_max_order=args.bdf_max_order, **hb)
    if args.json:
        mu = np.asarray(res.multipliers, dtype=complex)
        print(json_text({
            "status": res.status, "message": res.message, "kind": res.kind,
            **_method_info(hb, res, start),
            "speed_hz": res.speed_hz, "chamber_pressure_pa": res.chamber_pressure_pa,
            "period_s": res.period_s if res.ok else None,
            "amplitude_m": res.amplitude() if res.ok and res.journal_x_m.shape[1] else None,
            "stable": res.stable, "stability_resolved": res.stability_resolved,
            "critical_type": res.critical_type,
            "multipliers_real": mu.real, "multipliers_imag": mu.imag,
            "trivial_index": res.trivial_index, "critical_index": res.critical_index,
            "residuals": res.residuals, "stats": res.stats,
        }))
    else:
        print(repr(res))
        info = _method_info(hb, res, start)
        settings = ", ".join(f"{k} = {x}" for k, x in info.items() if k != "method")
        print(f"method: {info['method']}" + (f" ({settings})" if settings else ""))
        if res.ok:
            print(table_text(res.multipliers_frame().head(8)))
        else:
            hint = _start_hint(args, start)
            if hint:
                print(hint.lstrip("\n"))
    if args.plot and res.ok:
        save_figure(res.plot(), args.plot, args.dpi)
    return 0 if res.ok else 1


def _method_info(hb: dict, res, start) -> dict:
    """The method and its settings for the output: M as used (the result's, else the
    default 4H), the start amplitude only where it was used (a cycle from the equilibrium)."""
    if hb["method"] != "harmonic_balance":
        return {"method": "shooting", "floquet": hb.get("floquet") or "flow"}
    info = {"method": "harmonic_balance", "harmonics": hb["harmonics"],
            "time_points": int(res.stats.get("time_points",
                                             hb["time_points"] or 4 * hb["harmonics"])),
            "floquet": hb["floquet"]}
    if start is None and res.kind == "autonomous":
        info["start_amplitude_c"] = res.stats.get("start_amplitude_c", hb["start_amplitude_c"])
    return info


#: the orbit branch's defaults of the flags ``continuation`` leaves at None
ORBIT_DEFAULTS = {"kind": "autonomous", "rtol": 1e-8, "tol": 1e-6, "disturbance_c": 0.1,
                  "subharmonic": 1, "speed_hz": 50.0, "chamber_pressure_pa": 0.0,
                  "ds": 0.05, "max_points": 50, "newton": DEFAULT_NEWTON}
#: the operating variables a branch of orbits by shooting varies (harmonic balance: also a
#: numeric model field path)
ORBIT_VARY = OPERATING


def _hopf_point(args, s, vary):
    """``--start hopf``: the Hopf point of the threshold in --bounds at the operating point
    (rd.hopf), or None when there is none (printed)."""
    h = analysis.hopf(s, vary, bounds=tuple(args.bounds), speed_hz=args.speed_hz,
                      chamber_pressure_pa=args.chamber_pressure_pa,
                      config_ay_m=args.config_ay_m)
    if not h.ok:
        print(f"rotordyn: no Hopf point in --bounds: {h!r}")
        return None
    return h


def _cmd_continuation(args) -> int:
    check_figure(args.plot)
    v.bounds("--bounds", args.bounds)
    if args.ds is not None:
        v.positive("--ds", args.ds)
    out = None
    if args.out is not None:
        out = out_dir("--out", args.out)  # before the solve
        import matplotlib

        matplotlib.use("Agg")  # the --out figure
    if args.start == "equilibrium":
        if args.method != "shooting":
            raise InputError("--method: applies only to a branch of orbits (--start orbit)")
        return branches.run_equilibrium(args, out)
    branches.refuse(args, branches.EQUILIBRIUM_ONLY,
                    "applies only to a branch of equilibria (--start equilibrium)")
    if args.start == "hopf":
        branches.refuse(args, branches.NOT_FROM_HOPF, "does not apply to --start hopf (the "
                        "first cycle is the normal form's limit cycle at the Hopf point)")
        if args.method == "shooting" and args.vary not in ORBIT_VARY:
            args.method = "harmonic_balance"  # a model field: the only correctors
    else:
        branches.refuse(args, branches.HOPF_ONLY, "applies only to --start hopf")
    if args.method == "harmonic_balance" and args.newton is not None:
        raise InputError("--newton: applies only to --method shooting (the correctors of "
                         "harmonic balance are Newton on the orbit's coefficients)")
    for k, val in ORBIT_DEFAULTS.items():
        if getattr(args, k) is None:
            setattr(args, k, val)
    if args.method != "harmonic_balance" and args.floquet is not None \
            and args.floquet not in SHOOTING_BRANCH_FLOQUET:
        raise InputError(f"--floquet: with --method shooting expected one of "
                         f"{', '.join(SHOOTING_BRANCH_FLOQUET)}, got {args.floquet!r}")
    hb = _hb_options(args, shooting_floquet=True)
    method = hb["method"]
    fq = hb["floquet"] or ("samples" if method == "harmonic_balance" else "flow")
    if args.floquet_margin is not None:
        if method != "harmonic_balance" and fq != "samples":
            raise InputError("--floquet-margin: applies only to --floquet samples with "
                             "--method shooting (the flow route screens nothing)")
        v.in_range("--floquet-margin", args.floquet_margin, 0.0, 0.5)
    if args.floquet_tol is not None:
        if fq != "samples":
            raise InputError("--floquet-tol: applies only to --floquet samples")
        v.in_range("--floquet-tol", args.floquet_tol, 0.0, 0.5)
    newton = args.newton
    s = models.load(args.model)
    try:  # before the start orbit is solved: an unknown parameter, a field with shooting
        vary = field_parameter(s, args.vary)
    except InputError as exc:
        raise branches.flagged(exc) from None
    if vary not in ORBIT_VARY and method != "harmonic_balance":
        raise InputError(f"--method: a branch of orbits over the model field {vary} has "
                         "harmonic-balance correctors only (--method harmonic_balance; "
                         "shooting varies chamber_pressure_pa, speed_hz or config_ay_m)")
    ub = _unbalances(args.unbalance)
    if args.start == "hopf":
        hres = _hopf_point(args, s, vary)
        if hres is None:
            return 1
    else:
        start = _settled_start(args, s, ub)
        if start is False:
            return 1
        # the start by the branch's method (harmonic balance: its multipliers from the
        # samples; the branch's first corrector solves it again with the branch's options)
        start_how = ({**hb, "floquet": "samples"} if method == "harmonic_balance" else
                     {"method": "shooting"})
        orbit = analysis.periodic_orbit(s, args.speed_hz, args.chamber_pressure_pa,
                                        args.config_ay_m, kind=args.kind, start=start,
                                        unbalances=ub, subharmonic=args.subharmonic,
                                        rtol=args.rtol, tol=args.tol, **start_how)
        if not orbit.ok:
            print(f"rotordyn: no start orbit: {orbit!r}" + _start_hint(args, start))
            return 1
    if method == "harmonic_balance":
        how = {"method": method, "harmonics": hb["harmonics"], "time_points": hb["time_points"],
               "floquet": hb["floquet"], "floquet_margin": args.floquet_margin,
               "floquet_tol": args.floquet_tol}
    else:  # shooting: its route, and the screen's options with samples
        how = {"newton": newton, "floquet": fq, "floquet_margin": args.floquet_margin,
               "floquet_tol": args.floquet_tol}
    steps = {"ds_max": max(0.2, args.ds) if args.ds_max is None else args.ds_max}
    if args.ds_min is not None:
        steps["ds_min"] = args.ds_min
    try:
        if args.start == "hopf":
            br = hopf_branch(s, hres, tuple(args.bounds), distance=args.hopf_distance,
                             ds=args.ds, max_points=args.max_points,
                             param_scale=args.param_scale, rtol=args.rtol, tol=args.tol,
                             **how, **steps)
        else:
            br = analysis.continuation(s, args.vary, tuple(args.bounds), orbit,
                                       unbalances=ub, ds=args.ds,
                                       max_points=args.max_points, direction=args.direction,
                                       param_scale=args.param_scale, rtol=args.rtol,
                                       tol=args.tol, **how, **steps)
    except InputError as exc:
        raise branches.flagged(exc) from None
    except ConvergenceError as exc:  # the first cycle at the Hopf point
        print(f"rotordyn: no start orbit: {exc}")
        return 1
    info = {"method": method}
    if method == "harmonic_balance":
        info.update(harmonics=br.stats["harmonics"], time_points=br.stats["time_points"],
                    floquet=br.stats["floquet"], floquet_margin=br.stats["floquet_margin"],
                    floquet_tol=br.stats.get("floquet_tol", 0.0))
    routes = [o.stats.get("floquet", "flow") for o in br.orbits]
    record = {
        "status": br.status, "stop": br.stop, "message": br.message, "start": args.start,
        "vary": br.vary, "kind": br.kind, **info,
        "newton": newton if method == "shooting" else None, "parameter": br.parameter,
        "amplitude_m": br.amplitude_m, "period_s": br.period_s,
        "max_multiplier": br.max_multiplier, "stable": br.stable,
        "critical_type": list(br.critical_type), "floquet_route": routes,
        "bifurcations": [{"kind": b["kind"], "index": b["index"],
                          "parameter": b["parameter"]} for b in br.bifurcations],
        "stats": br.stats,
    }
    if args.start == "hopf":
        record["hopf"] = {"value": hres.value, "type": hres.type, "l1": hres.l1,
                          "l1_error": hres.l1_error, "cycle_side": hres.cycle_side,
                          "whirl_frequency_hz": hres.whirl_frequency_hz}
    branches.write_outputs(br, record, args, out)  # before stdout (a closed pipe ends it)
    if args.json:
        print(json_text(record))
    else:
        if args.start == "hopf":
            print(repr(hres))
        print(repr(br))
        settings = ", ".join(f"{k} = {x}" for k, x in info.items() if k != "method")
        print(f"method: {method}" + (f" ({settings})" if settings else f" (newton = {newton})"))
        # one row per (point, bearing): both named, or the bearings' rows look repeated
        cols = ["point", "bearing", br.vary, "amplitude_m", "period_s", "max_multiplier",
                "stable", "critical_type", "bifurcation"]
        df = br.to_frame()[cols]
        if method == "harmonic_balance":
            df = df.assign(floquet=np.repeat(routes, len(br.bearing_names)))
        print(table_text(df))
    return 0 if br.ok else 1
