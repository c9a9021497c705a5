"""Two sections of the report that an API 684 lateral analysis carries beside the Campbell
diagram and the unbalance response:

* the mode shape at each critical speed (the system's eigenvector at that speed whose damped
  frequency is the crossing's, forward whirl, drawn as whirl orbits along the rotor);
* each bearing's stiffness and damping coefficients kxx … cyy over the analysed speeds
  (:func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients`, pads and sleeve
  condensed at the synchronous whirl frequency), as a table and a figure.

Both return their figures, so the HTML report inlines them and the CLI's output directory
gets them as PNG files."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotordyn import analysis
from rotordyn.analysis.bearing_coefficients import bearing_coefficients

MAX_CRITICAL_SHAPES = 6  # the lowest forward critical speeds drawn (a report's usual few)


@dataclass
class CriticalShape:
    """The mode at critical speed ``speed_hz``: its damped frequency (Hz), whirl, log
    decrement and the 3-D figure (None when no matching mode was found: ``why`` says why)."""

    speed_hz: float
    freq_hz: float
    whirl: str
    log_dec: float
    figure: object
    why: str = ""


def _pick(freqs, whirl, kind, target_hz) -> int | None:
    """The forward rotor mode nearest ``target_hz`` (None if there is none)."""
    ok = [j for j in range(len(freqs)) if whirl[j] == "forward" and freqs[j] > 0
          and (kind is None or kind[j] == "rotor")]
    if not ok:
        return None
    return min(ok, key=lambda j: abs(freqs[j] - target_hz))


def critical_mode_shapes(system, critical_speeds_hz, chamber_pressure_pa: float,
                         config_ay_m, *, max_n: int = MAX_CRITICAL_SHAPES,
                         progress=None) -> list[CriticalShape]:
    """The mode shape at each of the first ``max_n`` forward critical speeds (Hz): with bearing
    elements the system's stability eigenvectors at that speed (equilibrium there), else the
    rotor's modes on its supports; the mode picked is the forward rotor mode whose damped
    frequency is nearest the crossing's (1×: the speed itself)."""
    out: list[CriticalShape] = []
    crit = [float(x) for x in critical_speeds_hz][:max_n]
    for n, nc in enumerate(crit):
        try:
            if system.bearings:
                r = analysis.stability(system, nc, chamber_pressure_pa, config_ay_m)
                ok = r.status in ("ok", "contact") and len(r.eigenvalues) > 0
                kind = r.kind
            else:
                r = analysis.modes(system, nc, reduction="none", n_modes=16)
                ok, kind = r.status == "ok", None
        except Exception as exc:  # noqa: BLE001 - a failed point is reported, not raised
            out.append(CriticalShape(nc, np.nan, "", np.nan, None, f"{exc}"))
            continue
        j = _pick(r.frequencies_hz, r.whirl, kind, nc) if ok else None
        if j is None:
            why = (f"no forward rotor mode at {nc:.4g} Hz" if ok
                   else f"{r.status}: {r.message}")
            out.append(CriticalShape(nc, np.nan, "", np.nan, None, why))
            continue
        ax = r.plot(j, system=system)
        ld = float(r.log_dec[j])
        ld = 0.0 if abs(ld) < 1e-6 else ld
        ax.set_title(f"critical speed {n + 1}: {nc:.4g} Hz ({60 * nc:.0f} rpm)\nmode "
                     f"{r.frequencies_hz[j]:.4g} Hz, {r.whirl[j]}, δ = {ld:.3g}")
        out.append(CriticalShape(nc, float(r.frequencies_hz[j]), str(r.whirl[j]), ld,
                                 ax.figure))
        if progress is not None:
            progress(n + 1, len(crit))
    return out


def coefficient_speeds(speeds_hz, n: int = 11) -> np.ndarray:
    """``n`` speeds spread over the analysed range (the table's rows per bearing)."""
    sp = np.asarray(speeds_hz, dtype=float)
    return np.linspace(float(sp.min()), float(sp.max()), min(n, sp.size))


def bearing_coefficient_frame(system, speeds_hz, chamber_pressure_pa: float, config_ay_m,
                              progress=None):
    """The bearings' coefficients at :func:`coefficient_speeds` (an empty frame without bearing
    elements)."""
    return bearing_coefficients(system, coefficient_speeds(speeds_hz), chamber_pressure_pa,
                                config_ay_m, progress=progress)


def coefficient_rows(frame) -> list[tuple]:
    """Table rows: bearing, speed (Hz), kxx … kyy (MN/m), cxx … cyy (kN·s/m), status."""
    rows = []
    for r in frame.itertuples(index=False):
        d = r._asdict()
        ks = [d[f"k{p}_n_per_m"] / 1e6 for p in ("xx", "xy", "yx", "yy")]
        cs = [d[f"c{p}_n_s_per_m"] / 1e3 for p in ("xx", "xy", "yx", "yy")]
        rows.append((d["bearing"], f"{d['speed_hz']:.4g}",
                     *(f"{x:.4g}" if np.isfinite(x) else "n/a" for x in ks + cs), d["status"]))
    return rows


COEFFICIENT_HEADER = ("bearing", "speed (Hz)", "kxx (MN/m)", "kxy (MN/m)", "kyx (MN/m)",
                      "kyy (MN/m)", "cxx (kN·s/m)", "cxy (kN·s/m)", "cyx (kN·s/m)",
                      "cyy (kN·s/m)", "status")

__all__ = ["COEFFICIENT_HEADER", "CriticalShape", "MAX_CRITICAL_SHAPES",
           "bearing_coefficient_frame", "coefficient_rows", "coefficient_speeds",
           "critical_mode_shapes"]
