"""The boundary surface by columns (rotordyn.sweep.surface, issue 22): on analytic fields of
max Re λ whose dense fine grid is cheap, every column's crossings (pairs of neighbouring fine
nodes along y in different states, both evaluated) and every node's inferred state equal the
dense grid's, from far fewer points than the cell refinement; the zero contour drawn from the
column field cuts each column where the dense column's linear interpolation does; then a
boundary-surface sweep of a rigid rotor on two short bearings (not the paper rig) against
dense columns of the same model.

The reference is the dense grid itself, so the comparison is exact (states) or to rounding
(interpolated positions, 1e-12 relative).
"""

import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import run_sweep
from rotordyn.sweep.boundary import Refinement, polylines
from rotordyn.sweep.spec import SweepSpec, fine_axes
from rotordyn.sweep.surface import ColumnPlan, column_field
from rotordyn.sweep.work import Job, run_chunk

sys.path.insert(0, str(Path(__file__).parent))
from test_linear_references import rigid_rotor  # noqa: E402
from test_sweep_boundary_refine import point_column  # noqa: E402


def _nodes(n, n0):
    return sorted({(2 * k * (n - 1) + n0 - 1) // (2 * (n0 - 1)) for k in range(n0)})


def _run(plan, st, z):
    """Run ``plan`` on the dense states ``st`` and values ``z``; the number of points."""
    n = 0
    while True:
        assert not any(plan.evaluated[p] for p in plan.points)  # never twice
        res = {p: (int(st[p]), float(z[p])) for p in plan.points}
        n += len(res)
        if not plan.advance(res):
            return n


def _cells(st, n0s):
    plan = Refinement(*[_nodes(s, n0) for s, n0 in zip(st.shape, n0s)])
    seen = np.zeros(st.shape, bool)
    view = {}
    while True:
        for idx in plan.points:
            seen[idx] = True
            view[idx] = int(st[idx])
        if not plan.advance(view):
            return seen.sum()


def _grid(n, nz=None):
    g = np.linspace(0.0, 1.0, n)
    return np.meshgrid(g, g, np.linspace(0.0, 1.0, nz or n), indexing="ij")


SURFACES = {
    # a wavy threshold surface whose height varies with z, and a failed region
    "wave": lambda X, Y, Z: (Y - 0.5 - 0.2 * np.sin(3 * np.pi * X) * np.cos(2 * Z) - 0.15 * Z,
                             (X > 0.8) & (Y < 0.15) & (Z > 0.5)),
    # a stable pocket (an ellipsoid leaving the box through x = 0, z = 0 and z = 1): columns
    # with two crossings beside columns with none (the surface folds over in y)
    "fold": lambda X, Y, Z: (((X - 0.4) / 0.5) ** 2 + ((Y - 0.45) / 0.3) ** 2
                             + ((Z - 0.5) / 0.8) ** 2 - 1.0, None),
    # steep: the crossing moves ~3 fine steps in y per fine step in x
    "steep": lambda X, Y, Z: (Y - 0.5 - 0.45 * np.sin(2 * np.pi * (X + 0.3 * Z)), None),
}


@pytest.mark.parametrize("n, nz", [(65, 65), (61, 33), (40, 17)])
@pytest.mark.parametrize("field", sorted(SURFACES))
def test_columns_equal_dense_grid(field, n, nz):
    """From a 9 x 9 x 5 coarse grid: every node's state (evaluated or inferred) and every
    column's crossings equal the dense grid's; each crossing's two nodes are evaluated; the
    points are far fewer than the cell refinement's (which evaluates every corner of every
    mixed fine cube) and no point is evaluated twice."""
    X, Y, Z = _grid(n, nz)
    z, failed = SURFACES[field](X, Y, Z)
    st = np.where(failed if failed is not None else False, 2, np.where(z < 0, 0, 1))
    plan = ColumnPlan(_nodes(n, 9), _nodes(n, 9), _nodes(nz, 5), st.shape)
    npts = _run(plan, st, z)
    np.testing.assert_array_equal(plan.states, st)
    dense = st[:, 1:, :] != st[:, :-1, :]
    got = dense & plan.evaluated[:, 1:, :] & plan.evaluated[:, :-1, :]
    np.testing.assert_array_equal(got, dense)
    assert dense.any()
    assert npts == plan.evaluated.sum()
    cells = _cells(st, (9, 9, 5))
    assert npts < 0.6 * cells, (npts, cells)


def test_two_dimensional_columns():
    """One z node (a boundary curve, 1001 x 1001 from 26 x 26): the same rule on the columns
    of the plane; every state equal to the dense grid's, and the zero contour of the column
    field cuts every column where the dense column's interpolation does (1e-12)."""
    n = 1001
    xs, ys = np.linspace(-2.5e-3, 2.5e-3, n), np.linspace(0.0, 0.3e6, n)
    X, Y = np.meshgrid(xs / 2.5e-3, ys / 0.3e6, indexing="ij")
    z = (Y - 0.5 - 0.2 * np.sin(3 * np.pi * X) - 0.05 * X)[:, :, None]
    st = np.where(z < 0, 0, 1)
    plan = ColumnPlan(_nodes(n, 26), _nodes(n, 26), [0], st.shape)
    npts = _run(plan, st, z)
    np.testing.assert_array_equal(plan.states, st)
    assert npts < 0.005 * n * n
    F = column_field(plan.states[:, :, 0], plan.evaluated[:, :, 0],
                     np.where(plan.evaluated, z, np.nan)[:, :, 0])
    lines = polylines(xs, ys, F)
    assert len(lines) == 1
    verts = np.concatenate(lines)
    for i in range(0, n, 13):
        col = z[i, :, 0]
        k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
        want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
        got = verts[np.abs(verts[:, 0] - xs[i]) <= 1e-12 * 2.5e-3, 1]
        np.testing.assert_allclose(np.unique(got), np.sort(want), rtol=1e-12)


def test_column_field_signs_and_exact_nodes():
    """The contour field keeps every evaluated value, has each node's state as its sign
    (NaN where failed), and is the crossing's line elsewhere on a crossing column."""
    S = np.array([[0, 0, 0, 1, 1, 1], [1, 1, 1, 1, 1, 1], [0, 0, 2, 2, 1, 1]], np.int8)
    E = np.zeros_like(S, bool)
    E[0, 2:4] = E[1, 0] = E[2, [0, 1, 4]] = True
    V = np.full(S.shape, np.nan)
    V[0, 2], V[0, 3], V[1, 0], V[2, 0], V[2, 1], V[2, 4] = -1.0, 3.0, 5.0, -2.0, -1.0, 4.0
    F = column_field(S, E, V)
    np.testing.assert_allclose(F[0], [-9.0, -5.0, -1.0, 3.0, 7.0, 11.0])
    np.testing.assert_allclose(F[1], [5.0] * 6)  # no crossing: the slice's largest |value|
    assert F[2, 0] == -2.0 and F[2, 1] == -1.0 and F[2, 4] == 4.0 and F[2, 5] == 5.0
    assert np.isnan(F[2, 2:4]).all()


SURFACE = """
schema = "rotordyn/sweep/1"
name = "lund-surface"
model = "{model}"
analysis = "boundary"
chunk_size = 16

[grid]
"rotor.disks.0.mass_kg" = {{start = 0.2, stop = 1.4, num = 5}}
speed_hz = {{start = 110.0, stop = 150.0, num = 5}}
gravity_m_s2 = {{start = 6.0, stop = 12.0, num = 3}}

[options]
x = "rotor.disks.0.mass_kg"
y = "speed_hz"
z = "gravity_m_s2"
resolution = {res}
{refine}
"""


def test_surface_sweep_by_columns_matches_dense_columns(tmp_path):
    """A boundary surface of the rigid rotor on two short bearings over (mass, speed,
    gravity) at 17³ from 5 x 5 x 3, by columns (the surface default), from under a fifth of
    the fine points: on three mass columns of three gravity slices, evaluated densely
    through the same chunk function, the crossing lies between the same two fine speeds,
    both evaluated, and the contour's speed there is the dense column's interpolation (1e-9
    relative: the equilibria start from other guesses)."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125, n_circ=72).to_toml(model)
    p = tmp_path / "s.toml"
    p.write_text(SURFACE.format(model=model, res=17, refine=""))
    res = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    assert res.manifest["n_points"] < 0.2 * 17**3
    ds = sw.open(tmp_path / "o")
    fr, b = ds.frame.drop_duplicates("point_id"), ds.boundary()
    spec = SweepSpec.from_toml(p)
    ax, _ = fine_axes(spec)
    job = Job(spec.name, model.read_text(), spec.analysis, spec.options, ax)
    x = "rotor.disks.0.mass_kg"
    ys = np.asarray(ax["speed_hz"])
    checked = 0
    for kz in (0, 8, 16):
        g = ax["gravity_m_s2"][kz]
        for i in (2, 8, 14):
            t = run_chunk(job, 0, 0, 0, [(i * 17 + j) * 17 + kz for j in range(17)])
            col = point_column(t)
            k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
            sub = fr[(fr[x] == ax[x][i]) & (fr["gravity_m_s2"] == g)]
            jj = np.sort(np.searchsorted(ys, sub["speed_hz"].to_numpy()))
            st = (sub.sort_values("speed_hz")["max_real_1_per_s"].to_numpy() >= 0)
            kb = [a for a, s0, s1 in zip(jj, st, st[1:]) if s0 != s1]
            assert np.all(np.diff(jj)[[list(jj).index(a) for a in kb]] == 1) if kb else True
            assert kb == list(k)
            if len(k):
                want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
                sl = b[(b["gravity_m_s2"] == g) & (np.abs(b[x] - ax[x][i]) <= 1e-12)]
                np.testing.assert_allclose(np.unique(sl["speed_hz"]), want, rtol=1e-9)
                checked += 1
    assert checked >= 6


def test_refine_option_is_checked(tmp_path):
    """options.refine is "columns" or "cells" (the error names the field)."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(model)
    p = tmp_path / "s.toml"
    p.write_text(SURFACE.format(model=model, res=9, refine='refine = "octree"'))
    with pytest.raises(rd.InputError, match=r"options.refine"):
        SweepSpec.from_toml(p)


CURVE = """
schema = "rotordyn/sweep/1"
name = "lund-curve"
model = "{model}"
analysis = "boundary"
chunk_size = 16

[grid]
"rotor.disks.0.mass_kg" = {{start = 0.2, stop = 1.4, num = 5}}
speed_hz = {{start = 110.0, stop = 150.0, num = 5}}

[options]
x = "rotor.disks.0.mass_kg"
y = "speed_hz"
resolution = 30
refine = "columns"
"""


def test_curve_sweep_by_columns_matches_dense_columns(tmp_path):
    """A boundary curve (no z) by columns, at resolution 30 from 5 x 5 (cells of 7.25 fine
    steps), on the rigid rotor: on every third column, evaluated densely, the crossing lies
    between the same two fine speeds, both evaluated, and the contour's speed is the dense
    column's interpolation (1e-9 relative)."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125, n_circ=72).to_toml(model)
    p = tmp_path / "s.toml"
    p.write_text(CURVE.format(model=model))
    res = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    assert res.manifest["n_points"] < 200  # of 900
    ds = sw.open(tmp_path / "o")
    fr, b = ds.frame.drop_duplicates("point_id"), ds.boundary()
    spec = SweepSpec.from_toml(p)
    ax, _ = fine_axes(spec)
    job = Job(spec.name, model.read_text(), spec.analysis, spec.options, ax)
    x = "rotor.disks.0.mass_kg"
    ys = np.asarray(ax["speed_hz"])
    for i in range(0, 30, 3):
        t = run_chunk(job, 0, 0, 0, [i * 30 + j for j in range(30)])
        col = point_column(t)
        k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
        assert len(k) == 1
        sub = fr[fr[x] == ax[x][i]].set_index("speed_hz")["max_real_1_per_s"]
        assert ys[k[0]] in sub.index and ys[k[0] + 1] in sub.index
        assert (sub.loc[ys[k[0]]] >= 0) != (sub.loc[ys[k[0] + 1]] >= 0)
        want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
        got = b[np.abs(b[x] - ax[x][i]) <= 1e-12]["speed_hz"].to_numpy()
        np.testing.assert_allclose(np.unique(got), want, rtol=1e-9)


def test_surface_by_columns_resumes_without_recomputing(tmp_path, monkeypatch):
    """A finished surface run again finds every chunk of the same plan in its store (the
    chunking depends on the plan only), evaluates nothing and writes the same boundary."""
    import rotordyn.sweep.boundary as bd

    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125, n_circ=72).to_toml(model)
    p = tmp_path / "s.toml"
    p.write_text(SURFACE.format(model=model, res=9, refine=""))
    first = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    b0 = sw.open(tmp_path / "o").boundary()

    def no_executor(*a, **k):
        raise AssertionError("a done chunk was computed again")

    monkeypatch.setattr(bd, "executor", no_executor)
    again = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    assert again.manifest["n_points"] == first.manifest["n_points"]
    assert again.manifest["points_by_reason"] == first.manifest["points_by_reason"]
    assert sw.open(tmp_path / "o").boundary().equals(b0)


def test_max_real_batch_own_starts_change_cost_not_answer():
    """``MaxRealBatchInput.starts``: a point started from another point's equilibrium (or a
    blend of two) gets the max Re λ of its cold start to round-off (the equilibrium is
    polished), the start is used (from the roots: under half the Reynolds solves of the
    cold starts), every equilibrium comes back in ``r``, and a start of the wrong shape is
    refused naming the field."""
    from rotordyn import _core
    from rotordyn.analysis.assembly import Assembled
    from rotordyn.model.builtin import paper_rig
    from rotordyn.sweep.points import equilibrium_options

    asm = Assembled(paper_rig())
    sol = _core.SystemSolver(asm.model)

    def batch(pcs, restart, starts=None, max_iter=100):
        inp = _core.MaxRealBatchInput()
        n = len(pcs)
        inp.omega = [2 * np.pi * 50.0] * n
        inp.pressure = pcs
        inp.a = np.array([asm.config_vector(-1.85e-3, None)] * n)
        inp.valid, inp.restart = [1] * n, restart
        inp.r0 = np.zeros(0)
        inp.options = equilibrium_options({"max_iter": max_iter})
        inp.xy_pairs, inp.rot_pairs = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()
        inp.sleeve = [q for bc in asm.bearings for q in bc.sleeve]
        if starts is not None:
            inp.starts = starts
        return _core.max_real_batch(sol, inp)

    pcs = [0.05e6, 0.15e6, 0.3e6]
    cold = batch(pcs, [1, 1, 1])
    R = np.asarray(cold.r)
    assert R.shape == (3, asm.n) and np.isfinite(R).all()
    S = np.full((3, asm.n), np.nan)
    S[0], S[2] = R[1], 0.5 * (R[0] + R[1])  # other points' equilibria; row 1: cold
    own = batch(pcs, [1, 1, 1], S)
    np.testing.assert_allclose(np.asarray(own.y), np.asarray(cold.y), rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(np.asarray(own.r), R, rtol=1e-9, atol=1e-15)
    # the start is used: from the roots themselves far fewer Reynolds solves than cold
    n0 = sol.reynolds_solves
    batch(pcs, [1, 1, 1])
    n_cold = sol.reynolds_solves - n0
    n0 = sol.reynolds_solves
    warm = batch(pcs, [1, 1, 1], R.copy())
    n_warm = sol.reynolds_solves - n0
    assert n_warm < 0.5 * n_cold, (n_warm, n_cold)
    np.testing.assert_allclose(np.asarray(warm.y), np.asarray(cold.y), rtol=1e-9, atol=1e-9)
    with pytest.raises(rd.InputError, match="starts"):
        batch(pcs, [1, 1, 1], np.zeros((2, asm.n)))
