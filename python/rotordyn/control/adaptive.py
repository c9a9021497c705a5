"""Adaptive 1× unbalance rejection: an influence-coefficient (normalised LMS) adaptation of the
once-per-revolution chamber-pressure command, integrated in the CVODE loop of the nonlinear
transient.

The command p_ad(t) = Re(P e^{iθ}) = P_r cos θ − P_i sin θ (θ the rotor angle) is added to
the pressure command. With T(Ω) ∈ ℂ^{n_y} the influence coefficients — the steady 1×
measurement response to P = 1 Pa (the linear plant's frequency response at Ω, valve included)
— the measured 1× response is Y = Y_u + T P, and the least-squares optimum is

    P* = argmin |Y_u + T P|² = −T⁺ Y_u,   T⁺ = Tᴴ / (Tᴴ T).

The law (C. R. Knospe, R. W. Hope, S. J. Fedigan and R. D. Williams, "Experiments in the
control of unbalance response using magnetic bearings", *Mechatronics* 5 (1995) 385–400;
continuous form of W. Widrow and S. D. Stearns, *Adaptive Signal Processing*, 1985, ch. 11)

    Ṗ = −γ T̂⁺(Ω) · 2 y(t) e^{−iθ},   y the measurements minus their equilibrium value,

demodulates y at 1× (2 y e^{−iθ} averages to Y over a revolution) and steps P toward P* at the
rate γ (1/s): with T̂ = T and a constant speed the revolution-average is Ṗ = −γ (P − P*),
first-order convergence with time constant 1/γ, whatever the plant's phase; γ well below
the speed (γ ≪ Ω) keeps the averaging valid. T̂⁺(Ω) is tabulated over a speed grid and
interpolated piecewise linearly at Ω(t) in the C++ right-hand side.

Extensions for a run-up (docs/control.md §2.6; each off by default, the law above bit for bit):

    Ṗ = −γ(Ω) T̂⁺(Ω) · 2 y(t) e^{−iθ} − σ P,

a leak σ (``leak_1_per_s``: revolution-averaged fixed point P = −(T̂⁺T + σ/γ)⁻¹ T̂⁺ Y_u, P
bounded by γ|T̂⁺Y|/σ), γ(Ω) a schedule over the speed (designed on the plant by
:func:`rotordyn.control.adaptive_design.adaptive_design`), and ``freeze_at_limits`` (no
gradient while the command is outside the valve's limits).

Washout (``washout_hz`` f_w, off by default): the law measures y relative to the starting
equilibrium, and during a run-up the equilibrium drifts with the speed; demodulated, a slow
drift d(t) gives Ṗ ≈ −2γ T̂⁺ d e^{−iθ}, a 1× ripple of P and so a steady (DC) part of the
command p_ad = Re(P e^{iθ}) ≈ Re(2γ i T̂⁺ d / (kΩ)) (docs/control.md §2.6). The washout
H(s) = s/(s + ω_w), ω_w = 2π f_w, on each measurement (states z, ż = ω_w (y − z), started at
z(0) = y(0)) passes y − z to the demodulation: a constant d decays as e^{−ω_w t}, a ramp
d = ρ t leaves ρ/ω_w instead of ρ t. At the 1× the washout multiplies the response by
H(ikΩ), and the update uses T̂⁺/H(ikΩ) = T̂⁺ (1 − i ω_w/(kΩ)) (the plant's T̂ times H): the
revolution-averaged law, its fixed point P* and its rate γ are unchanged. The condition
ω_w ≪ kΩ (checked: f_w ≤ 0.25 k f_min over the run) keeps the 1× clear of the corner and
the compensation near 1; ω_w above the drift's rate (1/time scale) makes the removal
effective.
"""

from __future__ import annotations

import numpy as np

from rotordyn._common import validate as v
from rotordyn.operation.adaptive import (MAX_GAIN_1_PER_S, MAX_LEAK_1_PER_S, AdaptiveRejection,
                                         _gain, _gain_schedule, _is_scalar, _leak)
from rotordyn.operation.measurement import parse_measurements


def influence_coefficients(system, speeds_hz, measurements, *, chamber_pressure_pa=0.0,
                           config_ay_m=None, actuator=None) -> np.ndarray:
    """T(Ω) (n_g, n_y) complex: the linear plant's frequency response from the pressure
    command to the measurements at the rotor frequency, re-linearised at each speed (the
    valve's lag included). ``chamber_pressure_pa``: a number or a callable of the speed."""
    from rotordyn.control.plant import plant

    sp = v.vector("speeds_hz", speeds_hz)
    meas = parse_measurements(measurements)
    rows = []
    for f in sp:
        pc = chamber_pressure_pa(float(f)) if callable(chamber_pressure_pa) \
            else chamber_pressure_pa
        p = plant(system, float(f), pc, config_ay_m, measurements=meas, actuator=actuator)
        G = p.frequency_response([float(f)])[0]  # (n_y + n_z, 1 + n_d)
        rows.append(G[:p.C.shape[0], 0])  # the measured signals (a journal: x and y)
    return np.array(rows)


def adaptive_rejection(system, speeds_hz, measurements, gain_1_per_s, *,
                       chamber_pressure_pa=0.0, config_ay_m=None, actuator=None,
                       p0_pa: complex = 0j, leak_1_per_s: float = 0.0,
                       freeze_at_limits: bool = False,
                       washout_hz: float = 0.0) -> AdaptiveRejection:
    """The adaptive 1× law with influence coefficients from the linear model
    (:func:`influence_coefficients`) on the grid ``speeds_hz``; ``gain_1_per_s`` a number or a
    schedule γ(Ω) (:class:`AdaptiveRejection`; designed on the plant:
    :func:`rotordyn.control.adaptive_design.adaptive_design`), ``leak_1_per_s`` σ,
    ``freeze_at_limits`` the gradient off while the command is saturated, ``washout_hz`` the
    washout's corner f_w (Hz; 0: none)."""
    sp = v.vector("speeds_hz", speeds_hz)
    g = _gain(gain_1_per_s) if _is_scalar(gain_1_per_s) else _gain_schedule(gain_1_per_s, sp)
    _leak(leak_1_per_s)
    T = influence_coefficients(system, speeds_hz, measurements,
                               chamber_pressure_pa=chamber_pressure_pa,
                               config_ay_m=config_ay_m, actuator=actuator)
    return AdaptiveRejection(measurements, speeds_hz, T, g, p0_pa, 1.0, leak_1_per_s,
                             freeze_at_limits, washout_hz)


__all__ = ["AdaptiveRejection", "MAX_GAIN_1_PER_S", "adaptive_rejection", "influence_coefficients",
           "MAX_LEAK_1_PER_S"]
