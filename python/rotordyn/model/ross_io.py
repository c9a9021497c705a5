"""ROSS rotors as rotordyn systems (optional: ``pip install rotordyn[ross]``): a ROSS ``Rotor``
(uniform shaft elements, disks, linear bearings) as a :class:`rotordyn.System`: one section per
ROSS shaft element (stations = ROSS nodes; its proportional damping alpha, beta as the
section's ``damping_alpha_1_per_s``, ``damping_beta_s``), materials by (E, G, ρ), disks, and
bearings as linear supports (constant coefficients) or :class:`~rotordyn.bearings.TableBearing`
(speed-dependent ones, or with mass coefficients mxx…myy; ROSS frequencies are rad/s, ours Hz).
The other direction, a bearing element as a ROSS ``BearingElement``, is
:func:`rotordyn.bearings.to_ross_bearing`."""

from __future__ import annotations

import math

import numpy as np

from rotordyn.bearings.coefficients import COEFF_NAMES
from rotordyn.bearings.ross_io import MASS_NAMES
from rotordyn.bearings.table import TableBearing
from rotordyn.errors import InputError
from rotordyn.model.rotor import Disk, Material, Rotor, ShaftSection, Support
from rotordyn.model.rotor import Reduction
from rotordyn.model.system import System


def system_from_ross(rotor, *, name: str = ""):
    """A :class:`rotordyn.System` with ROSS ``rotor``'s shaft, disks and linear bearings
    (full FE model, no reduction). Bearing mass coefficients (mxx…myy) become a
    TableBearing's mass columns. InputError for what has no counterpart here (tapered
    elements, point masses, bearings linking two nodes)."""
    mats: dict = {}
    sections = []
    elems = sorted(rotor.shaft_elements, key=lambda e: e.n)
    for i, e in enumerate(elems):
        if getattr(e, "n", i) != i:
            raise InputError(f"rotor.shaft_elements[{i}]: expected elements on consecutive "
                             "nodes (one per ROSS node interval)")
        if abs(e.idl - e.idr) > 1e-12 or abs(e.odl - e.odr) > 1e-12:
            raise InputError(f"rotor.shaft_elements[{i}]: tapered elements are not supported")
        m = e.material
        key = (float(m.E), float(m.G_s), float(m.rho))
        if key not in mats:
            mats[key] = Material(name=f"m{len(mats)}", density_kg_m3=key[2], young_pa=key[0],
                                 shear_modulus_pa=key[1])
        # ROSS's proportional damping C_e = α M_e + β K_e (its ShaftElement alpha, beta)
        alpha, beta = float(getattr(e, "alpha", 0.0) or 0.0), float(getattr(e, "beta", 0.0) or 0.0)
        sections.append(ShaftSection(length_m=float(e.L), outer_diameter_m=float(e.odl),
                                     inner_diameter_m=float(e.idl), material=mats[key].name,
                                     damping_alpha_1_per_s=alpha or None,
                                     damping_beta_s=beta or None))
    disks = tuple(Disk(station=int(d.n), mass_kg=float(d.m), ip_kg_m2=float(d.Ip),
                       id_kg_m2=float(d.Id)) for d in rotor.disk_elements)
    if getattr(rotor, "point_mass_elements", None):
        raise InputError("rotor.point_mass_elements: not supported")
    supports, bearings = [], []
    for j, b in enumerate(rotor.bearing_elements):
        if getattr(b, "n_link", None) is not None:
            raise InputError(f"rotor.bearing_elements[{j}]: bearings linking two nodes are not "
                             "supported")
        vals = {c: np.atleast_1d(np.asarray(getattr(b, c), dtype=float)) for c in COEFF_NAMES}
        mvals = {c: np.atleast_1d(np.asarray(getattr(b, c, None) if getattr(b, c, None)
                                             is not None else 0.0, dtype=float)) for c in MASS_NAMES}
        has_mass = any(np.any(v != 0) for v in mvals.values())
        freq = getattr(b, "frequency", None)
        const = freq is None or all(np.all(v == v[0]) for v in vals.values())
        tag = str(getattr(b, "tag", "") or f"ross_bearing{j}")
        if has_mass:  # mass terms: a table (a linear support has none), constant or by speed
            f_hz = (np.asarray(freq, dtype=float) / (2 * math.pi) if freq is not None
                    and np.size(freq) > 1 else np.array([0.0]))
            ns = f_hz.size

            def col(v, ns=ns):
                return tuple(float(x) for x in (np.full(ns, v[0]) if v.size == 1 else v))

            bearings.append(TableBearing(
                station=int(b.n), speeds_hz=tuple(f_hz), name=tag,
                **{f"{c}_n_per_m" if c[0] == "k" else f"{c}_n_s_per_m": col(vals[c])
                   for c in COEFF_NAMES},
                **{f"{c}_kg": col(mvals[c]) for c in MASS_NAMES}))
        elif const:
            supports.append(Support(station=int(b.n), type="linear", name=tag,
                                    **{f"{c}_n_per_m" if c[0] == "k" else f"{c}_n_s_per_m":
                                       float(vals[c][0]) for c in COEFF_NAMES}))
        else:
            f_hz = np.asarray(freq, dtype=float) / (2 * math.pi)
            bearings.append(TableBearing(
                station=int(b.n), speeds_hz=tuple(f_hz), name=tag,
                **{f"{c}_n_per_m" if c[0] == "k" else f"{c}_n_s_per_m": tuple(vals[c])
                   for c in COEFF_NAMES}))
    red = Reduction(master_stations=tuple(sorted(b.station for b in bearings)), method="none")
    return System(rotor=Rotor(tuple(sections), disks), materials=tuple(mats.values()),
                  supports=tuple(supports), bearings=tuple(bearings), reduction=red,
                  name=name or str(getattr(rotor, "tag", "") or "ross-rotor"))
