"""The ``limit_cycle`` sweep analysis (issue 19; docs/nonlinear.md, "Fig. 9 with Hopf type and
the bistable region"): along each line of the varied axis the cycle branch born at the line's
Hopf point, continued through folds, and the cycle at every grid value it passes by
shooting.

References: the rows against a direct ``rotordyn.hopf`` / ``hopf_branch`` /
``rotordyn.periodic_orbit`` at the same grid value (shot from the nearest branch point, a
different start and phase than the sweep's interpolated one: the tolerance 1e-6 relative is
the shooting's convergence, tol 1e-7 of the clearance at rtol 1e-9, and the orbit's semi-major axis
refined between samples); the compressor on plain bearings over the speed, whose branch
(docs/nonlinear.md, tests/test_continuation.py) folds at 121.69 Hz with the stable whip
cycle coexisting with the stable equilibrium below the Hopf speed 126.5 Hz."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
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


def _direct_branch(system, value, span, start_amplitude=0.08, **kw):
    """The sweep's branch by the public API: rd.hopf at the crossing, the cycle shot from the
    leading order where its amplitude is start_amplitude·c, rd.continuation away from the
    Hopf point (the steps as the sweep chooses them)."""
    from rotordyn.analysis.hopf import hopf_cycle

    h = rd.hopf(system, "speed_hz", at=value)
    d = min((start_amplitude * h.length_scale_m) ** 2 / np.max(h.amplitude_coefficient),
            0.05 * span)
    sgn = 1 if h.cycle_side == "above" else -1
    c0 = hopf_cycle(system, h, h.value + sgn * d, rtol=kw["rtol"], tol=kw["tol"])
    a0 = max(c0.amplitude(b) for b in range(2)) / c0.length_scale_m
    ds0 = min(kw["ds"], max(0.5 * a0, 2e-3))
    return rd.continuation(system, "speed_hz", kw["bounds"], c0, direction=sgn, ds=ds0,
                           ds_min=min(1e-3, 0.5 * ds0), ds_max=0.2, rtol=kw["rtol"],
                           tol=kw["tol"], max_points=kw["max_points"], n_out=101)


def test_limit_cycle_rows_equal_direct_shooting_and_do_not_depend_on_workers(tmp_path):
    """Compressor on plain bearings (36 × 6), speeds 126.0, 126.6, 127.0 Hz: the same rows
    bit for bit with 1 thread and 2 worker processes; one ``hopf`` row (the crossing, as the
    ``hopf`` analysis); at 126.6 Hz, between the Hopf point (126.5 Hz) and the fold of the
    small cycles (126.64 Hz), two cycles (the small stable one and the unstable one beyond
    the fold), each equal to rotordyn.periodic_orbit at 126.6 Hz shot from the nearest point
    of a directly continued branch (period, semi-major axis, |μ_c| within 1e-6 relative)."""
    import pandas as pd

    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep
    from rotordyn.sweep.limit_cycle_rows import semi_major_axis

    speeds = [126.0, 126.6, 127.0]
    spec = _spec(tmp_path, speeds, rtol=1e-9, tol=1e-7)
    assert run_sweep(spec, tmp_path / "a", threads=1, progress=False).complete
    assert run_sweep(spec, tmp_path / "b", workers=2, progress=False).complete
    fa, fb = sw.open(tmp_path / "a").frame, sw.open(tmp_path / "b").frame
    pd.testing.assert_frame_equal(fa, fb, check_exact=True)
    hop = fa[fa["record"] == "hopf"]
    assert len(hop) == 1 and hop["status"].iloc[0] == "ok"
    assert hop["value"].iloc[0] == pytest.approx(126.5, abs=0.05)
    cyc = fa[fa["record"] == "cycle"]
    assert set(cyc["point_id"]) == {0, 1, 2}
    at = cyc[(cyc["speed_hz"] == 126.6) & (cyc["status"] == "ok")]
    assert len(at) >= 1
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    import dataclasses

    s = dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                              for b in s.bearings))
    br = _direct_branch(s, hop["value"].iloc[0], 1.0, rtol=1e-9, tol=1e-7, ds=0.1,
                        max_points=30, bounds=(125.95, 127.05))
    for _, row in at.iterrows():
        # the branch point nearest this cycle (same period and amplitude), shot at 126.6 Hz
        k = int(np.argmin(np.abs(br.period_s - row["period_s"]) / row["period_s"]
                          + np.abs(br.amplitude_m[:, 0] - row["amplitude_m"]) / 1e-4
                          + np.abs(br.parameter - 126.6)))
        o = br.orbits[k]
        d = rd.periodic_orbit(s, 126.6, start=(o.r[0], o.v[0]), period_s=o.period_s,
                              rtol=1e-9, tol=1e-7, n_out=1001)
        assert d.ok, d.message
        assert row["period_s"] == pytest.approx(d.period_s, rel=1e-6)
        A = semi_major_axis(d.journal_x_m[:, 0], d.journal_y_m[:, 0])
        assert row["amplitude_m"] == pytest.approx(A, rel=1e-6)
        assert row["max_multiplier"] == pytest.approx(abs(d.critical_multiplier), rel=1e-6)
        assert row["stable"] == d.stable
        assert row["bearing"] == "NDE bearing"
        assert not row["coexists_with_stable_equilibrium"]  # 126.6 Hz: above the Hopf point


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
