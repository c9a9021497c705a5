"""The plain journal bearing's result records (:mod:`rotordyn.bearings.journal`): one Reynolds
solve, the pressure field on the film grid and the static equilibrium of a rigid journal."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class FilmResult:
    """Outputs of one Reynolds solve (SI units)."""

    force_n: np.ndarray
    friction_torque_n_m: float
    inlet_flow_m3_s: float
    side_flow_m3_s: float
    h_min_m: float
    h_min_angle_deg: float
    iterations: int
    # jfo films (docs/film-physics.md, "A starved film"): the grooves' inlet fill θ_in (1: a
    # full film at the groove), the fraction of the grooves' pressure_pa they hold (1
    # flooded), whether a metered supply starved the film, and the angle (deg) where the
    # full film starts downstream of the first groove (NaN: not jfo, or none)
    inlet_fill: float = 1.0
    groove_pressure_factor: float = 1.0
    starved: bool = False
    full_film_start_deg: float = float("nan")


@dataclass(frozen=True, slots=True)
class PressureField:
    """Pressure on the film grid: ``p_pa[j, k]`` at ``phi_rad[j]``, ``z_m[k]`` (k=0, -1: ends)."""

    phi_rad: np.ndarray
    z_m: np.ndarray
    p_pa: np.ndarray
    h_m: np.ndarray
    theta: np.ndarray
    force_n: np.ndarray

    def to_frame(self):
        import pandas as pd

        phi, z = np.meshgrid(self.phi_rad, self.z_m, indexing="ij")
        return pd.DataFrame(
            {
                "phi_rad": phi.ravel(),
                "z_m": z.ravel(),
                "p_pa": self.p_pa.ravel(),
                "h_m": self.h_m.ravel(),
                "theta": self.theta.ravel(),
            }
        )


@dataclass(frozen=True, slots=True)
class BearingEquilibrium:
    """Static equilibrium of a rigid journal: film force + load = 0.

    ``sommerfeld`` is S = μ N L D / W · (R/c)² with N = |speed_hz| (rev/s); the attitude angle
    is the angle from the load line to the line of centres, positive in the rotation sense.
    """

    x_m: float
    y_m: float
    eccentricity_ratio: float
    attitude_angle_deg: float
    sommerfeld: float
    load_n: tuple[float, float]
    speed_hz: float
    force_n: np.ndarray
    residual_rel: float
    iterations: int
    status: str = "ok"
    message: str = ""

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame(
            [
                {
                    "speed_hz": self.speed_hz,
                    "load_x_n": self.load_n[0],
                    "load_y_n": self.load_n[1],
                    "journal_x_m": self.x_m,
                    "journal_y_m": self.y_m,
                    "eccentricity_ratio": self.eccentricity_ratio,
                    "attitude_angle_deg": self.attitude_angle_deg,
                    "sommerfeld": self.sommerfeld,
                    "residual_rel": self.residual_rel,
                    "status": self.status,
                    "message": self.message,
                }
            ]
        )


__all__ = ["BearingEquilibrium", "FilmResult", "PressureField"]
