"""Periodic orbits of the nonlinear system (paper eq. 12) and their Floquet multipliers."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

if TYPE_CHECKING:
    import pandas as pd

CRITICAL_TYPES = ("fold", "period_doubling", "neimark_sacker")


@dataclass(frozen=True)
class PeriodicOrbitResult(Display):
    """One period of a periodic orbit of eq. 12 found by shooting.

    kind: ``"autonomous"`` (a self-excited limit cycle, period unknown) or ``"forced"``
    (unbalance forcing, period k·2π/Ω). t: (n_t,) s over [t0, t0 + T]; r, v: (n_t, n)
    coordinates and velocities (m, m/s); journal_x_m, journal_y_m: (n_t, n_bearings) relative
    to each housing; period_s: T; monodromy: (2n, 2n) ∂x(t0 + T)/∂x(t0) with x = (r, ṙ)
    (harmonic balance with ``floquet="hill"``: the one Hill's exponents and eigenvectors
    give, (0, 0) where their Floquet solutions are numerically dependent);
    multipliers: (2n,) complex Floquet multipliers, largest modulus first; trivial_index:
    index of the trivial multiplier (autonomous: the flow direction, ≈ 1), −1 for forced
    orbits; critical_index: the non-trivial multiplier of largest modulus; stable: its modulus
    < 1; critical_type: how it leaves the unit circle when the orbit loses stability:
    ``"fold"`` (real, +1), ``"period_doubling"`` (real, −1), ``"neimark_sacker"`` (complex
    pair: a torus, quasi-periodic whirl). residuals: the shooting residual per Newton
    iteration, in units of length_scale_m (velocities: length_scale_m·ω).
    ``stats["newton_correction"]`` (shooting): the largest component of the Newton step the
    final, error-controlled monodromy gives at the converged start, same units — the
    estimated distance to the exact orbit (the residual test alone allows tol/|1 − μ|, large
    near a Hopf point); NaN for harmonic balance and continuation points. status ``"ok"`` or
    ``"not_converged"``/``"rub"``/``"error"`` (then no multipliers: arrays empty, stable
    False).
    """

    kind: str
    speed_hz: float
    chamber_pressure_pa: float
    config_ay_m: float
    period_s: float
    t: np.ndarray
    r: np.ndarray
    v: np.ndarray
    journal_x_m: np.ndarray
    journal_y_m: np.ndarray
    clearance_m: np.ndarray
    bearing_names: tuple
    monodromy: np.ndarray
    multipliers: np.ndarray
    trivial_index: int
    critical_index: int
    stable: bool
    critical_type: str
    residuals: np.ndarray
    length_scale_m: float
    stats: dict = field(default_factory=dict)
    status: str = "ok"
    message: str = ""

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @property
    def trivial_multiplier(self) -> complex | None:
        """The trivial multiplier (autonomous orbits), else None."""
        return complex(self.multipliers[self.trivial_index]) if self.trivial_index >= 0 else None

    @property
    def critical_multiplier(self) -> complex | None:
        return complex(self.multipliers[self.critical_index]) if self.critical_index >= 0 \
            else None

    @property
    def stability_resolved(self) -> bool:
        """False where the multipliers' own error estimate leaves the stable/unstable verdict
        undecided (harmonic balance, ``floquet="samples"``: the refinement did not converge
        within its budget, or | |μ_c| − 1 | ≤ ``stats["floquet_error"]``); True otherwise."""
        return bool(self.stats.get("floquet_resolved", True))

    def amplitude(self, bearing: int = 0) -> float:
        """Largest distance of the journal from the orbit's mean position, m. The samples
        close the period (the last repeats the first), so the mean is taken over one period
        without the repeated endpoint."""
        x = self.journal_x_m[:, bearing]
        y = self.journal_y_m[:, bearing]
        xm, ym = (x[:-1].mean(), y[:-1].mean()) if len(x) > 2 else (x.mean(), y.mean())
        return float(np.max(np.hypot(x - xm, y - ym)))

    def __repr__(self) -> str:
        head = (f"<PeriodicOrbitResult {self.status}: {self.kind}, {self.speed_hz:g} Hz, p_c = "
                f"{self.chamber_pressure_pa / 1e6:g} MPa")
        if not self.ok:
            return head + f": {self.message}>"
        mc = self.critical_multiplier
        err = self.stats.get("floquet_error")
        pm = "" if err is None else f" ± {err:.2g}"
        crit = "" if mc is None else (f", critical multiplier |μ| = {abs(mc):.4g}{pm} "
                                      f"({self.critical_type})")
        verdict = ("stable" if self.stable else "unstable") if self.stability_resolved \
            else "stability unresolved"
        amp = f", amplitude {self.amplitude() * 1e6:.4g} µm" if self.journal_x_m.shape[1] else ""
        return (head + f", period {self.period_s * 1e3:.5g} ms ({1 / self.period_s:.5g} Hz)"
                f"{amp}, {verdict}{crit}>")

    def to_frame(self) -> pd.DataFrame:
        """One row per (time, bearing) of the orbit, with the period and the stability
        (``stable`` is a verdict only where ``stability_resolved``: see that property)."""
        import pandas as pd
        nt, nb = self.journal_x_m.shape
        return pd.DataFrame({
            "t_s": np.repeat(self.t, nb),
            "bearing": np.tile(np.asarray(self.bearing_names, dtype=object), nt),
            "kind": self.kind,
            "speed_hz": self.speed_hz,
            "chamber_pressure_pa": self.chamber_pressure_pa,
            "config_ay_m": self.config_ay_m,
            "period_s": self.period_s,
            "journal_x_m": self.journal_x_m.ravel(),
            "journal_y_m": self.journal_y_m.ravel(),
            "stable": self.stable,
            "stability_resolved": self.stability_resolved,
            "status": self.status,
        })

    def multipliers_frame(self) -> pd.DataFrame:
        """One row per Floquet multiplier: real and imaginary parts, modulus, argument (rad),
        whether it is the trivial or the critical one."""
        import pandas as pd
        mu = np.asarray(self.multipliers, dtype=complex)
        i = np.arange(mu.size)
        return pd.DataFrame({
            "index": i, "real": mu.real, "imag": mu.imag, "modulus": np.abs(mu),
            "angle_rad": np.angle(mu), "trivial": i == self.trivial_index,
            "critical": i == self.critical_index,
        })

    def plot(self, bearing: int = 0, axes=None):
        """Two panels: the journal orbit in units of the clearance (with the clearance
        circle) and the Floquet multipliers in the complex plane with the unit circle.
        Returns the two Axes."""
        from matplotlib.lines import Line2D

        from rotordyn.plot._style import PAGE_IN, paper_style

        @paper_style
        def draw(axes):
            import matplotlib.pyplot as plt

            if axes is None:
                fig = plt.figure(figsize=(PAGE_IN, PAGE_IN * 0.45), layout="constrained")
                axes = fig.subplots(1, 2)
            ax, axm = axes
            th = np.linspace(0, 2 * np.pi, 200)
            if self.journal_x_m.shape[1]:
                c = self.clearance_m[bearing]
                ax.plot(np.cos(th), np.sin(th), "k-", lw=0.8)
                # no verdict (floquet "none", an unresolved estimate): neither blue nor red
                col, lab = (("tab:blue", "stable orbit") if self.stable else
                            ("tab:red", "unstable orbit")) if self.stability_resolved else \
                    ("tab:gray", "orbit (stability unresolved)")
                ax.plot(self.journal_x_m[:, bearing] / c, self.journal_y_m[:, bearing] / c,
                        color=col, lw=1.0)
                ax.set_aspect("equal")
                ax.set_xlabel("journal x / c (–), horizontal")
                ax.set_ylabel("journal y / c (–), vertical up")
                ax.set_title(f"{self.bearing_names[bearing]}: {self.kind} orbit, T = "
                             f"{self.period_s * 1e3:.4g} ms")
                ax.legend(handles=[
                    Line2D([], [], color="k", lw=0.8, label="clearance circle"),
                    Line2D([], [], color=col, label=lab)],
                    loc="lower left", fontsize=6)
            axm.plot(np.cos(th), np.sin(th), "k-", lw=0.8)
            mu = np.asarray(self.multipliers, dtype=complex)
            if mu.size:
                axm.plot(mu.real, mu.imag, "x", color="tab:blue", label="Floquet multipliers")
                if self.trivial_index >= 0:
                    m0 = mu[self.trivial_index]
                    axm.plot([m0.real], [m0.imag], "o", mfc="none", color="tab:green",
                             label="trivial (flow direction)")
                if self.critical_index >= 0:
                    mc = mu[self.critical_index]
                    axm.plot([mc.real], [mc.imag], "s", mfc="none", color="tab:red",
                             label=f"critical ({self.critical_type})")
                axm.legend(loc="lower left", fontsize=6)
            axm.set_aspect("equal")
            axm.set_xlabel("Re μ (–)")
            axm.set_ylabel("Im μ (–)")
            axm.set_title("Floquet multipliers and the unit circle")
            return ax, axm

        return draw(axes)
