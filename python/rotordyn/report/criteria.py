"""What the report computes for any model, apart from its layout: the speed range (API 684:
0 to at least 125 % of the maximum continuous speed), the API unbalance and where it is placed,
the undamped critical speed map, and the checks with their criteria and verdicts (PASS/FAIL only
where a criterion applies, "not resolved" where a value cannot be computed).

Sources: API 684 2nd ed. (2005) §2.8 (speed range, unbalance U = 6350 W/N g·mm, AF and the
separation margins: :mod:`rotordyn._common.api`), API 617 8th ed. (2014) §4.8.2.11–12 (the
amplitude limit and the 75 % of clearance check)."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import analysis
from rotordyn._common.api import (API_CRITICALLY_DAMPED_AF, RESONANT_LOG_DEC, RESONANT_ZETA,
                                  af_text)
from rotordyn._common.status import CONVERGED
from rotordyn._common.whirl import driven_by_unbalance
from rotordyn.model.rotor import Reduction, Support

API_SPEED_FACTOR = 1.25        # API 684: analyse from 0 to at least 125 % of N_mc
API_UNBALANCE_G_MM = 6350.0    # API 684/617: U = 6350 W / N g·mm (W kg, N rpm)
API_CLEARANCE_FRACTION = 0.75  # API 617: peak-to-peak ≤ 75 % of the diametral clearance
SCREEN_LOG_DEC = 0.1           # screening: forward rotor modes in the window δ > 0.1
LOG_DEC_ROUND_OFF = 1e-6       # |δ| below this is round-off of an undamped mode, not a sign
N_SPEEDS = 121                 # grid of the Campbell diagram and the unbalance response
PAPER_SPEEDS_HZ = np.arange(5.0, 121.0, 1.0)  # the paper's Fig. 12/13 speeds (§6.3)

NOT_RESOLVED = "not resolved"


def amplitude_limit_um(n_mc_rpm: float) -> float:
    """API 617 unbalance response amplitude limit, peak-to-peak µm: 25.4 √(12000/N_mc), and
    not more than 25.4 µm (the formula is capped below 12000 rpm)."""
    return float(min(25.4, 25.4 * np.sqrt(12000.0 / n_mc_rpm)))


def critical_speed_map(system, k_range=(1e5, 1e10), n_k=21, n_modes=4):
    """Undamped natural frequencies (Hz, at rest) against an isotropic stiffness k (N/m) put
    in place of each bearing element (or of each linear support when there are none), x/y
    duplicates removed. Returns (k (n_k,), f (n_k, n_modes), stations)."""
    stations = [b.station for b in system.bearings] or [s.station for s in system.supports
                                                        if s.type == "linear"]
    base = tuple(s for s in system.supports if s.station not in stations)
    ks = np.geomspace(*k_range, n_k)
    f = np.full((n_k, n_modes), np.nan)
    for i, k in enumerate(ks):
        sup = base + tuple(Support(st, "linear", kxx_n_per_m=k, kyy_n_per_m=k)
                           for st in stations)
        s = dataclasses.replace(system, supports=sup, bearings=(), thermal=None,
                                reduction=Reduction(method="none"))  # (no films: no oil)
        m = analysis.modes(s, 0.0, reduction="none", n_modes=2 * n_modes)
        fr = _distinct(m.frequencies_hz)[:n_modes]
        f[i, :fr.size] = fr
    return ks, f, stations


def _distinct(freqs, rtol: float = 1e-6) -> np.ndarray:
    """Frequencies with the (x, y) pairs of an axisymmetric rotor at rest counted once."""
    out: list[float] = []
    for x in np.sort(np.asarray(freqs, dtype=float)):
        if np.isfinite(x) and x > 0 and (not out or x > out[-1] * (1 + rtol)):
            out.append(float(x))
    return np.asarray(out)


@dataclasses.dataclass(frozen=True)
class SpeedRange:
    """speeds_hz (n,), the maximum continuous speed N_mc (Hz) the API checks use, and how
    both were chosen (stated in the report)."""

    speeds_hz: np.ndarray
    n_mc_hz: float
    why: str


def table_window(system):
    """(lo, hi, text): the speeds (Hz) every bearing table of ``system`` covers (tables that
    extrapolate, or of one speed, cover all), and which table bounds them; None without such a
    table."""
    from rotordyn.bearings import TableBearing

    tabs = [b for b in system.bearings if isinstance(b, TableBearing) and not b.extrapolate
            and len(b.speeds_hz) > 1]
    if not tabs:
        return None
    lo_b = max(tabs, key=lambda b: b.speeds_hz[0])
    hi_b = min(tabs, key=lambda b: b.speeds_hz[-1])
    lo, hi = float(lo_b.speeds_hz[0]), float(hi_b.speeds_hz[-1])
    name = lambda b: repr(b.name or f"station {b.station}")  # noqa: E731
    text = (f"the table of bearing {name(hi_b)} ends at {hi:g} Hz"
            + (f", that of bearing {name(lo_b)} starts at {lo:g} Hz" if lo > 0 else "")
            + "; extend the tables or set extrapolate = true to analyse further")
    return lo, hi, text


def _within_tables(win, rng: SpeedRange, explicit: bool, given_n_mc: bool) -> SpeedRange:
    """``rng`` limited to the speeds the bearing tables cover (the coefficients are not
    defined outside them), saying so in its ``why``: an automatic range is cut there (as many
    speeds over what is left), a given list keeps its speeds inside them; a
    maximum continuous speed outside them, or a list with no speed inside, is refused naming
    the option."""
    from rotordyn.errors import InputError

    if win is None:  # no bearing table bounds the speeds (:func:`table_window`)
        return rng
    lo, hi, text = win
    sp = rng.speeds_hz
    tol = 1e-12 * max(abs(lo), abs(hi))
    if sp[0] >= lo - tol and sp[-1] <= hi + tol:
        return rng
    cut = sp[(sp >= lo - tol) & (sp <= hi + tol)]
    if explicit:
        if cut.size == 0:
            raise InputError(f"speeds_hz (--speeds-hz): {sp[0]:g}–{sp[-1]:g} Hz has no speed "
                             f"within the bearing tables' {lo:g}–{hi:g} Hz ({text})")
        return SpeedRange(cut, min(rng.n_mc_hz, hi), f"{rng.why}; {sp.size - cut.size} of "
                          f"them outside the bearing tables dropped: {text}")
    if rng.n_mc_hz > hi + tol or rng.n_mc_hz < lo - tol:
        if given_n_mc:  # the user's maximum continuous speed: refused, named
            raise InputError(f"--operating-speed-hz: the maximum continuous speed "
                             f"{rng.n_mc_hz:g} Hz is outside the bearing tables' {lo:g}–{hi:g} "
                             f"Hz ({text})")
        top = min(max(rng.n_mc_hz, lo), hi)  # the model's own N_mc, moved into the tables
        rng = SpeedRange(sp, top, f"{rng.why}; N_mc taken as {top:.4g} Hz, inside the tables")
    a, b = max(sp[0], lo), min(sp[-1], hi)
    if not a < b:  # no overlap: the tables' own speeds
        a, b = lo, hi
    cut = np.linspace(a, b, sp.size)  # the same grid size
    return SpeedRange(cut, rng.n_mc_hz, f"{rng.why}; cut to {cut[0]:.4g}–{cut[-1]:.4g} Hz: "
                      f"{text}")


def speed_range(system, operating_speed_hz=None, speeds_hz=None, rigid_map=None,
                paper: bool = False) -> SpeedRange:
    """The report's speeds: ``speeds_hz`` when given; else 2 %…125 % of the maximum operating
    speed (API 684), for the paper's rig its 5–120 Hz when that reaches further; else, for the
    paper's rig, its 5–120 Hz; else up to 125 % of the second
    undamped critical speed on stiff bearings (``rigid_map`` from :func:`critical_speed_map`),
    so the first two criticals are in range — then, with bearing tables, within the speeds
    they cover (:func:`table_window`; N_mc at most their top over 1.25 when it was not
    given)."""
    rng = _speed_range(system, operating_speed_hz, speeds_hz, rigid_map, paper)
    win = table_window(system)
    if win is not None and speeds_hz is None and not operating_speed_hz \
            and API_SPEED_FACTOR * rng.n_mc_hz > win[1]:
        top = win[1] / API_SPEED_FACTOR
        rng = SpeedRange(rng.speeds_hz, top, rng.why + f"; N_mc taken as {top:.4g} Hz, the "
                         "tables' top speed / 1.25")
    return _within_tables(win, rng, speeds_hz is not None, bool(operating_speed_hz))


def _speed_range(system, operating_speed_hz, speeds_hz, rigid_map, paper) -> SpeedRange:
    if speeds_hz is not None:
        sp = np.asarray(speeds_hz, dtype=float)
        top = float(operating_speed_hz[1]) if operating_speed_hz else float(sp[-1]) / 1.25
        return SpeedRange(sp, top, "as given (--speeds-hz)")
    if operating_speed_hz:
        top = float(operating_speed_hz[1])
        hi = API_SPEED_FACTOR * top
        if paper and hi <= PAPER_SPEEDS_HZ[-1]:
            # The paper's own range holds both of its critical speeds (39, 90 Hz); 125 % of
            # the rig's 55 Hz (69 Hz) would cut the second off.
            return SpeedRange(PAPER_SPEEDS_HZ.copy(), top,
                              f"the paper's 5–120 Hz (beyond 125 % of the maximum operating "
                              f"speed {top:g} Hz, API 684; it holds both critical speeds of "
                              "the paper)")
        return SpeedRange(np.linspace(0.02 * hi, hi, N_SPEEDS), top,
                          f"2 %…125 % of the maximum operating speed {top:g} Hz (API 684)")
    if paper:
        return SpeedRange(PAPER_SPEEDS_HZ.copy(), 55.0, "the paper's 5–120 Hz")
    ks, f, _ = rigid_map if rigid_map is not None else critical_speed_map(system)
    second = f[-1, min(1, f.shape[1] - 1)]
    top = float(second) if np.isfinite(second) else float(np.nanmax(f))
    hi = API_SPEED_FACTOR * top
    return SpeedRange(np.linspace(0.02 * hi, hi, N_SPEEDS), top,
                      f"no operating speed given: up to 125 % of the second undamped critical "
                      f"speed on stiff bearings ({top:.4g} Hz); margins not assessed")


def overhung_mass_kg(system, station: int) -> float | None:
    """The mass (kg) outboard of the outermost bearing or support on the side of ``station``
    when ``station`` lies beyond it (an overhung end: shaft sections past that support's
    station and the disks beyond it), else None (``station`` between the supports)."""
    at = sorted({b.station for b in system.bearings} | {s.station for s in system.supports})
    if not at or at[0] <= station <= at[-1]:
        return None
    secs = system.rotor.sections
    right = station > at[-1]
    idx = range(at[-1], len(secs)) if right else range(0, at[0])
    shaft = sum(secs[i].mass_kg(system.material(secs[i].material)) for i in idx)
    disks = sum(d.mass_kg for d in system.rotor.disks
                if (d.station > at[-1] if right else d.station < at[0]))
    return float(shaft + disks)


def api_unbalance(system, n_mc_hz: float, speed_hz: float, pc: float, ay):
    """(station, U kg·m, why): the API unbalance U = 6350 W/N g·mm for the first forward rotor
    mode, W the rotor's whole static load (the journals' loads summed, as API 684 takes for a
    mode with its largest deflection between the bearings) or, when that deflection is at an
    overhung end (outboard of every bearing and support), the overhung weight (API 617 / API
    684 §2.8: "the weight outboard of the bearing", :func:`overhung_mass_kg`), placed at the
    station of that mode's largest deflection at ``speed_hz``; the largest disk when no mode
    is found. The
    first forward mode is the lowest forward rotor mode with a resonance (damping ratio below
    1/√2, as API 617 Level I's :func:`rotordyn.level1` judges it): an overdamped rigid-body
    root of stiff, heavily damped films (tilting pads) has no peak to excite."""
    u_kgm = API_UNBALANCE_G_MM * system.mass_kg / (60.0 * n_mc_hz) * 1e-6
    try:
        st = analysis.stability(system, speed_hz, pc, ay)
    except Exception:  # noqa: BLE001 - the placement falls back to the largest disk
        st = None
    if st is not None and st.rotor_shapes is not None and len(st.eigenvalues):
        fwd = [j for j in range(len(st.eigenvalues)) if driven_by_unbalance(st.whirl[j])
               and st.kind[j] == "rotor" and st.eigenvalues[j].imag > 0
               and st.damping_ratio[j] < RESONANT_ZETA]  # a mode with a resonance
        if fwd:
            j = fwd[0]
            nodes = system.rotor.station_nodes()
            amp = np.abs(st.rotor_shapes[nodes, 0, j]) + np.abs(st.rotor_shapes[nodes, 1, j])
            k = int(np.argmax(amp))
            why = (f"at station {k}, the largest deflection of the first forward mode "
                   f"({st.frequencies_hz[j]:.4g} Hz at {speed_hz:.4g} Hz)")
            w = overhung_mass_kg(system, k)
            if w is not None:
                u_kgm = API_UNBALANCE_G_MM * w / (60.0 * n_mc_hz) * 1e-6
                why += f", W = the overhung weight {w:.4g} kg (outboard of the bearing)"
            return k, u_kgm, why
    disk = max(system.rotor.disks, key=lambda d: d.mass_kg) if system.rotor.disks else None
    k = disk.station if disk else system.rotor.n_stations // 2
    return k, u_kgm, f"at station {k} (the largest disk)"


class Checks:
    """The checks: name, criterion, value, verdict (True PASS, False FAIL, None no criterion
    applies, NOT_RESOLVED a value that cannot be computed). ``films``: the physics the rows
    added next are computed on ("isothermal films", "thermal films"; "" without an oil
    system), kept per row in ``films_of``."""

    def __init__(self):
        self.rows: list[tuple[str, str, str, object]] = []
        self.films_of: list[str] = []
        self.films = ""

    def add(self, name: str, criterion: str, value: str, verdict) -> None:
        self.rows.append((name, criterion, value, verdict))
        self.films_of.append(self.films)

    def text_lines(self) -> list[str]:
        """The checks as text (the HTML report's checks table): the overall verdict, then one
        line per check, ``RESULT  check [films]: value (criterion)``."""
        out = ["", f"checks: overall {self.overall()} (every check with its criterion)"]
        for (name, crit, value, ok), films in zip(self.rows, self.films_of):
            res = ("n/a" if ok is None else ok if isinstance(ok, str)
                   else "PASS" if ok else "FAIL")
            out.append(f"  {res:<12} {name}" + (f" [{films}]" if films else "")
                       + f": {value} ({crit})")
        return out

    def overall(self) -> str:
        """FAIL if any check fails, else NOT RESOLVED if any is, else PASS (a check that was not
        evaluated, e.g. "not evaluated (no stage data)", neither passes nor fails)."""
        vs = [r[3] for r in self.rows]
        if any(x is False for x in vs):
            return "FAIL"
        if any(x == NOT_RESOLVED for x in vs):
            return "NOT RESOLVED"
        return "PASS"


def separation_checks(checks: Checks, u, station: int) -> list[tuple]:
    """Rows of the peaks table at ``station`` and their separation-margin checks (none for a
    peak with AF < 1: no resonance)."""
    rows = []
    for r in u.peaks(station).to_dict("records"):
        af, kind = r["amplification_factor"], r["af_kind"]
        req = r.get("required_margin_pct", np.nan)
        sm = r.get("separation_margin_pct", np.nan)
        if u.operating_speed_hz is None:
            verdict = None
        elif kind == "unresolved":
            verdict = NOT_RESOLVED
        else:
            verdict = bool(sm >= req)
        rows.append((r["critical_speed_hz"], r["peak_m"], af_text(af, kind), sm, req, verdict))
        # AF < 1: a half-power band wider than the speed, no resonance (docs/api-criteria.md):
        # in the peaks table, but no separation margin of a critical speed to check
        if u.operating_speed_hz is not None and not (kind != "unresolved" and af < 1.0):
            crit = ("API 684: AF < 2.5 critically damped, no margin; else SM ≥ 17(1 − 1/(AF − "
                    "1.5)) % (≤ 16 %) below / 10 + that (≤ 26 %) above the operating range")
            val = (f"{af_text(af, kind)}, SM {sm:.1f} %, required "
                   + ("none" if req == 0 else f"{req:.1f} %" if np.isfinite(req) else
                      "not known (the half-power band leaves the speed range or runs into "
                      "another resonance)"))
            checks.add(f"separation margin, N_c = {r['critical_speed_hz']:.4g} Hz (station "
                       f"{station})", crit, val, verdict)
    return rows


def amplitude_checks(checks: Checks, u, station: int, n_mc_hz: float, clearance_m=None):
    """The API 617 amplitude limit in the operating range and, at a bearing (``clearance_m``),
    the peak-to-peak orbit against 75 % of the diametral clearance over the whole range."""
    k = list(u.stations).index(station)
    a = 2 * u.major_m[:, k]  # peak-to-peak of the orbit's major axis, m
    ok_pts = np.isfinite(a) & u.stable
    if u.operating_speed_hz is not None:
        lo, hi = u.operating_speed_hz
        inr = (u.speeds_hz >= lo) & (u.speeds_hz <= hi) & ok_pts
        lim = amplitude_limit_um(60.0 * n_mc_hz)
        if inr.any():
            pp = float(np.max(a[inr])) * 1e6
            checks.add(f"vibration amplitude in the operating range (station {station})",
                       "API 617: peak-to-peak ≤ 25.4 √(12000/N_mc) µm, at most 25.4 µm",
                       f"{pp:.3g} µm (limit {lim:.3g} µm)", bool(pp <= lim))
        else:
            checks.add(f"vibration amplitude in the operating range (station {station})",
                       "API 617 amplitude limit", "no stable, converged speed in the range",
                       NOT_RESOLVED)
    if clearance_m:
        if ok_pts.any():
            pp = float(np.max(a[ok_pts]))
            lim = API_CLEARANCE_FRACTION * 2 * clearance_m
            checks.add(f"orbit against the bearing clearance (station {station})",
                       "API 617: peak-to-peak ≤ 75 % of the diametral clearance at any speed",
                       f"{pp * 1e6:.3g} µm (limit {lim * 1e6:.3g} µm)", bool(pp <= lim))


def stability_screen(checks: Checks, c, window_hz: float, op_range) -> np.ndarray:
    """Forward rotor modes below ``window_hz``: their log decrement (round-off of undamped
    modes set to 0). Checks: δ > 0.1 in the operating range (a screening without cross-coupling;
    API 617 Level I with Q_A is :mod:`rotordyn.report.level1`) and no growing forward mode
    over the whole range. Returns the screened δ (n_speeds, n_modes), NaN elsewhere."""
    fwd = (c.rotor_mask() & driven_by_unbalance(c.whirl) & (c.frequencies_hz < window_hz)
           & (c.frequencies_hz > 0))
    ld = np.where(fwd & (c.log_dec < RESONANT_LOG_DEC), c.log_dec, np.nan)
    ld = np.where(np.abs(ld) < LOG_DEC_ROUND_OFF, 0.0, ld)
    # per speed: converged, and whether any forward rotor mode lies below the window at all
    conv = _converged_speeds(c)
    conv = np.where(conv, np.where(fwd.any(axis=1), 2, 1), 0)
    if op_range is not None:
        inr = (c.speeds_hz >= op_range[0]) & (c.speeds_hz <= op_range[1])
        _screen_check(checks, "stability screening in the operating range",
                      f"forward rotor modes below {window_hz:.4g} Hz: δ > {SCREEN_LOG_DEC} "
                      "without cross-coupling (API 617 Level I with Q_A: its own checks)",
                      ld[inr], conv[inr], window_hz, lambda m: m > SCREEN_LOG_DEC, "the range")
    _screen_check(checks, "no growing forward mode over the speed range",
                  f"forward rotor modes below {window_hz:.4g} Hz: δ ≥ 0", ld, conv, window_hz,
                  lambda m: m >= 0, "the speed range")
    return ld


def _converged_speeds(c) -> np.ndarray:
    """(n_speeds,) True where the Campbell diagram ``c`` has a converged equilibrium."""
    ps = getattr(c, "point_status", None)
    if ps is None:
        return np.full(len(c.speeds_hz), c.status in CONVERGED)
    return np.isin(np.asarray(ps, dtype=object), CONVERGED)


def _screen_check(checks: Checks, name: str, criterion: str, ld, conv, window_hz: float,
                  passes, where: str) -> None:
    """One screening check on the screened δ ``ld`` of some speeds: its minimum; or, where
    speeds converged but no forward rotor mode below ``window_hz`` has a resonance (none
    there, or every one damped beyond ζ = 1/√2, δ ≥ 2π: nothing to grow, as an unstable mode
    has ζ < 0), PASS saying which; NOT RESOLVED without a converged speed. ``conv`` per
    speed: 0 not converged, 1 converged without a forward rotor mode below the window, 2
    with one."""
    if np.isfinite(ld).any():
        m = float(np.nanmin(ld))
        checks.add(name, criterion, f"minimum δ = {m:.3g}", bool(passes(m)))
    elif np.any(conv == 2):
        checks.add(name, criterion, f"no forward rotor mode with a resonance below "
                   f"{window_hz:.4g} Hz (all damped beyond δ = 2π) in {where}", True)
    elif np.any(conv == 1):
        checks.add(name, criterion, f"no forward rotor mode below {window_hz:.4g} Hz in "
                   f"{where}", True)
    else:
        checks.add(name, criterion, f"no converged point in {where}", NOT_RESOLVED)


__all__ = ["API_CRITICALLY_DAMPED_AF", "Checks", "NOT_RESOLVED", "SpeedRange", "amplitude_checks",
           "amplitude_limit_um", "api_unbalance", "critical_speed_map", "overhung_mass_kg",
           "separation_checks", "speed_range", "stability_screen"]
