"""Every new bearing element in a system (issue 12): equilibrium, stability, Campbell,
unbalance response, the nonlinear transient agreeing with the linear model at small amplitude,
and the TOML round trip.

The transient check is independent of the linearisation code path: the linear response is
x(t) = expm(A t) x0 of the state matrix built from the linearised model, compared with the
CVODE integration of the nonlinear film forces for a 0.5 µm initial journal displacement
(0.5-1 % of the clearance, so the nonlinear terms are ~1 % of the response; tolerance 3 % of
the peak amplitude).
"""

import dataclasses
import math

import numpy as np
import pytest
import scipy.linalg

import rotordyn
from rotordyn.bearings import (FixedGeometryBearing, SqueezeFilmDamper, TableBearing,
                               TiltingPadBearing)

ROTOR_TOML = """
schema = "rotordyn/model/1"
name = "small-rotor"
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.1e11
poisson = 0.3
[rotor]
[[rotor.section]]
length_m = 0.2
outer_diameter_m = 0.03
[[rotor.section]]
length_m = 0.2
outer_diameter_m = 0.03
[[disk]]
station = 1
mass_kg = 5.0
ip_kg_m2 = 0.01
id_kg_m2 = 0.005
[reduction]
master_stations = [0, 1, 2]
method = "guyan"
"""

FILM = dict(diameter_m=0.03, length_m=0.015, clearance_m=5e-5, viscosity_pa_s=0.02,
            n_circ=36, n_axial=6)


def _bearings(kind):
    if kind == "fixed_geometry":
        return [FixedGeometryBearing(station=s, kind="elliptical", **FILM) for s in (0, 2)]
    if kind == "tilting_pad":
        return [TiltingPadBearing(station=s, preload=0.3, pad_inertia_kg_m2=2e-5, **FILM)
                for s in (0, 2)]
    if kind == "squeeze_film_damper":
        return [SqueezeFilmDamper(station=s, cavitation="none", centring_spring_n_per_m=2e6,
                                  **FILM) for s in (0, 2)]
    if kind == "sealed_squeeze_film_damper":  # π film, end seals of G_s = c³/(12μL)
        g = FILM["clearance_m"] ** 3 / (12 * FILM["viscosity_pa_s"] * FILM["length_m"])
        return [SqueezeFilmDamper(station=s, cavitation="gumbel", centring_spring_n_per_m=2e6,
                                  end_seal_conductance_m3_per_pa_s_per_m=g, **FILM)
                for s in (0, 2)]
    if kind == "short_squeeze_film_damper":  # the short-damper (Ocvirk) model, full film
        return [SqueezeFilmDamper(station=s, cavitation="none", centring_spring_n_per_m=2e6,
                                  film_model="short", **FILM) for s in (0, 2)]
    if kind == "table":
        return [TableBearing(station=s, speeds_hz=(10.0, 60.0, 110.0),
                             kxx_n_per_m=(2e6, 3e6, 4e6), kyy_n_per_m=(3e6, 4e6, 5e6),
                             kxy_n_per_m=(1e5, 2e5, 3e5), kyx_n_per_m=(-1e5, -2e5, -3e5),
                             cxx_n_s_per_m=(2e3, 1.5e3, 1e3), cyy_n_s_per_m=(2e3, 1.5e3, 1e3))
                for s in (0, 2)]
    raise ValueError(kind)


KINDS = ["fixed_geometry", "tilting_pad", "squeeze_film_damper", "sealed_squeeze_film_damper",
         "short_squeeze_film_damper", "table"]


def _system(kind):
    base = rotordyn.System.from_toml(ROTOR_TOML, is_text=True)
    return dataclasses.replace(base, bearings=tuple(_bearings(kind)))


@pytest.mark.parametrize("kind", KINDS)
def test_toml_round_trip(kind):
    s = _system(kind)
    text = s.to_toml()
    assert f'type = "{kind.removeprefix("sealed_").removeprefix("short_")}"' in text
    assert rotordyn.System.from_toml(text, is_text=True) == s


@pytest.mark.parametrize("kind", KINDS)
def test_equilibrium_stability_campbell_unbalance(kind):
    s = _system(kind)
    e = rotordyn.equilibrium(s, speed_hz=50.0)
    assert e.status == "ok", e.message
    # the bearings carry the weight: the total vertical bearing force equals the weight
    W = s.mass_kg * 9.81
    assert np.sum(e.film_force_n[[1, 5]]) == pytest.approx(W, rel=1e-6)
    st = rotordyn.stability(s, speed_hz=50.0)
    assert st.status == "ok"
    assert np.all(np.isfinite(st.eigenvalues))
    cb = rotordyn.campbell(s, [20.0, 50.0, 80.0])
    assert np.all(np.asarray(cb.point_status) == "ok")
    ub = rotordyn.unbalance_response(s, [(1, 1e-5, 0.0)], [30.0, 60.0], stations=[1])
    assert np.all(np.asarray(ub.point_status) == "ok")
    amp = np.abs(np.asarray(ub.x))
    assert np.all(np.isfinite(amp)) and np.all(amp > 0)


@pytest.mark.parametrize("kind", KINDS)
def test_transient_matches_linear_model_small_amplitude(kind):
    s = _system(kind)
    f = 50.0
    lm = rotordyn.linearize(s, speed_hz=f)
    e = lm.equilibrium
    n = lm.M.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(lm.M, lm.K), -np.linalg.solve(lm.M, lm.D)]])
    d = 0.5e-6
    tr = rotordyn.transient(s, t_end_s=0.01, speed_hz=f, disturbance_m=(d, 0.0), n_out=11)
    assert tr.status == "ok", tr.message
    x0 = np.concatenate([tr.r[0] - e.r, np.zeros(n)])
    lin = np.array([(scipy.linalg.expm(A * t) @ x0)[:n] for t in tr.t])
    dev = tr.r - e.r
    jx = 0  # station 0's x
    scale = np.max(np.abs(lin[:, jx]))
    assert np.max(np.abs(dev[:, jx] - lin[:, jx])) < 0.03 * scale, (dev[:, jx], lin[:, jx])


@pytest.mark.parametrize("kind, path, value", [
    ("fixed_geometry", "bearings.*.preload", 0.3),
    ("tilting_pad", "bearings.0.pivot_offset", 0.6),
    ("squeeze_film_damper", "bearings.*.centring_spring_n_per_m", 4e6),
])
def test_fields_are_sweep_axes(kind, path, value):
    """Element fields are sweep axes (model paths of rotordyn.sweep.paths): the changed model
    validates again and its operating point moves."""
    from rotordyn.sweep.paths import get_field, set_field

    s = _system(kind)
    s2 = set_field(s, path, value)
    assert np.all(np.asarray(get_field(s2, path), dtype=float) == value)
    e1, e2 = rotordyn.equilibrium(s, speed_hz=50.0), rotordyn.equilibrium(s2, speed_hz=50.0)
    assert e1.status == e2.status == "ok"
    assert not np.allclose(e1.r[:6], e2.r[:6], rtol=1e-6, atol=0)
    with pytest.raises(rotordyn.errors.InputError):
        set_field(s, path, 1.5 if "spring" not in path else -1.0)
