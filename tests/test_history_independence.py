"""The same public call gives the same answer bit for bit whatever ran before (project rule).

Each analysis is called (A), then a different call on the same system object (B: another
speed, chamber pressure or housing offset), then A again: the arrays must be identical, not
close. Before every public call started from a defined state (python/rotordyn/_common/
calls.py), the second A warm-started its first equilibrium from B's and differed at round-off
(~1e-13 relative; more near a fold). Models: the compressor on plain and on tilting-pad
bearings, the compressor with its oil system (thermal), the paper rig (active bearing,
sleeve). Lean grids: the point is equality, not accuracy.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled

MODELS = Path(__file__).parent / "data" / "models"


def _coarse(s, n_circ=24, n_axial=6):
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=n_circ, n_axial=n_axial)
        if hasattr(b, "n_circ") and hasattr(b, "n_axial") else b for b in s.bearings))


def _model(name):
    return rd.System.from_toml(MODELS / name)


def _rig():
    return _coarse(rd.models.paper_rig(), 36, 8)


def _same(a, b):
    """Equal arrays bit for bit (NaN where NaN)."""
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape
    assert np.array_equal(a, b, equal_nan=True), float(np.nanmax(np.abs(a - b)))


def _aba(call_a, call_b, arrays):
    first = arrays(call_a())
    call_b()
    again = arrays(call_a())
    for x, y in zip(first, again):
        _same(x, y)
    return first


CASES = [("compressor_plain.toml", 150.0, 90.0), ("compressor_tilting_pad.toml", 150.0, 90.0)]


@pytest.mark.parametrize("name,fa,fb", CASES)
def test_equilibrium_stability_campbell_unbalance_on_the_compressor(name, fa, fb):
    s = _model(name)
    _aba(lambda: rd.equilibrium(s, fa), lambda: rd.equilibrium(s, fb), lambda e: (e.r,))
    _aba(lambda: rd.stability(s, fa), lambda: rd.stability(s, fb),
         lambda st: (st.eigenvalues,))
    _aba(lambda: rd.campbell(s, [fa, fa + 20.0]), lambda: rd.campbell(s, [fb]),
         lambda c: (c.eigenvalues,))
    ub = [(3, 1e-4, 0.0)]
    _aba(lambda: rd.unbalance_response(s, ub, [fa, fa + 20.0], stations=[1, 3]),
         lambda: rd.unbalance_response(s, ub, [fb], stations=[1]),
         lambda u: (u.x, u.y))


def test_thermal_equilibrium_and_its_stability_on_the_compressor():
    s = _model("compressor_plain_thermal.toml")
    _aba(lambda: rd.system_thermal_equilibrium(s, speed_hz=150.0),
         lambda: rd.system_thermal_equilibrium(s, speed_hz=90.0),
         lambda t: (t.r, t.viscosity_pa_s, t.temperature_rise_k))
    _aba(lambda: rd.stability(s, 150.0, thermal=True), lambda: rd.equilibrium(s, 90.0),
         lambda st: (st.eigenvalues,))


def test_the_paper_rig_with_other_pressures_and_offsets_between():
    s = _rig()
    _aba(lambda: rd.equilibrium(s, 50.0, 0.2e6, 0.0),
         lambda: rd.equilibrium(s, 80.0, 0.4e6, 2e-5), lambda e: (e.r,))
    _aba(lambda: rd.stability(s, 50.0, 0.2e6, 0.0),
         lambda: rd.stability(s, 30.0, 0.1e6, -2e-5), lambda st: (st.eigenvalues,))
    _aba(lambda: rd.campbell(s, [40.0, 50.0], 0.2e6),
         lambda: rd.campbell(s, [70.0], 0.4e6), lambda c: (c.eigenvalues,))
    ub = [(4, 1e-5, 0.0)]
    _aba(lambda: rd.unbalance_response(s, ub, [40.0, 50.0], chamber_pressure_pa=0.2e6),
         lambda: rd.unbalance_response(s, ub, [70.0], chamber_pressure_pa=0.4e6),
         lambda u: (u.x, u.y))


def test_a_call_still_continues_along_its_own_path():
    """Within one call the warm start stays: a Campbell's second speed starts from the first
    speed's equilibrium (fewer Newton iterations than cold), and the system's cached state is
    reset only when the next public call begins."""
    s = _model("compressor_plain.toml")
    rd.campbell(s, [100.0, 101.0])
    asm = assembled(s)  # outside any call: the cache as the Campbell left it
    assert asm.last_r is not None
    rd.equilibrium(s, 90.0)  # a new call: starts cold, then holds its own result
    cold = rd.equilibrium(s, 101.0)
    warm = rd.equilibrium(s, 101.0, r0=rd.equilibrium(s, 100.0).r)
    assert warm.iterations < cold.iterations
    np.testing.assert_allclose(warm.r, cold.r, rtol=0, atol=1e-12 * np.abs(cold.r).max())


def test_a_sweep_chunk_continues_along_its_line_only():
    """A stability chunk (one C++ call, a fresh solver) gives the same rows bit for bit with
    other work between, and its continuation along the line moves them from the cold answer
    of each point alone (each point its own chunk) only within the solver's tolerance:
    observed 4e-11 of the largest value on this line (max Re λ; frequencies 1.4e-12), the
    same statuses. Continuation is kept (it follows a branch along a line, and costs half
    of the cold starts: benchmarks/bench_cold_start.py)."""
    from rotordyn.sweep.work import Job, run_chunk

    s = _model("compressor_plain.toml")
    speeds = list(np.linspace(60.0, 250.0, 6))
    job = Job("h", s.to_toml(), "stability", {"n_modes": 6}, {"speed_hz": speeds})
    whole = run_chunk(job, 0, 0, len(speeds))
    rd.stability(s, 120.0)
    rd.campbell(s, [80.0, 200.0])
    again = run_chunk(job, 0, 0, len(speeds))
    assert whole.equals(again)
    alone = [run_chunk(job, k, k, k + 1) for k in range(len(speeds))]

    def col(tables, name):
        return np.concatenate([np.asarray(t.column(name).to_pylist(), dtype=float)
                               for t in tables])

    assert sum((t.column("status").to_pylist() for t in alone), []) == \
        whole.column("status").to_pylist()
    for name in ("freq_hz", "eig_real_1_per_s", "max_real_1_per_s", "journal_y_m"):
        a, b = col([whole], name), col(alone, name)
        assert np.nanmax(np.abs(a - b)) <= 1e-9 * np.nanmax(np.abs(a)), name
