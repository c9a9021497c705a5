"""A tilted journal's outputs beyond the equilibrium (issue 20): the stability and Campbell
sweep rows, the transient's time histories and the report's coefficient tables carry the
journal rotations, the films' moments, the edge film and the 4×4 coupling blocks.

On the compressor of tests/data/models (not the paper rig) on plain journal bearings with
`tilt = true` and the housings misaligned about y (α L/2 = 0.075 c):
* stability/Campbell sweep rows: the per-bearing lists (`tilt_bearing`, `journal_theta_*`,
  `film_moment_*`, `tilt_h_min_m`, `h_min_z_m`) equal the direct equilibrium's `tilt` at the
  point (the sweep continues its equilibria with a reused Jacobian: equal within the
  equilibrium tolerance, checked at 1e-6 of the largest entry); a failed point's row has them
  null; an untilted model's schema has none of them;
* `TransientResult.to_frame()`: the rotations are the state's, the moments at t = 0 (the
  run starts at the equilibrium, at rest) equal the equilibrium's film moments, and at a
  later sample the standalone film's (`tilted_forces` with the journal's translational and
  angular velocities) to 1e-9;
* `bearing_coefficients` / the report: the 4×4 entries beyond the x, y block equal the
  standalone film's `tilted_coefficients` at the equilibrium pose, and the text report
  prints the coupling tables only for a tilting film.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
import rotordyn.sweep as sw
from rotordyn.bearings.tilt import tilted_coefficients, tilted_forces
from rotordyn.sweep import run_sweep

MODELS = Path(__file__).parent / "data" / "models"
AL = 3e-4  # rad: housing misalignment about y


def compressor(tilt=True, **fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=tilt, n_circ=36, n_axial=8, **fields)
        for b in s.bearings))


LISTS = ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
         "film_moment_y_n_m", "h_min_z_m")


def _sweep(tmp_path, system, analysis, grid, name="s"):
    system.to_toml(tmp_path / f"{name}.toml")
    spec = tmp_path / f"{name}_spec.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "{name}"\nmodel = "{name}.toml"\n'
                    f'analysis = "{analysis}"\n[grid]\n{grid}\n[options]\nn_modes = 4\n')
    run_sweep(spec, tmp_path / f"o_{name}", threads=1)
    return sw.open(tmp_path / f"o_{name}").frame


@pytest.mark.parametrize("analysis", ["stability", "campbell"])
def test_sweep_rows_carry_the_equilibrium_tilt(tmp_path, analysis):
    s = compressor(config_theta_y_rad=AL)
    # DE misaligned by 3.99 mrad (open at the edge, |θ| L/2 = 0.9975 c) has no equilibrium
    # (docs/film-physics.md): a failed row that must carry no tilt values
    f = _sweep(tmp_path, s, analysis, '"bearings.1.config_theta_y_rad" = [3e-4, 3.99e-3]\n'
               'speed_hz = [100.0, 150.0]')
    bad = f[f["bearings.1.config_theta_y_rad"] == 3.99e-3]
    assert len(bad) == 2 and (bad["status"] == "no_equilibrium").all()
    for c in ("tilt_bearing", "tilt_h_min_m", *LISTS):
        assert bad[c].isna().all(), c
    good = f[f["bearings.1.config_theta_y_rad"] == AL]
    assert (good["status"] == "ok").all() and len(good) == 2 * 4
    for speed, g in good.groupby("speed_hz"):
        e = rotordyn.equilibrium(s, speed_hz=speed)
        assert e.status == "ok"
        row = g.iloc[0]
        assert list(row["tilt_bearing"]) == [b.name for b in s.bearings]
        for c in LISTS:
            ref = np.array([e.tilt[i][c] for i in range(len(s.bearings))])
            got = np.asarray(row[c], dtype=float)
            np.testing.assert_allclose(got, ref, rtol=1e-6, atol=1e-6 * np.abs(ref).max(),
                                       err_msg=c)
            for _, other in g.iterrows():  # every mode row of the point the same lists
                np.testing.assert_array_equal(np.asarray(other[c], dtype=float), got)
        np.testing.assert_allclose(np.asarray(row["tilt_h_min_m"], dtype=float), e.h_min_m,
                                   rtol=1e-6)
        assert abs(np.asarray(row["film_moment_y_n_m"], dtype=float)).max() > 0.01
        assert np.all(np.abs(np.asarray(row["h_min_z_m"], dtype=float))
                      == pytest.approx(s.bearings[0].length_m / 2))


def test_untilted_stability_sweep_has_no_tilt_columns(tmp_path):
    f = _sweep(tmp_path, compressor(tilt=False), "stability", "speed_hz = [150.0]", "flat")
    assert (f["status"] == "ok").all()
    assert "tilt_bearing" not in f and "journal_theta_x_rad" not in f


def test_transient_frame_has_rotations_and_moments():
    s = compressor(config_theta_y_rad=AL)
    e = rotordyn.equilibrium(s, speed_hz=150.0)
    tr = rotordyn.transient(s, t_end_s=4 / 150.0, speed_hz=150.0, n_out=17,
                            unbalances=[(3, 2e-4, 0.0)])
    assert tr.status == "ok", tr.message
    fr = tr.to_frame()
    nb = len(s.bearings)
    for c in ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
              "film_moment_y_n_m"):
        assert c in fr and np.all(np.isfinite(fr[c]))
    from rotordyn.analysis.assembly import assembled

    bcs = assembled(s).bearings
    for b, bc in enumerate(bcs):
        np.testing.assert_array_equal(tr.journal_theta_x_rad[:, b], tr.r[:, bc.rot[0]])
        np.testing.assert_array_equal(fr["journal_theta_y_rad"].to_numpy()[b::nb],
                                      tr.r[:, bc.rot[1]])
        # t = 0: the equilibrium at rest
        m0 = np.array([tr.film_moment_x_n_m[0, b], tr.film_moment_y_n_m[0, b]])
        ref0 = np.array([e.tilt[b]["film_moment_x_n_m"], e.tilt[b]["film_moment_y_n_m"]])
        np.testing.assert_allclose(m0, ref0, rtol=1e-6, atol=1e-6 * np.abs(ref0).max())
        # a later sample, the journal moving: the standalone film at that state
        k = 12
        t = tilted_forces(s.bearings[b].journal_bearing(), x_m=tr.r[k, bc.jx],
                          y_m=tr.r[k, bc.jy], theta_x_rad=tr.r[k, bc.rot[0]],
                          theta_y_rad=tr.r[k, bc.rot[1]], vx_m_s=tr.v[k, bc.jx],
                          vy_m_s=tr.v[k, bc.jy], wx_rad_s=tr.v[k, bc.rot[0]],
                          wy_rad_s=tr.v[k, bc.rot[1]], speed_hz=150.0)
        got = np.array([tr.film_moment_x_n_m[k, b], tr.film_moment_y_n_m[k, b]])
        np.testing.assert_allclose(got, t.film_moment_n_m, rtol=1e-9,
                                   atol=1e-9 * np.abs(t.film_moment_n_m).max())
        assert np.ptp(tr.film_moment_y_n_m[:, b]) > 0  # it moves with the unbalance
    # without the recording: the same run (bit for bit), no moments, rotations kept
    tn = rotordyn.transient(s, t_end_s=4 / 150.0, speed_hz=150.0, n_out=17,
                            unbalances=[(3, 2e-4, 0.0)], record_film_moments=False)
    np.testing.assert_array_equal(tn.r, tr.r)
    assert tn.film_moment_x_n_m is None and "film_moment_y_n_m" not in tn.to_frame()
    assert "journal_theta_x_rad" in tn.to_frame()
    np.testing.assert_array_equal(tn.journal_theta_y_rad, tr.journal_theta_y_rad)
    with pytest.raises(rotordyn.InputError, match="record_film_moments"):
        rotordyn.transient(s, t_end_s=1 / 150.0, speed_hz=150.0, record_film_moments="yes")
    # an untilted model's frame is unchanged
    t0 = rotordyn.transient(compressor(tilt=False), t_end_s=1 / 150.0, speed_hz=150.0,
                            n_out=5)
    assert "film_moment_x_n_m" not in t0.to_frame() and t0.film_moment_x_n_m is None


def test_report_prints_the_coupling_blocks():
    from rotordyn.analysis.bearing_coefficients import TILT_COLUMNS, bearing_coefficients
    from rotordyn.report.sections import coefficient_text_lines

    s = compressor(config_theta_y_rad=AL)
    eqs: list = []
    fr = bearing_coefficients(s, [150.0], equilibria=eqs)
    e = eqs[0][2]
    assert set(TILT_COLUMNS) <= set(fr) and len(TILT_COLUMNS) == 24
    for i, b in enumerate(s.bearings):
        row = fr[fr["bearing"] == b.name].iloc[0]
        K, C = tilted_coefficients(b.journal_bearing(), x_m=e.journal_x_m[i],
                                   y_m=e.journal_y_m[i], speed_hz=150.0,
                                   theta_x_rad=e.tilt[i]["journal_theta_x_rad"],
                                   theta_y_rad=e.tilt[i]["journal_theta_y_rad"])
        _assert_coupling(row, K, C, TILT_COLUMNS, 1e-6, lambda M: np.abs(M[2:, 2:]).max())
        assert row["ktxtx_n_m_per_rad"] > 0 and row["cxtx_n_s_per_rad"] != 0
    text = "\n".join(coefficient_text_lines(fr))
    assert "tilting films: stiffness coupling" in text and "kθxθx (kN·m/rad)" in text
    assert "cxθy (N·s/rad)" in text
    # an untilted model: the x, y table alone, its frame without the tilt columns
    fu = bearing_coefficients(compressor(tilt=False), [150.0])
    assert not set(TILT_COLUMNS) & set(fu)
    tu = "\n".join(coefficient_text_lines(fu))
    assert "tilting" not in tu and "kxx (MN/m)" in tu


def _assert_coupling(row, K, C, columns, rel, scale):
    """The coupling entries (outside the x, y block) of a coefficient row against K, C
    (4×4 over x, y, θx, θy): relative ``rel``, absolute ``rel·scale(M)``."""
    q = ("x", "y", "tx", "ty")
    for kc, M in (("k", K), ("c", C)):
        for a in range(4):
            for c in range(4):
                if a < 2 and c < 2:
                    continue
                col = next(n for n in columns if n.startswith(f"{kc}{q[a]}{q[c]}_"))
                assert row[col] == pytest.approx(M[a, c], rel=rel, abs=rel * scale(M)), col


def test_tilting_pad_coupling_blocks_are_the_standalone_pads():
    """Pads condensed at synchronous whirl onto (x, y, θx, θy) in the system equal the
    standalone pads' `tilted_coefficients` (pads at their equilibrium for the held pose,
    condensed at ν = Ω) at the system's equilibrium pose: the embedding of the pads' own
    coordinates beside the rotations (measured agreement ~1e-14)."""
    from rotordyn.analysis.bearing_coefficients import TILT_COLUMNS, bearing_coefficients

    s = rotordyn.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6, tilt=True, config_theta_y_rad=AL)
        for b in s.bearings))
    eqs: list = []
    fr = bearing_coefficients(s, [150.0], equilibria=eqs)
    e = eqs[0][2]
    for i, b in enumerate(s.bearings):
        K, C = tilted_coefficients(b, x_m=e.journal_x_m[i], y_m=e.journal_y_m[i],
                                   speed_hz=150.0,
                                   theta_x_rad=e.tilt[i]["journal_theta_x_rad"],
                                   theta_y_rad=e.tilt[i]["journal_theta_y_rad"])
        row = fr[fr["bearing"] == b.name].iloc[0]
        np.testing.assert_allclose(
            row[["kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m"]].to_numpy(float),
            K[:2, :2].ravel(), rtol=1e-9)
        _assert_coupling(row, K, C, TILT_COLUMNS, 1e-9, lambda M: np.abs(M).max())


def test_thermal_stability_rows_carry_the_tilt(tmp_path):
    """`options.thermal`: the tilt lists are those of the point's thermal equilibrium (the
    direct `rotordyn.stability(..., thermal={})`'s equilibrium, the same calls: equal)."""
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    s = dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, tilt=True, n_circ=36, n_axial=8, config_theta_y_rad=AL)
        for b in s.bearings))
    s.to_toml(tmp_path / "th.toml")
    spec = tmp_path / "th_spec.toml"
    spec.write_text('schema = "rotordyn/sweep/1"\nname = "th"\nmodel = "th.toml"\n'
                    'analysis = "stability"\n[grid]\nspeed_hz = [150.0]\n'
                    '[options]\nn_modes = 4\n[options.thermal]\n')
    run_sweep(spec, tmp_path / "o_th", threads=1)
    f = sw.open(tmp_path / "o_th").frame
    assert (f["status"] == "ok").all() and len(f) == 4
    st = rotordyn.stability(s, 150.0, n_modes=4, thermal={})
    e = st.linear.equilibrium
    row = f.iloc[0]
    assert list(row["tilt_bearing"]) == [b.name for b in s.bearings]
    for c in LISTS:
        ref = np.array([e.tilt[i][c] for i in range(len(s.bearings))])
        np.testing.assert_allclose(np.asarray(row[c], dtype=float), ref, rtol=1e-9,
                                   atol=1e-9 * np.abs(ref).max(), err_msg=c)
    assert row["max_temperature_c"] > 0  # the thermal columns beside them
