"""Journal tilt and bearing misalignment in fixed-geometry bearings (issue 20): every lobe's
film couples to the journal's rotations (θx, θy) with the plain bearing's convention
(docs/film-physics.md, "Journal tilt and bearing misalignment").

References: zero tilt equals the untilted lobes (the weighted coordinates add exact zeros);
a 360° arc without preload is the plain bearing, whose tilted film is built by another path
(``tilt.tilt_coupling``, one 360° coupling, against ``FixedGeometryBearing.films``' mapped
lobe grid); the mirror z → −z maps a tilt θ to −θ, so a tilt and its opposite give equal
forces and opposite moments (to round-off); K on the rotations against central differences
of forces and moments; the grid study's observed order (second-order scheme); a system test
on the compressor of tests/data/models with elliptical (two-lobe) bearings.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.analysis.assembly import assembled
from rotordyn.bearings import (FixedGeometryBearing, JournalBearing, TiltingPadBearing,
                               misaligned_equilibrium, tilted_coefficients, tilted_forces)
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
GEOM = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4, viscosity_pa_s=0.018)
POSE = dict(x_m=2e-5, y_m=-4e-5, speed_hz=100.0)
TILT = dict(theta_x_rad=4e-4, theta_y_rad=-6e-4)  # edge displacement 18 µm = 0.18 c


def fixed(kind, **kw):
    return FixedGeometryBearing(station=0, kind=kind, **{**GEOM, "n_circ": 48, "n_axial": 12,
                                                         **kw})


KINDS = [dict(kind="elliptical"), dict(kind="offset_halves"), dict(kind="three_lobe"),
         dict(kind="partial_arc", arc_deg=160.0),
         dict(kind="pressure_dam", dam_depth_m=2e-4)]


@pytest.mark.parametrize("kw", KINDS, ids=lambda k: k["kind"])
def test_zero_tilt_is_the_untilted_bearing(kw):
    """The four-coordinate lobes at θ = 0: forces and the 2×2 K, C of the untilted bearing
    (weighted coordinates add exact zeros to h; the half-grid shortcut tests h itself)."""
    b = fixed(**kw)
    t = tilted_forces(b, **POSE)
    f = b.forces(**POSE)
    np.testing.assert_allclose(t.force_n, f, rtol=1e-12, atol=1e-12 * np.abs(f).max())
    K, C = tilted_coefficients(b, **POSE)
    K0, C0 = b.coefficients(**POSE)
    np.testing.assert_allclose(K[:2, :2], K0, rtol=0, atol=1e-12 * np.abs(K0).max())
    np.testing.assert_allclose(C[:2, :2], C0, rtol=0, atol=1e-12 * np.abs(C0).max())


def test_full_arc_equals_the_plain_journal_bearing_tilted():
    """kind = partial_arc, arc_deg = 360 (no preload): the plain journal bearing's tilted film
    (forces, moments, 4×4 K, C, edge film, misaligned equilibrium) to 1e-12."""
    fb = fixed("partial_arc", arc_deg=360.0)
    jb = JournalBearing(**GEOM, n_circ=48, n_axial=12)
    a, b = tilted_forces(fb, **POSE, **TILT), tilted_forces(jb, **POSE, **TILT)
    np.testing.assert_allclose(a.force_n, b.force_n, rtol=1e-12)
    np.testing.assert_allclose(a.film_moment_n_m, b.film_moment_n_m, rtol=1e-12)
    assert (a.h_min_m, a.h_min_angle_deg, a.h_min_z_m) == pytest.approx(
        (b.h_min_m, b.h_min_angle_deg, b.h_min_z_m), rel=1e-12)
    for A, B in zip(tilted_coefficients(fb, **POSE, **TILT),
                    tilted_coefficients(jb, **POSE, **TILT)):
        np.testing.assert_allclose(A, B, rtol=0, atol=1e-12 * np.abs(B).max())
    ma = misaligned_equilibrium(fb, load_n=(0.0, -2000.0), speed_hz=100.0, theta_x_rad=4e-4)
    mb = misaligned_equilibrium(jb, load_n=(0.0, -2000.0), speed_hz=100.0, theta_x_rad=4e-4)
    assert ma.status == mb.status == "ok"
    assert (ma.x_m, ma.y_m) == pytest.approx((mb.x_m, mb.y_m), rel=1e-10)
    np.testing.assert_allclose(ma.film_moment_n_m, mb.film_moment_n_m, rtol=1e-9)


@pytest.mark.parametrize("kw", KINDS[:4], ids=lambda k: k["kind"])
def test_opposite_tilts_mirror(kw):
    """Mirror z → −z: a tilt and its opposite give the same forces, opposite moments and the
    edge film at the opposite edge (symmetric grid in z: to round-off). A tilt of the aligned
    journal gives moments of the order of F·θ·L²/c."""
    b = fixed(**kw)
    p = tilted_forces(b, **POSE, **TILT)
    m = tilted_forces(b, **POSE, theta_x_rad=-TILT["theta_x_rad"],
                      theta_y_rad=-TILT["theta_y_rad"])
    F = np.abs(p.force_n).max()
    np.testing.assert_allclose(p.force_n, m.force_n, rtol=0, atol=1e-10 * F)
    np.testing.assert_allclose(p.film_moment_n_m, -m.film_moment_n_m, rtol=0,
                               atol=1e-10 * np.abs(p.film_moment_n_m).max())
    assert p.h_min_z_m == pytest.approx(-m.h_min_z_m, abs=1e-15)
    assert abs(p.h_min_z_m) == pytest.approx(0.5 * b.length_m)
    assert np.abs(p.film_moment_n_m).max() > 1e-3 * F * b.length_m


def test_centred_tilt_no_force_first_order_moment_with_its_sign():
    """Centred journal, Swift–Stieber film, in a 360° arc and in the elliptical bearing (lobes
    at 90° and 270°): both films are invariant under (φ, z) → (φ + π, −z), so the net force
    of a tilted journal vanishes (round-off) while the moment is first order in θ; θy > 0
    gives Mx < 0 (docs/film-physics.md's sign check; the elliptical's preloaded lobes give
    the same sign). The moment is odd in θ, M = M1 θ + O(θ³): observed orders 1.002 (360°)
    and 1.024 (elliptical: its lobes' cavitation boundaries move with the tilt) for θ·L/2 =
    0.05 → 0.025 c."""
    for b in (fixed("partial_arc", arc_deg=360.0), fixed("elliptical")):
        ms = []
        for th in (2e-4, 1e-4):
            t = tilted_forces(b, x_m=0.0, y_m=0.0, speed_hz=100.0, theta_y_rad=th)
            assert t.film_moment_n_m[0] < 0.0
            assert np.hypot(*t.force_n) < 1e-9 * np.hypot(*t.film_moment_n_m) / b.length_m
            ms.append(np.hypot(*t.film_moment_n_m))
        assert np.log2(ms[0] / ms[1]) == pytest.approx(1.0, abs=0.04)


@pytest.mark.parametrize("kind", ["elliptical", "three_lobe"])
def test_loaded_small_tilt_changes_the_force_at_second_order(kind):
    """Eccentric journal, full film (smooth in θ): F(θ) − F(0) is even in θ, so second order
    (observed 2 ± 0.05), the moment first order (1 ± 0.02)."""
    b = fixed(kind, cavitation="none")
    f0 = tilted_forces(b, **POSE).force_n
    df, dm = [], []
    for th in (4e-4, 2e-4, 1e-4):
        t = tilted_forces(b, **POSE, theta_x_rad=-0.5 * th, theta_y_rad=th)
        df.append(np.hypot(*(t.force_n - f0)))
        dm.append(np.hypot(*t.film_moment_n_m))
    of = np.log2(np.array(df[:-1]) / df[1:])
    om = np.log2(np.array(dm[:-1]) / dm[1:])
    assert np.all(np.abs(of - 2.0) < 0.05), of
    assert np.all(np.abs(om - 1.0) < 0.02), om


@pytest.mark.parametrize("kw", [dict(kind="elliptical"), dict(kind="three_lobe"),
                                dict(kind="pressure_dam", dam_depth_m=2e-4)],
                         ids=lambda k: k["kind"])
def test_4x4_coefficients_match_finite_differences(kw):
    """The perturbation K, C (4×4 over x, y, θx, θy) against central differences of the
    forces and moments of the same discrete film, block by block (force/moment rows ×
    translation/rotation columns), within 2e-5 of each block's largest entry (the
    differences' truncation and the active set's round-off)."""
    b = fixed(**kw)
    K, C = tilted_coefficients(b, **POSE, **TILT)
    Kf, Cf = tilted_coefficients(b, **POSE, **TILT, method="finite_difference")
    for A, B in ((K, Kf), (C, Cf)):
        for r in (slice(0, 2), slice(2, 4)):
            for c in (slice(0, 2), slice(2, 4)):
                np.testing.assert_allclose(A[r, c], B[r, c], rtol=0,
                                           atol=2e-5 * np.abs(B[r, c]).max())
    assert np.abs(K[2:, 2:]).max() > 0 and np.abs(K[:2, 2:]).max() > 0


def test_grid_convergence_of_the_moments():
    """Elliptical bearing, full film (no cavitation: smooth pressure), tilted and eccentric:
    the moments on 24×6 → 48×12 → 96×24 (each lobe's mapped grid doubles too) converge with
    an observed order within ±0.3 of 2 (trapezoid rule, central differences)."""
    Ms = []
    for n in (24, 48, 96):
        b = fixed("elliptical", n_circ=2 * n, n_axial=n // 4, cavitation="none")
        Ms.append(tilted_forces(b, **POSE, **TILT).film_moment_n_m)
    e1, e2 = np.linalg.norm(Ms[1] - Ms[0]), np.linalg.norm(Ms[2] - Ms[1])
    assert np.log2(e1 / e2) == pytest.approx(2.0, abs=0.3)


def test_bad_poses_and_fields_raise_input_error():
    b = fixed("elliptical")
    # edge film closes: at z = −L/2 the journal centre is 1.1 c below the centre (lobe 270°)
    with pytest.raises(InputError, match="theta_x_rad, theta_y_rad.*closes a lobe's film"):
        tilted_forces(b, x_m=0.0, y_m=-5e-5, speed_hz=100.0, theta_x_rad=-2.4e-3)
    with pytest.raises(InputError, match="config_theta_x_rad, config_theta_y_rad"):
        fixed("elliptical", tilt=True, config_theta_x_rad=4.1e-3)
    # a misalignment that closes only the plain bearing's film (4.1e-3 · L/2 = 1.025 c along
    # x) keeps the elliptical's horizontal film open (grooves at 0° and 180° ± 10°): allowed
    ok = fixed("elliptical", tilt=True, config_theta_y_rad=4.05e-3)
    assert ok.edge_film(0.0, 0.0, 0.0, 4.05e-3)[0] > 0
    with pytest.raises(InputError, match="tilt = true"):
        fixed("elliptical", config_theta_y_rad=1e-4)
    with pytest.raises(InputError, match="tilt"):
        fixed("elliptical", tilt=1)
    with pytest.raises(InputError, match="film_model"):
        fixed("partial_arc", arc_deg=360.0, tilt=True, film_model="short")
    with pytest.raises(InputError, match=r"tilting_pad_bearing\.config_theta_x_rad"):
        TiltingPadBearing(station=0, **GEOM, tilt=True, config_theta_x_rad=4.1e-3)


# -- system: the compressor on two elliptical bearings ----------------------------------------
F_HZ = 150.0


def compressor(tilt=True, kind="elliptical", **fields):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain.toml")
    bs = tuple(FixedGeometryBearing(station=b.station, name=b.name, diameter_m=b.diameter_m,
                                    length_m=b.length_m, clearance_m=b.clearance_m,
                                    viscosity_pa_s=b.viscosity_pa_s, kind=kind, n_circ=48,
                                    n_axial=12, tilt=tilt, **fields) for b in s.bearings)
    return dataclasses.replace(s, bearings=bs)


def test_system_equilibrium_guyan_equals_full_and_misalignment_moves_the_edge_film():
    """Guyan with the bearings' rotations kept as masters reaches the unreduced model's
    equilibrium (static condensation is exact at the masters); the weight is carried; a
    housing misalignment puts the minimum film at an edge, thinner than the aligned one."""
    s = compressor(config_theta_y_rad=3e-4)
    assert s.tilt_stations() == [1, 5]
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    assert e.status == "ok", e.message
    full = dataclasses.replace(s, reduction=dataclasses.replace(s.reduction, method="none"))
    ef = rotordyn.equilibrium(full, speed_hz=F_HZ)
    assert ef.status == "ok", ef.message
    np.testing.assert_allclose(e.journal_y_m, ef.journal_y_m, rtol=1e-6)
    np.testing.assert_allclose(e.journal_x_m, ef.journal_x_m, rtol=1e-6)
    L = s.bearings[0].length_m
    for i in (0, 1):
        assert e.tilt[i]["journal_theta_y_rad"] == pytest.approx(
            ef.tilt[i]["journal_theta_y_rad"], rel=1e-6)
        assert e.tilt[i]["config_theta_y_rad"] == 3e-4
        assert abs(e.tilt[i]["h_min_z_m"]) == pytest.approx(L / 2)
    asm = assembled(s)
    fy = sum(e.film_force_n[bc.jy] for bc in asm.bearings)
    assert fy == pytest.approx(s.mass_kg * 9.81, rel=1e-6)
    assert np.abs(np.concatenate([e.film_force_n[list(bc.rot)] for bc in asm.bearings])).max() \
        > 1e-3
    e0 = rotordyn.equilibrium(compressor(tilt=False), speed_hz=F_HZ)
    assert e0.status == "ok" and not e0.tilt
    assert np.all(e.h_min_m < e0.h_min_m)
    assert {"journal_theta_y_rad", "h_min_z_m"} <= set(e.to_frame().columns)


def test_system_zero_tilt_equals_untilted_and_coefficients():
    """tilt = true without misalignment on a rigid-rotation-free equilibrium: the system's
    film K_H on the rotations against central differences; the untilted system's
    equilibrium is close (the rotations are new coordinates, the moments small)."""
    s = compressor(config_theta_x_rad=1e-4)
    e = rotordyn.equilibrium(s, speed_hz=F_HZ)
    asm = assembled(s)
    w = 2 * np.pi * F_HZ
    lin = asm.solver.linearize(e.r, np.zeros(asm.n), w)
    fd = asm.solver.linearize_fd(e.r, w, 1e-6)
    for bc in asm.bearings:
        idx = [bc.jx, bc.jy] + list(bc.rot)
        for A, B in ((lin.KH, fd.KH), (lin.DH, fd.DH)):
            blk, ref = (np.asarray(X)[np.ix_(idx, idx)] for X in (A, B))
            np.testing.assert_allclose(blk, ref, rtol=0, atol=2e-5 * np.abs(ref).max())


def test_system_stability_transient_and_toml_round_trip():
    s = compressor(kind="three_lobe", config_theta_y_rad=2e-4)
    st = rotordyn.stability(s, speed_hz=F_HZ)
    assert st.status == "ok" and np.all(np.isfinite(st.eigenvalues))
    st0 = rotordyn.stability(compressor(tilt=False, kind="three_lobe"), speed_hz=F_HZ)
    assert len(st.eigenvalues) == len(st0.eigenvalues) + 4  # two stations' θx, θy
    tr = rotordyn.transient(s, t_end_s=0.002, speed_hz=F_HZ, disturbance_m=(0.5e-6, 0.0),
                            n_out=5, rtol=1e-8, atol_m=1e-13)
    assert tr.status == "ok", tr.message
    assert np.all(np.isfinite(tr.r))
    text = s.to_toml()
    assert "tilt = true" in text and "config_theta_y_rad = 0.0002" in text
    assert rotordyn.System.from_toml(text, is_text=True) == s


def test_misalignment_as_a_sweep_axis_of_a_lobed_bearing(tmp_path):
    """The sweep's equilibrium rows of a lobed tilting bearing (rotations, the edge film's z
    taken from the thinnest lobe) equal direct calls."""
    import rotordyn.sweep as sw
    from rotordyn.sweep import run_sweep

    s = compressor()
    s.to_toml(tmp_path / "m.toml")
    p = tmp_path / "s.toml"
    p.write_text('schema = "rotordyn/sweep/1"\nname = "tilt"\nmodel = "m.toml"\n'
                 'analysis = "equilibrium"\nchunk_size = 4\n[grid]\n'
                 '"bearings.0.config_theta_y_rad" = [0.0, -3e-4]\nspeed_hz = 150.0\n')
    res = run_sweep(p, tmp_path / "o", threads=1)
    assert res.complete and res.counts["failed"] == 0
    fr = sw.open(tmp_path / "o").frame
    for val, g in fr.groupby("bearings.0.config_theta_y_rad"):
        b0 = dataclasses.replace(s.bearings[0], config_theta_y_rad=float(val))
        e = rotordyn.equilibrium(dataclasses.replace(s, bearings=(b0, s.bearings[1])),
                                 speed_hz=150.0)
        for i in (0, 1):
            row = g[g["bearing"] == e.bearing_names[i]].iloc[0]
            assert row["journal_y_m"] == pytest.approx(e.journal_y_m[i], rel=1e-8)
            assert row["h_min_m"] == pytest.approx(e.h_min_m[i], rel=1e-8)
            for k in ("journal_theta_x_rad", "journal_theta_y_rad", "h_min_z_m"):
                assert row[k] == pytest.approx(e.tilt[i][k], rel=1e-7, abs=1e-15), k
