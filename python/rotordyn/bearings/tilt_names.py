"""One vocabulary for a tilted journal's outputs (issue 20): the names of the system's
equilibrium (``EquilibriumResult.tilt``), of the sweep rows, of the thermal frames and of the
transient are the names of the standalone results too, so tables of either join on them:

* ``journal_theta_x_rad``, ``journal_theta_y_rad``: the journal's rotation relative to the
  bearing (housing), rad — a field of a standalone result and a frame column;
* ``film_moment_n_m`` (the field: Mx, My, N·m) and ``film_moment_x_n_m``,
  ``film_moment_y_n_m`` (the frame columns and JSON keys): the film's moment on the journal
  about the bearing centre.

The standalone functions' *inputs* keep their keyword names ``theta_x_rad``, ``theta_y_rad``
(the imposed tilt, as the model file's ``config_theta_*`` are inputs). The standalone
results' former output names (``theta_x_rad``, ``theta_y_rad``, ``moment_n_m``; before
2026-12-05) are read-only aliases that warn (:class:`RenamedTiltOutputs`)."""

from __future__ import annotations

import warnings

from rotordyn.errors import RotordynDeprecationWarning

RENAMED = {"theta_x_rad": "journal_theta_x_rad", "theta_y_rad": "journal_theta_y_rad",
           "moment_n_m": "film_moment_n_m"}
"""Former output field name -> its name now."""


class RenamedTiltOutputs:
    """Mixin of a result with the tilted journal's outputs: its former field names (RENAMED)
    read the new ones with a :class:`rotordyn.errors.RotordynDeprecationWarning`."""

    __slots__ = ()

    def __getattr__(self, name: str):  # only reached when the normal lookup fails
        new = RENAMED.get(name)
        if new is None:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        warnings.warn(f"{type(self).__name__}.{name} is renamed {new} (the name of the "
                      "system's, the sweeps' and the thermal frames' outputs); the old name "
                      "is read for now", RotordynDeprecationWarning, stacklevel=2)
        return getattr(self, new)


__all__ = ["RENAMED", "RenamedTiltOutputs"]
