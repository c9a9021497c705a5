"""A sweep's parquet files carry what reproduces a point (the sweep store used as a user
would, 2026-12-05).

Before, every part's schema metadata (key ``rotordyn``) held the sweep id, the spec and model
hashes, the version and the units, but not the analysis, its options or the build: a reader of
``pyarrow.dataset.dataset(OUT)`` (or of part files copied elsewhere) could not tell
``n_modes = 6`` from the defaults. Now each part also holds ``analysis``, ``options`` and
``build_info``; with the model's TOML (the manifest's ``model``, whose SHA-256 prefix is
``model_hash``) one row is recomputed by the public API to round-off. Model: the compressor of
tests/data/models on plain bearings (not the paper rig)."""

import hashlib
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow.dataset as ds

import rotordyn
from rotordyn.model.paths import set_field
from rotordyn.sweep import run_sweep

MODEL = (Path(__file__).parent / "data" / "models" / "compressor_plain.toml").resolve()


def test_a_row_is_reproduced_from_the_files_metadata(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "meta"\nmodel = "{MODEL}"\n'
                    'analysis = "stability"\nchunk_size = 4\n[grid]\n'
                    '"bearings.*.clearance_m" = [1e-4, 1.4e-4]\n'
                    'speed_hz = [60.0, 110.0, 160.0]\n[options]\nn_modes = 3\n')
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1, progress=False)
    d = ds.dataset(out)
    meta = json.loads(d.schema.metadata[b"rotordyn"])
    assert meta["analysis"] == "stability" and meta["options"] == {"n_modes": 3}
    assert meta["build_info"]["rotordyn"] == meta["rotordyn"] == rotordyn.__version__
    manifest = json.loads((out / "_rotordyn_sweep.json").read_text())
    assert hashlib.sha256(manifest["model"].encode()).hexdigest()[:16] == meta["model_hash"]
    # every part says the same
    for f in d.files:
        assert json.loads(ds.dataset(f).schema.metadata[b"rotordyn"]) == meta
    df = pd.read_parquet(out)
    row = df[df.point_id == 4]
    system = set_field(rotordyn.System.from_toml(manifest["model"], is_text=True),
                       "bearings.*.clearance_m", float(row["bearings.*.clearance_m"].iloc[0]))
    r = getattr(rotordyn, meta["analysis"])(system, speed_hz=float(row.speed_hz.iloc[0]),
                                            **meta["options"])
    fr = r.to_frame()
    assert np.allclose(np.sort(fr.freq_hz), np.sort(row.freq_hz), rtol=1e-9)
    assert np.allclose(np.sort(fr.eig_real_1_per_s), np.sort(row.eig_real_1_per_s),
                       rtol=1e-7, atol=1e-7)
