"""The stability chunk's modified Newton (issue 22): along a sweep line the equilibrium keeps
its Newton Jacobian K + K_H from step to step with Broyden updates (``jacobian="reuse"``,
the default; ``"line"`` starts from the previous point's K_H) instead of forming K_H by
linearised solves at every step (``"exact"``, the former iteration); the final K_H, D_H of a
converged point are always formed exactly.

References and tolerances:
- The exact-Jacobian Newton on the same lines: both stop at the first iterate inside the
  equilibrium tolerance (1e-10 of the load; sweeps do not polish), so the roots agree to that
  tolerance, not to round-off: positions within 1e-7 of the clearance (observed 1.4e-13 m on
  the rig), eigenvalues within 1e-7 of the largest |lambda|, statuses, whirl and stability
  verdicts identical.
- Cost (not time): fewer linearisations per point (observed on 10 x 100 map points
  2.76 -> 2.02 with 2.75 -> 2.86 Reynolds solves). On the code before, ``jacobian`` does not
  exist and ``linearizations`` is not exposed, so this fails there.
- Line independence: a line after another line (in one call, or on a solver used before)
  equals the line alone bit for bit (the Jacobian is forgotten at each line's start and at
  each equilibrium's return).
Models: the paper rig (Fig. 9 lines over p_c at 50 Hz); a compressor on two plain bearings
(tests/data/models/compressor_plain.toml, a speed line).
"""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.errors import InputError
from rotordyn.sweep.points import equilibrium_options
from rotordyn.units import hz_to_rad_s

_ASM = {}


def _asm(name):
    if name not in _ASM:
        _ASM[name] = Assembled(rd.models.paper_rig() if name == "rig" else rd.System.from_toml(
            Path(__file__).parent / "data" / "models" / f"{name}.toml"))
    return _ASM[name]


def _rig_inputs(ays, pcs):
    asm = _asm("rig")
    a = np.array([asm.config_vector(ay) for ay in ays for _ in pcs])
    p = np.tile(np.asarray(pcs, float), len(ays))
    w = np.full(len(p), hz_to_rad_s(50.0))
    restart = [1 if k == 0 else 0 for _ in ays for k in range(len(pcs))]
    return w, p, a, restart


def _run(name, inp, jacobian, solver=None):
    asm = _asm(name)
    solver = solver or _core.SystemSolver(asm.model)
    res = _core.stability_batch(
        solver, *inp, equilibrium_options({}), 0, False, FD_REL_STEP, asm.rotor.xy_pairs(),
        asm.rotor.rot_pairs(), [i for bc in asm.bearings for i in bc.sleeve],
        jacobian=jacobian)
    return res, solver


def _within_tolerance(name, a, b):
    clearance = min(bc.clearance_m for bc in _asm(name).bearings)
    assert list(a.status) == list(b.status)
    assert np.array_equal(np.asarray(a.n_eig), np.asarray(b.n_eig))
    assert np.array_equal(np.asarray(a.whirl), np.asarray(b.whirl))
    ra, rb = np.asarray(a.r), np.asarray(b.r)
    assert np.nanmax(np.abs(ra - rb)) <= 1e-7 * clearance
    ea, eb = np.asarray(a.eigenvalues), np.asarray(b.eigenvalues)
    m = np.isfinite(ea) & np.isfinite(eb)
    assert np.array_equal(m, np.isfinite(ea))
    assert np.max(np.abs(ea - eb)[m]) <= 1e-7 * np.max(np.abs(ea[m]))
    # stability verdicts
    assert np.array_equal(np.nanmax(ea.real, axis=1) > 0, np.nanmax(eb.real, axis=1) > 0)


def _same(r1, r2, sl1=slice(None), sl2=slice(None)):
    assert list(r1.status)[sl1] == list(r2.status)[sl2]
    assert np.array_equal(np.asarray(r1.iterations)[sl1], np.asarray(r2.iterations)[sl2])
    for k in ("r", "h_min", "eigenvalues", "sleeve_share", "whirl"):
        x, y = np.asarray(getattr(r1, k))[sl1], np.asarray(getattr(r2, k))[sl2]
        assert np.array_equal(x, y, equal_nan=True), k


PCS = np.linspace(0.0, 0.3e6, 40)
AYS = [-2.5e-3, -1.85e-3, 0.5e-3, 2.5e-3]


@pytest.mark.parametrize("jacobian", ["reuse", "line"])
def test_rig_lines_same_equilibria_and_verdicts_fewer_linearisations(jacobian):
    inp = _rig_inputs(AYS, PCS)
    exact, s_exact = _run("rig", inp, "exact")
    new, s_new = _run("rig", inp, jacobian)
    assert set(exact.status) <= {"ok", "contact"} and "ok" in exact.status
    _within_tolerance("rig", new, exact)
    assert s_new.linearizations < s_exact.linearizations


def test_compressor_speed_line_same_equilibria_and_line_independence():
    asm = _asm("compressor_plain")
    speeds = np.linspace(40.0, 160.0, 30)
    w = np.concatenate([hz_to_rad_s(speeds), hz_to_rad_s(speeds[::-1])])
    p = np.zeros(len(w))
    a = np.array([asm.config_vector(None)] * len(w))
    n = len(speeds)
    restart = [1 if k in (0, n) else 0 for k in range(len(w))]
    exact, s_exact = _run("compressor_plain", (w, p, a, restart), "exact")
    for jac in ("reuse", "line"):
        new, s_new = _run("compressor_plain", (w, p, a, restart), jac)
        assert set(new.status) == {"ok"}
        _within_tolerance("compressor_plain", new, exact)
        assert s_new.linearizations < s_exact.linearizations
        alone, _ = _run("compressor_plain", (w[n:], p[n:], a[n:], [1] + [0] * (n - 1)), jac)
        _same(new, alone, slice(n, None))


@pytest.mark.parametrize("jacobian", ["reuse", "line"])
def test_rig_line_independent_of_the_previous_line_and_solver_history(jacobian):
    alone, _ = _run("rig", _rig_inputs([0.5e-3], PCS), jacobian)
    both, _ = _run("rig", _rig_inputs([-2.5e-3, 0.5e-3], PCS), jacobian)
    n = len(PCS)
    _same(both, alone, slice(n, 2 * n), slice(0, n))
    asm = _asm("rig")
    solver = _core.SystemSolver(asm.model)
    solver.equilibrium(hz_to_rad_s(30.0), 0.25e6, asm.config_vector(2.0e-3), np.zeros(0),
                       equilibrium_options({}))
    _run("rig", _rig_inputs([-1.5e-3], PCS[::-1]), "exact" if jacobian == "line" else "line",
         solver)
    again, _ = _run("rig", _rig_inputs([0.5e-3], PCS), jacobian, solver)
    _same(again, alone)


def test_single_equilibrium_with_reuse_and_guess():
    """SystemSolver.equilibrium with options.reuse_jacobian, cold and from a K_H guess: the
    exact Newton's root within the tolerance; a guess of the wrong shape is an InputError."""
    asm = _asm("rig")
    w, pc, a = hz_to_rad_s(50.0), 0.12e6, asm.config_vector(-1.85e-3)
    o = equilibrium_options({})
    ref = _core.SystemSolver(asm.model).equilibrium(w, pc, a, np.zeros(0), o)
    o2 = equilibrium_options({})
    o2.reuse_jacobian = True
    s = _core.SystemSolver(asm.model)
    cold = s.equilibrium(w, pc, a, np.zeros(0), o2)
    kh = np.asarray(s.linearize(np.asarray(cold.r), np.zeros(asm.n), w).KH)
    warm = s.equilibrium(w, 0.125e6, a, np.asarray(cold.r), o2, kh)
    ref2 = _core.SystemSolver(asm.model).equilibrium(w, 0.125e6, a, np.zeros(0), o)
    c = min(bc.clearance_m for bc in asm.bearings)
    for got, want in ((cold, ref), (warm, ref2)):
        assert got.status == want.status == "ok"
        assert got.residual < o.tol
        assert np.max(np.abs(np.asarray(got.r) - np.asarray(want.r))) <= 1e-7 * c
    with pytest.raises(InputError, match="kh_guess"):
        s.equilibrium(w, pc, a, np.zeros(0), o2, np.zeros((2, 2)))
    o2.reuse_contraction = 1.5
    with pytest.raises(InputError, match="reuse_contraction"):
        s.equilibrium(w, pc, a, np.zeros(0), o2)


def test_unknown_jacobian_is_an_input_error():
    with pytest.raises(InputError, match="jacobian"):
        _run("rig", _rig_inputs([0.5e-3], PCS[:3]), "secant")
