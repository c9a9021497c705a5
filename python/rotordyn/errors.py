"""rotordyn exceptions; every error raised by rotordyn subclasses :class:`RotordynError`.

``InputError`` (also a ``ValueError``) names the offending field and its allowed range;
``ConvergenceError``, ``ContactError`` and ``SundialsError`` (also ``RuntimeError``) come from
the solvers; ``StarvedFilmError`` is the ConvergenceError of a thermal film whose metered supply
and hot oil fall short of the flow it draws (its class attribute ``status`` is "starved").
The classes are created by the C++ core so that C++ exceptions map onto them.
"""

from rotordyn._core import (  # noqa: F401
    ContactError,
    ConvergenceError,
    InputError,
    RotordynError,
    StarvedFilmError,
    SundialsError,
)

__all__ = ["RotordynError", "InputError", "ConvergenceError", "ContactError", "SundialsError",
           "StarvedFilmError"]


def status_error(status: str, message: str) -> ConvergenceError:
    """The exception of a point that ended with a failed ``status``: ``StarvedFilmError`` for
    "starved" (one mapping of the status, shared by every caller), ``ConvergenceError``
    otherwise."""
    cls = StarvedFilmError if str(status) == "starved" else ConvergenceError
    return cls(message)


class RotordynWarning(UserWarning):
    """Base class of rotordyn's warnings (the computation goes on; the input is suspicious)."""


class UnitWarning(RotordynWarning):
    """A value far outside its physical range, most likely a unit slip (millimetres typed as
    metres, GPa as Pa, mPa·s as Pa·s, g/cm³ as kg/m³). The message names the field and the
    likely slip. See :mod:`rotordyn._common.plausibility`."""


class RotordynDeprecationWarning(RotordynWarning, FutureWarning):
    """A model-file key or keyword that was renamed: still read, under its new name; the
    message names both. A FutureWarning, so it is shown by default (Python hides a
    DeprecationWarning outside __main__), as the user who wrote the file must see it."""


class OutputError(InputError):
    """A result could not be written although the destination was fine when the run
    started: a full disk, a quota, an I/O error (the message starts with ``out:``). A
    runtime failure (the CLI exits 1, not 2); an :class:`InputError` too, as such ``out:``
    errors were before issue 21, so code catching InputError still catches it."""


class FieldCombinationError(InputError):
    """A fault of a combination of a model's fields, not of a value on its own (a bearing's
    misalignment with its length and clearance; a transition's onset with its full Re_h). An
    :class:`InputError` (a model is refused with it); a sweep makes a grid point that raises
    it a row with status ``error`` and this message, and refuses the spec only when every
    value of the axis raises it (:mod:`rotordyn.sweep.spec`)."""


class ClosedFilmError(FieldCombinationError):
    """A bearing's misalignment (``config_theta_x_rad``, ``config_theta_y_rad``) closes a film
    at an edge for a journal on the housing's axis: a fault of the combination of the
    misalignment with the bearing's length and clearance, not of a value on its own. An
    :class:`InputError` (a model is refused with it); a sweep makes a grid point that raises
    it a row with status ``error`` and this message, and refuses the spec only when every
    value of the axis raises it (:mod:`rotordyn.sweep.spec`)."""


__all__ += ["RotordynWarning", "UnitWarning", "RotordynDeprecationWarning", "OutputError",
            "FieldCombinationError", "ClosedFilmError"]
