"""The systems of a harmonic-balance branch over a model field (``rd.continuation(system,
"bearings.0.viscosity_pa_s", bounds, start=orbit, method="harmonic_balance")``;
docs/nonlinear.md, "Branches over a model field").

The corrector is the core's (``_core.hb_continuation_step``, the one of p_c, Ω and a_y): a
model field changes the assembled model itself, so the core asks for the system at every value
it visits (the iterates, the line search's trials and the p ± h of ∂R/∂p) through the provider
built here: the system re-assembled with the field at p (:class:`FieldSystems`, a few kept)
with the branch's orbit input on it, or the model's refusal of the value (an evaluation that
failed, with the model's message)."""

from __future__ import annotations

from rotordyn import _core
from rotordyn.errors import InputError


def field_systems(setup):
    """``system_at(p)`` → ``_core.HbSystemAt`` for the corrector of the branch ``setup`` (a
    model field at p, in its SI unit)."""

    def system_at(p: float):
        at = _core.HbSystemAt()
        try:
            asm = setup.field.at(p)
            inp = setup.input_at(p)
        except InputError as exc:
            at.refused = f"the model refuses {setup.vary} = {p:.6g}: {exc}"
            return at
        at.solver, at.input = asm.solver, inp
        return at

    return system_at
