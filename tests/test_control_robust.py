"""Robust stability of a fixed law over a grid (issue 24, rotordyn.control.robust):

- each point's verdict against the closed-loop eigenvalues assembled here with numpy from the
  same plant ([A + B D_k C, B C_k; B_k C, A_k]), on the rig with the tuned PD and LQG laws,
  with a point known stable (50 Hz, docs/control.md §3.1) and one known unstable (70 Hz, above
  the PD's threshold speed 69.8 Hz at 0.1 MPa; at 0.05 MPa max Re λ ≈ +6.8 1/s);
- the worst case of each quantity equals the extreme over the rows, at its point;
- the margins in a row equal rotordyn.control.margins.margins() at that point;
- the ISO 14839-3 zone limits (peak |S| 3, 4, 5);
- a point whose equilibrium fails (p_c = 100 MPa) is a row with its status and no verdict;
- the rows do not depend on the chunking or the number of threads, and a rerun resumes;
- a model-field axis (viscosity) against the model rebuilt by hand;
- bad input is an InputError naming the field.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import margins as mg
from rotordyn.control.plant import plant
from rotordyn.sweep.robust import build_spec, robust
from rotordyn.errors import InputError
from rotordyn.sweep.paths import set_field
from rotordyn.control.robust import iso_zone

PC, AY = 0.05e6, -1.85e-3
MODELS = Path(__file__).parent / "data" / "models"
COLD = {"warm_start": False}


@pytest.fixture(scope="module")
def rig_laws():
    from rotordyn.control.lqr import lqg
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.reduction import modal_truncation

    rig = rd.models.paper_rig()
    # cold: the laws must not depend on the warm start other tests leave behind
    p = plant(rig, 50.0, PC, AY, measurements=[("journal", 0)], equilibrium=COLD)
    return rig, {"pd": tune_pd(p)[0], "lqg": lqg(modal_truncation(p, 500.0)[0])}


def numpy_max_real(system, k, f, pc, ay, **field):
    """max Re λ of the closed loop assembled here from the plant's matrices."""
    p = plant(system, f, pc, ay, measurements=k.measurements, equilibrium=COLD)
    A, B, C = p.A, p.B, p.C
    top = np.hstack([A + B @ k.D @ C, B @ k.C])
    bot = np.hstack([k.B @ C, k.A])
    return float(np.linalg.eigvals(np.vstack([top, bot])).real.max())


@pytest.mark.parametrize("law", ["pd", "lqg"])
def test_verdicts_equal_the_numpy_closed_loop(rig_laws, law):
    rig, laws = rig_laws
    k = laws[law]
    grid = {"speed_hz": [30.0, 50.0, 70.0], "config_ay_m": AY, "chamber_pressure_pa": PC}
    cold = robust(rig, k, grid, margins=False, threads=1, continuation=False)
    r = robust(rig, k, grid, margins=False, threads=1)  # equilibria continued in speed
    f = r.frame
    assert list(f.status) == ["ok"] * 3
    for (_, row), (_, row0) in zip(f.iterrows(), cold.frame.iterrows()):
        ref = numpy_max_real(rig, k, row.speed_hz, PC, AY)
        # each point solved cold: the direct call's equilibrium, to round-off
        assert row0.max_real_1_per_s == pytest.approx(ref, rel=1e-9, abs=1e-9)
        # continued: the same equilibrium within the solver's tolerance; the LQG loop's
        # slowest mode (ζ = 0.0005, of the near-degenerate 38 Hz pair) moves by ~1e-7 of it
        assert row.max_real_1_per_s == pytest.approx(ref, rel=1e-6, abs=1e-9)
        assert bool(row.point_stable) == bool(row0.point_stable) == (ref < 0)
    # the known points: 50 Hz stable, 70 Hz unstable
    assert bool(f.point_stable[f.speed_hz == 50.0].iloc[0])
    assert not bool(f.point_stable[f.speed_hz == 70.0].iloc[0])
    assert not r.all_stable and r.summary()["unstable"] >= 1


def test_margins_worst_case_and_zones(rig_laws):
    rig, laws = rig_laws
    k = laws["pd"]
    grid = {"speed_hz": [30.0, 50.0, 70.0], "chamber_pressure_pa": [PC, 0.1e6],
            "config_ay_m": AY}
    r = robust(rig, k, grid, threads=2)
    f = r.frame
    assert len(f) == 6
    # margins at a point equal control/margins.py's on the same plant
    row = f[(f.speed_hz == 50.0) & (f.chamber_pressure_pa == PC)].iloc[0]
    m = mg.margins(plant(rig, 50.0, PC, AY, equilibrium=COLD), k).input
    for col, ref in (("gain_margin_lower", m.gain_margin_lower),
                     ("gain_margin_upper", m.gain_margin_upper),
                     ("phase_margin_deg", m.phase_margin_deg),
                     ("delay_margin_s", m.delay_margin_s),
                     ("peak_sensitivity", m.peak_sensitivity),
                     ("disk_margin", m.disk.alpha)):
        assert row[col] == pytest.approx(ref, rel=1e-9), col
    # the tuned PD of docs/control.md §2.1: (0.0637, 1.530), peak |S| 2.987 → zone A
    assert (round(row.gain_margin_lower, 4), round(row.gain_margin_upper, 3)) == (0.0637, 1.530)
    assert row.iso_zone == "A"
    # an unstable point has a verdict and no margins
    bad = f[f.point_stable == False]  # noqa: E712
    assert len(bad) >= 1 and bad.peak_sensitivity.isna().all() and bad.iso_zone.isna().all()
    # the worst case of each quantity is the extreme over the rows, reported with its point
    w = r.worst()
    for col, how in (("max_real_1_per_s", "max"), ("min_damping_ratio", "min"),
                     ("gain_margin_upper", "min"), ("gain_margin_lower", "max"),
                     ("phase_margin_deg", "min"), ("delay_margin_s", "min"),
                     ("disk_margin", "min"), ("peak_sensitivity", "max")):
        s = f[col].astype(float)
        ext = s.max() if how == "max" else s.min()
        if col == "phase_margin_deg":  # the least in magnitude
            ext = s[s.abs() == s.abs().min()].iloc[0]
        assert w[col]["value"] == ext, col
        at = f[f.point_id == w[col]["point_id"]].iloc[0]
        assert at[col] == ext and at.speed_hz == w[col]["speed_hz"]
    # each stable row's zone follows its own peak |S|
    for _, row in f[f.point_stable == True].iterrows():  # noqa: E712
        assert row.iso_zone == iso_zone(row.peak_sensitivity)
        assert row.peak_sensitivity_db == pytest.approx(20 * math.log10(row.peak_sensitivity))


def test_iso_14839_zone_limits():
    """ISO 14839-3 zone limits of the peak sensitivity: A ≤ 3 (9.5 dB), B ≤ 4 (12 dB),
    C ≤ 5 (14 dB), D above."""
    assert [iso_zone(x) for x in (1.0, 3.0, 3.0 + 1e-12, 4.0, 4.5, 5.0, 5.0 + 1e-12, 1e3)] \
        == ["A", "A", "B", "B", "C", "C", "D", "D"]
    assert iso_zone(math.nan) is None and iso_zone(math.inf) == "D"
    assert 20 * math.log10(3) == pytest.approx(9.5, abs=0.05)
    assert 20 * math.log10(4) == pytest.approx(12.0, abs=0.05)
    assert 20 * math.log10(5) == pytest.approx(14.0, abs=0.05)


def test_failed_equilibrium_is_a_row_without_verdict(rig_laws):
    rig, laws = rig_laws
    assert rd.equilibrium(rig, 50.0, 1e8, AY, warm_start=False).status == "no_equilibrium"
    r = robust(rig, laws["pd"], {"chamber_pressure_pa": [PC, 1e8], "speed_hz": 50.0,
                                 "config_ay_m": AY}, threads=1)
    f = r.frame
    ok, failed = f.iloc[0], f.iloc[1]
    assert ok.status == "ok" and bool(ok.point_stable)
    assert failed.status == "no_equilibrium" and "no closed-loop verdict" in failed.message
    assert failed.point_stable is None or (isinstance(failed.point_stable, float)
                                           and math.isnan(failed.point_stable))
    for col in ("max_real_1_per_s", "gain_margin_upper", "peak_sensitivity", "journal_x_m"):
        assert math.isnan(failed[col]), col
    assert r.summary()["failed"] == 1 and not r.all_stable
    # the worst case is over the points that have a verdict
    assert r.worst()["max_real_1_per_s"]["point_id"] == int(ok.point_id)


def test_rows_do_not_depend_on_chunks_or_threads_and_resume(rig_laws, tmp_path):
    rig, laws = rig_laws
    grid = {"speed_hz": {"start": 40.0, "stop": 60.0, "num": 5},
            "chamber_pressure_pa": [0.04e6, 0.06e6], "config_ay_m": AY}
    a = robust(rig, laws["pd"], grid, margins=False, threads=1, chunk_size=10)
    b = robust(rig, laws["pd"], grid, margins=False, threads=2, chunk_size=1,
               out=tmp_path / "r")
    cols = [c for c in a.frame.columns if c not in ("chunk_id",)]
    assert a.frame[cols].equals(b.frame[cols])
    # a rerun on the same directory resumes (nothing left to compute) with the same rows
    c = robust(rig, laws["pd"], grid, margins=False, threads=2, chunk_size=1,
               out=tmp_path / "r")
    assert c.frame.equals(b.frame)
    # equilibria continued along the speed lines, or each solved cold: the same loop
    d = robust(rig, laws["pd"], grid, margins=False, threads=1, continuation=False)
    assert d.frame.point_stable.equals(a.frame.point_stable)
    np.testing.assert_allclose(d.frame.max_real_1_per_s, a.frame.max_real_1_per_s, rtol=1e-9)


def test_model_field_axis_against_the_rebuilt_model(rig_laws):
    rig, laws = rig_laws
    k = laws["pd"]
    r = robust(rig, k, {"bearings.active.viscosity_pa_s": [0.03, 0.05], "speed_hz": 50.0,
                        "chamber_pressure_pa": PC, "config_ay_m": AY},
               margins=False, threads=1)
    for _, row in r.frame.iterrows():
        mu = row["bearings.active.viscosity_pa_s"]
        sysv = set_field(rig, "bearings.active.viscosity_pa_s", mu)
        ref = numpy_max_real(sysv, k, 50.0, PC, AY)
        assert row.max_real_1_per_s == pytest.approx(ref, rel=1e-9, abs=1e-9)
    # the viscosity changes the loop
    assert abs(r.frame.max_real_1_per_s.diff().iloc[1]) > 1e-3


def test_bad_input_names_the_field(rig_laws):
    rig, laws = rig_laws
    k = laws["pd"]
    cases = [({}, "grid"), ({"speed_hz": []}, "grid.speed_hz"),
             ({"speed_hz": [50.0, math.nan]}, r"grid.speed_hz\[1\]"),
             ({"speed_hz": [50.0, math.inf]}, r"grid.speed_hz\[1\]"),
             ({"nonsense": [1.0]}, "grid.nonsense"),
             ({"bearings.active.no_such_field_m": [1.0]},
              "grid.bearings.active.no_such_field_m"),
             ({"chamber_pressure_pa": [-1.0]}, r"grid.chamber_pressure_pa\[0\]"),
             ({"config_ax_m": [0.0]}, "grid.config_ax_m")]
    for grid, field in cases:
        with pytest.raises(InputError, match=field):
            build_spec(rig, k, grid)
    with pytest.raises(InputError, match="grid"):
        build_spec(rig, k, [50.0])
    with pytest.raises(InputError, match="controller"):
        build_spec(rig, "pd", {"speed_hz": 50.0})
    with pytest.raises(InputError, match="margins"):
        build_spec(rig, k, {"speed_hz": 50.0}, margins="yes")
    with pytest.raises(InputError, match="equilibrium.max_iter"):
        build_spec(rig, k, {"speed_hz": 50.0}, equilibrium={"max_iter": 0})
    with pytest.raises(InputError, match="system"):
        build_spec("paper-rig", k, {"speed_hz": 50.0})


def test_not_the_rig_compressor_with_an_active_bearing():
    """The compressor (1.2 m, 210 kg) with the rig's active bearing scaled to its 100 mm DE
    journal (tests/data/models/compressor_active_de.toml): a PD tuned at 150 Hz, 0.5 MPa (open
    loop unstable there) over speed × p_c. Verdicts against the numpy closed loop; p_c = 0
    leaves the sleeve without support (no equilibrium: rows without verdict)."""
    from rotordyn.control.pid import tune_pd

    s = rd.System.from_toml(f"{MODELS}/compressor_active_de.toml")
    p = plant(s, 150.0, 0.5e6, measurements=[("journal", 0)])
    assert p.poles.real.max() > 0
    k = tune_pd(p)[0]
    r = robust(s, k, {"speed_hz": [100.0, 150.0, 200.0],
                      "chamber_pressure_pa": [0.0, 0.5e6, 1e6]}, threads=2)
    f = r.frame
    failed = f[f.point_stable.isna()]
    assert len(failed) >= 1 and set(failed.status) <= {"no_equilibrium", "not_converged"}
    have = f[f.point_stable.notna()]
    assert {True, False} <= set(have.point_stable.astype(bool))
    for _, row in have.iterrows():
        ref = numpy_max_real(s, k, row.speed_hz, row.chamber_pressure_pa, None)
        assert row.max_real_1_per_s == pytest.approx(ref, rel=1e-9, abs=1e-9)
        assert bool(row.point_stable) == (ref < 0)
    design = have[(have.speed_hz == 150.0) & (have.chamber_pressure_pa == 0.5e6)].iloc[0]
    assert bool(design.point_stable)
    m = mg.margins(plant(s, 150.0, 0.5e6, equilibrium=COLD), k).input
    assert design.gain_margin_upper == pytest.approx(m.gain_margin_upper, rel=1e-9)
    assert design.peak_sensitivity == pytest.approx(m.peak_sensitivity, rel=1e-9)
    assert design.iso_zone == iso_zone(m.peak_sensitivity)


def test_the_same_sweep_from_a_spec_file(rig_laws, tmp_path):
    """The spec text robust() stores, run as a file by the sweep runner (``rotordyn sweep``),
    gives the same rows."""
    from rotordyn.sweep.robust import spec_toml
    from rotordyn.sweep import open_dataset, run_sweep

    rig, laws = rig_laws
    grid = {"speed_hz": [50.0, 70.0], "chamber_pressure_pa": PC, "config_ay_m": AY}
    a = robust(rig, laws["pd"], grid, margins=False, threads=1)
    spec = build_spec(rig, laws["pd"], grid, margins=False)
    path = tmp_path / "robust.toml"
    path.write_text(spec_toml("robust", spec.axes, spec.options, spec.chunk_size, "paper-rig"))
    res = run_sweep(path, tmp_path / "out", threads=1, progress=False)
    assert res.counts == {"ok": 2, "failed": 0, "unstable": 1}
    b = open_dataset(tmp_path / "out").frame
    cols = ["speed_hz", "point_stable", "max_real_1_per_s", "min_damping_ratio", "status"]
    assert a.frame[cols].equals(b[cols])
