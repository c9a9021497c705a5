"""Linear bearing with speed-dependent coefficients (a bearing table from a bearing code or a
test rig): K(Ω), C(Ω) and optionally the mass coefficients M(Ω) (``mxx_kg`` … ``myy_kg``,
all four or none) interpolated linearly in speed between the rows (in C++, so the transient
with a varying speed sees them too). The mass coefficients (force −M(Ω) q̈, e.g. the fluid
inertia of a damper or seal) enter the system's mass matrix at the bearing's station at the
analysis speed: linearisation, stability, Campbell, unbalance response, sweeps, and in the
transient the mass matrix at the current speed (refactored when the speed changes). A speed outside the table is an
``InputError`` naming it, unless ``extrapolate=True`` (the end intervals are then extended).

Linear interpolation error: |e| ≤ h²/8 · max|K''| per interval of width h; a table sampled
every 10 Hz from a plain bearing at 20-200 Hz interpolates its coefficients within ~1 % (see
tests/test_bearing_table.py, which measures it).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED
from rotordyn.bearings._film import SystemParts
from rotordyn.errors import InputError

K_FIELDS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m")
C_FIELDS = ("cxx_n_s_per_m", "cxy_n_s_per_m", "cyx_n_s_per_m", "cyy_n_s_per_m")
M_FIELDS = ("mxx_kg", "mxy_kg", "myx_kg", "myy_kg")


def _entry(field: str, i: int, x) -> float:
    """One table entry: a real number (non-finite ones are refused by check() by field)."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise InputError(f"{field}[{i}]: expected a number, got {x!r:.80}")
    try:
        return float(x)
    except OverflowError:
        raise InputError(f"{field}[{i}]: expected a finite number, got an integer of "
                         f"{len(str(abs(x)))} digits") from None


@dataclass(frozen=True, slots=True)
class TableBearing:
    """Linear bearing at ``station`` whose 2×2 stiffness (N/m) and damping (N·s/m) are
    tabulated against ``speeds_hz`` (strictly increasing); force = −K(Ω) q − C(Ω) q̇ with q the
    journal's displacement from its housing (configuration ``config_ax_m``/``config_ay_m``);
    with mass coefficients (kg, all four or none) − M(Ω) q̈ too."""

    station: int
    speeds_hz: tuple[float, ...]
    kxx_n_per_m: tuple[float, ...]
    kyy_n_per_m: tuple[float, ...]
    kxy_n_per_m: tuple[float, ...] = ()
    kyx_n_per_m: tuple[float, ...] = ()
    cxx_n_s_per_m: tuple[float, ...] = ()
    cxy_n_s_per_m: tuple[float, ...] = ()
    cyx_n_s_per_m: tuple[float, ...] = ()
    cyy_n_s_per_m: tuple[float, ...] = ()
    extrapolate: bool = False
    config_ax_m: float = 0.0
    config_ay_m: float = 0.0
    name: str = ""
    mxx_kg: tuple[float, ...] = ()
    mxy_kg: tuple[float, ...] = ()
    myx_kg: tuple[float, ...] = ()
    myy_kg: tuple[float, ...] = ()

    def __post_init__(self):
        for f in ("speeds_hz",) + K_FIELDS + C_FIELDS + M_FIELDS:
            val = getattr(self, f)
            # a mapping or a set iterates over keys / in no order: not a column of a table
            if isinstance(val, (str, bytes, dict, set, frozenset)) or not hasattr(val, "__iter__"):
                raise InputError(f"{f}: expected a sequence of numbers, got {val!r:.80}")
            object.__setattr__(self, f, tuple(_entry(f, i, x) for i, x in enumerate(val)))
        self.check("table_bearing", None)

    def check(self, where: str, n_stations: int | None) -> None:
        v.text(f"{where}.name", self.name)
        if n_stations is not None:
            v.integer(f"{where}.station", self.station, lo=0, hi=n_stations - 1)
        s = np.asarray(self.speeds_hz)
        if s.size == 0:
            raise InputError(f"{where}.speeds_hz: expected at least one speed")
        if not np.all(np.isfinite(s)):
            raise InputError(f"{where}.speeds_hz: expected finite speeds, got {self.speeds_hz}")
        if np.any(np.abs(s) > v.MAX_SPEED_HZ):  # the analyses' own speed range
            raise InputError(f"{where}.speeds_hz: expected speeds in [-{v.MAX_SPEED_HZ:g}, "
                             f"{v.MAX_SPEED_HZ:g}] Hz, got {float(s[np.argmax(np.abs(s))])!r}")
        bad = np.flatnonzero(np.diff(s) <= 0)
        if bad.size:
            i = int(bad[0]) + 1
            raise InputError(f"{where}.speeds_hz: expected strictly increasing speeds, got "
                             f"{s[i]:g} Hz after {s[i - 1]:g} Hz (row {i})")
        given = [f for f in M_FIELDS if getattr(self, f)]
        if given and len(given) < 4:
            missing = [f for f in M_FIELDS if f not in given]
            raise InputError(f"{where}.{', '.join(missing)}: mass coefficients come as all four "
                             f"(mxx_kg, mxy_kg, myx_kg, myy_kg) or none; got only "
                             f"{', '.join(given)}")
        for f in K_FIELDS + C_FIELDS + M_FIELDS:
            val = getattr(self, f)
            if val and len(val) != s.size:
                raise InputError(f"{where}.{f}: expected {s.size} values (one per speed) or none,"
                                 f" got {len(val)}")
            if val and not np.all(np.isfinite(val)):
                raise InputError(f"{where}.{f}: expected finite values")
        if not isinstance(self.extrapolate, (bool, np.bool_)):
            raise InputError(f"{where}.extrapolate: expected true or false, got {self.extrapolate!r}")
        v.finite(f"{where}.config_ax_m", self.config_ax_m)
        v.finite(f"{where}.config_ay_m", self.config_ay_m)

    # -- values ---------------------------------------------------------------------------
    def _matrix(self, fields) -> np.ndarray:
        n = len(self.speeds_hz)
        return np.column_stack([np.asarray(getattr(self, f)) if getattr(self, f) else np.zeros(n)
                                for f in fields])

    def to_core(self, jx: int, jy: int, name: str) -> "_core.TableCoupling":
        t = _core.TableCoupling()
        t.name = name
        t.coords = [int(jx), int(jy)]
        t.omegas = 2 * math.pi * np.asarray(self.speeds_hz)
        t.K = np.ascontiguousarray(self._matrix(K_FIELDS))
        t.C = np.ascontiguousarray(self._matrix(C_FIELDS))
        if self.has_mass:
            t.M = np.ascontiguousarray(self._matrix(M_FIELDS))
        t.extrapolate = bool(self.extrapolate)
        return t

    @property
    def has_mass(self) -> bool:
        """True when the table carries mass coefficients."""
        return bool(self.mxx_kg)

    def check_speed(self, speed_hz: float, where: str = "speed_hz") -> None:
        """InputError naming the speed when it is outside the table (and not extrapolating)."""
        lo, hi = self.speeds_hz[0], self.speeds_hz[-1]
        tol = 1e-12 * max(abs(lo), abs(hi))
        if not self.extrapolate and len(self.speeds_hz) > 1 and not lo - tol <= speed_hz <= hi + tol:
            raise InputError(f"{where}: {speed_hz:g} Hz is outside bearing "
                             f"'{self.name or self.station}''s table [{lo:g}, {hi:g}] Hz "
                             "(extend the table or set extrapolate = true)")

    def coefficients(self, speed_hz: float) -> tuple[np.ndarray, np.ndarray]:
        """(K, C), 2×2 each, at ``speed_hz`` (the same interpolation the system uses)."""
        f = v.finite("speed_hz", speed_hz)
        self.check_speed(f)
        K, C = self.to_core(0, 1, self.name).at(2 * math.pi * f)
        return np.asarray(K), np.asarray(C)

    def mass(self, speed_hz: float) -> np.ndarray:
        """M (2×2, kg) at ``speed_hz`` (zero without mass coefficients)."""
        f = v.finite("speed_hz", speed_hz)
        self.check_speed(f)
        return np.asarray(self.to_core(0, 1, self.name).mass_at(2 * math.pi * f))

    def system_parts(self, jx: int, jy: int, first_extra: int, name: str):
        return SystemParts(films=[], tables=[self.to_core(jx, jy, name)])

    # -- CSV ------------------------------------------------------------------------------
    @classmethod
    def from_csv(cls, path, *, station: int, extrapolate: bool = False, name: str = "",
                 config_ax_m: float = 0.0, config_ay_m: float = 0.0) -> "TableBearing":
        """Read a table: a header row with ``speed_hz`` and any of ``kxx_n_per_m`` …
        ``cyy_n_s_per_m`` (and the mass columns ``mxx_kg`` … ``myy_kg``: all four or none;
        other columns, e.g. ``status`` from :meth:`CoefficientTable.to_csv`,
        are ignored; a row whose status is not converged (``ok`` or ``contact``) is an error;
        the file is UTF-8 and names each column once)."""
        p = Path(path)
        if not p.is_file():
            raise InputError(f"csv: no such file {str(p)!r}")
        try:
            with p.open(newline="", encoding="utf-8") as fh:
                lines = list(csv.reader(fh))
        except UnicodeDecodeError as exc:
            raise InputError(f"csv: {str(p)!r} is not UTF-8 text (byte {exc.start}); save it "
                             "as UTF-8") from None
        except OSError as exc:
            raise InputError(f"csv: cannot read {str(p)!r}: {exc.strerror}") from None
        header = [h.strip() for h in lines[0]] if lines else []
        twice = sorted({h for h in header if header.count(h) > 1})
        if twice:  # DictReader would keep the last column of each name silently
            raise InputError(f"csv: {str(p)!r} has the column {twice[0]!r} more than once")
        rows = [dict(zip(header, r)) for r in lines[1:] if r]
        if not rows or "speed_hz" not in rows[0]:
            raise InputError(f"csv: {str(p)!r} needs a header row with a speed_hz column")
        cols = {}
        for f in ("speed_hz",) + K_FIELDS + C_FIELDS + M_FIELDS:
            if f in rows[0]:
                try:
                    cols[f] = tuple(float(r[f]) for r in rows)
                except (TypeError, ValueError):
                    raise InputError(f"csv: column {f} of {str(p)!r} holds a non-number") from None
        for i, r in enumerate(rows):  # converged rows: ok, or contact (a thin film)
            if r.get("status", "ok") not in CONVERGED + ("",):
                raise InputError(f"csv: row {i + 1} of {str(p)!r} has status {r['status']!r}")
        speeds = cols.pop("speed_hz")
        return cls(station=station, speeds_hz=speeds, extrapolate=extrapolate, name=name,
                   config_ax_m=config_ax_m, config_ay_m=config_ay_m,
                   **{f: cols.get(f, ()) for f in K_FIELDS + C_FIELDS + M_FIELDS
                      if f not in ("kxx_n_per_m", "kyy_n_per_m")},
                   kxx_n_per_m=cols.get("kxx_n_per_m", ()), kyy_n_per_m=cols.get("kyy_n_per_m", ()))

    @classmethod
    def from_coefficient_table(cls, table, *, station: int, **kw) -> "TableBearing":
        """A table bearing from a :class:`~rotordyn.bearings.CoefficientTable` (converged rows
        only: ok or contact)."""
        bad = [i for i, s in enumerate(table.status) if s not in CONVERGED]
        if bad:
            raise InputError(f"table: row {bad[0]} ({table.speeds_hz[bad[0]]:g} Hz) is "
                             f"{table.status[bad[0]]}: {table.message[bad[0]]}")
        kw2 = {f: tuple(table.K[:, k // 2, k % 2]) for k, f in enumerate(K_FIELDS)}
        kw2.update({f: tuple(table.C[:, k // 2, k % 2]) for k, f in enumerate(C_FIELDS)})
        return cls(station=station, speeds_hz=tuple(table.speeds_hz), **kw2, **kw)
