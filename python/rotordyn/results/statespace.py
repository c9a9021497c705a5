"""Linear state-space model for control-law synthesis (paper eq. 19)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

from rotordyn.results.stability import LinearModel
from rotordyn.units import unit_of

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class StateSpaceResult(Display):
    """ẋ = A x + B u, y = C x + D u with x = [Δr; Δṙ] about the equilibrium.

    A (2n, 2n), B (2n, n_u), C (n_y, 2n), D (n_y, n_u), SI units: inputs in Pa (chamber
    pressure fluctuation ΔC of eq. 11) or N (forces), outputs in m or m/s.
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    input_names: tuple
    output_names: tuple
    state_names: tuple
    linear: LinearModel

    def __repr__(self) -> str:
        def names(t):
            return ", ".join(map(str, t[:4])) + (", …" if len(t) > 4 else "")

        return (f"<StateSpaceResult {self.A.shape[0]} states, {self.B.shape[1]} inputs "
                f"({names(self.input_names)}), {self.C.shape[0]} outputs "
                f"({names(self.output_names)}); at {self.linear.speed_hz:g} Hz, "
                f"max Re pole {np.max(self.poles.real):.3g} 1/s>")

    @property
    def poles(self) -> np.ndarray:
        return np.linalg.eigvals(self.A)

    def frequency_response(self, freqs_hz) -> np.ndarray:
        """G(iω) = C (iωI − A)⁻¹ B + D at each frequency, (n_f, n_y, n_u) complex."""
        f = np.atleast_1d(np.asarray(freqs_hz, dtype=float))
        n = self.A.shape[0]
        out = np.empty((f.size, self.C.shape[0], self.B.shape[1]), dtype=complex)
        for i, fi in enumerate(f):
            out[i] = self.C @ np.linalg.solve(2j * np.pi * fi * np.eye(n) - self.A, self.B) + self.D
        return out

    def plot(self, freqs_hz=None, ax=None):
        """Magnitude of every input-to-output frequency response |G(i2πf)| against f (log-log),
        in the outputs' unit per the inputs' unit (m/Pa, m/N, …)."""
        from rotordyn.plot._style import COLUMN_IN, new_axes, paper_style

        f = np.geomspace(1.0, 1000.0, 400) if freqs_hz is None else np.asarray(freqs_hz, float)

        @paper_style
        def draw(ax):
            ax = new_axes(ax, width=COLUMN_IN * 1.3, aspect=0.7)
            G = self.frequency_response(f)
            for i, yn in enumerate(self.output_names):
                for j, un in enumerate(self.input_names):
                    uu = "Pa" if "pressure" in str(un) else "N"
                    yu = "m/s" if "vel" in str(yn) or str(yn).startswith("v") else "m"
                    ax.loglog(f, np.abs(G[:, i, j]), label=f"{un} → {yn} ({yu}/{uu})")
            ax.set_xlabel("frequency (Hz)")
            ax.set_ylabel("|G(i2πf)| (output unit / input unit)")
            ax.set_title(f"linear model at {self.linear.speed_hz:g} Hz")
            ax.legend(loc="best", fontsize=6)
            return ax

        return draw(ax)

    def to_control(self, *, balanced: bool = True):
        """A python-control ``StateSpace`` (needs the optional ``control`` package).
        ``balanced`` (default): states scaled by powers of two (exact; each state's name
        carries its ``·2^-e``, :mod:`rotordyn._common.balance`), so python-control evaluates
        it to round-off with or without slycot; the transfer function is the same."""
        try:
            import control
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise ImportError("to_control() needs python-control: pip install control") from exc
        from rotordyn._common import validate as v
        from rotordyn._common.balance import scaled, scaled_state_names, state_scaling

        v.boolean("balanced", balanced)
        A, B, C, names = self.A, self.B, self.C, list(self.state_names)
        if balanced:
            t = state_scaling(A, B, C)
            A, B, C = scaled(A, B, C, t)
            names = scaled_state_names(names, t)
        return control.ss(A, B, C, self.D, inputs=list(self.input_names),
                          outputs=list(self.output_names), states=names)

    def to_frame(self) -> pd.DataFrame:
        """The matrices as a tidy table (matrix, row, col, value, unit): ``unit`` is the
        entry's own (the value column mixes them): A and B map to the derivative of the row's
        state (its unit per second), C and D to the row's output, per unit of the column's
        state or input, e.g. ``(m/s)/(N)``."""
        import pandas as pd
        rows = []
        for name, M, rn, cn in (("A", self.A, self.state_names, self.state_names),
                                ("B", self.B, self.state_names, self.input_names),
                                ("C", self.C, self.output_names, self.state_names),
                                ("D", self.D, self.output_names, self.input_names)):
            ru = [coordinate_unit(r) + ("/s" if name in "AB" else "") for r in rn]
            cu = [coordinate_unit(c) for c in cn]
            for i in range(M.shape[0]):
                for j in range(M.shape[1]):
                    rows.append((name, rn[i], cn[j], M[i, j], f"({ru[i]})/({cu[j]})"))
        return pd.DataFrame(rows, columns=["matrix", "row", "col", "value", "unit"])


def coordinate_unit(name: str) -> str:
    """The unit of a state, input or output name: a coordinate label (``station2.x`` m,
    ``station2.rot_x`` rad, ``<bearing>.sleeve1`` m, ``<bearing>.pad0.eta`` m, ``cb_mode1``
    modal, 1), its rate ``d(…)/dt`` (that unit per second), or a suffixed name
    (``force_x_n[4]`` N, ``velocity_x_m_s[4]`` m/s)."""
    if name.startswith("d(") and name.endswith(")/dt"):
        inner = coordinate_unit(name[2:-4])
        return "1/s" if inner == "1" else f"{inner}/s"
    base = name.split("[")[0]
    if unit_of(base) != "1":
        return unit_of(base)
    last = name.rsplit(".", 1)[-1]
    if last.startswith("rot_"):
        return "rad"
    if last in ("x", "y", "eta", "pivot") or last.startswith("sleeve"):
        return "m"
    return "1"
