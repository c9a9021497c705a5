"""The film code every bearing element shares: the cavitation models, the checks of the fields
every film element has, and the film geometry of the fixed-geometry, tilting-pad and
squeeze-film elements.

One general film: a bearing is a set of *pads* (arcs of the bush), each with its own centre
of curvature (preload m and offset α), separated by grooves held at the supply pressure.
A pad's film thickness with the journal at (x, y) (DESIGN frame) is

    h(φ) = C_p − (C_p − C_b) cos(φ − φ_p) − x cos φ − y sin φ  [+ tilt / pivot terms],

C_b the bearing (minimum, assembled) clearance, C_p = C_b / (1 − m) the pad's machined
clearance and φ_p = φ_start + α·β the angle of the pad's minimum clearance (the pivot of a
tilting pad; β the pad arc). A 360° pad without preload is the plain bearing.

Each pad is one film coupling of the C++ system (``FilmCoupling``) on the existing Reynolds
core: the pad's arc is mapped onto m intervals of a periodic core grid of N = m + 2 nodes,
whose remaining nodes form a groove (Dirichlet, p = supply pressure), so p equals the supply
pressure on both pad edges. The core's angle φ_c maps to φ = φ_start + s·φ_c with
s = β N / (2π m); the Reynolds equation on the pad is then exactly the core's with the
diameter s·D and the surface speed ω/s (``spin_factor`` = 1/s), and its area element
s·R dφ_c dz is R dφ dz, so forces by virtual work need no correction. Pad edges therefore
sit exactly on grid nodes whatever the arc.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rotordyn import _core
from rotordyn._common import plausibility
from rotordyn._common import validate as v
from rotordyn.errors import ClosedFilmError, FieldCombinationError, InputError

CAVITATION_MODELS = ("none", "gumbel", "reynolds", "jfo")
# Turbulent lubrication models (C++ core, docs/film-physics.md): "laminar" or "ng_pan"
# (Ng & Pan 1965 / Elrod & Ng 1967 in the fits of Taylor & Dowson 1974).
TURBULENCE_MODELS = ("laminar", "ng_pan")
MAX_DENSITY_KG_M3 = 1e5


def check_turbulence(where: str, turbulence, density_kg_m3, onset_re=None,
                     full_re=None) -> None:
    """The turbulence model, the oil density it needs (kg/m³, None: not given) and its
    optional laminar-to-turbulent transition (``turbulence_onset_re`` < ``turbulence_full_re``,
    finite, onset >= 0, both or neither, only with a turbulent model)."""
    v.choice(f"{where}.turbulence", turbulence, TURBULENCE_MODELS)
    if (onset_re is None) != (full_re is None):
        missing = "turbulence_onset_re" if onset_re is None else "turbulence_full_re"
        raise InputError(f"{where}.{missing}: the transition needs both turbulence_onset_re "
                         "and turbulence_full_re (or neither), got None")
    if onset_re is not None:
        if turbulence == "laminar":
            raise InputError(f"{where}.turbulence_onset_re: a laminar-to-turbulent transition "
                             "needs turbulence = 'ng_pan', got 'laminar'")
        on = v.non_negative(f"{where}.turbulence_onset_re", onset_re)
        full = v.finite(f"{where}.turbulence_full_re", full_re)
        if not full > on:  # a pair's fault (a sweep point's error row, not the spec)
            raise FieldCombinationError(f"{where}.turbulence_full_re: expected a Re_h > "
                             f"turbulence_onset_re = {on!r}, got {full_re!r}")
    if density_kg_m3 is not None:
        v.in_range(f"{where}.density_kg_m3", density_kg_m3, 0.0, MAX_DENSITY_KG_M3,
                   lo_open=True)
    elif turbulence != "laminar":
        raise InputError(f"{where}.density_kg_m3: expected the oil density in (0, "
                         f"{MAX_DENSITY_KG_M3:g}] kg/m^3 with turbulence = {turbulence!r} (the "
                         f"film Reynolds number rho*U*h/mu needs it), got None")


def set_turbulence(g, turbulence: str, density_kg_m3, onset_re=None, full_re=None) -> None:
    """Put the turbulence model (and its transition, if any) on a core geometry (laminar
    leaves the default)."""
    g.turbulence = turbulence
    if density_kg_m3 is not None:
        g.density_kg_m3 = float(density_kg_m3)
    if onset_re is not None:
        g.turbulence_onset_re = float(onset_re)
        g.turbulence_full_re = float(full_re)

TWO_PI = 2.0 * math.pi
GAP_FACTOR = 4.0  # film thickness put on the (pressure-prescribed) gap nodes, × C_p


def check_film_fields(b, where: str, n_stations: int | None) -> None:
    """The fields every film element has (station, D, L, c, μ, cavitation, grid,
    configuration, name); ``n_stations`` None skips the station range (a standalone
    element). Placed in a system (``n_stations`` given), every film element — plain, active,
    fixed-geometry, tilting-pad, squeeze-film — gets the unit-slip warnings of its
    diameter, clearance, viscosity and housing offsets (:mod:`rotordyn._common.plausibility`)."""
    v.text(f"{where}.name", b.name)
    if n_stations is not None:
        v.integer(f"{where}.station", b.station, lo=0, hi=n_stations - 1)
    v.positive(f"{where}.diameter_m", b.diameter_m)
    v.positive(f"{where}.length_m", b.length_m)
    c = v.positive(f"{where}.clearance_m", b.clearance_m)
    if c >= 0.1 * b.diameter_m:
        raise InputError(f"{where}.clearance_m: expected a value in (0, 0.1 × diameter_m), "
                         f"got {b.clearance_m!r}")
    v.positive(f"{where}.viscosity_pa_s", b.viscosity_pa_s)
    v.choice(f"{where}.cavitation", b.cavitation, CAVITATION_MODELS)
    v.integer(f"{where}.n_circ", b.n_circ, lo=12, hi=4096)
    v.integer(f"{where}.n_axial", b.n_axial, lo=2, hi=1024)
    v.finite(f"{where}.config_ax_m", b.config_ax_m)
    v.finite(f"{where}.config_ay_m", b.config_ay_m)
    check_turbulence(where, getattr(b, "turbulence", "laminar"), getattr(b, "density_kg_m3", None),
                     getattr(b, "turbulence_onset_re", None), getattr(b, "turbulence_full_re", None))
    if n_stations is not None:  # placed in a system: unit-slip warnings, once, by its path
        plausibility.length(f"{where}.diameter_m", b.diameter_m)
        plausibility.clearance(f"{where}.clearance_m", b.clearance_m, b.diameter_m)
        plausibility.viscosity(f"{where}.viscosity_pa_s", b.viscosity_pa_s)
        plausibility.housing_offset(f"{where}.config_ax_m", b.config_ax_m, b.clearance_m)
        plausibility.housing_offset(f"{where}.config_ay_m", b.config_ay_m, b.clearance_m)


def tilt_fields(b, where: str) -> tuple[float, float]:
    """``tilt`` (bool) and the housing misalignment (θx, θy) in rad: finite, and only with
    tilt. Returns (θx, θy)."""
    v.boolean(f"{where}.tilt", b.tilt)
    tx = v.finite(f"{where}.config_theta_x_rad", b.config_theta_x_rad)
    ty = v.finite(f"{where}.config_theta_y_rad", b.config_theta_y_rad)
    if (tx or ty) and not b.tilt:
        raise InputError(f"{where}.config_theta_x_rad, config_theta_y_rad: a misalignment "
                         "needs the film coupled to the journal's rotations (tilt = true)")
    return tx, ty


def check_tilt_fields(b, where: str) -> None:
    """``tilt`` (bool) and the housing misalignment (config_theta_x_rad, config_theta_y_rad:
    finite, only with tilt, and not closing the film at an edge for a journal on the shaft
    line: sqrt(θx² + θy²)·L/2 < c)."""
    tx, ty = tilt_fields(b, where)
    edge = math.hypot(tx, ty) * 0.5 * b.length_m
    if not edge < b.clearance_m:
        raise ClosedFilmError(
            f"{where}.config_theta_x_rad, config_theta_y_rad: the misalignment closes the film"
            f" at an edge (|theta|·L/2 = {edge:g} m); expected sqrt(theta_x² + theta_y²)·"
            f"length_m/2 < clearance_m = {b.clearance_m:g} m")


def check_speeds(speeds_hz, max_hz: float = v.MAX_SPEED_HZ, why: str = "") -> np.ndarray:
    """Speeds of a standalone coefficient table (Hz): numbers, finite, nonzero, |f| ≤
    ``max_hz`` (an element whose film is solved on a mapped grid has a lower limit: ``why``)."""
    s = v.vector("speeds_hz", [speeds_hz] if np.ndim(speeds_hz) == 0 else speeds_hz)
    if s.size == 0 or np.any(s == 0):
        raise InputError(f"speeds_hz: expected a 1-D array of finite nonzero speeds, got "
                         f"{speeds_hz!r}")
    if np.any(np.abs(s) > max_hz):
        raise InputError(f"speeds_hz: expected |speed| <= {max_hz:.4g} Hz{why}, got "
                         f"{float(s[np.argmax(np.abs(s))])!r}")
    return s


def check_load(load_n) -> np.ndarray:
    if np.ndim(load_n) != 1 or np.size(load_n) != 2:
        raise InputError(f"load_n: expected two numbers (Fx, Fy) in N, got {load_n!r}")
    ld = v.vector("load_n", load_n, 2)
    if not np.hypot(*ld) > 0:
        raise InputError(f"load_n: expected a finite nonzero load (Fx, Fy) in N, got {load_n!r}")
    return ld



@dataclass
class PadFilm:
    """One pad's film: a C++ FilmCoupling plus the physical angles of its nodes."""

    coupling: "_core.FilmCoupling"
    phi: np.ndarray          # (N,) physical angle of each core node, rad (gap nodes: NaN)
    on_pad: np.ndarray       # (N,) bool
    scale: float             # s
    extra_labels: list = field(default_factory=list)


def arc_scale(arc_rad: float, n_circ: int) -> float:
    """s = β N / (2π m) of a pad of arc β mapped onto m intervals of an N = m + 2 node core
    grid (1 for a 360° film): the core solves the pad with diameter s·D at speed ω/s."""
    if abs(arc_rad - TWO_PI) < 1e-12:
        return 1.0
    m = max(10, int(round(n_circ * arc_rad / TWO_PI)))
    return arc_rad * (m + 2) / (TWO_PI * m)


def check_arc(field: str, arc_deg: float, b) -> None:
    """A pad or lobe arc long enough for its film: the mapped grid's diameter s·D must exceed
    twice the clearance (the core's film-geometry rule), i.e. the arc length must exceed
    about 4π·c (a shorter "pad" is a slit of the clearance's size, not a bearing pad)."""
    s = arc_scale(math.radians(arc_deg), b.n_circ)
    if not b.clearance_m < 0.5 * s * b.diameter_m:
        need = math.degrees(4 * math.pi * b.clearance_m / b.diameter_m / 1.2)
        raise InputError(f"{field}: expected an arc of more than about {need:.3g} deg for "
                         f"clearance_m = {b.clearance_m:g} and diameter_m = {b.diameter_m:g}, "
                         f"got {arc_deg!r}")


def speed_limit(films) -> tuple[float, str]:
    """The largest |speed| (Hz) of a table over ``films`` (PadFilm or couplings) and why it is
    below the solver's 1e5 Hz: a pad's film is solved at ω/s on its mapped grid."""
    s = min([p.scale for p in films if isinstance(p, PadFilm)] or [1.0])
    if s >= 1.0:
        return v.MAX_SPEED_HZ, ""
    return v.MAX_SPEED_HZ * s, (f" (the film solver's {v.MAX_SPEED_HZ:g} Hz on the pads' mapped "
                                f"grids, s = {s:.3g})")


def pad_film(*, name: str, diameter_m: float, length_m: float, clearance_m: float,
             viscosity_pa_s: float, cavitation: str, start_rad: float, arc_rad: float,
             pivot_rad: float, preload: float, n_circ: int, n_axial: int, coords: list[int],
             extra_shapes=(), supply_pressure_pa: float = 0.0, spin: float = 1.0,
             base_extra=None, end_seal_conductance: float | None = None,
             short_bearing: bool = False, pockets=(), turbulence: str = "laminar",
             density_kg_m3: float | None = None, turbulence_onset_re: float | None = None,
             turbulence_full_re: float | None = None) -> PadFilm:
    """Film coupling of one pad (or of a full 360° bush when ``arc_rad`` is 2π).

    ``extra_shapes``: callables φ (rad, pad nodes) → ∂h/∂r_k for coordinates beyond the
    journal's x, y (pad tilt, pivot displacement), in the order of ``coords[2:]``.
    ``base_extra(phi, z)``: optional (N_pad, n_axial+1) addition to the base film (smooth).
    ``pockets``: recesses (offset from the pad start rad, arc rad, z_min m, z_max m, depth m):
    steps in the film, passed to the core as exact edges (``_core.Pocket``), not sampled.
    ``n_circ``: nodes per 360° (the pad gets round(n_circ·β/2π) intervals, at least 10).
    ``end_seal_conductance``: G_s, m²/(Pa·s), of seals at both ends (Robin condition in the
    Reynolds core); None: open ends (p = 0 at z = ±L/2). ``short_bearing``: the core's
    short-bearing (Ocvirk) approximation (360° films only). ``turbulence``,
    ``density_kg_m3``: the turbulent lubrication model (``TURBULENCE_MODELS``) and the oil
    density of its film Reynolds number (the mapped grid keeps the pad's surface speed ωR);
    ``turbulence_onset_re``, ``turbulence_full_re``: its optional transition (None: none).
    """
    Cb = clearance_m
    Cp = Cb / (1.0 - preload)
    full = abs(arc_rad - TWO_PI) < 1e-12
    s = arc_scale(arc_rad, n_circ)
    if full:
        N = int(n_circ)
        m = N
        phi = start_rad + TWO_PI * np.arange(N) / N
        on = np.ones(N, dtype=bool)
        grooves = []
    else:
        m = max(10, int(round(n_circ * arc_rad / TWO_PI)))  # core grids need N >= 12
        N = m + 2
        j = np.arange(N)
        on = j <= m
        phi = np.where(on, start_rad + s * TWO_PI * j / N, np.nan)
        dc = 360.0 / N
        grooves = [_core.Groove(0.5 * (m + N) * dc, (N - m) * dc, float(supply_pressure_pa))]
    php = phi[on]
    base = np.full(N, GAP_FACTOR * Cp)
    base[on] = Cp - (Cp - Cb) * np.cos(php - pivot_rad)
    cols = [-np.cos(php), -np.sin(php)] + [np.asarray(f(php), dtype=float) for f in extra_shapes]
    shape = np.zeros((N, len(cols)))
    shape[on] = np.column_stack(cols)
    g = _core.JournalBearingGeometry()
    g.diameter_m = diameter_m * s
    g.length_m = length_m
    g.clearance_m = Cb
    g.viscosity_pa_s = viscosity_pa_s
    g.grooves = grooves
    if end_seal_conductance is not None:
        g.end_seal_conductance = float(end_seal_conductance)
    g.short_bearing = bool(short_bearing)
    set_turbulence(g, turbulence, density_kg_m3, turbulence_onset_re, turbulence_full_re)
    g.pockets = [_core.Pocket(math.degrees(a / s), math.degrees(arc / s), z0, z1, d)
                 for a, arc, z0, z1, d in pockets]  # core angle = (φ − start) / s
    f = _core.FilmCoupling()
    f.name = name
    f.geometry = g
    f.grid = _core.FilmGrid(N, int(n_axial))
    f.cavitation = cavitation
    f.coords = [int(c) for c in coords]
    f.shape = shape
    if base_extra is not None:
        z = np.linspace(-0.5 * length_m, 0.5 * length_m, int(n_axial) + 1)
        b2 = np.repeat(base[:, None], int(n_axial) + 1, axis=1)
        b2[on] += base_extra(php, z)
        f.base_h = b2
    elif not (full and preload == 0.0):
        f.base_h = base[:, None]
    f.spin_factor = spin / s
    return PadFilm(f, phi, on, s)


@dataclass
class SystemParts:
    """What a bearing element adds to the system of eq. 12-13: films and tables on the journal
    coordinates (and on its own extra coordinates), and M, K, C over [journal x, journal y,
    extras...] ((2 + n_extra) square; the extras' inertia may couple to the journal)."""

    films: list
    tables: list
    n_extra: int = 0
    M: np.ndarray | None = None
    K: np.ndarray | None = None
    C: np.ndarray | None = None
    labels: tuple = ()
    penalty: np.ndarray | None = None  # homotopy penalty over [x, y, extras] (pads only)
    # per pad, its own coordinates (indices into [x, y, extras]: tilt, then pivot): the C++
    # equilibrium solves them pad by pad (SystemModel.pad_coords, pad_equilibrium.cpp)
    pad_groups: list = field(default_factory=list)
    # per pad group, 1 if its last coordinate is the pad's pitch (spherical pivot, journal
    # tilt; SystemModel.pad_pitch), else 0; empty: none
    pad_pitch: list = field(default_factory=list)


def standalone_model(parts: SystemParts, load_n) -> "_core.SystemModel":
    """The core model of a standalone bearing: the journal's x, y (coordinates 0, 1, loaded by
    ``load_n`` (Fx, Fy) N) and the extras after them with their structural M, K, C; the films
    (pads' couplings), tables and pad coordinate groups of ``parts``."""
    n = 2 + parts.n_extra
    model = _core.SystemModel()
    M, K, C = np.zeros((n, n)), np.zeros((n, n)), np.zeros((n, n))
    if parts.n_extra:
        M += parts.M
        K += parts.K
        C += parts.C
    model.M, model.K, model.C, model.G = M, K, C, np.zeros((n, n))
    Q = np.zeros(n)
    Q[:2] = load_n
    model.Q = Q
    model.chamber = np.zeros(n)
    model.films = [p.coupling if isinstance(p, PadFilm) else p for p in parts.films]
    model.tables = parts.tables
    model.pad_coords = [list(g) for g in parts.pad_groups]
    model.pad_pitch = [int(p) for p in parts.pad_pitch]
    return model


def operating_table(parts: SystemParts, load_n, speeds_hz, *, n_threads: int = 1,
                    tol: float = 1e-10, info: dict | None = None):
    """Equilibrium + linearisation of a standalone bearing (journal x, y = coordinates 0, 1,
    extras after) at each speed: r (n_s, n); K, C (n_s, n, n) = film K_H, D_H plus the extra
    coordinates' structural K, C (pivot stiffness); status, message; M (n, n). ``info``
    (optional dict) receives ``path`` and ``reynolds_solves`` per speed (tuples)."""
    model = standalone_model(parts, load_n)
    n = 2 + parts.n_extra
    M, K, C = (np.array(a, dtype=float) for a in (model.M, model.K, model.C))  # structural
    opt = _core.EquilibriumOptions()
    opt.tol = tol
    w = np.ascontiguousarray(np.asarray(speeds_hz, dtype=float) * TWO_PI)
    pen = parts.penalty if parts.penalty is not None else np.zeros((0, 0))
    res = _core.operating_points(model, w, np.zeros(n), np.zeros(0), opt, int(n_threads), pen)
    ns = len(w)
    if info is not None:
        info["path"] = tuple(res.path)
        info["reynolds_solves"] = tuple(int(x) for x in res.reynolds_solves)
    return (np.asarray(res.r), np.asarray(res.KH).reshape(ns, n, n) + K,
            np.asarray(res.DH).reshape(ns, n, n) + C, list(res.status), list(res.message), M)


def reduce_coefficients(KH, DH, M, nu, n_journal: int = 2):
    """Condense extra (pad) coordinates at the whirl frequency ν (rad/s): the journal's
    impedance Z = Z_jj − Z_jp Z_pp⁻¹ Z_pj with Z = K + iνC − ν²M over its first ``n_journal``
    coordinates (2: x, y; 4: x, y, θx, θy of a tilting journal); K = Re Z, C = Im Z / ν.
    ν = 0 gives the static condensation of K and the limit of C."""
    if KH.shape[0] == n_journal:
        return KH.copy(), DH.copy()
    if nu == 0.0:
        nu = 1e-9 * max(1.0, np.abs(KH).max() / max(np.abs(DH).max(), 1e-300))
    Z = KH + 1j * nu * DH - nu ** 2 * M
    j, p = slice(0, n_journal), slice(n_journal, None)
    Zr = Z[j, j] - Z[j, p] @ np.linalg.solve(Z[p, p], Z[p, j])
    return Zr.real.copy(), Zr.imag / nu


def imposed_tilt(f: _core.FilmCoupling, theta_x: float, theta_y: float) -> _core.FilmCoupling:
    """The film ``f`` on (x, y, θx, θy) turned into a film on (x, y) alone with the tilt
    (θx, θy) in its base thickness: base_h + S(·, 2)·w(2, ·)·θx + S(·, 3)·w(3, ·)·θy
    (n_circ, n_axial + 1); ``f`` keeps its first two coordinates."""
    S, W = np.asarray(f.shape), np.asarray(f.axial_weight)
    n, k1 = S.shape[0], W.shape[1]
    b = np.asarray(f.base_h)
    base = np.full((n, k1), f.geometry.clearance_m) if b.size == 0 else np.broadcast_to(
        b.reshape(n, -1), (n, k1)).copy()
    base += np.outer(S[:, 2], W[2] * theta_x) + np.outer(S[:, 3], W[3] * theta_y)
    f.base_h = np.ascontiguousarray(base)
    f.coords = list(f.coords)[:2]
    f.shape = np.ascontiguousarray(S[:, :2])
    f.axial_weight = np.zeros((0, 0))
    return f


def min_film(s, phis=None) -> tuple[float, float, float]:
    """(h_min m, its angle deg, its z m) over the solver's films (the thinnest one's; a lobe's
    core-grid angle mapped to its physical angle with ``phis``)."""
    h = np.asarray(s.last_h_min, dtype=float)
    i = int(np.argmin(h))
    a = float(s.last_h_min_angle_deg[i])
    if phis is not None:
        a = lobe_angle(a, phis[i])
    return float(h[i]), a, float(s.last_h_min_z_m[i])


def lobe_angle(a: float, phi) -> float:
    """A lobe's core-grid angle ``a`` (deg) as its physical angle (deg in [0, 360); NaN on
    a gap node), ``phi`` the lobe's node angles (rad)."""
    j = int(round(a / 360.0 * len(phi))) % len(phi)
    return float(np.degrees(phi[j]) % 360.0) if np.isfinite(phi[j]) else math.nan
