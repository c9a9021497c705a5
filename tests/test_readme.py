"""The README's Python example runs as written and prints what it claims."""

import re
from pathlib import Path

import numpy as np

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_python_example_runs(tmp_path, monkeypatch):
    text = README.read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "README has no python example"
    monkeypatch.chdir(tmp_path)
    ns: dict = {}
    for b in blocks:
        exec(compile(b, "README.md", "exec"), ns)
    np.testing.assert_allclose(ns["m"].eigenvalues.imag, [85.389, 87.796, 251.785, 294.713],
                               atol=2e-3)
    assert abs(ns["r"].frequencies_hz[0] - 10.43) / 10.43 < 0.01
    assert (tmp_path / "my_rotor.toml").exists()
    assert ns["e"].status == "ok" and ns["t"].status == "ok" and ns["tr"].status == "ok"
    assert len(ns["c"].critical_speeds()) >= 2 and ns["ss"].A.shape[0] == 2 * len(ns["e"].r)
