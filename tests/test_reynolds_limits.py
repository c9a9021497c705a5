"""Issue 13 regressions for the plain journal bearing: non-finite or meaningless results that
came back as valid, inputs that crashed with plain ValueError/TypeError, groove angles, light
loads and film grids that exhausted time or memory. Each test makes the failing call as the
issue wrote it. No numerical tolerance, except where stated (light-load equilibria: the load
balance to the requested rtol, and the linear scaling of the eccentricity with the load to
1e-4, the homogeneity error of the film at eccentricity ratios ~1e-5)."""

import math

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.errors import ConvergenceError, InputError
from cli_output import error_lines

GOOD = dict(diameter_m=0.05, length_m=0.04, clearance_m=3e-4, viscosity_pa_s=0.04)


def small(**kw):
    return rd.JournalBearing(**GOOD, n_circ=36, n_axial=8, **kw)


# -- non-finite results with status ok -------------------------------------------------------
def test_huge_velocity_is_rejected_naming_the_range():
    with pytest.raises(InputError, match=r"vy_m_s: expected \|vy_m_s\| <= 1000"):
        small().forces(x_m=0.0, y_m=-1e-4, speed_hz=50.0, vy_m_s=1e308)


def test_huge_speed_is_rejected_single_and_batch():
    b = small()
    with pytest.raises(InputError, match=r"speed_hz: expected \|speed_hz\| <= 100000"):
        b.coefficients(x_m=0.0, y_m=-1e-4, speed_hz=1e300)
    out = b.coefficients_batch(x_m=[0.0, 0.0], y_m=[-1e-4, -1e-4], speed_hz=[50.0, 1e300],
                               on_error="nan")
    assert list(out["status"]) == [0, 1]
    assert "speed_hz" in out["message"][1]
    assert np.all(np.isfinite(out["K"][0])) and np.all(np.isnan(out["K"][1]))


def test_huge_groove_pressure_is_rejected():
    with pytest.raises(InputError, match="Groove.pressure_pa"):
        rd.Groove(90.0, 0.0, 1e308)
    g = rd._core.JournalBearingGeometry()
    g.grooves = [rd._core.Groove(90.0, 0.0, 1e308)]
    with pytest.raises(InputError, match=r"grooves\[0\].pressure_pa"):
        g.validate()


def test_finite_difference_step_below_round_off_is_rejected():
    with pytest.raises(InputError, match="rel_step"):
        small().coefficients(x_m=0.0, y_m=-1e-4, speed_hz=50.0, method="finite_difference",
                             rel_step=1e-300)
    with pytest.raises(InputError, match="rel_step"):
        rd.linearize(rd.models.paper_rig(), 50.0, 0.15e6, -1.85e-3,
                     method="finite_difference", rel_step=1e-300)


def test_rtol_outside_its_range_is_rejected():
    with pytest.raises(InputError, match="rtol"):
        small().static_equilibrium(load_n=(0.0, -100.0), speed_hz=50.0, rtol=1e300)


def test_tiny_load_has_a_truthful_nearly_concentric_equilibrium():
    """static_equilibrium(load_n=(0, -1e-200)) returned ok with residual 0 (underflow in the
    norm); loads 1e-100..1e-6 N raised ConvergenceError with a wrong message. Now the position
    scales linearly with the load (the film is positively homogeneous at the centre) and the
    load balance is reported relative to the load."""
    b = rd.JournalBearing(**GOOD)
    ref = b.static_equilibrium(load_n=(0.0, -1e-3), speed_hz=50.0)  # solved directly
    assert ref.status == "ok" and ref.residual_rel <= 1e-10
    assert 0.0 < ref.eccentricity_ratio < 1e-4
    for load in (1e-6, 1e-12, 1e-100, 1e-200):
        e = b.static_equilibrium(load_n=(0.0, -load), speed_hz=50.0)
        assert e.status == "ok" and e.residual_rel <= 1e-10
        assert e.eccentricity_ratio == pytest.approx(ref.eccentricity_ratio * load / 1e-3,
                                                     rel=1e-4)
        assert e.attitude_angle_deg == pytest.approx(ref.attitude_angle_deg, abs=1e-2)
        np.testing.assert_allclose(e.force_n, [0.0, load], rtol=1e-9, atol=1e-9 * load)
    zero = b.static_equilibrium(load_n=(0.0, 0.0), speed_hz=50.0)
    assert (zero.x_m, zero.y_m, zero.eccentricity_ratio) == (0.0, 0.0, 0.0)
    # light but resolvable loads converge directly (were ConvergenceError at 1e-6 N)
    for load in (1e-4, 1e-2, 1.0):
        e = b.static_equilibrium(load_n=(0.0, -load), speed_hz=50.0)
        np.testing.assert_allclose(e.force_n, [0.0, load], rtol=1e-9, atol=1e-9 * load)


# -- plain ValueError/TypeError -> InputError naming the field --------------------------------
@pytest.mark.parametrize("value", ["90", None, [90.0], True])
def test_groove_angle_must_be_a_number(value):
    with pytest.raises(InputError, match="Groove.center_deg"):
        rd.Groove(value)


def test_groove_stores_floats_and_grooves_none_is_rejected():
    assert rd.Groove(90) == rd.Groove(90.0)
    assert isinstance(rd.Groove(90).center_deg, float)
    with pytest.raises(InputError, match="grooves"):
        rd.JournalBearing(**GOOD, grooves=None)
    with pytest.raises(InputError, match="grooves"):
        rd.JournalBearing(**GOOD, grooves="90")


def test_groove_angle_wraps_in_degrees():
    """Groove(center_deg=90 + 360e6) was 15 % off Groove(90) (wrapped after conversion to
    radians); center_deg=1e300 overflowed lround."""
    def force(center):
        b = rd.JournalBearing(**GOOD, n_circ=36, n_axial=8, cavitation="jfo",
                              grooves=[rd.Groove(center)])
        return b.forces(x_m=1e-4, y_m=-1.5e-4, speed_hz=50.0)

    assert np.array_equal(force(90.0 + 360e6), force(90.0))
    assert np.all(np.isfinite(force(1e300)))


@pytest.mark.parametrize("kw, field", [
    (dict(x_m="0.0"), "x_m"), (dict(x_m=None), "x_m"), (dict(speed_hz="50"), "speed_hz"),
    (dict(vx_m_s=[1.0]), "vx_m_s"),
])
def test_text_none_and_lists_in_operating_points(kw, field):
    args = dict(x_m=0.0, y_m=-1e-4, speed_hz=50.0)
    args.update(kw)
    with pytest.raises(InputError, match=field):
        small().forces(**args)


@pytest.mark.parametrize("load", [(1.0,), (1.0, 2.0, 3.0), "ab", None, ("1", 2.0)])
def test_load_of_the_wrong_length_or_type(load):
    with pytest.raises(InputError, match="load_n"):
        small().static_equilibrium(load_n=load, speed_hz=50.0)


@pytest.mark.parametrize("kw, field", [
    (dict(n_circ=2**31), "n_circ"), (dict(n_axial=2**40), "n_axial"),
    (dict(n_circ="72"), "n_circ"), (dict(cavitation=None), "cavitation"),
])
def test_constructor_integers_and_types(kw, field):
    with pytest.raises(InputError, match=field):
        rd.JournalBearing(**GOOD, **kw)


def test_batch_inputs_text_and_huge_thread_counts():
    b = small()
    with pytest.raises(InputError, match="x_m"):
        b.forces_batch(x_m=["a"], y_m=0.0, speed_hz=50.0)
    with pytest.raises(InputError, match="n_threads"):
        b.forces_batch(x_m=[0.0], y_m=0.0, speed_hz=50.0, n_threads=2**31)
    with pytest.raises(InputError, match="shapes"):
        b.coefficients_batch(x_m=[0.0, 1e-5], y_m=[0.0, 1e-5, 2e-5], speed_hz=50.0)


# -- resources -------------------------------------------------------------------------------
def test_film_grid_beyond_memory_is_refused_before_allocation():
    """4096 × 1024 ended in std::bad_alloc: now an InputError naming the fields and the
    estimate, before any allocation."""
    with pytest.raises(InputError, match=r"n_circ, n_axial: .* GB"):
        rd.JournalBearing(**GOOD, n_circ=4096, n_axial=1024)
    g, _ = small().to_core()
    with pytest.raises(InputError, match=r"n_circ, n_axial"):
        rd._core.ReynoldsSolver(g, rd._core.FilmGrid(4096, 1024), "reynolds")


def test_factorisation_estimate_refuses_fill_heavy_grids():
    """Below the node cap, a grid whose sparse factorisation would exceed the work cap
    (~1e11 multiply-adds per factorisation, minutes per solve) is refused with the estimate
    before any allocation of its size."""
    with pytest.raises(InputError, match=r"n_circ, n_axial: the 1500 x 1500 film grid needs "
                                         r"about .* multiply-adds"):
        rd.JournalBearing(**GOOD, n_circ=1500, n_axial=1500).forces(x_m=0.0, y_m=-1e-4,
                                                                    speed_hz=50.0)


def test_long_thin_grid_solves_in_a_few_iterations():
    """A 10^5 × 4 grid took 143 s (one cavitation node per active-set step); it now solves in
    a few steps. Asserted on the iteration count, not on time."""
    b = rd.JournalBearing(**GOOD, n_circ=20000, n_axial=4)
    r = b.solve(x_m=1e-4, y_m=-1.5e-4, speed_hz=50.0)
    assert r.iterations <= 4
    ref = rd.JournalBearing(**GOOD, n_circ=72, n_axial=4).forces(x_m=1e-4, y_m=-1.5e-4,
                                                                  speed_hz=50.0)
    np.testing.assert_allclose(r.force_n, ref, rtol=0.05)


def test_cli_huge_grid_exits_2_naming_the_field():
    import subprocess
    import sys

    p = subprocess.run([sys.executable, "-m", "rotordyn.cli", "bearing", "--diameter-m", "0.05",
                        "--length-m", "0.04", "--clearance-m", "3e-4", "--viscosity-pa-s",
                        "0.04", "--speed-hz", "50", "--x-m", "0", "--y-m", "-1e-4",
                        "--n-circ", "3000000000"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "n_circ" in p.stderr and "Traceback" not in p.stderr
    assert len(error_lines(p.stderr)) == 1


def test_non_finite_films_are_never_returned_as_ok():
    """A film whose pressure scale overflows double precision raises instead of returning
    NaN or inf (the check every result passes before it leaves the core)."""
    b = rd.JournalBearing(diameter_m=1e150, length_m=1e150, clearance_m=1e-150,
                          viscosity_pa_s=1e150, n_circ=24, n_axial=4)
    try:
        f = b.forces(x_m=0.0, y_m=-0.5e-150, speed_hz=50.0)
    except (ConvergenceError, InputError):
        return
    assert np.all(np.isfinite(f))
