"""Shared command-line plumbing: the argument parser every ``rotordyn`` subcommand uses
(errors as :class:`rotordyn.InputError`, negative numbers in any notation read as values,
defaults stated in the help) and strict JSON output (NaN and ±inf as ``null``)."""

from __future__ import annotations

import argparse
import json
import math
import re

import numpy as np

import sys
from pathlib import Path

from rotordyn.errors import InputError

MAX_SPEEDS = 100_000  # speeds of one Campbell/unbalance/table run (more is not a diagram)

# A negative number, in any notation float() reads: -5, -.5, -5e2, -1.85E-3, -inf is not one.
_NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


class ArgumentParser(argparse.ArgumentParser):
    """argparse that raises InputError (exit 2 through main) instead of exiting itself, reads
    negative numbers in scientific notation (``--load-n 0 -5e2``) as values, not options, and
    states every option's default in its help."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", _HelpFormatter)
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message):
        raise InputError(f"{self.prog}: {message}")


class _HelpFormatter(argparse.RawDescriptionHelpFormatter):
    """Appends "(default: X)" to an option's help unless the help already states it or the
    option has no meaningful default (flags, required options)."""

    def _get_help_string(self, action):
        text = action.help or ""
        d = action.default
        if "default" in text or d is None or d is False or d is argparse.SUPPRESS \
                or d == [] or action.required or not action.option_strings:
            return text
        if isinstance(d, (list, tuple)):
            d = " ".join(str(x) for x in d)
        return f"{text} (default: {d})"


def _finite_or_none(o):
    """Recursively replace NaN/±inf floats by None (JSON null)."""
    if isinstance(o, float):
        return o if math.isfinite(o) else None
    if isinstance(o, dict):
        return {k: _finite_or_none(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [_finite_or_none(v) for v in o]
    return o


def json_text(obj) -> str:
    """Strict JSON (RFC 8259): numpy values converted, NaN, ±inf and pandas' NA (a nullable
    column's missing value) written as null."""

    def plain(o):
        if type(o).__name__ == "NAType":  # pandas.NA, without importing pandas here
            return None
        if isinstance(o, np.ndarray):
            return plain(o.tolist())
        if isinstance(o, (np.floating, np.integer, np.bool_)):
            return o.item()
        if isinstance(o, dict):
            return {k: plain(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [plain(v) for v in o]
        return o

    return json.dumps(_finite_or_none(plain(obj)), indent=2, allow_nan=False)


def speeds(text: str) -> np.ndarray:
    """"a:b:step" (inclusive) or "f1,f2,..." → speeds in Hz (at most MAX_SPEEDS)."""
    bad = InputError(
        f"--speeds-hz: expected 'start:stop:step' or a comma-separated list, got {text!r}")
    try:
        if ":" in text:
            a, b, st = (float(x) for x in text.split(":"))
        else:
            return np.array([float(x) for x in text.split(",")])
    except ValueError:
        raise bad from None
    if not (np.isfinite(a) and np.isfinite(b) and np.isfinite(st)) or st <= 0 or b < a:
        raise bad
    # Count before allocating (issue 13: 5:1e9:1e-9 raised MemoryError).
    count = math.floor((b - a) / st + 0.5) + 1
    if count > MAX_SPEEDS:
        raise InputError(
            f"--speeds-hz: expected at most {MAX_SPEEDS} speeds, {text!r} gives {count:.3g}")
    return np.arange(a, b + 0.5 * st, st)


MODEL_HELP = ("model: a TOML file or a built-in name (paper-rig, paper-rig-hs, friswell-5.9.1); "
              "see `rotordyn validate`")
JSON_HELP = "print one JSON record on stdout (NaN written as null) instead of a table"


def add_operating_point(s, speed=True):
    if speed:
        s.add_argument("--speed-hz", type=float, default=50.0, metavar="HZ",
                       help="spin speed W, Hz")
    s.add_argument("--chamber-pressure-pa", type=float, default=0.0, metavar="PA",
                   help="active bearing chamber pressure p_c, Pa gauge (0.15 MPa = 1.5e5)")
    s.add_argument("--config-ay-m", type=float, default=None, metavar="M",
                   help="housing offset a_y of the active bearing, m, > 0 above the line "
                        "(-1.85 mm = -1.85e-3; default: the model's own)")


def default_vary(system) -> str:
    """The threshold's default parameter: p_c with an active journal bearing, else speed."""
    from rotordyn.bearings import ActiveJournalBearing

    act = any(isinstance(b, ActiveJournalBearing) for b in system.bearings)
    return "chamber_pressure_pa" if act else "speed_hz"


def figure_path(flag: str, path: str) -> str:
    """An output figure: its folder must exist and its suffix be a format matplotlib writes
    (issue 13: a missing folder or an unknown suffix gave a traceback after the solve)."""
    from matplotlib.figure import Figure

    p = Path(path)
    kinds = Figure().canvas.get_supported_filetypes()
    if p.suffix.lstrip(".").lower() not in kinds:
        raise InputError(f"{flag}: expected a file name ending in one of "
                                  f"{', '.join('.' + k for k in sorted(kinds))}, got {path!r}")
    folder = p.parent if str(p.parent) else Path(".")
    if not folder.is_dir():
        raise InputError(f"{flag}: folder {str(folder)!r} does not exist")
    if p.is_dir():
        raise InputError(f"{flag}: {path!r} is a directory")
    return path


def out_dir(flag: str, path: str) -> str:
    """An output directory, created (with its parents) if missing; InputError naming the
    flag when it is a file or cannot be created."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InputError(f"{flag}: {path!r} exists and is not a directory")
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"{flag}: cannot create {path!r}: {exc.strerror}") from None
    return path


FIGURE_DPI = 200  # the figure style's resolution (rotordyn.plot._style.RC, savefig.dpi)


def add_dpi(s) -> None:
    """``--dpi`` on a command that writes a figure."""
    s.add_argument("--dpi", type=int, default=FIGURE_DPI, metavar="N",
                   help=f"resolution of a PNG figure, dots per inch (default {FIGURE_DPI})")


def check_dpi(dpi) -> int:
    if isinstance(dpi, bool) or not isinstance(dpi, int) or not 50 <= dpi <= 2400:
        raise InputError(f"--dpi: expected an integer in [50, 2400], got {dpi!r}")
    return dpi


def save_figure(ax, path: str, dpi: int = FIGURE_DPI) -> None:
    """Save the figure of ``ax`` (or of the first of a tuple of Axes) to PNG/SVG/PDF at
    ``dpi`` (the style's 200 by default; the rc context the figure was drawn in is gone by
    now, so the resolution is given explicitly)."""
    import matplotlib.pyplot as plt

    fig = (ax[0] if isinstance(ax, tuple) else ax).figure
    fig.savefig(path, dpi=check_dpi(dpi))
    plt.close(fig)
    print(f"wrote {path}", file=sys.stderr)


def check_figure(path) -> None:
    """Check a --plot file before any solve (folder, format) and select the Agg backend
    (matplotlib is imported only when there is a figure to draw: start-up cost)."""
    if path is None:
        return
    figure_path("--plot", path)
    import matplotlib

    matplotlib.use("Agg")


def table_text(df) -> str:
    """A result table as the terminal shows it: 6 significant digits (not pandas' fixed 6
    decimals, which printed 69 µm as 0.000069), and small lengths — a ``*_m`` column whose
    values are all below 1 cm: amplitudes, positions, films — in µm with the column renamed
    ``*_um``; an axial place (``*_z_m``, e.g. the minimum film's ``h_min_z_m``) stays in m
    whatever its values (it was µm when 0, an aligned journal, and m at an edge).
    ``--json`` keeps SI."""
    import numpy as np

    from rotordyn.units import unit_of

    if df.empty:  # never pandas' "Empty DataFrame / Columns: [...]" dump
        return "(no rows)"
    out = df.copy()
    for c in list(out.columns):
        # a length (suffix _m alone: not _n_m, N·m)
        if not (isinstance(c, str) and unit_of(c) == "m") or out[c].dtype.kind != "f":
            continue
        if c.endswith("_z_m"):  # a place along the bearing, not a small length
            continue
        vals = out[c].to_numpy(dtype=float)
        if np.isfinite(vals).any() and np.nanmax(np.abs(vals)) < 0.01:
            out[c] = vals * 1e6
            out = out.rename(columns={c: c[:-2] + "_um"})
    # +0.0 turns a −0.0 (a zero reached from below) into 0: never "-0" in a table
    return out.to_string(index=False, float_format=lambda x: f"{x + 0.0:.6g}")


def add_thermal_arguments(s) -> None:
    """The effective-temperature model's options (docs/film-physics.md)."""
    s.add_argument("--supply-temperature-c", type=float, default=None, metavar="T",
                   help="effective-temperature thermal equilibrium with the oil supplied at T "
                        "degC (with --load-n and an --oil-* law)")
    s.add_argument("--oil-walther", type=float, nargs=4, default=None,
                   metavar=("T1_C", "NU1_MM2_S", "T2_C", "NU2_MM2_S"),
                   help="Walther (ASTM D341) viscosity law through two points")
    s.add_argument("--oil-exponential", type=float, nargs=3, default=None,
                   metavar=("MU_REF_PA_S", "T_REF_C", "BETA_1_PER_K"),
                   help="exponential viscosity law mu_ref exp(-beta (T - T_ref))")
    s.add_argument("--oil-power", type=float, nargs=4, default=None,
                   metavar=("T1_C", "MU1_PA_S", "T2_C", "MU2_PA_S"),
                   help="power viscosity law mu = a T^b (T in degC; ROSS's law) through two "
                        "points (its range is then [1, 200] degC)")
    s.add_argument("--specific-heat-j-per-kg-k", type=float, default=None, metavar="CP",
                   help="oil specific heat, J/(kg K) (thermal model; default: the model's "
                        "[thermal.oil] with `rotordyn thermal`, else 2000)")
    s.add_argument("--supply-flow-m3-s", type=float, default=None, metavar="Q",
                   help="fresh oil supply flow, m3/s (default: the model's [thermal], else 0: "
                        "the film's own demand)")
    s.add_argument("--carry-over", type=float, default=None, metavar="LAMBDA",
                   help="hot-oil carry-over fraction of the recirculating flow, [0, 1] "
                        "(default: the model's [thermal], else 0)")
    s.add_argument("--effective-factor", type=float, default=None, metavar="K",
                   help="T_eff = T_in + K dT, K in [0.5, 1] (0.5: the average film "
                        "temperature; default: the model's [thermal], else 0.5)")


def add_thd_arguments(s) -> None:
    """The thermal model selector and the THD film's wall options (docs/film-physics.md);
    each left out: the model's ``[thermal]`` value (standalone bearing: the default)."""
    s.add_argument("--model", dest="thermal_model", choices=["effective", "thd"], default=None,
                   help="thermal film model: effective (global heat balance) or thd (energy "
                        "equation over the grid; default: the model's [thermal] model, else "
                        "effective)")
    s.add_argument("--journal-htc-w-m2k", type=float, default=None, metavar="H",
                   help="thd: heat-transfer coefficient to the journal, W/(m2 K) (0 adiabatic)")
    s.add_argument("--bush-htc-w-m2k", type=float, default=None, metavar="H",
                   help="thd: heat-transfer coefficient to the bush, W/(m2 K) (0 adiabatic)")
    s.add_argument("--journal-temperature-c", type=float, default=None, metavar="T",
                   help="thd: journal wall temperature, degC (default: the supply temperature)")
    s.add_argument("--bush-temperature-c", type=float, default=None, metavar="T",
                   help="thd: bush wall temperature, degC (default: the supply temperature)")


def oil_from_args(args, base=None) -> "Oil | None":
    """The thermal model's oil from the options of :func:`add_thermal_arguments`, or None
    (isothermal) when no supply temperature is given. ``base``: the model's oil (its
    ``[thermal.oil]``), whose density, specific heat and conductivity an --oil-* law keeps
    (density and specific heat unless ``--density-kg-m3``, ``--specific-heat-j-per-kg-k`` are
    given; without a model oil: 870, 2000 and 0.13 W/(m K))."""
    from rotordyn.bearings.thermal import Oil

    if args.supply_temperature_c is None:
        if any(x is not None for x in (args.oil_walther, args.oil_exponential, args.oil_power)):
            raise InputError("--supply-temperature-c: an --oil-* law needs the supply "
                             "temperature (the thermal model)")
        return None
    if sum(x is not None for x in (args.oil_walther, args.oil_exponential, args.oil_power)) != 1:
        raise InputError("--oil-walther/--oil-exponential/--oil-power: the thermal model needs "
                         "exactly one viscosity law")
    rho = args.density_kg_m3 if args.density_kg_m3 is not None else \
        base.density_kg_m3 if base is not None else 870.0
    cp = args.specific_heat_j_per_kg_k if args.specific_heat_j_per_kg_k is not None else \
        base.specific_heat_j_per_kg_k if base is not None else 2000.0
    common = dict(density_kg_m3=rho, specific_heat_j_per_kg_k=cp)
    if base is not None:  # the oil's conductivity (the THD film's own) is not the law's
        common["conductivity_w_per_m_k"] = base.conductivity_w_per_m_k
    if args.oil_walther is not None:
        t1, n1, t2, n2 = args.oil_walther
        return Oil(viscosity_law="walther", t1_c=t1, nu1_mm2_s=n1, t2_c=t2, nu2_mm2_s=n2,
                   **common)
    if args.oil_power is not None:
        t1, m1, t2, m2 = args.oil_power
        return Oil(viscosity_law="power", t1_c=t1, mu1_pa_s=m1, t2_c=t2, mu2_pa_s=m2,
                   t_min_c=1.0, **common)
    mu, tr, beta = args.oil_exponential
    return Oil(viscosity_law="exponential", mu_ref_pa_s=mu, t_ref_c=tr, beta_1_per_k=beta,
               **common)


def journal_pose(args, equilibrium):
    """The journal's pose for ``rotordyn bearing`` (aligned or tilted): with ``--load-n``
    the equilibrium ``equilibrium(load_n)`` under it, (x, y, 0, 0, that result); else the
    given ``--x-m --y-m`` and ``--vx-m-s --vy-m-s``, (x, y, vx, vy, None). InputError naming
    the field when both or neither are given."""
    if args.load_n is not None:
        if args.x_m is not None or args.y_m is not None:
            raise InputError("--load-n: give either --load-n or --x-m/--y-m, not both")
        eq = equilibrium(tuple(args.load_n))
        return eq.x_m, eq.y_m, 0.0, 0.0, eq
    if args.x_m is None or args.y_m is None:
        raise InputError("--x-m/--y-m: journal position required (or give --load-n)")
    return args.x_m, args.y_m, args.vx_m_s, args.vy_m_s, None
