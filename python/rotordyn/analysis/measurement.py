"""Measurements a controller reads: rows of C_m mapping the state [r; ṙ] (2n) to sensor
signals (m or m/s), the same outputs as :func:`rotordyn.statespace`."""

from __future__ import annotations

import numpy as np

from rotordyn.analysis.assembly import assembled
from rotordyn.errors import InputError
from rotordyn.operation.measurement import parse_measurements


def measurement_matrix(system, measurements) -> tuple[np.ndarray, tuple]:
    """C_m (n_y, 2n) and the signal names. ``("journal", b)``: journal x, y of bearing b
    relative to its housing (m); ``("journal_velocity", b)`` (m/s); ``("displacement", s)`` and
    ``("velocity", s)`` at rotor station s. InputError names the measurement that does not
    exist."""
    items = parse_measurements(measurements)
    asm = assembled(system)
    n = asm.n
    rows, names = [], []
    for kind, where in items:
        if kind in ("displacement", "velocity"):
            try:
                Co = asm.station_output_matrix(where)
            except InputError as exc:
                raise InputError(f"measurements: ({kind!r}, {where!r}): {exc}") from None
            unit = "m" if kind == "displacement" else "m_s"
            z = np.zeros_like(Co)
            rows += list(np.hstack([Co, z]) if kind == "displacement" else np.hstack([z, Co]))
            names += [f"{kind}_x_{unit}[{where}]", f"{kind}_y_{unit}[{where}]"]
        else:
            bcs = [bc for bc in asm.bearings
                   if not isinstance(where, bool) and isinstance(where, (int, np.integer))
                   and bc.index == where]
            if not bcs:
                raise InputError(f"measurements: ({kind!r}, {where!r}): no journal bearing with "
                                 f"index {where!r} (bearings: "
                                 f"{[bc.index for bc in asm.bearings]})")
            bc = bcs[0]
            off = 0 if kind == "journal" else n
            for j, ci in enumerate((bc.jx, bc.jy)):
                row = np.zeros(2 * n)
                row[off + ci] = 1.0
                rows.append(row)
                unit = "m" if kind == "journal" else "m_s"
                names.append(f"{kind}_{'xy'[j]}_{unit}[{where}]")
    return np.vstack(rows), tuple(names)
