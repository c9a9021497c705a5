"""Robust stability and performance of a fixed feedback law over a grid of operating points
and model uncertainties: the closed loop at one point (:func:`closed_loop_point`) and the rows
of a grid with their worst cases (:class:`RobustResult`). The grid itself runs as the
``robust`` analysis of the sweep machinery, in one call: :func:`rotordyn.sweep.robust.robust`
(the sweep room sits above this one, docs/architecture.md).

The law K (a :class:`~rotordyn.control.Controller`) stays fixed; at every point — speed, p_c,
a_y and any numeric model field (``bearings.active.clearance_m``,
``bearings.active.viscosity_pa_s``, ...) — the plant is re-linearised about that point's own
equilibrium (solved cold, ``warm_start=False``, or from a given ``r0``; never from whatever
this thread solved before):

* stability: the closed-loop eigenvalues λ of [A + B D_k C, B C_k; B_k C, A_k] (a discrete law:
  the exact sampled-data loop, λ = ln z / T; a computation delay as in
  :func:`rotordyn.control.closedloop.closed_loop`), the spectral abscissa max Re λ and the least
  damping ratio min ζ, ζ = −Re λ / |λ|;
* performance, at a stable point: the margins of the loop broken at the valve command,
  L = −K G (:func:`rotordyn.control.margins.loop_margins`, located exactly): gain margins below
  and above 1, phase and delay margins, balanced disk margin, peak |S| = max_ω |1/(1 + L)|
  and its zone after ISO 14839-3.

Sensitivity zones after ISO 14839-3:2006 (Mechanical vibration — Vibration of rotating
machinery equipped with active magnetic bearings — Part 3: Evaluation of stability margin):
zone A ≤ 3 (9.5 dB), B ≤ 4 (12 dB), C ≤ 5 (14 dB), D above. The limits are those of the
standard's evaluation table as quoted in the AMB literature; we did not hold the standard's
text. ROSS (petrobras/ross, ``Rotor.run_amb_sensitivity`` and ``SensitivityResults``, read at
commit 631a249) computes the peak sensitivity "according to ISO 14839-3" per bearing axis
(``max_abs_sensitivities``) but implements no zone limits, so there was nothing there to check
these numbers against.

Not built: the structured singular value μ over the physical parameters. SLICOT's AB13MD
(slycot, the optional ``hinf`` extra) bounds μ of a given M(iω) for a block structure, but
rotordyn has no linear fractional representation of the film coefficients in speed,
clearance or viscosity (the plant is re-linearised numerically at each point), so there is no
M to give it; python-control has no μ. The multivariable disk margin at the measurements
(:func:`rotordyn.control.margins.multiloop_disk_margin`) is the μ of a diagonal complex
perturbation of the measurement channels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rotordyn.errors import InputError

# zone upper limits of the peak sensitivity (ISO 14839-3, module docstring)
ISO_ZONES = (("A", 3.0), ("B", 4.0), ("C", 5.0))
ZONES = ["A", "B", "C", "D"]
ACTUATOR_KEYS = ("order", "time_constant_s", "natural_frequency_hz", "damping", "p_min_pa",
                 "p_max_pa", "rate_limit_pa_s")


def iso_zone(peak_sensitivity: float) -> str | None:
    """Zone A/B/C/D of a peak sensitivity (a number ≥ 1 for a stable loop; None if NaN)."""
    if not math.isfinite(peak_sensitivity):
        return None if math.isnan(peak_sensitivity) else "D"
    for zone, hi in ISO_ZONES:
        if peak_sensitivity <= hi:
            return zone
    return "D"


def build_controller(d: dict):
    """The :class:`~rotordyn.control.Controller` of an ``options.controller`` table."""
    from rotordyn.operation.controller import Controller

    D = np.asarray(d["D"], float).reshape(1, -1) if d["D"] else np.zeros((1, 0))
    ny = D.shape[1]
    nk = len(d["A"])
    A = np.asarray(d["A"], float).reshape(nk, nk) if nk else np.zeros((0, 0))
    B = np.asarray(d["B"], float).reshape(nk, ny) if nk else np.zeros((0, ny))
    C = np.asarray(d["C"], float).reshape(1, nk) if nk else np.zeros((1, 0))
    return Controller(A, B, C, D, [tuple(m) for m in d["measurements"]],
                      sample_time_s=d.get("sample_time_s"),
                      computation_delay_s=d.get("computation_delay_s") or 0.0,
                      name=d.get("name", "controller"))


def controller_table(k) -> dict:
    """A Controller as an ``options.controller`` table (plain floats: TOML/JSON-ready)."""
    d = {"A": k.A.tolist(), "B": k.B.tolist(), "C": k.C.tolist(), "D": k.D.tolist(),
         "measurements": [list(m) for m in k.measurements], "name": k.name}
    if k.sample_time_s is not None:
        d["sample_time_s"] = float(k.sample_time_s)
    if k.computation_delay_s:
        d["computation_delay_s"] = float(k.computation_delay_s)
    return d


def actuator_table(a) -> dict:
    return {k: (float(getattr(a, k)) if k != "order" else int(a.order)) for k in ACTUATOR_KEYS}


MARGIN_COLS = ("gain_margin_lower", "gain_margin_lower_hz", "gain_margin_upper",
                "gain_margin_upper_hz", "phase_margin_deg", "phase_margin_hz",
                "delay_margin_s", "delay_margin_hz", "peak_sensitivity",
                "peak_sensitivity_hz", "disk_margin", "disk_margin_hz")


def closed_loop_point(system, k, speed_hz, pc, ay, *, actuator=None, equilibrium=None,
                      with_margins=True, pade_order=6):
    """(plant, closed-loop eigenvalues λ (1/s), loop margins or None, message) of the law
    ``k`` at one operating point (module docstring). Raises what the plant raises (a
    ConvergenceError when the equilibrium fails)."""
    from rotordyn.control import lti
    from rotordyn.control.closedloop import closed_loop
    from rotordyn.control.delay import with_pade_delay
    from rotordyn.control.margins import controller_ss, loop_margins, plant_ss
    from rotordyn.control.plant import plant

    p = plant(system, speed_hz, pc, ay, measurements=k.measurements, actuator=actuator,
              equilibrium={"warm_start": False, **(equilibrium or {})})
    cl = closed_loop(p, k, freqs_hz=[1.0, 2.0], pade_order=pade_order, with_margins=False)
    lam = cl.eigenvalues
    if not np.all(np.isfinite(lam)):
        raise ArithmeticError("non-finite closed-loop eigenvalues")
    if not (with_margins and lam.real.max() < 0):
        from rotordyn.results.modes import point_stable

        msg = "margins not computed" if lam.real.max() < 0 else \
            (("marginally stable" if point_stable(lam) else "unstable")
             + f" closed loop (largest Re λ = {lam.real.max():.6g} 1/s): no margins")
        return p, lam, None, msg
    tau = k.computation_delay_s
    kk = with_pade_delay(k, tau, pade_order) if tau and not k.discrete else k
    P = plant_ss(p, kk.sample_time_s, tau if kk.discrete else 0.0)
    m = loop_margins(lti.loop_at_input(P, controller_ss(kk)), name="input (valve command)")
    return p, lam, m, ""


def margin_columns(m) -> dict:
    """The margin columns of a row from :class:`~rotordyn.control.margins.LoopMargins`."""
    if m is None:
        return {}
    d = m.disk
    ps = float(m.peak_sensitivity)
    return {"gain_margin_lower": m.gain_margin_lower,
            "gain_margin_lower_hz": m.gain_margin_lower_hz,
            "gain_margin_upper": m.gain_margin_upper,
            "gain_margin_upper_hz": m.gain_margin_upper_hz,
            "phase_margin_deg": m.phase_margin_deg, "phase_margin_hz": m.phase_margin_hz,
            "delay_margin_s": m.delay_margin_s, "delay_margin_hz": m.delay_margin_hz,
            "peak_sensitivity": ps, "peak_sensitivity_hz": m.peak_sensitivity_hz,
            "peak_sensitivity_db": 20 * math.log10(ps) if ps > 0 else math.nan,
            "disk_margin": d.alpha, "disk_margin_hz": d.frequency_hz,
            "disk_gain_db": d.gain_db[1], "disk_phase_deg": d.phase_deg,
            "iso_zone": iso_zone(ps)}


def eigen_columns(lam) -> dict:
    from rotordyn.results.modes import damping_ratio, point_stable

    z = damping_ratio(lam)
    i, j = int(np.argmax(lam.real)), int(np.argmin(z))
    return {"point_stable": point_stable(lam),  # the stability rows' rule
            "max_real_1_per_s": float(lam.real[i]),
            "max_real_freq_hz": float(abs(lam.imag[i]) / (2 * np.pi)),
            "min_damping_ratio": float(z[j]),
            "min_damping_freq_hz": float(abs(lam.imag[j]) / (2 * np.pi))}




# worst case of each column: "max" or "min" over the points that have it
WORST = {"max_real_1_per_s": "max", "min_damping_ratio": "min",
         "gain_margin_lower": "max", "gain_margin_upper": "min", "phase_margin_deg": "min_abs",
         "delay_margin_s": "min", "disk_margin": "min", "peak_sensitivity": "max"}


@dataclass(frozen=True)
class RobustResult:
    """Rows of a robust sweep (one per grid point, in ``point_id`` order): the axes, status,
    ``point_stable`` (null without a verdict), max Re λ (1/s), min ζ, the margins and the ISO
    14839-3 zone of the peak sensitivity. :meth:`worst` gives each quantity's worst case with
    its point."""

    frame: object
    axes: dict
    controller_name: str = "controller"
    out: Path | None = None

    def to_frame(self):
        return self.frame.copy()

    @property
    def verdicts(self):
        """The rows that have a closed-loop verdict (equilibrium converged)."""
        return self.frame[self.frame["point_stable"].notna()]

    @property
    def failed(self):
        """The rows without a verdict (status other than ok), with their messages."""
        return self.frame[self.frame["point_stable"].isna()]

    @property
    def all_stable(self) -> bool:
        """Every point has a verdict and it is stable."""
        return bool(len(self.failed) == 0 and self.frame["point_stable"].astype(bool).all())

    def worst(self) -> dict:
        """{quantity: {"value", "point_id", axis values...}} — max Re λ and peak |S| at their
        largest, gain_margin_lower at its largest, the phase margin at its smallest magnitude
        (a stable loop of an unstable plant can have a negative one), the others at their
        smallest, over the points that have the quantity (margins: the stable points)."""
        out = {}
        for col, how in WORST.items():
            s = self.frame[col].astype(float)
            ok = s.notna()
            if not ok.any():
                continue
            i = s[ok].idxmax() if how == "max" else (s[ok].abs() if how == "min_abs"
                                                     else s[ok]).idxmin()
            row = self.frame.loc[i]
            out[col] = {"value": float(row[col]), "point_id": int(row["point_id"]),
                        **{a: float(row[a]) for a in self.axes}}
        return out

    def summary(self) -> dict:
        """Counts (points, with a verdict, stable, unstable, failed), the worst zone and
        :meth:`worst`."""
        f = self.frame
        have = f["point_stable"].notna()
        st = f.loc[have, "point_stable"].astype(bool)
        zones = f["iso_zone"].dropna().astype(str)
        return {"controller": self.controller_name, "points": int(len(f)),
                "with_verdict": int(have.sum()), "stable": int(st.sum()),
                "unstable": int((~st).sum()), "failed": int((~have).sum()),
                "all_stable": self.all_stable,
                "worst_iso_zone": max(zones) if len(zones) else None,
                "zones": {z: int((zones == z).sum()) for z in ZONES},
                "worst": self.worst()}

    def __repr__(self):
        s = self.summary()
        w = s["worst"].get("max_real_1_per_s", {})
        return (f"RobustResult({self.controller_name}: {s['points']} points, {s['stable']} "
                f"stable, {s['unstable']} unstable, {s['failed']} without verdict; worst max "
                f"Re λ {w.get('value', math.nan):.4g} 1/s at point {w.get('point_id')}; worst "
                f"zone {s['worst_iso_zone']})")

    def plot(self, value: str = "max_real_1_per_s", x: str | None = None,
             y: str | None = None, ax=None, **fixed):
        """``value`` over one axis (a line per value of a second varying axis) or a map over
        two (``x``, ``y``; ``fixed`` axis=value picks the slice of the others); failed points
        are gaps, the worst point is marked. Returns the matplotlib Figure."""
        import matplotlib.pyplot as plt

        if value not in self.frame.columns or value in ("status", "message", "iso_zone"):
            raise InputError(f"value: expected a numeric column of the rows, got {value!r}")
        varying = [a for a, vals in self.axes.items() if len(vals) > 1]
        x = x or (varying[-1] if varying else next(iter(self.axes)))
        for a in [x] + ([y] if y else []) + list(fixed):
            if a not in self.axes:
                raise InputError(f"x/y/fixed: {a!r} is not an axis of this sweep "
                                 f"(axes: {', '.join(self.axes)})")
        f = self.frame
        for a, val in fixed.items():
            f = f[np.isclose(f[a].astype(float), float(val), rtol=1e-12, atol=0)]
        vals = f[value].astype(float)
        fig = ax.figure if ax is not None else plt.figure(figsize=(7, 4.5))
        ax = ax or fig.add_subplot(111)
        if y:
            piv = f.assign(_v=vals).pivot_table(index=y, columns=x, values="_v",
                                                aggfunc="first", dropna=False)
            m = ax.pcolormesh(piv.columns.values, piv.index.values, piv.values,
                              shading="nearest")
            fig.colorbar(m, ax=ax, label=value)
            ax.set_ylabel(y)
        else:
            others = [a for a in varying if a != x]
            groups = f.groupby(others) if others else [((), f)]
            for key, g in groups:
                lab = ", ".join(f"{a}={k:g}" for a, k in zip(others, np.atleast_1d(key))) \
                    if others else None
                ax.plot(g[x].astype(float), g[value].astype(float), ".-", label=lab)
            if others and len(groups) <= 12:
                ax.legend(fontsize=7)
            ax.set_ylabel(value)
            if value == "max_real_1_per_s":
                ax.axhline(0.0, color="k", lw=0.6)
            if value == "peak_sensitivity":
                ax.set_yscale("log")
                for z, hi in ISO_ZONES:
                    ax.axhline(hi, color="0.6", lw=0.6, ls="--")
                    ax.text(ax.get_xlim()[1], hi, f" {z}/{chr(ord(z) + 1)}", fontsize=7,
                            va="center")
        ax.set_xlabel(x)
        ax.set_title(f"{self.controller_name}: {value}")
        return fig
