"""``rotordyn report MODEL --out DIR [--html FILE]``: the main job of ``make run``."""

from __future__ import annotations

from rotordyn.cli.common import MODEL_HELP, out_dir
from rotordyn.cli.common import speeds as parse_speeds


def register(sub) -> None:
    """``report`` on the ``rotordyn`` parser's subparsers ``sub``."""
    s = sub.add_parser("report", help="the main job: analyses of a model written under --out")
    s.add_argument("model", help=MODEL_HELP)
    s.add_argument("--out", default="out", metavar="DIR",
                   help="directory for report.txt, tables and figures: among them the "
                        "critical speeds with their source (1× crossing or response peak), "
                        "critical_speeds.csv, the mode shape at each, critical_mode_<k>.png, "
                        "and the bearing coefficients over speed, bearing_coefficients.csv/.png")
    s.add_argument("--html", default=None, metavar="FILE",
                   help="also write one self-contained HTML report (figures as SVG)")
    s.add_argument("--operating-speed-hz", type=float, nargs=2, default=None,
                   metavar=("MIN", "MAX"),
                   help="operating speed range, Hz, for the API margins in the HTML report "
                        "(default: 45 55 for paper-rig, none otherwise); the analysed speeds "
                        "then run to 125 %% of MAX (API 684; the paper's rig: 5-120 Hz)")
    s.add_argument("--speeds-hz", default=None, metavar="SPEC",
                   help="analysed speeds of the report, Hz: start:stop:step or a list "
                        "(default: from the operating speeds, see docs)")
    s.add_argument("--gas-density-kg-m3", type=float, default=None, metavar="RHO",
                   help="API 617 Level I: average gas density (first-stage suction, last-stage "
                        "discharge), kg/m³, echoed for the screening figure")
    s.add_argument("--csr-limit", type=float, default=None, metavar="CSR",
                   help="API 617 Level I: the Region B boundary CSR of the standard's screening "
                        "figure at that density (without it that criterion is not resolved "
                        "where it applies)")
    s.set_defaults(func=_cmd_report)


def _cmd_report(args) -> int:
    from rotordyn import report  # (matplotlib: only when used)

    speeds = None if args.speeds_hz is None else parse_speeds(args.speeds_hz)
    l1 = {k: v for k, v in (("gas_density_kg_m3", args.gas_density_kg_m3),
                            ("csr_limit", args.csr_limit)) if v is not None}
    return report.run(args.model, out_dir("--out", args.out), html=args.html,
                      operating_speed_hz=args.operating_speed_hz, speeds_hz=speeds,
                      level1_options=l1)
