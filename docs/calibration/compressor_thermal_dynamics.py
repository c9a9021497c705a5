"""Stability of the three-impeller compressor on two plain journal bearings with each speed at
its own thermal equilibrium (issue 20; docs/film-physics.md, "Dynamics at each point's own
thermal equilibrium"), against the isothermal film at the supply temperature.

Model: tests/data/models/compressor_plain_thermal.toml (ISO VG 32 supplied at 45 °C,
carry-over 0.6 / 0.4, the DE bearing with a metered 2e-5 m³/s), films on 36 × 8 (the tests'
grid). Printed: per speed max Re λ isothermal at μ(45 °C) and at each speed's thermal
equilibrium (effective-temperature and THD films) with T_eff; the isothermal whirl-onset speed
at several viscosities (the trend that predicts the thermal shift); the thermal onset by
Brent's method on the thermal max Re λ and by ``rotordyn.threshold(..., thermal=...)``; the
isothermal onset of the model frozen at μ(T_eff) of the thermal onset (must equal it).

Run:  python docs/calibration/compressor_thermal_dynamics.py   (~10 s on 2 shared cores)
"""

import dataclasses
import os
import time
from pathlib import Path

from scipy.optimize import brentq

import rotordyn as rd

MODEL = Path(__file__).resolve().parents[2] / "tests" / "data" / "models" / \
    "compressor_plain_thermal.toml"


def iso(s, mus):
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, viscosity_pa_s=float(m)) for b, m in zip(s.bearings, mus)))


def main():
    t0, c0 = time.time(), time.process_time()
    print(f"load average {os.getloadavg()[0]:.2f}")
    s = rd.System.from_toml(MODEL)
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))
    oil, ts = s.thermal.oil, s.thermal.supply_temperature_c
    mu_s = oil.viscosity_pa_s(ts)
    cold = iso(s, [mu_s] * 2)
    print(f"mu({ts:g} degC) = {mu_s:.5g} Pa s")
    print("speed_hz  maxRe_iso45  maxRe_eff  T_eff_NDE  T_eff_DE  maxRe_thd  T_mean_thd_NDE/DE")
    for f in (60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 200.0, 250.0):
        a = rd.stability(cold, f, warm_start=False).max_real_1_per_s
        e = rd.stability(s, f, thermal=True)
        te = e.thermal.effective_temperature_c
        try:
            d = rd.stability(s, f, thermal={"model": "thd"})
            td = d.thermal.effective_temperature_c
            thd = f"{d.max_real_1_per_s:9.3f}  {td[0]:.2f}/{td[1]:.2f}"
        except rd.errors.ConvergenceError as exc:  # reported, not hidden
            thd = f"failed: {exc}"
        print(f"{f:8.1f}  {a:11.3f}  {e.max_real_1_per_s:9.3f}  {te[0]:9.2f}  {te[1]:8.2f}  "
              + thd)
    print("isothermal onset speed against the viscosity (both bearings):")
    for mu in (0.008, 0.012, 0.015, 0.018, mu_s, 0.03):
        t = rd.threshold(iso(s, [mu] * 2), "speed_hz", bounds=(100.0, 150.0), xtol=1e-7)
        print(f"  mu = {mu:.4f} Pa s: {t.value:.4f} Hz ({t.status})")
    f0 = rd.threshold(cold, "speed_hz", bounds=(100.0, 150.0), xtol=1e-7).value
    for model in ("effective", "thd"):
        kw = {"model": model}
        f_th = brentq(lambda f: rd.stability(s, f, thermal=kw).max_real_1_per_s, 110.0, 140.0,
                      xtol=1e-7)
        t = rd.system_thermal_equilibrium(s, speed_hz=f_th, model=model)
        line = (f"{model}: thermal onset {f_th:.4f} Hz ({f_th - f0:+.3f} Hz against "
                f"{f0:.4f} Hz isothermal at {ts:g} degC), T_eff "
                + "/".join(f"{x:.2f}" for x in t.effective_temperature_c) + " degC")
        thr = rd.threshold(s, "speed_hz", bounds=(110.0, 140.0), xtol=1e-7, thermal=kw)
        line += f"; rotordyn.threshold(thermal=...) {thr.value:.4f} Hz"
        if model == "effective":
            mus = [oil.viscosity_pa_s(float(x)) for x in t.effective_temperature_c]
            f1 = rd.threshold(iso(s, mus), "speed_hz", bounds=(110.0, 140.0), xtol=1e-7).value
            line += (f"; isothermal onset at mu(T_eff) = "
                     + "/".join(f"{m:.5f}" for m in mus) + f" Pa s: {f1:.4f} Hz "
                     f"(|diff| {abs(f1 - f_th):.2g} Hz)")
        print(line)
    print(f"{time.time() - t0:.1f} s wall, {time.process_time() - c0:.1f} s CPU, "
          f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
