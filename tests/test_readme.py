"""The README runs as written: every ```python block (in order, one namespace), then every
shell command of the plain ``` blocks (in order, continuation lines joined), all in one empty
temporary directory outside the clone (issue 18: the commands must run from any directory; the
sweep specs are built in). Commands starting with ``make`` are the entry points that run this
very test and are not re-run. Each command must exit 0."""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"


def blocks(text):
    """(language, body) of every fenced block, in order."""
    return re.findall(r"^```(\w*)\n(.*?)^```", text, flags=re.S | re.M)


def python_blocks(text):
    return [b for lang, b in blocks(text) if lang == "python"]


def shell_commands(text):
    """Commands of the plain ``` blocks: continuation lines joined, comments dropped."""
    cmds = []
    for block in [b for lang, b in blocks(text) if lang in ("", "sh", "bash", "console")]:
        for line in block.replace("\\\n", " ").splitlines():
            toks = shlex.split(line, comments=True)
            if toks:
                cmds.append(toks)
    return cmds


def test_shell_command_parsing():
    text = ("```python\nx = 1\n```\n\n```\nrotordyn a --x 1 \\\n    --y -2   # note\n"
            "# only a comment\nmake run\n```\n")
    assert shell_commands(text) == [["rotordyn", "a", "--x", "1", "--y", "-2"], ["make", "run"]]


def test_readme_runs_as_written(tmp_path, monkeypatch):
    text = README.read_text(encoding="utf-8")
    blocks = python_blocks(text)
    assert blocks, "README has no python example"
    monkeypatch.chdir(tmp_path)
    assert not str(tmp_path).startswith(str(ROOT))
    ns: dict = {}
    for b in blocks:
        exec(compile(b, "README.md", "exec"), ns)
    np.testing.assert_allclose(ns["m"].eigenvalues.imag, [85.389, 87.796, 251.785, 294.713],
                               atol=2e-3)
    assert abs(ns["r"].frequencies_hz[0] - 10.43) / 10.43 < 0.01
    assert (tmp_path / "my_rotor.toml").exists()
    assert ns["e"].status == "ok" and ns["t"].status == "ok" and ns["tr"].status == "ok"
    assert len(ns["c"].critical_speeds()) >= 2 and ns["ss"].A.shape[0] == 2 * len(ns["e"].r)
    # the Level I / limit cycle / thermal block: the values its comments state
    assert ns["l1"].verdict() == "FAIL (Level II required)"
    assert ns["cyc"].ok and abs(ns["cyc"].period_s - 39.9e-3) < 0.2e-3
    assert abs(ns["vg32"].viscosity_pa_s(40.0) / 870.0 * 1e6 - 32.0) < 1e-6

    cmds = shell_commands(text)
    run = [c for c in cmds if c[0] != "make"]
    assert len(run) >= 10 and all(c[0] == "rotordyn" for c in run), run
    env = dict(os.environ, PATH=os.path.dirname(sys.executable) + os.pathsep
               + os.environ.get("PATH", ""))
    for c in run:
        p = subprocess.run([sys.executable, "-m", "rotordyn.cli", *c[1:]], capture_output=True,
                           text=True, cwd=tmp_path, env=env)
        assert p.returncode == 0, f"README command failed: {shlex.join(c)}\n{p.stderr[-2000:]}"
        assert "rotordyn: warning" not in p.stderr, (shlex.join(c), p.stderr)
    assert (tmp_path / "out" / "fig9.png").stat().st_size > 10000
