"""State-space export of the linearised system for control-law synthesis (paper eq. 19: the
chamber-pressure fluctuation ΔC and excitation forces F as inputs)."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import linearize
from rotordyn.errors import ConvergenceError, InputError
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.model.system import System
from rotordyn.results.statespace import StateSpaceResult


def _parse(item, kinds, field):
    if isinstance(item, str):
        item = (item,)
    if not isinstance(item, tuple) or not item or item[0] not in kinds:
        raise InputError(f"{field}: expected one of {kinds} (with a station or bearing index "
                         f"where needed), got {item!r}")
    return item


def _checked_items(asm, inputs, outputs) -> tuple[list, list]:
    """The input and output items resolved against the model before the equilibrium is
    solved (an item the model lacks: InputError naming the argument and the item). Inputs:
    (item, the active bearings it drives | the station's load matrix); outputs: (kind,
    station or bearing, the station's output matrix | the state indices). Default outputs:
    every bearing's journal."""
    ins = []
    for item in inputs:
        item = _parse(item, ("chamber_pressure", "force"), "inputs")
        if item[0] == "chamber_pressure":
            bcs = [bc for bc in asm.bearings
                   if bc.sleeve and (len(item) == 1 or bc.index == item[1])]
            if not bcs:
                raise InputError(f"inputs: {item!r} needs an active bearing")
            ins.append((item, bcs))
            continue
        if len(item) != 2:
            raise InputError(f"inputs: expected ('force', station), got {item!r}")
        try:
            ins.append((item, asm.station_load_matrix(item[1])))
        except InputError as exc:  # name the argument and the item, not a bare "station"
            raise InputError(f"inputs: {item!r}: {exc}") from None
    if not outputs:
        outputs = [("journal", bc.index) for bc in asm.bearings]
    outs = []
    for item in outputs:
        item = _parse(item, ("displacement", "velocity", "journal", "sleeve"), "outputs")
        if len(item) != 2:
            raise InputError(f"outputs: expected (kind, station or bearing), got {item!r}")
        kind, where = item
        if kind in ("displacement", "velocity"):
            try:
                outs.append((kind, where, asm.station_output_matrix(where)))
            except InputError as exc:
                raise InputError(f"outputs: {item!r}: {exc}") from None
            continue
        bcs = [bc for bc in asm.bearings if bc.index == where]
        if not bcs:
            raise InputError(f"outputs: {item!r}: no bearing with index {where!r} "
                             f"(bearings: 0..{len(asm.bearings) - 1})")
        idx = [bcs[0].jx, bcs[0].jy] if kind == "journal" else list(bcs[0].sleeve)
        if not idx:
            raise InputError(f"outputs: bearing {where} has no sleeve")
        outs.append((kind, where, idx))
    return ins, outs


@limited_blas
def statespace(system: System, inputs=("chamber_pressure",), outputs=(), *,
               speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
               config_ay_m: float | None = None, **kw) -> StateSpaceResult:
    """(A, B, C, D) of the linearised system about its equilibrium.

    inputs: ``"chamber_pressure"`` (Pa, every active bearing's ΔC_s of eq. 11), or
    ``("chamber_pressure", bearing_index)``, or ``("force", station)`` (two inputs Fx, Fy, N).
    outputs: ``("displacement", station)`` (x, y in m), ``("velocity", station)`` (m/s),
    ``("journal", bearing_index)`` (journal x, y relative to the housing, m),
    ``("sleeve", bearing_index)`` (sleeve masters, m). Default: the journal of every bearing.
    """
    for name, val in (("inputs", inputs), ("outputs", outputs)):
        if isinstance(val, str):
            val = (val,)
        if not isinstance(val, (tuple, list)):
            raise InputError(f"{name}: expected a list of {name}, got {val!r}")
    inputs = (inputs,) if isinstance(inputs, str) else inputs
    asm = assembled(system)
    ins, outs = _checked_items(asm, inputs, outputs)  # bad items: before the solve
    lm = linearize(system, speed_hz, chamber_pressure_pa, config_ay_m, **kw)
    if lm.status not in CONVERGED:
        raise ConvergenceError(f"statespace: no equilibrium at this operating point ({lm.status}: "
                         f"{lm.equilibrium.message})")
    n = asm.n
    Minv = np.linalg.inv(lm.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ lm.K, -Minv @ lm.D]])
    names = list(lm.labels)
    states = tuple(names + [f"d({s})/dt" for s in names])

    bcols, in_names = [], []
    for item, what in ins:
        if item[0] == "chamber_pressure":
            f = np.zeros(n)
            for bc in what:
                f[list(bc.sleeve)] = lm.chamber[list(bc.sleeve)]
            bcols.append(f)
            in_names.append("chamber_pressure_pa" if len(item) == 1 else
                            f"chamber_pressure_pa[{item[1]}]")
        else:
            bcols += [what[:, 0], what[:, 1]]
            in_names += [f"force_x_n[{item[1]}]", f"force_y_n[{item[1]}]"]
    B = np.vstack([np.zeros((n, len(bcols))), Minv @ np.column_stack(bcols)]) if bcols \
        else np.zeros((2 * n, 0))

    crows, out_names = [], []
    for kind, where, what in outs:
        if kind in ("displacement", "velocity"):
            z = np.zeros_like(what)
            rows = np.hstack([what, z]) if kind == "displacement" else np.hstack([z, what])
            unit = "m" if kind == "displacement" else "m_s"
            crows += list(rows)
            out_names += [f"{kind}_x_{unit}[{where}]", f"{kind}_y_{unit}[{where}]"]
        else:
            for j, ci in enumerate(what):
                row = np.zeros(2 * n)
                row[ci] = 1.0
                crows.append(row)
                out_names.append(f"journal_{'xy'[j]}_m[{where}]" if kind == "journal"
                                 else f"sleeve_{j + 1}_m[{where}]")
    C = np.vstack(crows)
    D = np.zeros((C.shape[0], B.shape[1]))
    return StateSpaceResult(A, B, C, D, tuple(in_names), tuple(out_names), states, lm)
