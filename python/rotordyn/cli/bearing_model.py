"""``rotordyn bearing --model-file MODEL [--bearing NAME]``: a model file's fluid-film bearing
at one operating point, aligned (:mod:`rotordyn.cli.bearing_aligned`) or with the journal
tilted relative to it (``--theta-x-rad``, ``--theta-y-rad``), isothermal
(:func:`rotordyn.cli.bearing_tilt.run_tilted`) or at its thermal equilibrium
(:func:`rotordyn.cli.bearing_thermal.run_thermal_tilted`): a plain (``journal``),
tilting-pad or fixed-geometry bearing of a built-in model or a model TOML, with its own
geometry, pads or lobes, grid, cavitation and grooves (``--n-circ``, ``--n-axial`` override
its grid). The housing's misalignment (``config_theta_*``) and offsets are not applied: they
place the housing against a system's shaft line; standalone the journal's tilt relative to
the bearing is given."""

from __future__ import annotations

import argparse
import dataclasses

from rotordyn.errors import InputError

# the options that describe a bearing by its dimensions (refused with --model-file: the
# model's bearing has its own), with their defaults when not given
OWN_OPTIONS = {"diameter_m": None, "length_m": None, "clearance_m": None,
               "viscosity_pa_s": None, "turbulence": None, "turbulence_onset_re": None,
               "turbulence_full_re": None, "cavitation": None, "groove": []}


def add_model_arguments(s: argparse.ArgumentParser) -> None:
    s.add_argument("--model-file", default=None, metavar="MODEL",
                   help="a built-in model name or a model TOML: its bearing --bearing (plain, "
                        "tilting-pad or fixed-geometry, with its own geometry, grid, "
                        "cavitation) instead of --diameter-m ...; aligned as in the "
                        "system, or tilted with --theta-x-rad/--theta-y-rad; isothermal or "
                        "thermal")
    s.add_argument("--bearing", default=None, metavar="NAME",
                   help="with --model-file: the bearing's name (default: the model's only "
                        "fluid-film bearing)")


def model_bearing(args: argparse.Namespace):
    """(bearing, its record) of ``--model-file``/``--bearing``: a FluidFilmBearing,
    TiltingPadBearing or FixedGeometryBearing (``--n-circ``, ``--n-axial`` given: that grid).
    InputError naming the option otherwise."""
    from rotordyn.bearings import (BEARING_TYPES, FixedGeometryBearing, FluidFilmBearing,
                                   TiltingPadBearing)
    from rotordyn.model import builtin as models

    kind = {cls: name for name, cls in BEARING_TYPES.items()}

    for k, default in OWN_OPTIONS.items():
        if getattr(args, k) != default:
            raise InputError(f"--{k.replace('_', '-')}: not with --model-file (the model's "
                             "bearing has its own)")
    system = models.load(args.model_file)
    kinds = (FluidFilmBearing, TiltingPadBearing, FixedGeometryBearing)
    films = [b for b in system.bearings if isinstance(b, kinds)]
    names = [b.name for b in system.bearings]
    if args.bearing is None:
        if len(films) != 1:
            raise InputError(f"--bearing: expected one of {names} (the model has "
                             f"{len(films)} plain, tilting-pad or fixed-geometry bearings)")
        b = films[0]
    else:
        got = [b for b in system.bearings if b.name == args.bearing]
        if not got:
            raise InputError(f"--bearing: expected one of {names}, got {args.bearing!r}")
        b = got[0]
        if not isinstance(b, kinds):
            raise InputError(f"--bearing: {args.bearing!r} is a {kind[type(b)]} "
                             "bearing; expected a plain (journal), tilting_pad or "
                             "fixed_geometry bearing")
    grid = {k: getattr(args, k) for k in ("n_circ", "n_axial") if getattr(args, k) is not None}
    if grid:
        b = dataclasses.replace(b, **grid)
    return b, {"model": args.model_file, "name": b.name, "type": kind[type(b)],
               "station": int(b.station), "n_circ": int(b.n_circ), "n_axial": int(b.n_axial)}


__all__ = ["OWN_OPTIONS", "add_model_arguments", "model_bearing"]
