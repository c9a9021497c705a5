"""The linear closed loop of a plant and a controller: eigenvalues, stability margin (least
damping ratio, largest real part), and every loop margin (:mod:`rotordyn.control.margins`:
gain margins below and above 1, phase, delay and disk margins, peak sensitivity, located
exactly; loop-at-a-time and multivariable disk margins when several measurements are fed
back)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control import _checks as chk
from rotordyn.control.plant import as_plant, paired
from rotordyn.errors import InputError
from rotordyn.operation.controller import Controller
from rotordyn.operation.profiles import PressureSchedule
from rotordyn.results.modes import damping_ratio, point_stable


@dataclass(frozen=True)
class ClosedLoopResult:
    """A (closed-loop state matrix; a discrete controller: the sampled-data loop's),
    eigenvalues (1/s), damping ratios; ``margins`` (:class:`~rotordyn.control.margins.Margins`:
    every gain margin, phase, delay and disk margin, peak sensitivities, located exactly) or
    None with ``margins_message`` saying why (the closed loop is not stable: margins are not
    defined); ``frequency_hz`` and ``loop`` = L(iω) = −K G at the actuator input on the
    requested grid (for Bode and Nyquist plots)."""

    A: np.ndarray
    eigenvalues: np.ndarray
    damping_ratio: np.ndarray
    margins: object
    margins_message: str
    frequency_hz: np.ndarray
    loop: np.ndarray

    @property
    def max_real(self) -> float:
        return float(self.eigenvalues.real.max())

    @property
    def min_damping(self) -> float:
        return float(self.damping_ratio.min())

    @property
    def stable(self) -> bool:
        """Every Re λ below the round-off band (:func:`rotordyn.results.modes.point_stable`)."""
        return point_stable(self.eigenvalues)

    def _m(self, name):
        return getattr(self.margins.input, name) if self.margins is not None else math.nan

    @property
    def gain_margin_lower(self) -> float:
        """Lowest loop-gain factor < 1 keeping the loop stable (0: none; NaN: unstable)."""
        return self._m("gain_margin_lower")

    @property
    def gain_margin_upper(self) -> float:
        """Largest loop-gain factor > 1 keeping the loop stable (inf: none; NaN: unstable)."""
        return self._m("gain_margin_upper")

    @property
    def phase_margin_deg(self) -> float:
        return self._m("phase_margin_deg")

    @property
    def delay_margin_s(self) -> float:
        return self._m("delay_margin_s")

    @property
    def peak_sensitivity(self) -> float:
        return self._m("peak_sensitivity")

    @property
    def disk_margin(self) -> float:
        return self.margins.input.disk.alpha if self.margins is not None else math.nan

    def __repr__(self):
        head = (f"ClosedLoopResult(stable={self.stable}, max Re λ={self.max_real:.4g} 1/s, "
                f"min ζ={self.min_damping:.4g}")
        if self.margins is None:
            return head + f", margins: {self.margins_message})"
        m = self.margins.input
        return (head + f", GM=({m.gain_margin_lower:.4g}, {m.gain_margin_upper:.4g}), "
                f"PM={m.phase_margin_deg:.4g}°, DM={m.delay_margin_s * 1e3:.4g} ms, "
                f"|S|max={m.peak_sensitivity:.4g}, disk ±{m.disk.gain_db[1]:.3g} dB/"
                f"±{m.disk.phase_deg:.3g}°)")


def _discrete_loop(p, k, freqs_hz, delay_s=0.0):
    """Sampled-data loop of a discrete controller: the plant discretised exactly with a
    zero-order hold (Φ = e^{AT}, Γ = ∫e^{Aτ}dτ B; with a computation delay the exact
    delayed hold of :mod:`rotordyn.control.delay`) and sampled at the controller's instants;
    closed-loop z-eigenvalues mapped to s = ln z / T. Returns (A_cl (discrete), λ_s,
    L(e^{iωT})) with the frequencies limited to below Nyquist."""
    from rotordyn.control import lti
    from rotordyn.control.margins import controller_ss, plant_ss

    T = k.sample_time_s
    P = plant_ss(p, T, delay_s)
    K = controller_ss(k)
    Ad = lti.feedback_A(P, K)
    z = np.linalg.eigvals(Ad).astype(complex)
    # a dead-beat mode (z = 0, e.g. the held command of a one-sample computation delay) is
    # reported at |z| = 1e-300, i.e. Re λ = −690/T: finite, faster than any sampled mode
    z = np.where(np.abs(z) < 1e-300, 1e-300, z)
    lam = np.log(z) / T
    f = np.asarray(freqs_hz, dtype=float)
    f = f[f < 0.5 / T]
    L = lti.freqresp(lti.balanced(lti.loop_at_input(P, K)), 2 * np.pi * f)[:, 0, 0]
    return Ad, lam, L


def closed_loop_matrix(p, k) -> np.ndarray:
    """State matrix of [x; x_k] for ẋ = A x + B u, y = C x, u = C_k x_k + D_k y,
    ẋ_k = A_k x_k + B_k y (continuous controllers; a discrete one via its ZOH continuous
    equivalent is not formed here)."""
    paired(p, k)
    if k.discrete:
        raise InputError("controller.sample_time_s: a continuous closed-loop matrix needs a "
                         "continuous controller (closed_loop() handles discrete ones)")
    A, B, C = p.A, p.B, p.C
    Dr = p.info.get("feedthrough")
    if Dr is not None and np.any(Dr):
        # y = C x + D_r u with u = C_k x_k + D_k y: solve the algebraic loop.
        M = np.linalg.inv(np.eye(C.shape[0]) - Dr @ k.D)
        Cy, Dy = M @ C, M @ Dr @ k.C
    else:
        Cy, Dy = C, np.zeros((C.shape[0], k.n_states))
    nk = k.n_states
    top = np.hstack([A + B @ k.D @ Cy, B @ (k.C + k.D @ Dy)])
    bot = np.hstack([k.B @ Cy, k.A + k.B @ Dy])
    return np.vstack([top, bot]) if nk else A + B @ k.D @ Cy


def loop_response(p, k, freqs_hz) -> np.ndarray:
    """L(iω) = −K(iω) G(iω), (n_f,) complex (negative-feedback convention; a discrete law: the
    ZOH-sampled loop at z = e^{iωT}), evaluated on the
    balanced realisation of the loop (:func:`rotordyn.control.lti.balanced`)."""
    from rotordyn.control import lti
    from rotordyn.control.margins import controller_ss, plant_ss

    paired(p, k)
    w = 2 * np.pi * chk.frequencies("freqs_hz", freqs_hz)
    loop = lti.balanced(lti.loop_at_input(plant_ss(p, k.sample_time_s), controller_ss(k)))
    return lti.freqresp(loop, w)[:, 0, 0]


def closed_loop(p, k, *, freqs_hz=None, computation_delay_s: float | None = None,
                pade_order: int = 6, with_margins: bool = True) -> ClosedLoopResult:
    """Closed loop of plant ``p`` (:func:`rotordyn.control.plant`) and controller ``k``
    (:class:`rotordyn.control.Controller`; a discrete one closes a sampled-data loop with the
    plant discretised exactly under ZOH, eigenvalues mapped back by s = ln z / T, margins
    below Nyquist). Margins: :func:`rotordyn.control.margins.margins` (exact; None with the
    reason when the closed loop is unstable). ``freqs_hz``: the grid of the returned loop
    response (default 0.1 Hz – 5 kHz, 4000 points; a discrete law: below Nyquist).
    ``computation_delay_s`` (s, ≥ 0; None: the law's own; :mod:`rotordyn.control.delay`): the
    command reaches the valve that much later — a continuous law through the Padé
    approximant of ``pade_order`` (1..20; its phase error:
    :func:`rotordyn.control.delay.pade_phase_error`), a discrete law exactly (at most its
    sample time). ``with_margins=False`` skips the margins (0.3–3 s on the rig; e.g. inside a
    root search on the eigenvalues): ``margins`` None, ``margins_message`` says so."""
    from rotordyn.control.delay import check_order, computation_delay_for, with_pade_delay
    from rotordyn.control.margins import margins

    as_plant(p)
    if not isinstance(k, Controller):  # a python-control system reading the plant's outputs
        k = Controller.from_lti(k, p.measurements)
    paired(p, k)
    tau = computation_delay_for(k, computation_delay_s)
    check_order(pade_order)
    f = np.logspace(-1, np.log10(5000.0), 4000) if freqs_hz is None \
        else chk.frequencies("freqs_hz", freqs_hz)
    if k.discrete and not np.any(f < 0.5 / k.sample_time_s):
        raise InputError(f"freqs_hz: expected frequencies below the controller's Nyquist "
                         f"frequency {0.5 / k.sample_time_s:g} Hz, got {f[0]:g} .. {f[-1]:g}")
    k0 = k
    if tau and not k.discrete:
        k = with_pade_delay(k, tau, pade_order)
    if k.discrete:
        Acl, lam, L = _discrete_loop(p, k, f, tau)
        f = f[f < 0.5 / k.sample_time_s]
    else:
        Acl = closed_loop_matrix(p, k)
        lam = np.linalg.eigvals(Acl)
        L = loop_response(p, k, f)
    v.boolean("with_margins", with_margins)
    if not with_margins:
        m, msg = None, "not computed (with_margins=False)"
    elif np.all(np.isfinite(lam)) and lam.real.max() < 0:
        m, msg = margins(p, k0, computation_delay_s=tau, pade_order=pade_order), "ok"
    else:
        from rotordyn.results.modes import point_stable

        m = None
        marginal = np.all(np.isfinite(lam)) and point_stable(lam)  # .stable, yet not decaying
        msg = (f"not computed: the closed loop is " + ("only marginally stable" if marginal
                                                       else "not stable")
               + f" (largest Re λ = {float(np.nanmax(lam.real)):.6g} 1/s)")
    return ClosedLoopResult(Acl, lam, damping_ratio(lam), m, msg, f, L)


def closed_loop_unbalance(system, controller, unbalances, speeds_hz, *, chamber_pressure_pa=0.0,
                          config_ay_m=None, stations=None, actuator=None):
    """Steady unbalance response of the linear closed loop at each speed (plant re-linearised
    at every speed about the equilibrium at the base pressure — a number or a
    :class:`~rotordyn.control.PressureSchedule` of speed — and the same controller).
    Returns a DataFrame (speed_hz, chamber_pressure_pa, amplitude_m[station] …,
    max_real_1_per_s, min_damping_ratio)."""
    import pandas as pd

    from rotordyn.analysis.assembly import assembled
    from rotordyn.control.plant import plant as make_plant
    from rotordyn.units import hz_to_rad_s

    chk.system(system)
    chk.controller(controller, continuous=True)
    chk.measured_by(system, controller)
    ub = chk.unbalances(system, unbalances)
    sp = chk.speeds("speeds_hz", speeds_hz)
    if isinstance(chamber_pressure_pa, PressureSchedule):
        sched = chamber_pressure_pa
        if sched.kind == "time_table":
            raise InputError("chamber_pressure_pa: expected a number, a constant or a speed "
                             "schedule (a linear steady response has no time), got a time table")
        pcs = np.interp(sp, sched.x, sched.p_pa) if sched.kind == "speed_table" \
            else np.full(sp.size, sched.value_pa)
        if np.any(pcs < 0):
            raise InputError(f"chamber_pressure_pa: expected pressures >= 0 Pa over the speeds, "
                             f"got {float(pcs.min())!r}")
    else:
        pcs = np.full(sp.size, v.non_negative("chamber_pressure_pa", chamber_pressure_pa))
    config_ay_m = chk.config_ay(system, config_ay_m)
    actuator = chk.actuator(actuator)
    outs = chk.stations(system, stations) if stations is not None \
        else tuple(dict.fromkeys(s for s, _, _ in ub))
    asm = assembled(system)
    rows = []
    for f, pc in zip(sp, pcs):
        p = make_plant(system, f, float(pc), config_ay_m, measurements=controller.measurements,
                       actuator=actuator)
        n = p.n_mech
        F = asm.unbalance_load(ub)
        w = hz_to_rad_s(f)
        Minv = np.linalg.inv(p.info["M"]) if "M" in p.info else None
        bF = np.zeros(p.A.shape[0], dtype=complex)
        bF[n:2 * n] = (Minv if Minv is not None else np.linalg.inv(_mass(system))) @ (w**2 * F)
        Acl = closed_loop_matrix(p, controller)
        N = Acl.shape[0]
        b = np.concatenate([bF, np.zeros(N - bF.size)])
        x = np.linalg.solve(1j * w * np.eye(N) - Acl, b)
        row = {"speed_hz": f, "chamber_pressure_pa": float(pc)}
        for st in outs:
            Co = asm.station_output_matrix(st)
            X, Y = Co @ x[:n]
            row[f"amplitude_m[{st}]"] = float(np.hypot(abs(X), abs(Y)))
        lam = np.linalg.eigvals(Acl)
        row["max_real_1_per_s"] = float(lam.real.max())
        row["min_damping_ratio"] = float(damping_ratio(lam).min())
        rows.append(row)
    return pd.DataFrame(rows)


def _mass(system):
    from rotordyn.analysis.assembly import assembled

    return np.asarray(assembled(system).model.M)
