"""A transient whose journal reaches the bush stops with status "rub" (issue 8 session 4,
found by `make fuzz`): before, such a run was called "contact" — the status of a *converged*
equilibrium with a thin film (rotordyn.results.equilibrium.CONVERGED) — so a waterfall sweep
took its NaN rows for a converged point, and the film force (∝ 1/h³) held CVODE for 500 000
ever smaller steps (49 s) before it gave up. Now the run stops after the step that takes a
film below ``rub_fraction`` (default 1e-3) of its clearance, keeps the rows reached (NaN
after), and says where; a start that closes a film is an InputError naming the field."""

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.assembly import assembled
from rotordyn.control import SpeedProfile
from rotordyn.results.equilibrium import CONVERGED


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def test_a_run_that_reaches_the_bush_says_rub(rig):
    # a 2e-3 kg m unbalance at disk B at the first critical speed: the orbit grows to the bush
    tr = rd.transient(rig, 0.2, 38.6, 0.5e6, 0.0, unbalances=[(6, 2e-3, 0.0)], n_out=201)
    assert tr.status == "rub" and tr.status not in CONVERGED
    assert "reached the bush" in tr.message and "active bearing" in tr.message
    done = np.all(np.isfinite(tr.r), axis=1)
    assert 0 < done.sum() < len(done) and np.all(done[: done.sum()])  # rows reached, then NaN
    h = tr.h_min_m[done]
    assert np.all(h > 0) and h.min() < 0.05 * tr.clearance_m[0]  # it was closing in
    # without the rub check the run creeps on toward h = 0 (not run here: 49 s); a looser
    # threshold stops it earlier
    early = rd.transient(rig, 0.2, 38.6, 0.5e6, 0.0, unbalances=[(6, 2e-3, 0.0)], n_out=201,
                         rub_fraction=0.05)
    assert early.status == "rub"
    assert np.all(np.isfinite(early.r), axis=1).sum() <= done.sum()


def test_a_start_inside_the_bush_is_an_input_error(rig):
    # the fuzz case (1 Hz, p_c = 362652 Pa) with the disturbance taken from its equilibrium: one
    # and a half times the thinnest film, toward it (the fuzzed 6.32e-5 m sat on the knife edge
    # and moved with the gravity load's last digits)
    e = rd.equilibrium(rig, 1.0, 362652.0)
    phi = np.radians(e.h_min_angle_deg[0])
    d = 1.5 * e.h_min_m[0] * np.array([np.cos(phi), np.sin(phi)])
    with pytest.raises(rd.InputError, match="disturbance_m: the start closes film"):
        rd.transient(rig, 0.01, 1.0, 362652.0, None, n_out=2, disturbance_m=tuple(d))
    asm = assembled(rig)
    r0 = np.zeros(asm.n)
    r0[asm.bearings[0].jy] = -2 * asm.bearings[0].clearance_m
    with pytest.raises(rd.InputError, match="r0: the start closes film"):
        rd.transient(rig, 0.01, 50.0, 0.1e6, r0=r0, n_out=2)


@pytest.mark.parametrize("bad", [-0.1, 1.0, float("nan")])
def test_rub_fraction_is_checked(rig, bad):
    with pytest.raises(rd.InputError, match="rub_fraction"):
        rd.transient(rig, 0.01, 50.0, 0.1e6, n_out=2, rub_fraction=bad)


def test_film_h_min_includes_the_bearing_geometry():
    """h_min (the transient's output and the rub check) is min(base_h + S r) as the film
    solve builds it: for a lobed bearing base_h is not the clearance (it was taken as the
    clearance before)."""
    from rotordyn.bearings import FixedGeometryBearing
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.1, outer_diameter_m=0.1) for _ in range(4))
    brg = tuple(FixedGeometryBearing(station=s, kind="elliptical", diameter_m=0.05,
                                     length_m=0.025, clearance_m=1e-4, viscosity_pa_s=0.02,
                                     n_circ=36, n_axial=8) for s in (0, 4))
    system = rd.System(rotor=rd.Rotor(shaft, ()), materials=(steel,), bearings=brg,
                       reduction=rd.Reduction(master_stations=(0, 4), method="guyan"))
    asm = assembled(system)
    r = np.random.default_rng(2).uniform(-2e-5, 2e-5, asm.n)
    got = asm.solver.film_h_min(r)
    for f, g in zip(asm.model.films, got):
        base = np.asarray(f.base_h)
        assert base.size and not np.allclose(base, f.geometry.clearance_m)  # lobed
        h = (base.min(axis=1) if base.shape[1] > 1 else base[:, 0]) + np.asarray(f.shape) @ r[
            np.asarray(f.coords)]
        assert g == pytest.approx(h.min(), rel=1e-14)


WATERFALL = """
schema = "rotordyn/sweep/1"
name = "t-rub"
model = "paper-rig"
analysis = "waterfall"
chunk_size = 1

[grid]
speed_hz = [20.0, 38.6]
chamber_pressure_pa = 0.5e6
config_ay_m = 0.0

[options]
unbalances = [[6, 2.0e-3, 0.0]]
revolutions = 8
{extra}
"""


def test_a_waterfall_point_that_rubs_is_a_rub_row(tmp_path):
    """At the first critical speed the 2e-3 kg m unbalance drives the journal to the bush: that
    point is one 'rub' row with its message (before: spectrum rows of NaN called 'contact',
    counted as converged); the point below the critical speed is unaffected."""
    from rotordyn.sweep import run_sweep
    spec = tmp_path / "w.toml"
    spec.write_text(WATERFALL.format(extra=""))
    res = run_sweep(spec, tmp_path / "o", threads=1)
    df = res.to_frame()
    rub = df[df["speed_hz"] == 38.6]
    assert len(rub) == 1 and rub["status"].iloc[0] == "rub"
    assert "reached the bush" in rub["message"].iloc[0]
    ok = df[df["speed_hz"] == 20.0]
    assert len(ok) > 1 and (ok["status"] == "ok").all()
    assert np.all(np.isfinite(ok["amplitude_x_m"]))


def test_rub_fraction_option_is_checked(tmp_path):
    from rotordyn.sweep.spec import SweepSpec
    spec = tmp_path / "w.toml"
    spec.write_text(WATERFALL.format(extra="rub_fraction = 1.5"))
    with pytest.raises(rd.InputError, match=r"options\.rub_fraction"):
        SweepSpec.from_toml(spec)


def test_a_run_up_that_rubs_keeps_the_revolutions_reached(tmp_path):
    """A run-up through the first critical speed with a 2e-3 kg m unbalance rubs near 38.7 Hz:
    the whole revolutions before are rows with status 'rub' and finite values (the NaN angles
    of the stopped rows used to become garbage revolution numbers; the last, partial
    revolution is left out)."""
    from rotordyn.sweep import run_sweep
    spec = tmp_path / "r.toml"
    spec.write_text(WATERFALL.replace('analysis = "waterfall"', 'analysis = "run-up"')
                    .replace("speed_hz = [20.0, 38.6]\n", "")
                    .replace("revolutions = 8\n{extra}",
                             "start_hz = 30.0\nstop_hz = 45.0\nrate_hz_per_s = 15.0"))
    df = run_sweep(spec, tmp_path / "o", threads=1).to_frame()
    assert (df["status"] == "rub").all() and len(df) > 10
    assert df["revolution"].min() == 0 and df["revolution"].is_monotonic_increasing
    assert df["revolution"].max() == len(df) - 1
    assert 35.0 < df["speed_hz"].max() < 45.0
    # the same run on its own: the rows stop one revolution short of where it rubbed
    tr = rd.transient(rd.models.paper_rig(), 1.0, chamber_pressure_pa=0.5e6, config_ay_m=0.0,
                      speed=SpeedProfile.ramp(30.0, 45.0, 15.0),
                      unbalances=[(6, 2e-3, 0.0)], n_out=int(37.5 * 32) + 1)
    done = np.isfinite(tr.angle_rad)
    last = int(np.floor(tr.angle_rad[done][-1] / (2 * np.pi)))
    assert tr.status == "rub" and df["revolution"].max() == last - 1
    assert np.all(np.isfinite(df[["amplitude_x_m", "amplitude_y_m", "h_min_m"]].to_numpy()))


def test_a_discrete_controller_run_that_rubs_says_rub(rig):
    """The rub check runs after every CVODE step in a run with a discrete controller too (it
    steps one at a time between its sample instants)."""
    from rotordyn.control import Controller
    k = Controller.static([[0.0, 0.0]], [("journal", 0)], sample_time_s=1e-3)
    tr = rd.transient(rig, 0.2, 38.6, 0.5e6, 0.0, unbalances=[(6, 2e-3, 0.0)], n_out=201,
                      controller=k)
    assert tr.status == "rub" and "reached the bush" in tr.message
    assert 0 < np.all(np.isfinite(tr.r), axis=1).sum() < 201
