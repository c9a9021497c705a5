"""An unbalance sweep says where its response is no steady orbit.

Above the threshold of instability the linear unbalance response is only the forced part of a
motion that grows (oil whip): `rotordyn.unbalance_response` says so (`stable`, the frame's
`point_stable`, "N speeds above the threshold of instability (no steady response)"), but the
sweep's unbalance rows had no verdict at all: on the 6-stage pump on plain bearings
(tests/data/models/pump6_plain_thermal.toml, threshold ≈ 106 Hz isothermal) the rows at 115
and 120 Hz read status ok with a 3 µm orbit and the run's summary said "unstable 0". The rows
now carry `point_stable` (the stability rows' rule; null where no equilibrium converged) and
the chunk counts take it; checked against `rotordyn.unbalance_response(..., check_stability=
True)` at the same speeds, isothermal and at each speed's thermal equilibrium.
"""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.sweep import run_sweep

MODEL = Path(__file__).parent / "data" / "models" / "pump6_plain_thermal.toml"
SPEEDS = [60.0, 115.0, 120.0]
UB = [(4, 2e-4, 0.0)]


def _spec(tmp_path, thermal: bool) -> Path:
    spec = tmp_path / "spec.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "pump-unbalance-{'thermal' if thermal else 'iso'}"
model = "{MODEL}"
analysis = "unbalance"

[grid]
speed_hz = {SPEEDS}

[options]
unbalances = [[4, 2e-4, 0.0]]
stations = [4, 5]
''' + ("\n[options.thermal]\n" if thermal else ""))
    return spec


@pytest.mark.parametrize("thermal", [False, True])
def test_unbalance_rows_carry_the_stability_verdict(tmp_path, thermal):
    res = run_sweep(str(_spec(tmp_path, thermal)), str(tmp_path / "out"), threads=1,
                    progress=False)
    df = pd.read_parquet(tmp_path / "out")
    assert len(df) == len(SPEEDS) * 2
    u = rd.unbalance_response(rd.System.from_toml(MODEL), UB, SPEEDS, stations=[4, 5],
                              refine=False, check_stability=True,
                              thermal={} if thermal else None)
    want = np.repeat(u.stable, 2)
    got = df.sort_values(["speed_hz", "station"]).point_stable.to_numpy(dtype=bool)
    assert np.array_equal(got, want)
    assert want.any() and not want.all()  # both sides of the threshold are in the grid
    assert res.counts["unstable"] == int((~u.stable).sum())
    assert (df.status == "ok").all()


def test_a_failed_point_has_no_stability_verdict(tmp_path):
    """A point without an equilibrium (a film of 1e-7 Pa·s cannot carry the pump) has no
    verdict: ``point_stable`` null (not False, not True) and the point counted failed, not
    unstable."""
    spec = tmp_path / "spec.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "pump-unbalance-failed"
model = "{MODEL}"
analysis = "unbalance"

[grid]
"bearings.*.viscosity_pa_s" = [1e-7, 0.02]
speed_hz = [60.0, 80.0]

[options]
unbalances = [[4, 2e-4, 0.0]]
stations = [4, 5]
''')
    res = run_sweep(str(spec), str(tmp_path / "out"), threads=1, progress=False)
    df = pd.read_parquet(tmp_path / "out")
    bad = df[df["bearings.*.viscosity_pa_s"] == 1e-7]
    good = df[df["bearings.*.viscosity_pa_s"] == 0.02]
    assert len(bad) == 4 and (bad.status == "no_equilibrium").all()
    assert bad.point_stable.isna().all()
    assert (good.status == "ok").all() and good.point_stable.astype(bool).all()
    assert res.counts == {"ok": 2, "failed": 2, "unstable": 0}
