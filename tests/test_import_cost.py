"""Guards the start-up cost of the package and of the command line: ``import rotordyn``, and
the ``rotordyn`` command's argument parsing up to ``--help``, ``info`` or a bad-input exit 2,
load none of the libraries only some analyses need (pandas ~0.7 s of CPU under load,
matplotlib, dask, scipy.optimize, pyarrow): they are imported inside the functions that use
them (``to_frame()``, the solvers, the plots). The test suite starts the CLI in a subprocess
a few hundred times, and every user command pays the start-up.

Not a timed test: it checks ``sys.modules`` of a fresh interpreter, which is exact and does
not depend on the machine's load (the figures: benchmarks/bench_import.py). Each test failed
on the code before the imports were moved (pandas, scipy.optimize and pyarrow were loaded by
``import rotordyn``, matplotlib by a bad-model exit 2)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

HEAVY = ("pandas", "matplotlib", "dask", "distributed", "pyarrow", "scipy.optimize")


def _heavy_after(code: str, cwd=None) -> list:
    """Run ``code`` in a fresh interpreter (in ``cwd``), then report which of HEAVY it loaded
    (JSON on the last line of stdout, so that the code may print)."""
    probe = (f"{code}\nimport json, sys\n"
             f"print(json.dumps(sorted(m for m in {HEAVY!r} if m in sys.modules)))")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONSTARTUP"}
    p = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env,
                       cwd=cwd)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout.strip().splitlines()[-1])


def test_import_rotordyn_loads_no_heavy_library():
    assert _heavy_after("import rotordyn") == []


def test_public_api_is_complete_without_heavy_libraries():
    """Every name of ``rotordyn.__all__`` resolves with no heavy library loaded: the lazy
    imports moved into functions, not the names out of the package."""
    code = "import rotordyn\nfor n in rotordyn.__all__:\n    getattr(rotordyn, n)"
    assert _heavy_after(code) == []


@pytest.mark.parametrize(("argv", "code"), [
    (["--help"], 0),
    (["info"], 0),
    (["campbell", "--help"], 0),
    (["modes", "no-such-model"], 2),
    (["modes", "paper-rig", "--speed-hz", "fast"], 2),
    (["validate", "no-such-model"], 2),
    (["report", "no-such-model", "--out", "never-written"], 2),
])
def test_cli_parsing_and_bad_input_load_no_heavy_library(argv, code, tmp_path):
    """The CLI as its entry point runs it (``rotordyn.cli.main``), in a fresh interpreter:
    the parser of every command family is built, the arguments parsed, a bad input rejected
    with exit 2 before any heavy library is imported."""
    run = (f"from rotordyn.cli import main\n"
           f"try:\n    rc = main({argv!r})\nexcept SystemExit as e:\n    rc = e.code\n"
           f"assert rc == {code}, rc")
    assert _heavy_after(run, cwd=tmp_path) == []


def test_the_probe_sees_a_heavy_import():
    """The check can fail: a result table (``to_frame()``) does load pandas."""
    code = ("import rotordyn as rd\n"
            "rd.modes(rd.models.load('paper-rig'), n_modes=2, without_bearings=True).to_frame()")
    assert "pandas" in _heavy_after(code)
