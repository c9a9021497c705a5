"""Sweeps into a parquet dataset: results equal the direct API, bad points are status rows,
the directory is a dataset pandas/pyarrow (and polars/duckdb when installed) read directly,
resume verifies every part, a second driver is refused, bad specs name the field."""

import json
import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import SweepSpec, run_sweep
from cli_output import error_lines

SPEC = """
schema = "rotordyn/sweep/1"
name = "t-stability"
model = "paper-rig"
analysis = "stability"
chunk_size = 3

[grid]
config_ay_m = [-1.85e-3, 0.0]
chamber_pressure_pa = [0.0, 0.1e6, 0.2e6]
speed_hz = 50.0
"""


def _spec(tmp_path, text=SPEC, name="spec.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.fixture(scope="module")
def sweep_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("sweep")
    spec = _spec(d)
    res = run_sweep(spec, d / "out", threads=2)
    return spec, d / "out", res


def test_dataset_layout_and_values(sweep_dir):
    spec, out, res = sweep_dir
    assert res.complete and res.counts == {"ok": 6, "failed": 0, "unstable": 0}
    df = res.to_frame()
    assert list(df.columns[:6]) == ["sweep_id", "point_id", "chunk_id", "speed_hz",
                                    "chamber_pressure_pa", "config_ay_m"]
    assert list(df.columns[-2:]) == ["status", "message"]
    assert df["point_id"].nunique() == 6 and df["point_id"].dtype == np.int64
    assert set(df["status"].cat.categories) >= {"ok", "contact", "error"}
    # one point against the direct API (same code, other thread)
    p = df[(df["config_ay_m"] == -1.85e-3) & (df["chamber_pressure_pa"] == 0.1e6)]
    st = rd.stability(rd.models.paper_rig(), 50.0, 0.1e6, -1.85e-3, warm_start=False)
    np.testing.assert_allclose(np.sort(p["freq_hz"].to_numpy()), np.sort(st.frequencies_hz),
                               rtol=1e-7)
    assert (p["point_stable"] == st.stable).all()
    # mode_stable is the mode's own, point_stable the point's
    np.testing.assert_array_equal(p["mode_stable"].astype(bool),
                                  p["eig_real_1_per_s"] < 0)
    # the equilibrium is in the stability rows
    e = rd.equilibrium(rd.models.paper_rig(), 50.0, 0.1e6, -1.85e-3, warm_start=False)
    np.testing.assert_allclose(p["journal_y_m"].iloc[0], e.journal_y_m[-1], rtol=1e-6)
    np.testing.assert_allclose(p["h_min_m"].iloc[0], e.h_min_m.min(), rtol=1e-6)
    files = sorted(out.glob("*.parquet"))
    md = json.loads(pq.read_schema(files[0]).metadata[b"rotordyn"])
    assert md["units"]["chamber_pressure_pa"]["units"] == "Pa" and md["rotordyn"]
    m = json.loads((out / "_rotordyn_sweep.json").read_text())
    assert m["n_points"] == 6 and "[[bearing]]" in m["model"]
    assert all(f.name.startswith("part-") for f in files)


def test_readers_read_the_directory(sweep_dir):
    """pandas.read_parquet(OUT) equals rotordyn.sweep.open(OUT); pyarrow, polars and duckdb
    read the directory (the bookkeeping files start with '_'; polars needs the glob
    OUT/*.parquet)."""
    _, out, _ = sweep_dir
    ds = sw.open(out)
    pd.testing.assert_frame_equal(pd.read_parquet(out), ds.frame)
    import pyarrow.dataset as pads

    assert pads.dataset(out, format="parquet").count_rows() == len(ds.frame)
    try:
        import polars as pl
    except ImportError:
        pl = None
    if pl is not None:
        # polars (1.44) reads every file of a bare directory, so it is given the glob
        assert pl.read_parquet(f"{out}/*.parquet").height == len(ds.frame)
    try:
        import duckdb
    except ImportError:
        duckdb = None
    if duckdb is not None:
        n = duckdb.sql(f"select count(*) from read_parquet('{out}/*.parquet')").fetchall()[0][0]
        assert n == len(ds.frame)
    mp = ds.pivot("max_real_1_per_s", "config_ay_m", "chamber_pressure_pa")
    assert mp.shape == (2, 3) and np.isfinite(mp.to_numpy()).all()


def test_exact_grid_values_and_index_columns(tmp_path):
    spec = SweepSpec.from_toml(_spec(tmp_path, SPEC.replace(
        "config_ay_m = [-1.85e-3, 0.0]", "config_ay_m = {start = -2.5e-3, stop = 2.5e-3, "
        "num = 21}").replace("speed_hz = 50.0", "speed_hz = {start = 1, stop = 1000, num = 4, "
                             "scale = \"log\"}")))
    ay = spec.axes["config_ay_m"]
    assert ay[1] == -0.00225 and repr(ay[1]) == "-0.00225" and ay[10] == 0.0
    assert spec.axes["speed_hz"] == [1.0, 10.0, 100.0, 1000.0]


def test_invalid_points_are_status_rows(tmp_path):
    """Contact and a point that cannot converge give status rows; every other point is
    computed. (A negative pressure was an error row too; since issue 21 it is refused when
    the spec loads, naming grid.chamber_pressure_pa[0].)"""
    text = SPEC.replace("chamber_pressure_pa = [0.0, 0.1e6, 0.2e6]",
                        "chamber_pressure_pa = [-1e5, 0.1e6]").replace(
        "config_ay_m = [-1.85e-3, 0.0]", "config_ay_m = [0.0, 0.05]").replace(
        "[grid]", "[options]\nmax_iter = 100\n\n[grid]")
    with pytest.raises(rd.InputError, match=r"grid\.chamber_pressure_pa\[0\]"):
        run_sweep(_spec(tmp_path, text, "neg.toml"), tmp_path / "neg", threads=1)
    text = text.replace("[-1e5, 0.1e6]", "[0.05e6, 0.1e6]")
    res = run_sweep(_spec(tmp_path, text), tmp_path / "o", threads=1)
    df = res.to_frame()
    assert res.complete and df["point_id"].nunique() == 4
    far = df[(df["config_ay_m"] == 0.05) & (df["chamber_pressure_pa"] > 0)]
    assert (far["status"] != "ok").all() and len(far) >= 1
    good = df[(df["config_ay_m"] == 0.0) & (df["chamber_pressure_pa"] > 0)]
    assert (good["status"] == "ok").all() and len(good) > 1
    # a point that cannot converge in its iteration budget
    text2 = text.replace("max_iter = 100", "max_iter = 1")
    res2 = run_sweep(_spec(tmp_path, text2, "s2.toml"), tmp_path / "o2", threads=1)
    d2 = res2.to_frame()
    assert res2.complete and d2["point_id"].nunique() == 4
    assert (d2["status"] == "not_converged").any()
    assert d2.loc[d2["status"] == "not_converged", "freq_hz"].isna().all()


def test_resume_verifies_parts(sweep_dir, tmp_path):
    spec, out, _ = sweep_dir
    before = sw.open(out).frame
    files = sorted(out.glob("part-*.parquet"))
    keep, bad = files[0], files[1]
    t0 = keep.stat().st_mtime_ns
    # truncate one part (a damaged file that still exists)
    bad.write_bytes(bad.read_bytes()[:100])
    res = run_sweep(spec, out, threads=1)
    assert res.complete and keep.stat().st_mtime_ns == t0
    pd.testing.assert_frame_equal(sw.open(out).frame, before)
    # a finished sweep is never recomputed
    run_sweep(spec, out, threads=1)
    assert keep.stat().st_mtime_ns == t0


def test_directory_safety(sweep_dir, tmp_path):
    spec, out, _ = sweep_dir
    # a changed spec refuses the old directory
    other = _spec(tmp_path, SPEC.replace("chunk_size = 3", "chunk_size = 2"), "other.toml")
    with pytest.raises(rd.InputError, match="different sweep"):
        run_sweep(other, out, threads=1)
    # --out pointing at a file
    f = tmp_path / "afile"
    f.write_text("x")
    with pytest.raises(rd.InputError, match="is a file"):
        run_sweep(spec, f, threads=1)
    # a second driver is refused while the lock is held
    (out / "_lock").write_text(json.dumps({"pid": os.getppid(), "host": os.uname().nodename}))
    try:
        with pytest.raises(rd.InputError, match="in use by another sweep"):
            run_sweep(spec, out, threads=1)
    finally:
        (out / "_lock").unlink()
    # a stale lock (its process is gone) is taken over
    (out / "_lock").write_text(json.dumps({"pid": 2**22 + 12345, "host": os.uname().nodename}))
    assert run_sweep(spec, out, threads=1).complete
    # leftover parts without a manifest are not mixed in
    d = tmp_path / "left"
    d.mkdir()
    (d / "part-000000-000000.parquet").write_bytes(next(out.glob("part-*")).read_bytes())
    with pytest.raises(rd.InputError, match="no sweep manifest"):
        run_sweep(spec, d, threads=1)
    # a corrupt manifest
    d2 = tmp_path / "corrupt"
    d2.mkdir()
    (d2 / "_rotordyn_sweep.json").write_text("{not json")
    with pytest.raises(rd.InputError, match="corrupt"):
        run_sweep(spec, d2, threads=1)
    # --no-resume refuses a directory holding another sweep
    renamed = _spec(tmp_path, SPEC.replace('name = "t-stability"', 'name = "other"'), "r.toml")
    with pytest.raises(rd.InputError, match="holds sweep 't-stability'"):
        run_sweep(renamed, out, threads=1, resume=False)


def test_failed_points_are_status_rows(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC.replace("config_ay_m = [-1.85e-3, 0.0]", "config_ay_m = [0.0, 0.05]")
                    .replace("analysis = \"stability\"", "analysis = \"equilibrium\""))
    res = run_sweep(spec, tmp_path / "o", threads=1)
    df = res.to_frame()
    assert res.complete and len(df) == 6
    bad = df[(df["config_ay_m"] == 0.05) & (df["chamber_pressure_pa"] <= 0.1e6)]
    # failed solves (no equilibrium with an open film), never the converged "contact" (issue 13)
    assert (bad["status"] == "no_equilibrium").all() and bad["message"].str.contains("film").all()
    assert (df[df["config_ay_m"] == 0.0]["status"] == "ok").all()


@pytest.mark.skipif(os.geteuid() == 0, reason="root ignores directory permissions")
def test_read_only_directory(tmp_path, sweep_dir):
    spec = sweep_dir[0]
    d = tmp_path / "ro"
    d.mkdir()
    d.chmod(0o500)
    try:
        with pytest.raises(rd.InputError, match="out: .*not writable"):
            run_sweep(spec, d, threads=1)
    finally:
        d.chmod(0o700)


@pytest.mark.parametrize(("text", "field"), [
    (SPEC.replace("chunk_size = 3", "chunk_size = 3\ncolour = 1"), "spec.colour"),
    (SPEC.replace("speed_hz = 50.0", "rpm = 50.0"), "grid.rpm"),
    (SPEC.replace('analysis = "stability"', 'analysis = "magic"'), "analysis"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = {start = 1.0, stop = 2.0}"), "grid.speed_hz"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = 50.0\n[options]\nn_modes = \"x\""),
     "options.n_modes"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = 50.0\n\"bearings.active.clearence_m\" = 1e-4"),
     "bearings.active.clearence_m"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = 50.0\nbearings.active.clearance_m = -1e-4"),
     "bearings.active.clearance_m"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = 50.0\nrotor.disks.9.mass_kg = 1.0"),
     "rotor.disks.9"),
    (SPEC.replace('analysis = "stability"', 'analysis = "waterfall"').replace(
        "speed_hz = 50.0", "speed_hz = 50.0\n[options]\nunbalances = [1]"), "unbalances"),
    (SPEC.replace('analysis = "stability"', 'analysis = "waterfall"').replace(
        "speed_hz = 50.0", "speed_hz = 50.0\n[options]\nunbalances = [[1, 1e-5, 0]]\n"
        "rtol = [1]"), "options.rtol"),
])
def test_bad_specs_name_the_field(tmp_path, text, field):
    p = _spec(tmp_path, text, "bad.toml")
    with pytest.raises(rd.InputError, match=field.replace(".", r"\.")):
        SweepSpec.from_toml(p)
    r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "sweep", str(p), "--out",
                        str(tmp_path / "o")], capture_output=True, text=True)
    assert r.returncode == 2 and field.split(".")[-1] in r.stderr
    assert len(error_lines(r.stderr)) == 1


def test_model_field_axes(tmp_path):
    """Dotted-path axes rebuild the model: a clearance axis on the active bearing and the
    configuration of every bearing; the values land in the rows."""
    text = SPEC.replace("config_ay_m = [-1.85e-3, 0.0]",
                        "bearings.active.clearance_m = [2.5e-4, 3.0e-4]").replace(
        "chamber_pressure_pa = [0.0, 0.1e6, 0.2e6]", "chamber_pressure_pa = 0.1e6").replace(
        'analysis = "stability"', 'analysis = "equilibrium"').replace(
        "speed_hz = 50.0", "speed_hz = 50.0\n\"bearings.*.config_ay_m\" = -1.85e-3")
    res = run_sweep(_spec(tmp_path, text), tmp_path / "o", threads=1)
    df = res.to_frame()
    assert res.complete and (df["status"] == "ok").all()
    base = rd.models.paper_rig()
    from rotordyn.sweep.paths import set_field

    s = set_field(base, "bearings.active.clearance_m", 2.5e-4)
    e = rd.equilibrium(s, 50.0, 0.1e6, -1.85e-3, warm_start=False)
    row = df[df["bearings.active.clearance_m"] == 2.5e-4]
    np.testing.assert_allclose(row["journal_y_m"].to_numpy()[-1], e.journal_y_m[-1], rtol=1e-6)
    assert (row["x_over_c"].abs().to_numpy() * 2.5e-4 == pytest.approx(
        row["journal_x_m"].abs().to_numpy()))


def test_cli_json_and_plot(sweep_dir, tmp_path):
    spec, out, _ = sweep_dir
    r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "sweep", str(spec), "--out",
                        str(out), "--threads", "1", "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert j["chunks_done"] == j["n_chunks"] == 2 and r.stderr == ""
    fig = tmp_path / "map.png"
    r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "plot", str(out), "--kind",
                        "stability-map", "--out", str(fig)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert fig.stat().st_size > 1000


def test_shipped_specs_parse():
    root = os.path.join(os.path.dirname(__file__), "..", "sweeps")
    names = [f for f in os.listdir(root) if f.endswith(".toml")]
    assert len(names) >= 4
    for f in names:
        s = SweepSpec.from_toml(os.path.join(root, f))
        assert s.n_points and s.chunk_bounds()


def test_progress_line_counts_and_eta():
    import io

    from rotordyn.sweep.execution import Progress

    s = io.StringIO()
    p = Progress(4, 1, {"ok": 3, "failed": 0, "unstable": 1}, stream=s, enabled=True)
    p.status("starting 2 worker processes")
    p.update({"ok": 2, "failed": 1, "unstable": 0})
    p.update({"ok": 3, "failed": 0, "unstable": 2})
    p.close()
    last = s.getvalue().strip().split("\r")[-1]
    assert "3/4 chunks" in last and "ok 8 failed 1 unstable 3" in last and "ETA" in last
    assert "starting 2 worker processes" in s.getvalue()
    q = io.StringIO()
    Progress(4, 0, {}, stream=q, enabled=False).update({"ok": 1})
    assert q.getvalue() == ""
