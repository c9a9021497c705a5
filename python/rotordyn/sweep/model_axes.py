"""A model-field axis of a sweep checked against the model when the spec loads
(:func:`check_model_axis`): every value cheaply, then the model rebuilt with each distinct
value (or a spread of them); a fault of a combination of fields is that point's row."""

from __future__ import annotations

import numpy as np

from rotordyn.errors import FieldCombinationError, InputError

CHECK_ALL = 4096  # distinct values of a model-field axis each rebuilt into a model


def check_model_axis(system, name: str, vals: list) -> None:
    """The values of a model-field axis against the model, fast for any length: a cheap
    check of every value (an integer field takes integers), then the model rebuilt with
    each distinct value once when there are at most CHECK_ALL of them, else with the
    smallest, the largest and CHECK_ALL evenly spaced distinct values between (the model's
    checks bound one field at a time; a value they would still reject becomes that point's
    ``error`` row, never a crash). The error names ``grid.<name>[i]``, i the first index
    holding the rejected value. A value whose bearing misalignment closes a film
    (:class:`rotordyn.errors.ClosedFilmError`, a combination of fields) is that point's
    ``error`` row with the message, as is any fault of a combination of fields
    (:class:`rotordyn.errors.FieldCombinationError`: a transition's onset above its full
    Re_h on another axis); the spec is refused only when every checked value is."""
    from rotordyn.sweep.paths import get_field, set_field

    arr = np.asarray(vals, dtype=float)
    try:
        old = get_field(system, name)
    except (AttributeError, IndexError, KeyError, TypeError, InputError):
        old = []
    if any(isinstance(o, int) and not isinstance(o, bool) for o in old):
        bad = np.flatnonzero(arr != np.round(arr))
        if bad.size:
            raise InputError(f"grid.{name}[{bad[0]}]: expected an integer (the field holds "
                             f"one), got {vals[bad[0]]!r}")
    uniq, first = np.unique(arr, return_index=True)
    if len(uniq) <= CHECK_ALL:
        pick = range(len(uniq))
    else:
        pick = np.unique(np.linspace(0, len(uniq) - 1, CHECK_ALL).round().astype(int))
    head = f"grid.{name}: "
    closed = []  # (index, message) of the values refused for a combination of fields
    for k in pick:
        i = int(first[k])
        try:
            set_field(system, name, vals[i])
        except FieldCombinationError as exc:  # that point's row (status error), not the spec
            closed.append((i, str(exc).removeprefix(head)))
        except InputError as exc:
            msg = str(exc).removeprefix(head)
            raise InputError(f"grid.{name}[{i}]: {msg}") from None
    if closed and len(closed) == len(pick):
        i, msg = min(closed)  # the first grid index
        raise InputError(f"grid.{name}[{i}]: {msg} (every checked value of the axis is refused: no point could run)")


__all__ = ["CHECK_ALL", "check_model_axis"]
