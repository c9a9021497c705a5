"""Command-line interface: ``rotordyn <command> ...``.

Exit codes: 0 success, 2 bad input (the message names the field), 1 runtime failure.
Machine-readable output goes to stdout with ``--json``; logs go to stderr.
"""

from __future__ import annotations

import argparse
import json
import sys

import numpy as np

import rotordyn
from rotordyn import cli_bearing


class _ArgumentParser(argparse.ArgumentParser):
    """argparse that raises InputError (exit 2 through main) instead of exiting itself."""

    def error(self, message):
        raise rotordyn.InputError(f"{self.prog}: {message}")


def _json(obj) -> str:
    def conv(o):
        if isinstance(o, np.ndarray):
            return o.tolist()
        if isinstance(o, (np.floating, np.integer)):
            return o.item()
        raise TypeError(type(o).__name__)

    return json.dumps(obj, indent=2, default=conv)


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
def _cmd_validate(args) -> int:
    s = rotordyn.models.load(args.model)
    print(f"{args.model}: ok ({s.rotor.n_elements} elements, {s.rotor.n_stations} stations, "
          f"{s.mass_kg:.4f} kg)")
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
    s = rotordyn.models.load(args.model)
    r = rotordyn.modes(s, args.speed_hz, reduction=args.reduction, n_modes=args.n_modes)
    if args.json:
        print(_json(_modes_payload(r)))
    else:
        print(r.to_frame().to_string(index=False))
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
    return 0 if e.status in ("ok", "contact") else 1


# -- linear analyses (issue 5) -----------------------------------------------------------
def _speeds(text: str) -> np.ndarray:
    """"a:b:step" (inclusive) or "f1,f2,..." → speeds in Hz."""
    try:
        if ":" in text:
            a, b, st = (float(x) for x in text.split(":"))
            if st <= 0 or b < a:
                raise ValueError
            return np.arange(a, b + 0.5 * st, st)
        return np.array([float(x) for x in text.split(",")])
    except ValueError:
        raise rotordyn.InputError(
            f"--speeds-hz: expected 'start:stop:step' or a comma-separated list, got {text!r}"
        ) from None


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
    return 0


def _cmd_campbell(args) -> int:
    s = rotordyn.models.load(args.model)
    speeds = _speeds(args.speeds_hz)
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
        import matplotlib

        matplotlib.use("Agg")
        ax = c.plot()
        ax.figure.savefig(args.plot, dpi=120, bbox_inches="tight")
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
    return 0


def _add_operating_point(s, speed=True):
    if speed:
        s.add_argument("--speed-hz", type=float, default=50.0)
    s.add_argument("--chamber-pressure-pa", type=float, default=0.0)
    s.add_argument("--config-ay-m", type=float, default=None)


# -- sweeps and plots ----------------------------------------------------------------------
def _cmd_sweep(args) -> int:
    from rotordyn.sweep import run_sweep

    def progress(done, total):
        print(f"chunks {done}/{total}", file=sys.stderr)

    res = run_sweep(args.spec, args.out, scheduler=args.scheduler, workers=args.workers,
                    resume=args.resume, progress=progress)
    m = res.manifest
    failed = m.get("chunks_failed", {})
    print(f"{m['sweep_id']}: {len(m['chunks_done'])}/{m['n_chunks']} chunks, "
          f"{m['n_points']} points -> {args.out}" + (f"; {len(failed)} chunks failed" if failed
                                                     else ""))
    return 0 if res.complete else 1


def _cmd_plot(args) -> int:
    from rotordyn.plot import plot_dataset
    from rotordyn.sweep import read_dataset

    plot_dataset(read_dataset(args.dir), args.kind, args.out)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


# -- report (the main job of `make run`) --------------------------------------------------
def _cmd_report(args) -> int:
    from rotordyn import report

    return report.run(args.model, args.out)


def build_parser() -> argparse.ArgumentParser:
    p = _ArgumentParser(prog="rotordyn", description=rotordyn.__doc__)
    sub = p.add_subparsers(dest="command", required=True, parser_class=_ArgumentParser)

    s = sub.add_parser("info", help="package and library versions")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_info)

    s = sub.add_parser("validate", help="check a model file")
    s.add_argument("model", help="TOML path or a built-in name (paper-rig, friswell-5.9.1)")
    s.set_defaults(func=_cmd_validate)

    s = sub.add_parser("modes", help="natural frequencies of the rotor (full or reduced)")
    s.add_argument("model", help="TOML path or a built-in name (paper-rig, friswell-5.9.1)")
    s.add_argument("--speed-hz", type=float, default=0.0)
    s.add_argument("--reduction", choices=["none", "guyan", "irs", "craig-bampton"], default=None,
                   help="default: the model's [reduction] method")
    s.add_argument("--n-modes", type=int, default=None)
    s.add_argument("--part", choices=["rotor", "sleeve"], default="rotor")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_modes)

    s = sub.add_parser("equilibrium", help="static equilibrium of the system (eq. 14)")
    s.add_argument("model", help="TOML path or a built-in name (paper-rig)")
    s.add_argument("--speed-hz", type=float, default=50.0)
    s.add_argument("--chamber-pressure-pa", type=float, default=0.0)
    s.add_argument("--config-ay-m", type=float, default=None,
                   help="housing offset a_y of the active bearing (default: the model's)")
    s.add_argument("--method", choices=["newton", "successive"], default="newton")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_equilibrium)

    s = sub.add_parser("stability", help="eigenvalues of the linearised system (eq. 19)")
    s.add_argument("model")
    _add_operating_point(s)
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_stability)

    s = sub.add_parser("campbell", help="natural frequencies against speed; critical speeds")
    s.add_argument("model")
    s.add_argument("--speeds-hz", default="5:120:1", help="start:stop:step or a list")
    _add_operating_point(s, speed=False)
    s.add_argument("--harmonic", type=float, default=1.0)
    s.add_argument("--all-whirl", action="store_true", help="backward crossings too")
    s.add_argument("--plot", default=None, help="write the diagram to this PNG/SVG")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_campbell)

    s = sub.add_parser("threshold", help="threshold of instability (max Re λ = 0)")
    s.add_argument("model")
    s.add_argument("--vary", choices=["chamber_pressure_pa", "config_ay_m", "speed_hz"],
                   default="chamber_pressure_pa")
    s.add_argument("--bounds", type=float, nargs=2, default=(0.0, 0.5e6), metavar=("LO", "HI"))
    s.add_argument("--n-scan", type=int, default=11)
    _add_operating_point(s)
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_threshold)

    s = sub.add_parser("unbalance", help="unbalance response, critical speeds, API 684 margins")
    s.add_argument("model")
    s.add_argument("--unbalance", action="append", required=True,
                   metavar="STATION,MASS_KG_M,PHASE_DEG")
    s.add_argument("--speeds-hz", default="5:120:1")
    s.add_argument("--station", type=int, action="append", default=None)
    s.add_argument("--operating-speed-hz", type=float, nargs=2, default=None)
    _add_operating_point(s, speed=False)
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_unbalance)

    s = sub.add_parser("sweep", help="run a sweep spec on dask into a parquet dataset")
    s.add_argument("spec", help="sweeps/<name>.toml")
    s.add_argument("--out", required=True)
    s.add_argument("--scheduler", default=None, help="tcp://host:port of an existing cluster")
    s.add_argument("--workers", type=int, default=None, help="LocalCluster worker processes")
    s.add_argument("--resume", action=argparse.BooleanOptionalAction, default=True)
    s.set_defaults(func=_cmd_sweep)

    s = sub.add_parser("plot", help="figure from a sweep directory")
    s.add_argument("dir")
    s.add_argument("--kind", required=True,
                   choices=["stability-map", "equilibrium", "campbell", "waterfall"])
    s.add_argument("--out", required=True, help="FIG.png or FIG.svg")
    s.set_defaults(func=_cmd_plot)

    s = sub.add_parser("report", help="the main job: analyses of a model written under --out")
    s.add_argument("model")
    s.add_argument("--out", default="out")
    s.set_defaults(func=_cmd_report)
    cli_bearing.register(sub)
    from rotordyn import cli_control  # issue 8: `rotordyn control ...`

    cli_control.register(sub)
    return p


def _join_negative_numbers(argv: list[str]) -> list[str]:
    """``--flag -1.85e-3`` → ``--flag=-1.85e-3`` (argparse takes "-1.85e-3" for an option)."""
    out, i = [], 0
    while i < len(argv):
        tok = argv[i]
        if tok.startswith("--") and "=" not in tok and i + 1 < len(argv) and \
                argv[i + 1].startswith("-"):
            try:
                float(argv[i + 1])
            except ValueError:
                pass
            else:
                out.append(f"{tok}={argv[i + 1]}")
                i += 2
                continue
        out.append(tok)
        i += 1
    return out


def main(argv: list[str] | None = None) -> int:
    argv = _join_negative_numbers(list(sys.argv[1:] if argv is None else argv))
    try:
        args = build_parser().parse_args(argv)
        return int(args.func(args) or 0)
    except rotordyn.InputError as exc:
        print(f"rotordyn: error: {exc}", file=sys.stderr)
        return 2
    except rotordyn.RotordynError as exc:
        print(f"rotordyn: failed: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:  # output piped into e.g. `head`
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
