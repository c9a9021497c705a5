"""The whole model: materials, rotor, supports, bearings and the reduction settings.

``System`` is what a TOML model file describes (``System.from_toml`` / ``to_toml``) and what
every analysis takes. Frozen: build a changed copy with :func:`dataclasses.replace`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError
from rotordyn._common import plausibility
from rotordyn._common import validate as v
from rotordyn.bearings import BEARING_TYPES, FluidFilmBearing, ThermalModel
from rotordyn.bearings import ActiveJournalBearing, FixedGeometryBearing, TiltingPadBearing
from rotordyn.model.rotor import (REDUCTION_METHODS, STEEL, Material,  # noqa: F401
                                 Reduction, Rotor, Support)
from rotordyn.model.stage import Stage
from rotordyn.model.toml_io import system_fields_from_toml, system_to_toml

if TYPE_CHECKING:
    import scipy.sparse as sp


@dataclass(frozen=True, slots=True)
class System:
    """A rotor-bearing system (paper eq. 12): rotor, supports, bearings, reduction."""

    rotor: Rotor
    materials: tuple[Material, ...] = (STEEL,)
    supports: tuple[Support, ...] = ()
    reduction: Reduction = field(default_factory=Reduction)
    bearings: tuple = ()  # FluidFilmBearing, ActiveJournalBearing or rotordyn.bearings elements
    gravity_m_s2: float = 9.81
    name: str = ""
    description: str = ""
    stages: tuple[Stage, ...] = ()  # aerodynamic stages for API 617 Level I (``[[stage]]``)
    thermal: ThermalModel | None = None  # the oil system (``[thermal]``; docs/film-physics.md)

    def __post_init__(self):
        object.__setattr__(self, "materials", tuple(self.materials))
        object.__setattr__(self, "stages", tuple(self.stages))
        object.__setattr__(self, "supports", tuple(self.supports))
        object.__setattr__(self, "bearings", tuple(self.bearings))
        v.non_negative("gravity_m_s2", self.gravity_m_s2)
        plausibility.gravity("gravity_m_s2", self.gravity_m_s2)
        v.text("name", self.name)
        v.text("description", self.description)
        if not isinstance(self.rotor, Rotor):
            raise InputError(f"rotor: expected a Rotor, got {type(self.rotor).__name__}")
        if not isinstance(self.reduction, Reduction):
            raise InputError(f"reduction: expected a Reduction, got "
                             f"{type(self.reduction).__name__}")
        for i, m in enumerate(self.materials):
            if not isinstance(m, Material):
                raise InputError(f"materials[{i}]: expected a Material, got {type(m).__name__}")
        for i, s in enumerate(self.supports):
            if not isinstance(s, Support):
                raise InputError(f"support[{i}]: expected a Support, got {type(s).__name__}")
        names = [m.name for m in self.materials]
        if len(set(names)) != len(names):
            raise InputError(f"material: names must be unique, got {names}")
        for i, s in enumerate(self.rotor.sections):
            if s.material not in names:
                raise InputError(
                    f"rotor.section[{i}].material: expected one of {names}, got {s.material!r}")
        n = self.rotor.n_stations
        at: dict[int, int] = {}
        for i, s in enumerate(self.supports):
            s.check(f"support[{i}]", n)
            # Two rigid supports, or a rigid and a linear one, at the same station are a
            # modelling error (issue 13); linear supports at one station add up.
            j = at.get(s.station)
            if j is not None and "rigid" in (s.type, self.supports[j].type):
                raise InputError(
                    f"support[{i}].station: station {s.station} already has support[{j}] "
                    f"({self.supports[j].type}); a rigid support must be the only support at "
                    "its station")
            if j is None or s.type == "rigid":
                at[s.station] = i
        for i, st in enumerate(self.reduction.master_stations):
            if st >= n:
                raise InputError(
                    f"reduction.master_stations[{i}]: expected a station in [0, {n - 1}], got {st}")
            if any(s.station == st and s.type == "rigid" for s in self.supports):
                raise InputError(
                    f"reduction.master_stations[{i}]: station {st} has a rigid support; "
                    "its translations are fixed and cannot be masters")
        for i, st in enumerate(self.stages):
            if not isinstance(st, Stage):
                raise InputError(f"stage[{i}]: expected a Stage, got {type(st).__name__}")
            st.check(f"stage[{i}]", n)
        seen = set()
        for i, b in enumerate(self.bearings):
            where = f"bearing[{i}]"
            if not isinstance(b, tuple(BEARING_TYPES.values())):
                raise InputError(f"{where}: expected one of "
                                 f"{', '.join(c.__name__ for c in BEARING_TYPES.values())}, "
                                 f"got {type(b).__name__}")
            b.check(where, n)
            dup = [j for j in range(i) if b.name and self.bearings[j].name == b.name]
            if dup:  # outputs, sweep axes (bearings.<name>) and films look bearings up by name
                raise InputError(f"{where}.name: expected a name no other bearing has, got "
                                 f"{b.name!r} (also bearing[{dup[0]}])")
            if b.station in seen:
                raise InputError(f"{where}.station: station {b.station} already has a bearing")
            seen.add(b.station)
            if any(s.station == b.station and s.type == "rigid" for s in self.supports):
                raise InputError(f"{where}.station: station {b.station} has a rigid support")
            if (self.reduction.method != "none"
                    and b.station not in self.reduction.master_stations):
                raise InputError(
                    f"{where}.station: station {b.station} must be one of "
                    f"reduction.master_stations {list(self.reduction.master_stations)} "
                    "(the film acts on the journal's x and y)")
        if self.thermal is not None:
            if not isinstance(self.thermal, ThermalModel):
                raise InputError(f"thermal: expected a ThermalModel, got "
                                 f"{type(self.thermal).__name__}")
            # plain and active journal bearings, and the pad bearings (pad_thd.py): the
            # bearings the thermal models take (rotordyn.analysis.thermal)
            plain = {b.name for b in self.bearings if b.name and isinstance(
                b, (FluidFilmBearing, ActiveJournalBearing, TiltingPadBearing,
                    FixedGeometryBearing))}
            kinds = {b.name: type(b).__name__ for b in self.bearings if b.name}
            for i, f in enumerate(self.thermal.films):
                if f.bearing not in plain:
                    why = (f" (a {kinds[f.bearing]}: it has no film for a thermal model)"
                           if f.bearing in kinds else "")
                    raise InputError(f"thermal.film[{i}].bearing: expected the name of a plain "
                                     f"or active journal bearing, or a tilting-pad or "
                                     f"fixed-geometry bearing, of the model "
                                     f"{sorted(plain)}, got {f.bearing!r}{why}")


    # -- lookups -----------------------------------------------------------------------
    def material(self, name: str) -> Material:
        for m in self.materials:
            if m.name == name:
                return m
        raise InputError(f"material: no material named {name!r}")

    @property
    def mass_kg(self) -> float:
        """Total mass of shaft sections and disks, kg."""
        shaft = sum(s.mass_kg(self.material(s.material)) for s in self.rotor.sections)
        return float(shaft + sum(d.mass_kg for d in self.rotor.disks))

    # -- C++ model -----------------------------------------------------------------------
    def to_core(self, *, shear: bool = True, rotary_inertia: bool = True) -> "_core.RotorModel":
        """The C++ ``RotorModel`` (elements, disks, linear and rigid supports at FE nodes)."""
        nodes = self.rotor.station_nodes()
        m = _core.RotorModel()
        elems = []
        for s in self.rotor.sections:
            elems.extend(s.to_core(self.material(s.material), shear=shear,
                                   rotary_inertia=rotary_inertia,
                                   damping_alpha_1_per_s=self.rotor.damping_alpha_1_per_s,
                                   damping_beta_s=self.rotor.damping_beta_s))
        m.elements = elems
        disks = []
        for d in self.rotor.disks:
            cd = _core.Disk()
            cd.node, cd.mass, cd.ip, cd.id = int(nodes[d.station]), d.mass_kg, d.ip_kg_m2, d.id_kg_m2
            disks.append(cd)
        m.disks = disks
        lin, rigid = [], []
        for s in self.supports:
            if s.type == "rigid":
                rigid.append(int(nodes[s.station]))
            else:
                cs = _core.LinearSupport()
                cs.node, cs.k, cs.c = int(nodes[s.station]), s.k(), s.c()
                lin.append(cs)
        m.supports = lin
        m.rigid_nodes = rigid
        return m

    def _sparse(self, key: str) -> sp.csc_matrix:
        import scipy.sparse as sp
        data, indices, indptr, shape = _core.assemble(self.to_core())[key]
        return sp.csc_matrix((data, indices, indptr), shape=shape)

    def M(self) -> sp.csc_matrix:
        """Free-free mass matrix of the rotor FE model, (4 n_nodes, 4 n_nodes), sparse."""
        return self._sparse("M")

    def K(self) -> sp.csc_matrix:
        """Free-free stiffness matrix (linear supports included), sparse."""
        return self._sparse("K")

    def C(self) -> sp.csc_matrix:
        """Damping matrix: the linear supports' dampers and the shaft's material damping
        Σ (α M_e + β K_e), sparse."""
        return self._sparse("C")

    def G(self) -> sp.csc_matrix:
        """Gyroscopic matrix per unit spin speed (rad/s), skew-symmetric, sparse."""
        return self._sparse("G")

    def master_dofs(self) -> np.ndarray:
        """Full-model DOF indices of the masters: the translations x, y per master station
        (2 n_masters), then the rotations θx, θy of each station whose film couples to them
        (a bearing with ``tilt = true``; :meth:`tilt_stations` order)."""
        nodes = self.rotor.station_nodes()
        return np.array([4 * nodes[s] + k for s in self.reduction.master_stations for k in (0, 1)]
                        + [4 * nodes[s] + k for s in self.tilt_stations() for k in (2, 3)],
                        dtype=np.int64)

    def tilt_stations(self) -> list[int]:
        """Stations whose rotations a film couples to (bearings with ``tilt = true``), in the
        order of the bearings, each once: their θx, θy stay masters of a reduction."""
        out: list[int] = []
        for b in self.bearings:
            if getattr(b, "tilt", False) is True and b.station not in out:
                out.append(int(b.station))
        return out

    # -- TOML ----------------------------------------------------------------------------
    @classmethod
    def from_toml(cls, path_or_text, *, is_text: bool = False) -> "System":
        """Read a model file (``schema = "rotordyn/model/1"``); unknown keys are errors."""
        return cls(**system_fields_from_toml(path_or_text, is_text=is_text))

    def to_toml(self, path=None) -> str:
        """The model as TOML text (written to ``path`` when given); round-trips losslessly."""
        text = system_to_toml(self)
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text)
        return text
