"""The stability chunk's cavitation-set carry (issue 22): along a sweep line each film's
Swift–Stieber solve starts from the last converged cavitation set (of the same equilibrium,
and of the previous point on the line) instead of the coarse-grid prediction; the sets are
forgotten at every line start and when the call returns.

References and tolerances:
- The same lines with the carry off (``carry_cavitation=False``: every equilibrium starts
  its first solve from the prediction). The Swift–Stieber problem has one solution and the
  active-set iteration stops on the same set from either start, so every output is equal
  bit for bit (observed on 1,000 points of the Fig. 9 map; only degenerate nodes, p = 0 and
  A p - b = 0 together, could differ, at round-off) — the iterations column included.
- Cost (not time): on a line as dense as a map's (60 points over 0-0.3 MPa) the active-set
  iterations per Reynolds solve fall with the carry (observed on the map at 100 points per
  line 1.74 -> 1.44, at 300 points 1.84 -> 1.25; 2.82 before this change, when every solve of
  an equilibrium started from the prediction). On a coarse line the previous point's set is
  a worse start than the prediction (12 points: 2.18 -> 2.44; break-even near 25). On the
  code before, ``carry_cavitation`` does not exist and ``reynolds_iterations`` is not
  exposed, so this fails there.
- Line independence: a line after another line in one call, or on a solver that ran other
  work before, equals the line alone on a fresh solver bit for bit (the carry and the
  extrapolated start both restart at the line's first point).
- A point alone against the same point inside a line: different Newton starts (cold vs
  extrapolated), the same root to the equilibrium tolerance (1e-10 of the load; no polish
  in sweeps): positions within 1e-7 of the clearance and eigenvalues within 1e-7 of the
  largest |lambda| (as tests/test_stability_line_start.py), statuses equal.
Model: the paper rig, Fig. 9 lines over p_c at 50 Hz.
"""

import numpy as np

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.sweep.points import equilibrium_options
from rotordyn.units import hz_to_rad_s

_ASM = None


def _asm():
    global _ASM
    if _ASM is None:
        _ASM = Assembled(rd.models.paper_rig())
    return _ASM


def _inputs(ays, pcs):
    asm = _asm()
    a = np.array([asm.config_vector(ay) for ay in ays for _ in pcs])
    p = np.tile(np.asarray(pcs, float), len(ays))
    w = np.full(len(p), hz_to_rad_s(50.0))
    restart = [1 if k == 0 else 0 for _ in ays for k in range(len(pcs))]
    return w, p, a, restart


def _run(inp, solver=None, carry=True):
    asm = _asm()
    solver = solver or _core.SystemSolver(asm.model)
    res = _core.stability_batch(
        solver, *inp, equilibrium_options({}), 0, False, FD_REL_STEP, asm.rotor.xy_pairs(),
        asm.rotor.rot_pairs(), [i for bc in asm.bearings for i in bc.sleeve],
        carry_cavitation=carry)
    return res, solver


def _same(r1, r2, sl1=slice(None), sl2=slice(None)):
    assert list(r1.status)[sl1] == list(r2.status)[sl2]
    assert np.array_equal(np.asarray(r1.iterations)[sl1], np.asarray(r2.iterations)[sl2])
    assert np.array_equal(np.asarray(r1.n_eig)[sl1], np.asarray(r2.n_eig)[sl2])
    for k in ("r", "h_min", "eigenvalues", "sleeve_share"):
        x, y = np.asarray(getattr(r1, k))[sl1], np.asarray(getattr(r2, k))[sl2]
        assert np.array_equal(x, y, equal_nan=True), k
    assert np.array_equal(np.asarray(r1.whirl)[sl1], np.asarray(r2.whirl)[sl2])


PCS = np.linspace(0.0, 0.3e6, 12)
AYS = [-2.5e-3, -1.5e-3, 0.5e-3, 2.5e-3]


def test_carry_same_bits_fewer_active_set_iterations():
    on, _ = _run(_inputs(AYS, PCS), carry=True)
    off, _ = _run(_inputs(AYS, PCS), carry=False)
    assert set(on.status) <= {"ok", "contact"} and "ok" in on.status
    _same(on, off)
    inp = _inputs(AYS[1:3], np.linspace(0.0, 0.3e6, 60))
    on, s_on = _run(inp, carry=True)
    off, s_off = _run(inp, carry=False)
    _same(on, off)
    assert s_on.reynolds_solves == s_off.reynolds_solves
    it_on = s_on.reynolds_iterations / s_on.reynolds_solves
    it_off = s_off.reynolds_iterations / s_off.reynolds_solves
    assert it_on < it_off


def test_line_independent_of_the_previous_line_and_solver_history():
    alone, _ = _run(_inputs([0.5e-3], PCS))
    both, _ = _run(_inputs([-2.5e-3, 0.5e-3], PCS))
    n = len(PCS)
    _same(both, alone, slice(n, 2 * n), slice(0, n))
    # a solver that ran other work before (an equilibrium far away, another batch)
    asm = _asm()
    solver = _core.SystemSolver(asm.model)
    solver.equilibrium(hz_to_rad_s(30.0), 0.25e6, asm.config_vector(2.0e-3), np.zeros(0),
                       equilibrium_options({}))
    _run(_inputs([-1.5e-3], PCS[::-1]), solver)
    again, _ = _run(_inputs([0.5e-3], PCS), solver)
    _same(again, alone)


def test_equilibrium_after_a_line_equals_a_fresh_one():
    """The carry is off again when the call returns: an equilibrium on the same solver is
    the fresh solver's, bit for bit."""
    asm = _asm()
    o = equilibrium_options({})
    args = (hz_to_rad_s(50.0), 0.12e6, asm.config_vector(-1.85e-3), np.zeros(0), o)
    fresh = _core.SystemSolver(asm.model).equilibrium(*args)
    _, solver = _run(_inputs([0.5e-3], PCS))
    after = solver.equilibrium(*args)
    assert after.status == fresh.status == "ok"
    assert np.array_equal(np.asarray(after.r), np.asarray(fresh.r))
    assert after.iterations == fresh.iterations


def test_point_alone_equals_the_point_inside_its_line():
    asm = _asm()
    line, _ = _run(_inputs([-1.5e-3], PCS))
    clearance = min(bc.clearance_m for bc in asm.bearings)
    for i in (0, 5, len(PCS) - 1):
        one, _ = _run(_inputs([-1.5e-3], PCS[i:i + 1]))
        assert one.status[0] == line.status[i]
        assert np.max(np.abs(np.asarray(one.r)[0] - np.asarray(line.r)[i])) <= 1e-7 * clearance
        k = one.n_eig[0]
        assert k == line.n_eig[i]
        a = np.sort_complex(np.asarray(one.eigenvalues)[0, :k])
        b = np.sort_complex(np.asarray(line.eigenvalues)[i, :k])
        assert np.max(np.abs(a - b)) <= 1e-7 * np.max(np.abs(a))


def test_carry_on_a_speed_line_of_a_compressor_on_plain_bearings():
    """Not the paper rig: a compressor on two plain journal bearings (two films, no sleeve), a
    line over the speed (the carried cavitation sets come from another speed, not another
    p_c): carry on and off give the same bits, the second line the same as if alone."""
    from pathlib import Path

    asm = Assembled(rd.System.from_toml(Path(__file__).parent / "data" / "models"
                                        / "compressor_plain.toml"))
    speeds = np.linspace(40.0, 160.0, 30)
    w = np.concatenate([hz_to_rad_s(speeds), hz_to_rad_s(speeds[::-1])])
    p = np.zeros(len(w))
    a = np.array([asm.config_vector(None)] * len(w))
    restart = [1 if k in (0, len(speeds)) else 0 for k in range(len(w))]

    def run(inp, carry):
        solver = _core.SystemSolver(asm.model)
        return _core.stability_batch(
            solver, *inp, equilibrium_options({}), 0, False, FD_REL_STEP,
            asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
            [i for bc in asm.bearings for i in bc.sleeve], carry_cavitation=carry), solver

    (on, s_on), (off, s_off) = run((w, p, a, restart), True), run((w, p, a, restart), False)
    assert set(on.status) == {"ok"}
    _same(on, off)
    n = len(speeds)
    alone, _ = run((w[n:], p[n:], a[n:], [1] + [0] * (n - 1)), True)
    _same(on, alone, slice(n, None))
    assert s_on.reynolds_iterations < s_off.reynolds_iterations
