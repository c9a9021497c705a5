"""Branches of static equilibria (issue 19; docs/nonlinear.md "Continuation of equilibria"):
every Hopf point of a branch against rotordyn.threshold's crossing on the same bounds, and
the CPU time of each branch (one thread; the load printed).

Run:  .venv/bin/python docs/calibration/equilibrium_branches.py
"""

from __future__ import annotations

import dataclasses
import os
import time
from pathlib import Path

import rotordyn as rd
from rotordyn.model.paths import set_field

ROOT = Path(__file__).resolve().parents[2]


def coarse(system):
    return dataclasses.replace(system, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6) if hasattr(b, "n_circ") else b
        for b in system.bearings))


def run(name, system, vary, bounds, check=None, **kw):
    t = time.process_time()
    br = rd.continuation(system, vary, bounds, **kw)
    cpu = time.process_time() - t
    print(f"{name}: {br!r}\n    {len(br)} points, {cpu:.2f} s CPU, stats {br.stats}, "
          f"load {os.getloadavg()[0]:.1f}")
    for b in br.bifurcations:
        print(f"    {b['kind']} at {b['parameter']:.9g} (refined {b['refined']}), whirl "
              f"{b['whirl_frequency_hz']:.5g} Hz, eigenvalue {b['eigenvalue']:.3g}")
    if check is not None:
        check(br)
    return br


def main():
    comp = coarse(rd.System.from_toml(ROOT / "tests/data/models/compressor_plain.toml"))
    rig = coarse(rd.models.paper_rig())

    def vs_threshold(system, vary, bounds, **fixed):
        def check(br):
            th = rd.threshold(system, vary, bounds=bounds, **fixed)
            for hb, c in zip(br.hopf_points(), th.crossings):
                print(f"    rd.threshold crossing {c:.9g}: branch − threshold = {hb - c:.3g}")
        return check

    run("compressor (36 x 6), speed 100-150 Hz", comp, "speed_hz", (100.0, 150.0),
        check=vs_threshold(comp, "speed_hz", (100.0, 150.0)))

    def clearance_check(br):
        for hp in br.hopf_points():
            th = rd.threshold(set_field(comp, "bearings.*.clearance_m", hp), "speed_hz",
                              bounds=(121.0, 141.0))
            print(f"    threshold speed with that clearance: {th.value:.9g} Hz")

    run("compressor (36 x 6), both clearances 100 -> 60 µm at 130 Hz", comp,
        "bearings.*.clearance_m", (0.6e-4, 1.0e-4), speed_hz=130.0, direction=-1, ds=0.05,
        ds_max=0.1, check=clearance_check)
    run("compressor (36 x 6), both viscosities 0.018 -> 0.004 Pa s at 130 Hz", comp,
        "bearings.*.viscosity_pa_s", (0.004, 0.018), speed_hz=130.0, direction=-1)
    run("rig (36 x 6), a_y = -1.85 mm, 50 Hz, p_c 0-0.3 MPa", rig, "chamber_pressure_pa",
        (0.0, 0.3e6), speed_hz=50.0, config_ay_m=-1.85e-3,
        check=vs_threshold(rig, "chamber_pressure_pa", (0.0, 0.3e6), speed_hz=50.0,
                           config_ay_m=-1.85e-3))
    run("rig (36 x 6), a_y = 0, p_c = 0.4 MPa, speed 20-150 Hz", rig, "speed_hz",
        (20.0, 150.0), chamber_pressure_pa=0.4e6, config_ay_m=0.0,
        check=vs_threshold(rig, "speed_hz", (20.0, 150.0), chamber_pressure_pa=0.4e6,
                           config_ay_m=0.0))
    run("rig as built (72 x 16), a_y = 0, p_c = 0.4 MPa, speed 20-150 Hz",
        rd.models.paper_rig(), "speed_hz", (20.0, 150.0), chamber_pressure_pa=0.4e6,
        config_ay_m=0.0)


if __name__ == "__main__":
    main()
