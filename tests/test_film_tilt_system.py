"""Journal tilt in a system (issue 20): plain bearings whose films couple to the rotor's
rotations at their stations (``tilt = true``), housing misalignment as the configuration at
those rotations, Guyan masters that keep the rotations, model file and sweep axes.

References: the static Guyan condensation is exact for the master coordinates (K_mm* u_m =
Tᵀ f), so the Guyan model with the rotations kept as masters reaches the same equilibrium
(translations and rotations at the bearings) as the unreduced FE model; K_H on the rotations
against central differences of the film forces and moments; the weight is carried by the
bearings' vertical forces; the edge film sits at an edge.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.analysis.assembly import assembled
from rotordyn.errors import InputError
from rotordyn.sweep import run_sweep

MODELS = Path(__file__).parent / "data" / "models"
F_HZ = 150.0


def compressor(tilt=True, **fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    bs = tuple(dataclasses.replace(b, tilt=tilt, n_circ=48, n_axial=12, **fields)
               for b in s.bearings)
    return dataclasses.replace(s, bearings=bs)


def test_guyan_masters_keep_the_rotations_static_condensation_is_exact():
    s = compressor()
    assert s.tilt_stations() == [1, 5]
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    assert e.status == "ok", e.message
    full = dataclasses.replace(s, reduction=dataclasses.replace(s.reduction, method="none"))
    ef = rotordyn.equilibrium(full, speed_hz=F_HZ)
    assert ef.status == "ok", ef.message
    np.testing.assert_allclose(e.journal_x_m, ef.journal_x_m, rtol=0, atol=1e-9 * 1e-4)
    np.testing.assert_allclose(e.journal_y_m, ef.journal_y_m, rtol=0, atol=1e-9 * 1e-4)
    for i in (0, 1):
        for k in ("journal_theta_x_rad", "journal_theta_y_rad", "h_min_z_m"):
            assert e.tilt[i][k] == pytest.approx(ef.tilt[i][k], rel=1e-6, abs=1e-12), k
    # the rotor's slope at the bearings is real (not zero) and the films carry moments
    th = np.array([[e.tilt[i]["journal_theta_x_rad"], e.tilt[i]["journal_theta_y_rad"]]
                   for i in (0, 1)])
    assert np.abs(th).max() > 1e-6
    asm = assembled(s)
    mom = [e.film_force_n[list(bc.rot)] for bc in asm.bearings]
    assert np.abs(np.concatenate(mom)).max() > 0.1  # N·m
    # weight carried by the vertical film forces
    W = s.mass_kg * 9.81
    fy = sum(e.film_force_n[bc.jy] for bc in asm.bearings)
    assert fy == pytest.approx(W, rel=1e-6)
    # the untilted system: same weight, other rotations (no film moments)
    e0 = rotordyn.equilibrium(compressor(tilt=False), speed_hz=F_HZ)
    assert e0.status == "ok" and not e0.tilt
    assert np.abs(e.journal_y_m - e0.journal_y_m).max() > 0


def test_system_tilt_coefficients_match_finite_differences():
    s = compressor(config_theta_y_rad=2e-4)
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    assert e.status == "ok", e.message
    asm = assembled(s)
    w = 2 * np.pi * F_HZ
    lin = asm.solver.linearize(e.r, np.zeros(asm.n), w)
    fd = asm.solver.linearize_fd(e.r, w, 1e-6)
    for bc in asm.bearings:
        idx = [bc.jx, bc.jy] + list(bc.rot)
        for A, B in ((lin.KH, fd.KH), (lin.DH, fd.DH)):
            for rows in (idx[:2], idx[2:]):
                for cols in (idx[:2], idx[2:]):
                    blk = np.asarray(A)[np.ix_(rows, cols)]
                    ref = np.asarray(B)[np.ix_(rows, cols)]
                    np.testing.assert_allclose(blk, ref, rtol=0, atol=2e-5 * np.abs(ref).max())
        assert np.abs(np.asarray(lin.KH)[np.ix_(idx[2:], idx[2:])]).max() > 0


def test_misalignment_moves_the_minimum_film_to_an_edge():
    al = 3e-4  # rad: α L/2 = 0.075 c
    s = compressor(config_theta_y_rad=al)
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    e0 = rotordyn.equilibrium(compressor(), speed_hz=F_HZ)
    assert e.status == "ok", e.message
    L = s.bearings[0].length_m
    for i in (0, 1):
        assert e.tilt[i]["config_theta_y_rad"] == al
        assert abs(e.tilt[i]["h_min_z_m"]) == pytest.approx(L / 2)
        # the journal follows the shaft line: relative tilt ≈ −α (the films resist a little)
        assert e.tilt[i]["journal_theta_y_rad"] == pytest.approx(-al, rel=0.3)
    assert np.all(e.h_min_m < e0.h_min_m)
    fr = e.to_frame()
    assert {"journal_theta_x_rad", "journal_theta_y_rad", "config_theta_y_rad",
            "h_min_z_m"} <= set(fr.columns)


def test_stability_campbell_with_tilting_films():
    s = compressor(config_theta_x_rad=1e-4)
    st = rotordyn.stability(s, speed_hz=F_HZ)
    assert st.status == "ok"
    assert np.all(np.isfinite(st.eigenvalues))
    st0 = rotordyn.stability(compressor(tilt=False), speed_hz=F_HZ)
    # the rotations of the two bearing stations are coordinates now: four more modes
    assert len(st.eigenvalues) == len(st0.eigenvalues) + 4
    # the film moments move the least damped mode, a little at this slenderness
    assert st.eigenvalues.real.max() != st0.eigenvalues.real.max()
    cb = rotordyn.campbell(s, [60.0, 150.0])
    assert np.all(np.asarray(cb.point_status) == "ok")


def test_toml_round_trip_with_tilt_and_misalignment():
    s = compressor(config_theta_x_rad=1e-4, config_theta_y_rad=-2e-4)
    text = s.to_toml()
    assert "tilt = true" in text and "config_theta_y_rad = -0.0002" in text
    assert rotordyn.System.from_toml(text, is_text=True) == s


def test_misalignment_as_a_sweep_axis(tmp_path):
    s = compressor()
    s.to_toml(tmp_path / "m.toml")
    p = tmp_path / "s.toml"
    p.write_text('schema = "rotordyn/sweep/1"\nname = "tilt"\nmodel = "m.toml"\n'
                 'analysis = "equilibrium"\nchunk_size = 4\n[grid]\n'
                 '"bearings.0.config_theta_y_rad" = [0.0, 2e-4]\nspeed_hz = 150.0\n')
    res = run_sweep(p, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    for val, g in fr.groupby("bearings.0.config_theta_y_rad"):
        b0 = dataclasses.replace(s.bearings[0], config_theta_y_rad=float(val))
        e = rotordyn.equilibrium(dataclasses.replace(s, bearings=(b0, s.bearings[1])),
                                 speed_hz=150.0)
        row = g[g["bearing"] == e.bearing_names[0]].iloc[0]
        assert row["journal_y_m"] == pytest.approx(e.journal_y_m[0], rel=1e-8)
        for k in ("journal_theta_x_rad", "journal_theta_y_rad", "h_min_z_m",
                  "film_moment_x_n_m", "film_moment_y_n_m"):
            assert row[k] == pytest.approx(e.tilt[0][k], rel=1e-7, abs=1e-15), k


@pytest.mark.parametrize("fields,match", [
    (dict(config_theta_y_rad=float("nan")), "config_theta_y_rad"),
    (dict(config_theta_x_rad=4.1e-3), "config_theta_x_rad, config_theta_y_rad"),
    (dict(tilt=False, config_theta_x_rad=1e-4), "tilt = true"),
    (dict(tilt=1), "tilt"),
])
def test_bad_tilt_fields_raise_input_error(fields, match):
    with pytest.raises(InputError, match=match):
        s = compressor(**{"tilt": True, **fields})
        rotordyn.equilibrium(s, speed_hz=F_HZ)


def rig_with_tilt(**fields):
    rig = rotordyn.models.paper_rig()
    bs = tuple(dataclasses.replace(b, tilt=True, **fields)
               if isinstance(b, rotordyn.ActiveJournalBearing) else b for b in rig.bearings)
    return dataclasses.replace(rig, bearings=bs)


def test_paper_rig_active_bearing_tilt():
    """The rig's active bearing with a tilting film (sleeve coordinates of weight 1 beside the
    rotations): at a_y = −1.85 mm the housing offset bends the shaft, the journal crosses the
    bearing at a slope and the minimum film moves to an edge; the Guyan model with the
    station's rotations as masters reaches the unreduced model's equilibrium."""
    s = rig_with_tilt()
    kw = dict(speed_hz=50.0, chamber_pressure_pa=0.1e6, config_ay_m=-1.85e-3)
    e = rotordyn.equilibrium(s, **kw)
    assert e.status == "ok", e.message
    e0 = rotordyn.equilibrium(rotordyn.models.paper_rig(), **kw)
    t = e.tilt[0]
    L = s.bearings[0].length_m
    assert abs(t["journal_theta_x_rad"]) > 1e-4  # the offset's slope at the bearing (rad)
    assert abs(t["h_min_z_m"]) == pytest.approx(L / 2)
    assert e.h_min_m[0] < e0.h_min_m[0]
    full = dataclasses.replace(s, reduction=dataclasses.replace(s.reduction, method="none"))
    ef = rotordyn.equilibrium(full, **kw)
    assert ef.status == "ok", ef.message
    assert e.journal_x_m[0] == pytest.approx(ef.journal_x_m[0], rel=1e-6)
    assert e.journal_y_m[0] == pytest.approx(ef.journal_y_m[0], rel=1e-6)
    assert t["journal_theta_x_rad"] == pytest.approx(ef.tilt[0]["journal_theta_x_rad"], rel=1e-6)
    np.testing.assert_allclose(e.sleeve_m[0], ef.sleeve_m[0], rtol=1e-6,
                               atol=1e-9 * np.abs(ef.sleeve_m[0]).max())
    st = rotordyn.stability(s, 50.0, 0.1e6, -1.85e-3)
    assert st.status == "ok" and np.all(np.isfinite(st.eigenvalues))
    cb = rotordyn.campbell(s, [30.0, 50.0], chamber_pressure_pa=0.4e6)
    assert np.all(np.asarray(cb.point_status) == "ok")


def test_paper_rig_tilt_toml_round_trip_and_misalignment_axis(tmp_path):
    s = rig_with_tilt(config_theta_x_rad=5e-4)
    assert rotordyn.System.from_toml(s.to_toml(), is_text=True) == s
    s.to_toml(tmp_path / "m.toml")
    p = tmp_path / "s.toml"
    p.write_text('schema = "rotordyn/sweep/1"\nname = "tilt"\nmodel = "m.toml"\n'
                 'analysis = "stability"\nchunk_size = 4\n[grid]\n'
                 '"bearings.0.config_theta_x_rad" = [0.0, 5e-4]\nspeed_hz = 50.0\n'
                 'chamber_pressure_pa = 0.1e6\n')
    res = run_sweep(p, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    for val, g in fr.groupby("bearings.0.config_theta_x_rad"):
        b0 = dataclasses.replace(s.bearings[0], config_theta_x_rad=float(val))
        st = rotordyn.stability(dataclasses.replace(s, bearings=(b0,)), speed_hz=50.0,
                                chamber_pressure_pa=0.1e6)
        np.testing.assert_allclose(g["max_real_1_per_s"].iloc[0], st.eigenvalues.real.max(),
                                   rtol=1e-7)


def test_transient_matches_the_linear_model_at_small_amplitude():
    """A 0.5 µm kick of the compressor with tilting, misaligned films: the nonlinear transient
    against exp(A t) of the linearised model (eq. 19), every coordinate (translations and
    rotations) within 1 % of its amplitude (observed ≤ 0.5 %). The rotations need an absolute
    tolerance below their amplitude (~1e-6 rad): atol_m applies to them in rad."""
    import scipy.linalg

    s = compressor(config_theta_y_rad=2e-4)
    lm = rotordyn.linearize(s, speed_hz=F_HZ)
    e = lm.equilibrium
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    tr = rotordyn.transient(s, t_end_s=0.01, speed_hz=F_HZ, disturbance_m=(0.5e-6, 0.0),
                            n_out=11, rtol=1e-9, atol_m=1e-13)
    assert tr.status == "ok", tr.message
    x0 = np.concatenate([tr.r[0] - e.r, np.zeros(n)])
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - e.r
    scale = np.abs(lin).max(axis=0)
    assert np.all(np.abs(dev - lin).max(axis=0) < 0.01 * scale)


@pytest.mark.parametrize("method", ["craig-bampton", "irs"])
def test_other_reductions_keep_the_rotations(method):
    """Craig–Bampton (constraint modes = Guyan's, plus fixed-interface modes) is exact
    statically at the masters like Guyan; IRS adds inertia corrections to the transformation,
    so its static loads differ slightly (observed: rotations +0.12 %, translations 1.5e-6)."""
    s = compressor()
    red = dataclasses.replace(s.reduction, method=method,
                              n_modes=2 if method == "craig-bampton" else 0)
    e = rotordyn.equilibrium(dataclasses.replace(s, reduction=red), speed_hz=F_HZ)
    full = dataclasses.replace(s, reduction=dataclasses.replace(s.reduction, method="none"))
    ef = rotordyn.equilibrium(full, speed_hz=F_HZ)
    assert e.status == "ok" and ef.status == "ok"
    rel = 1e-6 if method == "craig-bampton" else 5e-3
    for i in (0, 1):
        assert e.tilt[i]["journal_theta_x_rad"] == pytest.approx(
            ef.tilt[i]["journal_theta_x_rad"], rel=rel)
    np.testing.assert_allclose(e.journal_y_m, ef.journal_y_m, rtol=rel)
