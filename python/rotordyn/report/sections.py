"""Sections of the report that an API 684 lateral analysis carries beside the Campbell
diagram and the unbalance response:

* the critical speeds, each with where it comes from (:func:`critical_speed_table`): a damped
  Campbell crossing of the 1× line by a forward rotor mode, a peak of the unbalance response
  (API 684's definition, and the only one a heavily damped mode that never reaches 1× has),
  or both;
* the mode shape at each critical speed (the system's eigenvector at that speed whose damped
  frequency is nearest the critical's — the crossing's or the peak's, i.e. the speed itself —
  of the critical's whirl: forward, or backward where the response orbit at the responding
  station whirls backward, :mod:`rotordyn.report.critical_whirl`; drawn as whirl orbits
  along the rotor);
* each bearing's stiffness and damping coefficients kxx … cyy over the analysed speeds
  (:func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients`, pads and sleeve
  condensed at the synchronous whirl frequency), as a table and a figure.

Both return their figures, so the HTML report inlines them and the CLI's output directory
gets them as PNG files."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn import analysis
from rotordyn._common.api import af_text
from rotordyn._common.whirl import driven_by_unbalance
from rotordyn.analysis.bearing_coefficients import bearing_coefficients
from rotordyn._common.api import RESONANT_LOG_DEC
from rotordyn.report.critical_whirl import (BACKWARD_NOTE, backward_crossings, mode_in_band,
                                            pick_backward, response_whirl, station_whirl,
                                            whirl_text)
from rotordyn.report.tables import (COEFFICIENT_HEADER, MISSING, _text_table, cell,
                                    coefficient_rows, tilt_coefficient_tables)

if TYPE_CHECKING:
    import pandas as pd

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
    source: str = ""  # where the critical speed comes from (critical_speed_table's source)


SOURCE_CAMPBELL = "damped Campbell crossing (1×, forward)"
SOURCE_CAMPBELL_BACKWARD = "damped Campbell crossing (1×, backward)"
SOURCE_PEAK = "unbalance response peak"
SOURCE_LEAST_DAMPED = ("no critical speed in range: the least damped forward mode at the "
                       "maximum continuous speed (with a resonance below the screening window, "
                       "else the first one with a resonance)")
UNSTABLE_NOTE = "(at a linearly unstable speed: not a steady orbit)"
MERGE_RTOL = 0.05  # a crossing and a peak (or peaks at two stations) this close are one critical
CRITICAL_COLUMNS = ("speed_hz", "source", "campbell_hz", "log_dec", "peak_hz", "stations",
                    "amplification_factor", "af_kind", "whirl", "whirl_station")


def _peak_groups(unbalance, rtol: float) -> list[dict]:
    """The resonance peaks of every output station, peaks within ``rtol`` of each other counted
    once (the largest one's speed, AF and half-power speeds, every station that shows it). A
    peak whose half-power band is wider than its speed (AF < 1: a wiggle on a rising curve, no
    resonance) is left out; one at a linearly unstable speed is kept and flagged."""
    rows = []
    stable = unbalance.stable
    for st in unbalance.stations:
        for r in unbalance.peaks(int(st)).to_dict("records"):
            if r["af_kind"] != "unresolved" and r["amplification_factor"] < 1.0:
                continue
            i = int(np.argmin(np.abs(unbalance.speeds_hz - r["critical_speed_hz"])))
            r["stable"] = bool(stable[i])
            rows.append(r)
    rows.sort(key=lambda r: r["critical_speed_hz"])
    groups: list[list[dict]] = []
    for r in rows:
        if groups and r["critical_speed_hz"] <= groups[-1][0]["critical_speed_hz"] * (1 + rtol):
            groups[-1].append(r)
        else:
            groups.append([r])
    out = []
    for g in groups:
        top = max(g, key=lambda r: r["peak_m"])
        out.append({"peak_hz": float(top["critical_speed_hz"]),
                    "band_hz": (float(top["n1_hz"]), float(top["n2_hz"])),
                    "stations": sorted({int(r["station"]) for r in g}),
                    "amplification_factor": float(top["amplification_factor"]),
                    "af_kind": str(top["af_kind"]), "stable": bool(top["stable"])})
    return out


def _near(crossing: float, group: dict, rtol: float) -> bool:
    """A Campbell crossing belongs to a response peak when it lies in the peak's half-power band
    or within ``rtol`` of the peak."""
    lo, hi = group["band_hz"]
    return (abs(crossing - group["peak_hz"]) <= rtol * group["peak_hz"]
            or (np.isfinite(lo) and np.isfinite(hi) and lo <= crossing <= hi))


def critical_speed_table(campbell, unbalance=None, *, rtol: float = MERGE_RTOL) -> pd.DataFrame:
    """The critical speeds an engineer reads off a lateral analysis, each once, with its source:
    the forward 1× crossings of the damped Campbell diagram (``campbell``:
    :class:`~rotordyn.results.campbell.CampbellResult`) and the resonance peaks of the unbalance
    response (``unbalance``: :class:`~rotordyn.results.unbalance.UnbalanceResult`, every output
    station; AF < 1 is no resonance and left out); a crossing inside a peak's half-power band
    or within ``rtol`` (relative) of it is the same critical. A peak without a crossing and
    without any damped forward mode of ``campbell`` inside its half-power band at that speed
    is two modes' responses interfering, not a resonance: it is left out and listed in
    ``attrs["not_resonances"]`` ((speed Hz, stations) pairs, :func:`not_resonance_note`).
    A crossing without a response peak whose mode has no resonance there (δ ≥ 2π, damping
    ratio ≥ 1/√2, the rule of :data:`~rotordyn.report.criteria.RESONANT_LOG_DEC`: a heavily
    damped bearing mode at low speed) is not a critical speed either: it is left out and listed
    in ``attrs["overdamped_crossings"]`` ((speed Hz, δ) pairs).

    Columns :data:`CRITICAL_COLUMNS`: ``speed_hz`` (Hz: the crossing's where there is one, else
    the peak's), ``source`` (:data:`SOURCE_CAMPBELL`, :data:`SOURCE_PEAK` or both joined by
    " + "; a peak at a linearly unstable speed says so), ``campbell_hz``, ``log_dec`` (the
    crossing mode's δ there: δ ≳ 1.3, AF ≈ π/δ < 2.5, is critically damped), ``peak_hz`` (NaN
    where absent), ``stations`` (the stations whose response peaks there, text),
    ``amplification_factor`` and ``af_kind`` of the largest peak, ``whirl`` and
    ``whirl_station``: a peak's whirl is that of the circular component of the response that
    resonates at the responding station (the output station with the largest orbit there;
    :func:`rotordyn.report.critical_whirl.response_whirl`), and a backward peak is matched with
    the backward 1× crossings (:data:`SOURCE_CAMPBELL_BACKWARD`) and backward modes; a
    crossing alone carries its mode's whirl (station −1)."""
    import pandas as pd
    cross, cross_ld, cross_wh = _crossings(campbell, whirls=True)
    back, back_ld = backward_crossings(campbell)
    peaks = _peak_groups(unbalance, rtol) if unbalance is not None else []
    used: set[int] = set()
    used_back: set[int] = set()
    rows, dropped = [], []
    for g in peaks:
        label, _, at = response_whirl(unbalance, g["stations"], g["peak_hz"], rtol)
        if label == "backward" and any(i not in used and _near(cross[i], g, rtol)
                                       for i in range(cross.size)):
            label = "forward"  # a forward mode crosses 1× inside the peak too: it is that one
        bw = label == "backward"  # matched with backward crossings and backward modes
        xs, xld, taken = (back, back_ld, used_back) if bw else (cross, cross_ld, used)
        near = [i for i in range(xs.size) if i not in taken and _near(xs[i], g, rtol)]
        i = min(near, key=lambda i: abs(xs[i] - g["peak_hz"])) if near else None
        if i is not None:
            taken.add(i)
        elif campbell is not None and not mode_in_band(campbell, g, label):
            dropped.append(g)  # two modes' responses interfering, no resonance of its own
            continue
        peak = SOURCE_PEAK + ("" if g["stable"] else " " + UNSTABLE_NOTE)
        src = SOURCE_CAMPBELL_BACKWARD if bw else SOURCE_CAMPBELL
        rows.append({"speed_hz": xs[i] if i is not None else g["peak_hz"],
                     "source": (src + " + " if i is not None else "") + peak,
                     "campbell_hz": xs[i] if i is not None else np.nan,
                     "log_dec": xld[i] if i is not None else np.nan,
                     "peak_hz": g["peak_hz"],
                     "stations": ", ".join(str(x) for x in g["stations"]),
                     "amplification_factor": g["amplification_factor"],
                     "af_kind": g["af_kind"], "whirl": label, "whirl_station": at})
    overdamped = []
    for i in range(cross.size):
        if i not in used and cross_ld[i] >= RESONANT_LOG_DEC:
            overdamped.append((float(cross[i]), float(cross_ld[i])))
        elif i not in used:
            rows.append({"speed_hz": cross[i], "source": SOURCE_CAMPBELL, "campbell_hz": cross[i],
                         "log_dec": cross_ld[i], "peak_hz": np.nan, "stations": "", "amplification_factor": np.nan,
                         "af_kind": "", "whirl": cross_wh[i], "whirl_station": -1})
    df = pd.DataFrame(rows, columns=list(CRITICAL_COLUMNS)).sort_values("speed_hz",
                                                                       ignore_index=True)
    df.attrs["not_resonances"] = [(g["peak_hz"], ", ".join(str(x) for x in g["stations"]))
                                  for g in dropped]
    df.attrs["overdamped_crossings"] = overdamped
    return df


def _crossings(campbell, whirls: bool = False) -> tuple:
    """The forward (and planar) 1× crossings (Hz) and the crossing mode's log decrement there
    (interpolated along the tracked mode); ``whirls``: also each crossing's whirl ("forward"
    or "planar"), from the same table."""
    if campbell is None:
        return (np.empty(0), np.empty(0)) + (([],) if whirls else ())
    cs = campbell.critical_speeds()
    out = cs["speed_hz"].to_numpy(dtype=float), cs["log_dec"].to_numpy(dtype=float)
    return out + (([str(w) for w in cs["whirl"]],) if whirls else ())


def not_resonance_note(table) -> str:
    """The response peaks and the Campbell crossings :func:`critical_speed_table` did not
    count (empty when none)."""
    gone = table.attrs.get("not_resonances", [])
    flat = table.attrs.get("overdamped_crossings", [])
    out = []
    if gone:
        out.append("Response peaks not counted as critical speeds (no damped forward mode "
                   "within their half-power band at that speed: two modes' responses "
                   "interfering): " + "; ".join(f"{f:.4g} Hz at station(s) {st}"
                                                for f, st in gone) + ".")
    if flat:
        out.append("1× crossings not counted as critical speeds (the mode has no resonance "
                   f"there: δ ≥ 2π, damping ratio ≥ 1/√2; no response peak): "
                   + "; ".join(f"{f:.4g} Hz (δ = {ld:.3g})" for f, ld in flat) + ".")
    return " ".join(out)


def backward_note(table) -> str:
    """How a backward critical speed is treated (empty without one in ``table``)."""
    has = table is not None and len(table) and (table["whirl"] == "backward").any()
    return BACKWARD_NOTE if has else ""


CRITICAL_HEADER = ("critical speed (Hz)", "(rpm)", "source", "whirl", "1× crossing (Hz)",
                   "δ at the crossing", "response peak (Hz)", "peak at stations", "AF")


def critical_rows(table) -> list[tuple]:
    """Rows of :data:`CRITICAL_HEADER` from :func:`critical_speed_table`."""
    out = []
    for r in table.itertuples(index=False):
        out.append((f"{r.speed_hz:.4g}", f"{60 * r.speed_hz:.0f}", r.source,
                    r.whirl or MISSING, cell(r.campbell_hz, ".4g"), cell(r.log_dec + 0.0, ".3g"),
                    cell(r.peak_hz, ".4g"), r.stations or MISSING,
                    af_text(r.amplification_factor, r.af_kind) if r.af_kind else MISSING))
    return out


def shape_source(source: str, whirl: str = "forward") -> str:
    """How the mode of a critical was picked, for the figure's caption (``whirl``: the
    critical's, :func:`rotordyn.report.critical_whirl.response_whirl`)."""
    if source == SOURCE_LEAST_DAMPED:
        return "no 1× crossing and no resonance peak in range: the least damped forward mode"
    if whirl.endswith("backward"):
        return ("the backward component of the response resonates at the responding station: "
                "the damped rotor mode nearest the speed whose orbit there whirls backward")
    if source.startswith(SOURCE_CAMPBELL):
        return "the mode crossing 1× in the damped Campbell diagram"
    return ("the damped forward mode nearest the unbalance response peak's frequency at that "
            "speed")


def _pick(freqs, whirl, kind, target_hz) -> int | None:
    """The forward rotor mode nearest ``target_hz`` (None if there is none)."""
    ok = [j for j in range(len(freqs)) if driven_by_unbalance(whirl[j]) and freqs[j] > 0
          and (kind is None or kind[j] == "rotor")]
    if not ok:
        return None
    return min(ok, key=lambda j: abs(freqs[j] - target_hz))


def _least_damped(r, kind, below_hz) -> int | None:
    """The forward rotor mode with the smallest log decrement among those with a resonance
    (δ < 2π, damping ratio below 1/√2) below ``below_hz`` (Hz); else the first (lowest)
    forward rotor mode with a resonance above it; else the least damped of all below
    ``below_hz`` — an overdamped root of heavily damped films (δ in the thousands on tilting
    pads) is drawn only when no mode has a resonance."""
    fwd = [j for j in range(len(r.frequencies_hz)) if driven_by_unbalance(r.whirl[j])
           and r.frequencies_hz[j] > 0 and (kind is None or kind[j] == "rotor")]
    res = [j for j in fwd if r.log_dec[j] < RESONANT_LOG_DEC]
    low = [j for j in res if r.frequencies_hz[j] < below_hz]
    if low:
        return min(low, key=lambda j: r.log_dec[j])
    if res:
        return min(res, key=lambda j: r.frequencies_hz[j])
    low = [j for j in fwd if r.frequencies_hz[j] < below_hz]
    return min(low, key=lambda j: r.log_dec[j]) if low else None


def shapes_for(system, crit, n_mc_hz: float, window_hz: float, chamber_pressure_pa: float,
               config_ay_m, progress=None) -> list[CriticalShape]:
    """The report's mode shapes: one at each critical speed of ``crit``
    (:func:`critical_speed_table`); with none in range, the least damped forward rotor mode
    below ``window_hz`` at the maximum continuous speed ``n_mc_hz`` (what a heavily damped
    machine whose modes give no resonance shows), so a report always draws one."""
    if len(crit):
        return critical_mode_shapes(system, crit["speed_hz"].to_numpy(), chamber_pressure_pa,
                                    config_ay_m, progress=progress,
                                    sources=list(crit["source"]),
                                    whirls=list(zip(crit["whirl"], crit["whirl_station"])))
    return critical_mode_shapes(system, [n_mc_hz], chamber_pressure_pa, config_ay_m,
                                progress=progress, sources=[SOURCE_LEAST_DAMPED],
                                least_damped_below_hz=window_hz)


def critical_mode_shapes(system, critical_speeds_hz, chamber_pressure_pa: float,
                         config_ay_m, *, max_n: int = MAX_CRITICAL_SHAPES,
                         progress=None, sources=None, whirls=None,
                         least_damped_below_hz: float = np.inf) -> list[CriticalShape]:
    """The mode shape at each of the first ``max_n`` critical speeds (Hz): with bearing
    elements the system's stability eigenvectors at that speed (equilibrium there), else the
    rotor's modes on its supports; the mode picked is the forward rotor mode whose damped
    frequency is nearest the critical's frequency (1× at a Campbell crossing and at an unbalance
    response peak alike: the speed itself). ``sources``: each critical's source (the
    ``source`` column of :func:`critical_speed_table`; default: Campbell crossings), named in
    the figure's title; a source :data:`SOURCE_LEAST_DAMPED` draws instead the least damped
    forward rotor mode below ``least_damped_below_hz`` at that speed (a model without any
    critical speed in range, :func:`shapes_for`). ``whirls``: each critical's (whirl, station)
    (the ``whirl`` and ``whirl_station`` columns): a backward one draws the rotor mode nearest
    the speed whose orbit at that station whirls backward
    (:func:`rotordyn.report.critical_whirl.pick_backward`)."""
    out: list[CriticalShape] = []
    crit = [float(x) for x in critical_speeds_hz][:max_n]
    srcs = list(sources)[:max_n] if sources is not None else [SOURCE_CAMPBELL] * len(crit)
    whs = list(whirls)[:max_n] if whirls is not None else [("forward", -1)] * len(crit)
    for n, (nc, src, (wh, at)) in enumerate(zip(crit, srcs, whs)):
        try:
            if system.bearings:
                r = analysis.stability(system, nc, chamber_pressure_pa, config_ay_m)
                ok = r.status in ("ok", "contact") and len(r.eigenvalues) > 0
                kind = r.kind
            else:
                r = analysis.modes(system, nc, reduction="none", n_modes=16)
                ok, kind = r.status == "ok", None
        except Exception as exc:  # noqa: BLE001 - a failed point is reported, not raised
            out.append(CriticalShape(nc, np.nan, "", np.nan, None, f"{exc}", src))
            continue
        bw = wh == "backward"
        if ok and src == SOURCE_LEAST_DAMPED:
            j = _least_damped(r, kind, least_damped_below_hz)
        elif ok and bw:
            j = pick_backward(r, kind, system, int(at), nc)
        else:
            j = _pick(r.frequencies_hz, r.whirl, kind, nc) if ok else None
        if j is None:
            why = (f"no {'backward' if bw else 'forward'} rotor mode at {nc:.4g} Hz" if ok
                   else f"{r.status}: {r.message}")
            out.append(CriticalShape(nc, np.nan, "", np.nan, None, why, src))
            continue
        ax = r.plot(j, system=system)
        ld = float(r.log_dec[j])
        ld = 0.0 if abs(ld) < 1e-6 else ld
        if src == SOURCE_LEAST_DAMPED and r.frequencies_hz[j] >= least_damped_below_hz:
            head = (f"no critical speed; first forward mode with a resonance (none below "
                    f"{least_damped_below_hz:.4g} Hz) at {nc:.4g} Hz")
        elif src == SOURCE_LEAST_DAMPED:
            head = f"no critical speed; least damped forward mode at {nc:.4g} Hz"
        else:
            how = "1× crossing" if src.startswith(SOURCE_CAMPBELL) else "response peak"
            how += ", backward whirl" if bw else ""
            head = f"critical speed {n + 1} ({how}): {nc:.4g} Hz ({60 * nc:.0f} rpm)"
        # a backward critical's mode by its orbit at the responding station (its summed label
        # may say otherwise on strongly elliptical modes)
        name = (whirl_text("backward", station_whirl(r, system, int(at))[j]) if bw
                else str(r.whirl[j]))
        ax.set_title(f"{head}\nmode {r.frequencies_hz[j]:.4g} Hz, {name}, δ = {ld:.3g}")
        out.append(CriticalShape(nc, float(r.frequencies_hz[j]), name, ld, ax.figure,
                                 source=src))
        if progress is not None:
            progress(n + 1, len(crit))
    return out


def api_response(system, speeds_hz, n_mc_hz: float, chamber_pressure_pa: float, config_ay_m,
                 operating_speed_hz=None, thermal=None):
    """The report's unbalance response: the API 684 unbalance
    (:func:`rotordyn.report.criteria.api_unbalance`) over ``speeds_hz`` (Hz) at its own station
    and every bearing (or support) station (``thermal``: as :func:`rotordyn.
    unbalance_response`'s). Returns (UnbalanceResult, station, U kg·m, where)."""
    from rotordyn.report.criteria import api_unbalance

    st_ub, u_kgm, where = api_unbalance(system, n_mc_hz, n_mc_hz, chamber_pressure_pa,
                                        config_ay_m)
    probes = sorted({b.station for b in system.bearings}
                    or {x.station for x in system.supports})
    outs = sorted({st_ub, *probes})
    u = analysis.unbalance_response(system, [(st_ub, u_kgm, 0.0)], speeds_hz, stations=outs,
                                    chamber_pressure_pa=chamber_pressure_pa,
                                    config_ay_m=config_ay_m,
                                    operating_speed_hz=operating_speed_hz, thermal=thermal)
    return u, st_ub, u_kgm, where


def thermal_critical_speeds(system, rng, chamber_pressure_pa: float, config_ay_m,
                            operating_speed_hz=None):
    """(table, note, CampbellResult) of :func:`thermal_results` (its unbalance response left
    out)."""
    return thermal_results(system, rng, chamber_pressure_pa, config_ay_m,
                           operating_speed_hz)[:3]


def thermal_results(system, rng, chamber_pressure_pa: float, config_ay_m,
                    operating_speed_hz=None):
    """The critical speeds (:func:`critical_speed_table`) of the damped Campbell diagram and
    the API unbalance response with every speed at its own thermal equilibrium of the model's
    ``[thermal]`` (field frozen for K_H, D_H; docs/film-physics.md, "Dynamics at each point's
    own thermal equilibrium"), over the positive analysed speeds. Returns (table, note, the
    CampbellResult, the UnbalanceResult) — the report's sections 3c, 4b and 5a: (None, "",
    None, None) without an oil system or bearing elements, (None, why, None, None) when the
    thermal model does not apply to the bearings."""
    from rotordyn.errors import InputError

    if getattr(system, "thermal", None) is None or not system.bearings:
        return None, "", None, None
    sp = np.asarray(rng.speeds_hz, dtype=float)
    sp = sp[sp > 0]  # a thermal equilibrium needs a turning journal
    if sp.size < 2:
        return (None, "not evaluated: fewer than two positive speeds in the analysed range",
                None, None)
    try:  # InputError: the model's thermal model does not apply to its bearings
        c = analysis.campbell(system, sp, chamber_pressure_pa, config_ay_m, thermal=True)
        u, *_ = api_response(system, sp, rng.n_mc_hz, chamber_pressure_pa, config_ay_m,
                             operating_speed_hz, thermal=True)
    except InputError as exc:
        return None, f"not evaluated: {exc}", None, None
    bad = int(np.sum([s not in ("ok", "contact") for s in c.point_status]))
    note = (f"thermal model {system.thermal.model}, oil supplied at "
            f"{system.thermal.supply_temperature_c:g} °C; each of {sp.size} speeds at its own "
            "thermal equilibrium, the temperature field frozen"
            + (f"; {bad} speed(s) without a thermal equilibrium (not linearised)" if bad
               else ""))
    return critical_speed_table(c, u), note, c, u


def thermal_critical_text_lines(crit, note: str) -> list[str]:
    """The text report's critical speeds on thermal films (nothing without an oil system)."""
    if crit is None:
        return ["", f"critical speeds on thermal films: {note}"] if note else []
    lines = ["", f"critical speeds on thermal films ({note}; critical_speeds_thermal.csv)"]
    if len(crit):
        lines += _text_table(CRITICAL_HEADER, critical_rows(crit))
    else:
        lines.append("  none: no resonant forward 1× crossing and no response peak in the range")
    return (lines + (["  " + not_resonance_note(crit)] if not_resonance_note(crit) else [])
            + (["  " + backward_note(crit)] if backward_note(crit) else []))


def critical_text_lines(crit, shapes, rng, chamber_pressure_pa: float, active: bool,
                        files: bool = True) -> list[str]:
    """The text report's lines: the critical speeds ``crit`` (:func:`critical_speed_table`)
    with their sources, then each mode shape of ``shapes`` (:func:`critical_mode_shapes`) and
    its file ``critical_mode_<k>.png`` (``files``)."""
    sp = rng.speeds_hz
    lines = ["", f"critical speeds over {sp[0]:.4g}–{sp[-1]:.4g} Hz ({rng.why})"
             + (f", p_c = {chamber_pressure_pa / 1e6:g} MPa" if active else "")
             + ": each with its source (1× crossing of the damped Campbell diagram, peak of the"
             " API unbalance response, or both)"]
    if len(crit):
        lines += _text_table(CRITICAL_HEADER, critical_rows(crit))
    else:
        lines.append("  none: no resonant forward 1× crossing and no response peak in the range")
    if not_resonance_note(crit):
        lines.append("  " + not_resonance_note(crit))
    if backward_note(crit):
        lines.append("  " + backward_note(crit))
    for k, m in enumerate(shapes, start=1):
        if m.figure is None:
            lines.append(f"  mode shape at critical speed {k} ({m.speed_hz:.4g} Hz): not "
                         f"resolved ({m.why})")
            continue
        what = ("mode shape" if m.source == SOURCE_LEAST_DAMPED
                else f"mode shape at critical speed {k}")
        lines.append(f"  {f'critical_mode_{k}.png: ' if files else ''}{what}, "
                     f"{m.speed_hz:.4g} Hz ({m.source}): {m.whirl} mode at "
                     f"{m.freq_hz:.4g} Hz, log dec {m.log_dec:.3g} "
                     f"({shape_source(m.source, m.whirl)})")
    if len(crit) > len(shapes):
        lines.append(f"  mode shapes of the first {len(shapes)} of {len(crit)} drawn")
    return lines


def coefficient_text_lines(coeffs) -> list[str]:
    """The text report's table of the bearings' coefficients (none without bearings)."""
    if coeffs.empty:
        return []
    lines = (["", "bearing coefficients over speed (dF = −K dq − C dq̇; x horizontal, y up; "
              "bearing_coefficients.csv/.png)"]
             + _text_table(COEFFICIENT_HEADER, coefficient_rows(coeffs)))
    for (head, rows), what in zip(tilt_coefficient_tables(coeffs), ("stiffness", "damping")):
        lines += ["", f"tilting films: {what} coupling blocks of the 4×4 over (x, y, θx, θy) "
                  "(dH = −K dr − C dṙ, H = (Fx, Fy, Mx, My); the x, y block above)"]
        lines += _text_table(head, rows)
    return lines


def write_text_sections(system, rng, chamber_pressure_pa: float, config_ay_m, outdir,
                        operating_speed_hz=None, campbell=None, level1=None) -> list[str]:
    """The text report's critical speeds (with their sources), the mode shape at each one
    (``critical_mode_<k>.png``, ``critical_speeds.csv``) and the bearings' coefficients over
    speed (``bearing_coefficients.csv``/``.png``) under ``outdir``, as the HTML report has
    them; with an oil system (``[thermal]``) the bearing temperatures, power loss and K, C at
    the thermal equilibrium (:mod:`rotordyn.report.thermal`) and the critical speeds on thermal
    films; then the unbalance response and the stability screen on the isothermal and (with an
    oil system) thermal films (:func:`rotordyn.report.thermal_dynamics.text_sections`: the
    thermal ones from the same Campbell diagram and response as the critical speeds, not
    computed twice) and the checks with their overall verdict, Level I's (``level1``: the
    (Level1Result or None, why) of :func:`rotordyn.report.level1.evaluate`) among them.
    ``rng``: :class:`rotordyn.report.criteria.SpeedRange`; ``campbell``: a Campbell diagram
    over ``rng.speeds_hz`` already computed (else computed here). Returns the lines."""
    from pathlib import Path

    import matplotlib.pyplot as plt

    from rotordyn.plot.coefficients import bearing_coefficients as coefficient_figure
    from rotordyn.report import level1 as level1_report
    from rotordyn.report import thermal_dynamics
    from rotordyn.report.criteria import Checks

    outdir = Path(outdir)
    sp = rng.speeds_hz
    pc, ay = chamber_pressure_pa, config_ay_m
    c = campbell
    if c is None:
        c = (analysis.campbell(system, sp, pc, ay) if system.bearings
             else analysis.rotor_campbell(system, sp, n_modes=12))
    u, _, u_kgm, where = api_response(system, sp, rng.n_mc_hz, pc, ay, operating_speed_hz)
    crit = critical_speed_table(c, u)
    crit.to_csv(outdir / "critical_speeds.csv", index=False)
    shapes = shapes_for(system, crit, rng.n_mc_hz, 1.5 * float(sp[-1]), pc, ay)
    for k, m in enumerate(shapes, start=1):
        if m.figure is not None:
            m.figure.savefig(outdir / f"critical_mode_{k}.png", dpi=200, bbox_inches="tight")
            plt.close(m.figure)
    lines = critical_text_lines(crit, shapes, rng, pc, ay is not None)
    eqs: list = []
    coeffs = bearing_coefficient_frame(system, sp, pc, ay, equilibria=eqs)
    if not coeffs.empty:
        coeffs.to_csv(outdir / "bearing_coefficients.csv", index=False)
        fig = coefficient_figure(coeffs)
        fig.savefig(outdir / "bearing_coefficients.png", dpi=200, bbox_inches="tight")
        plt.close(fig)
    from rotordyn.report.thermal import thermal_frames, thermal_text_lines, write_thermal
    from rotordyn.report.films import film_text_lines, write_films

    film_tab, lengths = write_films(system, eqs, outdir)

    th, th_coeffs, note = thermal_frames(system, sp, pc, ay)
    write_thermal(th, th_coeffs, outdir)
    tcrit, tnote, tc, tu = thermal_results(system, rng, pc, ay, operating_speed_hz)
    if tcrit is not None:
        tcrit.to_csv(outdir / "critical_speeds_thermal.csv", index=False)
    checks = Checks()
    films = thermal_dynamics.ISOTHERMAL if getattr(system, "thermal", None) is not None else ""
    dyn = thermal_dynamics.text_sections(
        checks, response=(u, u_kgm, where), thermal_response=tu, campbell=c,
        thermal_campbell=tc, outs=list(u.stations), n_mc_hz=rng.n_mc_hz,
        clear={b.station: getattr(b, "clearance_m", None) for b in system.bearings},
        window_hz=1.5 * float(sp[-1]), op_range=operating_speed_hz, films=films)
    checks.films = films  # Level I: isothermal films (as in the HTML report)
    if level1 is not None:
        level1_report.add_checks(*level1, checks)
    from rotordyn.report.pad_onset import pad_onset_lines

    return (lines + coefficient_text_lines(coeffs) + film_text_lines(film_tab, lengths)
            + thermal_text_lines(th, th_coeffs, note)
            + thermal_critical_text_lines(tcrit, tnote) + dyn + pad_onset_lines(eqs)
            + checks.text_lines())


def coefficient_speeds(speeds_hz, n: int = 11) -> np.ndarray:
    """``n`` speeds spread over the analysed range (the table's rows per bearing)."""
    sp = np.asarray(speeds_hz, dtype=float)
    return np.linspace(float(sp.min()), float(sp.max()), min(n, sp.size))


def bearing_coefficient_frame(system, speeds_hz, chamber_pressure_pa: float, config_ay_m,
                              progress=None, equilibria: list | None = None):
    """The bearings' coefficients at :func:`coefficient_speeds` (an empty frame without bearing
    elements); ``equilibria`` receives the equilibria they were taken at
    (:func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients`)."""
    return bearing_coefficients(system, coefficient_speeds(speeds_hz), chamber_pressure_pa,
                                config_ay_m, progress=progress, equilibria=equilibria)


__all__ = ["COEFFICIENT_HEADER", "CRITICAL_COLUMNS", "CRITICAL_HEADER", "CriticalShape",
           "MAX_CRITICAL_SHAPES", "SOURCE_CAMPBELL", "SOURCE_LEAST_DAMPED", "SOURCE_PEAK", "bearing_coefficient_frame",
           "api_response", "coefficient_rows", "coefficient_speeds", "critical_mode_shapes",
           "SOURCE_CAMPBELL_BACKWARD", "backward_note",
           "coefficient_text_lines", "critical_rows", "critical_speed_table",
           "critical_text_lines", "not_resonance_note", "shape_source", "shapes_for",
           "thermal_critical_speeds", "thermal_critical_text_lines", "thermal_results",
           "write_text_sections"]
