"""The adaptive boundary's refinement at any resolution (not only (res - 1) / (coarse - 1) a
power of two): on analytic fields of max Re λ whose dense fine grid is cheap, the crossings
the refinement finds on every column and every row, and the zero contour drawn from its
evaluated points, are those of the dense grid; then one sweep of a rigid rotor (Lund's case,
tests/test_sweep_analyses.py) at an odd resolution against dense columns of the same model.

The reference is the dense grid itself (every fine node evaluated), so the comparison is exact:
a crossing is a pair of neighbouring fine nodes in different states, and its interpolated
position uses the same two values (tolerance 1e-12 relative, rounding only).
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
from rotordyn.sweep.work import Job, run_chunk

sys.path.insert(0, str(Path(__file__).parent))
from test_linear_references import rigid_rotor  # noqa: E402


def point_column(t, name="max_real_1_per_s"):
    """A boundary chunk's per-point value (its first row: a point's mode rows share it)."""
    pid = t.column("point_id").to_numpy()
    first = np.r_[0, np.flatnonzero(np.diff(pid)) + 1]
    return np.asarray(t.column(name).to_pylist())[first]


def _states(z, failed):
    return np.where(failed, 2, np.where(z < 0, 0, 1))


def _refine(n, n0, st):
    """Run the plan on the state array ``st`` (n, n); return the evaluated mask."""
    nodes = sorted({(2 * k * (n - 1) + n0 - 1) // (2 * (n0 - 1)) for k in range(n0)})
    plan = Refinement(nodes, nodes)
    seen = np.zeros(st.shape, bool)
    view = {}
    while True:
        for i, j in plan.points:
            seen[i, j] = True
            view[i, j] = int(st[i, j])
        if not plan.advance(view):
            break
    return seen, plan


def _crossings(st, seen, axis):
    """Per line along ``axis``: the set of k with nodes k, k+1 evaluated and of different
    states."""
    s, m = (st, seen) if axis == 1 else (st.T, seen.T)
    d = (s[:, 1:] != s[:, :-1]) & m[:, 1:] & m[:, :-1]
    return [set(np.flatnonzero(r)) for r in d]


FIELDS = {
    # a wavy threshold curve across the whole plane
    "wave": lambda x, y: (y - 0.5 - 0.2 * np.sin(3 * np.pi * x) - 0.05 * x, None),
    # an unstable island (an ellipse several coarse cells wide) plus a failed corner
    "island": lambda x, y: (0.06 - ((x - 0.45) / 1.3) ** 2 - (y - 0.55) ** 2,
                            (x > 0.85) & (y < 0.2) & (y > 0.03)),
}


@pytest.mark.parametrize("n", [1001, 997, 38])
@pytest.mark.parametrize("field", sorted(FIELDS))
def test_refinement_crossings_equal_dense_grid(n, field):
    """Every column's and every row's crossings (stable/unstable/failed changes between
    neighbouring fine nodes) found by the refinement from a 26 x 26 coarse grid equal the
    dense grid's, at resolutions whose ratio to the coarse grid is 40 (1001), 39.84 (997,
    prime: cells of 39 and 40 steps) and 1.48 (38); far fewer points are evaluated."""
    xs = np.linspace(0.0, 1.0, n)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    z, failed = FIELDS[field](X, Y)
    st = _states(z, np.zeros_like(z, bool) if failed is None else failed)
    seen, plan = _refine(n, 26, st)
    for axis in (0, 1):
        dense = _crossings(st, np.ones_like(seen), axis)
        got = _crossings(st, seen, axis)
        assert got == dense
        assert sum(map(len, dense)) > 0
    if n > 100:
        assert seen.sum() < 0.02 * n * n, seen.sum()
    assert plan.points == set() and plan.cells == []


@pytest.mark.parametrize("n", [1001, 997])
def test_contour_on_columns_equals_dense_interpolation(n):
    """The zero contour through the evaluated points only (NaN elsewhere) cuts sampled columns
    exactly where the dense column's linear interpolation does (1e-12 relative)."""
    xs = np.linspace(-2.5e-3, 2.5e-3, n)
    ys = np.linspace(0.0, 0.3e6, n)
    X, Y = np.meshgrid(xs / 2.5e-3, ys / 0.3e6, indexing="ij")
    z, _ = FIELDS["wave"](X, Y)
    st = _states(z, np.zeros_like(z, bool))
    seen, _ = _refine(n, 26, st)
    lines = polylines(xs, ys, np.where(seen, z, np.nan))
    verts = np.concatenate(lines)
    for i in range(0, n, 97):
        col = z[i]
        k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
        want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
        # the contour's vertex on a column edge: x is the column's (to rounding)
        got = verts[np.abs(verts[:, 0] - xs[i]) <= 1e-12 * 2.5e-3, 1]
        np.testing.assert_allclose(np.unique(got), np.sort(want), rtol=1e-12)


def _spec(tmp_path, model, res, n0=5):
    p = tmp_path / "s.toml"
    p.write_text(f"""
schema = "rotordyn/sweep/1"
name = "lund-any"
model = "{model}"
analysis = "boundary"
chunk_size = 16

[grid]
"rotor.disks.0.mass_kg" = {{start = 0.2, stop = 1.4, num = {n0}}}
speed_hz = {{start = 110.0, stop = 150.0, num = {n0}}}

[options]
x = "rotor.disks.0.mass_kg"
y = "speed_hz"
resolution = {res}
""")
    return p


def test_sweep_at_odd_resolution_matches_dense_columns(tmp_path):
    """A boundary sweep at resolution 30 from a 5 x 5 coarse grid (29 / 4 = 7.25 steps per
    cell: the old power-of-two rule rejected it) of the rigid rotor on two short bearings;
    on four sampled columns, evaluated densely through the same chunk function, the crossing
    positions are those of the dense column (same fine nodes, 1e-9 relative on the
    interpolated speed: the equilibria start from different guesses)."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(model)
    p = _spec(tmp_path, model, 30)
    res = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    ds = sw.open(tmp_path / "o")
    fr = ds.frame.drop_duplicates("point_id")  # one row per point (its modes share it)
    assert res.manifest["fine_points"] == 900 and len(fr) == res.manifest["n_points"] < 900
    spec = SweepSpec.from_toml(p)
    ax, nodes = fine_axes(spec)
    assert nodes["speed_hz"] == [0, 7, 15, 22, 29]
    job = Job(spec.name, model.read_text(), spec.analysis, spec.options, ax)
    ny = len(ax["speed_hz"])
    x = "rotor.disks.0.mass_kg"
    xs = np.asarray(ax[x])
    ys = np.asarray(ax["speed_hz"])
    b = ds.boundary()
    for i in (3, 11, 16, 28):
        t = run_chunk(job, 0, 0, 0, [i * ny + j for j in range(ny)])
        col = point_column(t)
        k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
        assert len(k) == 1
        want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
        got = b[np.abs(b[x] - xs[i]) <= 1e-12]["speed_hz"].to_numpy()
        np.testing.assert_allclose(np.unique(got), want, rtol=1e-9)
        sub = fr[fr[x] == xs[i]].set_index("speed_hz")["max_real_1_per_s"]
        for kk in (k[0], k[0] + 1):
            assert sub.loc[ys[kk]] == pytest.approx(col[kk], rel=1e-6, abs=1e-9)


def test_resolution_below_coarse_count_is_rejected(tmp_path):
    """A fine grid coarser than the coarse grid names the field and the bound."""
    rig = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(rig)
    with pytest.raises(rd.InputError, match=r"options.resolution: expected >= 5"):
        SweepSpec.from_toml(_spec(tmp_path, rig, 4))


@pytest.mark.parametrize("n", [65, 61])
def test_surface_refinement_crossings_equal_dense_grid(n):
    """The refinement in three dimensions (a boundary surface over x, y, z) from a 9³ coarse
    grid: along every fine line of each axis the crossings equal the dense grid's (a wavy
    threshold surface whose height varies with z, and a failed region)."""
    g = np.linspace(0.0, 1.0, n)
    X, Y, Z = np.meshgrid(g, g, g, indexing="ij")
    z = Y - 0.5 - 0.2 * np.sin(3 * np.pi * X) * np.cos(2 * Z) - 0.15 * Z
    st = _states(z, (X > 0.8) & (Y < 0.15) & (Z > 0.5))
    nodes = sorted({(2 * k * (n - 1) + 8) // 16 for k in range(9)})
    plan = Refinement(nodes, nodes, nodes)
    seen = np.zeros(st.shape, bool)
    view = {}
    while True:
        for idx in plan.points:
            seen[idx] = True
            view[idx] = int(st[idx])
        if not plan.advance(view):
            break
    for axis in range(3):
        s = np.moveaxis(st, axis, -1)
        m = np.moveaxis(seen, axis, -1)
        dense = s[..., 1:] != s[..., :-1]
        got = dense & m[..., 1:] & m[..., :-1]
        np.testing.assert_array_equal(got, dense)
    assert dense.any() and seen.sum() < 0.25 * n**3


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
resolution = 9
"""


def test_boundary_surface_sweep(tmp_path):
    """A boundary surface over (mass, speed, gravity) of the rigid rotor (the load sets the
    eccentricity, hence the threshold) from a 5 x 5 x 3 coarse grid: a contour on every
    gravity slice whose evaluated points change sign, cutting the slice's dense column of the
    same model where the dense evaluation changes sign (same nodes, 1e-9 relative)."""
    model = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(model)
    p = tmp_path / "s.toml"
    p.write_text(SURFACE.format(model=model))
    res = run_sweep(p, tmp_path / "o", threads=2, progress=False)
    assert res.manifest["fine_points"] == 729 and res.manifest["n_points"] < 729
    ds = sw.open(tmp_path / "o")
    b = ds.boundary()
    # a contour on exactly the gravity slices whose evaluated points change sign
    mixed = ds.frame.groupby("gravity_m_s2")["point_stable"].nunique()
    assert set(b["gravity_m_s2"]) == set(mixed[mixed > 1].index)
    assert len(set(b["gravity_m_s2"])) >= 5
    spec = SweepSpec.from_toml(p)
    ax, _ = fine_axes(spec)
    job = Job(spec.name, model.read_text(), spec.analysis, spec.options, ax)
    ys = np.asarray(ax["speed_hz"])
    for i, kz in ((4, 4), (2, 8)):  # a mass column at two gravities
        pid = [(i * 9 + j) * 9 + kz for j in range(9)]
        t = run_chunk(job, 0, 0, 0, pid)
        col = point_column(t)
        k = np.flatnonzero(np.sign(col[1:]) != np.sign(col[:-1]))
        assert len(k) == 1
        want = ys[k] + (ys[k + 1] - ys[k]) * col[k] / (col[k] - col[k + 1])
        sl = b[(b["gravity_m_s2"] == ax["gravity_m_s2"][kz])
               & (np.abs(b["rotor.disks.0.mass_kg"] - ax["rotor.disks.0.mass_kg"][i]) <= 1e-12)]
        np.testing.assert_allclose(np.unique(sl["speed_hz"]), want, rtol=1e-9)


@pytest.mark.parametrize("zline, msg", [
    ('z = "speed_hz"', r"options.z: must differ from options.x and options.y"),
    ('z = "gravity_m_s2"', r"options.z: 'gravity_m_s2' must be a grid axis with >= 2 values"),
])
def test_surface_options_are_checked(tmp_path, zline, msg):
    """A third refined axis must be another grid axis with a range (error names the field)."""
    rig = tmp_path / "rigid.toml"
    rigid_rotor(1.0, 0.125).to_toml(rig)
    p = _spec(tmp_path, rig, 9)
    p.write_text(p.read_text() + zline + "\n")
    with pytest.raises(rd.InputError, match=msg):
        SweepSpec.from_toml(p)
