"""The stability chunk's start along a line (issue 22): each point's equilibrium starts from
its predecessors' equilibria extrapolated in the line's input (here p_c; the polynomial
through up to three of them), not from the previous equilibrium copied.

References and tolerances:
- The plain continuation (``solver.equilibrium`` from the previous "ok" equilibrium, the
  chunk's loop before this change), reproduced here on a fresh solver. Both converge to the
  same root to the equilibrium tolerance (1e-10 of the load; the polish then steps on to the
  discrete root where the Jacobian is well conditioned): positions agree to 1e-7 of the
  clearance (observed ~1e-9), eigenvalues to 1e-7 of the largest |λ| (another root would
  differ by orders more).
- Cost: from the extrapolated start the line's Newton iterations (polish steps included)
  are fewer than from the copied start (observed 3.0 -> 1.8 per point on the paper rig); the
  copied start gives the loop's count exactly, so this fails on the code before (the
  chunk's Newton with the exact Jacobian at every step, ``jacobian="exact"``, as the loop's).
- A failing extrapolated start is retried from the previous equilibrium: the statuses equal
  the loop's.
Model: the paper rig, a Fig. 9 line over p_c at a_y = -1.5 mm, 50 Hz.
"""

import numpy as np

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.sweep.points import equilibrium_options
from rotordyn.units import hz_to_rad_s


def _line():
    s = rd.models.paper_rig()
    asm = Assembled(s)
    pcs = np.linspace(0.0, 0.3e6, 16)
    a = np.array([asm.config_vector(-1.5e-3)] * len(pcs))
    w = np.full(len(pcs), hz_to_rad_s(50.0))
    return asm, w, pcs, a


def test_extrapolated_start_same_roots_fewer_iterations():
    asm, w, pcs, a = _line()
    o = equilibrium_options({})
    res = _core.stability_batch(
        _core.SystemSolver(asm.model), w, pcs, a, [1] + [0] * (len(pcs) - 1), o, 0, False,
        FD_REL_STEP, asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
        [i for bc in asm.bearings for i in bc.sleeve], jacobian="exact")  # the loop's Newton
    solver = _core.SystemSolver(asm.model)
    m = asm.model
    prev, its = np.zeros(0), []
    clearance = min(bc.clearance_m for bc in asm.bearings)
    for i, pc in enumerate(pcs):
        e = solver.equilibrium(w[i], pc, a[i], prev, o)
        assert res.status[i] == e.status == "ok"
        prev = np.asarray(e.r)
        its.append(e.iterations)
        assert np.max(np.abs(np.asarray(res.r)[i] - prev)) <= 1e-7 * clearance
        lin = solver.linearize(e.r, np.zeros(len(prev)), w[i])
        mr = _core.modal(m.M, m.C + w[i] * m.G + lin.DH, m.K + lin.KH,
                         asm.rotor.xy_pairs(), 0, True, asm.rotor.rot_pairs())
        lam = np.sort_complex(np.asarray(mr.eigenvalues))
        got = np.sort_complex(np.asarray(res.eigenvalues)[i, :res.n_eig[i]])
        assert len(got) == len(lam)
        assert np.max(np.abs(got - lam)) <= 1e-7 * np.max(np.abs(lam))
    got_its = np.asarray(res.iterations)
    assert got_its[:2].tolist() == its[:2]  # cold start, then the copied start
    assert got_its[2:].sum() < np.sum(its[2:])


def test_split_line_restarts_at_the_split():
    """A line split into two batches (a chunk boundary: cold start there) gives the same
    roots as the whole line to the tolerance above; each batch alone is deterministic
    (the same call twice: identical bits)."""
    asm, w, pcs, a = _line()
    o = equilibrium_options({})

    def run(sl, restart):
        return _core.stability_batch(
            _core.SystemSolver(asm.model), w[sl], pcs[sl], a[sl], restart, o, 0, False,
            FD_REL_STEP, asm.rotor.xy_pairs(), asm.rotor.rot_pairs(),
            [i for bc in asm.bearings for i in bc.sleeve])

    n = len(pcs)
    whole = run(slice(0, n), [1] + [0] * (n - 1))
    again = run(slice(0, n), [1] + [0] * (n - 1))
    assert np.array_equal(np.asarray(whole.r), np.asarray(again.r))
    tail = run(slice(7, n), [1] + [0] * (n - 8))
    clearance = min(bc.clearance_m for bc in asm.bearings)
    assert np.max(np.abs(np.asarray(whole.r)[7:] - np.asarray(tail.r))) <= 1e-7 * clearance
