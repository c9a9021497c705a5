"""``rotordyn bearing ... --supply-temperature-c ...`` on a starved plain film: a metered
``--supply-flow-m3-s`` below what the film draws (status "starved", the Python API raises
``StarvedFilmError``) is a status record like the command's other failed statuses (the tilted
thermal and the pad bearings' aligned thermal equilibria, docs/film-physics.md): text or
``--json`` with ``status`` "starved" and the message naming the supply and the least supply
that feeds the film, exit 1.

Found by QA (qa21, 2026-12-06): the aligned plain film let the StarvedFilmError through to the
CLI's general error path ("error: ..." on stderr, nothing on stdout, exit 1), so ``--json``
printed no record.

Models: the compressor's DE bearing (tests/data/models/compressor_plain_thermal.toml, D 0.1 m,
L 0.05 m, c 0.1 mm, ISO VG 32 at 45 °C, 150 Hz; not the paper rig) through ``--model-file``
and built from flags. The least supply that feeds the film (``least_supply_m3_s``,
bracketed to 1 % by the command) is checked against the film: fed (status ok, exit 0) at
1.001 × it and starved 2 % below it. The C++ message's own shortfall "Q - Q_r" at the starved
iterate's flows is an estimate only: on this bearing from 1e-7 m³/s it named 3.44e-5 m³/s
(effective model; the bracket 7.26e-5) and 1.33e-4 (THD; the bracket 6.77e-5)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
PLAIN_THERMAL = str(MODELS / "compressor_plain_thermal.toml")
FLAGS = ["--diameter-m", "0.1", "--length-m", "0.05", "--clearance-m", "1e-4",
         "--n-circ", "48", "--n-axial", "8"]
MODEL = ["--model-file", PLAIN_THERMAL, "--bearing", "DE bearing", "--n-circ", "48",
         "--n-axial", "8"]
OIL = ["--supply-temperature-c", "45", "--oil-walther", "40", "32", "100", "5.4",
       "--density-kg-m3", "860", "--carry-over", "0.4"]
POINT = ["--speed-hz", "150", "--load-n", "0", "-1500"]
QMIN = re.compile(r"the shortfall at this state, Q - Q_r = ([0-9.eE+-]+) m\^3/s")


def _run(capsys, *argv):
    code = main(["bearing", *argv])
    cap = capsys.readouterr()
    return code, cap.out, cap.err


@pytest.mark.parametrize("model", ["effective", "thd"])
@pytest.mark.parametrize("src", ["flags", "model_file"])
def test_starved_plain_film_is_a_status_record(capsys, model, src):
    geo = FLAGS if src == "flags" else MODEL
    argv = [*geo, *OIL, *POINT, "--model", model]
    code, out, err = _run(capsys, *argv, "--supply-flow-m3-s", "1e-7", "--json")
    assert code == 1, err
    assert out, f"no record on stdout (stderr: {err!r})"
    rec = json.loads(out)
    assert rec["status"] == "starved"
    assert "starved" in rec["message"] and "Q_f = 1e-07" in rec["message"]
    assert rec["supply_flow_m3_s"] == 1e-7 and rec["load_n"] == [0.0, -1500.0]
    assert rec["thermal_model"] == model
    assert "k_n_per_m" not in rec and "thermal" not in rec  # nothing of a failed point
    # the C++ estimate (the shortfall Q - Q_r at the starved iterate's flows) is kept; the
    # least supply that feeds the film is bracketed by the command
    assert QMIN.search(rec["message"]) is not None
    qmin = rec["least_supply_m3_s"]
    assert f"the least supply that feeds the film: {qmin:.4g} m^3/s" in rec["message"]
    assert 1e-7 < qmin < 1e-3  # a plausible film demand (m³/s) for this bearing
    # truthful: just above it the film is fed (exit 0, status ok), 2 % below it starved
    code, out, _ = _run(capsys, *argv, "--supply-flow-m3-s", f"{1.001 * qmin:.8g}", "--json")
    assert code == 0 and json.loads(out)["thermal"]["status"] == "ok"
    code, out, _ = _run(capsys, *argv, "--supply-flow-m3-s", f"{0.98 * qmin:.8g}", "--json")
    assert code == 1 and json.loads(out)["status"] == "starved"
    # the text form: one record line, the status, the supply and the least supply
    code, out, err = _run(capsys, *argv, "--supply-flow-m3-s", "1e-7")
    assert code == 1 and not err
    assert f"({model} model): starved (" in out and "1e-07 m3/s" in out
    assert "Q - Q_r" in out and "no film outputs or coefficients" in out



class _Fed:
    status, message = "ok", ""


def _fake(least, fail_above=None, estimate=None):
    """A solve(q) that starves below ``least`` (its message naming ``estimate``), converges
    at or above it, and fails otherwise above ``fail_above``; counts its calls."""
    from rotordyn.errors import ConvergenceError, StarvedFilmError

    calls = []

    def solve(q):
        calls.append(q)
        if fail_above is not None and q >= fail_above:
            raise ConvergenceError("no equilibrium")
        if q < least:
            est = q if estimate is None else estimate
            raise StarvedFilmError(f"starved: the shortfall at this state, Q - Q_r = {est:g} "
                                   "m^3/s, estimates the supply it needs")
        return _Fed()
    return solve, calls


def test_least_supply_bracket_unit():
    """The bracket is between a starved and a fed supply: a supply that fails otherwise is
    neither end (it had been taken as fed, so 'the least supply that feeds the film' could be
    one with no equilibrium), and an estimate at or below the supply already tried makes the
    walk double instead of creeping by 0.1 %."""
    from rotordyn.cli.bearing_thermal import LEAST_SUPPLY_RTOL, least_feeding_supply

    solve, calls = _fake(7.26e-5)  # the estimate stalls at the supply tried: doubling
    q = least_feeding_supply(solve, 1e-7, "")
    assert 7.26e-5 <= q <= 7.26e-5 * (1 + 2 * LEAST_SUPPLY_RTOL) and len(calls) < 30
    solve, _ = _fake(7.26e-5, estimate=1.33e-4)  # an estimate above the least: bisected down
    q = least_feeding_supply(solve, 1e-7, "Q - Q_r = 1.33e-4 m^3/s")
    assert 7.26e-5 <= q <= 7.26e-5 * (1 + 2 * LEAST_SUPPLY_RTOL)
    solve, _ = _fake(7.26e-5, fail_above=5e-5)  # no fed supply without another failure
    assert least_feeding_supply(solve, 1e-7, "") is None
