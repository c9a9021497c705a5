"""Sweep chunks built as columnar blocks (issue 22) give the rows of the former per-row code bit
for bit, and boundary-refinement chunks as one ``max_real_batch`` call per run of points give
the values of the former per-point loop bit for bit.

Reference: tests/sweep_rows_reference.py, the chunk code as it was before (one dict per row,
the generic ``to_table``; boundary points by the Python loop of equilibrium, linearisation and
modal calls), kept verbatim. Comparison: the same schema and metadata, the same null masks,
every float column equal bit for bit (its IEEE-754 bit patterns, NaN included), every other
column equal value for value. Tolerance: none. Samples: the paper rig (Fig. 9 lines over p_c
with a refused point, a model-field axis, finite-difference linearisation, tracking on and
off) and the compressor models of tests/data/models (Campbell, a tilting-pad equilibrium, a
table bearing whose solve raises, a threshold over speed, an unbalance line).
"""

import sys
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pytest

import rotordyn as rd
from rotordyn.sweep.work import Job, run_chunk

sys.path.insert(0, str(Path(__file__).parent))
import sweep_rows_reference as ref  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


def _model(name):
    if name == "rig":
        return rd.models.paper_rig().to_toml()
    return rd.System.from_toml(str(MODELS / f"compressor_{name}.toml")).to_toml()


def _same_column(a, b) -> bool:
    a, b = a.combine_chunks(), b.combine_chunks()
    if a.type != b.type or len(a) != len(b):
        return False
    if not np.array_equal(a.is_null().to_numpy(zero_copy_only=False),
                          b.is_null().to_numpy(zero_copy_only=False)):
        return False
    if pa.types.is_list(a.type):  # per-film lists: the offsets, then the values as a column
        return (np.array_equal(a.offsets.to_numpy(), b.offsets.to_numpy())
                and _same_column(pa.chunked_array([a.flatten()]),
                                 pa.chunked_array([b.flatten()])))
    if pa.types.is_floating(a.type):
        x = pc.fill_null(a, 0.0).to_numpy(zero_copy_only=False)
        y = pc.fill_null(b, 0.0).to_numpy(zero_copy_only=False)
        return np.array_equal(x.view(np.uint64), y.view(np.uint64))
    return a.to_pylist() == b.to_pylist()


def assert_identical(new: pa.Table, old: pa.Table):
    assert new.schema.equals(old.schema, check_metadata=True)
    assert new.num_rows == old.num_rows
    diff = [f for f in old.schema.names if not _same_column(new[f], old[f])]
    assert not diff, f"columns differ: {diff}"


PCS = [0.0, 0.1e6, -1.0, 0.2e6, 0.3e6]  # -1 Pa: a refused point inside a line
CASES = {
    "stability": ("rig", "stability", {}, {"config_ay_m": [-1.85e-3, 1.5e-3],
                                           "chamber_pressure_pa": PCS, "speed_hz": [50.0]},
                  (1, 10)),
    "stability-untracked-fd": ("rig", "stability", {"n_modes": 6, "track": False,
                                                    "linearization": "finite_difference"},
                               {"chamber_pressure_pa": PCS[:3]}, None),
    "stability-model-field": ("plain", "stability", {},
                              {"bearings.0.clearance_m": [1e-4, 1.5e-4],
                               "speed_hz": [40.0, 120.0]}, None),
    "campbell": ("plain", "campbell", {"n_modes": 8}, {"speed_hz": [20.0, 90.0, 160.0]}, None),
    "equilibrium": ("rig", "equilibrium", {}, {"config_ay_m": [-1.85e-3, 0.0],
                                               "chamber_pressure_pa": PCS}, None),
    "equilibrium-raises": ("table", "equilibrium", {}, {"speed_hz": [30.0, 1e5, 60.0, -5.0]},
                           None),
    "equilibrium-tilting": ("tilting_pad", "equilibrium", {}, {"speed_hz": [50.0, 100.0]}, None),
    "threshold": ("rig", "threshold", {"vary": "chamber_pressure_pa"},
                  {"config_ay_m": [-1.85e-3, 2.0e-3], "speed_hz": [50.0],
                   "chamber_pressure_pa": [0.0, 0.1e6, 0.2e6, 0.3e6]}, None),
    "threshold-speed": ("plain", "threshold", {"vary": "speed_hz"},
                        {"speed_hz": [20.0, 150.0, 280.0, 400.0]}, None),
    "unbalance": ("rig", "unbalance", {"unbalances": [[6, 2e-5, 0.0]], "stations": [6, 4]},
                  {"chamber_pressure_pa": [0.2e6], "speed_hz": list(np.arange(30.0, 71.0, 5.0))},
                  None),
    "unbalance-margins": ("plain", "unbalance", {"unbalances": [[3, 1e-5, 0.0]],
                                                 "operating_speed_hz": [100.0, 120.0]},
                          {"speed_hz": list(np.linspace(10.0, 300.0, 12))}, None),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_chunk_rows_equal_the_former_per_row_code(case):
    model, analysis, options, axes, span = CASES[case]
    job = Job("s", _model(model), analysis, options, axes)
    job.meta = {"sweep_id": "s", "units": {"speed_hz": {"units": "Hz"}}}
    lo, hi = span or (0, int(np.prod(job.shape)))
    new, old = run_chunk(job, 3, lo, hi), ref.run_chunk(job, 3, lo, hi)
    assert new.num_rows > 0
    assert_identical(new, old)


BOUNDARY = {
    # runs along p_c with gaps (the continuation starts cold after a gap), a refused point
    "rig": ("rig", {}, {"config_ay_m": list(np.linspace(-2.5e-3, 2.5e-3, 5)),
                        "chamber_pressure_pa": [-1.0, 0.0, 0.1e6, 0.2e6, 0.3e6],
                        "speed_hz": [50.0]}, [0, 1, 2, 3, 4, 6, 8, 9, 12, 13, 14, 24]),
    "rig-rotor-modes": ("rig", {"exclude_sleeve_modes": True},
                        {"config_ay_m": [-1.85e-3, 0.0], "chamber_pressure_pa": [0.0, 0.15e6,
                                                                                 0.3e6]},
                        [0, 1, 2, 3, 5]),
    # the innermost axis a model field: each point its own model, continued across them
    "model-field": ("plain", {}, {"speed_hz": [60.0, 200.0],
                                  "bearings.0.clearance_m": [1e-4, 1.5e-4, 2e-4]},
                    [0, 1, 2, 4, 5]),
}


@pytest.mark.parametrize("case", sorted(BOUNDARY))
def test_boundary_chunk_equals_the_point_loop(case):
    model, options, axes, pids = BOUNDARY[case]
    job = Job("s", _model(model), "boundary", options, axes)
    job.level = 2
    new, old = run_chunk(job, 5, 0, 0, pids), ref.run_chunk(job, 5, 0, 0, pids)
    got = new.column("point_id").to_pylist()  # one row per mode (a failed point: one)
    assert [p for k, p in enumerate(got) if k == 0 or p != got[k - 1]] == pids
    st = new.column("status").cast("string").to_pylist()
    assert "ok" in st
    assert_identical(new, old)


def test_identity_check_can_fail():
    """The comparison sees a one-ulp change of one float and a changed null mask."""
    job = Job("s", _model("rig"), "equilibrium", {}, {"chamber_pressure_pa": [0.0, 0.1e6]})
    t = run_chunk(job, 0, 0, 2)
    x = t.column("journal_x_m").to_numpy().copy()
    x[0] = np.nextafter(x[0], np.inf)
    bumped = t.set_column(t.schema.get_field_index("journal_x_m"), "journal_x_m", pa.array(x))
    with pytest.raises(AssertionError):
        assert_identical(bumped, t)
    y = t.column("iterations").to_pylist()
    masked = t.set_column(t.schema.get_field_index("iterations"),
                          t.schema.field("iterations"), pa.array([None] + y[1:], pa.int64()))
    with pytest.raises(AssertionError):
        assert_identical(masked, t)
