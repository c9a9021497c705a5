"""Static analysis: deflection, shear force and bending moment along the rotor and the reaction
at every support and bearing, at the system's equilibrium (ROSS's ``run_static``; for the
paper's statically indeterminate rotor, how the load is shared between the bearings for a
given configuration vector a)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn.results._display import Display

from rotordyn._common.status import CONVERGED

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class StaticResult(Display):
    """Static state of the rotor (DESIGN frame: x horizontal, y up, gravity along −y).

    node_positions_m (n_nodes,); deflection_x_m, deflection_y_m (n_nodes,): absolute
    displacement of every FE node (for a journal: its position relative to the housing plus
    the housing offset a). Internal forces at both ends of every element, at
    ``section_positions_m`` (2 n_elements,) = (z_left, z_right) per element:
    ``shear_x_n``/``shear_y_n`` the resultant of all external forces (gravity, reactions)
    acting on the rotor left of the section; ``moment_yz_n_m`` the bending moment in the vertical
    (y–z) plane of those forces about the section, sagging positive (a beam on two supports
    under its weight has M > 0), ``moment_xz_n_m`` likewise in the horizontal plane.
    reactions: one row per support and bearing element (``name``, ``station``, ``kind``,
    ``force_x_n``, ``force_y_n``: the force it exerts on the rotor, N; with a tilting film,
    ``tilt = true``, also ``film_moment_x_n_m``, ``film_moment_y_n_m``: the film's moment on the
    journal about x and y, N·m, NaN for the other rows). ``weight_n``: the rotor's weight;
    the reactions' y-sum balances it.
    """

    speed_hz: float
    node_positions_m: np.ndarray
    deflection_x_m: np.ndarray
    deflection_y_m: np.ndarray
    section_positions_m: np.ndarray
    shear_x_n: np.ndarray
    shear_y_n: np.ndarray
    moment_xz_n_m: np.ndarray
    moment_yz_n_m: np.ndarray
    reactions: pd.DataFrame
    weight_n: float
    status: str = "ok"
    message: str = ""

    @property
    def converged(self) -> bool:
        return self.status in CONVERGED

    def __repr__(self) -> str:
        if not self.converged:
            return f"<StaticResult {self.status}: {self.message}>"
        k = int(np.argmax(np.abs(self.deflection_y_m)))
        j = int(np.argmax(np.abs(self.moment_yz_n_m)))
        share = ", ".join(f"{r.name or r.kind} {r.force_y_n:.4g} N"
                          for r in self.reactions.itertuples())
        return (f"<StaticResult at {self.speed_hz:g} Hz: weight {self.weight_n:.4g} N carried by "
                f"{share}; largest deflection {self.deflection_y_m[k] * 1e6:.4g} µm at z = "
                f"{self.node_positions_m[k]:.4g} m, largest moment {self.moment_yz_n_m[j]:.4g} "
                f"N·m at z = {self.section_positions_m[j]:.4g} m>")

    def to_frame(self) -> pd.DataFrame:
        """One row per element end: z, side, the deflection there, shear and moment."""
        import pandas as pd
        z = self.section_positions_m
        defl_x = np.interp(z, self.node_positions_m, self.deflection_x_m)
        defl_y = np.interp(z, self.node_positions_m, self.deflection_y_m)
        n = z.size
        return pd.DataFrame({
            "z_m": z, "side": np.tile(["left", "right"], n // 2),
            "deflection_x_m": defl_x, "deflection_y_m": defl_y,
            "shear_x_n": self.shear_x_n, "shear_y_n": self.shear_y_n,
            "moment_xz_n_m": self.moment_xz_n_m, "moment_yz_n_m": self.moment_yz_n_m,
            "status": [self.status] * n,
        })

    def plot(self, axes=None, system=None):
        """Deflection, shear force and bending moment along the rotor, the reactions marked;
        returns the three Axes."""
        from rotordyn.plot.static import static_diagram

        return static_diagram(self, axes=axes, system=system)
