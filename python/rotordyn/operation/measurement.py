"""What a controller measures: ``[("journal", 0), ("displacement", 6), ...]`` — journal x, y
of a bearing relative to its housing (m), their velocities (m/s), or a rotor station's
displacement or velocity. The rows of C_m that map the state to these signals are
:func:`rotordyn.analysis.measurement.measurement_matrix`."""

from __future__ import annotations

from rotordyn._common import validate as v
from rotordyn.errors import InputError

KINDS = ("journal", "journal_velocity", "displacement", "velocity")


def parse_measurements(measurements) -> tuple:
    """Normalise ``[("journal", 0), ("displacement", 6), ...]`` (a single tuple is one item)."""
    if isinstance(measurements, tuple) and measurements and isinstance(measurements[0], str):
        measurements = [measurements]
    if isinstance(measurements, (str, bytes, dict)):
        raise InputError(f"measurements: expected a list of (kind, station or bearing), got "
                         f"{measurements!r}")
    try:
        items = [tuple(m) if not isinstance(m, (str, bytes, dict)) else None
                 for m in measurements]
        if None in items:
            raise TypeError
    except TypeError:
        raise InputError(f"measurements: expected a list of (kind, station or bearing), got "
                         f"{measurements!r}") from None
    if not items:
        raise InputError("measurements: expected at least one (kind, station or bearing)")
    out = []
    for i, it in enumerate(items):
        if len(it) != 2 or not isinstance(it[0], str) or it[0] not in KINDS:
            raise InputError(f"measurements: expected (kind, index) with kind in {KINDS}, "
                             f"got {it!r}")
        out.append((it[0], v.integer(f"measurements[{i}] ({it[0]!r}) index", it[1], lo=0)))
    return tuple(out)
