"""An output directory holding what the dataset's readers would take for data (the sweep store
used as a user would, 2026-12-05).

``pandas.read_parquet(OUT)`` and ``pyarrow.dataset.dataset(OUT)`` read every file and
sub-directory of OUT whose name does not begin with ``_`` or ``.``. Before, the store checked
only OUT's own ``*.parquet`` names: a sweep into a directory holding ``notes.txt`` ran, then
``pandas.read_parquet(OUT)`` failed ("Could not read schema from 'OUT/notes.txt'"); a sweep into
a directory holding another sweep in ``OUT/old/`` ran, and ``pandas.read_parquet(OUT)`` returned
both sweeps' rows mixed (480 + 160 rows of two sweeps, no error). Now either is one InputError
naming the entry before anything is written, on a new directory and on a resume alike, and the
user's entry is left alone. Model: the compressor of tests/data/models on plain bearings."""

import shutil
from pathlib import Path

import pandas as pd
import pytest

from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep

MODEL = (Path(__file__).parent / "data" / "models" / "compressor_plain.toml").resolve()


def _spec(tmp_path, name):
    p = tmp_path / f"{name}.toml"
    p.write_text(f'schema = "rotordyn/sweep/1"\nname = "{name}"\nmodel = "{MODEL}"\n'
                 'analysis = "stability"\nchunk_size = 4\n[grid]\n'
                 'speed_hz = [60.0, 110.0, 160.0]\n[options]\nn_modes = 2\n')
    return p


@pytest.fixture(scope="module")
def other(tmp_path_factory):
    d = tmp_path_factory.mktemp("other")
    run_sweep(_spec(d, "other"), d / "out", threads=1, progress=False)
    return d / "out"


@pytest.mark.parametrize("entry", ["notes.txt", "old"])
def test_a_directory_the_readers_would_mix_is_refused(tmp_path, other, entry):
    out = tmp_path / "out"
    out.mkdir()
    if entry == "old":
        shutil.copytree(other, out / "old")  # another sweep's parts, one level down
    else:
        (out / entry).write_text("my notes\n")
    with pytest.raises(InputError, match=rf"out: .* holds '{entry}', which "
                       r"pandas\.read_parquet\(OUT\) and pyarrow\.dataset would read"):
        run_sweep(_spec(tmp_path, "s"), out, threads=1, progress=False)
    assert sorted(p.name for p in out.iterdir()) == [entry]  # nothing written, nothing removed


def test_hidden_entries_are_allowed_and_a_resume_checks_too(tmp_path):
    out = tmp_path / "out"
    (out / ".git").mkdir(parents=True)
    (out / "_notes").write_text("skipped by the readers\n")
    spec = _spec(tmp_path, "s")
    run_sweep(spec, out, threads=1, progress=False)
    assert len(pd.read_parquet(out)) == 3 * 2
    (out / "plot.png").write_bytes(b"\x89PNG")
    with pytest.raises(InputError, match=r"holds 'plot\.png'"):
        run_sweep(spec, out, threads=1, progress=False)
    assert (out / "plot.png").exists()
