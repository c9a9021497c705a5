"""A tilting-pad equilibrium that cannot be found fails fast and truthfully (C++
``pad_equilibrium.cpp``, the pad assembly's stall stop).

The case (from tests/test_fuzz.py::test_fuzz_bearing_elements, which generates it on every
derandomized run): two narrow pads (25° arc) loaded between them, a stiff pivot, a side
load. No equilibrium is found at any speed. Before the stall stop the homotopy's first stage
(the model with the stiff pad penalty, bearing_table.cpp) ran its pad assembly for 100
iterations of line-search steps t ~ 1e-6 … 1e-12, each lowering the residual by ~1e-6 of
itself: 2.7·10^6 Reynolds solves, ~9 s CPU per speed, a "hang" in the fuzz run.

Checks, no timing (the machine is shared): every row is not_converged with a message naming
the failed stages and NaN coefficients; the homotopy's first stage, rebuilt here through the
bound SystemSolver, stops its pad assembly at the work budget (10^5 Reynolds solves at the
default max_iter) and costs under 2·10^5 Reynolds solves in all (the count, not the clock:
2.73·10^6 without the budget).
"""

import math

import numpy as np

from rotordyn import _core
from rotordyn.bearings import TiltingPadBearing
from rotordyn.bearings._film import standalone_model

CASE = {"station": 0, "diameter_m": 0.1, "length_m": 0.05, "clearance_m": 0.0001,
        "viscosity_pa_s": 0.03, "n_circ": 36, "n_axial": 6, "n_pads": 2,
        "pad_arc_deg": 24.89739304129195, "pivot_offset": 0.36627976909786186,
        "preload": 0.1775660523307009, "load": "between", "pivot_stiffness_n_per_m": 1e12,
        "pad_mass_kg": 0.5}
LOAD = (-1447.3499698536116, -1447.3499698536116)


def test_hopeless_case_rows_are_not_converged_with_nan_coefficients():
    """Status truthful, message says where each stage stopped, no coefficients."""
    tab = TiltingPadBearing(**CASE).coefficient_table([1.9, 13.987487463109678], LOAD)
    assert tab.status == ("not_converged", "not_converged")
    for msg in tab.message:
        assert "pad assembly" in msg and "load continuation reached" in msg, msg
    assert np.isnan(tab.K).all() and np.isnan(tab.C).all()


def test_homotopy_first_stage_cost_is_bounded():
    """The stage that ran 2.7e6 Reynolds solves: the homotopy's stage t = 0 (K + κ_0 P,
    κ_0 = 100 max|diag K_H| at the centre, bearing_table.cpp homotopy_start) at 1.9 Hz."""
    b = TiltingPadBearing(**CASE)
    parts = b.system_parts(0, 1, 2, "bearing")
    model = standalone_model(parts, np.array(LOAD))
    n = 2 + parts.n_extra
    omega = 2 * math.pi * 1.9
    zero = np.zeros(n)
    lin = _core.SystemSolver(model).linearize(zero, zero, omega)
    kappa0 = 100.0 * np.abs(np.diag(np.asarray(lin.KH))).max()
    P = np.asarray(parts.penalty)
    model.K = np.asarray(model.K) + kappa0 / np.diag(P).max() * P
    solver = _core.SystemSolver(model)
    opt = _core.EquilibriumOptions()
    opt.tol = 1e-10
    e = solver.equilibrium(omega, 0.0, zero, zero, opt)
    assert e.status in ("not_converged", "no_equilibrium")
    assert "pad assembly: stopped after" in e.message, e.message
    assert solver.reynolds_solves < 200_000, solver.reynolds_solves
