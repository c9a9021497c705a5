"""Unbalance response: amplitude, phase and orbit ellipse at stations against speed (Bode and
polar data), with API 684-style amplification factors and separation margins."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common.status import CONVERGED, point_messages
from rotordyn.results._display import Display


from rotordyn._common.api import (  # noqa: F401 - the criteria of the peaks
    API_CRITICALLY_DAMPED_AF, af_text, amplification_factor, api_required_margin)

if TYPE_CHECKING:
    import pandas as pd

# A local maximum with no half-power band that rises less than this fraction of its height
# above its surroundings (its topographic prominence) is a ripple of the response, not a
# resonance: the films' coefficients are only piecewise smooth in speed (a film node changes
# its cavitation state), and the adaptive speed grid resolves those kinks.
RIPPLE_PROMINENCE = 0.02

PEAK_COLUMNS = ("station", "critical_speed_hz", "peak_m", "n1_hz", "n2_hz",
                "amplification_factor", "af_kind", "critically_damped")
"""The columns of :meth:`UnbalanceResult.peaks` (plus ``separation_margin_pct`` and
``required_margin_pct`` when operating speeds are known), also when there is no peak."""


def half_power_walk(a: np.ndarray, i: int, half: float, step: int) -> tuple[int, bool]:
    """(j, cut): the first index where the response ``a`` falls to ``half`` walking from the
    peak ``i`` in direction ``step`` (or the end of the speeds), and whether the walk climbed
    into another resonance first (the response rose by more than :data:`RIPPLE_PROMINENCE`
    of the peak above its lowest value since the peak). One walk for the half-power speeds
    (:func:`_half_power_speed`) and the unbalance response's grid refinement around them."""
    j, low, n = i, a[i], len(a)
    while 0 < j < n - 1 and a[j] > half:
        if a[j] > low + RIPPLE_PROMINENCE * a[i]:
            return j, True
        low = min(low, a[j])
        j += step
    return j, bool(a[j] > half and a[j] > low + RIPPLE_PROMINENCE * a[i])


def _half_power_speed(a: np.ndarray, s: np.ndarray, i: int, half: float, step: int
                      ) -> tuple[float, bool]:
    """(N, cut): the speed where the response ``a`` first falls to ``half`` walking from the
    peak ``i`` in direction ``step`` (linear interpolation; NaN when it does not fall that far
    within the speeds), and whether the walk climbed into another resonance first
    (:func:`half_power_walk`). A cut band has no half-power speed on that side: taking the
    range's end instead made a small resonance on a larger one's skirt "critically damped"
    (issue qa21)."""
    j, cut = half_power_walk(a, i, half, step)
    if cut or a[j] > half:
        return float("nan"), cut
    if step < 0:
        return float(s[j] + (half - a[j]) * (s[j + 1] - s[j]) / (a[j + 1] - a[j])), False
    return float(s[j - 1] + (a[j - 1] - half) * (s[j] - s[j - 1]) / (a[j - 1] - a[j])), False


@dataclass(frozen=True)
class UnbalanceResult(Display):
    """x, y: (n_speeds, n_stations) complex amplitudes (m) of x = Re(X e^{iΩt}) at the output
    stations; speeds_hz (n_speeds,); point_status (n_speeds,); max_real_1_per_s (n_speeds,)
    the linear system's largest Re λ at each speed (round-off of an undamped mode, within
    :data:`~rotordyn.results.modes.ROUND_OFF_REL` of 0, set to 0), or None when not checked (``stable``)."""

    speeds_hz: np.ndarray
    stations: tuple
    x: np.ndarray
    y: np.ndarray
    point_status: np.ndarray
    unbalances: tuple
    operating_speed_hz: tuple | None = None
    max_real_1_per_s: np.ndarray | None = None
    thermal: tuple = ()  # (n_speeds,) SystemThermalResult per speed (``thermal=``), else ()
    # (n_speeds,) object: why a speed failed (str), None where it converged; filled from
    # point_status when not given (rotordyn._common.status.point_messages)
    point_message: np.ndarray | None = None

    def __post_init__(self):
        msg = [""] * len(self.point_status) if self.point_message is None else \
            self.point_message
        object.__setattr__(self, "point_message", point_messages(self.point_status, msg))

    @property
    def stable(self) -> np.ndarray:
        """(n_speeds,) bool: the equilibrium is linearly stable (every Re λ below the round-off
        band of :data:`rotordyn.results.modes.ROUND_OFF_REL`, which ``max_real_1_per_s``
        already sets to 0), so the unbalance response is a steady orbit; all True when not checked.
        Above the threshold of instability the computed response is the forced part of a
        motion that grows: it is not what the machine shows. False at a speed without a
        converged equilibrium (nothing was linearised there: no stable verdict)."""
        solved = self._solved()
        if self.max_real_1_per_s is None:
            return solved
        return solved & ~(self.max_real_1_per_s > 0)

    def _solved(self) -> np.ndarray:
        """(n_speeds,) bool: the speed's equilibrium converged."""
        return np.isin(np.asarray(self.point_status, dtype=str), list(CONVERGED))

    def __repr__(self) -> str:
        a = self.major_m
        pk = ""
        if np.isfinite(a).any():
            i, k = np.unravel_index(np.nanargmax(a), a.shape)
            pk = (f"; largest orbit {a[i, k] * 1e6:.4g} µm at station {self.stations[k]}, "
                  f"{self.speeds_hz[i]:.4g} Hz")
        bad = int(np.sum(self.point_status != "ok"))
        uns = int(np.sum(self._solved() & ~self.stable))
        return (f"<UnbalanceResult {len(self.speeds_hz)} speeds {self.speeds_hz[0]:g}–"
                f"{self.speeds_hz[-1]:g} Hz, stations {list(self.stations)}{pk}"
                + (f"; {bad} speeds not ok" if bad else "")
                + (f"; {uns} speeds above the threshold of instability (no steady response)"
                   if uns else "") + ">")

    @property
    def forward_m(self) -> np.ndarray:
        return np.abs(self.x + 1j * self.y) / 2

    @property
    def backward_m(self) -> np.ndarray:
        return np.abs(np.conj(self.x) + 1j * np.conj(self.y)) / 2

    @property
    def major_m(self) -> np.ndarray:
        """Orbit semi-major axis, m."""
        return self.forward_m + self.backward_m

    @property
    def minor_m(self) -> np.ndarray:
        """Orbit semi-minor axis, m."""
        return np.abs(self.forward_m - self.backward_m)

    def to_frame(self) -> pd.DataFrame:
        """One row per (speed, station); with ``thermal`` (each speed at its own thermal
        equilibrium) also the thermal columns of each speed
        (:data:`rotordyn.results.thermal.THERMAL_POINT_COLUMNS`)."""
        import pandas as pd
        from rotordyn.results.modes import whirl_index, whirl_label

        ns, nk = self.x.shape
        whirl = whirl_label(whirl_index(self.x, self.y, axis=()))  # per speed and station
        # A speed without a converged equilibrium has no orbit, so no whirl and no stability
        # verdict (null, not "planar" and True)
        solved = self._solved()
        orbit = solved[:, None] & np.isfinite(self.x) & np.isfinite(self.y)
        whirl = np.where(orbit, whirl, None)
        verdict = pd.array(np.repeat(self.stable, nk), dtype="boolean")
        verdict[~np.repeat(solved, nk)] = pd.NA
        df = pd.DataFrame({
            "speed_hz": np.repeat(self.speeds_hz, nk),
            "station": np.tile(np.asarray(self.stations, dtype=np.int64), ns),
            "amplitude_x_m": np.abs(self.x).ravel(),
            "phase_x_deg": np.degrees(np.angle(self.x)).ravel(),
            "amplitude_y_m": np.abs(self.y).ravel(),
            "phase_y_deg": np.degrees(np.angle(self.y)).ravel(),
            "major_m": self.major_m.ravel(),
            "minor_m": self.minor_m.ravel(),
            "whirl": pd.Categorical(whirl.ravel(),
                                    categories=["forward", "backward", "planar"]),
            "point_stable": verdict,
            "status": pd.Categorical(np.repeat(self.point_status, nk)),
        })
        if self.thermal:
            from rotordyn.results.thermal import thermal_frame_columns

            for k, col in thermal_frame_columns(self.thermal, nk).items():
                df[k] = col
        return df

    def peaks(self, station: int | None = None, *, amplitude: str = "major") -> pd.DataFrame:
        """Resonance peaks of the response at ``station`` (default: the first output station):
        critical speed (parabolic peak), amplification factor AF = N_c / (N_2 − N_1) by the
        half-power method (API 684; :func:`amplification_factor` for ``af_kind``), whether it is
        critically damped (AF < 2.5), and, when operating speeds are known, the separation
        margin and the margin API 617/684 requires (NaN: the AF is not resolved, so the margin
        cannot be judged). A local maximum without a half-power band that rises less than
        :data:`RIPPLE_PROMINENCE` (2 %) of its height above its surroundings is a ripple of the
        film coefficients, not a peak. Columns :data:`PEAK_COLUMNS` even when there is none."""
        import pandas as pd
        k = 0 if station is None else list(self.stations).index(station)
        from scipy.signal import peak_prominences

        a = {"major": self.major_m, "x": np.abs(self.x), "y": np.abs(self.y)}[amplitude][:, k]
        s = self.speeds_hz
        rows = []
        for i in range(1, len(s) - 1):
            if not (a[i] > a[i - 1] and a[i] >= a[i + 1]):
                continue
            prominence = peak_prominences(np.nan_to_num(a, nan=0.0), [i])[0][0] / a[i]
            # parabola through the three points
            x0, x1, x2, y0, y1, y2 = s[i - 1], s[i], s[i + 1], a[i - 1], a[i], a[i + 1]
            den = (x0 - x1) * (x0 - x2) * (x1 - x2)
            A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den
            B = (x2**2 * (y0 - y1) + x1**2 * (y2 - y0) + x0**2 * (y1 - y2)) / den
            nc = -B / (2 * A) if A < 0 else x1
            peak = max(y1, A * nc**2 + B * nc + (y1 - A * x1**2 - B * x1))
            half = peak / np.sqrt(2)
            n1, cut1 = _half_power_speed(a, s, i, half, -1)
            n2, cut2 = _half_power_speed(a, s, i, half, +1)
            if cut1 or cut2:  # the band runs into another resonance: N_1 or N_2 does not exist
                af, kind = float("nan"), "unresolved"
            else:
                af, kind = amplification_factor(nc, n1, n2, s[0], s[-1])
            if prominence < RIPPLE_PROMINENCE:
                continue  # a ripple (RIPPLE_PROMINENCE), not a resonance
            row = {"station": int(self.stations[k]), "critical_speed_hz": nc, "peak_m": peak,
                   "n1_hz": n1, "n2_hz": n2, "amplification_factor": af, "af_kind": kind,
                   "critically_damped": bool(af < API_CRITICALLY_DAMPED_AF)}
            if self.operating_speed_hz is not None:
                lo, hi = self.operating_speed_hz
                below = nc < lo
                ref = lo if below else hi
                row["separation_margin_pct"] = (100 * abs(ref - nc) / ref
                                                if not lo <= nc <= hi else 0.0)
                row["required_margin_pct"] = api_required_margin(af, below)
            rows.append(row)
        cols = list(PEAK_COLUMNS) + (["separation_margin_pct", "required_margin_pct"]
                                     if self.operating_speed_hz is not None else [])
        return pd.DataFrame(rows, columns=cols)

    def plot(self, station: int | None = None, axes=None, kind: str = "bode", *,
             speed_hz: float | None = None, system=None):
        """``kind="bode"``: amplitude (µm) and phase against speed with AF, half-power bands,
        operating range and margins (returns (ax_amp, ax_phase)); ``"polar"``: the response
        vector over speed (returns Axes); ``"deflected"``: orbits at the output stations at
        ``speed_hz`` (``system`` for axial positions)."""
        from rotordyn.plot.response import bode, polar
        from rotordyn.plot.shapes import deflected_shape

        if kind == "bode":
            return bode(self, station=station, axes=axes)
        if kind == "polar":
            return polar(self, station=station, ax=axes)
        if kind == "deflected":
            sp = self.speeds_hz[np.nanargmax(np.nanmax(self.major_m, axis=1))] \
                if speed_hz is None else speed_hz
            return deflected_shape(self, sp, ax=axes, system=system)
        from rotordyn.errors import InputError

        raise InputError(f"kind: expected 'bode', 'polar' or 'deflected', got {kind!r}")
