"""Energy balance of a THD film recomputed from its returned fields (used by the THD tests):
the heat the face flows carry out of the film (upwind face temperatures), the heat the walls
take, the dissipation of the film's cells and the worst relative mass defect of an inner cell.
(On bare arrays, with the wall term; test_film_thd.py and test_film_thd_active.py use it;
:func:`pad_balance` the same for one pad of a pad bearing, test_film_thd_pads.py and
test_thd_walls.py.)"""

import numpy as np


def upwind_faces(qp, qz):
    """Every face of the grid as (from cell, to cell, flow ≥ 0), oriented along its flow:
    ``qp`` (n_circ, n_axial + 1) the φ-faces j+1/2 (+ with φ), ``qz`` the axial faces k+1/2."""
    n, k1 = np.asarray(qp).shape
    for j in range(n):
        for k in range(k1):
            faces = [((j, k), ((j + 1) % n, k), qp[j, k])]
            if k < k1 - 1:
                faces.append(((j, k), (j, k + 1), qz[j, k]))
            for a, b, F in faces:
                yield (b, a, -F) if F < 0 else (a, b, F)


def balance(T, inlet_mask, flows, rho_c, ts, h_wall=0.0, t_wall=0.0):
    """``T``, ``inlet_mask``: (n_circ, n_axial + 1); ``flows``: dict with ``q_phi_m3_s``
    (face j+1/2, + with φ), ``q_z_m3_s`` (face k+1/2), ``dissipation_w``, ``area_m2``;
    ``rho_c`` = ρ c_p (J/(m³ K)); ``ts`` the supply temperature of ambient side inflow (°C);
    ``h_wall`` the summed wall heat-transfer coefficient (W/(m² K)) to walls at ``t_wall``.
    Returns (heat out by the flows W, dissipation W, heat to the walls W, mass defect)."""
    qp, qz = np.asarray(flows["q_phi_m3_s"]), np.asarray(flows["q_z_m3_s"])
    T = np.asarray(T)
    D = np.asarray(inlet_mask) > 0
    n, k1 = T.shape
    inflow = np.zeros_like(T)
    outflow = np.zeros_like(T)
    heat = 0.0
    for a, b, F in upwind_faces(qp, qz):
        inflow[b] += F
        outflow[a] += F
        if D[b] and not D[a]:
            heat += F * T[a]          # back to the inlet
        elif D[a] and not D[b]:
            heat -= F * T[a]          # from the inlet into the film
    mass = 0.0
    for j in range(n):
        for k in range(k1):
            if D[j, k]:
                continue
            B = inflow[j, k] - outflow[j, k]
            if k in (0, k1 - 1):      # open end: leaves (or ambient oil enters at T_s)
                heat += B * (T[j, k] if B > 0 else ts)
            else:
                mass = max(mass, abs(B) / max(inflow[j, k], 1e-300))
    diss = float(np.asarray(flows["dissipation_w"])[~D].sum())
    wall = float((h_wall * np.asarray(flows["area_m2"]) * (T - t_wall))[~D].sum())
    return rho_c * heat, diss, wall, mass


def pad_balance(T, D, fl, rho_c, ts, t_in=None):
    """Heat carried out of one pad by its flows minus what they bring in (W), the pad cells'
    dissipation (W) and the largest relative mass imbalance of a non-inlet interior cell.
    ``t_in`` (°C): the pad's inlet temperature, at which its trailing-edge cells' make-up
    (``fl["makeup_m3_s"]``, inlet-gap oil a cell the pad hardly feeds draws) enters; it
    leaves with the cell's oil, so it adds ρ c Σ m (T − T_in). None: no make-up term."""
    qp, qz = fl["q_phi_m3_s"], fl["q_z_m3_s"]
    n, k1 = T.shape
    inflow = np.zeros_like(T)
    outflow = np.zeros_like(T)
    heat = 0.0
    for a, b, F in upwind_faces(qp, qz):
        inflow[b] += F
        outflow[a] += F
        if D[b] and not D[a]:
            heat += F * T[a]          # out of the pad into the gap (trailing edge)
        elif D[a] and not D[b]:
            heat -= F * T[a]          # from the inlet gap into the pad
    imb = 0.0
    for j in range(n):
        for k in range(k1):
            if D[j, k]:
                continue
            B = inflow[j, k] - outflow[j, k]
            if D[(j + 1) % n, k]:             # trailing-edge column (prescribed pressure, end
                heat += B * T[j, k]           # cells too): what it does not pass on, at its T
            elif k in (0, k1 - 1):            # open end: leaves (or ambient oil at T_s enters)
                heat += B * (T[j, k] if B > 0 else ts)
            else:                             # mass not passed on leaves at the cell's T
                heat += B * T[j, k]
                imb = max(imb, abs(B) / max(inflow[j, k], 1e-300))
    if t_in is not None and "makeup_m3_s" in fl:
        m = np.asarray(fl["makeup_m3_s"])
        heat += float((m * (np.asarray(T) - t_in))[~D].sum())
    return rho_c * heat, fl["dissipation_w"][~D].sum(), imb
