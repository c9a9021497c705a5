"""Static equilibrium of the system (paper eq. 14-16)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display


from rotordyn._common.status import CONVERGED, FAILED, STATUSES  # noqa: F401

if TYPE_CHECKING:
    import pandas as pd


# to_frame()'s columns a failed equilibrium keeps (the others are its state: NaN)
_INPUT_COLUMNS = ["bearing", "speed_hz", "chamber_pressure_pa", "config_ax_m", "config_ay_m",
                  "config_theta_x_rad", "config_theta_y_rad", "iterations", "reynolds_solves",
                  "residual", "status", "message"]


@dataclass(frozen=True)
class EquilibriumResult(Display):
    """Equilibrium at one operating point.

    r: (n,) all coordinates (rotor masters relative to the housings, then sleeve masters, m).
    journal_x_m, journal_y_m, clearance_m, h_min_m, h_min_angle_deg: (n_bearings,) per bearing;
    journal positions are relative to the bearing housing (q of eq. 7), in the DESIGN frame.
    A bearing without a film (table or linear support: clearance 0) has NaN ("not
    applicable") in clearance-scaled values, h_min and its angle.
    sleeve_m: {bearing index: (n_m,) inward sleeve master coordinates, m}.
    """

    speed_hz: float
    chamber_pressure_pa: float
    config_ay_m: np.ndarray
    config_ax_m: np.ndarray
    method: str
    r: np.ndarray
    film_force_n: np.ndarray
    bearing_names: tuple
    journal_x_m: np.ndarray
    journal_y_m: np.ndarray
    clearance_m: np.ndarray
    h_min_m: np.ndarray
    h_min_angle_deg: np.ndarray
    sleeve_m: dict = field(default_factory=dict)
    iterations: int = 0
    reynolds_solves: int = 0
    residual: float = float("nan")
    pm: float = float("nan")
    status: str = "ok"
    message: str = ""
    # how the Newton start was reached: "newton", "pad_assembly" (tilting pads), "homotopy"
    # (tilting pads, fallback), "load_continuation", "successive"
    path: str = ""
    # bearings whose film couples to the journal's rotations (tilt = true): {bearing index:
    # {"journal_theta_x_rad", "journal_theta_y_rad" (relative to the housing),
    # "config_theta_x_rad", "config_theta_y_rad" (housing misalignment), "h_min_z_m"
    # (axial position of the minimum film, z = 0 mid-plane); tilting pads also
    # "pad_h_min_m", "pad_h_min_z_m" (tuples, every pad's minimum film and its z) and with
    # spherical pivots "pad_pitch_rad" (tuple): not columns of to_frame()}}
    tilt: dict = field(default_factory=dict)
    # tilting-pad bearings (tilted or not), converged equilibria only: {bearing index:
    # {"pad_pivot_deg", "pad_tilt_rad", "pad_p_max_pa", "pad_h_min_m", "pad_unloaded"}}, tuples
    # in pad order (analysis.equilibrium.pad_outputs); one row per pad in pads_frame()
    pads: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        pos = "; ".join(f"{n or i}: x/c = {x:.4f}, y/c = {y:.4f}"
                        for i, (n, x, y) in enumerate(zip(self.bearing_names, self.x_over_c,
                                                          self.y_over_c)))
        return (f"<EquilibriumResult {self.status}: {self.speed_hz:g} Hz, p_c = "
                f"{self.chamber_pressure_pa / 1e6:g} MPa; {pos or 'no bearings'}; "
                f"{self.iterations} iterations, residual {self.residual:.2g}>")

    @property
    def converged(self) -> bool:
        """True for a converged equilibrium (status ``"ok"`` or ``"contact"``)."""
        return self.status in CONVERGED

    def per_bearing(self) -> dict[str, dict]:
        """Each bearing's values keyed by its name (``bearing[i]`` when it has none), as plain
        numbers rather than arrays over the bearings: ``{name: {"config_ax_m", "config_ay_m",
        "journal_x_m", "journal_y_m", "x_over_c", "y_over_c", "eccentricity_ratio",
        "h_min_m", "h_min_angle_deg", "clearance_m"[, "sleeve_m" (list, m)][, the tilting
        film's outputs of :attr:`tilt` (per-pad tuples as lists)][, a tilting-pad bearing's
        :attr:`pads` (lists)]}}``."""
        out = {}
        for i, n in enumerate(self.bearing_names):
            d = {k: float(getattr(self, k)[i]) for k in (
                "config_ax_m", "config_ay_m", "journal_x_m", "journal_y_m", "x_over_c",
                "y_over_c", "eccentricity_ratio", "h_min_m", "h_min_angle_deg", "clearance_m")}
            if i in self.sleeve_m:
                d["sleeve_m"] = [float(x) for x in self.sleeve_m[i]]
            for k, val in self.tilt.get(i, {}).items():
                d[k] = [float(x) for x in val] if isinstance(val, tuple) else float(val)
            for k, val in self.pads.get(i, {}).items():
                d[k] = [bool(x) if k == "pad_unloaded" else float(x) for x in val]
            out[str(n or f"bearing[{i}]")] = d
        return out

    def bearing(self, name: str) -> dict:
        """One bearing's values (:meth:`per_bearing`) by name."""
        d = self.per_bearing()
        if name not in d:
            from rotordyn.errors import InputError

            raise InputError(f"bearing: expected one of {list(d)}, got {name!r}")
        return d[name]

    def _over_c(self, value) -> np.ndarray:
        # A bearing without a film (a table or linear support: clearance 0) has no
        # eccentricity ratio: NaN ("not applicable"), never ±inf.
        c = np.asarray(self.clearance_m, dtype=float)
        out = np.full(np.shape(value), np.nan)
        np.divide(value, c, out=out, where=c > 0)
        return out

    @property
    def x_over_c(self) -> np.ndarray:
        return self._over_c(self.journal_x_m)

    @property
    def y_over_c(self) -> np.ndarray:
        return self._over_c(self.journal_y_m)

    @property
    def eccentricity_ratio(self) -> np.ndarray:
        return self._over_c(np.hypot(self.journal_x_m, self.journal_y_m))

    def plot(self, ax=None):
        """Journal centre of every bearing in units of its clearance, in the clearance circle."""
        from matplotlib.lines import Line2D

        from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style

        @paper_style
        def draw(ax):
            ax = new_axes(ax, width=COLUMN_IN, aspect=1.0)
            th = np.linspace(0, 2 * np.pi, 361)
            ax.plot(np.cos(th), np.sin(th), color="0.4", lw=0.8)
            h = [Line2D([], [], color="0.4", lw=0.8, label="clearance circle (e = c)")]
            for i, n in enumerate(self.bearing_names):
                ln, = ax.plot([self.x_over_c[i]], [self.y_over_c[i]], "o", color=f"C{i}",
                              label=f"{n}: e/c = {self.eccentricity_ratio[i]:.3f}")
                h.append(ln)
            ax.set_aspect("equal")
            ax.set_xlim(-1.1, 1.1)
            ax.set_ylim(-1.1, 1.1)
            ax.set_xlabel("journal x / c (–), horizontal")
            ax.set_ylabel("journal y / c (–), vertical up")
            ax.set_title(f"equilibrium ({self.status}): {self.speed_hz:g} Hz, "
                         f"p_c = {self.chamber_pressure_pa / 1e6:g} MPa")
            ax.legend(handles=h, loc="lower left", fontsize=6)
            return ax

        return draw(ax)

    def pads_frame(self) -> pd.DataFrame:
        """One row per pad of every tilting-pad bearing: ``bearing``, ``pad`` (0-based, pivot
        order), ``pivot_deg``, ``tilt_rad``, ``p_max_pa`` (peak film pressure), ``h_min_m``
        and ``unloaded`` (its film carries no pressure). Empty without tilting pads or
        without a converged equilibrium."""
        import pandas as pd
        rows = []
        for bi, d in self.pads.items():
            for k in range(len(d["pad_tilt_rad"])):
                rows.append({"bearing": self.bearing_names[bi], "pad": k,
                             "pivot_deg": d["pad_pivot_deg"][k], "tilt_rad": d["pad_tilt_rad"][k],
                             "p_max_pa": d["pad_p_max_pa"][k], "h_min_m": d["pad_h_min_m"][k],
                             "unloaded": d["pad_unloaded"][k]})
        return pd.DataFrame(rows, columns=["bearing", "pad", "pivot_deg", "tilt_rad", "p_max_pa",
                                           "h_min_m", "unloaded"])

    def to_frame(self) -> pd.DataFrame:
        """One row per bearing: inputs (``chamber_pressure_pa`` with an active bearing only),
        journal position (m and /c), film, status. An equilibrium that did not converge has
        no position: its state columns (position, film, sleeve, tilt) are NaN, as in the
        sweep rows (the attributes keep the last iterate, for diagnosis)."""
        import pandas as pd
        nb = len(self.bearing_names)
        df = pd.DataFrame({
            "bearing": self.bearing_names,
            "speed_hz": np.full(nb, self.speed_hz),
            "config_ax_m": self.config_ax_m,
            "config_ay_m": self.config_ay_m,
            "journal_x_m": self.journal_x_m,
            "journal_y_m": self.journal_y_m,
            "x_over_c": self.x_over_c,
            "y_over_c": self.y_over_c,
            "eccentricity_ratio": self.eccentricity_ratio,
            "h_min_m": self.h_min_m,
            "h_min_angle_deg": self.h_min_angle_deg,
            "iterations": np.full(nb, self.iterations, dtype=np.int64),
            "reynolds_solves": np.full(nb, self.reynolds_solves, dtype=np.int64),
            "residual": np.full(nb, self.residual),
            "status": pd.Categorical([self.status] * nb, categories=list(STATUSES)),
            "message": [self.message] * nb,
        })
        if self.sleeve_m:  # an active bearing: the chamber pressure is an input
            df.insert(2, "chamber_pressure_pa", np.full(nb, self.chamber_pressure_pa))
        for bi, s in self.sleeve_m.items():
            for j, val in enumerate(s):
                col = f"sleeve_{j + 1}_m"
                if col not in df:
                    df[col] = np.nan
                df.loc[bi, col] = val
        for bi, d in self.tilt.items():  # tilting films: rotations, misalignment, edge film
            for col, val in d.items():
                if isinstance(val, tuple):  # per pad (pad_h_min_m, …): in .tilt only
                    continue
                if col not in df:
                    df[col] = np.nan
                df.loc[bi, col] = val
        if not self.converged:  # no state: inputs, counters, status and message only
            for col in df.columns.difference(_INPUT_COLUMNS):
                df[col] = np.nan
        return df
