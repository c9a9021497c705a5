"""ROSS interoperability (optional: ``pip install rotordyn[ross]``, i.e. ross-rotordynamics).

* :func:`to_ross_bearing` — a ROSS ``BearingElement`` whose speed-dependent coefficients come
  from this package's solver (any element with ``coefficient_table``, a
  :class:`~rotordyn.bearings.CoefficientTable` or a :class:`~rotordyn.bearings.TableBearing`),
  so ROSS users get these bearing models as a drop-in.
* :func:`system_from_ross` — a ROSS ``Rotor`` (uniform shaft elements, disks, linear bearings)
  as a :class:`rotordyn.System`: one section per ROSS shaft element (stations = ROSS nodes),
  materials by (E, G, ρ), disks, and bearings as linear supports (constant coefficients) or
  :class:`TableBearing` (speed-dependent ones, or with mass coefficients mxx…myy; ROSS
  frequencies are rad/s, ours Hz).
ROSS is imported only inside these functions.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn.errors import InputError
from rotordyn.results.equilibrium import CONVERGED

_COEF = ("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")
_MASS = ("mxx", "mxy", "myx", "myy")


def _ross():
    try:
        import ross
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise InputError("ross: this needs the optional dependency ross-rotordynamics "
                         "(pip install 'rotordyn[ross]')") from exc
    return ross


def to_ross_bearing(source, *, n: int, speeds_hz=None, load_n=None, tag: str | None = None,
                    n_threads: int = 1):
    """ROSS ``BearingElement`` at ROSS node ``n`` with coefficients over ``frequency`` (rad/s).

    ``source``: a CoefficientTable, a TableBearing, or a bearing with ``coefficient_table``
    (then ``speeds_hz`` and ``load_n`` are required: the equilibrium under the static load at
    each speed gives the coefficients; rows that fail are an error, never silently dropped).
    """
    ross = _ross()
    from rotordyn.bearings._element import CoefficientTable
    from rotordyn.bearings.table import C_FIELDS, K_FIELDS, M_FIELDS, TableBearing

    mass = {}
    if isinstance(source, TableBearing):
        speeds = np.asarray(source.speeds_hz)
        cols = {c: np.asarray(source._matrix((f,)))[:, 0]
                for c, f in zip(_COEF, K_FIELDS + C_FIELDS)}
        if source.has_mass:
            mass = {c: [float(x) for x in getattr(source, f)] for c, f in zip(_MASS, M_FIELDS)}
    else:
        if not isinstance(source, CoefficientTable):
            if speeds_hz is None or load_n is None:
                raise InputError("speeds_hz, load_n: required to tabulate a bearing for ROSS")
            source = source.coefficient_table(speeds_hz, load_n, n_threads=n_threads)
        bad = [i for i, s in enumerate(source.status) if s not in CONVERGED]
        if bad:
            i = bad[0]
            raise InputError(f"speeds_hz: no coefficients at {source.speeds_hz[i]:g} Hz "
                             f"({source.status[i]}: {source.message[i]})")
        speeds = np.asarray(source.speeds_hz)
        cols = {c: (source.K if c[0] == "k" else source.C)[:, "xy".index(c[1]), "xy".index(c[2])]
                for c in _COEF}
    kw = {c: [float(x) for x in cols[c]] for c in _COEF}
    kw.update(mass)
    if len(speeds) == 1:
        kw = {c: val[0] for c, val in kw.items()}
        return ross.BearingElement(n=int(n), tag=tag, **kw)
    return ross.BearingElement(n=int(n), frequency=[2 * math.pi * float(f) for f in speeds],
                               tag=tag, **kw)


def system_from_ross(rotor, *, name: str = ""):
    """A :class:`rotordyn.System` with ROSS ``rotor``'s shaft, disks and linear bearings
    (full FE model, no reduction). Bearing mass coefficients (mxx…myy) become a
    TableBearing's mass columns. InputError for what has no counterpart here (tapered
    elements, point masses, bearings linking two nodes)."""
    from rotordyn.bearings.table import TableBearing
    from rotordyn.model.rotor import Disk, Material, Rotor, ShaftSection, Support
    from rotordyn.model.system import Reduction, System

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
        sections.append(ShaftSection(length_m=float(e.L), outer_diameter_m=float(e.odl),
                                     inner_diameter_m=float(e.idl), material=mats[key].name))
    disks = tuple(Disk(station=int(d.n), mass_kg=float(d.m), ip_kg_m2=float(d.Ip),
                       id_kg_m2=float(d.Id)) for d in rotor.disk_elements)
    if getattr(rotor, "point_mass_elements", None):
        raise InputError("rotor.point_mass_elements: not supported")
    supports, bearings = [], []
    for j, b in enumerate(rotor.bearing_elements):
        if getattr(b, "n_link", None) is not None:
            raise InputError(f"rotor.bearing_elements[{j}]: bearings linking two nodes are not "
                             "supported")
        vals = {c: np.atleast_1d(np.asarray(getattr(b, c), dtype=float)) for c in _COEF}
        mvals = {c: np.atleast_1d(np.asarray(getattr(b, c, None) if getattr(b, c, None)
                                             is not None else 0.0, dtype=float)) for c in _MASS}
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
                   for c in _COEF},
                **{f"{c}_kg": col(mvals[c]) for c in _MASS}))
        elif const:
            supports.append(Support(station=int(b.n), type="linear", name=tag,
                                    **{f"{c}_n_per_m" if c[0] == "k" else f"{c}_n_s_per_m":
                                       float(vals[c][0]) for c in _COEF}))
        else:
            f_hz = np.asarray(freq, dtype=float) / (2 * math.pi)
            bearings.append(TableBearing(
                station=int(b.n), speeds_hz=tuple(f_hz), name=tag,
                **{f"{c}_n_per_m" if c[0] == "k" else f"{c}_n_s_per_m": tuple(vals[c])
                   for c in _COEF}))
    red = Reduction(master_stations=tuple(sorted(b.station for b in bearings)), method="none")
    return System(rotor=Rotor(tuple(sections), disks), materials=tuple(mats.values()),
                  supports=tuple(supports), bearings=tuple(bearings), reduction=red,
                  name=name or str(getattr(rotor, "tag", "") or "ross-rotor"))
