"""The compressor of tests/data/models on its two 5-pad tilting-pad bearings with tilting films
(issue 20): the thinnest pad's edge film, the journal's rotation, the film moment and the least
damped eigenvalue against the housing misalignment θy of both bearings, rocker against
spherical pivots, at 150 Hz (docs/film-physics.md, "Tilting-pad bearings").

Run ``python docs/calibration/pad_tilt.py``.
"""

import dataclasses
from pathlib import Path

import numpy as np

import rotordyn
from rotordyn.analysis.assembly import assembled

MODEL = (Path(__file__).resolve().parents[2] / "tests" / "data" / "models"
         / "compressor_tilting_pad.toml")


def compressor(**kw):
    s = rotordyn.System.from_toml(MODEL)
    return dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, **kw)
                                                 for b in s.bearings))


def low(ev) -> float:
    """Largest real part among the modes below 1 kHz (the rotor's lateral modes)."""
    ev = np.asarray(ev)
    return float(ev.real[np.abs(ev.imag) < 2 * np.pi * 1000.0].max())


def main():
    print("| pivot | theta_y (mrad) | h_min NDE aligned / tilting (um) | z of h_min (mm) | "
          "journal theta_y rel. (mrad) | M_x, M_y NDE (N m) | pad pitches NDE (mrad) | "
          "least damped below 1 kHz, aligned / tilting (1/s) | least damped overall (1/s, Hz) |")
    print("|---|---|---|---|---|---|---|---|---|")
    e0 = rotordyn.equilibrium(compressor(), speed_hz=150.0)
    l0 = low(rotordyn.stability(compressor(), speed_hz=150.0).eigenvalues)
    for pivot in ("rocker", "spherical"):
        for th in (0.0, 2e-4, 4e-4, 8e-4):
            s = compressor(tilt=True, config_theta_y_rad=th, pivot_type=pivot)
            e = rotordyn.equilibrium(s, speed_hz=150.0)
            ev = rotordyn.stability(s, speed_hz=150.0).eigenvalues
            top = ev[np.argmax(ev.real)]
            bc = assembled(s).bearings[0]
            t = e.tilt[0]
            pitch = ", ".join(f"{g * 1e3:+.3f}" for g in t.get("pad_pitch_rad", ())) or "—"
            print(f"| {pivot} | {th * 1e3:.1f} | {e0.h_min_m[0] * 1e6:.2f} / "
                  f"{e.h_min_m[0] * 1e6:.2f} | {t['h_min_z_m'] * 1e3:+.1f} | "
                  f"{t['journal_theta_y_rad'] * 1e3:+.4f} | {e.film_force_n[bc.rot[0]]:+.3f}, "
                  f"{e.film_force_n[bc.rot[1]]:+.3f} | {pitch} | {l0:.2f} / {low(ev):.2f} | "
                  f"{top.real:.2f}, {abs(top.imag) / (2 * np.pi):.0f} |")
            assert e.status == "ok" and e.path == "pad_assembly", e.message


if __name__ == "__main__":
    main()
