"""Command-line interface: ``rotordyn <command> ...``.

Exit codes: 0 success, 2 bad input (the message names the field), 1 runtime failure.
Machine-readable output goes to stdout with ``--json``; logs go to stderr.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn import cli_bearing
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.cli_common import ArgumentParser as _ArgumentParser
from rotordyn.cli_common import json_text as _json
from rotordyn.cli_common import speeds as _speeds



# -- info -------------------------------------------------------------------------------
def _cmd_info(args) -> int:
    info = rotordyn.build_info()
    if args.json:
        print(_json(info))
    else:
        print(f"rotordyn {rotordyn.__version__}")
        for key in ("eigen", "sundials", "suitesparse", "compiler"):
            if key in info:
                print(f"  {key}: {info[key]}")
    return 0


# -- validate ---------------------------------------------------------------------------
def _save(ax, path: str) -> None:
    """Save the figure of ``ax`` (or of the first of a tuple of Axes) to PNG/SVG/PDF."""
    import matplotlib.pyplot as plt

    fig = (ax[0] if isinstance(ax, tuple) else ax).figure
    fig.savefig(path)
    plt.close(fig)
    print(f"wrote {path}", file=sys.stderr)


def _check_fig(path) -> None:
    """Check a --plot file before any solve (folder, format) and select the Agg backend."""
    if path is not None:
        _figure_path("--plot", path)
    import matplotlib

    matplotlib.use("Agg")


def _cmd_validate(args) -> int:
    _check_fig(args.plot)
    s = rotordyn.models.load(args.model)
    print(f"{args.model}: ok ({s.rotor.n_elements} elements, {s.rotor.n_stations} stations, "
          f"{s.mass_kg:.4f} kg)")
    if args.plot:
        from rotordyn.plot import rotor_drawing

        _save(rotor_drawing(s), args.plot)
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
        from rotordyn import cli_sleeve  # provided with the sleeve model

        return cli_sleeve.modes(args)
    _check_fig(args.plot)
    s = rotordyn.models.load(args.model)
    r = rotordyn.modes(s, args.speed_hz, reduction=args.reduction, n_modes=args.n_modes)
    if args.json:
        print(_json(_modes_payload(r)))
    else:
        print(r.to_frame().to_string(index=False))
    if args.plot:
        shown = r.full if r.full is not None else r  # shapes of the full FE model
        if args.mode is not None:
            if not 1 <= args.mode <= len(shown.eigenvalues):
                raise rotordyn.InputError(f"--mode: expected 1..{len(shown.eigenvalues)}, got "
                                          f"{args.mode}")
            _save(shown.plot(args.mode - 1, system=s), args.plot)
        else:
            _save(shown.plot(), args.plot)
    return 0


# -- equilibrium ------------------------------------------------------------------------
def _cmd_equilibrium(args) -> int:
    s = rotordyn.models.load(args.model)
    e = rotordyn.equilibrium(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
                             method=args.method, warm_start=False)
    if args.json:
        print(_json({
            "status": e.status, "message": e.message, "method": e.method,
            "speed_hz": e.speed_hz, "chamber_pressure_pa": e.chamber_pressure_pa,
            "bearings": [
                {"name": e.bearing_names[i], "config_ax_m": e.config_ax_m[i],
                 "config_ay_m": e.config_ay_m[i], "journal_x_m": e.journal_x_m[i],
                 "journal_y_m": e.journal_y_m[i], "x_over_c": e.x_over_c[i],
                 "y_over_c": e.y_over_c[i], "h_min_m": e.h_min_m[i],
                 "sleeve_m": e.sleeve_m.get(i, np.zeros(0))}
                for i in range(len(e.bearing_names))],
            "iterations": e.iterations, "reynolds_solves": e.reynolds_solves,
            "residual": e.residual,
        }))
    else:
        print(e.to_frame().to_string(index=False))
    return 0 if e.converged else 1


# -- linear analyses (issue 5) -----------------------------------------------------------
def _figure_path(flag: str, path: str) -> str:
    """An output figure: its folder must exist and its suffix be a format matplotlib writes
    (issue 13: a missing folder or an unknown suffix gave a traceback after the solve)."""
    from matplotlib.figure import Figure

    p = Path(path)
    kinds = Figure().canvas.get_supported_filetypes()
    if p.suffix.lstrip(".").lower() not in kinds:
        raise rotordyn.InputError(f"{flag}: expected a file name ending in one of "
                                  f"{', '.join('.' + k for k in sorted(kinds))}, got {path!r}")
    folder = p.parent if str(p.parent) else Path(".")
    if not folder.is_dir():
        raise rotordyn.InputError(f"{flag}: folder {str(folder)!r} does not exist")
    if p.is_dir():
        raise rotordyn.InputError(f"{flag}: {path!r} is a directory")
    return path


def _out_dir(flag: str, path: str) -> str:
    """An output directory, created (with its parents) if missing; InputError naming the
    flag when it is a file or cannot be created."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise rotordyn.InputError(f"{flag}: {path!r} exists and is not a directory")
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise rotordyn.InputError(f"{flag}: cannot create {path!r}: {exc.strerror}") from None
    return path


def _cmd_stability(args) -> int:
    s = rotordyn.models.load(args.model)
    st = rotordyn.stability(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m)
    if args.json:
        print(_json({"status": st.status, "message": st.message, "stable": st.stable,
                     "speed_hz": st.speed_hz, "max_real_1_per_s": st.max_real_1_per_s,
                     "modes": st.to_frame()[["mode", "freq_hz", "eig_real_1_per_s",
                                             "damping_ratio", "log_dec"]].to_dict("list")
                     | {"whirl": list(st.whirl), "kind": list(st.kind)}}))
    else:
        print(st.to_frame().to_string(index=False))
    if st.status not in CONVERGED:  # a failed equilibrium: no eigenvalues, exit 1
        print(f"rotordyn: failed: {st.status}: {st.message}", file=sys.stderr)
        return 1
    return 0


def _cmd_campbell(args) -> int:
    _check_fig(args.plot)
    speeds = _speeds(args.speeds_hz)
    s = rotordyn.models.load(args.model)
    if s.bearings:
        c = rotordyn.campbell(s, speeds, args.chamber_pressure_pa, args.config_ay_m)
    else:
        c = rotordyn.rotor_campbell(s, speeds)
    crit = c.critical_speeds(harmonic=args.harmonic, whirl=None if args.all_whirl else "forward")
    if args.json:
        print(_json({"critical_speeds_hz": crit["speed_hz"].to_numpy(),
                     "critical_speeds": crit.to_dict("records"),
                     "speeds_hz": c.speeds_hz, "frequencies_hz": c.frequencies_hz,
                     "point_status": list(c.point_status) if c.point_status is not None
                     else None}))
    else:
        print(crit.to_string(index=False))
    if args.plot:
        _save(c.plot(), args.plot)
    return 0


def _cmd_threshold(args) -> int:
    s = rotordyn.models.load(args.model)
    lo, hi = args.bounds
    t = rotordyn.threshold(s, args.vary, bounds=(lo, hi), speed_hz=args.speed_hz,
                           chamber_pressure_pa=args.chamber_pressure_pa,
                           config_ay_m=args.config_ay_m, n_scan=args.n_scan)
    payload = {args.vary: t.value, "whirl_frequency_hz": t.whirl_frequency_hz,
               "whirl_ratio": t.whirl_ratio, "stable_side": t.stable_side,
               "crossings": list(t.crossings), "status": t.status, "message": t.message,
               "evaluations": t.evaluations}
    print(_json(payload) if args.json else t.to_frame().to_string(index=False))
    return 0


def _cmd_unbalance(args) -> int:
    _check_fig(args.plot)
    s = rotordyn.models.load(args.model)
    ub = []
    for text in args.unbalance:
        try:
            st, me, ph = text.split(",")
            ub.append((int(st), float(me), float(ph)))
        except ValueError:
            raise rotordyn.InputError(
                f"--unbalance: expected STATION,MASS_KG_M,PHASE_DEG, got {text!r}") from None
    u = rotordyn.unbalance_response(s, ub, _speeds(args.speeds_hz), stations=args.station,
                                    chamber_pressure_pa=args.chamber_pressure_pa,
                                    config_ay_m=args.config_ay_m,
                                    operating_speed_hz=args.operating_speed_hz)
    peaks = {int(st): u.peaks(st).to_dict("records") for st in u.stations}
    if args.json:
        print(_json({"stations": list(u.stations), "peaks": peaks,
                     "response": u.to_frame().to_dict("list")}))
    else:
        for st in u.stations:
            print(f"station {st}:")
            print(u.peaks(st).to_string(index=False))
    if args.plot:
        _save(u.plot(kind=args.plot_kind), args.plot)
    return 0


MODEL_HELP = ("model: a TOML file or a built-in name (paper-rig, paper-rig-hs, friswell-5.9.1); "
              "see `rotordyn validate`")
JSON_HELP = "print one JSON record on stdout (NaN written as null) instead of a table"


def _add_operating_point(s, speed=True):
    if speed:
        s.add_argument("--speed-hz", type=float, default=50.0, metavar="HZ",
                       help="spin speed W, Hz")
    s.add_argument("--chamber-pressure-pa", type=float, default=0.0, metavar="PA",
                   help="active bearing chamber pressure p_c, Pa gauge (0.15 MPa = 1.5e5)")
    s.add_argument("--config-ay-m", type=float, default=None, metavar="M",
                   help="housing offset a_y of the active bearing, m, > 0 above the line "
                        "(-1.85 mm = -1.85e-3; default: the model's own)")


# -- sweeps and plots ----------------------------------------------------------------------
def _cmd_sweep(args) -> int:
    from rotordyn.sweep import SweepInterrupted, run_sweep
    from rotordyn.sweep.runner import manifest_json

    try:
        res = run_sweep(args.spec, args.out, scheduler=args.scheduler, workers=args.workers,
                        threads=args.threads, resume=args.resume,
                        progress=False if args.json else None)
    except SweepInterrupted as exc:
        print(f"rotordyn: {exc}", file=sys.stderr)
        return 130
    if args.json:
        print(manifest_json(res))
    else:
        c = res.counts
        print(f"{res.manifest['sweep_id']}: {res.done}/{res.n_chunks} chunks, "
              f"{res.manifest['n_points']} points (ok {c['ok']}, failed {c['failed']}, "
              f"unstable {c['unstable']}) -> {args.out}")
    return 0 if res.complete else 1


def _cmd_plot(args) -> int:
    from rotordyn.plot import plot_dataset
    from rotordyn.sweep import read_dataset

    _figure_path("--out", args.out)
    kw = ({"style": args.style, "scale": args.scale, "axis": args.axis}
          if args.kind == "waterfall" else {})
    plot_dataset(read_dataset(args.dir), args.kind, args.out, **kw)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


# -- report (the main job of `make run`) --------------------------------------------------
def _cmd_report(args) -> int:
    from rotordyn import report

    return report.run(args.model, _out_dir("--out", args.out), html=args.html,
                      operating_speed_hz=args.operating_speed_hz)


def build_parser() -> argparse.ArgumentParser:
    p = _ArgumentParser(prog="rotordyn", description=rotordyn.__doc__,
                        epilog="Exit codes: 0 success, 2 bad input (one line naming the field), "
                               "1 runtime failure. Units: SI, flags carry the unit suffix.")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_ArgumentParser,
                           metavar="COMMAND")

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
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the mode shapes (full FE model) to FIG.png/.svg")
    s.add_argument("--mode", type=int, default=None, metavar="K",
                   help="with --plot: the 3-D whirl orbits of mode K (1-based) along the rotor "
                        "(default: all modes' shapes in the x plane)")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_modes)

    s = sub.add_parser("equilibrium", help="static equilibrium of the system (eq. 14)")
    s.add_argument("model", help=MODEL_HELP)
    _add_operating_point(s)
    s.add_argument("--method", choices=["newton", "successive"], default="newton",
                   help="equilibrium iteration")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_equilibrium)

    s = sub.add_parser("stability", help="eigenvalues of the linearised system (eq. 19)")
    s.add_argument("model", help=MODEL_HELP)
    _add_operating_point(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_stability)

    s = sub.add_parser("campbell", help="natural frequencies against speed; critical speeds")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--speeds-hz", default="5:120:1", metavar="SPEC",
                   help="speeds, Hz: start:stop:step (inclusive) or a comma-separated list")
    _add_operating_point(s, speed=False)
    s.add_argument("--harmonic", type=float, default=1.0, metavar="N",
                   help="excitation order: critical speeds where f = N x speed")
    s.add_argument("--all-whirl", action="store_true",
                   help="report backward-whirl crossings too (default: forward only)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the Campbell diagram to FIG.png or FIG.svg")
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_campbell)

    s = sub.add_parser("threshold", help="threshold of instability (max Re λ = 0)")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--vary", choices=["chamber_pressure_pa", "config_ay_m", "speed_hz"],
                   default="chamber_pressure_pa", help="the input scanned for the threshold")
    s.add_argument("--bounds", type=float, nargs=2, default=(0.0, 0.5e6), metavar=("LO", "HI"),
                   help="scan interval of --vary, in its unit (Pa, m or Hz)")
    s.add_argument("--n-scan", type=int, default=11, metavar="N",
                   help="points of the bracketing scan")
    _add_operating_point(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_threshold)

    s = sub.add_parser("unbalance", help="unbalance response, critical speeds, API 684 margins")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--unbalance", action="append", required=True,
                   metavar="STATION,MASS_KG_M,PHASE_DEG",
                   help="unbalance m·e (kg m) at a station with its phase (deg); repeatable")
    s.add_argument("--speeds-hz", default="5:120:1", metavar="SPEC",
                   help="speeds, Hz: start:stop:step or a list; refined near each peak")
    s.add_argument("--station", type=int, action="append", default=None, metavar="K",
                   help="output station, repeatable (default: the unbalanced stations)")
    s.add_argument("--operating-speed-hz", type=float, nargs=2, default=None,
                   metavar=("MIN", "MAX"),
                   help="operating speed range, Hz, for the API 684 separation margins")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="also write the response figure to FIG.png/.svg")
    s.add_argument("--plot-kind", choices=["bode", "polar"], default="bode",
                   help="figure for --plot: Bode (amplitude/phase, AF, margins) or polar")
    _add_operating_point(s, speed=False)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_unbalance)

    s = sub.add_parser("sweep", help="run a sweep spec on dask into a parquet dataset")
    s.add_argument("spec", help="sweep specification, sweeps/<name>.toml")
    s.add_argument("--out", required=True, metavar="DIR", help="output dataset directory")
    s.add_argument("--scheduler", default=None, metavar="ADDR",
                   help="tcp://host:port of an existing dask cluster (default: a LocalCluster)")
    s.add_argument("--workers", type=int, default=None, metavar="N",
                   help="LocalCluster worker processes (default: dask's choice)")
    s.add_argument("--threads", type=int, default=None, metavar="N",
                   help="compute on N threads in this process, no dask (default: off)")
    s.add_argument("--resume", action=argparse.BooleanOptionalAction, default=True,
                   help="continue an interrupted sweep in --out; --no-resume restarts the "
                        "same sweep from scratch")
    s.add_argument("--json", action="store_true", help="one JSON summary line, no progress")
    s.set_defaults(func=_cmd_sweep)

    s = sub.add_parser("plot", help="figure from a sweep directory")
    s.add_argument("dir", help="sweep dataset directory (written by `rotordyn sweep`)")
    s.add_argument("--kind", required=True,
                   choices=["stability-map", "equilibrium", "campbell", "waterfall"],
                   help="figure kind; it must match the sweep's analysis")
    s.add_argument("--out", required=True, metavar="FIG", help="FIG.png or FIG.svg")
    s.add_argument("--style", choices=["cascade", "map"], default="cascade",
                   help="waterfall: 3-D cascade or colour map (speed × frequency)")
    s.add_argument("--scale", choices=["linear", "log"], default="linear",
                   help="waterfall: amplitude scale")
    s.add_argument("--axis", choices=["x", "y"], default="x",
                   help="waterfall: journal motion component")
    s.set_defaults(func=_cmd_plot)

    s = sub.add_parser("report", help="the main job: analyses of a model written under --out")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--out", default="out", metavar="DIR",
                   help="directory for report.txt, tables and figures")
    s.add_argument("--html", default=None, metavar="FILE",
                   help="also write one self-contained HTML report (figures as SVG)")
    s.add_argument("--operating-speed-hz", type=float, nargs=2, default=None,
                   metavar=("MIN", "MAX"),
                   help="operating speed range, Hz, for the API margins in the HTML report "
                        "(default: 45 55 for paper-rig, none otherwise)")
    s.set_defaults(func=_cmd_report)
    cli_bearing.register(sub)
    from rotordyn import cli_control  # issue 8: `rotordyn control ...`

    cli_control.register(sub)
    return p


def _check_offset(s, args) -> None:
    """Unit plausibility of --config-ay-m against the active bearing's clearance."""
    from rotordyn import plausibility
    from rotordyn.model.bearings import ActiveJournalBearing

    ay = getattr(args, "config_ay_m", None)
    for b in s.bearings:
        if isinstance(b, ActiveJournalBearing):
            plausibility.housing_offset("--config-ay-m", ay, b.clearance_m)
            return


def _warning_printer(default):
    """rotordyn's own warnings as one line on stderr (``rotordyn: warning: <field> = ...``);
    other libraries' warnings as usual."""

    def show(message, category, filename, lineno, file=None, line=None):
        from rotordyn.errors import RotordynWarning

        if issubclass(category, RotordynWarning):
            print(f"rotordyn: warning: {message}", file=sys.stderr)
        else:
            default(message, category, filename, lineno, file, line)

    return show


def main(argv: list[str] | None = None) -> int:
    import warnings

    argv = list(sys.argv[1:] if argv is None else argv)
    shown = warnings.showwarning
    warnings.showwarning = _warning_printer(shown)
    try:
        args = build_parser().parse_args(argv)
        if getattr(args, "model", None) is not None and hasattr(args, "config_ay_m"):
            _check_offset(rotordyn.models.load(args.model), args)
        return int(args.func(args) or 0)
    except KeyboardInterrupt:
        print("rotordyn: interrupted", file=sys.stderr)
        return 130
    except rotordyn.InputError as exc:
        print(f"rotordyn: error: {exc}", file=sys.stderr)
        return 2
    except rotordyn.RotordynError as exc:
        print(f"rotordyn: failed: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:  # output piped into e.g. `head`
        return 0
    except MemoryError:
        print("rotordyn: failed: out of memory (reduce the grid, the number of points or "
              "n_out)", file=sys.stderr)
        return 1
    except OSError as exc:  # a file system failure while writing results
        print(f"rotordyn: failed: {exc}", file=sys.stderr)
        return 1
    except Exception as exc:  # a bug: one line, not a traceback (ROTORDYN_DEBUG=1 re-raises)
        if os.environ.get("ROTORDYN_DEBUG"):
            raise
        print(f"rotordyn: internal error: {type(exc).__name__}: {exc} (please report; "
              "ROTORDYN_DEBUG=1 shows the traceback)", file=sys.stderr)
        return 1
    finally:
        warnings.showwarning = shown


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
