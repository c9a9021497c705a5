"""Command-line interface: ``rotordyn <command> ...``, one module per command family
(:mod:`.analyses` single operating points, :mod:`.level1` API 617 Level I, :mod:`.bearing` one bearing, :mod:`.sleeve` the
active bearing's sleeve, :mod:`.sweeps` sweeps and their figures, :mod:`.report` the report,
:mod:`.control` control-law synthesis, :mod:`.nonlinear` periodic orbits), registered here on one parser; shared helpers in
:mod:`.common`.

Exit codes: 0 success, 2 bad input (the message names the field), 1 runtime failure.
Machine-readable output goes to stdout with ``--json``; logs go to stderr.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys

from rotordyn._common import plausibility
from rotordyn._common.info import DESCRIPTION
from rotordyn._common.interrupt import safe_interrupts
from rotordyn._common.progress import long_work
from rotordyn.bearings import ActiveJournalBearing
from rotordyn.cli import analyses, bearing, control, level1, nonlinear, report, sweeps
from rotordyn.cli import hopf as hopf_cli
from rotordyn.cli.common import ArgumentParser
from rotordyn.errors import InputError, OutputError, RotordynError, RotordynWarning
from rotordyn.model import builtin as models

COMMANDS = (analyses, level1, nonlinear, sweeps, report, bearing, control)
COMMANDS += (hopf_cli,)
"""The command families, in the order of ``rotordyn --help``."""

OWN_PROGRESS = ("report", "sweep")
"""Commands with their own progress line (steps, chunks); every other command says on stderr
that it is still running after a few seconds (:func:`rotordyn._common.progress.long_work`)."""


def _work_text(args) -> str:
    """``campbell`` and what it runs over (``campbell over speeds 5:120:1 Hz``)."""
    text = str(args.command)
    if getattr(args, "control_command", None):
        text += f" {args.control_command}"
    spec = getattr(args, "speeds_hz", None)
    if isinstance(spec, str):
        text += f" over speeds {spec} Hz"
    return text


def build_parser() -> argparse.ArgumentParser:
    p = ArgumentParser(prog="rotordyn", description=DESCRIPTION,
                       epilog="Exit codes: 0 success, 2 bad input (one line naming the field), "
                              "1 runtime failure. Units: SI, flags carry the unit suffix.")
    from rotordyn._common.info import __version__
    p.add_argument("--version", action="version", version=f"rotordyn {__version__}",
                   help="print the version and exit (`rotordyn info`: the libraries too)")
    sub = p.add_subparsers(dest="command", required=True, parser_class=ArgumentParser,
                           metavar="COMMAND")
    for family in COMMANDS:
        family.register(sub)
    return p


def _check_offset(s, args) -> None:
    """Unit plausibility of --config-ay-m against the active bearing's clearance."""
    ay = getattr(args, "config_ay_m", None)
    for b in s.bearings:
        if isinstance(b, ActiveJournalBearing):
            plausibility.housing_offset("--config-ay-m", ay, b.clearance_m)
            return


def _warning_printer(default):
    """rotordyn's own warnings as one line on stderr (``rotordyn: warning: <field> = ...``);
    other libraries' warnings as usual."""

    def show(message, category, filename, lineno, file=None, line=None):
        if issubclass(category, RotordynWarning):
            print(f"rotordyn: warning: {message}", file=sys.stderr)
        else:
            default(message, category, filename, lineno, file, line)

    return show


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    with safe_interrupts() as guard:  # Ctrl-C never lands inside an import (a broken lock)
        code = _main(argv)
    if guard.pending:  # a Ctrl-C deferred out of an import as the work ended
        print("rotordyn: interrupted", file=sys.stderr)
        return 130
    return code


def _main(argv: list[str]) -> int:
    import warnings

    shown = warnings.showwarning
    warnings.showwarning = _warning_printer(shown)
    try:
        args = build_parser().parse_args(argv)
        if getattr(args, "model", None) is not None and hasattr(args, "config_ay_m"):
            _check_offset(models.load(args.model), args)
        for name in getattr(args, "preload", ()):  # the command's heavy libraries (plot)
            importlib.import_module(name)
        with long_work(_work_text(args), enabled=args.command not in OWN_PROGRESS):
            return int(args.func(args) or 0)
    except KeyboardInterrupt:
        print("rotordyn: interrupted", file=sys.stderr)
        return 130
    except OutputError as exc:  # a full disk while writing: a runtime failure
        print(f"rotordyn: failed: {exc}", file=sys.stderr)
        return 1
    except InputError as exc:
        print(f"rotordyn: error: {exc}", file=sys.stderr)
        return 2
    except RotordynError as exc:
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
