"""The THD pads' passed-on flow and outlet temperature against ROSS 2.3 (docs/film-physics.md,
"THD pad bearings", side by side with ROSS): ROSS's `TiltingPad` example (the case of
tests/test_film_thd_pads.py::test_thd_tilting_pad_against_ross, 12 × 12 volumes per pad,
carry-over 0) and ours under the load ROSS's film carries, with ROSS's oil law: per pad the
outlet temperature and the flow passed on to the next pad over the pad's inflow (ROSS: the
flow at the pad's minimum-film column over the flow at its leading edge; ours: Q_in − Q_s
over Q_in). Needs ROSS (the rossvenv):

    PYTHONPATH=python /work/wt/rossvenv/bin/python docs/calibration/thd_pads_outlet_vs_ross.py
"""

import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests"))

from rotordyn.bearings import Oil, TiltingPadBearing  # noqa: E402


def main():
    import ross
    from test_film_thd_pads import _ross_example
    rb = _ross_example(ross, 12)
    f = np.array([float(np.ravel(rb.force_x_total_list[-1])[0]),
                  float(np.ravel(rb.force_y_total_list[-1])[0])])
    a, b = float(rb.a_a), float(rb.b_b)
    oil = Oil(viscosity_law="exponential", mu_ref_pa_s=a * np.exp(b * 40.0), t_ref_c=40.0,
              beta_1_per_k=-b, density_kg_m3=float(rb.rho),
              specific_heat_j_per_kg_k=float(rb.cp))
    tp = TiltingPadBearing(station=0, diameter_m=101.6e-3, length_m=50.8e-3,
                           clearance_m=74.9e-6, viscosity_pa_s=oil.viscosity_pa_s(40.0),
                           n_pads=5, pad_arc_deg=60.0, pivot_offset=0.5, preload=0.5,
                           orientation_deg=18.0, pad_thickness_m=12.7e-3, n_circ=72, n_axial=12)
    res = tp.thermal_equilibrium(load_n=-f, speed_hz=50.0, oil=oil, supply_temperature_c=40.0,
                                 carry_over=0.0)
    t_ross = np.asarray(rb.T_outlet, float)
    fmt = lambda v: ", ".join(f"{x:.3f}" for x in v)  # noqa: E731
    print(f"ROSS T_out {fmt(t_ross)}; Q_out/Q_in "
          f"{fmt(np.asarray(rb.Q_outlet, float) / np.asarray(rb.Q_inlet, float))}")
    print(f"ours T_out {fmt(res.outlet_temperature_c)}; Q_out/Q_in "
          f"{fmt(res.outlet_flow_m3_s / res.film_flow_m3_s)}")
    d = res.outlet_temperature_c - t_ross
    print(f"max |T_out - T_out(ROSS)| {np.max(np.abs(d)):.3f} K of a rise "
          f"{np.max(t_ross) - 40.0:.2f} K")
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
