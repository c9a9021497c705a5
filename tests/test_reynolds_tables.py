"""Reynolds solver against published design tables (reference tier c).

Sources
-------
* A. A. Raimondi & J. Boyd, "A solution for the finite journal bearing and its application to
  analysis and design", ASLE Trans. 1 (1958) 159–209 (tabulated in Hamrock, *Fundamentals of
  Fluid Film Lubrication*, and Shigley's *Mechanical Engineering Design*, ch. 12): 360° bearing,
  supply line (p = 0) at the maximum film thickness, Reynolds (Swift–Stieber) condition at
  rupture. Sommerfeld number S = μNLD/W·(R/c)² and attitude angle vs ε.
  Tolerance: 2 % on S and 1° on the attitude (the issue's requirement; R&B solved a relaxation
  grid by hand-checked digital computation, and our 144×32 grid is converged to < 0.5 % for
  ε ≤ 0.9). At ε = 0.97 the film is 3 % of the clearance at its thinnest and the error is
  dominated by the grid: there we use 1152×64 (converged values: +1.1 % at L/D = 1 and +1.9 %
  at L/D = 1/2 from the table, i.e. just inside the 2 %).
* J. W. Lund & K. K. Thomsen, "A calculation method and data for the dynamic coefficients of
  oil-lubricated journal bearings", ASME Topics in Fluid Film Bearing and Rotor Bearing System
  Design and Optimization (1978) 1–28: two axial grooves of 20° at the horizontal split, load
  vertical between them, L/D = 1, Reynolds boundary conditions. Table frame: x down (load),
  y horizontal, rotation from x to y; K = kc/W, B = bcω/W. Converted to the DESIGN frame
  (u = y_table, v = −x_table): K_table = [[K_vv, −K_vu], [−K_uv, K_uu]].
  Tolerance: 5 % of each coefficient (the issue's requirement) plus 0.02 absolute, because the
  table prints two decimals and the cross-coupled Kyx is small (|Kyx| ≤ 0.5 at ε ≥ 0.56, where
  5 % is below the printed precision). Eccentricity within 1 % + 0.002, attitude within 1°.
  L/D = 0.5 is not tested: we have no tabulated values we could cite for it.
"""

import math

import numpy as np
import pytest

import rotordyn

D, C_RAD, MU, N_HZ = 0.05, 1e-4, 0.02, 20.0
R = D / 2

# (eps, S, attitude deg) for L/D = 1 and 1/2
RAIMONDI_BOYD = {
    1.0: [(0.1, 1.33, 79.5), (0.2, 0.631, 74.02), (0.4, 0.264, 63.10), (0.6, 0.121, 50.58),
          (0.8, 0.0446, 36.24), (0.9, 0.0188, 26.45), (0.97, 0.00474, 15.47)],
    0.5: [(0.1, 4.31, 81.62), (0.2, 2.03, 74.94), (0.4, 0.779, 61.45), (0.6, 0.319, 48.14),
          (0.8, 0.0923, 33.31), (0.9, 0.0313, 23.66), (0.97, 0.00609, 13.75)],
}


@pytest.mark.parametrize("ld", [1.0, 0.5])
def test_raimondi_boyd_full_bearing(ld):
    L = ld * D
    for eps, s_ref, att_ref in RAIMONDI_BOYD[ld]:
        n_circ, n_axial = (1152, 64) if eps > 0.95 else (144, 32)
        b = rotordyn.JournalBearing(
            diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
            n_circ=n_circ, n_axial=n_axial, cavitation="reynolds",
            grooves=[rotordyn.Groove(90.0, 0.0, 0.0)],  # supply line at h_max for y < 0, x = 0
        )
        f = b.forces(x_m=0.0, y_m=-eps * C_RAD, speed_hz=N_HZ)
        W = float(np.linalg.norm(f))
        load = -f / W  # the load balancing the film force
        e = np.array([0.0, -1.0])  # line of centres
        att = math.degrees(math.atan2(load[0] * e[1] - load[1] * e[0], load @ e))
        S = MU * N_HZ * L * D / W * (R / C_RAD) ** 2
        assert S == pytest.approx(s_ref, rel=0.02), (eps, S, s_ref)
        assert att == pytest.approx(att_ref, abs=1.0), (eps, att, att_ref)


# S, eps, attitude, Kxx, Kxy, Kyx, Kyy, Bxx, Bxy=Byx, Byy (table frame)
LUND_THOMSEN_LD1 = [
    (0.991, 0.150, 70.58, 1.56, 7.29, -2.16, 1.52, 14.66, 1.58, 4.49),
    (0.635, 0.224, 63.54, 1.62, 5.33, -1.57, 1.56, 10.80, 1.70, 3.41),
    (0.235, 0.460, 49.27, 2.19, 3.57, -0.80, 1.55, 7.36, 1.89, 2.19),
    (0.159, 0.559, 44.33, 2.73, 3.36, -0.48, 1.48, 6.94, 1.78, 1.74),
    (0.108, 0.650, 39.72, 3.45, 3.34, -0.23, 1.44, 6.89, 1.72, 1.43),
]


def test_lund_thomsen_two_axial_groove_ld1():
    L = D
    omega = 2 * math.pi * N_HZ
    b = rotordyn.JournalBearing(
        diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
        n_circ=144, n_axial=32, cavitation="reynolds",
        grooves=[rotordyn.Groove(0.0, 20.0, 0.0), rotordyn.Groove(180.0, 20.0, 0.0)],
    )
    for S, eps, att, kxx, kxy, kyx, kyy, bxx, bxy, byy in LUND_THOMSEN_LD1:
        W = MU * N_HZ * L * D * (R / C_RAD) ** 2 / S
        eq = b.static_equilibrium(load_n=(0.0, -W), speed_hz=N_HZ)
        assert eq.eccentricity_ratio == pytest.approx(eps, rel=0.01, abs=0.002)
        assert eq.attitude_angle_deg == pytest.approx(att, abs=1.0)
        K, C = b.coefficients(x_m=eq.x_m, y_m=eq.y_m, speed_hz=N_HZ)
        k_tab = np.array([[K[1, 1], -K[1, 0]], [-K[0, 1], K[0, 0]]]) * C_RAD / W
        b_tab = np.array([[C[1, 1], -C[1, 0]], [-C[0, 1], C[0, 0]]]) * C_RAD * omega / W
        k_ref = np.array([[kxx, kxy], [kyx, kyy]])
        b_ref = np.array([[bxx, bxy], [bxy, byy]])
        assert np.all(np.abs(k_tab - k_ref) <= 0.05 * np.abs(k_ref) + 0.02), (S, k_tab, k_ref)
        assert np.all(np.abs(b_tab - b_ref) <= 0.05 * np.abs(b_ref) + 0.02), (S, b_tab, b_ref)
