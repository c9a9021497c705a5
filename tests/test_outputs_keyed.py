"""Guards issue 18's output defects on models that are not the paper rig: the equilibrium's
per-bearing values keyed by bearing name as plain numbers (``per_bearing()``, ``bearing(name)``
and ``rotordyn equilibrium --json``: a list of records, or one-element arrays, before), the
static reactions keyed by name in ``rotordyn static --json``, and ``to_frame()`` columns that
carry a unit suffix or are dimensionless by the suffix vocabulary, with no inputs that do not
apply (a threshold on a model without an active bearing listed ``config_ay_m = None`` and
``chamber_pressure_pa``)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
PLAIN = MODELS / "compressor_plain.toml"

# the suffix vocabulary (STYLE §12) plus the angle and count units the tables use
SUFFIX = re.compile(r"_(m|s|hz|rad_s|pa|n|n_per_m|n_s_per_m|kg|kg_m2|1_per_s|deg|nm|pct|"
                    r"m_s)$")
DIMENSIONLESS = {"bearing", "status", "message", "mode", "mode_id", "model", "whirl", "kind",
                 "station", "x_over_c", "y_over_c", "eccentricity_ratio", "iterations",
                 "reynolds_solves", "residual", "damping_ratio", "log_dec", "mode_stable",
                 "point_stable", "vary", "whirl_ratio", "stable_side", "evaluations", "side"}


def test_equilibrium_per_bearing_keyed_by_name(capsys):
    s = rd.System.from_toml(PLAIN)
    e = rd.equilibrium(s, 100.0)
    d = e.per_bearing()
    assert list(d) == ["NDE bearing", "DE bearing"]
    b = e.bearing("DE bearing")
    assert isinstance(b["x_over_c"], float) and b["x_over_c"] == pytest.approx(e.x_over_c[1])
    assert b["journal_y_m"] == pytest.approx(e.journal_y_m[1])
    with pytest.raises(rd.InputError, match="'NDE bearing', 'DE bearing'"):
        e.bearing("bearing 3")
    assert main(["equilibrium", str(PLAIN), "--speed-hz", "100", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["bearings"]) == {"NDE bearing", "DE bearing"}
    for rec in out["bearings"].values():
        assert all(not isinstance(v, list) for k, v in rec.items() if k != "sleeve_m")
        assert 0 < rec["eccentricity_ratio"] < 1
    assert main(["static", str(PLAIN), "--speed-hz", "100", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["reactions"]) == {"NDE bearing", "DE bearing"}
    assert sum(r["force_y_n"] for r in out["reactions"].values()) == pytest.approx(
        out["weight_n"], rel=1e-9)


def test_frames_carry_units_and_only_inputs_that_apply():
    s = rd.System.from_toml(PLAIN)
    lin = rd.System.from_toml(MODELS / "compressor_linear.toml")
    t = rd.threshold(s, "speed_hz", bounds=(60.0, 160.0), n_scan=5)
    frames = {
        "equilibrium": rd.equilibrium(s, 100.0).to_frame(),
        "stability": rd.stability(s, 100.0).to_frame(),
        "campbell": rd.campbell(s, [80.0, 100.0]).to_frame(),
        "modes": rd.modes(lin, 0.0, n_modes=2).to_frame(),
        "unbalance": rd.unbalance_response(lin, [(3, 1e-4, 0.0)], [100.0, 120.0],
                                           stations=[3], refine=False).to_frame(),
        "peaks": rd.unbalance_response(lin, [(3, 1e-4, 0.0)], np.linspace(100, 220, 25),
                                       stations=[3]).peaks(3),
        "static": rd.static(s, 100.0).to_frame(),
        "threshold": t.to_frame(),
    }
    for name, df in frames.items():
        for c in df.columns:
            assert c in DIMENSIONLESS or SUFFIX.search(c) or c == "amplification_factor" \
                or c == "af_kind" or c == "critically_damped", (name, c)
        assert "chamber_pressure_pa" not in df, name
        # (the equilibrium lists each bearing's own housing offset a, which any bearing has)
        assert name == "equilibrium" or "config_ay_m" not in df, name


def test_state_space_frame_has_the_unit_of_every_entry():
    """The state-space table mixes units in its value column: each row says its own."""
    s = rd.System.from_toml(PLAIN)
    ss = rd.statespace(s, inputs=[("force", 3)], outputs=[("journal", 0), ("velocity", 3)],
                       speed_hz=100.0)
    df = ss.to_frame()
    assert "unit" in df

    def one(m, r, c):
        row = df[(df["matrix"] == m) & (df["row"] == r) & (df["col"] == c)]
        assert len(row) == 1
        return row.iloc[0]

    a = one("A", "station3.x", "d(station3.x)/dt")
    assert a["unit"] == "(m/s)/(m/s)" and a["value"] == 1.0
    assert one("A", "d(station3.x)/dt", "station3.x")["unit"] == "(m/s/s)/(m)"
    assert one("B", "d(station3.y)/dt", "force_y_n[3]")["unit"] == "(m/s/s)/(N)"
    assert one("C", "journal_x_m[0]", "station1.x")["unit"] == "(m)/(m)"
    assert one("C", "velocity_x_m_s[3]", "d(station3.x)/dt")["unit"] == "(m/s)/(m/s)"
    assert one("D", "journal_y_m[0]", "force_x_n[3]")["unit"] == "(m)/(N)"
