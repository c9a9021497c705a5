"""Resuming a sweep directory whose parts were written with an older row schema (issue 20):
a stability sweep of a model with tilting films begun before its rows had the tilt list
columns (``tilt_bearing``, ``journal_theta_x_rad`` … ``tilt_h_min_m``, ``h_min_z_m``).

The old parts are made from a real run's parts by dropping those columns (the log's sizes,
hashes and row counts updated, as the older rotordyn would have logged them), one chunk left
to do. Before, the resume verified the parts (size, hash, rows: all fine), computed the
missing chunk with the new schema beside them, and left a dataset that no reader can
concatenate (``rotordyn.sweep.open``: "parts of different schemas") — the mixed dataset the
second test reproduces with the schema check switched off. Now the resume refuses at once,
naming the part and the missing columns, writes nothing, and ``--no-resume`` (resume=False)
recomputes every chunk into the dataset a fresh run writes.

Model: the compressor of tests/data/models on plain bearings with ``tilt = true``, the DE
housing misaligned about y (not the paper rig), 36 × 8; 3 chunks of 2 speeds."""

import dataclasses
import hashlib
import json
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.tilt_rows import TILT_OUTPUTS

MODELS = Path(__file__).parent / "data" / "models"


def _spec(tmp_path):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=36, n_axial=8) for b in s.bearings))
    s.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "spec.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "old"\nmodel = "m.toml"\n'
                    'analysis = "stability"\nchunk_size = 1\n[grid]\n'
                    '"bearings.1.config_theta_y_rad" = [1e-4, 2e-4, 3e-4]\n'
                    'speed_hz = [100.0, 150.0]\n[options]\nn_modes = 2\n')
    return spec


def _make_old(out: Path, drop_last: bool = True, columns=TILT_OUTPUTS) -> list[str]:
    """Rewrite the logged parts of ``out`` without ``columns`` (default the tilt columns: an
    older rotordyn's rows), log them as it would have, and forget the last chunk (left to
    do)."""
    log = out / "_chunks.jsonl"
    entries = [json.loads(x) for x in log.read_text().splitlines() if x.strip()]
    live = {e["file"]: e for e in entries if e["op"] == "file"}
    for e in entries:
        if e["op"] == "remove":
            live.pop(e["file"], None)
    last = max(live.values(), key=lambda e: e["hi"])
    keep = []
    for name, e in sorted(live.items()):
        if drop_last and e is last:
            (out / name).unlink()
            continue
        t = pq.read_table(out / name)
        t = t.drop_columns([c for c in columns if c in t.column_names])
        buf = pa.BufferOutputStream()
        pq.write_table(t, buf, compression="zstd")
        data = buf.getvalue().to_pybytes()
        (out / name).write_bytes(data)
        keep.append({**e, "bytes": len(data), "rows": t.num_rows,
                     "sha256": hashlib.sha256(data).hexdigest()})
    log.write_text("".join(json.dumps(e, sort_keys=True) + "\n" for e in keep))
    return [e["file"] for e in keep]


def test_resume_over_old_schema_parts_refuses_and_no_resume_recomputes(tmp_path):
    spec = _spec(tmp_path)
    fresh = tmp_path / "fresh"
    run_sweep(spec, fresh, threads=1)
    ref = sw.open(fresh).frame
    assert set(TILT_OUTPUTS) <= set(ref.columns)
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1)
    old = _make_old(out)
    assert len(old) == 2
    # the old dataset alone is consistent (readable, without the tilt columns)
    assert not set(TILT_OUTPUTS) & set(sw.open(out).frame.columns)
    before = sorted(p.name for p in out.iterdir())
    with pytest.raises(InputError) as exc:
        run_sweep(spec, out, threads=1)
    msg = str(exc.value)
    assert "another row schema" in msg and old[0] in msg and "tilt_bearing" in msg
    assert "--no-resume" in msg
    assert sorted(p.name for p in out.iterdir()) == before  # nothing written
    assert not set(TILT_OUTPUTS) & set(sw.open(out).frame.columns)
    # --no-resume recomputes every chunk: the fresh run's dataset
    run_sweep(spec, out, threads=1, resume=False)
    got = sw.open(out).frame
    assert list(got.columns) == list(ref.columns) and len(got) == len(ref)
    for c in ("eig_real_1_per_s", "journal_x_m"):
        assert got[c].tolist() == ref[c].tolist()
    assert got["tilt_h_min_m"].map(list).tolist() == ref["tilt_h_min_m"].map(list).tolist()


def test_without_the_check_the_resume_mixes_two_schemas(tmp_path, monkeypatch):
    """What the check prevents: with it switched off (the store told no schema, as before),
    the resume writes the missing chunk with the new schema beside the old parts, and the
    directory can no longer be read as one dataset."""
    import rotordyn.sweep.runner as runner

    spec = _spec(tmp_path)
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1)
    _make_old(out)
    monkeypatch.setattr(runner, "job_schema", lambda job, base: None)
    run_sweep(spec, out, threads=1)
    with pytest.raises(InputError, match="different schemas"):
        sw.open(out)


def test_a_resume_of_the_same_schema_still_resumes(tmp_path):
    spec = _spec(tmp_path)
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1)
    ref = sw.open(out).frame
    log = out / "_chunks.jsonl"
    lines = [x for x in log.read_text().splitlines() if x.strip()]
    last = json.loads(lines[-1])
    (out / last["file"]).unlink()
    log.write_text("\n".join(lines[:-1]) + "\n")
    run_sweep(spec, out, threads=1)
    got = sw.open(out).frame
    assert got["eig_real_1_per_s"].tolist() == ref["eig_real_1_per_s"].tolist()


def test_resume_of_a_thermal_sweep_before_carry_over_effective_refuses(tmp_path):
    """A thermal sweep (analysis "thermal") begun before its rows had ``carry_over_effective`` (the
    effective carry-over of a metered supply below the film's demand, 2026-12-06): the resume
    names the column and --no-resume; nothing is written. Model: the compressor on plain
    thermal bearings (36 × 8), not the paper rig."""
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))
    s.to_toml(tmp_path / "m.toml")
    spec = tmp_path / "spec.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "old-thermal"\nmodel = "m.toml"\n'
                    'analysis = "thermal"\nchunk_size = 1\n[grid]\n'
                    'speed_hz = [100.0, 150.0, 200.0]\n')
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1, progress=False)
    assert "carry_over_effective" in sw.open(out).frame.columns
    old = _make_old(out, columns=("carry_over_effective",))
    assert len(old) == 2
    before = sorted(p.name for p in out.iterdir())
    with pytest.raises(InputError) as exc:
        run_sweep(spec, out, threads=1, progress=False)
    msg = str(exc.value)
    assert "another row schema" in msg and "carry_over_effective" in msg
    assert "--no-resume" in msg
    assert sorted(p.name for p in out.iterdir()) == before
    run_sweep(spec, out, threads=1, resume=False, progress=False)
    got = sw.open(out).frame
    assert len(got) == 6 and got["carry_over_effective"].notna().all()  # 3 speeds × 2 films
