"""``rotordyn modes MODEL --part sleeve``: the flexible sleeve's full and condensed frequencies.

MODEL is ``paper-rig`` (the calibrated rig sleeve, docs/sleeve.md) or a TOML file with a
``[sleeve]`` table whose keys are :class:`rotordyn.bearings.sleeve.FlexibleSleeve`'s fields
(``radius_m``, ``thickness_m``, ``width_m``, ``arc_deg``, ``clamp_deg``, ``young_pa``,
``density_kg_m3``, ``poisson``, optional ``n_elements``, ``master_stations``, ...).
Reductions: ``guyan`` (the paper's three-step condensation, the default) or ``none``.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from rotordyn.cli.common import json_text
from rotordyn.errors import InputError
from rotordyn.bearings.sleeve import FlexibleSleeve, paper_rig_sleeve

PAPER_SLEEVE_HZ = (490.2, 1754.2, 6175.8)


def load_sleeve(model: str) -> FlexibleSleeve:
    """The sleeve of the model's active journal bearing (a built-in name such as
    ``paper-rig``, or a model TOML with an ``active_journal`` bearing), or the ``[sleeve]``
    table of a TOML file."""
    from rotordyn.model import builtin as models
    from rotordyn.bearings import ActiveJournalBearing

    from rotordyn.model.toml_io import parse_toml, read_text

    if model in models.BUILTIN or (model.endswith(".toml") and Path(model).is_file()
                                   and "[[bearing]]" in read_text(model)):
        system = models.load(model)
        for b in system.bearings:
            if isinstance(b, ActiveJournalBearing):
                return b.sleeve
        raise InputError(f"model: {model!r} has no active journal bearing (no sleeve)")
    if model == "paper_rig":
        return paper_rig_sleeve()
    path = Path(model)
    if not path.is_file():
        raise InputError(f"model: expected 'paper-rig' or a TOML file, got {model!r}")
    data = parse_toml(read_text(path), model)
    table = data.get("sleeve")
    if not isinstance(table, dict):
        raise InputError(f"{model}: expected a [sleeve] table")
    known = {f.name for f in dataclasses.fields(FlexibleSleeve)}
    unknown = sorted(set(table) - known)
    if unknown:
        raise InputError(f"sleeve.{unknown[0]}: unknown key; expected one of {sorted(known)}")
    kw = dict(table)
    if "master_stations" in kw:
        if not isinstance(kw["master_stations"], list):
            raise InputError(f"sleeve.master_stations: expected a list of integers, got "
                             f"{kw['master_stations']!r}")
        kw["master_stations"] = tuple(kw["master_stations"])
    missing = sorted(f.name for f in dataclasses.fields(FlexibleSleeve)
                     if f.default is dataclasses.MISSING and f.name not in kw)
    if missing:
        raise InputError(f"sleeve.{missing[0]}: required key missing")
    return FlexibleSleeve(**kw)


def modes(args) -> int:
    """Print (or ``--json``) the sleeve's full and condensed natural frequencies."""
    reduction = getattr(args, "reduction", None) or "guyan"
    if reduction not in ("guyan", "none"):
        raise InputError(
            f"--reduction: expected 'guyan' (the paper's three-step condensation) or 'none' "
            f"for --part sleeve, got {reduction!r}"
        )
    sleeve = load_sleeve(args.model)
    res = sleeve.condense()
    n_modes = getattr(args, "n_modes", None)
    n_full = len(res.freq_full_hz) if n_modes is None else int(n_modes)
    if n_full < 1:
        raise InputError(f"--n-modes: expected an integer >= 1, got {n_modes!r}")
    full = res.freq_full_hz[:n_full]
    cond = res.freq_condensed_hz
    payload = {
        "model": str(args.model),
        "part": "sleeve",
        "reduction": reduction,
        "full_frequencies_hz": full,
        "sleeve": {k: (list(v) if isinstance(v, tuple) else v)
                   for k, v in dataclasses.asdict(sleeve).items()},
    }
    if reduction == "guyan":
        k = min(len(cond), len(res.freq_full_hz))
        payload["frequencies_hz"] = cond
        payload["frequency_errors"] = cond[:k] / res.freq_full_hz[:k] - 1.0
        payload["master_stations"] = list(sleeve.master_stations)
        payload["master_phi_deg"] = np.degrees(res.master_phi_rad)
    if args.model in ("paper-rig", "paper_rig"):
        payload["paper_frequencies_hz"] = list(PAPER_SLEEVE_HZ)
    if getattr(args, "json", False):
        print(json_text(payload))
        return 0
    paper = payload.get("paper_frequencies_hz", [])
    head = f"{'mode':>4} {'full (Hz)':>11}"
    if reduction == "guyan":
        head += f" {'condensed (Hz)':>15} {'error':>8}"
    if paper:
        head += f" {'paper (Hz)':>11}"
    print(f"sleeve of {args.model}: {sleeve.n_elements} elements, {3 * sleeve.n_elements} DOF"
          + (f", masters at nodes {list(sleeve.master_stations)}" if reduction == "guyan" else ""))
    print(head)
    rows = len(full) if reduction == "none" else len(cond)
    for i in range(rows):
        line = f"{i + 1:>4} {res.freq_full_hz[i]:>11.1f}"
        if reduction == "guyan":
            line += f" {cond[i]:>15.1f} {100 * payload['frequency_errors'][i]:>7.2f}%"
        if i < len(paper):
            line += f" {paper[i]:>11.1f}"
        print(line)
    return 0
