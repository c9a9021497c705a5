"""Unbalance response: amplitude, phase and orbit ellipse at stations against speed (Bode and
polar data), with API 684-style amplification factors and separation margins."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd


def api_required_margin(af: float, below_operating: bool) -> float:
    """Separation margin required by API 617/684 for a critical speed with amplification factor
    ``af``: none below AF 2.5 (or for an unknown, NaN, AF); otherwise 17 (1 − 1/(AF − 1.5)) %
    below the operating range (at most 16 %) and 10 + 17 (1 − 1/(AF − 1.5)) % above it (at
    most 26 %); an infinite AF (half-power points not found) gets the largest margins."""
    if np.isnan(af) or af < 2.5:  # an unresolved (infinite) AF needs the largest margin
        return 0.0
    base = 17.0 * (1.0 - 1.0 / (af - 1.5))
    return min(16.0, base) if below_operating else min(26.0, 10.0 + base)


@dataclass(frozen=True)
class UnbalanceResult:
    """x, y: (n_speeds, n_stations) complex amplitudes (m) of x = Re(X e^{iΩt}) at the output
    stations; speeds_hz (n_speeds,); point_status (n_speeds,)."""

    speeds_hz: np.ndarray
    stations: tuple
    x: np.ndarray
    y: np.ndarray
    point_status: np.ndarray
    unbalances: tuple
    operating_speed_hz: tuple | None = None

    def __repr__(self) -> str:
        a = self.major_m
        pk = ""
        if np.isfinite(a).any():
            i, k = np.unravel_index(np.nanargmax(a), a.shape)
            pk = (f"; largest orbit {a[i, k] * 1e6:.4g} µm at station {self.stations[k]}, "
                  f"{self.speeds_hz[i]:.4g} Hz")
        bad = int(np.sum(self.point_status != "ok"))
        return (f"<UnbalanceResult {len(self.speeds_hz)} speeds {self.speeds_hz[0]:g}–"
                f"{self.speeds_hz[-1]:g} Hz, stations {list(self.stations)}{pk}"
                + (f"; {bad} speeds not ok" if bad else "") + ">")

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
        """One row per (speed, station)."""
        from rotordyn.results.modes import whirl_index, whirl_label

        ns, nk = self.x.shape
        whirl = whirl_label(whirl_index(self.x, self.y, axis=()))  # per speed and station
        return pd.DataFrame({
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
            "status": pd.Categorical(np.repeat(self.point_status, nk)),
        })

    def peaks(self, station: int | None = None, *, amplitude: str = "major") -> pd.DataFrame:
        """Resonance peaks of the response at ``station`` (default: the first output station):
        critical speed (parabolic peak), amplification factor AF = N_c / (N_2 − N_1) by the
        half-power method (API 684), and, when operating speeds are known, the separation
        margin and the margin API 617/684 requires."""
        k = 0 if station is None else list(self.stations).index(station)
        a = {"major": self.major_m, "x": np.abs(self.x), "y": np.abs(self.y)}[amplitude][:, k]
        s = self.speeds_hz
        rows = []
        for i in range(1, len(s) - 1):
            if not (a[i] > a[i - 1] and a[i] >= a[i + 1]):
                continue
            # parabola through the three points
            x0, x1, x2, y0, y1, y2 = s[i - 1], s[i], s[i + 1], a[i - 1], a[i], a[i + 1]
            den = (x0 - x1) * (x0 - x2) * (x1 - x2)
            A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den
            B = (x2**2 * (y0 - y1) + x1**2 * (y2 - y0) + x0**2 * (y1 - y2)) / den
            nc = -B / (2 * A) if A < 0 else x1
            peak = max(y1, A * nc**2 + B * nc + (y1 - A * x1**2 - B * x1))
            half = peak / np.sqrt(2)
            j = i
            while j > 0 and a[j] > half:
                j -= 1
            n1 = np.nan if a[j] > half else s[j] + (half - a[j]) * (s[j + 1] - s[j]) / (a[j + 1] - a[j])
            j = i
            while j < len(s) - 1 and a[j] > half:
                j += 1
            n2 = np.nan if a[j] > half else s[j - 1] + (a[j - 1] - half) * (s[j] - s[j - 1]) / (a[j - 1] - a[j])
            af = nc / (n2 - n1) if np.isfinite(n1) and np.isfinite(n2) and n2 > n1 else np.inf
            row = {"station": int(self.stations[k]), "critical_speed_hz": nc, "peak_m": peak,
                   "n1_hz": n1, "n2_hz": n2, "amplification_factor": af}
            if self.operating_speed_hz is not None:
                lo, hi = self.operating_speed_hz
                below = nc < lo
                ref = lo if below else hi
                row["separation_margin_pct"] = (100 * abs(ref - nc) / ref
                                                if not lo <= nc <= hi else 0.0)
                row["required_margin_pct"] = api_required_margin(af, below)
            rows.append(row)
        return pd.DataFrame(rows)

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
