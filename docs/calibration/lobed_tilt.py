"""The compressor of tests/data/models on two lobed bearings with tilting films (issue 20):
edge film, journal rotation, film moment and the least damped eigenvalue against the housing
misalignment θy of both bearings, at 150 Hz (docs/film-physics.md, "Fixed-geometry bearings").

Run ``python docs/calibration/lobed_tilt.py``.
"""

import dataclasses
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import FixedGeometryBearing

MODEL = Path(__file__).resolve().parents[2] / "tests" / "data" / "models" / "compressor_plain.toml"


def compressor(kind, tilt, theta_y=0.0):
    s = rotordyn.System.from_toml(MODEL)
    bs = tuple(FixedGeometryBearing(station=b.station, name=b.name, diameter_m=b.diameter_m,
                                    length_m=b.length_m, clearance_m=b.clearance_m,
                                    viscosity_pa_s=b.viscosity_pa_s, kind=kind, tilt=tilt,
                                    config_theta_y_rad=theta_y) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs)


def main():
    print("| kind | theta_y (mrad) | h_min NDE aligned / tilting (um) | z of h_min (mm) | "
          "journal theta_y rel. (mrad) | M_x NDE (N m) | max Re lambda aligned / tilting (1/s) |")
    print("|---|---|---|---|---|---|---|")
    for kind in ("elliptical", "three_lobe"):
        e0 = rotordyn.equilibrium(compressor(kind, False), speed_hz=150.0)
        l0 = rotordyn.stability(compressor(kind, False), speed_hz=150.0).eigenvalues.real.max()
        for th in (0.0, 1e-4, 2e-4, 3e-4, 4e-4):
            s = compressor(kind, True, th)
            e = rotordyn.equilibrium(s, speed_hz=150.0)
            lam = rotordyn.stability(s, speed_hz=150.0).eigenvalues.real.max()
            bc = assembled(s).bearings[0]
            t = e.tilt[0]
            print(f"| {kind} | {th * 1e3:.1f} | {e0.h_min_m[0] * 1e6:.2f} / "
                  f"{e.h_min_m[0] * 1e6:.2f} | {t['h_min_z_m'] * 1e3:+.1f} | "
                  f"{t['journal_theta_y_rad'] * 1e3:+.4f} | {e.film_force_n[bc.rot[0]]:+.3f} | "
                  f"{l0:.3f} / {lam:.3f} |")


if __name__ == "__main__":
    main()
