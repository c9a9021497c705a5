"""A model file's plain bearing (``FluidFilmBearing``, ``System.bearings[i]`` of a
``type = "journal"`` bearing) has JournalBearing's standalone thermal equilibrium (issue 20;
docs/film-physics.md, "Plain and tilting-pad bearings, standalone"). Before, it had no
``thermal_equilibrium`` (AttributeError), while ``JournalBearing`` had one.

Bearing: the compressor's NDE bearing of tests/data/models/compressor_plain_thermal.toml (D =
0.1 m, L = 0.05 m, c = 0.1 mm; 36 × 6 here) with its oil system (VG 32 at 45 °C), 4 kN at
100 Hz — not the paper rig. Two paths: the bearing read from the model file against a
JournalBearing built here from the same numbers; the same film and the same C++ call, so the
results agree to 1e-12 relative (observed: bit for bit).
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn
from rotordyn.errors import InputError

MODELS = Path(__file__).parent / "data" / "models"
GRID = dict(n_circ=36, n_axial=6)
TILT = dict(theta_x_rad=0.5e-4, theta_y_rad=2e-4)


def _model_bearing(**kw):
    s = rotordyn.System.from_toml(MODELS / "compressor_plain_thermal.toml")
    return dataclasses.replace(s.bearings[0], **GRID, **kw), s.thermal


def _by_hand():
    return rotordyn.JournalBearing(diameter_m=0.1, length_m=0.05, clearance_m=1e-4,
                                   viscosity_pa_s=0.018, **GRID)


def _kw(th, model):
    kw = dict(load_n=(0.0, -4000.0), speed_hz=100.0, oil=th.oil, model=model,
              supply_temperature_c=th.supply_temperature_c, carry_over=th.carry_over)
    if model == "effective":
        kw["effective_factor"] = th.effective_factor
    return kw


def _same(a, b, tilted):
    names = ["x_m", "y_m", "max_temperature_c", "inlet_temperature_c", "power_loss_w",
             "side_flow_m3_s", "film_flow_m3_s"]
    for n in names:
        assert getattr(a, n) == pytest.approx(getattr(b, n), rel=1e-12, abs=1e-18), n
    for n in ("K", "C") + (("K4", "C4", "film_moment_n_m") if tilted else ()):
        ref = np.asarray(getattr(b, n))
        np.testing.assert_allclose(getattr(a, n), ref, rtol=1e-12,
                                   atol=1e-12 * np.abs(ref).max(), err_msg=n)
    if tilted:
        assert (a.h_min_m, a.h_min_z_m) == pytest.approx((b.h_min_m, b.h_min_z_m), rel=1e-12)
    if hasattr(b, "temperature_c"):
        np.testing.assert_allclose(a.temperature_c, b.temperature_c, rtol=0, atol=1e-10)


@pytest.mark.parametrize("model", ["effective", "thd"])
def test_model_bearing_equals_the_journal_bearing(model):
    b, th = _model_bearing()
    kw = _kw(th, model)
    _same(b.thermal_equilibrium(**kw), _by_hand().thermal_equilibrium(**kw), tilted=False)
    # the journal tilted relative to the bearing: moments, edge film, K4, C4 as well
    t = b.thermal_equilibrium(**kw, **TILT)
    _same(t, _by_hand().thermal_equilibrium(**kw, **TILT), tilted=True)
    assert t.status == "ok" and np.abs(t.film_moment_n_m).min() > 0
    assert t.h_min_z_m == pytest.approx(0.025)  # the thin edge


def test_model_bearing_own_fields():
    """``tilt = true`` on the model bearing gives the tilted outputs at zero tilt (``tilt``
    None: the bearing's own field); the housing's misalignment ``config_theta_*`` (a system's)
    and a frozen viscosity field (a THD system's) are not applied standalone: the oil's law
    and the given journal tilt are."""
    _, th = _model_bearing()
    kw = _kw(th, "effective")
    ref = _by_hand().thermal_equilibrium(**kw, tilt=True)
    own, _ = _model_bearing(tilt=True, config_theta_y_rad=2e-4,
                            viscosity_field_pa_s=np.full((36, 7), 0.05))
    r = own.thermal_equilibrium(**kw)
    assert r.K4.shape == (4, 4) and r.h_min_z_m == 0.0
    _same(r, ref, tilted=True)
    # an explicit tilt=False on a tilt = true bearing: the untilted film
    plain = own.thermal_equilibrium(**kw, tilt=False)
    assert not hasattr(plain, "K4") or plain.K4 is None
    _same(plain, _by_hand().thermal_equilibrium(**kw), tilted=False)
    with pytest.raises(InputError, match="tilt"):
        own.thermal_equilibrium(**kw, tilt="yes")
    with pytest.raises(InputError, match="theta_y_rad"):
        own.thermal_equilibrium(**kw, theta_y_rad=float("inf"))
