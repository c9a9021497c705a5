"""Stability margins of a feedback loop, located exactly: every gain margin (the loop-gain
factors at which the closed loop turns unstable, below and above 1, with their frequencies),
phase margins and delay margins at every gain crossover, peak sensitivity |S| and
complementary sensitivity |T|, and disk margins (balanced σ = 0 and skewed σ), for a SISO loop
and, when several measurements are fed back, loop-at-a-time margins at each measurement and
the multivariable disk margin at the measurements.

Every crossing and peak is bracketed on a frequency grid (a log grid of ≥ 60 points per
decade over the poles' range, densified around every open- and closed-loop pole) and then
refined by Brent's method on a smooth function of ω to round-off: phase crossovers as roots
of Im L/|L|, gain crossovers as roots of ln|L|, peaks of |M| for M = (p + q L)/(1 + L) as
roots of d|M|²/dω = 2 Re(M̄ (q − p)/(1 + L)² dL/dω) with dL/dω = −C (sI − A)⁻² B ds/dω.
The value at a refined frequency is the loop's own response there, not a grid value.

Definitions (negative-feedback convention, closed loop 1 + L; rotordyn's controllers are
positive feedback u = K y, so the loop at the actuator is L = −K G):

* gain margin: α > 0 with 1 + α L(iω) = 0, i.e. L(iω) real negative, α = −1/L; the stable
  range of the loop gain is (``gain_margin_lower``, ``gain_margin_upper``) around 1 (0 and ∞
  when no crossing bounds it); ω = 0 and ω = ∞ (or Nyquist) are included.
* phase margin at each |L(iω_c)| = 1: PM = arg L + 180° wrapped to (−180°, 180°];
  ``phase_margin_deg`` is the one of smallest magnitude.
* delay margin: τ_c = (PM mod 360°)/ω_c per crossover, the least over crossovers (0 when
  |L(∞)| ≥ 1). A pure delay e^{−sτ} first puts a closed-loop root on the imaginary axis at
  τ = min τ_c.
* disk margin with skew σ (P. Seiler, A. Packard, P. Gahinet, "An introduction to disk
  margins", IEEE Control Systems Magazine 40(5), 2020, 78–95, eq. 12–14):
  α_max = 1/‖S + (σ − 1)/2‖∞; the loop stays stable for every gain
  f = (1 + (1 − σ)δ/2)/(1 − (1 + σ)δ/2), |δ| < α_max, i.e. gain in [g_lo, g_hi] =
  [(2 − α(1 − σ))/(2 + α(1 + σ)), (2 + α(1 − σ))/(2 − α(1 + σ))] together with phase
  ±arccos((1 + g_lo g_hi)/(g_lo + g_hi)). σ = 0: the balanced margin (g_lo = 1/g_hi,
  phase 2 arctan(α/2)); σ = 1: 1/‖S‖∞ (gain increase); σ = −1: 1/‖T‖∞.
* multivariable disk margin at the measurements: α = 1/max_ω μ_Δ(S_o + (σ − 1)/2 I) with
  S_o = (I + L_o)⁻¹, L_o = −G K and Δ diagonal complex (independent, simultaneous
  perturbations of every measurement channel). μ is the D-scaled upper bound
  min_D σ̄(D M D⁻¹), exact for up to three channels (Packard & Doyle, Automatica 29 (1993) 71,
  2S + F ≤ 3); for two channels in closed form (d² = |m₁₂|/|m₂₁|).

Margins are defined for a stable closed loop only: an unstable one is refused with an
:class:`~rotordyn.errors.InputError` naming the controller and the largest closed-loop Re λ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn._common import validate as v
from rotordyn.control import lti
from rotordyn.control import loop_response as lr
from rotordyn.errors import InputError

TINY = 1e-12  # |L| below it at a phase crossover: a round-off crossing (gain factor > 1e12)


@dataclass(frozen=True)
class DiskMargin:
    """Disk margin α with skew σ, the frequency of the worst case (Hz; 0: static, inf: high
    frequency), the gain range [gain_lo, gain_hi] (factors) and the phase (deg) it
    guarantees simultaneously."""

    sigma: float
    alpha: float
    frequency_hz: float
    gain_lo: float
    gain_hi: float
    phase_deg: float

    @property
    def gain_db(self) -> tuple[float, float]:
        with np.errstate(divide="ignore"):
            return (float(20 * np.log10(self.gain_lo)), float(20 * np.log10(self.gain_hi)))


def disk_from_alpha(alpha: float, sigma: float, frequency_hz: float) -> DiskMargin:
    """Gain range and phase of the disk of size α and skew σ (module docstring)."""
    a = alpha
    lo = (2 - a * (1 - sigma)) / (2 + a * (1 + sigma))
    den = 2 - a * (1 + sigma)
    hi = (2 + a * (1 - sigma)) / den if den > 0 else math.inf
    lo = max(lo, 0.0)
    if math.isinf(hi):
        c = lo
    else:
        c = (1 + lo * hi) / (lo + hi) if lo + hi > 0 else -1.0
    ph = math.degrees(math.acos(min(1.0, max(-1.0, c))))
    return DiskMargin(float(sigma), float(a), float(frequency_hz), float(lo), float(hi), ph)


@dataclass(frozen=True)
class LoopMargins:
    """Margins of one SISO loop (module docstring for the definitions). Frequencies in Hz;
    arrays are sorted by frequency. ``closed_loop_max_real``: the stable closed loop's largest
    Re λ (1/s)."""

    name: str
    gain_margins: np.ndarray
    gain_margin_hz: np.ndarray
    gain_margin_lower: float
    gain_margin_lower_hz: float
    gain_margin_upper: float
    gain_margin_upper_hz: float
    phase_margins_deg: np.ndarray
    crossover_hz: np.ndarray
    delay_margins_s: np.ndarray
    phase_margin_deg: float
    phase_margin_hz: float
    delay_margin_s: float
    delay_margin_hz: float
    peak_sensitivity: float
    peak_sensitivity_hz: float
    peak_complementary: float
    peak_complementary_hz: float
    disk: DiskMargin
    closed_loop_max_real: float
    loop: lti.SS = field(repr=False)
    response: str = field(default="direct solves", repr=False, compare=False)

    def disk_margin(self, sigma: float = 0.0) -> DiskMargin:
        """Disk margin with skew σ ∈ [−1e6, 1e6]: σ = 0 balanced (= ``disk``), σ = 1:
        1/‖S‖∞ (disks biased to gain increase), σ = −1: 1/‖T‖∞ (biased to decrease)."""
        sigma = v.in_range("sigma", sigma, -1e6, 1e6)
        return _disk_of(self.loop, sigma, self.response == "partial fractions")

    def rows(self) -> list[dict]:
        """One row per margin: (loop, kind, value, unit, frequency_hz)."""
        r = []
        for a, f in zip(self.gain_margins, self.gain_margin_hz):
            r.append((("gain_margin", float(a), "factor", float(f))))
        for pm, f, d in zip(self.phase_margins_deg, self.crossover_hz, self.delay_margins_s):
            r.append(("phase_margin", float(pm), "deg", float(f)))
            r.append(("delay_margin", float(d), "s", float(f)))
        r += [("gain_margin_lower", self.gain_margin_lower, "factor", self.gain_margin_lower_hz),
              ("gain_margin_upper", self.gain_margin_upper, "factor", self.gain_margin_upper_hz),
              ("peak_sensitivity", self.peak_sensitivity, "", self.peak_sensitivity_hz),
              ("peak_complementary_sensitivity", self.peak_complementary, "",
               self.peak_complementary_hz),
              ("disk_margin", self.disk.alpha, "", self.disk.frequency_hz),
              ("disk_gain_lo", self.disk.gain_lo, "factor", self.disk.frequency_hz),
              ("disk_gain_hi", self.disk.gain_hi, "factor", self.disk.frequency_hz),
              ("disk_phase", self.disk.phase_deg, "deg", self.disk.frequency_hz)]
        return [{"loop": self.name, "kind": k, "value": float(x), "unit": u,
                 "frequency_hz": float(f)} for k, x, u, f in r]

    def summary(self) -> dict:
        """A flat dict (JSON-ready floats; inf stays inf)."""
        lo_db, hi_db = self.disk.gain_db
        return {"gain_margin_lower": self.gain_margin_lower,
                "gain_margin_lower_hz": self.gain_margin_lower_hz,
                "gain_margin_upper": self.gain_margin_upper,
                "gain_margin_upper_hz": self.gain_margin_upper_hz,
                "phase_margin_deg": self.phase_margin_deg,
                "phase_margin_hz": self.phase_margin_hz,
                "delay_margin_s": self.delay_margin_s, "delay_margin_hz": self.delay_margin_hz,
                "peak_sensitivity": self.peak_sensitivity,
                "peak_sensitivity_hz": self.peak_sensitivity_hz,
                "peak_complementary_sensitivity": self.peak_complementary,
                "peak_complementary_sensitivity_hz": self.peak_complementary_hz,
                "disk_margin": self.disk.alpha, "disk_margin_hz": self.disk.frequency_hz,
                "disk_gain_db": [lo_db, hi_db], "disk_phase_deg": self.disk.phase_deg}

    def __repr__(self):
        d = self.disk
        lo_db, hi_db = d.gain_db
        return (f"LoopMargins({self.name}: GM ({self.gain_margin_lower:.4g} at "
                f"{self.gain_margin_lower_hz:.4g} Hz, {self.gain_margin_upper:.4g} at "
                f"{self.gain_margin_upper_hz:.4g} Hz), PM {self.phase_margin_deg:.2f}° at "
                f"{self.phase_margin_hz:.4g} Hz, DM {self.delay_margin_s * 1e3:.4g} ms, "
                f"|S|max {self.peak_sensitivity:.4g} at {self.peak_sensitivity_hz:.4g} Hz, "
                f"disk α {d.alpha:.4g}: [{lo_db:.2f}, {hi_db:.2f}] dB, ±{d.phase_deg:.2f}°)")


# ----------------------------------------------------------------------------- SISO margins

def _disk(resp: lr.Response, w, sigma, grid) -> DiskMargin:
    peak, wp = lr.peak(resp, resp.ss, w, (1 + sigma) / 2, (sigma - 1) / 2, grid)
    alpha = 1.0 / peak if peak > 0 else math.inf
    return disk_from_alpha(alpha, sigma, wp / (2 * math.pi))


def _open_poles(resp: lr.Response) -> np.ndarray:
    return lr.s_plane(resp.lam, resp.dt) if resp.modal else resp.ss.poles_s()


def _on_grid(ss: lti.SS, lam_cl: np.ndarray, modal: bool):
    """(response, grid ω, (L, dL/dω) on it): partial fractions checked against direct solves
    (:mod:`rotordyn.control.loop_response`), or direct solves with ``modal`` False."""
    resp = lr.Response(ss, modal)
    w = lr.grid_from([_open_poles(resp), lam_cl], ss.dt)
    return resp, w, resp.on_grid(w)


def _disk_of(ss: lti.SS, sigma: float, modal: bool = True) -> DiskMargin:
    lam_cl = lr.poles(lr.closed_A(ss), ss.dt)
    resp, w, grid = _on_grid(ss, lam_cl, modal)
    return _disk(resp, w, sigma, grid)


def loop_margins(loop, *, name: str = "loop", dt=None, modal: bool = True) -> LoopMargins:
    """Every margin of the SISO loop ``loop`` (negative-feedback convention, closed loop
    1 + L): an (A, B, C, D) tuple, a python-control system or an :class:`lti.SS`; ``dt`` a
    sample time for a discrete tuple. Refuses a loop whose closed loop is not stable.
    ``modal``: bracket on the grid with L by partial fractions from one eigen-decomposition
    where they pass their check against the direct solve (:mod:`rotordyn.control.loop_response`;
    the refinements and values are direct solves: the same margins to round-off, less CPU);
    False: one dense solve per grid frequency."""
    v.text("name", name)
    v.boolean("modal", modal)
    ss = lti.as_ss("loop", loop, dt)
    if ss.shape != (1, 1):
        raise InputError(f"loop: expected a SISO loop (1 input, 1 output), got {ss.shape[1]} "
                         f"inputs and {ss.shape[0]} outputs")
    ss = lti.balanced(ss)
    lam_cl = lr.poles(lr.closed_A(ss), ss.dt)
    mr = lr.max_real(lam_cl)
    if not mr < 0:
        raise InputError(f"{name}: the closed loop is not stable (largest Re λ = {mr:.6g} "
                         f"1/s); margins are defined for a stable closed loop only")
    return _loop_margins(ss, name, lam_cl, mr, modal)


def _loop_margins(ss: lti.SS, name: str, lam_cl, mr: float, modal: bool) -> LoopMargins:
    resp, w, (L, dL) = _on_grid(ss, lam_cl, modal)  # once for the crossings and every peak
    two_pi = 2 * math.pi

    # gain margins: L real negative
    def im_phase(lw):
        Li = resp.at(math.exp(lw))
        return Li.imag / abs(Li)
    with np.errstate(divide="ignore", invalid="ignore"):  # L = 0: no sign, skipped
        phase_sign = L.imag / np.abs(L)
    roots = lr.roots(im_phase, w, phase_sign)
    gm = []
    for wr in roots:
        Li = resp.exact(wr)
        if -TINY < Li.real < 0:  # |L| at round-off level (a channel the law ignores)
            continue
        if Li.real < 0:
            gm.append((-1.0 / Li.real, wr))
    L0, Linf, wtop = lr.ends(ss, resp)
    if L0 is not None and L0.real < -TINY and abs(L0.imag) <= 1e-12 * abs(L0):
        gm.insert(0, (-1.0 / L0.real, 0.0))
    if Linf.real < -TINY and abs(Linf.imag) <= 1e-12 * max(abs(Linf), 1e-300):
        gm.append((-1.0 / Linf.real, wtop))
    gms = np.array([g for g, _ in gm])
    gmw = np.array([x for _, x in gm]) / two_pi
    lower = [(g, f) for g, f in zip(gms, gmw) if g < 1]
    upper = [(g, f) for g, f in zip(gms, gmw) if g > 1]
    glo = max(lower) if lower else (0.0, math.nan)
    ghi = min(upper) if upper else (math.inf, math.nan)

    # phase and delay margins at |L| = 1
    def logmag(lw):
        return math.log(abs(resp.at(math.exp(lw))))
    with np.errstate(divide="ignore"):
        cross = lr.roots(logmag, w, np.log(np.abs(L)))
    pms, dms = [], []
    for wc in cross:
        Lc = resp.exact(wc)
        ph = math.atan2(Lc.imag, Lc.real) + math.pi  # (0, 2π]
        pm = (ph + math.pi) % two_pi - math.pi       # (−π, π]
        pms.append(math.degrees(pm))
        dms.append((pm % two_pi) / wc)
    pms, dms = np.array(pms), np.array(dms)
    cf = np.array(cross) / two_pi
    if pms.size:
        i = int(np.argmin(np.abs(pms)))
        pm, pmf = float(pms[i]), float(cf[i])
        j = int(np.argmin(dms))
        dm, dmf = float(dms[j]), float(cf[j])
    else:
        pm, pmf, dm, dmf = math.inf, math.nan, math.inf, math.nan
    if ss.dt is None and abs(Linf) >= 1:
        dm, dmf = 0.0, math.inf

    s_pk, s_w = lr.peak(resp, ss, w, 1.0, 0.0, (L, dL))
    t_pk, t_w = lr.peak(resp, ss, w, 0.0, 1.0, (L, dL))
    disk = _disk(resp, w, 0.0, (L, dL))
    return LoopMargins(name, gms, gmw, float(glo[0]), float(glo[1]), float(ghi[0]),
                       float(ghi[1]), pms, cf, dms, pm, pmf, dm, dmf, float(s_pk),
                       s_w / two_pi, float(t_pk), t_w / two_pi, disk, mr, ss,
                       "partial fractions" if resp.modal else "direct solves")


# --------------------------------------------------------------------- multivariable margins

def mu_diag(M: np.ndarray) -> float:
    """Upper bound of μ for a diagonal complex perturbation: min_D σ̄(D M D⁻¹) (exact for
    n ≤ 3). n = 2 in closed form: ‖DMD⁻¹‖_F² is least at d² = |m₁₂|/|m₂₁| and σ̄² =
    (F² + √(F⁴ − 4|det M|²))/2 grows with F² at fixed det."""
    from scipy.optimize import minimize
    n = M.shape[0]
    if n == 1:
        return float(abs(M[0, 0]))
    if n == 2:
        F2 = (abs(M[0, 0]) ** 2 + abs(M[1, 1]) ** 2 + 2 * abs(M[0, 1]) * abs(M[1, 0]))
        det2 = abs(M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]) ** 2
        return float(math.sqrt(0.5 * (F2 + math.sqrt(max(F2 * F2 - 4 * det2, 0.0)))))

    def f(x):
        d = np.exp(np.concatenate([[0.0], x]))
        return np.linalg.norm(d[:, None] * M / d[None, :], 2)

    res = minimize(f, np.zeros(n - 1), method="Nelder-Mead",
                   options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": 4000})
    return float(min(res.fun, f(np.zeros(n - 1))))


@dataclass(frozen=True)
class MultiLoopDisk:
    """Multivariable disk margin at the measurements (simultaneous independent perturbations
    of every channel): α, skew σ, frequency of the worst case (Hz), the guaranteed gain range
    and phase per channel."""

    disk: DiskMargin
    n_channels: int
    exact: bool


def multiloop_disk_margin(P, K, *, sigma: float = 0.0) -> MultiLoopDisk:
    """Disk margin of the loops broken at every output of P at once (L_o = −P K, K a
    positive-feedback law u = K y). ``P``, ``K``: state spaces (A, B, C, D), python-control
    systems or :class:`lti.SS`, same sample time. Refuses an unstable closed loop."""
    from scipy.optimize import minimize_scalar
    sigma = v.in_range("sigma", sigma, -1e6, 1e6)
    P = lti.balanced(lti.as_ss("plant", P))
    K = lti.balanced(lti.as_ss("controller", K, P.dt))
    _check_pair(P, K)
    Acl = lti.feedback_A(P, K)
    ok, mr = lti.stable(Acl, P.dt)
    if not ok:
        raise InputError(f"controller: the closed loop is not stable (largest Re λ = "
                         f"{mr:.6g} 1/s); margins are defined for a stable closed loop only")
    ny = P.shape[0]
    c = (sigma - 1) / 2
    eye = np.eye(ny)

    def mu_at(w):
        w = np.atleast_1d(w)
        Lo = -np.einsum("fij,fjk->fik", lti.freqresp(P, w), lti.freqresp(K, w))
        Mo = np.linalg.inv(eye + Lo) + c * eye
        return np.array([mu_diag(m) for m in Mo])

    w = lr.grid_from([lr.poles(Acl, P.dt), P.poles_s(), K.poles_s()], P.dt)
    mus = mu_at(w)
    i = int(np.argmax(mus))
    best = (float(mus[i]), float(w[i]))
    if 0 < i < w.size - 1:
        r = minimize_scalar(lambda lw: -mu_at(math.exp(lw))[0],
                            bounds=(math.log(w[i - 1]), math.log(w[i + 1])), method="bounded",
                            options={"xatol": 1e-13})
        if -r.fun > best[0]:
            best = (float(-r.fun), math.exp(r.x))
    for we in ([1e-300] if lti.dc_value(P) is not None else []):
        val = mu_at(we)[0]
        if val > best[0]:
            best = (val, 0.0)
    alpha = 1.0 / best[0] if best[0] > 0 else math.inf
    return MultiLoopDisk(disk_from_alpha(alpha, sigma, best[1] / (2 * math.pi)), ny, ny <= 3)


def _check_pair(P: lti.SS, K: lti.SS) -> None:
    if K.shape != (P.shape[1], P.shape[0]):
        raise InputError(f"controller: expected {P.shape[1]} output(s) and {P.shape[0]} "
                         f"input(s) (the plant's), got {K.shape[0]} and {K.shape[1]}")
    if (P.dt is None) != (K.dt is None) or (P.dt is not None and P.dt != K.dt):
        raise InputError(f"controller: sample time {K.dt} differs from the plant's {P.dt}")


def loop_at_a_time(P, K) -> list[LoopMargins]:
    """Margins of each measurement loop broken alone, the others closed (``P``, ``K`` as
    :func:`multiloop_disk_margin`)."""
    P = lti.balanced(lti.as_ss("plant", P))
    K = lti.balanced(lti.as_ss("controller", K, P.dt))
    _check_pair(P, K)
    ok, mr = lti.stable(lti.feedback_A(P, K), P.dt)
    if not ok:
        raise InputError(f"controller: the closed loop is not stable (largest Re λ = "
                         f"{mr:.6g} 1/s); margins are defined for a stable closed loop only")
    return [loop_margins(lti.loop_at_output(P, K, i), name=f"output {i}")
            for i in range(P.shape[0])]


# ------------------------------------------------------------ a rotordyn plant and controller

@dataclass(frozen=True)
class Margins:
    """Margins of a rotordyn closed loop: ``input`` at the valve command (the single
    actuator: every measurement fed back through K), and when more than one measurement is
    fed back ``outputs`` (loop-at-a-time, one per measurement) and ``multiloop`` (the
    multivariable disk margin at the measurements, σ = 0)."""

    input: LoopMargins
    outputs: tuple = ()
    multiloop: MultiLoopDisk | None = None

    def to_frame(self):
        """One row per margin: loop, kind, value, unit, frequency_hz."""
        import pandas as pd

        rows = self.input.rows()
        for m in self.outputs:
            rows += m.rows()
        if self.multiloop is not None:
            d = self.multiloop.disk
            rows += [{"loop": "outputs (multivariable)", "kind": k, "value": x, "unit": u,
                      "frequency_hz": d.frequency_hz}
                     for k, x, u in (("disk_margin", d.alpha, ""),
                                     ("disk_gain_lo", d.gain_lo, "factor"),
                                     ("disk_gain_hi", d.gain_hi, "factor"),
                                     ("disk_phase", d.phase_deg, "deg"))]
        return pd.DataFrame(rows)

    def summary(self) -> dict:
        out = self.input.summary()
        if self.outputs:
            out["loop_at_a_time"] = [m.summary() for m in self.outputs]
        if self.multiloop is not None:
            d = self.multiloop.disk
            out["multiloop_disk_margin"] = d.alpha
            out["multiloop_disk_margin_hz"] = d.frequency_hz
            out["multiloop_disk_gain_db"] = list(d.gain_db)
            out["multiloop_disk_phase_deg"] = d.phase_deg
        return out


def plant_ss(p, dt=None, delay_s: float = 0.0) -> lti.SS:
    """A :class:`~rotordyn.control.plant.Plant` (command → measurements, a reduced plant's
    feedthrough kept) as an :class:`lti.SS`; with ``dt`` discretised exactly under a
    zero-order hold (no feedthrough allowed then), and with a computation delay
    ``delay_s`` ∈ (0, dt] the exact sampled plant of :mod:`rotordyn.control.delay` (the
    previous command u[k−1] as an extra state)."""
    from rotordyn.control.delay import delayed_zoh

    Dr = p.info.get("feedthrough")
    D = np.asarray(Dr, float) if Dr is not None else np.zeros((p.C.shape[0], 1))
    if dt is None:
        return lti.SS(p.A, p.B, p.C, D)
    if np.any(D):
        raise InputError("controller.sample_time_s: a discrete controller on a reduced plant "
                         "with feedthrough is not supported; use the full plant")
    n = p.A.shape[0]
    Phi, G0, G1 = delayed_zoh(p.A, p.B, dt, delay_s)
    if delay_s == 0:
        return lti.SS(Phi, G0, p.C, D, dt)
    A = np.block([[Phi, G1], [np.zeros((1, n + 1))]])
    B = np.vstack([G0, [[1.0]]])
    return lti.SS(A, B, np.hstack([p.C, np.zeros((p.C.shape[0], 1))]), D, dt)


def controller_ss(k) -> lti.SS:
    return lti.SS(k.A, k.B, k.C, k.D, k.sample_time_s)


def margins(p, k, *, computation_delay_s: float | None = None,
            pade_order: int = 6) -> Margins:
    """Every margin of plant ``p`` (:func:`rotordyn.control.plant.plant`, full or reduced)
    closed by controller ``k`` (continuous, or discrete: sampled-data loop with the plant
    discretised exactly under a zero-order hold, frequencies up to Nyquist). A computation
    delay (:mod:`rotordyn.control.delay`; None: the law's own ``computation_delay_s``): a
    continuous law through its Padé approximant of ``pade_order``, a discrete law exactly
    (delay ≤ its sample time). InputError naming
    ``controller`` when the closed loop is not stable."""
    from rotordyn.control.delay import check_order, computation_delay_for, with_pade_delay
    from rotordyn.control.plant import paired

    paired(p, k)
    tau = computation_delay_for(k, computation_delay_s)
    check_order(pade_order)
    if tau and not k.discrete:
        k = with_pade_delay(k, tau, pade_order)
    P = plant_ss(p, k.sample_time_s, tau if k.discrete else 0.0)
    K = controller_ss(k)
    Acl = lti.feedback_A(lti.balanced(P), lti.balanced(K))
    ok, mr = lti.stable(Acl, P.dt)
    if not ok:
        raise InputError(f"controller: the closed loop of {k.name!r} is not stable (largest "
                         f"Re λ = {mr:.6g} 1/s); margins are defined for a stable closed loop "
                         f"only")
    inp = loop_margins(lti.loop_at_input(P, K), name="input (valve command)")
    if P.shape[0] == 1:
        return Margins(inp)
    names = [str(x) for x in p.output_names]
    outs = tuple(replace_name(m, f"output {names[i]}")
                 for i, m in enumerate(loop_at_a_time(P, K)))
    return Margins(inp, outs, multiloop_disk_margin(P, K))


def replace_name(m: LoopMargins, name: str) -> LoopMargins:
    from dataclasses import replace

    return replace(m, name=name)
