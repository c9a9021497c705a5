"""Command-line interface: ``rotordyn <command> ...``.

Exit codes: 0 success, 2 bad input (the message names the field), 1 runtime failure.
Machine-readable output goes to stdout with ``--json``; logs go to stderr.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

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


# -- report (the main job of `make run`) --------------------------------------------------
PAPER_ROTOR_HZ = (10.43, 43.04, 106.38)


def _cmd_report(args) -> int:
    import matplotlib

    matplotlib.use("Agg")
    s = rotordyn.models.load(args.model)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    r = rotordyn.modes(s, 0.0, reduction=s.reduction.method if s.reduction.method != "none"
                       else "guyan")
    f_red = r.frequencies_hz[::2]
    f_full = r.full.frequencies_hz[::2]
    lines = [f"{s.name or args.model}: rotor {s.rotor.length_m:.3f} m, {s.mass_kg:.3f} kg, "
             f"{s.rotor.n_elements} elements, masters at stations "
             f"{list(s.reduction.master_stations)} ({r.model})",
             f"{'mode':>4} {'full (Hz)':>11} {'condensed (Hz)':>15} {'error':>8}"
             + (f" {'paper (Hz)':>11}" if s.name == "paper-rig" else "")]
    for i, (a, b) in enumerate(zip(f_full, f_red)):
        row = f"{i + 1:>4} {a:>11.3f} {b:>15.3f} {100 * (b - a) / a:>7.2f}%"
        if s.name == "paper-rig" and i < len(PAPER_ROTOR_HZ):
            row += f" {PAPER_ROTOR_HZ[i]:>11.2f}"
        lines.append(row)
    text = "\n".join(lines)
    print(text)
    (out / "rotor_modes.txt").write_text(text + "\n")
    (out / "rotor_modes.json").write_text(_json(_modes_payload(r)) + "\n")
    r.to_frame().to_csv(out / "rotor_modes.csv", index=False)
    ax = r.full.plot(modes=range(0, 6, 2))
    ax.figure.savefig(out / "rotor_mode_shapes.png", dpi=120, bbox_inches="tight")
    print(f"wrote {out}/rotor_modes.txt, .json, .csv and rotor_mode_shapes.png", file=sys.stderr)
    return 0


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

    s = sub.add_parser("report", help="the main job: analyses of a model written under --out")
    s.add_argument("model")
    s.add_argument("--out", default="out")
    s.set_defaults(func=_cmd_report)
    cli_bearing.register(sub)
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


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
