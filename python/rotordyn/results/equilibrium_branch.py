"""A branch of static equilibria of eq. 12 continued over one parameter (pseudo-arclength),
with the linearised stability of every point and the Hopf points and folds on it: the data of
a bifurcation diagram of the equilibria (the companion of :class:`BranchResult`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display
from rotordyn.results.continuation import parameter_units
from rotordyn.results.modes import mode_stable, point_stable

if TYPE_CHECKING:
    import pandas as pd

EQUILIBRIUM_BIFURCATIONS = ("hopf", "fold", "branch_point")


@dataclass(frozen=True)
class EquilibriumBranchResult(Display):
    """A branch of static equilibria over the parameter ``vary``.

    parameter: (n_points,) in the SI unit of ``vary``; r: (n_points, n) every coordinate;
    journal_x_m, journal_y_m, eccentricity_ratio, h_min_m: (n_points, n_bearings) relative to
    each housing (as :class:`EquilibriumResult`); max_real_1_per_s, freq_hz: (n_points,) the
    least-damped eigenvalue of eq. 19 (its real part and damped frequency); n_unstable:
    (n_points,) eigenvalues with Re λ > 0 beyond round-off; stable: (n_points,) bool (every
    root ``mode_stable``, the round-off band of ``rotordyn.results.modes.ROUND_OFF_REL``);
    arclength, tangent_p: (n_points,) the scaled arclength s and dp/ds; point_status:
    (n_points,) each equilibrium's status (``ok`` or ``contact``: only converged points are on
    the branch). bifurcations: one dict per event between two successive points — ``kind``
    (``hopf``: a complex pair through the imaginary axis; ``fold``: a real eigenvalue through
    zero with the parameter turning back; ``branch_point``: a real eigenvalue through zero
    without a turn), ``index`` (the point after it), ``parameter``, ``r`` (n,) the state
    there, ``eigenvalue`` (the crossing one, 1/s), ``whirl_frequency_hz`` (Hopf),
    ``refined`` (located by Brent's method on the arclength; else linear interpolation of the
    indicator), ``smooth`` (False: the indicator — the crossing pair's Re λ, or the signed
    smallest singular value of K + K_H — jumps through zero there instead of crossing it, a
    change of a cavitated set; then ``jump`` = (value before, value after)) and ``message``. equilibria: every point's EquilibriumResult. stop: why the
    branch ended (``bound``, ``max_points``, ``step_min``, or a failed equilibrium's status);
    message: the last corrector failure, if any.
    """

    vary: str
    parameter: np.ndarray
    r: np.ndarray
    journal_x_m: np.ndarray
    journal_y_m: np.ndarray
    eccentricity_ratio: np.ndarray
    h_min_m: np.ndarray
    max_real_1_per_s: np.ndarray
    freq_hz: np.ndarray
    n_unstable: np.ndarray
    stable: np.ndarray
    arclength: np.ndarray
    tangent_p: np.ndarray
    point_status: tuple
    bearing_names: tuple
    clearance_m: np.ndarray
    bifurcations: tuple
    equilibria: tuple = ()
    fixed: dict = field(default_factory=dict)
    bounds: tuple = (np.nan, np.nan)
    stop: str = ""
    message: str = ""
    stats: dict = field(default_factory=dict)
    status: str = "ok"
    kind: str = "equilibrium"
    journal_index: tuple = ()  # (jx, jy) of each bearing's journal in r

    @classmethod
    def failed(cls, status, message, *, vary, bounds, fixed, bearing_names, clearance_m,
               stats=None, journal_index=()):
        nb = len(bearing_names)
        z = np.zeros((0, nb))
        return cls(vary=vary, parameter=np.zeros(0), r=np.zeros((0, 0)), journal_x_m=z,
                   journal_y_m=z, eccentricity_ratio=z, h_min_m=z,
                   max_real_1_per_s=np.zeros(0), freq_hz=np.zeros(0),
                   n_unstable=np.zeros(0, np.int64), stable=np.zeros(0, bool),
                   arclength=np.zeros(0), tangent_p=np.zeros(0), point_status=(),
                   bearing_names=bearing_names, clearance_m=clearance_m, bifurcations=(),
                   fixed=fixed, bounds=bounds, stop="start", message=message,
                   stats=stats or {}, status=status)

    @classmethod
    def from_points(cls, pts, bifurcations, *, vary, bounds, fixed, bearing_names,
                    clearance_m, stop, message, stats, journal_index=()):
        es = [q["e"] for q in pts]
        lam = [q["lam"] for q in pts]
        imax = [int(np.argmax(x.real)) for x in lam]
        return cls(
            vary=vary, parameter=np.array([q["p"] for q in pts]),
            r=np.array([np.asarray(e.r) for e in es]),
            journal_x_m=np.array([e.journal_x_m for e in es]),
            journal_y_m=np.array([e.journal_y_m for e in es]),
            eccentricity_ratio=np.array([e.eccentricity_ratio for e in es]),
            h_min_m=np.array([e.h_min_m for e in es]),
            max_real_1_per_s=np.array([float(x[i].real) for x, i in zip(lam, imax)]),
            freq_hz=np.array([abs(float(x[i].imag)) / (2 * np.pi) for x, i in zip(lam, imax)]),
            n_unstable=np.array([int(np.sum(~mode_stable(x))) for x in lam], dtype=np.int64),
            stable=np.array([point_stable(x) for x in lam], dtype=bool),
            arclength=np.array([q["s"] for q in pts]),
            tangent_p=np.array([q["t"][-1] for q in pts]),
            point_status=tuple(e.status for e in es), bearing_names=bearing_names,
            clearance_m=clearance_m, bifurcations=tuple(bifurcations), equilibria=tuple(es),
            fixed=fixed, bounds=bounds, stop=stop, message=message, stats=stats,
            journal_index=tuple(journal_index))

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def __len__(self) -> int:
        return int(self.parameter.size)

    def hopf_points(self) -> list:
        """The parameter values of the Hopf points on the branch (unit of vary)."""
        return [b["parameter"] for b in self.bifurcations if b["kind"] == "hopf"]

    def __repr__(self) -> str:
        u, sym, f, disp = parameter_units(self.vary)
        head = f"<EquilibriumBranchResult {self.status}: equilibria over {self.vary}"
        if not len(self):
            return head + f", no points: {self.message}>"
        p = self.parameter * f
        e = self.eccentricity_ratio[:, 0]
        bif = ", ".join(f"{b['kind']}{'' if b.get('smooth', True) else ' (non-smooth)'} at "
                        f"{sym} = {b['parameter'] * f:.6g} {disp}"
                        for b in self.bifurcations) or "no bifurcation"
        return (f"{head}, {len(self)} points, {sym} {p[0]:.5g} → {p[-1]:.5g} {disp}, "
                f"e/c {e[0]:.4g} → {e[-1]:.4g} ({self.bearing_names[0]}), "
                f"{int(np.sum(self.stable))} stable; {bif}; stop: {self.stop}>")

    def to_frame(self) -> pd.DataFrame:
        """One row per (branch point, bearing): point, bearing, the parameter (column named by
        ``vary``, SI), journal_x_m, journal_y_m, eccentricity_ratio, h_min_m,
        max_real_1_per_s, freq_hz (the least-damped eigenvalue), n_unstable, stable,
        arclength, tangent_p, bifurcation (kinds detected just before this point, else ""),
        status."""
        import pandas as pd
        npt, nb = len(self), len(self.bearing_names)
        bif = [""] * npt
        for b in self.bifurcations:
            i = b["index"]
            bif[i] = (bif[i] + "," if bif[i] else "") + b["kind"]
        rep = lambda x: np.repeat(np.asarray(x), nb)  # noqa: E731
        return pd.DataFrame({
            "point": rep(np.arange(npt)),
            "bearing": np.tile(np.asarray(self.bearing_names, dtype=object), npt),
            self.vary: rep(self.parameter),
            "journal_x_m": self.journal_x_m.ravel(),
            "journal_y_m": self.journal_y_m.ravel(),
            "eccentricity_ratio": self.eccentricity_ratio.ravel(),
            "h_min_m": self.h_min_m.ravel(),
            "max_real_1_per_s": rep(self.max_real_1_per_s),
            "freq_hz": rep(self.freq_hz),
            "n_unstable": rep(self.n_unstable),
            "stable": rep(self.stable),
            "arclength": rep(self.arclength),
            "tangent_p": rep(self.tangent_p),
            "bifurcation": np.repeat(np.asarray(bif, dtype=object), nb),
            "status": np.repeat(np.asarray(self.point_status, dtype=object), nb),
        })

    def bifurcations_frame(self) -> pd.DataFrame:
        """One row per (bifurcation, bearing): kind, index, the parameter (SI), bearing,
        eccentricity_ratio there, eigenvalue_real_1_per_s, eigenvalue_imag_1_per_s,
        whirl_frequency_hz, refined, message."""
        import pandas as pd
        cols = ["kind", "index", self.vary, "bearing", "eccentricity_ratio",
                "eigenvalue_real_1_per_s", "eigenvalue_imag_1_per_s", "whirl_frequency_hz",
                "refined", "smooth", "message"]
        rows = []
        jx = self._journal_index()
        for b in self.bifurcations:
            for k, name in enumerate(self.bearing_names):
                ecc = (float(np.hypot(b["r"][jx[k][0]], b["r"][jx[k][1]]) / self.clearance_m[k])
                       if jx else np.nan)
                rows.append({"kind": b["kind"], "index": b["index"],
                             self.vary: b["parameter"], "bearing": name,
                             "eccentricity_ratio": ecc,
                             "eigenvalue_real_1_per_s": b["eigenvalue"].real,
                             "eigenvalue_imag_1_per_s": b["eigenvalue"].imag,
                             "whirl_frequency_hz": b["whirl_frequency_hz"],
                             "refined": b["refined"], "smooth": b.get("smooth", True),
                             "message": b["message"]})
        return pd.DataFrame(rows, columns=cols)

    def _journal_index(self) -> list:
        return list(self.journal_index)

    def eccentricity_at(self, bif: dict, bearing: int = 0) -> float:
        """The journal eccentricity ratio of ``bearing`` at bifurcation ``bif``."""
        jx, jy = self._journal_index()[bearing]
        return float(np.hypot(bif["r"][jx], bif["r"][jy]) / self.clearance_m[bearing])

    def plot(self, bearing: int = 0, ax=None):
        """Bifurcation diagram: the journal's eccentricity ratio e/c against the parameter,
        stable equilibria solid, unstable dashed, Hopf points (star) and folds (circle)
        marked. Returns the Axes."""
        from matplotlib.lines import Line2D

        from rotordyn.plot._style import PAGE_IN, paper_style, stability_segments

        u, sym, f, disp = parameter_units(self.vary)
        marks = {"hopf": ("*", "k"), "fold": ("o", "tab:red"),
                 "branch_point": ("^", "tab:orange")}

        @paper_style
        def draw(ax):
            import matplotlib.pyplot as plt

            if ax is None:
                _, ax = plt.subplots(figsize=(PAGE_IN * 0.6, PAGE_IN * 0.45),
                                     layout="constrained")
            p = self.parameter * f
            e = self.eccentricity_ratio[:, bearing] if len(self) else np.zeros(0)
            handles = stability_segments(ax, p, e, self.stable, "equilibria")
            seen = set()
            for b in self.bifurcations:
                mk, col = marks[b["kind"]]
                ax.plot([b["parameter"] * f], [self.eccentricity_at(b, bearing)], mk,
                        color=col, mfc="none", ms=8)
                if b["kind"] not in seen:
                    seen.add(b["kind"])
                    handles.append(Line2D([], [], color=col, marker=mk, mfc="none", ls="",
                                          label=b["kind"].replace("_", " ")))
            ax.set_xlabel(f"{sym} ({disp})" if disp else sym)
            ax.set_ylabel(f"{self.bearing_names[bearing]}: eccentricity ratio e/c (–)")
            ax.set_title(f"equilibria over {sym}")
            ax.legend(handles=handles, fontsize=6)
            return ax

        return draw(ax)
