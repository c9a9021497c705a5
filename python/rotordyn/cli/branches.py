"""``rotordyn continuation --start equilibrium``: the branch of static equilibria over an
operating variable or a numeric model field (:func:`rotordyn.continuation` with
``start="equilibrium"``, analysis/equilibrium_branch.py), and the output both kinds of branch
share (``--json`` record, ``--out`` files, ``--plot``; docs/nonlinear.md)."""

from __future__ import annotations

import sys
from pathlib import Path

from rotordyn import analysis
from rotordyn.cli.common import json_text, save_figure, table_text
from rotordyn.errors import InputError
from rotordyn.model import builtin as models

#: the start of ``rotordyn continuation``: a periodic orbit found as by ``periodic-orbit``
#: (the default), the static equilibrium, or the cycles born at the Hopf point in --bounds
STARTS = ("orbit", "equilibrium", "hopf")

#: flags of an orbit branch only: (argparse dest, flag)
ORBIT_ONLY = (("kind", "--kind"), ("unbalance", "--unbalance"),
              ("subharmonic", "--subharmonic"), ("settle_s", "--settle-s"),
              ("disturbance_c", "--disturbance-c"), ("rtol", "--rtol"), ("newton", "--newton"),
              ("harmonics", "--harmonics"), ("samples", "--samples"), ("floquet", "--floquet"),
              ("floquet_margin", "--floquet-margin"), ("floquet_tol", "--floquet-tol"),
              ("start_amplitude_c", "--start-amplitude-c"))
#: flags of an equilibrium branch only
EQUILIBRIUM_ONLY = (("no_refine", "--no-refine"),)
#: flags of the start orbit that a branch from a Hopf point does not take (its first cycle is
#: the normal form's, an autonomous limit cycle)
NOT_FROM_HOPF = (("kind", "--kind"), ("unbalance", "--unbalance"),
                 ("subharmonic", "--subharmonic"), ("settle_s", "--settle-s"),
                 ("disturbance_c", "--disturbance-c"),
                 ("start_amplitude_c", "--start-amplitude-c"))
#: flags of a branch from a Hopf point only
HOPF_ONLY = (("hopf_distance", "--hopf-distance"),)

#: API keyword -> command-line flag, for the InputError of the API naming the flag
_FLAGS = {"vary": "--vary", "bounds": "--bounds", "ds": "--ds", "ds_min": "--ds-min",
          "ds_max": "--ds-max", "max_points": "--max-points", "direction": "--direction",
          "param_scale": "--param-scale", "tol": "--tol", "speed_hz": "--speed-hz",
          "chamber_pressure_pa": "--chamber-pressure-pa", "config_ay_m": "--config-ay-m",
          "method": "--method"}

#: the equilibrium API's defaults where the command line leaves a flag out
EQ_DEFAULTS = {"ds": 0.02, "ds_min": 1e-5, "ds_max": 0.05, "max_points": 200, "tol": 1e-10}


def add_arguments(c) -> None:
    """The flags of ``continuation`` beyond the orbit's (``--start``, the step controls
    shared by both branches, the equilibrium's own, ``--out``)."""
    c.add_argument("--start", choices=STARTS, default="orbit",
                   help="orbit (default): a limit cycle or forced orbit found as by "
                        "periodic-orbit, continued over --vary (chamber_pressure_pa, speed_hz "
                        "or config_ay_m; a model field path with --method harmonic_balance); "
                        "equilibrium: the static equilibrium, continued over "
                        "an operating variable or a numeric model field path (e.g. "
                        "bearings.*.clearance_m, supports.0.kyy_n_per_m), with max Re(lambda) "
                        "at every point, its Hopf points and folds. With equilibrium the "
                        "varied operating value starts on the bound the branch leaves from "
                        "(--direction), the others default to 50 Hz, 0 Pa and the model's "
                        "a_y; --ds 0.02, --ds-max 0.05, --max-points 200, --tol 1e-10 "
                        "(the equilibrium's). hopf: the Hopf point of the threshold in --bounds "
                        "(as rotordyn hopf; --vary also a model field path), its first cycle "
                        "from the normal form at --hopf-distance on the cycles' side, then the "
                        "branch of orbits away from the point (a model field: --method "
                        "harmonic_balance, the default there)")
    c.add_argument("--hopf-distance", type=float, default=None, metavar="D",
                   help="--start hopf: the first cycle's distance from the Hopf point (unit "
                        "of --vary; default 0.2 %% of the --bounds span)")
    c.add_argument("--ds-min", type=float, default=None, metavar="DS",
                   help="smallest arclength step; the branch stops below it (default: the "
                        "API's, 1e-3 for orbits, 1e-5 for equilibria)")
    c.add_argument("--ds-max", type=float, default=None, metavar="DS",
                   help="largest arclength step (default: 0.2 for orbits, 0.05 for "
                        "equilibria, or --ds if larger)")
    c.add_argument("--param-scale", type=float, default=None, metavar="P",
                   help="the parameter's scale in the arclength, unit of --vary (default: the "
                        "span of --bounds)")
    c.add_argument("--no-refine", action="store_true",
                   help="equilibria: do not locate the Hopf points and folds by Brent's "
                        "method on the arclength (linear interpolation between points)")
    c.add_argument("--out", default=None, metavar="DIR",
                   help="write branch.csv (one row per point and bearing, SI), "
                        "bifurcations.csv, branch.json (the --json record) and branch.png "
                        "(the bifurcation diagram) into DIR (created if missing)")


def refuse(args, flags, why: str) -> None:
    """InputError naming the first of ``flags`` given on the command line."""
    for dest, flag in flags:
        val = getattr(args, dest, None)
        if val is not None and val is not False:
            raise InputError(f"{flag}: {why}")


def flagged(exc: InputError, extra: dict | None = None) -> InputError:
    """The API's InputError with its keyword replaced by the command-line flag (``extra``:
    a command's own keyword → flag pairs beside the branch commands')."""
    flags = {**_FLAGS, **(extra or {})}
    text = str(exc)
    key, sep, rest = text.partition(":")
    if sep and key in flags:
        return InputError(f"{flags[key]}:{rest}")
    return exc


def run_equilibrium(args, out) -> int:
    """``continuation --start equilibrium`` (flags checked; ``out`` the --out directory or
    None). Exit 0 with a branch, 1 when the start equilibrium failed."""
    refuse(args, ORBIT_ONLY, "applies only to a branch of orbits (--start orbit)")
    s = models.load(args.model)
    ds = EQ_DEFAULTS["ds"] if args.ds is None else args.ds
    kw = dict(speed_hz=args.speed_hz, chamber_pressure_pa=args.chamber_pressure_pa,
              config_ay_m=args.config_ay_m, ds=ds,
              ds_min=EQ_DEFAULTS["ds_min"] if args.ds_min is None else args.ds_min,
              ds_max=max(EQ_DEFAULTS["ds_max"], ds) if args.ds_max is None else args.ds_max,
              max_points=EQ_DEFAULTS["max_points"] if args.max_points is None
              else args.max_points,
              direction=args.direction, param_scale=args.param_scale,
              tol=EQ_DEFAULTS["tol"] if args.tol is None else args.tol,
              refine=not args.no_refine)
    try:
        br = analysis.continuation(s, args.vary, tuple(args.bounds), start="equilibrium", **kw)
    except InputError as exc:
        raise flagged(exc) from None
    record = equilibrium_record(br)
    write_outputs(br, record, args, out)  # before stdout (a closed pipe ends the printing)
    if args.json:
        print(json_text(record))
    else:
        print(repr(br))
        if len(br):
            cols = [br.vary, "bearing", "eccentricity_ratio", "journal_x_m", "journal_y_m",
                    "max_real_1_per_s", "freq_hz", "n_unstable", "stable", "bifurcation"]
            print(table_text(br.to_frame()[cols]))
        if br.bifurcations:
            print("bifurcations:")
            print(table_text(br.bifurcations_frame().drop(columns=["message"])))
    return 0 if br.ok else 1


def equilibrium_record(br) -> dict:
    """The ``--json`` record of an equilibrium branch (SI; per-bearing values as lists over
    the points, each a list over ``bearings``)."""
    return {
        "status": br.status, "stop": br.stop, "message": br.message, "start": "equilibrium",
        "kind": br.kind, "vary": br.vary, "bounds": list(br.bounds), "fixed": br.fixed,
        "bearings": list(br.bearing_names), "parameter": br.parameter,
        "eccentricity_ratio": br.eccentricity_ratio, "journal_x_m": br.journal_x_m,
        "journal_y_m": br.journal_y_m, "h_min_m": br.h_min_m,
        "max_real_1_per_s": br.max_real_1_per_s, "freq_hz": br.freq_hz,
        "n_unstable": br.n_unstable, "stable": br.stable, "arclength": br.arclength,
        "tangent_p": br.tangent_p,
        "bifurcations": [{"kind": b["kind"], "index": b["index"], "parameter": b["parameter"],
                          "eigenvalue_real_1_per_s": b["eigenvalue"].real,
                          "eigenvalue_imag_1_per_s": b["eigenvalue"].imag,
                          "whirl_frequency_hz": b["whirl_frequency_hz"],
                          "refined": b["refined"], "smooth": b.get("smooth", True),
                          "message": b["message"]} for b in br.bifurcations],
        "stats": br.stats,
    }


def write_outputs(br, record: dict, args, out) -> None:
    """--plot FIG and --out DIR of a branch (orbits or equilibria)."""
    if args.plot and len(br):
        save_figure(br.plot(), args.plot, args.dpi)
    if out is None:
        return
    d = Path(out)
    files = []
    if len(br):
        br.to_frame().to_csv(d / "branch.csv", index=False)
        br.bifurcations_frame().to_csv(d / "bifurcations.csv", index=False)
        files += ["branch.csv", "bifurcations.csv"]
    (d / "branch.json").write_text(json_text(record) + "\n")
    files.append("branch.json")
    print(f"wrote {', '.join(str(d / f) for f in files)}", file=sys.stderr)
    if len(br):
        save_figure(br.plot(), str(d / "branch.png"), args.dpi)
