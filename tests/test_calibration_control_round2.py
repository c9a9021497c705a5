"""Options of docs/calibration/control_round2.py used in docs/control.md §2.6: the adaptive
law's frozen-speed loop without averaging (``exact_loop_matrix``), its DC-command prediction
(``dc_command``) and the step limit of the run-ups (``--max-steps``)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.control import Actuator
from rotordyn.control.adaptive_design import _linear_plants

SCRIPT = Path(__file__).resolve().parents[1] / "docs" / "calibration" / "control_round2.py"


@pytest.fixture(scope="module")
def script():
    spec = importlib.util.spec_from_file_location("control_round2", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("leak", [0.0, 0.5])
def test_dc_command_is_the_steady_state_of_the_full_loop(script, leak):
    """The 2 × 2 quasi-static reduction equals the DC steady state of the whole frozen-speed
    loop (plant states and Q = P e^{iθ} in the stationary frame, no averaging, solved as one
    linear system) forced by a constant measurement drift: rig, journal, 90.4 Hz, γ = 20 1/s."""
    rig = rd.models.paper_rig()
    f = 90.4
    (ss, T), = _linear_plants(rig, [f], [("journal", 0)], 0.5e6, 0.0, Actuator())
    G = T.conj() / np.vdot(T, T).real
    drift = np.array([12e-6, -40e-6])
    om, g = 2 * np.pi * f, 20.0
    n = ss.A.shape[0]
    W = 2 * g * G
    # z = [x, q1, q2]: x' = A x + B q1; y = C x + D q1 + drift; Q' = (iΩ − σ)Q − W y
    M = script.exact_loop_matrix(ss, om, G, g, leak)
    rhs = np.zeros(n + 2)
    rhs[n], rhs[n + 1] = (W @ drift).real, (W @ drift).imag
    z = np.linalg.solve(M, rhs)
    dc = script.dc_command(ss, om, G, g, drift, leak)
    assert abs(dc) > 1e3  # a command of kPa: the check is not on a vanishing number
    assert dc == pytest.approx(z[n], rel=1e-9)


def test_max_steps_reaches_the_integrator(script, monkeypatch):
    """A run-up limited to 3 steps per output interval stops early with a status that says so
    (the default limit integrates the same start)."""
    monkeypatch.setattr(script, "MAX_STEPS", 3)
    tr, _ = script.runup(rd.models.paper_rig(), 10.0)
    assert tr.status != "ok"
    ok = np.isfinite(tr.t)
    assert tr.t[ok].max() < 0.01


def test_exact_loop_matrix_closed_forms(script):
    """The frozen-speed loop without averaging: at γ = 0 its eigenvalues are the plant's and
    −σ ± iΩ (10⁻⁹); its rows reproduce x' = A x + B Re Q and Q' = (iΩ − σ)Q − 2γT̂⁺y on a
    random state (10⁻¹²), the 2 × 2 real form of the complex law written out independently."""
    rig = rd.models.paper_rig()
    f = 60.0
    (ss, T), = _linear_plants(rig, [f], [("journal", 0)], 0.5e6, 0.0, Actuator())
    G = T.conj() / np.vdot(T, T).real
    om, sig = 2 * np.pi * f, 0.7
    ev = np.sort_complex(np.linalg.eigvals(script.exact_loop_matrix(ss, om, G, 0.0, sig)))
    ref = np.sort_complex(np.concatenate([np.linalg.eigvals(ss.A),
                                          [-sig + 1j * om, -sig - 1j * om]]))
    assert np.allclose(ev, ref, rtol=0, atol=1e-9 * np.abs(ref).max())
    rng = np.random.default_rng(3)
    n = ss.A.shape[0]
    z = rng.standard_normal(n + 2)
    x, Q = z[:n], z[n] + 1j * z[n + 1]
    y = ss.C @ x + ss.D[:, 0] * Q.real
    Qd = (1j * om - sig) * Q - 2 * 15.0 * (G @ y)
    want = np.concatenate([ss.A @ x + ss.B[:, 0] * Q.real, [Qd.real, Qd.imag]])
    got = script.exact_loop_matrix(ss, om, G, 15.0, sig) @ z
    assert np.allclose(got, want, rtol=0, atol=1e-12 * np.abs(want).max())


def test_command_mean_over_whole_revolutions(script):
    """The mean of 0.5 MPa + 0.1 MPa cos θ + a 2 kPa/Hz ramp over ±4 revolutions of a 10 Hz/s
    run is the ramp's value where the speed is reached (the 1× part cancels over whole
    revolutions; the window is symmetric in angle, so the ramp's mean is off by its change over
    the window's time asymmetry, < 0.5 kPa here); NaN rows of a stopped run are ignored and a
    speed the run never reached gives NaN."""
    from types import SimpleNamespace

    t = np.linspace(0.0, 4.0, 80001)
    f = 10.0 + 10.0 * t
    th = 2 * np.pi * (10.0 * t + 5.0 * t ** 2)
    cmd = 0.5e6 + 0.1e6 * np.cos(th) + 2e3 * (f - 30.0)
    t[-100:] = np.nan
    tr = SimpleNamespace(t=t, speed_hz_t=f, chamber_pressure_command_pa=cmd, angle_rad=th)
    m = script.command_mean(tr, [20.0, 40.0, 60.0])
    assert m[0] == pytest.approx(0.5e6 - 2e4, abs=500.0)
    assert m[1] == pytest.approx(0.5e6 + 2e4, abs=500.0)
    assert np.isnan(m[2])
