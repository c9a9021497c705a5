"""Fig. 9 of the reference paper (boundary in (a_y, p_c) at W = 50 Hz) with and without journal
tilt in the active bearing (issue 20), and the edge film against a_y.

The committed rig (`rotordyn.models.paper_rig()`) as it is, and the same rig with
`tilt = true` on its active bearing: the film then couples to the rotations θx, θy of the
bearing station (kept as Guyan masters), so the slope that the housing offset a_y forces on the
shaft at the bearing tilts the journal in the film. For each a_y: every crossing of
max Re λ = 0 in p_c = 0 … 0.3 MPa (`rotordyn.threshold`, as docs/calibration/
paper_rig_stability.py), and at p_c = 0.1 MPa the equilibrium's journal rotation, minimum film
and where it sits (φ, z).

Run:  .venv/bin/python docs/calibration/paper_rig_tilt.py     (~30 s on 2 shared cores)
"""

from __future__ import annotations

import dataclasses

import numpy as np

import rotordyn as rd

PC_BOUNDS = (0.0, 0.3e6)
AY_MM = (-2.5, -2.25, -2.0, -1.85, -1.75, -1.5, -1.0, 0.0, 1.0, 2.0)


def with_tilt(system):
    bs = tuple(dataclasses.replace(b, tilt=True) if isinstance(b, rd.ActiveJournalBearing)
               else b for b in system.bearings)
    return dataclasses.replace(system, bearings=bs)


def main() -> int:
    rig = rd.models.paper_rig()
    tilt = with_tilt(rig)
    print("Fig. 9, W = 50 Hz: crossings of max Re(lambda) = 0 in p_c (MPa), "
          "+ becomes unstable, - becomes stable")
    print(f"{'a_y mm':>7}  {'aligned film':30s}  {'tilting film':30s}")
    for ay in AY_MM:
        row = []
        for s in (rig, tilt):
            th = rd.threshold(s, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=50.0,
                              config_ay_m=ay * 1e-3)
            cr = []
            for x in th.crossings:
                lo = rd.stability(s, 50.0, max(x - 1e3, 0.0), ay * 1e-3).eigenvalues.real.max()
                cr.append(f"{x / 1e6:.4f}{'+' if lo < 0 else '-'}")
            row.append(", ".join(cr) or "none")
        print(f"{ay:7.2f}  {row[0]:30s}  {row[1]:30s}")
    print("\nedge film at p_c = 0.1 MPa, W = 50 Hz")
    print(f"{'a_y mm':>7} {'h_min aligned um':>17} {'h_min tilting um':>17} {'phi deg':>8} "
          f"{'z mm':>6} {'theta_x mrad':>13} {'theta_y mrad':>13}")
    for ay in AY_MM:
        e0 = rd.equilibrium(rig, speed_hz=50.0, chamber_pressure_pa=0.1e6, config_ay_m=ay * 1e-3)
        e1 = rd.equilibrium(tilt, speed_hz=50.0, chamber_pressure_pa=0.1e6,
                            config_ay_m=ay * 1e-3)
        t = next(iter(e1.tilt.values()))
        print(f"{ay:7.2f} {e0.h_min_m[0] * 1e6:17.2f} {e1.h_min_m[0] * 1e6:17.2f} "
              f"{e1.h_min_angle_deg[0]:8.1f} {t['h_min_z_m'] * 1e3:6.1f} "
              f"{t['journal_theta_x_rad'] * 1e3:13.4f} {t['journal_theta_y_rad'] * 1e3:13.4f}"
              f"  ({e0.status}, {e1.status})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
