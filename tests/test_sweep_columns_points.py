"""Thermal, waterfall, run-up, robust and hopf chunks built as columnar blocks (issue 22) give
the rows of the former dict-per-row code bit for bit.

Reference: tests/sweep_point_rows_reference.py, the chunk code as it was before (one dict per
row, the generic ``to_table``), kept verbatim. Comparison: that of tests/test_sweep_columns.py
(the same schema and metadata, the same null masks, every float column equal bit for bit,
NaN included, every other column value for value). Tolerance: none. Samples: the paper rig
and the compressor models of tests/data/models (plain and thermal films, the tilting-pad
bearings with a THD film per pad and in a waterfall, a refused point in a line, a model field
or thermal field axis, points whose equilibrium fails).
"""

import copy
import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.sweep.work import Job, run_chunk

sys.path.insert(0, str(Path(__file__).parent))
import sweep_point_rows_reference as ref  # noqa: E402
from test_sweep_columns import _model, assert_identical  # noqa: E402

# compressor_plain_thermal.toml's oil system with the THD film, for the tilting-pad bearings
THD = """
[thermal]
supply_temperature_c = 45.0
carry_over = 0.6
model = "thd"

[thermal.oil]
viscosity_law = "walther"
t1_c = 40.0
nu1_mm2_s = 32.0
t2_c = 100.0
nu2_mm2_s = 5.4
density_kg_m3 = 860.0
specific_heat_j_per_kg_k = 2000.0
"""
UB_RIG = [[6, 2e-5, 0.0]]
UB_PLAIN = [[3, 1e-5, 0.0]]
CASES = {
    "thermal": ("plain_thermal", "thermal", {},
                {"thermal.supply_temperature_c": [35.0, 50.0],
                 "chamber_pressure_pa": [0.0, -1.0], "speed_hz": [150.0]}),
    "thermal-tilting-thd": ("tilting_pad+thd", "thermal", {},
                            {"thermal.supply_temperature_c": [35.0, 50.0],
                             "speed_hz": [100.0, 150.0]}),
    "thermal-no-model": ("plain", "thermal", {}, {"speed_hz": [100.0, 150.0]}),
    "waterfall-rig": ("rig", "waterfall", {"unbalances": UB_RIG, "revolutions": 6,
                                           "samples_per_revolution": 32},
                      {"chamber_pressure_pa": [0.2e6], "speed_hz": [40.0, -5.0, 50.0]}),
    "waterfall-rig-no-equilibrium": ("rig", "waterfall", {"unbalances": UB_RIG, "revolutions": 4,
                                                          "samples_per_revolution": 32},
                                     {"chamber_pressure_pa": [0.2e6, 100e6],
                                      "speed_hz": [40.0, 50.0]}),
    "waterfall-plain": ("plain", "waterfall", {"unbalances": UB_PLAIN, "revolutions": 6,
                                               "samples_per_revolution": 32,
                                               "max_frequency_hz": 300.0},
                        {"bearings.0.clearance_m": [1e-4, 1.5e-4], "speed_hz": [100.0]}),
    "waterfall-tilting": ("tilting_pad", "waterfall", {"unbalances": UB_PLAIN, "revolutions": 4,
                                                       "samples_per_revolution": 32,
                                                       "max_frequency_hz": 300.0},
                          {"speed_hz": [100.0, -5.0, 150.0]}),
    "run-up-rig": ("rig", "run-up", {"unbalances": UB_RIG, "start_hz": 30.0, "stop_hz": 33.0,
                                     "rate_hz_per_s": 15.0},
                   {"chamber_pressure_pa": [0.2e6, -1.0], "config_ay_m": [0.0]}),
    "run-up-rig-no-equilibrium": ("rig", "run-up", {"unbalances": UB_RIG, "start_hz": 30.0,
                                                    "stop_hz": 31.0, "rate_hz_per_s": 15.0},
                                  {"chamber_pressure_pa": [0.2e6, 100e6]}),
    "run-up-plain": ("plain", "run-up", {"unbalances": UB_PLAIN, "start_hz": 90.0,
                                         "stop_hz": 80.0, "rate_hz_per_s": 100.0},
                     {"bearings.0.clearance_m": [1e-4, 1.5e-4]}),
    "hopf-rig": ("rig", "hopf", {"vary": "chamber_pressure_pa"},
                 {"speed_hz": [50.0, 80.0], "config_ay_m": [1.5e-3],
                  "chamber_pressure_pa": [0.0, 0.2e6, 0.4e6]}),
    "hopf-plain": ("plain", "hopf", {"vary": "speed_hz"},
                   {"speed_hz": [20.0, 150.0, 280.0, 400.0]}),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_chunk_rows_equal_the_former_per_row_code(case):
    model, analysis, options, axes = CASES[case]
    name, _, extra = model.partition("+")
    job = Job("s", _model(name) + (THD if extra == "thd" else ""), analysis, options, axes)
    job.meta = {"sweep_id": "s", "units": {"speed_hz": {"units": "Hz"}}}
    hi = int(np.prod(job.shape))
    new, old = run_chunk(job, 3, 0, hi), ref.run_chunk(job, 3, 0, hi)
    assert new.num_rows > 0
    assert_identical(new, old)


@pytest.fixture(scope="module")
def pd_law():
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.plant import plant

    rig = rd.models.paper_rig()
    p = plant(rig, 50.0, 0.05e6, -1.85e-3, measurements=[("journal", 0)],
              equilibrium={"warm_start": False})
    return rig, tune_pd(p)[0]


@pytest.mark.parametrize("margins", [False, True])
def test_robust_chunk_equals_the_former_per_row_code(pd_law, margins):
    """Stable and unstable points (50, 70 Hz at 0.05 MPa) and one whose equilibrium fails
    (100 MPa), continued along speed; with and without the margins."""
    from rotordyn.sweep.robust import build_spec

    rig, law = pd_law
    grid = {"chamber_pressure_pa": [0.05e6, 100e6], "config_ay_m": -1.85e-3,
            "speed_hz": [50.0, 70.0] if not margins else [50.0]}
    spec = build_spec(rig, law, grid, margins=margins)
    job = Job("s", rig.to_toml(), "robust", spec.options, spec.axes)
    hi = int(np.prod(job.shape))
    new, old = run_chunk(job, 1, 0, hi), ref.run_chunk(job, 1, 0, hi)
    st = new.column("status").cast("string").to_pylist()
    assert "ok" in st and len(set(st)) > 1
    assert_identical(new, old)


LC_OPTIONS = {"vary": "speed_hz", "rtol": 1e-6, "tol": 1e-4, "ds": 0.1, "ds_max": 0.3,
              "sensitivity_rtol": 1e-4, "newton": "broyden"}
LC_GRID = {"bearings.*.n_circ": [36], "bearings.*.n_axial": [4]}


def _same_value(a, b) -> bool:
    """Equal values, floats (and float arrays) bit for bit, NaN included."""
    if isinstance(a, dict) or isinstance(b, dict):
        return (isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys()
                and all(_same_value(a[k], b[k]) for k in a))
    if isinstance(a, (float, np.floating, np.ndarray)) or isinstance(b, (float, np.floating,
                                                                         np.ndarray)):
        x, y = np.asarray(a), np.asarray(b)
        return (x.dtype == y.dtype and x.shape == y.shape
                and x.tobytes() == y.tobytes())
    return type(a) is type(b) and a == b


def _branch_inputs(job, line, hrow, span, ys):
    """Everything ``_branch`` reads: the job's options, the line's operating point, grid and
    shooting options, its system (as TOML), the Hopf row's crossing value (the one field of
    the row it reads), the span and the line's max real parts (copied: the caller's objects
    may change after the call)."""
    return (dict(job.options),
            {k: getattr(line, k) for k in ("vary", "p0", "xs", "rtol", "tol", "srtol",
                                           "n_out", "newton")},
            line.system.to_toml(), hrow["value"], float(span), np.array(ys, copy=True))


@pytest.fixture
def replayed_branches(monkeypatch):
    """The reference replays the cycle branches the code under test computed, for the same
    inputs (compared value for value, floats bit for bit), instead of continuing them a
    second time: both paths call the one ``limit_cycle_rows._branch`` (the reference imports
    it), a pure function of those inputs (its results do not depend on what ran before:
    tests/test_limit_cycle_sweep.py), so its answer for equal inputs is the same and the
    comparison below still sees every difference in how the rows are made of it. The
    continuations are ~85 % of this test's time (cProfile). Inputs that differ (or a
    replay asked for more often than recorded) call the real function."""
    from rotordyn.sweep import limit_cycle_rows as lcr

    real, tape = lcr._branch, []

    def record(*args):
        key = _branch_inputs(*args)
        try:
            out = real(*args)
        except Exception as exc:  # replayed as raised
            tape.append((key, exc))
            raise
        tape.append((key, copy.deepcopy(out)))
        return out

    def replay(*args):
        key = _branch_inputs(*args)
        for i, (k, out) in enumerate(tape):
            if all(_same_value(a, b) for a, b in zip(k[:2] + k[3:], key[:2] + key[3:])) \
                    and k[2] == key[2]:
                del tape[i]
                if isinstance(out, Exception):
                    raise out
                return copy.deepcopy(out)
        return real(*args)

    monkeypatch.setattr(lcr, "_branch", record)
    monkeypatch.setattr(ref, "_branch", replay)


@pytest.mark.parametrize("speeds, max_points", [([125.0, 127.0], 2),
                                                ([121.0, 125.0, 127.0], 40)])
def test_limit_cycle_chunk_equals_the_former_per_row_code(replayed_branches, speeds,
                                                          max_points):
    """The compressor's whip line of tests/test_limit_cycle_sweep.py: branches stopped
    early (``failed`` rows), then the full line (a stable cycle beside the stable
    equilibrium, ``no_cycle`` at 127 Hz), Hopf records and cycle records. The reference
    replays the code's cycle branches (fixture ``replayed_branches``)."""
    job = Job("s", _model("plain"), "limit_cycle", {**LC_OPTIONS, "max_points": max_points},
              {**LC_GRID, "speed_hz": speeds})
    hi = int(np.prod(job.shape))
    new = run_chunk(job, 2, 0, hi)  # first: it records the branches the reference replays
    old = ref.run_chunk(job, 2, 0, hi)
    rec = new.column("record").cast("string").to_pylist()
    assert "hopf" in rec and "cycle" in rec
    assert_identical(new, old)


def test_schemas_equal_the_stored_ones_of_the_code_before():
    """Column names, order and arrow types of a chunk's table against
    tests/data/sweep_point_schemas.json, written by ``schema()`` of the code at 6ea1047 (before
    the columnar blocks) for axes speed_hz × chamber_pressure_pa: a changed dtype fails here
    even where both paths of the comparisons above would change together. (Changed on purpose
    since: the hopf and limit_cycle rows' ``l1_refined``, float64 after
    ``amplitude_coefficient_m2``, the hopf analysis's ``grid_check``; the ``thermal`` rows' four
    THD wall columns, journal_temperature_c … heat_to_bush_w, float64, before ``iterations``,
    then the hot film's h_min_m and h_min_z_m, float64, before ``iterations``, then
    ``carry_over_effective``, float64, after ``supply_flow_m3_s`` (2026-12-06: the carry-over
    a metered supply short of the demand makes up);
    docs/film-physics.md; ``journal_bearing``, string, after the ``i_`` columns of the
    analyses whose rows do not name a bearing: which journal they describe.)"""
    import json

    stored = json.loads((Path(__file__).parent / "data" / "sweep_point_schemas.json")
                        .read_text())
    axes = {"speed_hz": [150.0], "chamber_pressure_pa": [0.0, -1.0]}
    for analysis, want in stored.items():
        opts = {"vary": "chamber_pressure_pa"} if analysis in ("hopf", "limit_cycle") else {}
        job = Job("s", _model("plain_thermal"), analysis, opts, axes)
        if analysis in ("hopf", "limit_cycle", "robust", "waterfall", "run-up"):
            from rotordyn.sweep.work import schema

            got = schema(analysis, list(axes))  # the schema every chunk is built to
        else:
            got = run_chunk(job, 0, 0, 2).schema
        assert [[f.name, str(f.type)] for f in got] == want, analysis
    t = run_chunk(Job("s", _model("plain"), "waterfall", {"unbalances": UB_PLAIN,
                                                            "revolutions": 4},
                      axes), 0, 0, 2)
    assert [[f.name, str(f.type)] for f in t.schema] == stored["waterfall"]
