"""Free-vibration analysis of the rotor alone: full FE model or reduced to master stations."""

from __future__ import annotations

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
        f = self.full
        if self.reduction is None:
            return f.M, f.K, f.C, f.G
        r = self.reduction
        return r.M, r.K, r.reduce(f.C), r.reduce(f.G)

    def xy_pairs(self):
        if self.reduction is None:
            return list(self.full.xy)
        n_m = len(self.system.reduction.master_stations)
        return [(2 * i, 2 * i + 1) for i in range(n_m)]

    def rot_pairs(self):
        """(iθx, iθy) pairs in the analysed coordinates (none for a reduced model)."""
        return list(self.full.rot) if self.reduction is None else []

    def expand(self, q: np.ndarray) -> np.ndarray:
        """Analysed coordinates (n, k) → full free-free FE DOFs (4 n_nodes, k), zeros at the
        fixed DOFs."""
        qf = q if self.reduction is None else self.reduction.T @ q
        n_full = 4 * (self.system.rotor.n_elements + 1)
        out = np.zeros((n_full,) + qf.shape[1:], dtype=qf.dtype)
        out[np.asarray(self.full.dofs)] = qf
        return out


def _result(rm: RotorMatrices, speed_hz: float, n_modes: int, model_name: str) -> ModesResult:
    M, K, C, G = rm.matrices()
    w = hz_to_rad_s(speed_hz)
    r = _core.modal(M, C + w * G, K, rm.xy_pairs(), n_modes, True, rm.rot_pairs())
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
    _check_no_bearings(system, "modes", without_bearings)
    v.speed("speed_hz", speed_hz)
    if n_modes is not None:
        v.integer("n_modes", n_modes, lo=1)
    method = system.reduction.method if reduction is None else reduction
    v.choice("reduction", method, REDUCTION_METHODS)
    full_rm = RotorMatrices(system, "none")
    n_full = full_rm.full.M.shape[0]
    if n_modes is not None:  # no more modes than coordinates (issue 13)
        n_modes = min(v.integer("n_modes", n_modes, lo=1), n_full)
    if method == "none":
        return _result(full_rm, speed_hz, n_modes or min(12, n_full), "full")
    rm = RotorMatrices(system, method)
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
    _check_no_bearings(system, "rotor_campbell", without_bearings)
    sp = v.speeds("speeds_hz", speeds_hz)
    v.integer("n_modes", n_modes, lo=1)
    if reduction is not None:
        v.choice("reduction", reduction, REDUCTION_METHODS)
    rm = RotorMatrices(system, reduction)
    M, K, C, G = rm.matrices()
    # More modes than coordinates is not meaningful: capped at the model's size (issue 13:
    # n_modes=10**6 gave a 10^6-column NaN array).
    n_modes = min(n_modes, M.shape[0])
    v.memory("n_modes", 16.0 * sp.size * n_modes)
    r = _core.campbell(M, C, G, K, rm.xy_pairs(), hz_to_rad_s(sp), n_modes, rm.rot_pairs())
    return CampbellResult(sp, np.asarray(r.eigenvalues), np.asarray(r.whirl),
                          model="full" if rm.reduction is None else rm.method)
