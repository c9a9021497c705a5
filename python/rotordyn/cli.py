"""Command-line interface: ``rotordyn <command> ...`` (exit 0 ok, 2 bad input, 1 failure)."""

from __future__ import annotations

import argparse
import json
import sys

import rotordyn
from rotordyn import cli_bearing


def _cmd_info(args: argparse.Namespace) -> int:
    info = rotordyn.build_info()
    if args.json:
        print(json.dumps(info, indent=2, sort_keys=True))
    else:
        print(f"rotordyn {rotordyn.__version__}")
        for key in ("eigen", "sundials", "suitesparse", "compiler"):
            if key in info:
                print(f"  {key}: {info[key]}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="rotordyn", description=rotordyn.__doc__)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("info", help="package and library versions")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_info)
    cli_bearing.register(sub)
    return p


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except rotordyn.InputError as exc:
        print(f"rotordyn: error: {exc}", file=sys.stderr)
        return 2
    except rotordyn.RotordynError as exc:
        print(f"rotordyn: failed: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
