"""``rotordyn report MODEL --out DIR [--html FILE]``: the main job of ``make run``."""

from __future__ import annotations

from rotordyn.cli.common import MODEL_HELP, out_dir


def register(sub) -> None:
    """``report`` on the ``rotordyn`` parser's subparsers ``sub``."""
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


def _cmd_report(args) -> int:
    from rotordyn import report  # (matplotlib: only when used)

    return report.run(args.model, out_dir("--out", args.out), html=args.html,
                      operating_speed_hz=args.operating_speed_hz)
