"""Aerodynamic stages (impellers, blade rows) for API 617's Level I stability analysis: the
anticipated cross-coupled stiffness q_A of each stage.

Source: API Standard 617, 8th ed. (2014), Part 1 §4.8.5 (Level I), and API Standard 684, 2nd
ed. (2005), §2.9 (the same formulas, the "modified Alford" or Wachel form):

    centrifugal stage:  q_A = B_c · C · P · (ρ_d/ρ_s) / (D_c · H_c · N),   B_c = 3
    axial stage:        q_A = B_t · C · P / (D_t · H_t · N),               B_t = 1.5

with C = 9.55 = 60/(2π) (rev/min per rad/s: C·P/N is the stage torque P/Ω). Units here
(consistent SI): P the stage's rated power in W, D_c the impeller diameter (axial: blade pitch
diameter D_t) in m, H_c the smaller of the diffuser width and the impeller discharge width
(axial: effective blade height H_t) in m, N the speed in rev/min, ρ_d/ρ_s the stage's discharge
over suction gas density; q_A in N/m. (The standard's US-unit form takes C = 63, P in hp, D and
H in inches and gives klbf/in; the same torque over D·H.) Q_A is the sum over the stages. (The formulas are the published ones; the clause
numbers are as recalled, not checked against the standards' text: docs/api-criteria.md.)
"""

from __future__ import annotations

from dataclasses import dataclass

from rotordyn._common import validate as v
from rotordyn.errors import InputError

STAGE_TYPES = ("centrifugal", "axial")
B_FACTOR = {"centrifugal": 3.0, "axial": 1.5}  # API 617: B_c = 3, B_t = 1.5
C_FACTOR = 9.55  # API 617: C = 9.55 (SI form), rev/min per rad/s


@dataclass(frozen=True, slots=True)
class Stage:
    """One impeller (``type="centrifugal"``) or blade row (``"axial"``) at a rotor station.

    power_w: rated power of the stage, W (> 0). diameter_m: impeller diameter D_c (axial: blade
    pitch diameter D_t), m. height_m: the smaller of the diffuser and impeller discharge widths
    H_c (axial: effective blade height H_t), m (< diameter). density_ratio: ρ_discharge /
    ρ_suction of the stage, in [1, 100] (centrifugal only: the axial formula has none).
    """

    station: int
    power_w: float
    diameter_m: float
    height_m: float
    density_ratio: float | None = None
    type: str = "centrifugal"
    name: str = ""

    def check(self, where: str, n_stations: int) -> None:
        v.integer(f"{where}.station", self.station, lo=0, hi=n_stations - 1)
        v.choice(f"{where}.type", self.type, STAGE_TYPES)
        v.text(f"{where}.name", self.name)
        v.in_range(f"{where}.power_w", self.power_w, 0.0, 1e10, lo_open=True)
        v.in_range(f"{where}.diameter_m", self.diameter_m, 0.0, 10.0, lo_open=True)
        v.in_range(f"{where}.height_m", self.height_m, 0.0, self.diameter_m, lo_open=True)
        if self.type == "centrifugal":
            if self.density_ratio is None:
                raise InputError(f"{where}.density_ratio: a centrifugal stage needs its "
                                 "discharge/suction gas density ratio (in [1, 100])")
            v.in_range(f"{where}.density_ratio", self.density_ratio, 1.0, 100.0)
        elif self.density_ratio is not None:
            raise InputError(f"{where}.density_ratio: an axial stage takes none (API 617's "
                             f"axial formula has no density ratio), got {self.density_ratio!r}")

    def cross_coupling_n_per_m(self, speed_hz: float) -> float:
        """q_A of this stage at ``speed_hz`` (N = 60·speed_hz rev/min), N/m."""
        rpm = 60.0 * v.positive("speed_hz", speed_hz)
        ratio = self.density_ratio if self.type == "centrifugal" else 1.0
        return (B_FACTOR[self.type] * C_FACTOR * self.power_w * ratio
                / (self.diameter_m * self.height_m * rpm))
