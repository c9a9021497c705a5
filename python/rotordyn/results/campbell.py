"""Campbell diagrams: natural frequencies against spin speed, and the critical speeds where a
frequency crosses a multiple of the running speed."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

from rotordyn._common.api import RESONANT_LOG_DEC
from rotordyn._common.status import CONVERGED, point_messages
from rotordyn._common.whirl import driven_by_unbalance
from rotordyn.results.modes import WHIRL_NAMES, log_dec

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class CampbellResult(Display):
    """speeds_hz: (n_speeds,). eigenvalues: (n_speeds, n_modes) complex, 1/s, modes sorted by
    damped frequency at each speed. whirl: (n_speeds, n_modes) int (+1 forward, −1 backward,
    0 planar). mode_id: (n_speeds, n_modes) int64 tracked id of each slot (eigenvector
    continuity, :func:`rotordyn.analysis.tracking.track_modes`; −1 for no mode), or None when
    the modes were not tracked (then a slot's index is its id)."""

    speeds_hz: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray
    model: str = "full"
    status: str = "ok"
    message: str = ""
    kind: np.ndarray | None = None  # (n_speeds, n_modes) "rotor"/"sleeve" (systems with films)
    point_status: np.ndarray | None = None  # (n_speeds,) equilibrium status per speed
    mode_id: np.ndarray | None = None  # (n_speeds, n_modes) tracked ids
    thermal: tuple = ()  # (n_speeds,) SystemThermalResult per speed (``thermal=``), else ()
    # (n_speeds,) object: why a speed failed (str), None where it converged; filled from
    # point_status when not given (rotordyn._common.status.point_messages)
    point_message: np.ndarray | None = None

    def __post_init__(self):
        ns = len(self.speeds_hz)
        st = self.point_status if self.point_status is not None else [self.status] * ns
        msg = [self.message] * ns if self.point_message is None else self.point_message
        object.__setattr__(self, "point_message", point_messages(st, msg))

    def ids(self) -> np.ndarray:
        """(n_speeds, n_modes) int64 mode ids: the tracked ones, else the slot index."""
        if self.mode_id is not None:
            return self.mode_id
        ns, nm = self.eigenvalues.shape
        return np.tile(np.arange(nm, dtype=np.int64), (ns, 1))

    def tracked(self, values: np.ndarray | None = None) -> np.ndarray:
        """Rearrange a (n_speeds, n_modes) array (default: the eigenvalues) by tracked mode:
        (n_speeds, n_ids), column j the values of mode id j along the speeds (NaN where that
        mode is absent). Plot these columns as curves: they cross where the modes cross."""
        vals = self.eigenvalues if values is None else np.asarray(values)
        ids = self.ids()
        n_ids = int(ids.max()) + 1 if ids.size and ids.max() >= 0 else 0
        dtype = vals.dtype if np.issubdtype(vals.dtype, np.inexact) else float
        out = np.full((vals.shape[0], n_ids), np.nan, dtype=dtype)
        i, j = np.nonzero(ids >= 0)
        out[i, ids[i, j]] = vals[i, j]
        return out

    def __repr__(self) -> str:
        ns, nm = self.eigenvalues.shape
        try:
            cs = self.critical_speeds()
            crit = cs.loc[cs["resonant"], "speed_hz"].to_numpy()
            cs = ", ".join(f"{x:.4g}" for x in crit[:6]) or "none"
        except Exception:  # noqa: BLE001 - a repr never raises
            cs = "?"
        bad = 0 if self.point_status is None else int(np.sum(self.point_status != "ok"))
        return (f"<CampbellResult {self.model}: {ns} speeds {self.speeds_hz[0]:g}–"
                f"{self.speeds_hz[-1]:g} Hz × {nm} modes; forward 1× critical speeds (Hz): {cs}"
                + (f"; {bad} speeds not ok" if bad else "")
                + (f"; status {self.status}" if self.status != "ok" else "") + ">")

    @property
    def frequencies_hz(self) -> np.ndarray:
        """(n_speeds, n_modes) damped natural frequencies, Hz."""
        return self.eigenvalues.imag / (2 * np.pi)

    @property
    def log_dec(self) -> np.ndarray:
        return log_dec(self.eigenvalues)

    def critical_speeds(self, harmonic: float = 1.0, whirl: str | None = "forward") -> pd.DataFrame:
        """Speeds where a mode's damped frequency equals ``harmonic`` × running speed, by linear
        interpolation between the computed speeds along each tracked mode. ``whirl`` filters by
        the mode's whirl at the crossing (None: any; "forward" keeps every mode an unbalance
        drives, forward and planar whirl, :func:`rotordyn._common.whirl.driven_by_unbalance`:
        on anisotropic supports the first critical can be a planar mode). Columns: mode (tracked id + 1),
        speed_hz, freq_hz, whirl, harmonic, log_dec (the mode's δ at the crossing, interpolated
        along the tracked mode) and resonant (δ < 2π, damping ratio below 1/√2: a root damped
        beyond it crosses the line but gives no resonance peak — a heavy bearing mode at low
        speed; :data:`rotordyn._common.api.RESONANT_LOG_DEC`)."""
        import pandas as pd
        rows = []
        f = self.frequencies_hz
        if self.kind is not None:
            f = np.where(self.kind == "rotor", f, np.nan)
        # Along the tracked curves: sorted slots swap modes where two frequencies cross.
        f = self.tracked(f)
        wh = self.tracked(self.whirl.astype(float))
        ld = self.tracked(np.where(np.isfinite(self.log_dec), self.log_dec, np.nan))
        for j in range(f.shape[1]):
            g = f[:, j] - harmonic * self.speeds_hz
            for i in np.where(np.sign(g[:-1]) * np.sign(g[1:]) < 0)[0]:
                t = g[i] / (g[i] - g[i + 1])
                s = self.speeds_hz[i] + t * (self.speeds_hz[i + 1] - self.speeds_hz[i])
                w = WHIRL_NAMES[int(wh[i if t < 0.5 else i + 1, j])]
                ok = np.isfinite(ld[:, j])
                d = float(np.interp(s, self.speeds_hz[ok], ld[ok, j])) if ok.any() else np.nan
                if (whirl is None or w == whirl
                        or (whirl == "forward" and bool(driven_by_unbalance(w)))):
                    rows.append({"mode": j + 1, "speed_hz": s, "freq_hz": harmonic * s,
                                 "whirl": w, "harmonic": harmonic, "log_dec": d,
                                 # an unknown δ (NaN) stays a critical speed
                                 "resonant": not d >= RESONANT_LOG_DEC})
        df = pd.DataFrame(rows, columns=["mode", "speed_hz", "freq_hz", "whirl", "harmonic",
                                         "log_dec", "resonant"])
        return df.sort_values("speed_hz", ignore_index=True)

    def rotor_mask(self) -> np.ndarray:
        """(n_speeds, n_modes) True for rotor modes (all when no sleeve)."""
        if self.kind is None:
            return np.ones(self.eigenvalues.shape, dtype=bool)
        return self.kind == "rotor"

    def to_frame(self) -> pd.DataFrame:
        """Tidy: one row per (speed, mode); with ``thermal`` (each speed at its own thermal
        equilibrium) also the thermal columns of each speed
        (:data:`rotordyn.results.thermal.THERMAL_POINT_COLUMNS`)."""
        import pandas as pd
        ns, nm = self.eigenvalues.shape
        lam = self.eigenvalues.ravel()
        st = (np.repeat(self.point_status, nm) if self.point_status is not None
              else [self.status] * (ns * nm))
        # "" where the speed converged, as every other frame and the sweep rows write it
        msg = ["" if m is None else m for m in np.repeat(self.point_message, nm)]
        # A slot without an eigenvalue (a failed speed's row) has no whirl and no kind: a
        # failed equilibrium is not classified.
        none = np.isnan(lam)
        whirl = [None if n else WHIRL_NAMES[int(w)] for n, w in zip(none, self.whirl.ravel())]
        df = pd.DataFrame({
            "model": pd.Categorical([self.model] * (ns * nm)),
            "speed_hz": np.repeat(self.speeds_hz, nm),
            "mode": np.tile(np.arange(1, nm + 1, dtype=np.int64), ns),
            "mode_id": self.ids().ravel(),
            "freq_hz": lam.imag / (2 * np.pi),
            "eig_real_1_per_s": lam.real,
            "log_dec": self.log_dec.ravel(),
            "whirl": pd.Categorical(whirl, categories=["forward", "backward", "planar"]),
            "status": pd.Categorical(st),
            "message": msg,
        })
        if self.kind is not None:
            kind = np.where(none, None, self.kind.ravel())
            df.insert(4, "kind", pd.Categorical(kind, categories=["rotor", "sleeve", "pad"]))
        if self.thermal:
            from rotordyn.results.thermal import thermal_frame_columns

            for k, col in thermal_frame_columns(self.thermal, nm).items():
                df[k] = col
        # A slot with no mode at a solved speed (fewer underdamped modes there than slots) is
        # not a row: a status-ok row never carries a NaN eigenvalue (the sweep's campbell rows
        # leave them out too). A failed speed keeps its NaN rows with its failed status.
        empty = ~np.isfinite(lam) & np.isin(np.asarray(st, dtype=str), list(CONVERGED))
        if empty.any():
            df = df[~empty].reset_index(drop=True)
        return df

    def plot(self, ax=None, harmonics=(0.5, 1.0, 2.0), color_by: str = "log_dec",
             critical: bool = True, rotor_only: bool = True):
        """Campbell diagram (:func:`rotordyn.plot.campbell_diagram`): tracked modes coloured by
        log decrement (or ``color_by="damping_ratio"``) with a colour bar, unstable stretches
        red, forward/backward/planar solid/dashed/dotted, order lines, critical speeds."""
        from rotordyn.plot.frequency import campbell_diagram

        return campbell_diagram(self, ax=ax, color_by=color_by, harmonics=harmonics,
                                critical=critical, rotor_only=rotor_only)
