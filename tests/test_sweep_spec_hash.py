"""A sweep resumes wherever its spec and model files are (2026-12-06).

The spec hash held the model reference as resolved, the TOML's absolute path: a project
directory moved, or mounted elsewhere on a cluster node, made the resume of an unchanged sweep
refuse with "spec changed". The model enters by its content (``model_hash``) only; a directory
written under the old hash still resumes. Two sweeps that differ only in their model must not
share dask task names, which held the spec hash alone. Model: the compressor of
tests/data/models on plain bearings (not the paper rig)."""

import json
import shutil
from pathlib import Path

import pytest

from rotordyn import InputError
from rotordyn.sweep import run_sweep
from rotordyn.sweep.spec import SweepSpec
from rotordyn.sweep.store import task_key

MODEL = Path(__file__).parent / "data" / "models" / "compressor_plain.toml"
SPEC = ('schema = "rotordyn/sweep/1"\nname = "h"\nmodel = "m.toml"\nanalysis = "stability"\n'
        'chunk_size = 3\n[grid]\n"bearings.*.clearance_m" = [1e-4, 1.3e-4]\n'
        'speed_hz = {start = 80.0, stop = 120.0, num = 3}\n[options]\nn_modes = 2\n')


def _project(d: Path, model_text: str) -> Path:
    d.mkdir()
    (d / "m.toml").write_text(model_text)
    (d / "s.toml").write_text(SPEC)
    return d / "s.toml"


def _parts(out: Path) -> dict:
    return {p.name: (p.stat().st_mtime_ns, p.read_bytes()) for p in out.glob("part-*")}


def test_moved_project_resumes_without_recomputing(tmp_path):
    spec_a = _project(tmp_path / "a", MODEL.read_text())
    out = tmp_path / "out"
    run_sweep(spec_a, out, threads=1, progress=False)
    before = _parts(out)
    assert len(before) == 2
    # the project moved: same files, another absolute path
    spec_b = tmp_path / "b" / "s.toml"
    shutil.move(str(tmp_path / "a"), str(tmp_path / "b"))
    a, b = SweepSpec.from_toml(spec_b), SweepSpec.from_toml(spec_b)
    assert a.hash() == b.hash()
    res = run_sweep(spec_b, out, threads=1, progress=False)
    assert res.dropped == ()
    assert _parts(out) == before     # nothing rewritten: every chunk was found done


def test_other_model_same_spec_is_refused_and_never_shares_tasks(tmp_path):
    spec_a = _project(tmp_path / "a", MODEL.read_text())
    text = MODEL.read_text()
    assert "viscosity_pa_s" in text
    other = text.replace("viscosity_pa_s = 0.018", "viscosity_pa_s = 0.02", 1)
    spec_b = _project(tmp_path / "b", other)
    sa, sb = SweepSpec.from_toml(spec_a), SweepSpec.from_toml(spec_b)
    assert sa.hash() == sb.hash()            # the spec is the same ...
    assert sa.load_model().to_toml() != sb.load_model().to_toml()   # ... the model is not
    out = tmp_path / "out"
    run_sweep(spec_a, out, threads=1, progress=False)
    man = json.loads((out / "_rotordyn_sweep.json").read_text())
    ha = task_key(man)
    with pytest.raises(InputError, match="model changed") as exc:
        run_sweep(spec_b, out, threads=1, progress=False)
    assert "spec changed" not in str(exc.value)
    hb = task_key({**man, "model_hash": "0" * 16})
    assert ha != hb and ha.startswith(man["spec_hash"])


def test_directory_written_under_the_old_hash_resumes(tmp_path):
    spec = _project(tmp_path / "a", MODEL.read_text())
    out = tmp_path / "out"
    run_sweep(spec, out, threads=1, progress=False)
    s = SweepSpec.from_toml(spec)
    mpath = out / "_rotordyn_sweep.json"
    man = json.loads(mpath.read_text())
    assert man["spec_hash"] == s.hash() != s.legacy_hash()
    man["spec_hash"] = s.legacy_hash()       # as an earlier rotordyn wrote it
    mpath.write_text(json.dumps(man, indent=1))
    before = _parts(out)
    res = run_sweep(spec, out, threads=1, progress=False)
    assert res.dropped == () and _parts(out) == before
    assert json.loads(mpath.read_text())["spec_hash"] == s.hash()   # rewritten
    # an unrelated hash is still refused
    man["spec_hash"] = "f" * 16
    mpath.write_text(json.dumps(man, indent=1))
    with pytest.raises(InputError, match="spec changed"):
        run_sweep(spec, out, threads=1, progress=False)
