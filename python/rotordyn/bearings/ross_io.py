"""Bearing elements as ROSS bearings (optional: ``pip install rotordyn[ross]``, i.e.
ross-rotordynamics): :func:`to_ross_bearing`, a ROSS ``BearingElement`` whose speed-dependent
coefficients come from this package's solver (any element with ``coefficient_table``, a
:class:`~rotordyn.bearings.CoefficientTable` or a :class:`~rotordyn.bearings.TableBearing`),
so ROSS users get these bearing models as a drop-in. The other direction, a ROSS ``Rotor`` as
a :class:`rotordyn.System`, is :func:`rotordyn.model.system_from_ross` (a whole system, so it
lives with the model). ROSS is imported only inside the functions.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn.bearings.coefficients import COEFF_NAMES
from rotordyn.errors import InputError
from rotordyn._common.status import CONVERGED

MASS_NAMES = ("mxx", "mxy", "myx", "myy")


def _ross():
    try:
        import ross
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise InputError("ross: this needs the optional dependency ross-rotordynamics "
                         "(pip install 'rotordyn[ross]')") from exc
    return ross


def to_ross_bearing(source, *, n: int, speeds_hz=None, load_n=None, tag: str | None = None,
                    n_threads: int = 1):
    """ROSS ``BearingElement`` at ROSS node ``n`` with coefficients over ``frequency`` (rad/s).

    ``source``: a CoefficientTable, a TableBearing, or a bearing with ``coefficient_table``
    (then ``speeds_hz`` and ``load_n`` are required: the equilibrium under the static load at
    each speed gives the coefficients; rows that fail are an error, never silently dropped).
    """
    ross = _ross()
    from rotordyn.bearings.coefficients import CoefficientTable
    from rotordyn.bearings.table import C_FIELDS, K_FIELDS, M_FIELDS, TableBearing

    mass = {}
    if isinstance(source, TableBearing):
        speeds = np.asarray(source.speeds_hz)
        cols = {c: np.asarray(source._matrix((f,)))[:, 0]
                for c, f in zip(COEFF_NAMES, K_FIELDS + C_FIELDS)}
        if source.has_mass:
            mass = {c: [float(x) for x in getattr(source, f)] for c, f in zip(MASS_NAMES, M_FIELDS)}
    else:
        if not isinstance(source, CoefficientTable):
            if speeds_hz is None or load_n is None:
                raise InputError("speeds_hz, load_n: required to tabulate a bearing for ROSS")
            source = source.coefficient_table(speeds_hz, load_n, n_threads=n_threads)
        bad = [i for i, s in enumerate(source.status) if s not in CONVERGED]
        if bad:
            i = bad[0]
            raise InputError(f"speeds_hz: no coefficients at {source.speeds_hz[i]:g} Hz "
                             f"({source.status[i]}: {source.message[i]})")
        speeds = np.asarray(source.speeds_hz)
        cols = {c: (source.K if c[0] == "k" else source.C)[:, "xy".index(c[1]), "xy".index(c[2])]
                for c in COEFF_NAMES}
    kw = {c: [float(x) for x in cols[c]] for c in COEFF_NAMES}
    kw.update(mass)
    if len(speeds) == 1:
        kw = {c: val[0] for c, val in kw.items()}
        return ross.BearingElement(n=int(n), tag=tag, **kw)
    return ross.BearingElement(n=int(n), frequency=[2 * math.pi * float(f) for f in speeds],
                               tag=tag, **kw)
