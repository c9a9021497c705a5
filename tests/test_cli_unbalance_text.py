"""`rotordyn unbalance` text output on a model without a resonance in range (the overhung pump,
tests/data/models/pump_overhung.toml): it printed pandas' "Empty DataFrame / Columns: [...] /
Index: []" per station and said nothing of the speeds above the threshold of instability
(98.4 Hz on this pump), where the response is no steady orbit. It now prints the result's
summary line and "no resonance peak over LO–HI Hz"."""

import contextlib
import io
from pathlib import Path

from rotordyn.cli import main

PUMP = Path(__file__).parent / "data" / "models" / "pump_overhung.toml"


def test_unbalance_text_without_peaks_says_so_and_names_unstable_speeds():
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        code = main(["unbalance", str(PUMP), "--unbalance", "3,1e-4,0", "--speeds-hz",
                     "60:150:30", "--station", "3"])
    text = out.getvalue()
    assert code == 0
    assert "Empty DataFrame" not in text
    assert "station 3: no resonance peak over 60–150 Hz" in text
    assert "2 speeds above the threshold of instability" in text  # 120 and 150 Hz
