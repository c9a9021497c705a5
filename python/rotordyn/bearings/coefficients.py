"""Bearing coefficients over speed, standalone (no rotor): the ``CoefficientTable`` result and
the one C++ batch that makes it for every film element."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn.bearings._film import (check_load, check_speeds, operating_table,
                                     reduce_coefficients, speed_limit)
from rotordyn.errors import InputError
from rotordyn._common.status import CONVERGED

COEFF_NAMES = ("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")


@dataclass(frozen=True)
class CoefficientTable:
    """Bearing coefficients over speed at a static load: one row per speed.

    ``K``, ``C`` (n_s, 2, 2) in N/m and N·s/m (dF = −K dq − C dq̇, DESIGN frame), ``x_m``,
    ``y_m`` the journal's equilibrium, ``status``/``message`` per row (rows neither ok nor
    contact — a converged thin film, its message says so — are NaN).
    ``whirl`` says at which whirl frequency extra coordinates (pads) were condensed."""

    speeds_hz: np.ndarray
    load_n: tuple
    x_m: np.ndarray
    y_m: np.ndarray
    K: np.ndarray
    C: np.ndarray
    status: tuple
    message: tuple
    clearance_m: float
    whirl: str = "synchronous"
    # per row: how the equilibrium was reached (tilting pads: "pad_assembly", or "homotopy"
    # when that failed) and its Reynolds solves (all films; a fallback row: the final stage's)
    path: tuple = ()
    reynolds_solves: tuple = ()

    def to_frame(self):
        import pandas as pd

        d = {"speed_hz": self.speeds_hz, "journal_x_m": self.x_m, "journal_y_m": self.y_m,
             "eccentricity_ratio": np.hypot(self.x_m, self.y_m) / self.clearance_m}
        for k, name in enumerate(COEFF_NAMES[:4]):
            d[f"{name}_n_per_m"] = self.K[:, k // 2, k % 2]
        for k, name in enumerate(COEFF_NAMES[4:]):
            d[f"{name}_n_s_per_m"] = self.C[:, k // 2, k % 2]
        d["status"] = list(self.status)
        d["message"] = list(self.message)
        return pd.DataFrame(d)

    def to_csv(self, path=None) -> str:
        """CSV text (written to ``path`` when given) that :meth:`TableBearing.from_csv` reads."""
        text = self.to_frame().to_csv(index=False, float_format="%.10g")
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text)
        return text

    def __repr__(self) -> str:
        ok = sum(s in CONVERGED for s in self.status)
        return (f"CoefficientTable({len(self.speeds_hz)} speeds {self.speeds_hz[0]:g}.."
                f"{self.speeds_hz[-1]:g} Hz, {ok} converged)")


def coefficient_table(parts, load_n, speeds_hz, clearance_m: float, *, n_threads: int = 1,
                      whirl_ratio: float | None = 1.0, tol: float = 1e-10) -> CoefficientTable:
    """Standalone table: equilibrium under ``load_n`` and the 2×2 coefficients at each speed;
    extra coordinates condensed at the whirl frequency ``whirl_ratio``·Ω (None: static)."""
    s = check_speeds(speeds_hz, *speed_limit(parts.films))
    ld = check_load(load_n)
    if isinstance(n_threads, bool) or not isinstance(n_threads, (int, np.integer)) or n_threads < 0:
        raise InputError(f"n_threads: expected an integer >= 0 (0: all cores), got {n_threads!r}")
    info = {}
    r, KH, DH, status, message, M = operating_table(parts, ld, s, n_threads=n_threads, tol=tol,
                                                    info=info)
    K = np.full((len(s), 2, 2), np.nan)
    C = np.full((len(s), 2, 2), np.nan)
    for i in range(len(s)):
        if status[i] not in CONVERGED:  # ok, or contact (converged, thin film)
            continue
        nu = 0.0 if whirl_ratio is None else whirl_ratio * 2 * math.pi * abs(s[i])
        K[i], C[i] = reduce_coefficients(KH[i], DH[i], M, nu)
    return CoefficientTable(s, tuple(ld), r[:, 0], r[:, 1], K, C, tuple(status), tuple(message),
                            clearance_m, "static" if whirl_ratio is None else
                            ("synchronous" if whirl_ratio == 1.0 else f"{whirl_ratio:g}×speed"),
                            info["path"], info["reynolds_solves"])
