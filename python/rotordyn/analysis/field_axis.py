"""A model field as the parameter of a branch (docs/nonlinear.md): the checked dotted path
(:mod:`rotordyn.model.paths`), its single value in the model, the system re-assembled at a
value (a few kept), and the check that the field acts on the equations of motion at all.
Shared by the branches of equilibria (:mod:`.equilibrium_branch`) and of periodic orbits
(:mod:`.orbit_branch`)."""

from __future__ import annotations

import dataclasses
from collections import OrderedDict

import numpy as np

from rotordyn.analysis.assembly import OPERATING, Assembled, check_operating_parameter
from rotordyn.errors import InputError, RotordynError
from rotordyn.model.paths import declared_type, get_field, set_field
from rotordyn.model.system import System



def field_parameter(system: System, vary) -> str:
    """``vary`` checked: an operating variable (acting on ``system``) or a numeric model field
    path; InputError naming ``vary`` otherwise."""
    if not isinstance(vary, str) or not vary:
        raise InputError(f"vary: expected one of {', '.join(OPERATING)} or a model field path "
                         f"(e.g. bearings.0.clearance_m), got {vary!r}")
    if vary in OPERATING:
        check_operating_parameter(system, vary)
        return vary
    if "." not in vary and not hasattr(system, vary):
        raise InputError(f"vary: unknown parameter {vary!r}: expected one of "
                         f"{', '.join(OPERATING)} or a model field path such as "
                         "bearings.0.clearance_m or bearings.*.viscosity_pa_s")
    try:
        vals = get_field(system, vary)
        set_field(system, vary, float(vals[0]) if vals else 0.0, where="vary")
    except InputError as exc:
        raise InputError(f"vary: unknown parameter {vary!r} ({exc})") from None
    except (AttributeError, IndexError, TypeError, ValueError) as exc:
        raise InputError(f"vary: unknown parameter {vary!r}: not a model field path "
                         f"({exc})") from None
    if _integer(system, vary, vals):
        raise InputError(f"vary: {vary} is an integer field (a grid size, a station or an "
                         f"index; now {vals[0]!r}), not a continuous parameter: a branch "
                         "varies a real-valued field such as bearings.0.clearance_m, "
                         "bearings.*.viscosity_pa_s or supports.0.kyy_n_per_m")
    return vary


def _integer(system: System, vary: str, vals) -> bool:
    """Whether ``vary`` is an integer field: declared ``int`` on its dataclass (a TOML integer
    in a float field is not), or, for an element of a list of numbers, holding ints."""
    head, _, name = vary.rpartition(".")
    try:
        owners = get_field(system, head) if head else [system]
    except (AttributeError, IndexError, TypeError, ValueError):
        owners = []
    kinds = [declared_type(o, name) for o in owners if dataclasses.is_dataclass(o)]
    if kinds:
        return any("float" not in k and "int" in k for k in kinds)
    return bool(vals) and all(isinstance(x, int) and not isinstance(x, bool) for x in vals)


def field_value(system: System, vary: str) -> float:
    """The one value of the field ``vary`` in ``system`` (InputError naming ``vary`` when the
    path selects fields with different values)."""
    vals = get_field(system, vary)
    if not vals or any(float(x) != float(vals[0]) for x in vals):
        raise InputError(f"vary: {vary} selects fields with different values {vals}; "
                         "a branch varies one value")
    return float(vals[0])


class FieldSystems:
    """``system`` re-assembled with the field ``vary`` at a value, the last few kept (the
    predictor, the iterates and their p ± h of a corrector). ``at(p)``: the
    :class:`Assembled` there; InputError naming ``vary`` when the model refuses the value or
    the field changes the number of coordinates."""

    KEEP = 6

    def __init__(self, system: System, vary: str, n: int):
        self.system, self.vary, self.n = system, vary, n
        self._cache: OrderedDict = OrderedDict()
        self.assemblies = 0

    def system_at(self, p) -> System:
        return set_field(self.system, self.vary, float(p), where="vary")

    def at(self, p) -> Assembled:
        key = float(p)
        hit = self._cache.get(key)
        if hit is not None:
            self._cache.move_to_end(key)
            return hit
        hit = Assembled(self.system_at(key))
        self.assemblies += 1
        if hit.n != self.n:
            raise InputError(f"vary: {self.vary} changes the number of coordinates "
                             f"({self.n} → {hit.n}); only fields that keep them can vary")
        self._cache[key] = hit
        while len(self._cache) > self.KEEP:
            self._cache.popitem(last=False)
        return hit


def check_acts(vary: str, lo: float, hi: float, snapshot) -> None:
    """InputError naming ``vary`` when the model field changes nothing between the bounds:
    ``snapshot(p)`` (the arrays the equations of motion are made of at p: the assembled M, C,
    G, K, loads, configuration, and the film forces and their linearisation at a state) is
    the same at ``lo`` and ``hi`` (a field read only by reports or drawings, e.g. a disk's
    diameter when its mass is given: the branch would be one point repeated). A bound the
    model refuses is an InputError naming ``bounds``; a snapshot that fails otherwise (a film
    closed at the state at that bound's value) counts as a change."""
    snaps = []
    for p in (lo, hi):
        try:
            snaps.append([np.asarray(x, dtype=float) for x in snapshot(p)])
        except InputError as exc:
            raise InputError(f"bounds: the model refuses {vary} = {p:g} ({exc})") from None
        except RotordynError:  # not comparable there, so not "the same"
            return
    if all(np.array_equal(x, y) for x, y in zip(*snaps)):
        raise InputError(f"vary: {vary} does not act on the model: the matrices, loads "
                         f"and film forces are the same at {lo:g} and {hi:g} (a field of "
                         "reports or drawings only); vary a field of the equations of motion")
