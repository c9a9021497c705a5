"""Options of docs/calibration/control_round2.py used in docs/control.md §2.6: the DC-command
prediction of the adaptive law (``dc_command``) and the step limit of its run-ups
(``--max-steps``)."""

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
    A, B, C, D = ss.A, ss.B[:, 0], ss.C, ss.D[:, 0]
    n = A.shape[0]
    W = 2 * g * G
    # z = [x, q1, q2]: x' = A x + B q1; y = C x + D q1 + drift; Q' = (iΩ − σ)Q − W y
    M = np.zeros((n + 2, n + 2))
    M[:n, :n], M[:n, n] = A, B
    M[n, :n], M[n + 1, :n] = -(W.real @ C), -(W.imag @ C)
    M[n, n] = -(W.real @ D) - leak
    M[n + 1, n] = -(W.imag @ D) + om
    M[n, n + 1], M[n + 1, n + 1] = -om, -leak
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
