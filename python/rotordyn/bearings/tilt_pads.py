"""Journal tilt and misalignment in a tilting-pad bearing, standalone (issue 20).

The journal's pose (x, y, θx, θy) at the bearing centre uses the plain bearing's convention
(:mod:`rotordyn.bearings.tilt`: at the axial position z the journal centre is at
(x + θy z, y − θx z)). Every pad's film carries the journal's tilt; the pads keep their own
coordinates (:meth:`TiltingPadBearing.system_parts` with ``rot``: η_k, the pivot u_k with a
flexible pivot, the pitch γ_k with ``pivot_type = "spherical"``), and for a journal held at a
pose each pad sits at its own equilibrium (the C++ pad assembly, ``pad_equilibrium.cpp``):

* :func:`pad_tilted_forces`: forces (N) and moments (N·m) on the journal at a pose, the pads
  in equilibrium; per pad its tilt, pitch and edge film, the thinnest pad's film and where;
* :func:`pad_tilted_coefficients`: the 4×4 K, C over (x, y, θx, θy) with the pad coordinates
  condensed at the whirl frequency ν = whirl_ratio·Ω (Z = K + iνC − ν²M, as
  :meth:`TiltingPadBearing.coefficient_table` does for the 2×2);
* :func:`pad_misaligned_equilibrium`: the journal's (x, y) under a load at an imposed tilt,
  the pads free.

``rotordyn.bearings.tilted_forces``, ``tilted_coefficients`` and ``misaligned_equilibrium``
call these for a :class:`TiltingPadBearing`. A pose is held by writing it into the pads'
base film (the journal's columns summed into ``base_h``); the pads' coordinates are then the
model's only ones (a spherical pad's pitch measured from the journal's slope along its pivot
line, γ_k = θ·t_k, so the base film stays open), and the equilibrium is the same C++ Newton
with the pad assembly as in a system.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import reduce_coefficients, speed_limit
from rotordyn.bearings.tilt_names import RenamedTiltOutputs
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi
N_JOURNAL = 4  # x, y, θx, θy


class _Layout:
    """The bearing's pads on [x, y, θx, θy, pad coordinates]: films, structural K, M and the
    pad groups; a film solver over all of them (model A); the pitch offsets' geometry."""

    def __init__(self, b):  # b: a TiltingPadBearing (not imported: its class calls this module)
        self.b = b
        self.parts = p = b.system_parts(0, 1, N_JOURNAL, b.name or "bearing", rot=(2, 3))
        self.n = n = p.n_extra
        self.npd = n // b.n_pads
        self.pitch = bool(p.pad_pitch and p.pad_pitch[0])
        idx = [0, 1] + list(range(N_JOURNAL, N_JOURNAL + n))
        N = N_JOURNAL + n
        self.K = np.zeros((N, N))
        self.M = np.zeros((N, N))
        self.K[np.ix_(idx, idx)] = p.K
        self.M[np.ix_(idx, idx)] = p.M
        self.psi = np.radians(b.pivot_angles_deg())
        model = _core.SystemModel()
        model.M, model.K = self.M, self.K
        model.C, model.G = np.zeros((N, N)), np.zeros((N, N))
        model.Q, model.chamber = np.zeros(N), np.zeros(N)
        model.films = [f.coupling for f in p.films]
        self.solver = _core.SystemSolver(model)
        self.phis = [f.phi for f in p.films]

    def pitch_offsets(self, theta_x: float, theta_y: float) -> np.ndarray:
        """(n,) the pads' coordinates' origin of a held pose: γ_k = θ·t_k (the pad parallel to
        the journal along its pivot line) on the pitches, 0 elsewhere."""
        p0 = np.zeros(self.n)
        if self.pitch:
            p0[self.npd - 1::self.npd] = theta_y * np.cos(self.psi) - theta_x * np.sin(self.psi)
        return p0

    def baked(self, keep_journal: list[int], pose: np.ndarray, p0: np.ndarray) -> list:
        """Films with the journal coordinates not in ``keep_journal`` held at ``pose`` (their
        columns summed into base_h) and the pads' coordinates measured from ``p0``; the kept
        coordinates renumbered [kept journal coordinates, pads]."""
        out = []
        nk = len(keep_journal)
        for pf in self.parts.films:
            f = pf.coupling
            S = np.asarray(f.shape)
            W = np.asarray(f.axial_weight)
            n_c, k1 = S.shape[0], W.shape[1]
            b = np.asarray(f.base_h)
            base = (np.full((n_c, k1), f.geometry.clearance_m) if b.size == 0 else
                    np.broadcast_to(b.reshape(n_c, -1), (n_c, k1)).copy())
            coords = list(f.coords)
            keep = []
            for loc, c in enumerate(coords):
                if c < N_JOURNAL and c not in keep_journal:
                    base += np.outer(S[:, loc], W[loc] * pose[c])
                    continue
                if c >= N_JOURNAL and p0[c - N_JOURNAL] != 0.0:
                    base += np.outer(S[:, loc], W[loc] * p0[c - N_JOURNAL])
                keep.append(loc)
            g = _core.FilmCoupling()
            g.name, g.geometry, g.grid, g.cavitation = f.name, f.geometry, f.grid, f.cavitation
            g.spin_factor = f.spin_factor
            if np.asarray(f.viscosity_field).size:  # a frozen (thermal) field stays the pad's
                g.viscosity_field = f.viscosity_field
            g.coords = [keep_journal.index(coords[loc]) if coords[loc] < N_JOURNAL
                        else nk + coords[loc] - N_JOURNAL for loc in keep]
            g.shape = np.ascontiguousarray(S[:, keep])
            Wk = W[keep]
            if not np.all(Wk == 1.0):
                g.axial_weight = np.ascontiguousarray(Wk)
            g.base_h = np.ascontiguousarray(base)
            out.append(g)
        return out

    def model(self, keep_journal: list[int], pose, p0, load) -> "_core.SystemModel":
        """The core model over [kept journal coordinates, pads] with the rest of the pose
        held: K, the load ``load`` (on the kept journal coordinates) less the held
        coordinates' and offsets' K terms."""
        held = [c for c in range(N_JOURNAL) if c not in keep_journal]
        kept = keep_journal + list(range(N_JOURNAL, N_JOURNAL + self.n))
        full = np.concatenate([np.asarray(pose, dtype=float), p0])
        m = _core.SystemModel()
        K = self.K[np.ix_(kept, kept)]
        N = len(kept)
        m.M, m.K, m.C, m.G = np.zeros((N, N)), K, np.zeros((N, N)), np.zeros((N, N))
        Q = np.zeros(N)
        Q[:len(keep_journal)] = load
        off = full.copy()
        off[keep_journal] = 0.0
        Q -= self.K[np.ix_(kept, held + kept)] @ off[held + kept]
        m.Q, m.chamber = Q, np.zeros(N)
        m.films = self.baked(keep_journal, np.asarray(pose, dtype=float), p0)
        shift = N_JOURNAL - len(keep_journal)
        m.pad_coords = [[c + 2 - shift for c in g] for g in self.parts.pad_groups]
        m.pad_pitch = [int(q) for q in self.parts.pad_pitch]
        return m

    def pads(self, r_full: np.ndarray):
        """Pad tilts δ_k and pitches γ_k (rad; 0 for rocker pads) from r = [pose, pads]."""
        ex = r_full[N_JOURNAL:]
        eta = ex[0::self.npd][: self.b.n_pads]
        qt = -r_full[0] * np.sin(self.psi) + r_full[1] * np.cos(self.psi)
        gam = ex[self.npd - 1::self.npd] if self.pitch else np.zeros(self.b.n_pads)
        return (eta - qt) / self.b.lever_m, np.asarray(gam, dtype=float)


_local = threading.local()


def _layout(b) -> _Layout:
    """This thread's layout of ``b`` (a few bearings kept)."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = {}
    hit = cache.get(b)
    if hit is None:
        if len(cache) >= 8:
            cache.pop(next(iter(cache)))
        hit = cache[b] = _Layout(b)
    return hit


def _options(tol: float) -> "_core.EquilibriumOptions":
    opt = _core.EquilibriumOptions()
    opt.tol = tol
    opt.polish = True
    return opt


def check_pad_pose(b, x_m, y_m, theta_x_rad, theta_y_rad,
                   names=("x_m", "y_m", "theta_x_rad", "theta_y_rad")) -> tuple[float, ...]:
    """Finite coordinates whose journal leaves every pad's film open at both edges with the
    pads untilted (and spherical pads pitched to the journal): InputError naming the field."""
    vals = tuple(v.finite(n, val) for n, val in zip(names, (x_m, y_m, theta_x_rad, theta_y_rad)))
    h, z, k = b.edge_film(*vals)
    if not h > 0.0:
        raise InputError(
            f"{names[2]}, {names[3]}: the tilted journal closes pad {k}'s film at the edge "
            f"z = {z:+g} m (minimum film {h:.6g} m with the pads untilted); expected a pose "
            f"whose film stays > 0 over the pads at z = ±L/2")
    return vals


def _speed(b, speed_hz) -> float:
    f = v.finite("speed_hz", speed_hz)
    top, why = speed_limit(_layout(b).parts.films)
    if f == 0.0 or abs(f) > top:
        raise InputError(f"speed_hz: expected 0 < |speed_hz| <= {top:.4g} Hz{why} (the pads' "
                         f"equilibrium needs a spinning journal), got {f!r}")
    return f


def _pad_equilibrium(b, pose: np.ndarray, omega: float, tol: float):
    """(r over [pose, pads], equilibrium result of the pads): each pad balanced for the held
    pose (a failure raises ConvergenceError with the core's message)."""
    lay = _layout(b)
    p0 = lay.pitch_offsets(pose[2], pose[3])
    model = lay.model([], pose, p0, np.zeros(0))
    e = _core.SystemSolver(model).equilibrium(omega, 0.0, np.zeros(lay.n), np.zeros(0),
                                              _options(tol))
    if e.status not in ("ok", "contact"):
        from rotordyn.errors import ConvergenceError

        raise ConvergenceError(f"tilting-pad bearing: the pads' equilibrium at the pose "
                               f"failed ({e.status}): {e.message}")
    return np.concatenate([pose, np.asarray(e.r) + p0]), e


@dataclass(frozen=True)
class PadTiltedFilm(RenamedTiltOutputs):
    """The film of a tilting-pad bearing on a journal held at a pose, every pad at its
    equilibrium: forces (Fx, Fy) N and moments (Mx, My) N·m on the journal about the bearing
    centre; the thinnest pad's minimum film (m) and where it is (φ deg from +x, z m); per pad
    (n_pads,): its tilt δ_k and pitch γ_k (rad; 0 for rocker pads), minimum film (m) and its
    axial position (m); ``r`` the coordinates [x, y, θx, θy, pad coordinates];
    ``unloaded_pads`` the pads without a pressured equilibrium."""

    force_n: np.ndarray
    film_moment_n_m: np.ndarray
    h_min_m: float
    h_min_angle_deg: float
    h_min_z_m: float
    pad_tilts_rad: np.ndarray
    pad_pitches_rad: np.ndarray
    pad_h_min_m: np.ndarray
    pad_h_min_z_m: np.ndarray
    r: np.ndarray
    unloaded_pads: int

    def to_frame(self):
        """One row per pad: its tilt, pitch and minimum film, with the journal's forces and
        moments on every row."""
        import pandas as pd

        n = len(self.pad_tilts_rad)
        return pd.DataFrame({
            "pad": np.arange(n), "pad_tilt_rad": self.pad_tilts_rad,
            "pad_pitch_rad": self.pad_pitches_rad, "h_min_m": self.pad_h_min_m,
            "h_min_z_m": self.pad_h_min_z_m,
            "force_x_n": np.full(n, self.force_n[0]), "force_y_n": np.full(n, self.force_n[1]),
            "film_moment_x_n_m": np.full(n, self.film_moment_n_m[0]),
            "film_moment_y_n_m": np.full(n, self.film_moment_n_m[1])})


def _film_at(lay: _Layout, r_full: np.ndarray, omega: float, unloaded: int) -> PadTiltedFilm:
    s = lay.solver
    H = np.asarray(s.film_forces(r_full, np.zeros(len(r_full)), omega))
    # the force on the journal at fixed pad tilts: H_q + Σ t_k H_η_k (the film's force on the
    # journal's q at fixed η misses the part through η = q·t_k + ℓ δ_k; H_η_k vanishes at a
    # balanced pad without a tilt spring)
    F = H[:2] + np.array([-np.sin(lay.psi), np.cos(lay.psi)]) @ H[N_JOURNAL::lay.npd][
        : lay.b.n_pads]
    h = np.asarray(s.last_h_min, dtype=float)
    hz = np.asarray(s.last_h_min_z_m, dtype=float)
    i = int(np.argmin(h))
    phi = lay.phis[i]
    j = int(round(float(s.last_h_min_angle_deg[i]) / 360.0 * len(phi))) % len(phi)
    ang = float(np.degrees(phi[j]) % 360.0) if np.isfinite(phi[j]) else math.nan
    tilts, pitches = lay.pads(r_full)
    return PadTiltedFilm(force_n=F, film_moment_n_m=H[2:4].copy(), h_min_m=float(h[i]),
                         h_min_angle_deg=ang, h_min_z_m=float(hz[i]), pad_tilts_rad=tilts,
                         pad_pitches_rad=pitches, pad_h_min_m=h.copy(), pad_h_min_z_m=hz.copy(),
                         r=r_full.copy(), unloaded_pads=int(unloaded))


def pad_tilted_forces(b, *, x_m: float, y_m: float, speed_hz: float,
                      theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                      tol: float = 1e-10) -> PadTiltedFilm:
    """Forces and moments on a journal held at (x, y) m tilted by (θx, θy) rad, every pad at
    its equilibrium for that pose (tilt, pivot, pitch), at ``speed_hz``."""
    pose = np.array(check_pad_pose(b, x_m, y_m, theta_x_rad, theta_y_rad))
    w = TWO_PI * _speed(b, speed_hz)
    r, e = _pad_equilibrium(b, pose, w, v.in_range("tol", tol, 1e-14, 1e-2))
    return _film_at(_layout(b), r, w, e.unloaded_pads)


def pad_tilted_coefficients(b, *, x_m: float, y_m: float, speed_hz: float,
                            theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                            whirl_ratio: float | None = 1.0, method: str = "perturbation",
                            rel_step: float = 1e-6, full: bool = False):
    """K, C (4×4 over x, y, θx, θy; ΔH = −K Δr − C Δṙ) of the journal at a pose with the pads
    at their equilibrium and their coordinates condensed at ν = ``whirl_ratio``·Ω (1:
    synchronous; None: static condensation). ``method``: ``"perturbation"`` (linearised
    Reynolds solves) or ``"finite_difference"`` (central differences of the pads' films, steps
    ``rel_step``·c) for the unreduced coefficients. ``full=True`` returns the unreduced
    (r, K, C, M) over [x, y, θx, θy, pad coordinates] instead (K, M with the pads' structural
    terms)."""
    pose = np.array(check_pad_pose(b, x_m, y_m, theta_x_rad, theta_y_rad))
    f = _speed(b, speed_hz)
    w = TWO_PI * f
    if whirl_ratio is not None:
        v.finite("whirl_ratio", whirl_ratio)
    r, _ = _pad_equilibrium(b, pose, w, 1e-10)
    lay = _layout(b)
    if method == "perturbation":
        lin = lay.solver.linearize(r, np.zeros(len(r)), w)
    elif method == "finite_difference":
        lin = lay.solver.linearize_fd(r, w, v.in_range("rel_step", rel_step, 1e-10, 0.1,
                                                       hi_open=True))
    else:
        raise InputError(f"method: expected 'perturbation' or 'finite_difference', got {method!r}")
    K = np.asarray(lin.KH) + lay.K
    C = np.asarray(lin.DH)
    if full:
        return r, K, C, lay.M.copy()
    nu = 0.0 if whirl_ratio is None else whirl_ratio * abs(w)
    return reduce_coefficients(K, C, lay.M, nu, N_JOURNAL)


@dataclass(frozen=True)
class PadMisalignedEquilibrium(RenamedTiltOutputs):
    """The journal of a tilting-pad bearing under a static load at an imposed tilt (θx, θy)
    relative to the bearing, the pads free: position (m), eccentricity ratio and attitude at
    the mid-plane, forces (N) and moments (N·m) on the journal, the thinnest pad's minimum film
    and where it is, per pad tilt, pitch and minimum film (:class:`PadTiltedFilm`'s fields in
    ``film``), status, message, iterations and how the start was reached (``path``); with
    ``coefficients=True`` the 4×4 ``K``, ``C`` there (as :func:`pad_tilted_coefficients`),
    else None."""

    x_m: float
    y_m: float
    journal_theta_x_rad: float
    journal_theta_y_rad: float
    eccentricity_ratio: float
    attitude_angle_deg: float
    force_n: np.ndarray
    film_moment_n_m: np.ndarray
    h_min_m: float
    h_min_angle_deg: float
    h_min_z_m: float
    status: str
    message: str
    iterations: int
    path: str
    film: PadTiltedFilm | None
    K: np.ndarray | None = None
    C: np.ndarray | None = None

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame([{
            "x_m": self.x_m, "y_m": self.y_m, "journal_theta_x_rad": self.journal_theta_x_rad,
            "journal_theta_y_rad": self.journal_theta_y_rad,
            "eccentricity_ratio": self.eccentricity_ratio,
            "attitude_angle_deg": self.attitude_angle_deg,
            "force_x_n": self.force_n[0], "force_y_n": self.force_n[1],
            "film_moment_x_n_m": self.film_moment_n_m[0],
            "film_moment_y_n_m": self.film_moment_n_m[1],
            "h_min_m": self.h_min_m, "h_min_angle_deg": self.h_min_angle_deg,
            "h_min_z_m": self.h_min_z_m, "status": self.status, "message": self.message}])


def pad_misaligned_equilibrium(b, *, load_n, speed_hz: float,
                               theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                               tol: float = 1e-10, coefficients: bool = False,
                               whirl_ratio: float | None = 1.0) -> PadMisalignedEquilibrium:
    """(x, y) where the pads' films balance ``load_n`` (N, on the journal) with the journal
    tilted by (θx, θy) rad, pads free (the C++ equilibrium with the pad assembly, the tilt
    homotopy as fallback); then the forces, moments and films there. ``coefficients=True``:
    also the operating point's 4×4 K, C over (x, y, θx, θy), the pads condensed at ν =
    ``whirl_ratio``·Ω (None: static), linearised about this equilibrium's own films —
    :func:`pad_tilted_coefficients` at (x, y) re-solves the pads at the held pose from the
    cold start (the same root to the tolerance, a second pad solve)."""
    if isinstance(load_n, (str, bytes)) or len(np.atleast_1d(load_n)) != 2:
        raise InputError(f"load_n: expected two numbers (Fx, Fy) in N, got {load_n!r}")
    lx, ly = v.finite("load_n[0]", load_n[0]), v.finite("load_n[1]", load_n[1])
    v.boolean("coefficients", coefficients)
    if whirl_ratio is not None:
        v.finite("whirl_ratio", whirl_ratio)
    _, _, tx, ty = check_pad_pose(b, 0.0, 0.0, theta_x_rad, theta_y_rad)
    f = _speed(b, speed_hz)
    w = TWO_PI * f
    lay = _layout(b)
    pose = np.array([0.0, 0.0, tx, ty])
    p0 = lay.pitch_offsets(tx, ty)
    model = lay.model([0, 1], pose, p0, np.array([lx, ly]))
    n = 2 + lay.n
    idx = [0, 1] + list(range(N_JOURNAL, N_JOURNAL + lay.n))
    pen = np.asarray(lay.parts.penalty)
    e = _core.pad_system_equilibrium(_core.SystemSolver(model), model, w, 0.0, np.zeros(n),
                                     np.zeros(0), np.zeros(0),
                                     _options(v.in_range("tol", tol, 1e-14, 1e-2)), pen)
    status, message = str(e.status), str(e.message)
    r = np.zeros(N_JOURNAL + lay.n)
    r[idx] = np.asarray(e.r)
    r[2], r[3] = tx, ty
    r[N_JOURNAL:] += p0
    x, y = float(r[0]), float(r[1])
    nan2 = np.full(2, np.nan)
    if status not in ("ok", "contact"):
        return PadMisalignedEquilibrium(x, y, tx, ty, math.nan, math.nan, nan2, nan2, math.nan,
                                        math.nan, math.nan, status, message,
                                        int(e.iterations), str(e.path), None)
    film = _film_at(lay, r, w, e.unloaded_pads)
    K = C = None
    if coefficients:  # the films' solve at r is reused (same coordinates)
        lin = lay.solver.linearize(r, np.zeros(len(r)), w)
        nu = 0.0 if whirl_ratio is None else whirl_ratio * abs(w)
        K, C = reduce_coefficients(np.asarray(lin.KH) + lay.K, np.asarray(lin.DH), lay.M, nu,
                                   N_JOURNAL)
    W = math.hypot(lx, ly)
    att = math.nan
    if W > 0.0 and (x != 0.0 or y != 0.0):
        dx, dy = lx / W, ly / W
        att = math.degrees(math.atan2(dx * y - dy * x, dx * x + dy * y))
        att = -att if f < 0 else att
    return PadMisalignedEquilibrium(
        x_m=x, y_m=y, journal_theta_x_rad=tx, journal_theta_y_rad=ty,
        eccentricity_ratio=math.hypot(x, y) / b.clearance_m, attitude_angle_deg=att,
        force_n=film.force_n, film_moment_n_m=film.film_moment_n_m, h_min_m=film.h_min_m,
        h_min_angle_deg=film.h_min_angle_deg, h_min_z_m=film.h_min_z_m, status=status,
        message=message, iterations=int(e.iterations), path=str(e.path), film=film, K=K, C=C)


__all__ = ["PadTiltedFilm", "PadMisalignedEquilibrium", "pad_tilted_forces",
           "pad_tilted_coefficients", "pad_misaligned_equilibrium", "check_pad_pose"]
