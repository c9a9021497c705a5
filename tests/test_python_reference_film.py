"""benchmarks/python_film.py is an independent NumPy/SciPy implementation of the system's film
forces (the finite-volume Reynolds equation, Swift–Stieber cavitation by the primal–dual active
set, SuperLU, virtual-work forces), written for the SciPy baseline of bench_control.py. It must
solve the same discrete problem as the C++ core: the Swift–Stieber complementarity problem has
one solution, so the forces agree to round-off (tolerance 1e-11 of the largest force; observed
~5e-15) — on the paper rig (sleeve coordinates, a zero-width groove at 90°), and on two plain
bearings with a pressurised finite-width groove, off-centre, whirling, at a second grid."""

import importlib.util
import pathlib

import numpy as np

import rotordyn as rd
from rotordyn.analysis.assembly import assembled

_PATH = pathlib.Path(__file__).resolve().parents[1] / "benchmarks" / "python_film.py"
_spec = importlib.util.spec_from_file_location("python_film", _PATH)
python_film = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(python_film)


def _states(asm, r0, scale, rng):
    n = asm.n
    out = [(r0, np.zeros(n))]
    for _ in range(4):
        out.append((r0 + scale * rng.uniform(-1, 1, n), 50 * scale * rng.normal(size=n)))
    return out


def test_python_film_equals_the_core_on_the_paper_rig():
    rig = rd.models.paper_rig()
    asm = assembled(rig)
    e = rd.equilibrium(rig, 50.0, 0.05e6, -1.85e-3)
    states = _states(asm, e.r, 2e-6, np.random.default_rng(3))
    forces = python_film.PythonFilmForces(asm.model)
    for hz in (50.0, 20.0):
        worst = python_film.check_against_core(asm.solver, forces, states, 2 * np.pi * hz)
        assert worst < 1e-11, worst


def test_python_film_equals_the_core_on_grooved_plain_bearings():
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.1, outer_diameter_m=0.1) for _ in range(4))
    groove = (rd.Groove(center_deg=200.0, width_deg=25.0, pressure_pa=0.2e6),)
    films = tuple(rd.FluidFilmBearing(s, diameter_m=0.05, length_m=0.03, clearance_m=1e-4,
                                      viscosity_pa_s=0.03, n_circ=48, n_axial=10,
                                      grooves=groove) for s in (0, 4))
    system = rd.System(rotor=rd.Rotor(shaft, ()), materials=(steel,), bearings=films,
                       reduction=rd.Reduction(master_stations=(0, 4), method="guyan"))
    asm = assembled(system)
    forces = python_film.PythonFilmForces(asm.model)
    rng = np.random.default_rng(7)
    r0 = np.zeros(asm.n)
    for b in asm.bearings:
        r0[b.jx], r0[b.jy] = 2e-5, -5e-5  # off-centre: a cavitated region and a full film
    states = _states(asm, r0, 1e-5, rng)
    worst = python_film.check_against_core(asm.solver, forces, states, 2 * np.pi * 60.0)
    assert worst < 1e-11, worst
