"""Free-vibration analysis of the rotor alone: full FE model or reduced to master stations."""

from __future__ import annotations

import threading
from collections import OrderedDict

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError
from rotordyn._common import validate as v
from rotordyn.model.system import REDUCTION_METHODS, System
from rotordyn.results.campbell import CampbellResult
from rotordyn.results.modes import WHIRL_NAMES, ModesResult
from rotordyn.units import hz_to_rad_s


class RotorMatrices:
    """Dense constrained matrices of the rotor and, optionally, their reduction.

    ``full``: ``_core.ConstrainedRotor`` (M, K, C, G after the rigid supports, ``dofs`` maps to
    the full free-free numbering). ``reduction``: ``_core.Reduction`` or None. ``xy``: (ix, iy)
    pairs in the analysed coordinates, for whirl classification.
    """

    def __init__(self, system: System, method: str | None = None):
        method = system.reduction.method if method is None else method
        v.choice("reduction", method, REDUCTION_METHODS)
        # The constrained matrices are dense: four N x N float64 arrays, N = 4 (n_elements+1),
        # and as many again while they are built and reduced. Refuse before allocating
        # (issue 13: n_elements = 10000 ended in std::bad_alloc).
        n_dof = 4 * (system.rotor.n_elements + 1)
        v.memory(f"rotor.n_elements (total {system.rotor.n_elements}, {n_dof} DOF)",
                 8.0 * 8.0 * n_dof**2)
        self.system = system
        self.method = method
        self.full = _core.constrain(system.to_core())
        self.reduction = None
        self._mats = None
        self._op = None
        self._xy = self._rot = None
        self._kc = False  # not yet built (None: no rotating damping)
        if method != "none":
            if not system.reduction.master_stations:
                raise InputError(
                    "reduction.master_stations: a reduced model needs at least one master "
                    "station")
            masters = [self.full.local(int(d)) for d in system.master_dofs()]
            n_modes = system.reduction.n_modes if method == "craig-bampton" else 0
            self.reduction = _core.reduce_model(method, self.full.M, self.full.K, masters, n_modes)

    def matrices(self):
        """(M, K, C, G) of the analysed model (reduced when a reduction is in use)."""
        if self._mats is None:
            f = self.full
            if self.reduction is None:
                mats = (f.M, f.K, f.C, f.G)
            else:
                r = self.reduction
                mats = (r.M, r.K, np.asarray(r.reduce(f.C)), np.asarray(r.reduce(f.G)))
                for a in mats[2:]:
                    a.flags.writeable = False  # shared through the cache: never altered
            self._mats = mats
        return self._mats

    def circulatory(self):
        """K_c of the analysed model (reduced like C), the circulatory stiffness per unit
        spin speed (rad/s) of the shaft's rotating (internal) damping, N·s/m: the fixed-frame
        equations take K + Ω K_c. K_c = −K_β J, K_β = Σ β_e K_e (the elements' β damping,
        assembled in C++) and J the 90° turn about z of every node's (x, y) and (θx, θy): the
        rotating-frame damping force −K_β (q̇ − Ω J q) (Friswell et al. 2010, Dynamics of
        Rotating Machines, rotating damping; Genta 2005, Dynamics of Rotating Systems). None when
        the rotor has no rotating damping."""
        if self._kc is False:
            self._kc = None
            if self.system.rotor.has_rotating_damping:
                kc = free_free_circulatory(self.system)
                dofs = np.asarray(self.full.dofs)
                kc = kc[np.ix_(dofs, dofs)]
                if self.reduction is not None:
                    kc = np.asarray(self.reduction.reduce(kc))
                kc.flags.writeable = False
                self._kc = kc
        return self._kc

    def operator(self):
        """The C++ ``ModalOperator`` of :meth:`matrices` (sparse pencil and K's factorisation,
        made on first use and kept with this object): a modal call on it costs its Arnoldi
        iteration, with the answer of ``_core.modal(M, C + ΩG, K, ...)`` to round-off."""
        if self._op is None:
            M, K, C, G = self.matrices()
            self._op = _core.ModalOperator(M, C, G, K)
        return self._op

    def xy_pairs(self):
        if self._xy is None:
            if self.reduction is None:
                self._xy = list(self.full.xy)
            else:
                n_m = len(self.system.reduction.master_stations)
                self._xy = [(2 * i, 2 * i + 1) for i in range(n_m)]
        return list(self._xy)  # a copy: the cached list is shared

    def rot_pairs(self):
        """(iθx, iθy) pairs in the analysed coordinates (none for a reduced model)."""
        if self._rot is None:
            self._rot = list(self.full.rot) if self.reduction is None else []
        return list(self._rot)

    def expand(self, q: np.ndarray) -> np.ndarray:
        """Analysed coordinates (n, k) → full free-free FE DOFs (4 n_nodes, k), zeros at the
        fixed DOFs."""
        qf = q if self.reduction is None else self.reduction.T @ q
        n_full = 4 * (self.system.rotor.n_elements + 1)
        out = np.zeros((n_full,) + qf.shape[1:], dtype=qf.dtype)
        out[np.asarray(self.full.dofs)] = qf
        return out


def free_free_circulatory(system) -> np.ndarray:
    """(4 n_nodes, 4 n_nodes) K_c = −K_β J of the free-free shaft (no supports, disks or
    constraints), N·s/m: K_β = Σ β_e K_e assembled in C++ (each section's β, else the
    rotor's), J :func:`turn_matrix`."""
    import scipy.sparse as sp

    core = system.to_core()
    elems = core.elements
    for e in elems:
        e.damping_alpha = 0.0
    core.elements, core.disks, core.supports, core.rigid_nodes = elems, [], [], []
    data, indices, indptr, shape = _core.assemble(core)["C"]
    Kb = sp.csc_matrix((data, indices, indptr), shape=shape)
    return -np.asarray((Kb @ turn_matrix(shape[0])).todense())


def turn_matrix(n_dof: int):
    """J (sparse, n_dof × n_dof): every node's (x, y, θx, θy) turned by +90° about z,
    (−y, x, −θy, θx); J q is i·q of the complex whirl notation."""
    import scipy.sparse as sp

    i = np.arange(0, n_dof, 2)  # the first of each pair (x, θx)
    rows = np.concatenate([i, i + 1])
    cols = np.concatenate([i + 1, i])
    vals = np.concatenate([-np.ones(i.size), np.ones(i.size)])
    return sp.csc_matrix((vals, (rows, cols)), shape=(n_dof, n_dof))


# Cache of the constrained (and reduced) matrices per (System, method), keyed by value: a System
# is a frozen dataclass of frozen parts, so an equal System has the same matrices, and a changed
# model (dataclasses.replace) is a different key. The entries are read-only (the C++ object's
# arrays are exposed as read-only views), so a caller cannot alter a cached matrix; nothing
# else is kept, so a call's answer does not depend on what ran before it. Bounded by bytes:
# the 404-DOF rotor of benchmarks/bench_rotor.py takes 5.2 MB; a model above the budget is
# never cached (its assembly is small next to its eigen-analysis anyway).
CACHE_BYTES = 256 * 2**20
_cache: OrderedDict = OrderedDict()
_cache_bytes = 0
_cache_lock = threading.Lock()


def _nbytes(rm: RotorMatrices) -> int:
    n = rm.full.M.shape[0]
    b = 2 * 4 * 8 * n * n  # the matrices, and the modal operator's dense copies
    if rm.reduction is not None:
        b += 8 * rm.reduction.T.size + 4 * 8 * rm.reduction.M.size
    return b


def rotor_matrices(system: System, method: str | None = None) -> RotorMatrices:
    """The :class:`RotorMatrices` of ``system`` (``method``: the reduction, default the
    model's), built once per value of (system, method) and then shared (least recently used
    entries dropped beyond ``CACHE_BYTES``). An unhashable system is built every time."""
    global _cache_bytes
    method = system.reduction.method if method is None else method
    try:
        key = (system, method)
        hash(key)
    except TypeError:
        return RotorMatrices(system, method)
    with _cache_lock:
        hit = _cache.get(key)
        if hit is not None:
            _cache.move_to_end(key)
            return hit
    rm = RotorMatrices(system, method)  # outside the lock: other threads go on
    nb = _nbytes(rm)
    if nb <= CACHE_BYTES:
        with _cache_lock:
            if key not in _cache:
                _cache[key] = rm
                _cache_bytes += nb
                while _cache_bytes > CACHE_BYTES:
                    _, old = _cache.popitem(last=False)
                    _cache_bytes -= _nbytes(old)
    return rm


def clear_cache() -> None:
    """Drop every cached :class:`RotorMatrices` (benchmarks time cold calls with it)."""
    global _cache_bytes
    with _cache_lock:
        _cache.clear()
        _cache_bytes = 0


def _result(rm: RotorMatrices, speed_hz: float, n_modes: int, model_name: str) -> ModesResult:
    w = hz_to_rad_s(speed_hz)
    kc = rm.circulatory()
    if kc is None:
        r = rm.operator().modal(w, rm.xy_pairs(), n_modes, True, rm.rot_pairs())
    else:  # K + Ω K_c changes with the speed: no kept factorisation of K
        M, K, C, G = rm.matrices()
        r = _core.modal(M, C + w * G, K + w * kc, rm.xy_pairs(), n_modes, True, rm.rot_pairs())
    shapes = rm.expand(np.asarray(r.modes))  # (4 n_nodes, n_modes)
    n_nodes = shapes.shape[0] // 4
    return ModesResult(
        speed_hz=float(speed_hz),
        model=model_name,
        eigenvalues=np.asarray(r.eigenvalues),
        whirl=np.array([WHIRL_NAMES[int(x)] for x in r.whirl], dtype=object),
        shapes=shapes.reshape(n_nodes, 4, -1),
        node_positions_m=rm.system.rotor.node_positions_m(),
    )


def _check_no_bearings(system: System, what: str, without_bearings) -> None:
    """The rotor-alone analyses refuse a system with bearing elements unless asked to leave
    them out: their films' stiffness and damping depend on the equilibrium at each speed, so
    the rotor's modes without them are not the system's (issue 18: ``modes`` silently showed
    the rotor on its supports only, where ROSS's ``run_modal`` includes the bearings)."""
    v.boolean("without_bearings", without_bearings)
    if system.bearings and not without_bearings:
        names = ", ".join(b.name or f"{type(b).__name__} at station {b.station}"
                          for b in system.bearings)
        raise InputError(
            f"without_bearings: the system has {len(system.bearings)} bearing element(s) "
            f"({names}) whose films depend on the equilibrium at each speed; {what} is the "
            "rotor on its supports alone. For the modes with the bearings use "
            "rotordyn.stability(system, speed_hz, ...) (CLI: rotordyn stability; Campbell: "
            "rotordyn.campbell); for the rotor without them pass without_bearings=True "
            "(CLI: --without-bearings)")


@limited_blas
def modes(system: System, speed_hz: float = 0.0, *, reduction: str | None = None,
          n_modes: int | None = None, without_bearings: bool = False) -> ModesResult:
    """Damped natural frequencies, damping, whirl and mode shapes of the rotor on its supports
    (rigid and linear), without any bearing element.

    Parameters
    ----------
    speed_hz : spin speed Ω/2π, Hz (gyroscopic coupling Ω G).
    reduction : ``"none"`` for the full FE model, or ``"guyan"``/``"irs"``/``"craig-bampton"``
        to condense to the model's master stations; default: the model's own setting.
    n_modes : number of modes (lowest damped frequencies) kept; default all of a reduced
        model, 12 of a full one. A reduced result carries the full model's ``full`` result
        with the same number of modes (for the frequency error).
    without_bearings : a system with bearing elements (fluid films, tables) is refused unless
        this is True: their coefficients depend on the equilibrium, so use
        :func:`rotordyn.stability` for the system's modes; True gives the rotor without them.
    """
    v.speed("speed_hz", speed_hz)  # a bad speed is named first, whatever else is wrong
    _check_no_bearings(system, "modes", without_bearings)
    if n_modes is not None:
        v.integer("n_modes", n_modes, lo=1)
    method = system.reduction.method if reduction is None else reduction
    v.choice("reduction", method, REDUCTION_METHODS)
    full_rm = rotor_matrices(system, "none")
    n_full = full_rm.full.M.shape[0]
    if n_modes is not None:  # no more modes than coordinates (issue 13)
        n_modes = min(v.integer("n_modes", n_modes, lo=1), n_full)
    if method == "none":
        return _result(full_rm, speed_hz, n_modes or min(12, n_full), "full")
    rm = rotor_matrices(system, method)
    n_red = rm.reduction.M.shape[0]
    k = min(n_modes or n_red, n_red)
    red = _result(rm, speed_hz, k, method)
    full = _result(full_rm, speed_hz, k, "full")
    return ModesResult(red.speed_hz, red.model, red.eigenvalues, red.whirl, red.shapes,
                       red.node_positions_m, full=full)


@limited_blas
def rotor_campbell(system: System, speeds_hz, *, reduction: str | None = None,
                   n_modes: int = 8, without_bearings: bool = False) -> CampbellResult:
    """Campbell diagram of the rotor on its linear/rigid supports (no fluid film): the
    ``n_modes`` lowest damped frequencies at each speed, computed in one C++ call.

    speeds_hz: (n_speeds,) increasing, Hz. A system with bearing elements is refused unless
    ``without_bearings`` (see :func:`modes`; :func:`rotordyn.campbell` includes them).
    """
    sp = v.speeds("speeds_hz", speeds_hz)
    _check_no_bearings(system, "rotor_campbell", without_bearings)
    v.integer("n_modes", n_modes, lo=1)
    if reduction is not None:
        v.choice("reduction", reduction, REDUCTION_METHODS)
    rm = rotor_matrices(system, reduction)
    M, K, C, G = rm.matrices()
    # More modes than coordinates is not meaningful: capped at the model's size (issue 13:
    # n_modes=10**6 gave a 10^6-column NaN array).
    n_modes = min(n_modes, M.shape[0])
    v.memory("n_modes", 16.0 * sp.size * n_modes)
    kc = rm.circulatory()
    if kc is None:
        r = _core.campbell(M, C, G, K, rm.xy_pairs(), hz_to_rad_s(sp), n_modes, rm.rot_pairs())
        ev, wh = np.asarray(r.eigenvalues), np.asarray(r.whirl)
    else:  # rotating damping: K + Ω K_c, one eigen-analysis per speed
        ev = np.full((sp.size, n_modes), complex(np.nan, np.nan))
        wh = np.zeros((sp.size, n_modes), dtype=np.int32)
        for i, w in enumerate(hz_to_rad_s(sp)):
            r = _core.modal(M, C + w * G, K + w * kc, rm.xy_pairs(), n_modes, False,
                            rm.rot_pairs())
            k = len(r.whirl)
            ev[i, :k] = np.asarray(r.eigenvalues)
            wh[i, :k] = [int(x) for x in r.whirl]
    return CampbellResult(sp, ev, wh,
                          model="full" if rm.reduction is None else rm.method)
