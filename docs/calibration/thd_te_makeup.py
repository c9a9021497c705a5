"""The THD trailing-edge make-up (cpp/src/thd.cpp, kTeMakeup; docs/film-physics.md, "A
trailing-edge cell the pad hardly feeds"): how much inlet-gap oil the lobes' and pads'
trailing-edge cells draw, whether each film's heat balance closes with it, and the results
the threshold moves.

Run ``python docs/calibration/thd_te_makeup.py`` against a build (the threshold is a
compile-time constant: the sensitivity table of docs/film-physics.md came from three builds
with kTeMakeup = 0.05, 0.1, 0.2). Cases:
* the turbine of tests/data/models (turbine_two_axial_groove_thd.toml: THD, VG32 at 45 °C,
  two turbulent two-axial-groove bearings) at 2, 5.387, 7.964 and 10.7 Hz: status, outer
  iterations, B1's eccentricity ratio, each lobe's T_max, power loss and make-up flow, and the
  largest heat-balance defect over the lobes, |ρc (heat out − in) − P| / P, with the make-up
  term and without it;
* the turbine's bearing B1 alone under 21 kN (about half the rotor's weight) at 5.387 Hz with
  carry-over λ = 0.5 (the make-up's heat now reaches the next lobe's inlet with the hot oil
  passed on): per lobe T_max, T_in, T_out and the reported-quantity balance
  |ρc (Q_out T_out + Σ q_s T − Q_in T_in) − P| / P;
* the compressor of tests/data/models on THD tilting pads (5 pads per bearing, 72 × 6, the
  plain-thermal model's oil system, λ = 0.6) at 150 Hz: the same per pad.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import numpy as np

import rotordyn

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
from thd_balance import pad_balance  # noqa: E402

MODELS = ROOT / "tests" / "data" / "models"


def balance_defects(r, rho_c):
    """Per film: (with the make-up term, without it) |heat out − in − P| / P, and the make-up
    flow (m³/s). THD films of pads and lobes (adiabatic: the heat the flows carry = P)."""
    out = []
    for k in range(len(r.bearing_names)):
        T, D, fl = r.temperature_c[k], r.inlet_mask[k] > 0, r.flows[k]
        t_in = float(r.inlet_temperature_c[k])
        h1, P, _ = pad_balance(T, D, fl, rho_c, r.supply_temperature_c, t_in=t_in)
        h0, _, _ = pad_balance(T, D, fl, rho_c, r.supply_temperature_c)
        m = float(np.asarray(fl["makeup_m3_s"])[~D].sum())
        out.append((abs(h1 - P) / P, abs(h0 - P) / P, m))
    return out


def report(name, system, speeds):
    oil = system.thermal.oil
    rho_c = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k
    for f in speeds:
        r = rotordyn.system_thermal_equilibrium(system, speed_hz=f)
        if r.status != "ok":
            print(f"{name} {f:g} Hz: {r.status} ({r.message})")
            continue
        c = system.bearings[0].clearance_m
        eps = float(np.hypot(r.journal_x_m[0], r.journal_y_m[0])) / c
        d = balance_defects(r, rho_c)
        tm = ", ".join(f"{t:.4f}" for t in r.max_temperature_c)
        pw = ", ".join(f"{p:.3f}" for p in r.power_loss_w)
        mk = ", ".join(f"{x[2] * 1e6:.4g}" for x in d)
        print(f"{name} {f:g} Hz: {r.iterations} outer steps, eps(0) = {eps:.5f}; T_max [{tm}] "
              f"degC; P [{pw}] W; make-up [{mk}] 1e-6 m3/s; heat-balance defect max "
              f"{max(x[0] for x in d):.2e} with the make-up, {max(x[1] for x in d):.2e} "
              "without")


def standalone(turbine) -> None:
    oil = turbine.thermal.oil
    rho_c = oil.density_kg_m3 * oil.specific_heat_j_per_kg_k
    b = turbine.bearings[0]
    r = b.thermal_equilibrium(load_n=(0.0, -21000.0), speed_hz=5.387, oil=oil,
                              supply_temperature_c=45.0, carry_over=0.5)
    defects = []
    for k in range(len(r.max_temperature_c)):
        T, D, fl = r.temperature_c[k], r.inlet_mask[k] > 0, r.flows[k]
        n, k1 = T.shape
        qp, qz = fl["q_phi_m3_s"], fl["q_z_m3_s"]
        inflow, outflow = np.zeros_like(T), np.zeros_like(T)
        from thd_balance import upwind_faces
        for a, c, F in upwind_faces(qp, qz):
            inflow[c] += F
            outflow[a] += F
        B = inflow - outflow
        side = sum(B[j, kk] * T[j, kk] for j in range(n) for kk in (0, k1 - 1)
                   if not D[j, kk] and not D[(j + 1) % n, kk] and B[j, kk] > 0)
        heat = rho_c * (r.outlet_flow_m3_s[k] * r.outlet_temperature_c[k] + side
                        - r.film_flow_m3_s[k] * r.inlet_temperature_c[k])
        defects.append(abs(heat - r.power_loss_w[k]) / r.power_loss_w[k])
    print(f"turbine B1 alone, 21 kN, 5.387 Hz, carry-over 0.5: {r.status}, {r.iterations} "
          f"steps, eps {r.eccentricity_ratio:.5f}; T_max {np.round(r.max_temperature_c, 4)}, "
          f"T_in {np.round(r.inlet_temperature_c, 4)}, T_out "
          f"{np.round(r.outlet_temperature_c, 4)} degC; P {np.round(r.power_loss_w, 3)} W; "
          f"make-up {np.round(r.makeup_flow_m3_s * 1e6, 3)} 1e-6 m3/s; reported-quantity "
          f"balance defect max {max(defects):.2e}")


def main() -> int:
    turbine = rotordyn.System.from_toml(MODELS / "turbine_two_axial_groove_thd.toml")
    report("turbine", turbine, (2.0, 5.387, 7.964, 10.7))
    standalone(turbine)
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    th = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    th = dataclasses.replace(th, model="thd", films=())
    comp = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=72, n_axial=6) for b in s.bearings), thermal=th)
    report("compressor THD pads", comp, (150.0,))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
