"""Assembly of the system of eq. 12-13 for the C++ core: condensed rotor + sleeve coordinates,
gravity, chamber loads and one film coupling per fluid-film bearing.

Coordinates r = [q (rotor: masters' x, y in station order, or every free FE DOF when the
reduction is "none"); r_s (each active bearing's sleeve masters, inward, in bearing order)].
An ``Assembled`` object is cached per (system, thread), so repeated operating points reuse the
reduction, the sleeve condensation and the Reynolds factorisations (warm starts).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np

from rotordyn import _core
from rotordyn._common.calls import current_epoch
from rotordyn.analysis.modes import rotor_matrices
from rotordyn.errors import InputError
from rotordyn._common import validate as v
from rotordyn.bearings import ActiveJournalBearing
from rotordyn.model.system import System


@dataclass
class BearingCoords:
    """Where bearing ``index`` sits in r: journal x, y and its sleeve coordinates."""

    index: int
    name: str
    jx: int
    jy: int
    sleeve: tuple[int, ...]
    clearance_m: float
    active: bool
    extra: tuple[int, ...] = ()  # the element's own coordinates (pad tilts, pivots)
    rot: tuple[int, ...] = ()    # the station's θx, θy when the film couples to them (tilt)
    labels: tuple[str, ...] = ()  # the own coordinates' labels (``name.pad0.eta`` …)


def gravity_load(system: System) -> np.ndarray:
    """(4 n_nodes,) consistent gravity load −g M e_y of the free-free rotor FE model (N, N·m),
    e_y = 1 at every node's y translation (gravity along −y)."""
    n_nodes = system.rotor.n_elements + 1
    return -system.gravity_m_s2 * np.asarray(system.M() @ np.tile([0.0, 1.0, 0.0, 0.0],
                                                                   n_nodes))


class Assembled:
    """The C++ ``SystemModel`` and ``SystemSolver`` of a System, with the index maps.

    Rotating shaft damping (``rotor.damping_rotating``): the model's ``Kc`` holds the
    circulatory stiffness K_c per unit spin speed on the rotor coordinates
    (:meth:`RotorMatrices.circulatory`, zero on sleeves and pads); the solver adds −Ω K_c r to
    H and Ω K_c to K_H, so every analysis built on H carries it (``Kc`` is empty without
    it, bit for bit the stationary model)."""

    def __init__(self, system: System):
        self.system = system
        self.rotor = rotor_matrices(system)
        M, K, C, G = self.rotor.matrices()
        n_r = M.shape[0]
        nodes = system.rotor.station_nodes()

        # Gravity: consistent nodal loads −g M e_y, e_y the rigid vertical translation of every
        # node (the fixed ones too: an element beside a rigid support loads its free node with
        # its whole shape-function integral), on the free DOFs, condensed.
        full = self.rotor.full
        dofs = np.asarray(full.dofs)
        q_full = gravity_load(system)[dofs]
        Q_r = q_full if self.rotor.reduction is None else np.asarray(self.rotor.reduction.T).T @ q_full

        def journal_index(station: int) -> tuple[int, int]:
            if self.rotor.reduction is None:
                return full.local(int(4 * nodes[station])), full.local(int(4 * nodes[station] + 1))
            i = list(system.reduction.master_stations).index(station)
            return 2 * i, 2 * i + 1

        def rotation_index(station: int, where: str) -> tuple[int, int]:
            """θx, θy of a station in r (masters after the translations when reduced)."""
            if self.rotor.reduction is None:
                out = (full.local(int(4 * nodes[station] + 2)),
                       full.local(int(4 * nodes[station] + 3)))
                if min(out) < 0:
                    raise InputError(f"{where}.tilt: the rotations of station {station} are "
                                     "fixed; a tilting film needs them free")
                return out
            k = 2 * len(system.reduction.master_stations) + 2 * system.tilt_stations().index(
                station)
            return k, k + 1

        blocks_M, blocks_K, blocks_C, chambers = [], [], [], []
        self.bearings: list[BearingCoords] = []
        self.sleeves = {}
        self.extra_labels: list[str] = []
        films, tables = [], []
        pad_coords = []  # tilting pads' own coordinates, per pad (pad-assembly equilibrium)
        pad_pitch = []   # per pad: 1 if its last coordinate is a pitch (spherical pivot)
        coupled = []  # (indices [jx, jy, extras], M, K, C) of elements with own coordinates
        self.film_owner: list[int] = []  # bearing index of each C++ film
        self.film_phi: list = []         # physical node angles of each film (None: core grid)
        n = n_r
        for bi, b in enumerate(system.bearings):
            jx, jy = journal_index(b.station)
            if hasattr(b, "system_parts"):  # rotordyn.bearings elements
                name = b.name or f"bearing[{bi}]"
                rot: tuple[int, ...] = ()
                if getattr(b, "tilt", False):  # lobes' and pads' films tilt too
                    rot = rotation_index(b.station, f"bearings[{bi}]")
                    parts = b.system_parts(jx, jy, n, name, rot=rot)
                else:
                    parts = b.system_parts(jx, jy, n, name)
                films += [p.coupling for p in parts.films]
                self.film_owner += [bi] * len(parts.films)
                self.film_phi += [p.phi for p in parts.films]
                tables += parts.tables
                extra = tuple(range(n, n + parts.n_extra))
                if parts.n_extra:
                    z = np.zeros((parts.n_extra, parts.n_extra))
                    blocks_M.append(z)
                    blocks_K.append(z)
                    blocks_C.append(z)
                    coupled.append(([jx, jy] + list(extra), parts.M, parts.K, parts.C,
                                    parts.penalty))
                    loc = [jx, jy] + list(extra)
                    pad_coords += [[loc[i] for i in g] for g in parts.pad_groups]
                    pad_pitch += (list(parts.pad_pitch) or [0] * len(parts.pad_groups))
                    self.extra_labels += list(parts.labels)
                    n += parts.n_extra
                self.bearings.append(BearingCoords(bi, name, jx, jy, (),
                                                   getattr(b, "clearance_m", 0.0), False, extra,
                                                   rot=rot, labels=tuple(parts.labels)))
                continue
            jb = b.journal_bearing()
            g, grid = jb.to_core()
            phi = 2 * np.pi * np.arange(b.n_circ) / b.n_circ
            shape = [-np.cos(phi), -np.sin(phi)]
            coords = [jx, jy]
            sleeve_idx: tuple[int, ...] = ()
            if isinstance(b, ActiveJournalBearing):
                res = b.sleeve.condense()
                self.sleeves[bi] = res
                W = res.interpolation_matrix(phi)
                nm = W.shape[1]
                sleeve_idx = tuple(range(n, n + nm))
                coords += list(sleeve_idx)
                shape += [-W[:, j] for j in range(nm)]
                start = None if b.chamber_start_deg is None else np.radians(b.chamber_start_deg)
                end = None if b.chamber_end_deg is None else np.radians(b.chamber_end_deg)
                blocks_M.append(res.mass_matrix)
                blocks_K.append(res.stiffness_matrix)
                blocks_C.append(np.zeros_like(res.mass_matrix))
                chambers.append((sleeve_idx, res.chamber_load(start, end)))
                n += nm
            rot: tuple[int, ...] = ()
            weight = None
            if getattr(b, "tilt", False):
                # h = c − (x + θy z) cos φ − (y − θx z) sin φ (rotor.hpp: dx/dz = θy,
                # dy/dz = −θx): the rotations' shapes sin φ, −cos φ with axial weight z
                rot = rotation_index(b.station, f"bearings[{bi}]")
                coords += list(rot)
                shape += [np.sin(phi), -np.cos(phi)]
                z = np.linspace(-0.5 * b.length_m, 0.5 * b.length_m, b.n_axial + 1)
                weight = np.ones((len(coords), b.n_axial + 1))
                weight[-2:] = z
            f = _core.FilmCoupling()
            f.name = b.name or f"bearing[{bi}]"
            f.geometry, f.grid, f.cavitation = g, grid, b.cavitation
            f.coords = [int(c) for c in coords]
            f.shape = np.column_stack(shape)
            if weight is not None:
                f.axial_weight = weight
            vf = getattr(b, "viscosity_field_pa_s", None)
            if vf is not None:  # a THD film's frozen temperature field
                f.viscosity_field = np.asarray(vf, dtype=float)
            films.append(f)
            self.film_owner.append(bi)
            self.film_phi.append(None)
            self.bearings.append(BearingCoords(bi, f.name, jx, jy, sleeve_idx, b.clearance_m,
                                               isinstance(b, ActiveJournalBearing), rot=rot))

        def block(A_r, blocks):
            out = np.zeros((n, n))
            out[:n_r, :n_r] = A_r
            k = n_r
            for B in blocks:
                m = B.shape[0]
                out[k:k + m, k:k + m] = B
                k += m
            return out

        model = _core.SystemModel()
        model.M = block(M, blocks_M)
        model.K = block(K, blocks_K)
        model.C = block(C, blocks_C)
        model.G = block(G, [np.zeros_like(B) for B in blocks_M])
        kc = self.rotor.circulatory()
        if kc is not None:  # rotating shaft damping: −Ω K_c r inside H (system.hpp)
            model.Kc = block(kc, [np.zeros_like(B) for B in blocks_M])
        Mm, Km, Cm = (np.array(x) for x in (model.M, model.K, model.C))
        self.pad_penalty = None  # tilt penalty of the pads (equilibrium homotopy), (n, n)
        for idx, Mp, Kp, Cp, Pp in coupled:  # pad inertia/pivot terms couple journal and pads
            ix = np.ix_(idx, idx)
            Mm[ix] += Mp
            Km[ix] += Kp
            Cm[ix] += Cp
            if Pp is not None:
                if self.pad_penalty is None:
                    self.pad_penalty = np.zeros((n, n))
                self.pad_penalty[ix] += Pp
        model.M, model.K, model.C = Mm, Km, Cm
        Q = np.zeros(n)
        Q[:n_r] = Q_r
        model.Q = Q
        ch = np.zeros(n)
        for idx, cs in chambers:
            ch[list(idx)] = cs
        model.chamber = ch
        model.films = films
        model.tables = tables
        model.pad_coords = pad_coords
        model.pad_pitch = pad_pitch if any(pad_pitch) else []
        self.model = model
        self.n = n
        self.n_rotor = n_r
        self.solver = _core.SystemSolver(model)
        self.last_r: np.ndarray | None = None  # last converged equilibrium (warm starts)
        self.epoch = current_epoch()  # the public call whose warm state this holds

    def forget(self) -> None:
        """Drop every warm state of an earlier call: the last equilibrium and the films'
        last solve and carried cavitation sets (the next solve starts from its own inputs)."""
        self.last_r = None
        self.solver.forget_state()

    def bearing_h_min(self, h_films, angle_films=None):
        """Per-bearing minimum film thickness (last axis: films → bearings; NaN for a bearing
        without a film) and, with ``angle_films``, the physical angle (deg) where it occurs."""
        h = np.asarray(h_films, dtype=float)
        nb = len(self.bearings)
        out = np.full(h.shape[:-1] + (nb,), np.nan)
        ang = np.full(nb, np.nan)
        for b in range(nb):
            idx = [i for i, o in enumerate(self.film_owner) if o == b]
            if not idx:
                continue
            out[..., b] = h[..., idx].min(axis=-1)
            if angle_films is not None and h.ndim == 1:
                i = idx[int(np.argmin(h[idx]))]
                a = float(angle_films[i])
                phi = self.film_phi[i]
                if phi is not None:  # pad film: core-grid angle -> physical angle
                    j = int(round(a / 360.0 * len(phi))) % len(phi)
                    a = float(np.degrees(phi[j]) % 360.0) if np.isfinite(phi[j]) else float("nan")
                ang[b] = a
        return out if angle_films is None else (out, ang)

    def min_film_index(self, bearing: int, h_films) -> np.ndarray:
        """Index of the film (of those of ``bearing``) with the least minimum film, per row
        of ``h_films`` (…, n_films): a lobed bearing's edge film is its thinnest lobe's."""
        idx = np.array([i for i, o in enumerate(self.film_owner) if o == bearing])
        h = np.asarray(h_films, dtype=float)
        return idx[np.argmin(h[..., idx], axis=-1)]

    def station_load_matrix(self, station: int) -> np.ndarray:
        """(n, 2) map from a force (Fx, Fy) at a rotor station (N) to generalised forces on r
        (consistent with the reduction: Tᵀ f)."""
        return self.station_output_matrix(station).T

    def unbalance_load(self, unbalances) -> np.ndarray:
        """(n,) complex amplitude F₁ of the unbalance forcing per Ω² (the force is
        Re(Ω² F₁ e^{iΩt})): Σ m e e^{iφ} (1, −i) at each (station, mass_kg_m, phase_deg),
        mapped onto r as :meth:`station_load_matrix`. ``unbalances`` already validated."""
        F1 = np.zeros(self.n, dtype=complex)
        for st, me, ph in unbalances:
            F1 += self.station_load_matrix(int(st)) @ (
                float(me) * np.exp(1j * np.radians(float(ph))) * np.array([1.0, -1j]))
        return F1

    def station_output_matrix(self, station: int) -> np.ndarray:
        """(2, n) map from r to the x, y displacement of a rotor station (m), through the
        reduction's transformation (zero on sleeve coordinates). InputError for a station
        with a rigid support or out of range."""
        nst = self.system.rotor.n_stations
        if isinstance(station, bool) or not isinstance(station, (int, np.integer)) \
                or not 0 <= station < nst:
            raise InputError(f"station: expected an integer in [0, {nst - 1}], got {station!r}")
        node = int(self.system.rotor.station_nodes()[station])
        full = self.rotor.full
        out = np.zeros((2, self.n))
        for k in (0, 1):
            loc = full.local(4 * node + k)
            if loc < 0:
                continue  # rigidly supported: no motion, no work
            if self.rotor.reduction is None:
                out[k, loc] = 1.0
            else:
                out[k, : self.n_rotor] = np.asarray(self.rotor.reduction.T)[loc]
        return out

    def config_vector(self, config_ay_m=None, config_ax_m=None) -> np.ndarray:
        """(n,) configuration a_r (eq. 13): each bearing's housing offset at its journal
        coordinates; ``config_ay_m``/``config_ax_m`` override the active bearing's values (or
        the only bearing's)."""
        a = np.zeros(self.n)
        active = [bc for bc in self.bearings if bc.active]
        if not active and len(self.bearings) == 1:
            active = self.bearings  # a single plain bearing is addressed the same way
        for bc in self.bearings:
            b = self.system.bearings[bc.index]
            a[bc.jx], a[bc.jy] = b.config_ax_m, b.config_ay_m
            if bc.rot:  # the housing's angular misalignment at the station's rotations
                a[bc.rot[0]], a[bc.rot[1]] = b.config_theta_x_rad, b.config_theta_y_rad
        for val, name, idx in ((config_ay_m, "config_ay_m", "jy"), (config_ax_m, "config_ax_m", "jx")):
            if val is None:
                continue
            if len(active) != 1:
                raise InputError(f"{name}: addresses the active bearing, but the system has "
                                 f"{len(active)}; set config_ax_m/config_ay_m on the bearings")
            a[getattr(active[0], idx)] = val
        return a


#: the operating variables a scan, a threshold or a branch can vary besides the model fields
#: (each acts through the solver's operating point, not by re-assembling the model)
OPERATING = ("speed_hz", "chamber_pressure_pa", "config_ay_m")


def chamber_pressure(system: System, value, field: str = "chamber_pressure_pa") -> float:
    """p_c, Pa: a finite number >= 0, and 0 on a system without an active journal bearing
    (a nonzero p_c there would act on nothing while the result echoed it as applied)."""
    p = v.non_negative(field, value)
    if p != 0.0 and not any(isinstance(b, ActiveJournalBearing) for b in system.bearings):
        raise InputError(f"{field}: {p:g} Pa acts on an active journal bearing's chamber and "
                         "this model has none; leave it 0 (allowed: 0)")
    return p


def check_operating_parameter(system: System, name: str, field: str = "vary") -> None:
    """``InputError`` naming ``field`` when the operating variable ``name`` acts on nothing in
    ``system``: ``chamber_pressure_pa`` needs an active journal bearing, ``config_ay_m`` the
    active bearing (or the system's only bearing). A scan over it would repeat one point."""
    asm = assembled(system)
    n_active = sum(bc.active for bc in asm.bearings)
    if name == "chamber_pressure_pa" and n_active == 0:
        raise InputError(f"{field}: chamber_pressure_pa acts on an active journal bearing's "
                         "chamber and this model has none; vary speed_hz (or a model field, "
                         "e.g. bearings.0.clearance_m, in a sweep or an equilibrium branch)")
    if name == "config_ay_m" and n_active != 1 and not (n_active == 0
                                                        and len(asm.bearings) == 1):
        raise InputError(f"{field}: config_ay_m is the housing offset of the active journal "
                         f"bearing, and this model has {n_active} active of "
                         f"{len(asm.bearings)} bearings; vary a bearing's own offset "
                         "(bearings.<name>.config_ay_m) instead")


_local = threading.local()


def assembled(system: System) -> Assembled:
    """This thread's cached ``Assembled`` for ``system`` (keyed by value; a few kept)."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = {}
    key = system
    hit = cache.get(key)
    if hit is None:
        if len(cache) >= 8:
            cache.pop(next(iter(cache)))
        hit = cache[key] = Assembled(system)
    _this_call(hit)
    return hit


def _this_call(asm: Assembled) -> None:
    """Reset ``asm``'s warm state when it was last used by another public call than the
    running one (rotordyn._common.calls): the same call gives the same answer bit for bit
    whatever ran before; the points of one call continue from each other."""
    epoch = current_epoch()
    if asm.epoch != epoch:
        asm.forget()
        asm.epoch = epoch


def pin_assembled(asm: Assembled) -> None:
    """Make ``asm`` this thread's cached ``Assembled`` for ``asm.system`` (sweeps: the
    analyses called by a chunk then use the chunk's own fresh solver, so their warm starts
    never depend on what the thread solved for an earlier chunk)."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = {}
    cache.pop(asm.system, None)
    if len(cache) >= 8:
        cache.pop(next(iter(cache)))
    cache[asm.system] = asm
    _this_call(asm)
