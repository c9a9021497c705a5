"""The default axial boundary condition (open ends, p = 0 at z = ±L/2) is bit-for-bit what
it was before the end-seal (Robin) option entered the Reynolds core.

The golden values in tests/data/reynolds_open_ends_golden.json were written by this module
(``python tests/test_reynolds_open_ends_golden.py --write``) on commit 95697f7, the last
commit before the end-seal option, and are compared here with exact equality (float.hex):
every cavitation model, the full and the half (axial-symmetry) system for an even and an odd
n_axial, a groove, a non-symmetric (misaligned) film, the perturbation coefficients, the
Newton equilibrium, the squeeze-film damper's system path and a fixed-geometry bearing.
Same machine, same compiler flags (Release, no -march=native, no FMA contraction on the
x86-64 baseline): the core's arithmetic is deterministic, so any change is a change of path.

Since the banded factorisation (a ring of prescribed or cavitated unknowns opens the circle:
reynolds_band.cpp), the default path rounds differently: the solvers built here are compared
bit for bit with ``band_factor = False`` (the sparse LDLᵀ the golden values were written
with), and every value of the default path within 1e-12 of its quantity's scale (observed
≤ 3e-14).
"""

import json
import math
import sys
from pathlib import Path

import numpy as np

from rotordyn import _core
from rotordyn.bearings import FixedGeometryBearing, SqueezeFilmDamper

GOLDEN = Path(__file__).parent / "data" / "reynolds_open_ends_golden.json"


def _solver(cav, n_axial, grooves=(), band=True):
    g = _core.JournalBearingGeometry()
    g.diameter_m, g.length_m, g.clearance_m, g.viscosity_pa_s = 0.05, 0.03, 1e-4, 0.02
    g.grooves = [_core.Groove(*gr) for gr in grooves]
    s = _core.ReynoldsSolver(g, _core.FilmGrid(36, n_axial), cav)
    s.band_factor = band
    return s


# built on the elements' own solvers (band_factor at its default, so --write stores these
# from the default path, the others from the sparse one; both are compared to 1e-12 below)
_ELEMENT_KEYS = ("sfd/forces", "sfd/orbit", "elliptical/forces")


def _cases(band=True) -> dict:
    out = {}
    w = 2 * math.pi * 50.0
    for cav in ("none", "gumbel", "reynolds", "jfo"):
        grooves = [(90.0, 20.0, 1e5)] if cav == "jfo" else [(90.0, 0.0, 5e4)]
        for na in (8, 7):
            s = _solver(cav, na, grooves, band)
            key = f"{cav}/{na}"
            sol = s.rigid(2e-5, -5e-5, 1e-3, -2e-3, w)
            out[key + "/force"] = list(sol.force_n)
            out[key + "/flows"] = [sol.side_flow_m3_s, sol.inlet_flow_m3_s,
                                   sol.friction_torque_nm]
            out[key + "/p_sum"] = [float(np.sum(sol.p_pa)), float(np.sum(sol.p_pa ** 2))]
            dc = s.coefficients(3e-5, -6e-5, w)
            out[key + "/K"] = list(np.ravel(dc.K))
            out[key + "/C"] = list(np.ravel(dc.C))
            # a misaligned journal: h varies along z (full system, non-symmetric)
            z = np.asarray(s.z_m)
            phi = np.asarray(s.phi_rad)
            h = (1e-4 - 4e-5 * np.cos(phi)[:, None] * (1 + 10 * z[None, :])
                 - 2e-5 * np.sin(phi)[:, None])
            hd = 1e-3 * np.sin(phi)[:, None] * (1 + 5 * z[None, :])
            sol = s.solve(h, hd, w)
            out[key + "/mis_force"] = list(sol.force_n)
            dp = s.linearize(np.cos(phi)[:, None] * np.ones_like(z)[None, :], np.zeros_like(h))
            out[key + "/mis_dF"] = list(s.integrate_force(dp))
            if cav != "jfo":
                e = s.equilibrium(0.0, -500.0, w)
                out[key + "/eq"] = [e.x_m, e.y_m]
    d = SqueezeFilmDamper(station=0, diameter_m=0.1, length_m=0.025, clearance_m=2e-4,
                          viscosity_pa_s=0.01, n_circ=36, n_axial=8)
    out["sfd/forces"] = list(d.forces(x_m=5e-5, y_m=0.0, vx_m_s=0.0, vy_m_s=0.02))
    out["sfd/orbit"] = list(d.orbit_coefficients(eccentricity_ratio=0.4, whirl_hz=30.0).values())
    fg = FixedGeometryBearing(station=0, kind="elliptical", diameter_m=0.05, length_m=0.025,
                              clearance_m=1e-4, viscosity_pa_s=0.02, n_circ=36, n_axial=8)
    out["elliptical/forces"] = list(fg.forces(x_m=1e-5, y_m=-3e-5, speed_hz=50.0))
    return {k: [float(x).hex() for x in v] for k, v in out.items()}


def test_open_ends_bit_for_bit_unchanged():
    golden = json.loads(GOLDEN.read_text())
    now = _cases(band=False)
    assert sorted(now) == sorted(golden)
    diff = {k: (now[k], golden[k]) for k in golden
            if k not in _ELEMENT_KEYS and now[k] != golden[k]}
    assert not diff, f"open-ends results changed: {diff}"


def test_open_ends_default_path_within_round_off():
    # the default path is the banded one here (the zero-width groove empties a ring)
    for cav in ("none", "gumbel", "reynolds"):
        s = _solver(cav, 8, [(90.0, 0.0, 5e4)])
        s.rigid(2e-5, -5e-5, 1e-3, -2e-3, 2 * math.pi * 50.0)
        assert s.band_factor_used, cav
    golden = json.loads(GOLDEN.read_text())
    now = _cases(band=True)
    worst = {}
    for k in golden:
        g = np.array([float.fromhex(x) for x in golden[k]])
        v = np.array([float.fromhex(x) for x in now[k]])
        worst[k] = float(np.abs(v - g).max() / np.abs(g).max())
    bad = {k: w for k, w in worst.items() if not w <= 1e-12}
    assert not bad, f"open-ends results moved beyond round-off: {bad}"


if __name__ == "__main__" and "--write" in sys.argv:
    GOLDEN.parent.mkdir(exist_ok=True)
    GOLDEN.write_text(json.dumps(_cases(band=False), indent=1, sort_keys=True) + "\n")
    print("wrote", GOLDEN)
