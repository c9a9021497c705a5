"""The ``limit_cycle`` sweep analysis (issue 19; docs/nonlinear.md, "Fig. 9 with Hopf type and
the bistable region"): along each line of the varied axis the cycle branch born at the line's
Hopf point, continued through folds, and the cycle at every grid value it passes by
shooting.

Model: the compressor on plain bearings (tests/data/models/compressor_plain.toml, not the
paper rig) on a coarse 36 × 4 film grid, over the speed. Its oil-whip branch
(tests/test_continuation.py, docs/nonlinear.md "A fold") is born at the Hopf point
(126.29 Hz on this grid), turns at a fold near 126.6 Hz into unstable cycles that grow as the
speed falls, and turns again at a fold near 121.8 Hz into the large stable whip cycle
(0.87-0.89 c) that exists above it: between the lower fold and the Hopf speed the stable
equilibrium and the stable whip cycle coexist.

References: the rows against rotordyn.periodic_orbit reached without continuation (a
transient at 130 Hz, then shooting at 127 Hz from it and at 125 Hz from the 127 Hz cycle:
another start, phase and path than the sweep's branch interpolation); the hopf records
against a ``hopf`` sweep of the same grid."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"

SPEC = """schema = "rotordyn/sweep/1"
name = "lc-compressor"
model = "{model}"
analysis = "{analysis}"
chunk_size = 1

[grid]
"bearings.*.n_circ" = 36
"bearings.*.n_axial" = 4
{axes}

[options]
vary = "speed_hz"
{options}
"""
#: the shooting and continuation options of the tests (docs/nonlinear.md: Broyden correctors,
#: the monodromy at 1e-4: a whip line in ~15 s CPU instead of ~40 s)
OPTIONS = """rtol = 1e-6
tol = 1e-4
ds = 0.1
ds_max = 0.3
sensitivity_rtol = 1e-4
newton = "broyden"
"""


def _spec(tmp_path, speeds, max_points=40, extra="", name="s.toml", analysis="limit_cycle",
          axes=""):
    p = tmp_path / name
    keys = {ln.split("=")[0].strip() for ln in extra.splitlines() if "=" in ln}
    base = "".join(ln + "\n" for ln in OPTIONS.splitlines() if ln.split("=")[0].strip()
                   not in keys)
    opts = "" if analysis == "hopf" else base + f"max_points = {max_points}\n" + extra
    axes = axes + "\nspeed_hz = [" + ", ".join(str(s) for s in speeds) + "]"
    p.write_text(SPEC.format(model=MODELS / "compressor_plain.toml", analysis=analysis,
                             axes=axes, options=opts))
    return p


def _system():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=4)
                                                 for b in s.bearings))


@pytest.fixture(scope="module")
def whip(tmp_path_factory):
    """The sweep over 121, 125, 127 Hz (one line, 1 thread) and its frame."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    tmp = tmp_path_factory.mktemp("lc")
    spec = _spec(tmp, [121.0, 125.0, 127.0])
    assert run_sweep(spec, tmp / "o", threads=1, progress=False).complete
    return tmp / "o", sw.open(tmp / "o").frame


def test_whip_line_flags_the_stable_cycle_beside_the_stable_equilibrium(whip):
    """121 Hz (below the lower fold): equilibrium stable, no cycle on the branch, not
    bistable. 125 Hz (between the fold and the Hopf speed): equilibrium stable and two cycles,
    the unstable inner one and the larger stable whip at about half the speed: bistable.
    127 Hz (above the Hopf speed): the stable whip beside an unstable equilibrium: a stable
    cycle but not bistable. The plot of the one-line dataset shades the one bistable cell."""
    import matplotlib

    matplotlib.use("Agg")
    from rotordyn.cli import main
    from rotordyn.plot.hopf_map import hopf_map

    out, f = whip
    hop = f[f["record"] == "hopf"]
    assert len(hop) == 1 and hop["status"].iloc[0] == "ok"
    assert 126.0 < hop["value"].iloc[0] < 126.6
    cyc = f[f["record"] == "cycle"]
    per = cyc.groupby("speed_hz")
    assert per["bistable"].max().to_dict() == {121.0: False, 125.0: True, 127.0: False}
    assert per["equilibrium_stable"].first().to_dict() == {121.0: True, 125.0: True,
                                                          127.0: False}
    assert list(cyc[cyc["speed_hz"] == 121.0]["status"]) == ["no_cycle"]
    g = cyc[cyc["speed_hz"] == 125.0].sort_values("cycle")
    assert list(g["status"]) == ["ok", "ok"] and list(g["stable"]) == [False, True]
    assert g["coexists_with_stable_equilibrium"].all()
    assert 0.5 < g["amplitude_c"].iloc[0] < g["amplitude_c"].iloc[1] < 1.0
    assert 0.45 < g["whirl_ratio"].iloc[1] < 0.55
    assert g["max_multiplier"].iloc[0] > 1 > g["max_multiplier"].iloc[1]
    top = cyc[cyc["speed_hz"] == 127.0]
    assert list(top["status"]) == ["ok"] and bool(top["stable"].iloc[0])
    assert not top["coexists_with_stable_equilibrium"].iloc[0]
    ax = hopf_map(f)
    assert len(ax.patches) == 1  # the bistable grid cell shaded
    fig = out.parent / "lc.png"
    assert main(["plot", str(out), "--kind", "hopf-map", "--out", str(fig)]) == 0
    assert fig.stat().st_size > 0


def test_whip_rows_equal_cycles_shot_without_continuation(whip):
    """The stable whip rows at 127 and 125 Hz against rotordyn.periodic_orbit at tol 1e-6:
    at 127 Hz from a 0.4 s transient at 130 Hz (equilibrium disturbed by 0.6 c), at 125 Hz from
    that 127 Hz cycle. The rows converge to tol = 1e-4 (the residual in units of the clearance,
    Broyden corrector), so a row's state may be off by up to tol/(1 − |μ_c|) ≈ 6.5e-4 c at
    |μ_c| = 0.845 — 7e-4 of the 0.88 c axis; how much of that a run uses depends on the last
    bits of the continuation's steps (they differ between machines and package builds).
    Tolerances, from that bound: period 1e-4, semi-major axis 1e-3, |μ_c| 1e-3 relative (the
    monodromy of both at sensitivity_rtol 1e-4). Measured at 127 / 125 Hz: period 8.6e-8 /
    2.7e-5, axis 7.8e-6 / 2.2e-4, |μ_c| 2.1e-5 / 3.6e-4 (numpy 2.4, scipy 1.17; an earlier
    machine: 8.2e-7 / 2.7e-7, 3.0e-6 / 1.1e-6, 4.7e-5 / 5.8e-5)."""
    from rotordyn.sweep.limit_cycle_rows import semi_major_axis

    _, f = whip
    s = _system()
    tr = rd.transient(s, 0.4, 130.0, disturbance_m=(0.0, 6e-5), n_out=4001)
    kw = dict(rtol=1e-6, tol=1e-6, n_out=1001, sensitivity_rtol=1e-4)
    o127 = rd.periodic_orbit(s, 127.0, start=tr, **kw)
    assert o127.ok, o127.message
    o125 = rd.periodic_orbit(s, 125.0, start=(o127.r[0], o127.v[0]), period_s=o127.period_s,
                             **kw)
    assert o125.ok, o125.message
    cyc = f[(f["record"] == "cycle") & (f["status"] == "ok")]
    for spd, d in ((127.0, o127), (125.0, o125)):
        assert d.stable
        row = cyc[(cyc["speed_hz"] == spd) & cyc["stable"].astype(bool)]
        assert len(row) == 1
        row = row.iloc[0]
        assert row["period_s"] == pytest.approx(d.period_s, rel=1e-4)
        A = semi_major_axis(d.journal_x_m[:, 0], d.journal_y_m[:, 0])
        assert row["amplitude_m"] == pytest.approx(A, rel=1e-3)
        assert row["max_multiplier"] == pytest.approx(abs(d.critical_multiplier), rel=1e-3)
        assert row["bearing"] == "NDE bearing"


def test_hopf_records_equal_a_hopf_sweep(tmp_path, whip):
    """The ``record = "hopf"`` rows carry the same crossing and l1 as a ``hopf`` sweep of the
    same grid, bit for bit: the shooting's ``tol`` is not the equilibrium tolerance of the
    threshold scan (it was: the crossing moved by 1e-3 Hz and l1 by 0.15 % on 36 × 6)."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    _, f = whip
    spec = _spec(tmp_path, [121.0, 125.0, 127.0], analysis="hopf")
    assert run_sweep(spec, tmp_path / "h", threads=1, progress=False).complete
    h = sw.open(tmp_path / "h").frame
    lc = f[f["record"] == "hopf"]
    assert len(h) == len(lc) == 1
    for c in ("value", "whirl_frequency_hz", "l1", "l1_error", "hopf_type", "alpha_prime",
              "amplitude_coefficient_m2", "status"):
        assert lc[c].iloc[0] == h[c].iloc[0], c


def test_rows_do_not_depend_on_threads_or_workers(tmp_path, whip):
    """125, 127 Hz: the same rows bit for bit on 1 thread of this process (after the other
    tests' solves of the same model) and in a fresh worker process (each line pins its
    chunk's fresh solver, so nothing solved before warm-starts it). The branch from the Hopf
    point reaches the unstable cycle at 125 Hz below the upper fold, as on the whip line;
    the line's bounds end above the lower fold, so the whip is not on the branch: 127 Hz is
    ``no_cycle`` (cycles off the branches born in the line's range are not searched for)."""
    import pandas as pd

    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    spec = _spec(tmp_path, [125.0, 127.0])
    assert run_sweep(spec, tmp_path / "a", threads=1, progress=False).complete
    assert run_sweep(spec, tmp_path / "b", workers=2, progress=False).complete
    fa, fb = sw.open(tmp_path / "a").frame, sw.open(tmp_path / "b").frame
    pd.testing.assert_frame_equal(fa, fb, check_exact=True)
    cyc = fa[fa["record"] == "cycle"]
    low = cyc[cyc["speed_hz"] == 125.0]
    assert list(low["status"]) == ["ok"] and not low["stable"].iloc[0]
    assert low["max_multiplier"].iloc[0] > 1 and not low["bistable"].iloc[0]
    # the same unstable inner cycle as on the whip line (another branch, same cycle). Each row
    # is converged to tol = 1e-4 c, its state within tol/|1 − μ_c| = 7e-4 c at μ_c = 1.14 near
    # the fold: two rows' axes (0.64 c) may differ by 2.2e-3, periods by ~1e-4. Measured:
    # axis 1.26e-3, period 4.2e-5 (numpy 2.4, scipy 1.17); an earlier machine: 6.8e-5, 5.5e-6
    _, f = whip
    inner = f[(f["record"] == "cycle") & (f["speed_hz"] == 125.0) & (f["cycle"] == 1)]
    assert low["amplitude_m"].iloc[0] == pytest.approx(inner["amplitude_m"].iloc[0], rel=3e-3)
    assert low["period_s"].iloc[0] == pytest.approx(inner["period_s"].iloc[0], rel=2e-4)
    assert list(cyc[cyc["speed_hz"] == 127.0]["status"]) == ["no_cycle"]


def test_a_branch_that_stops_early_gives_failed_rows(tmp_path):
    """max_points = 2: each branch stops after two points, short of the grid values; those
    points are rows with status ``failed`` and a message saying why (never a crashed sweep or
    a silent ``no_cycle``), without numbers."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    spec = _spec(tmp_path, [125.0, 127.0], max_points=2)
    assert run_sweep(spec, tmp_path / "o", threads=1, progress=False).complete
    f = sw.open(tmp_path / "o").frame
    cyc = f[f["record"] == "cycle"]
    assert list(cyc["status"]) == ["failed", "failed"]
    assert cyc["message"].str.contains("stopped early (max_points", regex=False).all()
    assert cyc["amplitude_m"].isna().all()
    assert list(f[f["record"] == "hopf"]["status"]) == ["ok"]


def test_newton_option_reaches_the_continuation(tmp_path, monkeypatch):
    """``options.newton = "fast"`` / ``"exact"`` (docs/nonlinear.md) load from the spec file,
    change the spec's hash (a dataset of one is not resumed by the other) and reach every
    continuation of the line (a spy on rotordyn.sweep.limit_cycle_rows.continuation;
    max_points = 2 keeps the run short: the rows are ``failed``, stopped early)."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import limit_cycle_rows, run_sweep
    from rotordyn.sweep.spec import SweepSpec

    specs = {m: _spec(tmp_path, [125.0, 127.0], max_points=2, extra=f'newton = "{m}"',
                      name=f"{m}.toml") for m in ("fast", "exact")}
    loaded = {m: SweepSpec.from_toml(p) for m, p in specs.items()}
    assert {m: s.options["newton"] for m, s in loaded.items()} == {"fast": "fast",
                                                                   "exact": "exact"}
    assert loaded["fast"].hash() != loaded["exact"].hash()
    seen = []
    real = limit_cycle_rows.continuation

    def spy(*args, **kw):
        seen.append(kw.get("newton"))
        return real(*args, **kw)

    monkeypatch.setattr(limit_cycle_rows, "continuation", spy)
    assert run_sweep(specs["fast"], tmp_path / "o", threads=1, progress=False).complete
    assert seen and set(seen) == {"fast"}
    f = sw.open(tmp_path / "o").frame
    assert list(f[f["record"] == "cycle"]["status"]) == ["failed", "failed"]


def test_bad_limit_cycle_specs_name_the_field(tmp_path):
    """An unknown station, a varied axis without bounds (one value), a start amplitude beyond
    the clearance and an unknown Newton method are InputErrors naming the field, before any
    solve."""
    from rotordyn.sweep.spec import SweepSpec

    with pytest.raises(rd.InputError, match="options.station"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="station = 99"))
    with pytest.raises(rd.InputError, match="options.vary.*bounds"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0]))
    with pytest.raises(rd.InputError, match="options.start_amplitude"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="start_amplitude = 2.0"))
    with pytest.raises(rd.InputError, match="options.newton.*'exact', 'fast'"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra='newton = "secant"'))
    spec = SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="station = 3"))
    assert spec.line_axis == "speed_hz" and spec.chunk_bounds() == [(0, 2)]


def test_starts_beyond_a_branch_end_at_another_hopf_point():
    """Which start a grid value beyond a branch's last point gets (measured case: the rig at
    a_y = −2.0 mm, whose branch born at the Hopf point 59.5 kPa grows to 0.93 c and shrinks
    again onto the equilibrium near −4 kPa; the first version shot 0–15 kPa from the leading
    order of the 59.5 kPa point, which closes the film, and wrote failed rows). A branch
    back at its own Hopf point: the leading order there, on the cycle side only; a branch
    ending at another Hopf point: the last point's cycle, only between it and that end."""
    from types import SimpleNamespace as NS

    import numpy as np

    from rotordyn.sweep.limit_cycle_rows import _starts

    n = 2
    orbit = [NS(r=np.full((3, n), float(k)), v=np.zeros((3, n)), period_s=0.04 + k)
             for k in range(3)]
    h = NS(value=60.0, cycle_side="below")

    def branch(p, stop, end):
        return NS(parameter=np.array(p), orbits=orbit, stop=stop,
                  bifurcations=({"kind": "hopf", "parameter": end},))

    far = branch([59.0, 30.0, -3.0], "hopf", -4.0)   # span 80: the end 64 from h
    assert [k for k, _ in _starts(h, far, 10.0, n, 80.0)] == ["branch"]  # one segment
    assert _starts(h, far, -3.5, n, 80.0)[0][0] == "branch"   # beyond the last point
    (how, st), = _starts(h, far, -3.5, n, 80.0)
    assert len(st) == 1 and st[0][2] == orbit[-1].period_s     # the last point's cycle
    assert _starts(h, far, -5.0, n, 80.0) == []               # beyond the end: none
    back = branch([50.0, 55.0, 59.0], "hopf", 59.9)           # back at its own point
    assert [k for k, _ in _starts(h, back, 59.5, n, 80.0)] == ["hopf"]
    assert _starts(h, back, 60.5, n, 80.0) == []    # beyond the Hopf point
    assert _starts(NS(value=60.0, cycle_side="above"), back, 59.5, n, 80.0) == []  # side
    assert [k for k, _ in _starts(h, back, 52.0, n, 80.0)] == ["branch"]
    (how, st), = _starts(h, back, 52.0, n, 80.0)
    assert len(st) == 2  # interpolated, then the nearer point
    assert np.allclose(st[0][0], 0.4) and np.allclose(st[1][0], 0.0)  # w = 2/5; point 0
