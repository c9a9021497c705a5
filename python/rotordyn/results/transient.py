"""Nonlinear transient results: journal orbits, time histories, spectra."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

if TYPE_CHECKING:
    import pandas as pd


_TILT = ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m", "film_moment_y_n_m")


@dataclass(frozen=True)
class TransientResult(Display):
    """t: (n_t,) s; r, v: (n_t, n) coordinates and velocities (m, m/s); journal_x_m,
    journal_y_m: (n_t, n_bearings) relative to each housing; h_min_m: (n_t, n_bearings);
    speed_hz_t, angle_rad: (n_t,) speed and rotor angle; chamber_pressure_command_pa,
    chamber_pressure_actual_pa: (n_t,) command (before saturation) and actuator output p_c;
    controller_output_pa: (n_t,) feedback increment (0 without a controller);
    actuator_states (n_t, order), controller_states (n_t, n_k)."""

    speed_hz: float
    chamber_pressure_pa: float
    config_ay_m: float
    t: np.ndarray
    r: np.ndarray
    v: np.ndarray
    journal_x_m: np.ndarray
    journal_y_m: np.ndarray
    clearance_m: np.ndarray
    h_min_m: np.ndarray
    bearing_names: tuple
    equilibrium_r: np.ndarray
    stats: dict
    status: str = "ok"
    message: str = ""
    speed_hz_t: np.ndarray | None = None
    angle_rad: np.ndarray | None = None
    chamber_pressure_command_pa: np.ndarray | None = None
    chamber_pressure_actual_pa: np.ndarray | None = None
    controller_output_pa: np.ndarray | None = None
    actuator_states: np.ndarray | None = None
    controller_states: np.ndarray | None = None
    adaptive_states: np.ndarray | None = None  # (n_t, 2) [Re P, Im P] Pa of the adaptive 1×
    # tilting films (tilt = true), (n_t, n_bearings), NaN for a bearing without one; None
    # when no film tilts: the journal's rotations relative to the housing (rad) and the
    # films' moments on the journal (N·m; one film solve per output after the run)
    journal_theta_x_rad: np.ndarray | None = None
    journal_theta_y_rad: np.ndarray | None = None
    film_moment_x_n_m: np.ndarray | None = None
    film_moment_y_n_m: np.ndarray | None = None

    def __repr__(self) -> str:
        amp = ""
        if len(self.t) > 1 and self.journal_x_m.shape[1]:
            amp = f", final amplitude {self.amplitude() * 1e6:.3g} µm ({self.bearing_names[0]})"
        return (f"<TransientResult {self.status}: {self.t[-1] - self.t[0] if len(self.t) else 0:g}"
                f" s, {len(self.t)} samples, {self.speed_hz:g} Hz, p_c = "
                f"{self.chamber_pressure_pa / 1e6:g} MPa{amp}>")

    def to_frame(self) -> pd.DataFrame:
        """One row per (time, bearing); with a tilting film also the journal's rotations
        and the films' moments (NaN for a bearing without a tilting film)."""
        import pandas as pd
        nt, nb = self.journal_x_m.shape

        def col(a, default):
            return np.repeat(a, nb) if a is not None else default

        tilt = {k: getattr(self, k).ravel() for k in _TILT if getattr(self, k) is not None}
        return pd.DataFrame({
            "t_s": np.repeat(self.t, nb),
            "bearing": np.tile(np.asarray(self.bearing_names, dtype=object), nt),
            "speed_hz": col(self.speed_hz_t, self.speed_hz),
            "chamber_pressure_pa": col(self.chamber_pressure_actual_pa,
                                       self.chamber_pressure_pa),
            "chamber_pressure_command_pa": col(self.chamber_pressure_command_pa,
                                               self.chamber_pressure_pa),
            "controller_output_pa": col(self.controller_output_pa, 0.0),
            "journal_x_m": self.journal_x_m.ravel(),
            "journal_y_m": self.journal_y_m.ravel(),
            "h_min_m": self.h_min_m.ravel(),
            **tilt,
            "status": self.status,
        })

    def amplitude(self, bearing: int = 0, last_fraction: float = 0.25) -> float:
        """Peak distance from the equilibrium over the last part of the run, m."""
        n = max(2, int(len(self.t) * last_fraction))
        x = self.journal_x_m[-n:, bearing]
        y = self.journal_y_m[-n:, bearing]
        return float(np.max(np.hypot(x - x.mean(), y - y.mean())))

    def spectrum(self, bearing: int = 0, last_fraction: float = 0.5, axis: str = "x"):
        """One-sided amplitude spectrum of the journal motion over the last part of the run:
        (freq_hz, amplitude_m). Needs uniformly spaced output times."""
        n = max(8, int(len(self.t) * last_fraction))
        z = (self.journal_x_m if axis == "x" else self.journal_y_m)[-n:, bearing]
        dt = np.diff(self.t[-n:])
        if not np.allclose(dt, dt[0], rtol=1e-6):
            raise ValueError("spectrum: output times must be uniformly spaced")
        z = z - z.mean()
        win = np.hanning(n)
        amp = 2 * np.abs(np.fft.rfft(z * win)) / win.sum()
        return np.fft.rfftfreq(n, dt[0]), amp

    def _signal(self, output):
        """(n_t, 2) x, y of ``output``: a bearing index (journal) or a (2, n) output matrix."""
        if isinstance(output, (int, np.integer)):
            return np.column_stack([self.journal_x_m[:, output], self.journal_y_m[:, output]])
        return self.r @ np.asarray(output).T

    def order_amplitude(self, output=0, speeds_hz=None, *, order: float = 1.0,
                        revolutions: float = 8.0):
        """Run-up order tracking: amplitude √(|X|² + |Y|²) of the ``order``× component of
        ``output`` (bearing index, or a (2, n) matrix such as ``station_output_matrix``) at
        each speed, by least squares on [1, t, cos kθ, sin kθ] over ±revolutions/2 around
        the time the run passes that speed (θ: the integrated rotor angle). Returns
        (speeds_hz, amplitude_m)."""
        if self.speed_hz_t is None or self.angle_rad is None:
            raise ValueError("order_amplitude: the result has no speed/angle history")
        z = self._signal(output)
        sp = self.speed_hz_t
        if speeds_hz is None:
            speeds_hz = np.linspace(sp.min(), sp.max(), 200)
        speeds_hz = np.asarray(speeds_hz, dtype=float)
        amp = np.full(speeds_hz.size, np.nan)
        mono = np.all(np.diff(sp) >= 0)
        for i, f in enumerate(speeds_hz):
            if f <= 0:
                continue
            tc = np.interp(f, sp, self.t) if mono else self.t[np.argmin(np.abs(sp - f))]
            win = np.abs(self.t - tc) <= 0.5 * revolutions / f
            if win.sum() < 8:
                continue
            th, tt = order * self.angle_rad[win], self.t[win] - tc
            A = np.column_stack([np.ones_like(tt), tt, np.cos(th), np.sin(th)])
            c = np.linalg.lstsq(A, z[win], rcond=None)[0]
            amp[i] = float(np.sqrt(np.sum(c[2:4] ** 2)))
        return speeds_hz, amp

    def waterfall(self, output=0, *, window_s: float = 0.25, step_s: float | None = None,
                  axis: int = 0):
        """Short-time amplitude spectra of ``output``'s x (axis 0) or y (1) motion (Hann
        window, mean removed): (speed_hz (n_w,), freq_hz (n_f,), amplitude_m (n_w, n_f)).
        Needs uniformly spaced output times."""
        z = self._signal(output)[:, axis]
        dt = np.diff(self.t)
        if not np.allclose(dt, dt[0], rtol=1e-6):
            raise ValueError("waterfall: output times must be uniformly spaced")
        nw = max(8, int(round(window_s / dt[0])))
        step = max(1, int(round((step_s or window_s / 2) / dt[0])))
        win = np.hanning(nw)
        sp, rows = [], []
        for s0 in range(0, len(z) - nw + 1, step):
            seg = z[s0:s0 + nw]
            rows.append(2 * np.abs(np.fft.rfft((seg - seg.mean()) * win)) / win.sum())
            sp.append(float(np.mean(self.speed_hz_t[s0:s0 + nw]))
                      if self.speed_hz_t is not None else self.speed_hz)
        return np.array(sp), np.fft.rfftfreq(nw, dt[0]), np.array(rows)

    def plot(self, bearing: int = 0, ax=None):
        """Journal orbit in units of the clearance, with the clearance circle and the
        equilibrium (start) point."""
        from matplotlib.lines import Line2D

        from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style

        @paper_style
        def draw(ax):
            ax = new_axes(ax, width=COLUMN_IN, aspect=1.0)
            c = self.clearance_m[bearing]
            th = np.linspace(0, 2 * np.pi, 200)
            ax.plot(np.cos(th), np.sin(th), "k-", lw=0.8)
            x, y = self.journal_x_m[:, bearing] / c, self.journal_y_m[:, bearing] / c
            ax.plot(x, y, lw=0.8, color="tab:blue")
            ax.plot(x[:1], y[:1], "o", color="tab:green", ms=3)
            ax.plot(x[-1:], y[-1:], "s", color="tab:red", ms=3)
            ax.set_aspect("equal")
            ax.set_xlabel("journal x / c (–), horizontal")
            ax.set_ylabel("journal y / c (–), vertical up")
            ax.set_title(f"{self.bearing_names[bearing]}: {self.speed_hz:g} Hz, "
                         f"p_c = {self.chamber_pressure_pa / 1e6:g} MPa")
            ax.legend(handles=[
                Line2D([], [], color="k", lw=0.8, label="clearance circle (e = c)"),
                Line2D([], [], color="tab:blue", lw=0.8,
                       label=f"orbit, {self.t[-1] - self.t[0]:.3g} s"),
                Line2D([], [], color="tab:green", marker="o", ls="", ms=3, label="start"),
                Line2D([], [], color="tab:red", marker="s", ls="", ms=3, label="end")],
                loc="lower left", fontsize=6)
            return ax

        return draw(ax)
