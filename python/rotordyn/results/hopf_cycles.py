"""The cycles born at a Hopf point at given amplitudes (``rd.hopf_cycles``): where each one
is, its stability, and what that says about the onset beside l1's verdict."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display
from rotordyn.results.continuation import UNITS

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class HopfCyclesResult(Display):
    """Per requested amplitude (``amplitude_c``, fraction of ``length_scale_m``, the smallest
    film clearance): ``value`` the cycle's parameter (unit of ``vary``), ``distance`` =
    value − ``hopf_value``, ``side`` ("above"/"below" the Hopf point), ``on_stable_side``
    (the cycle coexists with the stable equilibrium), ``amplitude_m`` (k, n_bearings: the
    largest distance of each journal from its mean), ``period_s``, ``max_multiplier`` (|μ|
    of the critical multiplier, the trivial one left out), ``stable``, ``leading_order_ratio``
    = A²/(amplitude_coefficient·|distance|) per the largest journal (1 where the leading order
    holds), ``floquet`` (the multipliers' route), ``status`` (``ok``; ``unresolved``: the
    corrector did not move the parameter, the row is kept but out of the verdicts; or the
    corrector's failure), ``message``; ``orbits`` the :class:`PeriodicOrbitResult` of each
    solved row (None where the corrector failed).

    ``onset``: ``"hard"`` when a converged cycle lies on the side where the equilibrium is
    stable (it coexists with the equilibrium: hysteresis), ``"soft"`` when every converged
    cycle lies on the unstable side and is stable, else ``"mixed"`` (unstable cycles on the
    unstable side: a further bifurcation) or ``"unknown"`` (none converged).
    ``l1_side_confirmed``: the smallest converged cycle lies on the side l1 predicts."""

    vary: str
    hopf_value: float
    hopf_type: str
    stable_side: str
    l1_cycle_side: str
    length_scale_m: float
    bearing_names: tuple
    amplitude_c: np.ndarray
    value: np.ndarray
    amplitude_m: np.ndarray
    period_s: np.ndarray
    max_multiplier: np.ndarray
    stable: np.ndarray
    leading_order_ratio: np.ndarray
    floquet: tuple
    statuses: tuple
    messages: tuple
    orbits: tuple
    stats: dict = field(default_factory=dict)

    @classmethod
    def from_rows(cls, hopf, rows, stats, **more) -> "HopfCyclesResult":
        nbear = len(hopf.bearing_names)
        k = len(rows)
        amp = np.full((k, nbear), math.nan)
        per, mu, ratio = np.full(k, math.nan), np.full(k, math.nan), np.full(k, math.nan)
        stable = np.zeros(k, dtype=bool)
        kappa = float(np.max(hopf.amplitude_coefficient))
        for i, r in enumerate(rows):
            o = r["orbit"]
            if o is None:
                continue
            amp[i] = [o.amplitude(j) for j in range(nbear)]
            per[i] = o.period_s
            mc = o.critical_multiplier
            mu[i] = abs(mc) if mc is not None else math.nan
            stable[i] = bool(o.stable)
            d = abs(r["value"] - hopf.value)
            ratio[i] = float(np.max(amp[i])) ** 2 / (kappa * d) if d > 0 else math.inf
        return cls(vary=hopf.vary, hopf_value=float(hopf.value), hopf_type=hopf.type,
                   stable_side=hopf.stable_side, l1_cycle_side=hopf.cycle_side,
                   length_scale_m=float(hopf.length_scale_m),
                   bearing_names=tuple(hopf.bearing_names),
                   amplitude_c=np.array([r["amplitude_c"] for r in rows]),
                   value=np.array([r["value"] for r in rows]), amplitude_m=amp, period_s=per,
                   max_multiplier=mu, stable=stable, leading_order_ratio=ratio,
                   floquet=tuple(r.get("floquet", "") for r in rows),
                   statuses=tuple(r["status"] for r in rows),
                   messages=tuple(r["message"] for r in rows),
                   orbits=tuple(r["orbit"] for r in rows), stats={**stats, **more})

    @property
    def converged(self) -> np.ndarray:
        return np.array([s == "ok" for s in self.statuses], dtype=bool)

    @property
    def distance(self) -> np.ndarray:
        return self.value - self.hopf_value

    @property
    def side(self) -> tuple:
        return tuple("" if not ok else ("above" if d > 0 else "below")
                     for ok, d in zip(self.converged, self.distance))

    @property
    def on_stable_side(self) -> np.ndarray:
        return np.array([s == self.stable_side for s in self.side], dtype=bool)

    @property
    def onset(self) -> str:
        ok = self.converged
        if not ok.any():
            return "unknown"
        if self.on_stable_side[ok].any():
            return "hard"
        return "soft" if self.stable[ok].all() else "mixed"

    @property
    def l1_side_confirmed(self) -> bool | None:
        ok = np.flatnonzero(self.converged)
        if ok.size == 0 or self.hopf_type == "degenerate":
            return None
        return self.side[ok[0]] == self.l1_cycle_side

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        rows = []
        side, oss = self.side, self.on_stable_side
        for i in range(len(self.amplitude_c)):
            row = {"amplitude_c": self.amplitude_c[i], self.vary: self.value[i],
                   "distance": self.distance[i], "side": side[i],
                   "on_stable_side": bool(oss[i]),
                   **{f"amplitude_m_{j}": self.amplitude_m[i, j]
                      for j in range(len(self.bearing_names))},
                   "period_s": self.period_s[i], "max_multiplier": self.max_multiplier[i],
                   "stable": bool(self.stable[i]),
                   "leading_order_ratio": self.leading_order_ratio[i],
                   "floquet": self.floquet[i], "status": self.statuses[i],
                   "message": self.messages[i]}
            rows.append(row)
        return pd.DataFrame(rows)

    def __repr__(self) -> str:
        unit, sym, f, u2 = UNITS[self.vary]
        ok = self.converged
        conf = self.l1_side_confirmed
        verdict = {True: "as l1 predicts", False: "not where l1 predicts",
                   None: "l1 gave no side"}[conf]
        parts = []
        for i in np.flatnonzero(ok):
            parts.append(f"{self.amplitude_c[i]:g} c: {sym} {self.distance[i] * f:+.4g} {u2}"
                         f" ({'stable' if self.stable[i] else 'unstable'})")
        others = {}
        for st in self.statuses:
            if st != "ok":
                others[st] = others.get(st, 0) + 1
        rest = "".join(f"; {k} at {st}" for st, k in others.items())
        return (f"<HopfCyclesResult {self.onset} onset at {sym} = {self.hopf_value * f:.6g} "
                f"{u2}: smallest cycle {verdict}; " + "; ".join(parts) + rest + ">")
