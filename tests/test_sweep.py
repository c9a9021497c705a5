"""Sweeps on dask (LocalCluster of worker processes) into a parquet dataset with a manifest:
results equal the direct API, a resumed sweep recomputes only missing chunks, a failed point
is a status row, bad specs name the field."""

import json
import os
import subprocess
import sys
import time

import numpy as np
import pyarrow.parquet as pq
import pytest

import rotordyn as rd
from rotordyn.sweep import SweepSpec, read_dataset, run_sweep

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


@pytest.fixture(scope="module")
def sweep_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("sweep")
    spec = d / "spec.toml"
    spec.write_text(SPEC)
    res = run_sweep(spec, d / "out", workers=2)
    return spec, d / "out", res


def test_dataset_layout_and_values(sweep_dir):
    spec, out, res = sweep_dir
    assert res.complete
    df = res.to_frame()
    assert list(df.columns[:6]) == ["sweep_id", "point_id", "chunk_id", "speed_hz",
                                    "chamber_pressure_pa", "config_ay_m"]
    assert list(df.columns[-2:]) == ["status", "message"]
    assert df["point_id"].nunique() == 6 and df["point_id"].dtype == np.int64
    assert set(df["status"].cat.categories) >= {"ok", "contact", "error"}
    # one point against the direct API (same code, other process)
    p = df[(df["config_ay_m"] == -1.85e-3) & (df["chamber_pressure_pa"] == 0.1e6)]
    st = rd.stability(rd.models.paper_rig(), 50.0, 0.1e6, -1.85e-3)
    np.testing.assert_allclose(np.sort(p["freq_hz"].to_numpy()), np.sort(st.frequencies_hz),
                               rtol=1e-8)
    md = json.loads(pq.read_schema(next(out.glob("part-*.parquet"))).metadata[b"rotordyn"])
    assert md["units"]["chamber_pressure_pa"]["units"] == "Pa" and "build_info" in md
    m = json.loads((out / "manifest.json").read_text())
    assert m["chunks_done"] == [0, 1] and m["n_points"] == 6 and "[[bearing]]" in m["model"]


def test_resume_recomputes_only_missing_chunks(sweep_dir):
    spec, out, _ = sweep_dir
    before = read_dataset(out)
    keep = out / "part-00000.parquet"
    t0 = keep.stat().st_mtime_ns
    (out / "part-00001.parquet").unlink()
    time.sleep(0.01)
    res = run_sweep(spec, out, workers=1)
    assert res.complete and keep.stat().st_mtime_ns == t0
    after = read_dataset(out)
    np.testing.assert_allclose(after["freq_hz"], before["freq_hz"], rtol=1e-12)
    # a finished sweep is never recomputed
    res = run_sweep(spec, out)
    assert keep.stat().st_mtime_ns == t0


def test_changed_spec_refuses_the_old_directory(sweep_dir, tmp_path):
    spec, out, _ = sweep_dir
    other = tmp_path / "other.toml"
    other.write_text(SPEC.replace("chunk_size = 3", "chunk_size = 2"))
    with pytest.raises(rd.InputError, match="different sweep"):
        run_sweep(other, out)


def test_failed_points_are_status_rows(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC.replace("config_ay_m = [-1.85e-3, 0.0]", "config_ay_m = [0.0, 0.05]")
                    .replace("analysis = \"stability\"", "analysis = \"equilibrium\""))
    res = run_sweep(spec, tmp_path / "o", workers=1)
    df = res.to_frame()
    assert res.complete and len(df) == 6
    bad = df[(df["config_ay_m"] == 0.05) & (df["chamber_pressure_pa"] <= 0.1e6)]
    # failed solves (no equilibrium with an open film), never the converged "contact" (issue 13)
    assert (bad["status"] == "no_equilibrium").all() and bad["message"].str.contains("film").all()
    assert (df[df["config_ay_m"] == 0.0]["status"] == "ok").all()


@pytest.mark.parametrize(("text", "field"), [
    (SPEC.replace("chunk_size = 3", "chunk_size = 3\ncolour = 1"), "spec.colour"),
    (SPEC.replace("speed_hz = 50.0", "rpm = 50.0"), "grid.rpm"),
    (SPEC.replace('analysis = "stability"', 'analysis = "magic"'), "analysis"),
    (SPEC.replace("speed_hz = 50.0", "speed_hz = {start = 1.0, stop = 2.0}"), "grid.speed_hz"),
])
def test_bad_specs_name_the_field(tmp_path, text, field):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(rd.InputError, match=field.replace(".", r"\.")):
        SweepSpec.from_toml(p)
    r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "sweep", str(p), "--out",
                        str(tmp_path / "o")], capture_output=True, text=True)
    assert r.returncode == 2 and field.split(".")[-1] in r.stderr


def test_plot_from_dataset(sweep_dir, tmp_path):
    _, out, _ = sweep_dir
    for kind in ("stability-map",):
        fig = tmp_path / f"{kind}.png"
        r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "plot", str(out), "--kind",
                            kind, "--out", str(fig)], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        assert fig.stat().st_size > 1000


def test_shipped_specs_parse():
    root = os.path.join(os.path.dirname(__file__), "..", "sweeps")
    names = [f for f in os.listdir(root) if f.endswith(".toml")]
    assert len(names) >= 4
    for f in names:
        s = SweepSpec.from_toml(os.path.join(root, f))
        assert s.points() and s.chunks()


def test_equilibrium_and_campbell_plots(tmp_path):
    """The equilibrium-loci and Campbell figures draw from their sweep datasets."""
    spec = tmp_path / "e.toml"
    spec.write_text(SPEC.replace('analysis = "stability"', 'analysis = "equilibrium"'))
    run_sweep(spec, tmp_path / "eq", workers=1)
    spec2 = tmp_path / "c.toml"
    spec2.write_text(SPEC.replace("config_ay_m = [-1.85e-3, 0.0]", "config_ay_m = 0.0")
                     .replace("chamber_pressure_pa = [0.0, 0.1e6, 0.2e6]",
                              "chamber_pressure_pa = 0.4e6")
                     .replace("speed_hz = 50.0", "speed_hz = [20.0, 40.0, 60.0]"))
    run_sweep(spec2, tmp_path / "camp", workers=1)
    for d, kind in (("eq", "equilibrium"), ("camp", "campbell")):
        fig = tmp_path / f"{kind}.png"
        r = subprocess.run([sys.executable, "-m", "rotordyn.cli", "plot", str(tmp_path / d),
                            "--kind", kind, "--out", str(fig)], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        assert fig.stat().st_size > 1000
