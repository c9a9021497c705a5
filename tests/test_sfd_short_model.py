"""The short-bearing (Ocvirk) film model of the Reynolds core (``short_bearing``) and the
squeeze-film damper's ``film_model = "short"``.

Sources
-------
* Short damper, circular centred orbit (Vance 1988 ch. 6; San Andrés, SFD notes; derived in
  ``rotordyn.bearings.squeeze_film``): full film F_r = 0, F_t = −πμRL³νε/(c²(1−ε²)^{3/2}).
  The model integrates p ∝ (z² − L²/4) with the trapezoidal rule, exactly
  −(L³/6)(1 − 1/n_axial²) (Euler–Maclaurin), and the periodic φ-integral spectrally: the full
  film's F_t equals the closed form × (1 − 1/n_axial²) to 1e-10, whatever L/D; the π film
  (clipped at the film's zero crossings) within 1 %.
* The finite-length film tends to the short model as L/D → 0 (1 % at L/D = 1/40).
* Short journal bearing (Ocvirk; Friswell, Penny, Garvey & Lees 2010 §5.5): load
  W = μωRL³/(4c²)·ε(16ε² + π²(1−ε²))^{1/2}/(1−ε²)², attitude tan ψ = π(1−ε²)^{1/2}/(4ε); and
  Lund's stability quantities (whirl ratio γ, critical mass M̄: frame-independent) from the
  model's own K, C equal those of the closed-form coefficients a, b (helpers of
  tests/test_linear_references.py) within 0.5 % (n_circ 144, n_axial 16: z-rule 0.4 %).
* Its perturbation K, C equal central finite differences (1e-5).
"""

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from rotordyn import _core
from rotordyn.bearings import SqueezeFilmDamper, short_damper_orbit_forces
from rotordyn.errors import InputError

sys.path.insert(0, str(Path(__file__).parent))
from test_linear_references import lund, ocvirk_load_factor, short_bearing_ab  # noqa: E402

D, C_RAD, MU, NU = 0.1, 2e-4, 0.01, 30.0


def _damper(L, cav, model, n_circ=144, n_axial=16):
    return SqueezeFilmDamper(station=0, diameter_m=D, length_m=L, clearance_m=C_RAD,
                             viscosity_pa_s=MU, cavitation=cav, n_circ=n_circ,
                             n_axial=n_axial, film_model=model)


@pytest.mark.parametrize("L", [0.025, 0.1])
@pytest.mark.parametrize("eps", [0.3, 0.7])
def test_short_damper_model_is_the_closed_form(L, eps):
    kw = dict(diameter_m=D, length_m=L, clearance_m=C_RAD, viscosity_pa_s=MU,
              eccentricity_ratio=eps, whirl_hz=NU)
    o = _damper(L, "none", "short").orbit_coefficients(eccentricity_ratio=eps, whirl_hz=NU)
    _, ft = short_damper_orbit_forces(film="full", **kw)
    assert o["f_t_n"] == pytest.approx(ft * (1 - 1 / 16 ** 2), rel=1e-10)
    assert abs(o["f_r_n"]) < 1e-10 * abs(ft)
    for cav in ("gumbel", "reynolds"):
        o = _damper(L, cav, "short").orbit_coefficients(eccentricity_ratio=eps, whirl_hz=NU)
        fr, ft = short_damper_orbit_forces(film="pi", **kw)
        assert o["f_t_n"] == pytest.approx(ft, rel=0.01)
        assert o["f_r_n"] == pytest.approx(fr, rel=0.01)


def test_finite_damper_tends_to_the_short_model():
    L = D / 40
    f = _damper(L, "gumbel", "finite", n_circ=72, n_axial=16).orbit_coefficients(
        eccentricity_ratio=0.5, whirl_hz=NU)
    s = _damper(L, "gumbel", "short", n_circ=72, n_axial=16).orbit_coefficients(
        eccentricity_ratio=0.5, whirl_hz=NU)
    assert f["c_eq_n_s_per_m"] == pytest.approx(s["c_eq_n_s_per_m"], rel=0.01)
    assert f["k_eq_n_per_m"] == pytest.approx(s["k_eq_n_per_m"], rel=0.01)
    L4 = _damper(D / 4, "gumbel", "finite", 72, 16).orbit_coefficients(eccentricity_ratio=0.5,
                                                                      whirl_hz=NU)
    s4 = _damper(D / 4, "gumbel", "short", 72, 16).orbit_coefficients(eccentricity_ratio=0.5,
                                                                     whirl_hz=NU)
    # the short model over-predicts the finite film (observed 5 % at L/D = 1/4)
    assert L4["c_eq_n_s_per_m"] < 0.97 * s4["c_eq_n_s_per_m"]


def _short_solver(cav, n_circ=144, n_axial=16, L=0.0125):
    g = _core.JournalBearingGeometry()
    g.diameter_m, g.length_m, g.clearance_m, g.viscosity_pa_s = D, L, C_RAD, MU
    g.short_bearing = True
    return _core.ReynoldsSolver(g, _core.FilmGrid(n_circ, n_axial), cav)


@pytest.mark.parametrize("eps", [0.2, 0.5])
def test_short_journal_bearing_is_ocvirks(eps):
    L, w = 0.0125, 2 * math.pi * 50.0
    s = _short_solver("gumbel", L=L)
    W = MU * w * (D / 2) * L ** 3 / (4 * C_RAD ** 2) * ocvirk_load_factor(eps)
    e = s.equilibrium(0.0, -W, w)
    assert math.hypot(e.x_m, e.y_m) / C_RAD == pytest.approx(eps, rel=5e-3)
    att = math.atan2(e.x_m, -e.y_m)  # from the load line, toward the rotation
    assert math.tan(att) == pytest.approx(math.pi * math.sqrt(1 - eps ** 2) / (4 * eps),
                                          rel=5e-3)
    dc = s.coefficients(e.x_m, e.y_m, w)
    g_model, m_model = lund(dc.K * C_RAD / W, dc.C * C_RAD * w / W)
    g_ref, m_ref = lund(*short_bearing_ab(eps))
    assert g_model == pytest.approx(g_ref, rel=5e-3)
    assert m_model == pytest.approx(m_ref, rel=5e-3)


@pytest.mark.parametrize("cav", ["none", "gumbel"])
def test_short_linearisation_matches_finite_differences(cav):
    s = _short_solver(cav, n_circ=72, n_axial=8)
    w = 2 * math.pi * 40.0
    dc = s.coefficients(4e-5, -9e-5, w)
    fd = s.coefficients_fd(4e-5, -9e-5, w, rel_step=1e-6)
    np.testing.assert_allclose(dc.K, fd.K, rtol=0, atol=1e-5 * np.abs(fd.K).max())
    np.testing.assert_allclose(dc.C, fd.C, rtol=0, atol=1e-5 * np.abs(fd.C).max())


def test_short_model_input_errors():
    with pytest.raises(InputError, match="film_model"):
        _damper(0.025, "gumbel", "long")
    with pytest.raises(InputError, match="short damper model has open ends"):
        SqueezeFilmDamper(station=0, diameter_m=D, length_m=0.025, clearance_m=C_RAD,
                          viscosity_pa_s=MU, film_model="short",
                          end_seal_conductance_m3_per_pa_s_per_m=1e-9)
    g = _core.JournalBearingGeometry()
    g.short_bearing = True
    g.grooves = [_core.Groove(90.0, 20.0, 1e5)]
    with pytest.raises(InputError, match="short_bearing"):
        _core.ReynoldsSolver(g, _core.FilmGrid(36, 8), "reynolds")
    g.grooves = []
    g.end_seal_conductance = 1e-6
    with pytest.raises(InputError, match="short_bearing"):
        _core.ReynoldsSolver(g, _core.FilmGrid(36, 8), "none")
