"""The ``limit_cycle`` sweep analysis (issue 19; docs/nonlinear.md, "Fig. 9 with Hopf type and
the bistable region"): along each line of the varied axis the cycle branch born at the line's
Hopf point, continued through folds, and the cycle at every grid value it passes by
shooting.

References: a row against rotordyn.periodic_orbit at the same grid value started from a
transient (another start and phase than the sweep's: the tolerance 1e-6 relative is the
shooting's convergence, tol 1e-8 of the clearance at rtol 1e-9, with the orbit's semi-major
axis refined between samples); the compressor on plain bearings over the speed, whose whip
branch (docs/nonlinear.md, tests/test_continuation.py) folds at 121.69 Hz with the stable
whip cycle coexisting with the stable equilibrium below the Hopf speed 126.5 Hz."""

from __future__ import annotations

from pathlib import Path

import pytest

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"

SPEC = """schema = "rotordyn/sweep/1"
name = "lc-compressor"
model = "{model}"
analysis = "limit_cycle"
chunk_size = 1

[grid]
"bearings.*.n_circ" = 36
"bearings.*.n_axial" = 6
speed_hz = [{speeds}]

[options]
vary = "speed_hz"
rtol = {rtol}
tol = {tol}
ds = 0.1
max_points = {max_points}
{extra}
"""


def _spec(tmp_path, speeds, tol=1e-4, max_points=30, extra="", name="s.toml", rtol=1e-6):
    p = tmp_path / name
    p.write_text(SPEC.format(model=MODELS / "compressor_plain.toml",
                             speeds=", ".join(str(s) for s in speeds), tol=tol, rtol=rtol,
                             max_points=max_points, extra=extra))
    return p


@pytest.mark.slow
def test_limit_cycle_rows_equal_direct_shooting_and_do_not_depend_on_workers(tmp_path):
    """Compressor on plain bearings (36 × 6), speeds 126.0 and 127.0 Hz (Hopf point
    126.5 Hz): the same rows bit for bit with 1 thread and 2 worker processes; one ``hopf``
    row (the crossing); at 127 Hz the stable whip cycle equals rotordyn.periodic_orbit
    started from a transient settled at 127 Hz (another start and phase than the sweep's
    branch interpolation): period, semi-major axis and |μ_c| within 1e-6 relative (rtol 1e-9,
    tol 1e-8: the shooting's convergence)."""
    import dataclasses

    import pandas as pd

    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from rotordyn.sweep.limit_cycle_rows import semi_major_axis

    spec = _spec(tmp_path, [126.0, 127.0], rtol=1e-9, tol=1e-8)
    assert run_sweep(spec, tmp_path / "a", threads=1, progress=False).complete
    assert run_sweep(spec, tmp_path / "b", workers=2, progress=False).complete
    fa, fb = sw.open(tmp_path / "a").frame, sw.open(tmp_path / "b").frame
    pd.testing.assert_frame_equal(fa, fb, check_exact=True)
    hop = fa[fa["record"] == "hopf"]
    assert len(hop) == 1 and hop["status"].iloc[0] == "ok"
    assert hop["value"].iloc[0] == pytest.approx(126.5, abs=0.05)
    cyc = fa[(fa["record"] == "cycle") & (fa["status"] == "ok")]
    row = cyc[(cyc["speed_hz"] == 127.0) & cyc["stable"].astype(bool)].iloc[-1]
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    tr = rd.transient(s, 1.0, 127.0, disturbance_m=(0.0, 1e-5), n_out=6001)
    d = rd.periodic_orbit(s, 127.0, start=tr, rtol=1e-9, tol=1e-8, n_out=1001)
    assert d.ok, d.message
    assert row["period_s"] == pytest.approx(d.period_s, rel=1e-6)
    A = semi_major_axis(d.journal_x_m[:, 0], d.journal_y_m[:, 0])
    assert row["amplitude_m"] == pytest.approx(A, rel=1e-6)
    assert row["max_multiplier"] == pytest.approx(abs(d.critical_multiplier), rel=1e-6)
    assert row["bearing"] == "NDE bearing"
    assert not row["coexists_with_stable_equilibrium"]  # 127 Hz: above the Hopf point


def test_compressor_bistable_interval_in_the_rows_and_the_plot(tmp_path):
    """The compressor on plain bearings (36 × 6) over the speed: the whip branch born at the
    Hopf point (126.5 Hz) folds at 126.64 Hz and at 121.69 Hz (docs/nonlinear.md), so below
    the Hopf speed down to the fold the stable whip cycle coexists with the linearly stable
    equilibrium (and the unstable cycle between them): bistable at 123 and 125 Hz, not at
    121 Hz (below the fold: no cycle) nor at 127 Hz (the equilibrium is unstable). The plot
    (`rotordyn plot --kind hopf-map`) of the one-line dataset is the cycles' bifurcation
    diagram with the bistable interval shaded."""
    import matplotlib

    matplotlib.use("Agg")
    import rotordyn.sweep as sw
    from rotordyn.cli import main
    from rotordyn.plot.hopf_map import hopf_map
    from rotordyn.sweep import run_sweep

    spec = _spec(tmp_path, [121.0, 123.0, 125.0, 127.0], max_points=40)
    assert run_sweep(spec, tmp_path / "o", threads=1, progress=False).complete
    f = sw.open(tmp_path / "o").frame
    cyc = f[f["record"] == "cycle"]
    per = cyc.groupby("speed_hz")
    bist = per["bistable"].max()
    assert bist.to_dict() == {121.0: False, 123.0: True, 125.0: True, 127.0: False}
    assert per["equilibrium_stable"].first().to_dict() == {121.0: True, 123.0: True,
                                                          125.0: True, 127.0: False}
    assert (cyc[cyc["speed_hz"] == 121.0]["status"] == "no_cycle").all()
    for spd in (123.0, 125.0):
        g = cyc[(cyc["speed_hz"] == spd) & (cyc["status"] == "ok")].sort_values("cycle")
        # the unstable inner cycle and the stable outer whip cycle (larger)
        assert list(g["stable"]) == [False, True]
        assert g["coexists_with_stable_equilibrium"].all()
        assert g["amplitude_c"].iloc[1] > g["amplitude_c"].iloc[0]
        assert 0.45 < g["whirl_ratio"].iloc[1] < 0.55
    assert cyc[(cyc["speed_hz"] == 127.0) & (cyc["status"] == "ok")]["stable"].any()
    ax = hopf_map(f)
    assert len(ax.patches) == 2  # the two bistable grid cells shaded
    fig = tmp_path / "lc.png"
    assert main(["plot", str(tmp_path / "o"), "--kind", "hopf-map", "--out", str(fig)]) == 0
    assert fig.stat().st_size > 0


def test_a_branch_that_stops_early_gives_failed_rows(tmp_path):
    """max_points = 2: the branch stops after two points, short of most grid values; those
    points are rows with status ``failed`` and a message saying why, never a crashed
    sweep or a silent ``no_cycle``."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    spec = _spec(tmp_path, [121.0, 127.0], max_points=2)
    assert run_sweep(spec, tmp_path / "o", threads=1, progress=False).complete
    f = sw.open(tmp_path / "o").frame
    cyc = f[f["record"] == "cycle"]
    bad = cyc[cyc["status"] == "failed"]
    assert len(bad) >= 1 and bad["message"].str.contains("stopped early").all()
    assert bad["amplitude_m"].isna().all()


def test_bad_limit_cycle_specs_name_the_field(tmp_path):
    """An unknown station and a varied axis without bounds (one value) are InputErrors
    naming the field, before any solve."""
    from rotordyn.sweep.spec import SweepSpec

    with pytest.raises(rd.InputError, match="options.station"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="station = 99"))
    with pytest.raises(rd.InputError, match="options.vary.*bounds"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0]))
    with pytest.raises(rd.InputError, match="options.start_amplitude"):
        SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="start_amplitude = 2.0"))
    spec = SweepSpec.from_toml(_spec(tmp_path, [121.0, 127.0], extra="station = 3"))
    assert spec.line_axis == "speed_hz" and spec.chunk_bounds() == [(0, 2)]
