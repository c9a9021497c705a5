"""A resume says what it found and dropped (the sweep store used as a user would,
2026-12-05).

A driver killed mid-run, a worker killed, a part truncated on disk, a part renamed into place
but never logged, a temporary left by a write that never finished: the resume verified them
and recomputed their chunks — the dataset equal to an uninterrupted run's, byte for byte —
but said nothing, so a user whose disk damaged a part learned of it from nothing. Now each
removed file is named with the reason (``SweepResult.dropped``; the CLI prints one stderr line,
``--json`` carries ``dropped``). Model: the compressor of tests/data/models on plain bearings
(not the paper rig), 4 × 12 points in 4 chunks (one line each)."""

import json
import shutil
from pathlib import Path

import pandas as pd

from rotordyn.cli import main
from rotordyn.sweep import run_sweep

MODEL = (Path(__file__).parent / "data" / "models" / "compressor_plain.toml").resolve()


def test_resume_names_what_it_dropped(tmp_path, capsys):
    spec = tmp_path / "s.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "r"\nmodel = "{MODEL}"\n'
                    'analysis = "stability"\nchunk_size = 6\n[grid]\n'
                    '"bearings.*.clearance_m" = [1e-4, 1.2e-4, 1.4e-4, 1.6e-4]\n'
                    'speed_hz = {start = 60.0, stop = 170.0, num = 12}\n[options]\nn_modes = 2\n')
    ref, out = tmp_path / "ref", tmp_path / "out"
    assert run_sweep(spec, ref, threads=1, progress=False).dropped == ()
    shutil.copytree(ref, out)
    # a part cut short, a part the log never heard of (the driver died between its rename and
    # the log line: here the log forgets chunk 3), and an unfinished temporary
    (out / "part-000001-000001.parquet").write_bytes(
        (ref / "part-000001-000001.parquet").read_bytes()[:1000])
    log = out / "_chunks.jsonl"
    lines = log.read_text().splitlines()
    log.write_text("".join(ln + "\n" for ln in lines if '"part-000003-000003' not in ln))
    (out / "_tmp-part-000002-000002.parquet-x1").write_bytes(b"PAR1")
    capsys.readouterr()
    assert main(["sweep", str(spec), "--out", str(out), "--threads", "1", "--json"]) == 0
    cap = capsys.readouterr()
    summary = json.loads(cap.out)
    dropped = dict(summary["dropped"])
    assert set(dropped) == {"part-000001-000001.parquet", "part-000003-000003.parquet",
                            "_tmp-part-000002-000002.parquet-x1"}
    assert "1000 bytes, the log says" in dropped["part-000001-000001.parquet"]
    assert "not in the log" in dropped["part-000003-000003.parquet"]
    assert "unfinished write" in dropped["_tmp-part-000002-000002.parquet-x1"]
    assert "3 file(s)" in cap.err and "part-000001-000001.parquet (" in cap.err
    assert summary["chunks_done"] == summary["n_chunks"] == 4
    # recomputed: the same files, byte for byte, as the uninterrupted run
    for f in sorted(ref.glob("part-*.parquet")):
        assert (out / f.name).read_bytes() == f.read_bytes()
    assert sorted(p.name for p in out.glob("part-*")) == sorted(p.name for p in
                                                                 ref.glob("part-*"))
    assert pd.read_parquet(out).equals(pd.read_parquet(ref))
    # a resume of the finished directory finds nothing to drop and says nothing
    assert main(["sweep", str(spec), "--out", str(out), "--threads", "1"]) == 0
    assert "resume" not in capsys.readouterr().err


def test_another_models_directory_says_the_model_changed(tmp_path):
    """The same spec on an edited model into the old directory: refused naming what changed
    (before: 'spec or model changed', for either)."""
    import pytest

    from rotordyn.errors import InputError

    model2 = tmp_path / "m2.toml"
    model2.write_text(MODEL.read_text().replace("viscosity_pa_s = 0.018",
                                                "viscosity_pa_s = 0.020"))
    text = ('schema = "rotordyn/sweep/1"\nname = "r"\nmodel = "{}"\nanalysis = "stability"\n'
            'chunk_size = 6\n[grid]\nspeed_hz = [60.0, 120.0]\n[options]\nn_modes = 2\n')
    a, b = tmp_path / "a.toml", tmp_path / "b.toml"
    a.write_text(text.format(MODEL))
    b.write_text(text.format(model2))
    run_sweep(a, tmp_path / "out", threads=1, progress=False)
    # the model enters the check by its content only (its path is not part of the spec hash
    # since 2026-12-06, tests/test_sweep_spec_hash.py)
    with pytest.raises(InputError, match=r"'r': model changed \(hash \w+, the directory's "
                       r"\w+\)\); use another"):
        run_sweep(b, tmp_path / "out", threads=1, progress=False)
    # the model file edited in place: the spec is the same, the model is not
    model2.write_text(MODEL.read_text())
    run_sweep(b, tmp_path / "out2", threads=1, progress=False)
    model2.write_text(MODEL.read_text().replace("viscosity_pa_s = 0.018",
                                                "viscosity_pa_s = 0.020"))
    with pytest.raises(InputError, match=r"'r': model changed \(hash"):
        run_sweep(b, tmp_path / "out2", threads=1, progress=False)
