"""The THD fixed point of the compressor's NDE plain bearing along the housing misalignment
(docs/film-physics.md, "Thermal films with a tilted journal", "Not unique" and its fix): per
misalignment θy, the system's thermal equilibrium (36 × 6, 150 Hz, THD) and the standalone
tilted one at the NDE journal's tilt and film load; T_max of both, their difference, the count
of cavitated cells, and at the end the largest jump of the system's T_max between adjacent
steps against the step.

Run ``python docs/calibration/thd_tilt_scan.py [start_mrad stop_mrad step_mrad]``
(default 0.25 0.32 0.0025).
"""

import dataclasses
import sys
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.analysis.assembly import assembled

MODELS = Path(__file__).resolve().parents[2] / "tests" / "data" / "models"


def system_and_standalone(theta_y_rad, k=0, grid=(36, 6)):
    """The system's THD equilibrium of the compressor with every housing misaligned by
    ``theta_y_rad`` and the standalone tilted film of bearing ``k`` at the system's journal
    tilt and film load: (system result, standalone result, bearing). Also used by
    tests/test_thd_fill_continuity.py."""
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=grid[0], n_axial=grid[1], tilt=True,
                            config_theta_y_rad=theta_y_rad)
        for b in s.bearings))
    th = s.thermal
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, model="thd")
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    ff = np.asarray(e.film_force_n)
    bc, b = assembled(res.system).bearings[k], s.bearings[k]
    own, tilt = th.film(b.name), e.tilt[k]
    sa = b.journal_bearing().thermal_equilibrium(
        load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=150.0, oil=th.oil, model="thd",
        supply_temperature_c=th.supply_temperature_c, carry_over=own.carry_over,
        supply_flow_m3_s=own.supply_flow_m3_s,
        theta_x_rad=tilt["journal_theta_x_rad"], theta_y_rad=tilt["journal_theta_y_rad"])
    return res, sa, b


def point(theta_y_rad, k=0, grid=(36, 6)):
    res, sa, _ = system_and_standalone(theta_y_rad, k, grid)
    fs, fa = np.asarray(res.flows[k]["fill"]), np.asarray(sa.flows["fill"])
    return (float(res.max_temperature_c[k]), float(sa.max_temperature_c),
            float(np.max(np.abs(np.asarray(res.temperature_c[k])
                                - np.asarray(sa.temperature_c)))),
            int((fs < 1).sum()), int((fa < 1).sum()), float(res.power_loss_w[k]), res.status)


if __name__ == "__main__":
    a, b, d = (float(x) for x in sys.argv[1:4]) if len(sys.argv) > 3 else (0.25, 0.32, 0.0025)
    thetas = np.arange(a, b + 0.5 * d, d)
    rows = []
    print("theta_y_mrad  T_max_system  T_max_standalone  max_field_diff_K  cav_sys cav_sa  P_W  "
          "system_status")
    for t in thetas:
        r = point(t * 1e-3)
        rows.append(r)
        print(f"{t:.4f}  {r[0]:.5f}  {r[1]:.5f}  {r[2]:.2e}  {r[3]:4d} {r[4]:4d}  {r[5]:.2f}",
              flush=True)
    T = np.array([r[0] for r in rows])
    jumps = np.abs(np.diff(T))  # NaN where a system point failed
    i = int(np.nanargmax(jumps))
    print(f"step {d} mrad: largest jump of system T_max {jumps[i]:.4f} K between "
          f"{thetas[i]:.4f} and {thetas[i + 1]:.4f} mrad; median jump {np.median(jumps):.4f} K; "
          f"largest system-standalone field difference {max(r[2] for r in rows):.2e} K")
