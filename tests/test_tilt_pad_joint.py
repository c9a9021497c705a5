"""Spherical-pivot tilting pads: each pad's (tilt[, pivot], pitch) by one joint Newton in the
pad assembly (cpp/src/pad_joint.cpp) against the nested solves it replaces (pitch ⊃ pivot ⊃
tilt; ``EquilibriumOptions.joint_pad_solve = False``), docs/film-physics.md, "Tilting-pad
bearings".

References: the nested solves are the reference — the same root to the solvers' tolerance
(1e-9 of the coordinate's scale, observed ≤ 1e-15) on the 5-pad bearing
(misaligned equilibrium under a load; a held eccentric pose with a pressure-free pad, preload
0.25) and on the compressor of tests/data/models with both housings misaligned, rigid and
flexible pivots; and the Reynolds solves the joint Newton saves (counted by the core).
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import TiltingPadBearing
from rotordyn.bearings.tilt_pads import (_layout, pad_misaligned_equilibrium,
                                         pad_tilted_coefficients)
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
C, L = 1e-4, 0.05
GEOM = dict(station=0, diameter_m=0.1, length_m=L, clearance_m=C, viscosity_pa_s=0.018,
            n_pads=5, pad_arc_deg=60.0, n_circ=72, n_axial=8, tilt=True,
            pivot_type="spherical")
FLEXIBLE = dict(pivot_stiffness_n_per_m=3e8, pad_mass_kg=0.3, pitch_stiffness_n_m_per_rad=10.0)
FLEXIBLE_ROCKER = dict(pivot_stiffness_n_per_m=3e8, pad_mass_kg=0.3)
W = 2 * math.pi * 100.0
TILT = (2e-4, -1e-4)


def options(joint):
    opt = _core.EquilibriumOptions()
    opt.tol, opt.polish, opt.joint_pad_solve = 1e-10, True, joint
    return opt


def scales(lay, n_journal):
    """Per coordinate of r: c for journal positions, pad tilts (η) and pivots, c/(L/2) for
    the pitches (the pitch that moves a pad's edge by c)."""
    s = np.full(n_journal + lay.n, C)
    if lay.pitch:
        s[n_journal + lay.npd - 1::lay.npd] = C / (0.5 * L)
    return s


def misaligned(b, load, joint):
    lay = _layout(b)
    pose = np.array([0.0, 0.0, *TILT])
    model = lay.model([0, 1], pose, lay.pitch_offsets(*TILT), np.array(load))
    return _core.pad_system_equilibrium(
        _core.SystemSolver(model), model, W, 0.0, np.zeros(2 + lay.n), np.zeros(0),
        np.zeros(0), options(joint), np.asarray(lay.parts.penalty)), scales(lay, 2)


def held(b, pose, joint):
    lay = _layout(b)
    model = lay.model([], np.array(pose), lay.pitch_offsets(*pose[2:]), np.zeros(0))
    solver = _core.SystemSolver(model)
    e = solver.equilibrium(W, 0.0, np.zeros(lay.n), np.zeros(0), options(joint))
    pmax = [float(np.asarray(solver.last_pressure(k)).max()) for k in range(b.n_pads)]
    return e, scales(lay, 0), pmax


def agree(ej, en, s, rel):
    assert ej.status == en.status == "ok", (ej.message, en.message)
    assert ej.path == en.path == "pad_assembly"
    d = np.abs(np.asarray(ej.r) - np.asarray(en.r)) / s
    assert d.max() <= rel, d.max()


@pytest.mark.parametrize("flexible", [False, True], ids=["rigid", "flexible"])
def test_joint_equals_nested_misaligned_equilibrium(flexible):
    """The journal under 1500 N at a tilt (every pad pressured): journal, pad tilts, pivots
    and pitches equal to 1e-9 of c (of c/(L/2) for the pitches; observed 5e-16), and fewer
    Reynolds solves (observed 102 against 229 rigid, 164 against 419 flexible)."""
    b = TiltingPadBearing(**GEOM, preload=0.5, **(FLEXIBLE if flexible else {}))
    (ej, s), (en, _) = misaligned(b, (0.0, -1500.0), True), misaligned(b, (0.0, -1500.0), False)
    agree(ej, en, s, 1e-9)
    assert ej.unloaded_pads == en.unloaded_pads == 0
    assert ej.reynolds_solves < 0.6 * en.reynolds_solves


@pytest.mark.parametrize("flexible", [False, True], ids=["rigid", "flexible"])
def test_joint_equals_nested_with_a_pressure_free_pad(flexible):
    """Preload 0.25, journal held at e = 0.4 c below the centre, tilted: the top pad carries
    no pressure (the nested solves' defined position: the boundary of its pressure-free set,
    pitch γ_def), the others are pressured; both paths give the same pads (1e-9 of the scale;
    observed 8e-16) and the same unloaded pad (solves: 264 against 277 rigid, 383 against 437
    flexible — the pressure-free pad's bisections, as in the nested path, dominate)."""
    b = TiltingPadBearing(**GEOM, preload=0.25, **(FLEXIBLE if flexible else {}))
    pose = (0.0, -0.4 * C, *TILT)
    (ej, s, pj), (en, _, pn) = held(b, pose, True), held(b, pose, False)
    agree(ej, en, s, 1e-9)
    assert ej.unloaded_pads == en.unloaded_pads == 1
    assert sum(p == 0.0 for p in pj) == sum(p == 0.0 for p in pn) == 1
    assert min(p for p in pj if p > 0) > 1e4  # the others clearly pressured (Pa)


def compressor(**fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    bs = tuple(dataclasses.replace(b, n_circ=48, n_axial=6, tilt=True, config_theta_y_rad=3e-4,
                                   **fields) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs)


def system_equilibrium(s, joint):
    asm = assembled(s)
    e = _core.pad_system_equilibrium(
        _core.SystemSolver(asm.model), asm.model, 2 * math.pi * 150.0, 0.0,
        asm.config_vector(None, None), np.zeros(0), np.zeros(0), options(joint),
        asm.pad_penalty)
    return e, asm


@pytest.mark.parametrize("flexible", [False, True], ids=["rigid", "flexible"])
def test_joint_equals_nested_compressor_and_saves_solves(flexible):
    """The compressor on two 5-pad spherical-pivot bearings, housings misaligned by 0.3 mrad,
    from the centred state: the equilibrium (every coordinate) equal to 1e-9 of its scale
    (c for positions, c/(L/2) for rotations; observed 2e-18 m absolute), the same as
    rotordyn.equilibrium's (the joint path is the default), and the Reynolds solves: the
    joint path takes at most 0.6 of the nested one's and at most 1.3× the rocker pads'
    (observed 154 against 306 and 152 rigid, 252 against 620 and 419 flexible; at 72 × 16
    rigid: 162 against 310 and 122)."""
    extra = dict(pivot_stiffness_n_per_m=3e8, pad_mass_kg=0.3) if flexible else {}
    s = compressor(pivot_type="spherical", **extra)
    (ej, asm), (en, _) = system_equilibrium(s, True), system_equilibrium(s, False)
    b = s.bearings[0]
    sc = np.full(asm.n, b.clearance_m)
    for bc in asm.bearings:  # rotations (journal tilts, pitches) on c/(L/2)
        sc[list(bc.rot)] = b.clearance_m / (0.5 * b.length_m)
        for j, lab in zip(bc.extra, bc.labels):
            if lab.endswith(".pitch"):
                sc[j] = b.clearance_m / (0.5 * b.length_m)
    agree(ej, en, sc, 1e-9)
    e = rotordyn.equilibrium(s, speed_hz=150.0, warm_start=False)
    assert np.abs((np.asarray(e.r) - np.asarray(ej.r)) / sc).max() <= 1e-9
    er, _ = system_equilibrium(compressor(pivot_type="rocker", **extra), True)
    assert er.status == "ok"
    assert ej.reynolds_solves <= 0.6 * en.reynolds_solves, (ej.reynolds_solves,
                                                           en.reynolds_solves)
    assert ej.reynolds_solves <= 1.3 * er.reynolds_solves, (ej.reynolds_solves,
                                                           er.reynolds_solves)


@pytest.mark.parametrize("pivot", ["rocker", "spherical"])
@pytest.mark.parametrize("whirl_ratio", [1.0, None], ids=["synchronous", "static"])
def test_operating_point_in_one_call(pivot, whirl_ratio):
    """pad_misaligned_equilibrium(coefficients=True) linearises about the equilibrium's own
    films: its 4×4 K, C equal pad_tilted_coefficients at the same (x, y) — the pads re-solved
    at the held pose from the cold start, the same root — to 1e-12 of the largest entry
    (observed 7e-16), flexible pivots included; bad input names the field."""
    b = TiltingPadBearing(**{**GEOM, "pivot_type": pivot}, preload=0.5, **FLEXIBLE_ROCKER)
    kw = dict(speed_hz=100.0, theta_x_rad=TILT[0], theta_y_rad=TILT[1])
    m = pad_misaligned_equilibrium(b, load_n=(0.0, -1500.0), coefficients=True,
                                   whirl_ratio=whirl_ratio, **kw)
    assert m.status == "ok" and m.K.shape == m.C.shape == (4, 4)
    K, C = pad_tilted_coefficients(b, x_m=m.x_m, y_m=m.y_m, whirl_ratio=whirl_ratio, **kw)
    np.testing.assert_allclose(m.K, K, rtol=0, atol=1e-12 * np.abs(K).max())
    np.testing.assert_allclose(m.C, C, rtol=0, atol=1e-12 * np.abs(C).max())
    assert pad_misaligned_equilibrium(b, load_n=(0.0, -1500.0), **kw).K is None
    with pytest.raises(InputError, match="coefficients"):
        pad_misaligned_equilibrium(b, load_n=(0.0, -1500.0), coefficients="yes", **kw)
    with pytest.raises(InputError, match="whirl_ratio"):
        pad_misaligned_equilibrium(b, load_n=(0.0, -1500.0), coefficients=True,
                                   whirl_ratio=float("nan"), **kw)


def test_a_lightly_loaded_pad_takes_the_nested_choice():
    """Zero preload, flexible pivots with a soft pitch seat, journal held near the centre and
    tilted: one pad carries a few hundred Pa and has two pressured equilibria (pitch
    −1.3e-5 rad at 359 Pa, −6.5e-4 rad at 7e4 Pa); below 1e-3 of μ|Ω|(R/C)² (2.8 kPa here) the
    joint Newton leaves it to the nested solves, so both paths give the same pads (1e-9 of
    the scale; observed 5e-19 m) and the same pressure-free pads (without that rule the joint
    Newton ended on the other equilibrium, 0.16 of c/(L/2) away in pitch)."""
    b = TiltingPadBearing(**GEOM, preload=0.0, **FLEXIBLE)
    pose = (1e-5, -3e-5, *TILT)
    (ej, s, pj), (en, _, pn) = held(b, pose, True), held(b, pose, False)
    agree(ej, en, s, 1e-9)
    assert ej.unloaded_pads == en.unloaded_pads
    assert sum(p == 0.0 for p in pj) == sum(p == 0.0 for p in pn)
