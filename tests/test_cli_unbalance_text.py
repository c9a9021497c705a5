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
    import numpy as np

    import rotordyn as rd

    u = rd.unbalance_response(rd.System.from_toml(PUMP), [(3, 1e-4, 0.0)],
                              np.array([60.0, 90.0, 120.0, 150.0]), stations=[3])
    n_unstable = int(np.sum(~np.asarray(u.stable)))
    assert n_unstable >= 1  # the pump's threshold lies in the range
    assert f"{n_unstable} speeds above the threshold of instability" in text


def test_unbalance_text_when_no_speed_converged_names_why():
    """The compressor with its drive-end housing misaligned by 3.99 mrad (θ L/2 = 0.9975 c):
    no speed has an equilibrium. The text said "no resonance peak" as if the response had
    been computed, and stderr named the speeds without why; --json had no statuses."""
    import json

    import rotordyn as rd

    model = Path(__file__).parent / "data" / "models" / "compressor_plain.toml"
    text = model.read_text().replace(
        'name = "DE bearing"', 'name = "DE bearing"\ntilt = true\nconfig_theta_x_rad = 3.99e-3')
    s = rd.System.from_toml(text, is_text=True)
    u = rd.unbalance_response(s, [(3, 1e-4, 0.0)], [100.0, 150.0], stations=[3])
    assert not any(st in ("ok", "contact") for st in u.point_status)
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        f = Path(d) / "m.toml"
        f.write_text(text)
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(["unbalance", str(f), "--unbalance", "3,1e-4,0", "--speeds-hz",
                         "100,150", "--station", "3"])
        assert code == 1
        assert "station 3: no converged speed" in out.getvalue()
        assert "no resonance peak" not in out.getvalue()
        msg = u.point_message[0]
        assert msg and msg in err.getvalue()
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            main(["unbalance", str(f), "--unbalance", "3,1e-4,0", "--speeds-hz", "100,150",
                  "--station", "3", "--json"])
        j = json.loads(out.getvalue())
        assert j["point_status"] == [str(x) for x in u.point_status]
        assert j["point_message"][0] == msg
