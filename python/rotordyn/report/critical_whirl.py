"""The whirl of a critical speed and the mode that matches it (docs/api-criteria.md, "Backward
resonances").

An unbalance is a force rotating forward with the shaft. On isotropic supports it drives only
forward whirl; on anisotropic ones (a table bearing with kxx ≠ kyy, tilting pads loaded
between pads, a soft pedestal in one direction) every mode is an ellipse, and a backward mode
crossing 1× is excited too: the response orbit at its peak whirls *against* the rotation. The
report used to know forward (and planar) modes only, so the mode it drew and named for such a
peak was the nearest forward one (an overhung fan on table bearings: a backward resonance at
27.9 Hz, ζ ≈ 0.03, drawn as the forward mode at 40.9 Hz; tests/test_report_backward_whirl.py).

Here a response peak takes the whirl of the circular component of the response that resonates
at its **responding station** (the output station with the largest orbit at the peak speed;
:func:`response_whirl`): backward when the backward component B rises across the peak clearly
more than the forward one F. The mode drawn for a backward peak is the rotor mode nearest the
speed whose own orbit *at that station* whirls backward (whirl index (|F|² − |B|²)/(|F|² +
|B|²) of the eigenvector's orbit there below −:data:`rotordyn._common.whirl.WHIRL_PLANAR_TOL`;
a mode's whirl label sums over every station and can differ from one station's); it is named
"elliptical backward" when that orbit's |index| < :data:`ELLIPTICAL_INDEX` (anisotropic
supports). A forward critical keeps the rule it had (the forward or planar rotor mode nearest
the speed)."""

from __future__ import annotations

import numpy as np

from rotordyn._common.whirl import WHIRL_PLANAR_TOL, driven_by_unbalance, whirl_index

ELLIPTICAL_INDEX = 0.9
"""A backward or forward orbit whose whirl index is below this in magnitude (minor/major axis
ratio below about 0.63) is named elliptical ("elliptical backward")."""

BACKWARD_NOTE = (
    "A backward critical speed (at the responding station the backward circular component of "
    "the response is the one that resonates; an unbalance drives a backward mode only through "
    "anisotropic supports, kxx ≠ kyy) is "
    "checked as a forward one is: its AF from the half-power band of its response peak (not "
    "resolved where that band runs into the forward response's rise, as for a weakly excited "
    "backward mode: then its margin is not judged; the mode's δ in the table gives its modal "
    "AF ≈ π/δ) and its "
    "separation margin from the operating speeds by API 684's rule (API 617 and API 684 do not "
    "distinguish the whirl of a resonance excited by unbalance), and its mode shape is the "
    "backward rotor mode nearest the speed. The stability screen (δ > 0.1) looks at forward "
    "modes only, as before.")


BACKWARD_RISE = 1.25
"""A peak is a backward resonance when, at its responding station, the backward circular
component of the response rises across the peak more than this factor above the forward
one's rise (:func:`response_whirl`). On a forward resonance of an elliptical mode both
components rise alike (the mode's fixed ellipse), so the factor keeps a tie forward."""


def _rise(a: np.ndarray, s: np.ndarray, i: int, rtol: float) -> float:
    """a[i] over the larger of ``a`` at the ends of the window N(1 ± rtol) about speed i."""
    lo = int(np.searchsorted(s, s[i] * (1 - rtol), side="left"))
    hi = int(np.searchsorted(s, s[i] * (1 + rtol), side="right")) - 1
    ref = max(a[min(lo, i)], a[max(hi, i)])
    return float(a[i] / ref) if ref > 0 else 1.0


def response_whirl(unbalance, stations, speed_hz: float, rtol: float = 0.05
                   ) -> tuple[str, float, int]:
    """(label, rise ratio, station) of a response peak at ``speed_hz``: at the responding
    station — of ``stations`` the one with the largest semi-major axis at the computed speed
    nearest ``speed_hz`` — the forward and backward circular components F = |x + iy|/2,
    B = |x̄ + iȳ|/2 of the response each rise across the peak by a[N]/max(a[N(1 − rtol)],
    a[N(1 + rtol)]); the peak is "backward" when B's rise exceeds F's by
    :data:`BACKWARD_RISE` and B itself peaks (rise > 1), else "forward". The orbit itself
    need not run backward at a backward resonance: the forward response of the other modes
    can still be larger there (the overhung fan at 27.7 Hz: F = 0.18 µm, B = 0.11 µm at
    station 1, but B rises 1.8× across the peak and F falls). Returns B's rise over F's."""
    s = np.asarray(unbalance.speeds_hz, dtype=float)
    i = int(np.argmin(np.abs(s - speed_hz)))
    cols = [list(unbalance.stations).index(int(st)) for st in stations]
    major = np.asarray(unbalance.major_m)[i, cols]
    k = cols[int(np.argmax(major))]
    rf = _rise(np.asarray(unbalance.forward_m)[:, k], s, i, rtol)
    rb = _rise(np.asarray(unbalance.backward_m)[:, k], s, i, rtol)
    ratio = rb / rf if rf > 0 else np.inf
    label = "backward" if rb > 1.0 and ratio > BACKWARD_RISE else "forward"
    return label, float(ratio), int(unbalance.stations[k])


def whirl_text(label: str, index: float) -> str:
    """A mode's whirl name from its label and its orbit's whirl index at the responding
    station: "elliptical backward" / "elliptical forward" when |index| <
    :data:`ELLIPTICAL_INDEX`; "" when unknown."""
    if not label:
        return ""
    if label != "planar" and np.isfinite(index) and abs(index) < ELLIPTICAL_INDEX:
        return f"elliptical {label}"
    return label


def matches(label: str, whirl) -> np.ndarray:
    """Where mode whirls ``whirl`` (labels or 1/0/−1 codes) suit a critical of whirl
    ``label``: backward ones for a backward critical, those an unbalance drives (forward and
    planar, :func:`driven_by_unbalance`) otherwise."""
    w = np.asarray(whirl)
    if label == "backward":
        return (w == -1) if w.dtype.kind in "biuf" else (w == "backward")
    return driven_by_unbalance(w)


def mode_in_band(campbell, group: dict, label: str = "forward") -> bool:
    """Whether a rotor mode of ``campbell`` of the peak's whirl ``label`` (:func:`matches`) at
    the speed nearest the peak has its damped frequency inside the peak's half-power band (an
    open side: unbounded there)."""
    i = int(np.argmin(np.abs(campbell.speeds_hz - group["peak_hz"])))
    f = campbell.frequencies_hz[i]
    ok = (campbell.rotor_mask()[i] & matches(label, campbell.whirl[i]) & (f > 0)
          & np.isfinite(f))
    lo, hi = group["band_hz"]
    lo = lo if np.isfinite(lo) else -np.inf
    hi = hi if np.isfinite(hi) else np.inf
    return bool(np.any(ok & (f >= lo) & (f <= hi)))


def station_whirl(r, system, station: int) -> np.ndarray:
    """(n_modes,) whirl index of each mode of ``r`` (StabilityResult or ModesResult) from its
    orbit at ``station`` alone."""
    shapes = getattr(r, "shapes", None)
    if shapes is None:
        shapes = r.rotor_shapes
    node = int(system.rotor.station_nodes()[int(station)])
    x, y = shapes[node, 0, :][None, :], shapes[node, 1, :][None, :]
    return np.asarray(whirl_index(x, y, axis=0), dtype=float)  # one station: no sum


def pick_backward(r, kind, system, station: int, target_hz: float) -> int | None:
    """The rotor mode (damped frequency > 0) nearest ``target_hz`` whose orbit at ``station``
    whirls backward (index below −:data:`WHIRL_PLANAR_TOL`); None if there is none."""
    idx = station_whirl(r, system, station)
    f = r.frequencies_hz
    ok = [j for j in range(len(f)) if f[j] > 0 and idx[j] <= -WHIRL_PLANAR_TOL
          and (kind is None or kind[j] == "rotor")]
    if not ok:
        return None
    return min(ok, key=lambda j: abs(f[j] - target_hz))


def backward_crossings(campbell) -> tuple[np.ndarray, np.ndarray]:
    """The backward 1× crossings of the damped Campbell diagram (Hz) and the crossing mode's
    δ there (they are critical speeds only where the response peaks: anisotropic supports)."""
    if campbell is None:
        return np.empty(0), np.empty(0)
    cs = campbell.critical_speeds(whirl="backward")
    return cs["speed_hz"].to_numpy(dtype=float), cs["log_dec"].to_numpy(dtype=float)


__all__ = ["BACKWARD_NOTE", "BACKWARD_RISE", "ELLIPTICAL_INDEX", "backward_crossings", "matches",
           "mode_in_band", "pick_backward", "response_whirl", "station_whirl", "whirl_text"]
