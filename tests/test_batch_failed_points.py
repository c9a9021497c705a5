"""One rule for a failed point in both sweep batches (``_core.equilibrium_batch``,
``_core.stability_batch``) and their rows: every numeric output of a point whose equilibrium
failed is NaN (the equilibrium, the minimum films and their z, the films' H, the residual;
the eigenvalues and sleeve shares, n_eig 0 and no modes), its status and a message are set;
only the iteration count (the work done) stays. Before, the equilibrium batch kept the failed
Newton's last iterate (r, H, minimum films, residual) and the stability batch its minimum
films — numbers beside a failed status, by two different rules.

A real failure, not a faked one: the compressor of tests/data/models on plain bearings with
``tilt = true`` (not the paper rig), its DE housing misaligned by 3.99 mrad about y (the film
nearly closed at an edge, |θ| L/2 = 0.9975 c: no equilibrium, docs/film-physics.md), between
points misaligned by 0.3 mrad that converge."""

import dataclasses
from pathlib import Path

import numpy as np

import rotordyn
import rotordyn.sweep as sw
from rotordyn import _core
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.sweep import run_sweep
from rotordyn.sweep.points import equilibrium_options
from rotordyn.units import hz_to_rad_s

MODELS = Path(__file__).parent / "data" / "models"
GOOD, BAD = 3e-4, 3.99e-3


def _compressor(theta):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=36, n_axial=8,
                            config_theta_y_rad=theta if k == 1 else 0.0)
        for k, b in enumerate(s.bearings)))


def _inputs(thetas):
    asms = [Assembled(_compressor(t)) for t in thetas]
    a = np.array([asm.config_vector() for asm in asms])
    return asms[0], (np.full(len(thetas), hz_to_rad_s(150.0)), np.zeros(len(thetas)), a,
                     [1] * len(thetas))


def _check(res, failed, extra=()):
    st = list(res.status)
    assert [s not in ("ok", "contact") for s in st] == failed
    for k, bad in enumerate(failed):
        arrays = [np.asarray(res.r)[k], np.asarray(res.h_min)[k],
                  np.asarray(res.h_min_z_m)[k], np.asarray(res.film_force)[k]]
        arrays += [np.atleast_1d(np.asarray(getattr(res, n))[k]) for n in extra]
        if bad:
            assert res.message[k], k
            for x in arrays:
                assert np.all(np.isnan(x)), (k, x)
        else:
            assert np.all(np.isfinite(np.asarray(res.r)[k]))
            assert np.all(np.isfinite(np.asarray(res.film_force)[k]))


def test_both_batches_fill_a_failed_point_by_one_rule():
    thetas = [GOOD, BAD, GOOD]
    asm, inp = _inputs(thetas)
    # the configuration vectors carry each point's misalignment (config_vector of its model)
    assert inp[2][1][asm.bearings[1].rot[1]] == BAD
    eq = _core.equilibrium_batch(_core.SystemSolver(asm.model), *inp, equilibrium_options({}))
    _check(eq, [False, True, False], extra=("residual",))
    assert np.isfinite(np.asarray(eq.residual)[[0, 2]]).all()
    st = _core.stability_batch(
        _core.SystemSolver(asm.model), *inp, equilibrium_options({}), 4, False, FD_REL_STEP,
        asm.rotor.xy_pairs(), asm.rotor.rot_pairs(), [])
    _check(st, [False, True, False], extra=("eigenvalues", "sleeve_share"))
    assert np.asarray(st.n_eig)[1] == 0 and np.asarray(st.modes[1]).size == 0
    assert np.asarray(st.n_eig)[0] == 4 and np.all(np.asarray(st.whirl)[1] == 0)
    assert list(eq.status) == list(st.status) and eq.status[1] != "error"
    assert int(np.asarray(eq.iterations)[1]) > 0  # the work done stays


def _sweep(tmp_path, analysis):
    s = _compressor(GOOD)
    s.to_toml(tmp_path / "m.toml")
    spec = tmp_path / f"{analysis}.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "{analysis}"\nmodel = "m.toml"\n'
                    f'analysis = "{analysis}"\n[grid]\n'
                    f'"bearings.1.config_theta_y_rad" = [{GOOD}, {BAD}]\n'
                    'speed_hz = [150.0]\n'
                    + ('[options]\nn_modes = 4\n' if analysis == "stability" else ''))
    run_sweep(spec, tmp_path / f"o_{analysis}", threads=1)
    return sw.open(tmp_path / f"o_{analysis}").frame


def test_failed_rows_of_both_sweeps_have_no_numbers(tmp_path):
    for analysis in ("equilibrium", "stability"):
        f = _sweep(tmp_path, analysis)
        bad = f[f["bearings.1.config_theta_y_rad"] == BAD]
        good = f[f["bearings.1.config_theta_y_rad"] == GOOD]
        assert len(bad) and (bad["status"] == "no_equilibrium").all(), analysis
        assert (bad["message"] != "").all() and (good["status"] == "ok").all()
        skip = {"point_id", "chunk_id", "speed_hz", "chamber_pressure_pa", "config_ay_m",
                "bearings.1.config_theta_y_rad", "iterations"}
        numeric = [c for c in f.columns if c not in skip and not c.startswith("i_")
                   and pd_numeric(f[c])]
        assert "journal_x_m" in numeric and "h_min_m" in numeric
        for c in numeric:
            assert bad[c].isna().all(), (analysis, c)
        assert good["journal_x_m"].notna().all()


def pd_numeric(col) -> bool:
    import pandas as pd

    return pd.api.types.is_float_dtype(col) or pd.api.types.is_integer_dtype(col)
