"""The two THD fixed points of the compressor's NDE plain bearing at +0.3 mrad
(docs/film-physics.md, "Not unique"): the system's thermal equilibrium and the standalone
tilted one at the NDE journal's tilt and film load, compared field by field.

Per misalignment: both results' T_max, T_in, position, power; the inlet hand-over (columns
and weights of ``inlet_mask`` at mid-length); the cells whose cavitation fill differs by more
than 0.05 between the two, and the count of cavitated cells.

Run ``python docs/calibration/thd_tilt_two_fixed_points.py [mrad ...]`` (default 0.2 0.3).

Since the fill of a cavitated cell next to the full film (2026-12-05, docs/film-physics.md,
"Fill of a cavitated cell next to the full film") the two calls meet one fixed point at every
misalignment measured (0-0.6 mrad): this script then prints equal rows and no differing cell;
``docs/calibration/thd_tilt_scan.py`` is the scan.
"""

import dataclasses
import sys
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.analysis.assembly import assembled

MODELS = Path(__file__).resolve().parents[2] / "tests" / "data" / "models"


def compare(theta_y_rad):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6, tilt=True, config_theta_y_rad=theta_y_rad)
        for b in s.bearings))
    th = s.thermal
    res = rotordyn.system_thermal_equilibrium(s, speed_hz=150.0, model="thd")
    e = rotordyn.equilibrium(res.system, speed_hz=150.0)
    ff = np.asarray(e.film_force_n)
    asm = assembled(res.system)
    for k, b in enumerate(s.bearings):
        bc, own, tilt = asm.bearings[k], th.film(b.name), e.tilt[k]
        sa = b.journal_bearing().thermal_equilibrium(
            load_n=(-ff[bc.jx], -ff[bc.jy]), speed_hz=150.0, oil=th.oil, model="thd",
            supply_temperature_c=th.supply_temperature_c, carry_over=own.carry_over,
            supply_flow_m3_s=own.supply_flow_m3_s,
            theta_x_rad=tilt["journal_theta_x_rad"], theta_y_rad=tilt["journal_theta_y_rad"])
        c = b.clearance_m
        kmid = b.n_axial // 2
        fs, fa = np.asarray(res.flows[k]["fill"]), np.asarray(sa.flows["fill"])
        flip = np.argwhere(np.abs(fs - fa) > 0.05).tolist()
        print(f"{theta_y_rad * 1e3:+.2f} mrad {b.name}")
        for name, tmax, tin, x, y, p, mask, fill in (
                ("system", res.max_temperature_c[k], res.inlet_temperature_c[k],
                 res.journal_x_m[k], res.journal_y_m[k], res.power_loss_w[k],
                 res.inlet_mask[k], fs),
                ("standalone", sa.max_temperature_c, sa.inlet_temperature_c, sa.x_m, sa.y_m,
                 sa.power_loss_w, sa.inlet_mask, fa)):
            m = np.asarray(mask)
            inlet = [(j, round(float(m[j, kmid]), 4)) for j in range(m.shape[0]) if m[j, kmid]]
            print(f"  {name:10s} T_max {tmax:.4f} T_in {tin:.4f} x/c {x / c:+.6f} "
                  f"y/c {y / c:+.6f} P {p:.1f} W inlet (column, weight) {inlet} "
                  f"cavitated cells {int((fill < 1).sum())}")
        print(f"  fill differs > 0.05 at (column, row) {flip}"
              + "".join(f"; ({j},{r}): {fs[j, r]:.3f} / {fa[j, r]:.3f}" for j, r in flip))


if __name__ == "__main__":
    for a in sys.argv[1:] or ["0.2", "0.3"]:
        compare(float(a) * 1e-3)
