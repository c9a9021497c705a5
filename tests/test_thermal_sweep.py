"""Sweeps with ``options.thermal`` (issue 20: stability, Campbell, unbalance with every point at
its own thermal equilibrium, the field frozen for K_H, D_H), built as columnar blocks
(python/rotordyn/sweep/thermal_rows.py), on compressor models of tests/data/models (plain,
tilting-pad with the THD film per pad, an active bearing), not the paper rig:

* the chunk tables equal the former dict-per-row code's bit for bit
  (tests/sweep_thermal_rows_reference.py; comparison of tests/test_sweep_columns.py: schema,
  metadata, null masks, every float bit for bit, NaN included; tolerance none);
* determinism: the dataset of a sweep is the same bit for bit (pandas assert_frame_equal,
  check_exact) with 1 thread, 2 threads and 2 worker processes, and when rerun after another
  model's computation in the same process;
* tilting pads with the THD film: rows ok, one temperature per pad film, finite, hotter than
  the supply, summaries consistent, eigenvalues those of the direct call (bit for bit);
* a failed thermal equilibrium (no system equilibrium at 1 GPa chamber pressure) is one
  status row per point with NaN thermal columns, and the frozen system is never linearised.
"""

import dataclasses
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.sweep import run_sweep
from rotordyn.sweep.work import Job, run_chunk

sys.path.insert(0, str(Path(__file__).parent))
import sweep_thermal_rows_reference as ref  # noqa: E402
from test_sweep_columns import assert_identical  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"
UB = [[3, 1e-4, 0.0]]


def _plain():
    s = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=8) for b in s.bearings))


def _pads():
    th = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    return dataclasses.replace(s, thermal=dataclasses.replace(th, model="thd"))


def _active():
    """Plain NDE bearing and active DE bearing with the compressor's oil system (one setting
    for both films)."""
    th = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    s = rd.System.from_toml(MODELS / "compressor_active.toml")
    return dataclasses.replace(s, thermal=dataclasses.replace(th, films=()))


def _job(system, analysis, options, axes):
    job = Job("s", system.to_toml(), analysis, options, axes)
    job.meta = {"sweep_id": "s", "units": {"speed_hz": {"units": "Hz"}}}
    return job


CASES = {
    "stability": (_plain, "stability", {"thermal": {}, "n_modes": 4},
                  {"thermal.supply_temperature_c": [40.0, 55.0], "speed_hz": [100.0, 0.0,
                                                                            150.0]}),
    "stability-untracked": (_plain, "stability", {"thermal": {"model": "thd"}, "n_modes": 4,
                                                  "track": False}, {"speed_hz": [100.0]}),
    "campbell-raises": (_plain, "campbell", {"thermal": {"supply_temperature_c": 195.0}},
                        {"speed_hz": [150.0, 160.0]}),
    "campbell-tilting-thd": (_pads, "campbell", {"thermal": {}, "n_modes": 6},
                             {"speed_hz": [100.0, 150.0]}),
    "stability-no-equilibrium": (_active, "stability", {"thermal": {}, "n_modes": 4},
                                 {"chamber_pressure_pa": [0.0, 1e9], "speed_hz": [100.0]}),
    "unbalance": (_plain, "unbalance", {"thermal": {}, "unbalances": UB, "stations": [3, 1]},
                  {"chamber_pressure_pa": [0.0, -1.0], "speed_hz": [80.0, 100.0, 150.0]}),
    "unbalance-no-equilibrium": (_active, "unbalance", {"thermal": {}, "unbalances": UB},
                                 {"chamber_pressure_pa": [1e9, 0.0], "speed_hz": [90.0, 100.0]}),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_chunk_rows_equal_the_former_per_row_code(case):
    model, analysis, options, axes = CASES[case]
    job = _job(model(), analysis, options, axes)
    hi = int(np.prod(job.shape))
    new, old = run_chunk(job, 2, 0, hi), ref.run_chunk(job, 2, 0, hi)
    assert new.num_rows > 0
    assert "film" in new.schema.names
    assert_identical(new, old)


SPEC = """
schema = "rotordyn/sweep/1"
name = "t-thermal-{analysis}"
model = "{model}"
analysis = "{analysis}"
chunk_size = 1

[grid]
"thermal.supply_temperature_c" = [40.0, 55.0]
speed_hz = [90.0, 125.0, 160.0]

[options]
{options}

[options.thermal]
tol_k = 1e-7
"""


def _spec(tmp_path, analysis):
    model = tmp_path / "compressor.toml"
    _plain().to_toml(model)
    options = "n_modes = 4" if analysis == "stability" else f"unbalances = {UB}"
    p = tmp_path / f"{analysis}.toml"
    p.write_text(SPEC.format(model=model.as_posix(), analysis=analysis, options=options))
    return p


def _frame(out):
    """The dataset's rows (in the dataset's own order: not re-sorted, that is compared too)."""
    return sw.open(out).frame


def _other_model_computation():
    """Another model's work in this process: the paper rig's stability, the tilting-pad
    compressor's THD thermal equilibrium and a sweep chunk of it (every per-process cache
    filled with other systems)."""
    rd.stability(rd.models.paper_rig(), 50.0, 0.1e6)
    rd.system_thermal_equilibrium(_pads(), speed_hz=120.0)
    run_chunk(_job(_pads(), "stability", {"thermal": {}}, {"speed_hz": [120.0]}), 0, 0, 1)


@pytest.mark.parametrize("analysis", ["stability", "unbalance"])
def test_dataset_identical_threads_and_after_other_work(tmp_path, analysis):
    spec = _spec(tmp_path, analysis)
    res = run_sweep(spec, tmp_path / "one", threads=1, progress=False)
    assert res.complete
    a = _frame(tmp_path / "one")
    assert set(a["status"]) == {"ok"} and a["max_temperature_c"].notna().all()
    assert run_sweep(spec, tmp_path / "two", threads=2, progress=False).complete
    pd.testing.assert_frame_equal(_frame(tmp_path / "two"), a, check_exact=True)
    _other_model_computation()
    assert run_sweep(spec, tmp_path / "again", threads=1, progress=False).complete
    pd.testing.assert_frame_equal(_frame(tmp_path / "again"), a, check_exact=True)


def test_dataset_identical_on_two_workers(tmp_path, monkeypatch):
    """Every chunk computed by the 2 dask worker processes (the driver hands all of them
    over), against the one-thread dataset."""
    from rotordyn.sweep import execution

    class WorkersOnly(execution.StartingCluster):
        def _overlap(self, job, tasks):  # no chunk in the driver: start the cluster first
            self.dask = execution.Dask(None, self.workers, self.timeout, self.progress)
            self.cluster = True
            return 0
            yield  # a generator, as the method it replaces

    spec = _spec(tmp_path, "stability")
    assert run_sweep(spec, tmp_path / "one", threads=1, progress=False).complete
    monkeypatch.setattr(execution, "StartingCluster", WorkersOnly)
    assert run_sweep(spec, tmp_path / "w", workers=2, progress=False).complete
    pd.testing.assert_frame_equal(_frame(tmp_path / "w"), _frame(tmp_path / "one"),
                                  check_exact=True)


def test_tilting_pad_thd_stability_sweep():
    s = _pads()
    job = _job(s, "stability", {"thermal": {}, "n_modes": 6}, {"speed_hz": [100.0, 150.0]})
    t = run_chunk(job, 0, 0, 2).to_pandas()
    assert set(t["status"]) == {"ok"}
    n_pads = sum(b.n_pads for b in s.bearings)
    for f, g in t.groupby("speed_hz"):
        st = rd.stability(s, f, n_modes=6, thermal=True)
        assert st.thermal.thermal_model == "thd"
        assert np.array_equal(g["eig_real_1_per_s"].to_numpy(), st.eigenvalues.real)
        assert np.array_equal(g["freq_hz"].to_numpy(), st.eigenvalues.imag / (2 * np.pi))
        r = g.iloc[0]
        assert len(r["film"]) == n_pads and all(".pad" in x for x in r["film"])
        for c in ("film_effective_temperature_c", "film_max_temperature_c",
                  "film_power_loss_w"):
            x = np.asarray(r[c])
            assert x.shape == (n_pads,) and np.all(np.isfinite(x)), c
        te, tm = np.asarray(r["film_effective_temperature_c"]), np.asarray(
            r["film_max_temperature_c"])
        assert np.all(tm >= te) and np.all(te > s.thermal.supply_temperature_c)
        assert r["max_temperature_c"] == tm.max()
        assert r["power_loss_w"] == pytest.approx(np.sum(r["film_power_loss_w"]), rel=1e-12)
        assert np.array_equal(te, st.thermal.effective_temperature_c)
        # every row of the point carries the same thermal columns
        assert all(list(x) == list(r["film_max_temperature_c"])
                   for x in g["film_max_temperature_c"])


def test_failed_thermal_equilibrium_is_a_status_row_never_linearised(monkeypatch):
    import rotordyn.analysis.linear as lin

    calls = []
    real = lin.stability

    def counted(system, speed_hz, *a, **kw):
        calls.append(float(speed_hz))
        return real(system, speed_hz, *a, **kw)

    monkeypatch.setattr(lin, "stability", counted)
    s = _active()
    job = _job(s, "stability", {"thermal": {}, "n_modes": 4},
               {"chamber_pressure_pa": [1e9, 0.0], "speed_hz": [100.0, 120.0]})
    t = run_chunk(job, 0, 0, 4).to_pandas()
    assert len(calls) == 2  # the two points at 0 Pa only
    bad = t[t["chamber_pressure_pa"] == 1e9]
    assert len(bad) == 2  # one row per point
    assert set(bad["status"]) == {"no_equilibrium"}
    assert bad["message"].str.startswith("thermal equilibrium: no equilibrium").all()
    assert bad["eig_real_1_per_s"].isna().all() and bad["mode"].isna().all()
    assert bad["max_temperature_c"].isna().all() and bad["power_loss_w"].isna().all()
    for x in bad["film_effective_temperature_c"]:
        assert len(x) == 2 and np.all(np.isnan(x))
    ok = t[t["chamber_pressure_pa"] == 0.0]
    assert set(ok["status"]) == {"ok"} and ok["max_temperature_c"].notna().all()
    # unbalance and Campbell: NaN rows with the thermal status
    job = _job(s, "unbalance", {"thermal": {}, "unbalances": UB},
               {"chamber_pressure_pa": [1e9], "speed_hz": [90.0, 100.0]})
    u = run_chunk(job, 0, 0, 2).to_pandas()
    assert set(u["status"]) == {"no_equilibrium"} and u["amplitude_x_m"].isna().all()
    assert u["message"].str.startswith("thermal equilibrium:").all()
    c = rd.campbell(s, [90.0, 100.0], 1e9, thermal=True)
    assert list(c.point_status) == ["no_equilibrium"] * 2
    assert np.isnan(c.eigenvalues).all()
    with pytest.raises(rd.errors.ConvergenceError, match="not linearised"):
        rd.stability(s, 100.0, 1e9, thermal=True)


def test_failed_system_equilibrium_returns_its_status():
    """The paper rig with an oil system at 100 MPa: the first system equilibrium fails, so no
    film ever got a thermal state; the result is that status with NaN temperatures (it raised
    an InputError on a zero viscosity before) and the model as given."""
    th = rd.System.from_toml(MODELS / "compressor_plain_thermal.toml").thermal
    rig = dataclasses.replace(rd.models.paper_rig(), thermal=dataclasses.replace(th, films=()))
    r = rd.system_thermal_equilibrium(rig, speed_hz=50.0, chamber_pressure_pa=100e6)
    assert r.status == "no_equilibrium"
    assert np.all(np.isnan(r.effective_temperature_c)) and np.all(np.isnan(r.viscosity_pa_s))
    assert r.system is rig


@pytest.mark.parametrize("model, key, value", [("effective", "journal_htc_w_m2k", 100.0),
                                               ("thd", "effective_factor", 0.5)])
def test_other_model_option_refused_before_any_row(tmp_path, model, key, value):
    """An ``options.thermal`` keyword of the other thermal model is an InputError naming it
    when the spec meets its model (as rd.system_thermal_equilibrium refuses it); before, the
    spec passed and every row of the sweep became the same failed point."""
    p = _spec(tmp_path, "stability")
    p.write_text(p.read_text() + f'model = "{model}"\n{key} = {value}\n')
    with pytest.raises(rd.InputError, match=rf"options\.thermal\.{key}: an option of model="):
        sw.SweepSpec.from_toml(p).check_against(_plain())
