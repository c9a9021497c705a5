"""Static analysis of the rotor at the system's equilibrium (issue 18; ROSS's ``run_static``):
deflection, shear force and bending moment along the rotor and the reaction at every support
and bearing, for any configuration vector a (paper eq. 7-14: how the weight is shared between
the bearings of the statically indeterminate rotor as a bearing moves).

Method. The equilibrium (eq. 14) gives the master coordinates and the film forces. The full FE
displacement follows exactly: with no reduction it is the equilibrium's own r (+ a at the
journals); with masters, the other DOFs solve K_ss u_s = f_s − K_sm u_m (static condensation is
exact for a static load; f the consistent gravity load −g M e_y). A rotor on supports alone is
K u = f. Element end forces F_e = K_e u_e − f_e give the internal forces at both ends of every
element; the reactions are the residual K u − f at the fixed DOFs (rigid supports), −K_s u of
the linear supports and the film (or table) forces of the bearings.

Rotating (internal) shaft damping (``rotor.damping_rotating``): a shaft spinning at Ω in a
static bend carries the internal damping stress of its rotating strain rate, the circulatory
force −Ω K_c u (K_c = −Σ β_e K_e J, :meth:`RotorMatrices.circulatory`). It is part of the
internal forces: every K above becomes K + Ω K_c — the slave recovery, the rotor on supports
alone, the elements' end forces (K_e − Ω β_e K_e J_e) u_e and the residual at the supports.
K_c has no resultant (rigid motions are in the null space of every K_e), so the reactions
still carry the weight; they turn sideways with the bend."""

from __future__ import annotations

import numpy as np

from rotordyn._common.status import CONVERGED
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import assembled, gravity_load
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.analysis.modes import free_free_circulatory, rotor_matrices, turn_matrix
from rotordyn.bearings import BEARING_TYPES
from rotordyn.errors import InputError
from rotordyn.model.system import System
from rotordyn.results.static import StaticResult


def _circulatory_betas(system: System, omega: float) -> list:
    """Per section Ω β (s·rad/s) of its rotating damping: 0 without ``damping_rotating``."""
    rot = system.rotor
    if not rot.has_rotating_damping:
        return [0.0] * len(rot.sections)
    return [omega * (rot.damping_beta_s if sec.damping_beta_s is None else sec.damping_beta_s)
            for sec in rot.sections]


def _element_forces(system: System, u_full: np.ndarray, g: float, omega: float = 0.0):
    """(z (2 n_e,), F (2 n_e, 4)): for every element its left and right end positions and the
    end forces (x, y, θx, θy) F_e = (K_e + Ω K_c,e) u_e − f_e exerted on it by the rest of the
    rotor (K_c,e = −β_e K_e J_e with rotating damping, else 0)."""
    z, F = [], []
    node = 0
    zs = 0.0
    uy = np.tile([0.0, 1.0, 0.0, 0.0], 2)
    J8 = turn_matrix(8).toarray()
    for sec, wb in zip(system.rotor.sections, _circulatory_betas(system, omega)):
        mat = system.material(sec.material)
        Ke, Me = sec.K(mat), sec.M(mat)
        if wb:
            Ke = Ke - wb * (Ke @ J8)
        fe = -g * (Me @ uy)
        le = sec.length_m / sec.n_elements
        for _ in range(sec.n_elements):
            ue = u_full[4 * node: 4 * node + 8]
            fend = Ke @ ue - fe
            z += [zs, zs + le]
            F += [fend[:4], fend[4:]]
            zs += le
            node += 1
    return np.asarray(z), np.asarray(F)


@limited_blas
def static(system: System, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
           config_ay_m: float | None = None, *, config_ax_m: float | None = None,
           **equilibrium_kw) -> StaticResult:
    """Deflection, shear force, bending moment and reactions at the equilibrium at
    ``speed_hz`` (bearing elements' films depend on it, and with rotating shaft damping the
    shaft's circulatory force Ω K_c u: the module's docstring; else a rotor on supports alone
    does not).

    The configuration (``config_ay_m``, ``config_ax_m``: the active or only bearing's housing
    offset; other bearings' offsets from the model) and ``equilibrium_kw`` are those of
    :func:`rotordyn.equilibrium`. A failed equilibrium is a result with its status and NaN
    fields, never a deflection. See :class:`rotordyn.results.StaticResult` for the sign
    conventions."""
    import pandas as pd
    from rotordyn._common import validate as v
    from rotordyn.units import hz_to_rad_s

    v.finite("speed_hz", speed_hz)
    g = float(system.gravity_m_s2)
    omega = hz_to_rad_s(float(speed_hz))
    rm = rotor_matrices(system, "none")
    full = rm.full
    dofs = np.asarray(full.dofs)
    n_full = 4 * (system.rotor.n_elements + 1)
    Kc = np.asarray(full.K)  # the constrained stiffness, + Ω K_c with rotating damping
    circ = rm.circulatory()
    if circ is not None:
        Kc = Kc + omega * np.asarray(circ)
    f_ff = gravity_load(system)
    fc = f_ff[dofs]  # the consistent gravity load on the free DOFs
    nodes = system.rotor.station_nodes()
    weight = -float(f_ff[1::4].sum())
    reactions = []
    status, message = "ok", ""
    if system.bearings:
        e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m,
                        config_ax_m=config_ax_m, **equilibrium_kw)
        status, message = e.status, e.message
        if e.status not in CONVERGED:
            nan = np.full(system.rotor.n_elements + 1, np.nan)
            ne2 = 2 * system.rotor.n_elements
            return StaticResult(float(speed_hz), system.rotor.node_positions_m(), nan, nan,
                                np.full(ne2, np.nan), *(np.full(ne2, np.nan),) * 4,
                                pd.DataFrame(columns=["name", "station", "kind", "force_x_n",
                                                      "force_y_n"]),
                                weight, e.status, e.message or "no equilibrium")
        asm = assembled(system)
        a = asm.config_vector(config_ay_m, config_ax_m)
        rr = (np.asarray(e.r) + a)[: asm.n_rotor]  # absolute: relative to housing + offset
        if asm.rotor.reduction is None:
            u = rr
        else:
            # every master: the stations' translations and the tilting films' rotations
            # (their film moments act there; as slaves they were taken as unloaded)
            m_idx = [full.local(int(d)) for d in system.master_dofs()]
            um = rr[: len(m_idx)]
            s_idx = np.setdiff1d(np.arange(dofs.size), m_idx)
            u = np.zeros(dofs.size)
            u[m_idx] = um
            rhs = fc[s_idx] - Kc[np.ix_(s_idx, m_idx)] @ um
            u[s_idx] = np.linalg.solve(Kc[np.ix_(s_idx, s_idx)], rhs)
        H = np.asarray(e.film_force_n)
        kinds = {cls: name for name, cls in BEARING_TYPES.items()}
        for bc in asm.bearings:
            b = system.bearings[bc.index]
            reactions.append({"name": b.name, "station": int(b.station), "kind": kinds[type(b)],
                              "force_x_n": float(H[bc.jx]), "force_y_n": float(H[bc.jy])})
            if bc.rot:  # a tilting film: its moments on the journal (the rotations' H)
                reactions[-1] |= {"film_moment_x_n_m": float(H[bc.rot[0]]),
                                  "film_moment_y_n_m": float(H[bc.rot[1]])}
    else:
        try:
            u = np.linalg.solve(Kc, fc)
        except np.linalg.LinAlgError:
            raise InputError("supports: the rotor has no supports or bearings that hold it "
                             "(a free-free rotor has no static deflection)") from None
        if not np.all(np.isfinite(u)) or np.linalg.cond(Kc) > 1e14:
            raise InputError("supports: the rotor has no supports or bearings that hold it "
                             "(a free-free rotor has no static deflection)")
    u_full = np.zeros(n_full)
    u_full[dofs] = u
    # Residual of the free-free rotor (without the linear supports): the supports' reactions
    # at their nodes, the bearing forces at theirs, ~0 elsewhere.
    K_ff = system.K().toarray()
    if circ is not None:  # the free-free circulatory stiffness
        K_ff = K_ff + omega * free_free_circulatory(system)
    k_sup = np.zeros((n_full, n_full))
    for sp in system.supports:
        if sp.type == "linear":
            i = 4 * int(nodes[sp.station])
            k_sup[i:i + 2, i:i + 2] += [[sp.kxx_n_per_m, sp.kxy_n_per_m],
                                        [sp.kyx_n_per_m, sp.kyy_n_per_m]]
    res = (K_ff - k_sup) @ u_full - f_ff
    for sp in system.supports:
        i = 4 * int(nodes[sp.station])
        fx, fy = (res[i], res[i + 1]) if sp.type == "rigid" else \
            (-(k_sup[i, i:i + 2] @ u_full[i:i + 2]), -(k_sup[i + 1, i:i + 2] @ u_full[i:i + 2]))
        reactions.append({"name": sp.name, "station": int(sp.station), "kind": sp.type,
                          "force_x_n": float(fx), "force_y_n": float(fy)})
    reactions.sort(key=lambda r: r["station"])
    columns = ["name", "station", "kind", "force_x_n", "force_y_n"]
    if any("film_moment_x_n_m" in r for r in reactions):
        columns += ["film_moment_x_n_m", "film_moment_y_n_m"]
    z, F = _element_forces(system, u_full, g, omega)
    # left end of an element: the forces left of the section are what the rotor to the left
    # exerts on it (+F); right end: minus the force the rest exerts there (−F).
    sgn = np.tile([1.0, -1.0], z.size // 2)
    return StaticResult(
        speed_hz=float(speed_hz), node_positions_m=system.rotor.node_positions_m(),
        deflection_x_m=u_full[0::4], deflection_y_m=u_full[1::4], section_positions_m=z,
        shear_x_n=sgn * F[:, 0], shear_y_n=sgn * F[:, 1],
        moment_xz_n_m=-sgn * F[:, 3], moment_yz_n_m=sgn * F[:, 2],
        reactions=pd.DataFrame(reactions, columns=columns),
        weight_n=weight, status=status, message=message)
