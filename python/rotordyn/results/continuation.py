"""A branch of periodic orbits of eq. 12 continued over one parameter (pseudo-arclength),
with its Floquet stability and bifurcations: the data of a bifurcation diagram."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

if TYPE_CHECKING:
    import pandas as pd

#: the continued variables, their units in the result and the factor from SI to that unit
UNITS = {"chamber_pressure_pa": ("Pa", "p_c", 1e-6, "MPa"),
         "speed_hz": ("Hz", "speed", 1.0, "Hz"),
         "config_ay_m": ("m", "a_y", 1e3, "mm")}
BIFURCATION_KINDS = ("fold", "period_doubling", "neimark_sacker", "stability_change", "hopf")


def parameter_units(vary: str) -> tuple:
    """(SI unit, symbol, display factor, display unit) of ``vary``: the operating variables'
    from UNITS, a model field's from its suffix (DESIGN §9)."""
    if vary in UNITS:
        return UNITS[vary]
    name = vary.rsplit(".", 1)[-1]
    for suffix, unit in (("_pa_s", "Pa·s"), ("_kg_m2", "kg·m²"), ("_n_per_m", "N/m"),
                         ("_n_s_per_m", "N·s/m"), ("_m_s2", "m/s²"), ("_kg", "kg"),
                         ("_pa", "Pa"), ("_hz", "Hz"), ("_deg", "deg"), ("_m", "m")):
        if name.endswith(suffix):
            return unit, vary, 1.0, unit
    return "", vary, 1.0, ""


@dataclass(frozen=True)
class BranchResult(Display):
    """A branch of periodic orbits over the parameter ``vary``.

    parameter: (n_points,) in the unit of ``vary`` (Pa, Hz, m, or a model field's SI unit);
    amplitude_m: (n_points, n_bearings) the largest distance of each journal from its orbit's
    mean position (a system without bearings: one column, "largest coordinate", the largest
    distance of any coordinate from its mean, clearance NaN); clearance_m: (n_bearings,), or
    (n_points, n_bearings) where a model field changes the clearances along the branch;
    period_s: (n_points,); max_multiplier: (n_points,) the modulus of the critical
    (non-trivial, largest) Floquet multiplier; stable: (n_points,) bool (max_multiplier < 1);
    critical_type: (n_points,) how the critical multiplier sits (``fold``: real > 0,
    ``period_doubling``: real < 0, ``neimark_sacker``: complex pair); arclength: (n_points,)
    the scaled pseudo-arclength s of each point (docs/nonlinear.md); tangent_p: (n_points,)
    dp/ds of the branch (a sign change: the parameter turns back, a fold).
    bifurcations: one dict per detected bifurcation between two successive points, with keys
    ``kind`` (``fold`` — a multiplier through +1 with the parameter turning back —,
    ``period_doubling`` — through −1 —, ``neimark_sacker`` — a complex pair through the unit
    circle —, ``stability_change`` — a real multiplier through +1 without a turn, e.g. a
    branch point —, or ``hopf`` — the cycles shrink onto the equilibrium: the branch ends,
    with ``curvature`` c of p = p_H + b·A + c·A², the period there, and
    ``beyond_parameter``/``beyond_amplitude_m`` of the corrected point past the turn, not on
    the branch), ``index`` (the point after it), ``parameter`` and ``amplitude_m`` (linear
    interpolation at the crossing), ``multiplier`` (the critical multiplier after it).
    orbits: the PeriodicOrbitResult of every point. stop: why the branch ended (``bound``,
    ``max_points``, ``step_min``, ``hopf`` — the branch passed through the
    equilibrium at a Hopf point —, ``equilibrium`` — the cycle shrank onto an equilibrium, a
    Hopf point —, ``rub``); message: the last corrector failure, if any.
    """

    vary: str
    kind: str
    parameter: np.ndarray
    amplitude_m: np.ndarray
    period_s: np.ndarray
    max_multiplier: np.ndarray
    stable: np.ndarray
    critical_type: tuple
    arclength: np.ndarray
    tangent_p: np.ndarray
    bearing_names: tuple
    clearance_m: np.ndarray
    bifurcations: tuple
    orbits: tuple = ()
    bounds: tuple = (np.nan, np.nan)
    stop: str = ""
    message: str = ""
    stats: dict = field(default_factory=dict)
    status: str = "ok"

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @property
    def unit(self) -> str:
        return parameter_units(self.vary)[0]

    def __len__(self) -> int:
        return int(self.parameter.size)

    def __repr__(self) -> str:
        u, sym, f, disp = parameter_units(self.vary)
        head = f"<BranchResult {self.status}: {self.kind} orbits over {self.vary}"
        if not len(self):
            return head + f", no points: {self.message}>"
        p = self.parameter * f
        a = self.amplitude_m[:, 0] * 1e6
        bif = ", ".join(f"{b['kind']} at {sym} = {b['parameter'] * f:.5g} {disp}"
                        for b in self.bifurcations) or "no bifurcation"
        return (f"{head}, {len(self)} points, {sym} {p[0]:.5g} → {p[-1]:.5g} {disp} (range "
                f"{p.min():.5g}…{p.max():.5g}), amplitude {a[0]:.4g} → {a[-1]:.4g} µm, "
                f"{int(np.sum(self.stable))} stable ({self.bearing_names[0]}); {bif}; "
                f"stop: {self.stop}>")

    def to_frame(self) -> pd.DataFrame:
        """One row per (branch point, bearing): the parameter in its unit (column named by
        ``vary``), amplitude_m, period_s, max_multiplier, stable, critical_type, arclength,
        and ``bifurcation`` (the kind of a bifurcation detected just before this point, else
        "")."""
        import pandas as pd
        npt = len(self)
        nb = self.amplitude_m.shape[1]
        bif = [""] * npt
        for b in self.bifurcations:
            bif[b["index"]] = (bif[b["index"]] + "," if bif[b["index"]] else "") + b["kind"]
        return pd.DataFrame({
            "point": np.repeat(np.arange(npt), nb),
            "bearing": np.tile(np.asarray(self.bearing_names, dtype=object), npt),
            self.vary: np.repeat(self.parameter, nb),
            "amplitude_m": self.amplitude_m.ravel(),
            "amplitude_c": (self.amplitude_m / np.atleast_2d(self.clearance_m)).ravel(),
            "period_s": np.repeat(self.period_s, nb),
            "max_multiplier": np.repeat(self.max_multiplier, nb),
            "stable": np.repeat(self.stable, nb),
            "critical_type": np.repeat(np.asarray(self.critical_type, dtype=object), nb),
            "arclength": np.repeat(self.arclength, nb),
            "bifurcation": np.repeat(np.asarray(bif, dtype=object), nb),
        })

    def bifurcations_frame(self) -> pd.DataFrame:
        """One row per bifurcation: kind, index, parameter (unit of ``vary``), amplitude_m,
        multiplier modulus and argument."""
        import pandas as pd
        rows = [{"kind": b["kind"], "index": b["index"], self.vary: b["parameter"],
                 "amplitude_m": b["amplitude_m"], "multiplier_modulus": abs(b["multiplier"]),
                 "multiplier_angle_rad": float(np.angle(b["multiplier"]))}
                for b in self.bifurcations]
        return pd.DataFrame(rows, columns=["kind", "index", self.vary, "amplitude_m",
                                           "multiplier_modulus", "multiplier_angle_rad"])

    def plot(self, bearing: int = 0, ax=None):
        """Bifurcation diagram: the journal's amplitude (µm) against the parameter, stable
        parts solid, unstable dashed, bifurcations marked. Returns the Axes."""
        from matplotlib.lines import Line2D

        from rotordyn.plot._style import PAGE_IN, paper_style, stability_segments

        u, sym, f, disp = parameter_units(self.vary)
        marks = {"fold": ("o", "tab:red"), "period_doubling": ("s", "tab:purple"),
                 "neimark_sacker": ("D", "tab:green"), "stability_change": ("^", "tab:orange"),
                 "hopf": ("*", "k")}

        @paper_style
        def draw(ax):
            import matplotlib.pyplot as plt

            if ax is None:
                _, ax = plt.subplots(figsize=(PAGE_IN * 0.6, PAGE_IN * 0.45),
                                     layout="constrained")
            p = self.parameter * f
            a = self.amplitude_m[:, bearing] * 1e6 if len(self) else np.zeros(0)
            handles = stability_segments(ax, p, a, self.stable, "orbits")
            ax.plot(p, a, ".", color="tab:blue", ms=3)
            seen = set()
            for b in self.bifurcations:
                mk, col = marks[b["kind"]]
                if b["kind"] == "hopf" and len(self):  # the branch's last stretch to it
                    ax.plot([p[-1], b["parameter"] * f], [a[-1], 0.0], ":", color="tab:blue",
                            lw=1.0)
                ax.plot([b["parameter"] * f], [b["amplitude_m"][bearing] * 1e6], mk, color=col,
                        mfc="none", ms=7)
                if b["kind"] not in seen:
                    seen.add(b["kind"])
                    handles.append(Line2D([], [], color=col, marker=mk, mfc="none", ls="",
                                          label=b["kind"].replace("_", " ")))
            ax.set_xlabel(f"{sym} ({disp})")
            ax.set_ylabel(f"{self.bearing_names[bearing]}: orbit amplitude (µm)")
            ax.set_title(f"{self.kind} orbits over {sym}")
            ax.legend(handles=handles, fontsize=6)
            return ax

        return draw(ax)
