"""`rotordyn.statespace` names the argument and the item of a bad input or output, and
refuses it before the equilibrium is solved.

Before 2026-12-06, on the compressor with its active DE bearing,
`inputs=[("force", 40)]` gave "station: expected an integer in [0, 6], got 40" (which
argument?) and `outputs=[("journal", 3)]` "outputs: no bearing with index 3", both only after
the equilibrium and linearisation had been solved.
"""

import importlib
from pathlib import Path

import pytest

import rotordyn as rd

# the module (rotordyn.analysis re-exports the function under the module's name)
ssmod = importlib.import_module("rotordyn.analysis.statespace")

MODEL = Path(__file__).parent / "data" / "models" / "compressor_active.toml"


@pytest.fixture()
def no_solve(monkeypatch):
    def refuse(*a, **k):
        raise AssertionError("the equilibrium was solved before the items were checked")
    monkeypatch.setattr(ssmod, "linearize", refuse)


@pytest.mark.parametrize("inputs, outputs, match", [
    ([("force", 40)], [("journal", 1)], r"inputs: \('force', 40\): station: .*\[0, 6\]"),
    (["chamber_pressure"], [("journal", 3)],
     r"outputs: \('journal', 3\): no bearing with index 3 \(bearings: 0\.\.1\)"),
    (["chamber_pressure"], [("displacement", -1)], r"outputs: \('displacement', -1\): station"),
    (["chamber_pressure"], [("sleeve", 0)], r"outputs: bearing 0 has no sleeve"),
])
def test_bad_items_named_before_the_solve(no_solve, inputs, outputs, match):
    s = rd.System.from_toml(MODEL)
    with pytest.raises(rd.InputError, match=match):
        rd.statespace(s, inputs=inputs, outputs=outputs, speed_hz=170.0,
                      chamber_pressure_pa=1e5, config_ay_m=0.0)


def test_good_items_still_build_the_model():
    s = rd.System.from_toml(MODEL)
    ss = rd.statespace(s, inputs=["chamber_pressure", ("force", 3)],
                       outputs=[("journal", 1), ("sleeve", 1), ("displacement", 3)],
                       speed_hz=170.0, chamber_pressure_pa=1e5, config_ay_m=0.0)
    assert ss.B.shape[1] == 3 and ss.C.shape[0] == 2 + 3 + 2
