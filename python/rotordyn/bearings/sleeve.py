"""Flexible sleeve of the active journal bearing (paper §3.1, eq. 1, 3, 11).

The sleeve is a curved cantilever of rectangular section (thickness ``d`` radial, width ``b``
axial) on a circular arc of mid-surface radius ``R``, clamped at one end. It is meshed with
exact-flexibility curved-beam elements (3 DOF per node: tangential, normal, rotation; see
``docs/sleeve.md``) and condensed with the paper's three-step Guyan method to a few radial
master coordinates ``r_s`` at chosen stations:

1. eliminate the rotations, 2. transform (x, y) at each node to polar (r, t),
3. condense to the radial coordinates of the master stations.

Conventions (DESIGN.md §3): bearing frame x horizontal, y up; film angle φ from +x, positive
with the rotation. ``clamp_deg`` is the paper's β: the angle of the clamped end measured from
the top of the bearing in the direction of rotation, so the clamp sits at φ = 90° + β and the
sleeve extends over ``arc_deg`` in the direction of rotation (β = 105°, ψ = 160°: φ = 195° …
355°, under the journal). Radial sleeve coordinates are positive **inward**, toward the
journal: the film thickness is ``h = c − x cos φ − y sin φ − w(φ)`` with
``w = W(φ) @ r_s``.

Example
-------
>>> from rotordyn.bearings.sleeve import paper_rig_sleeve
>>> res = paper_rig_sleeve().condense()
>>> res.mass_matrix.shape, res.interpolation_matrix([4.0, 5.0]).shape
((3, 3), (2, 3))
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.errors import InputError

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["FlexibleSleeve", "SleeveResult", "paper_rig_sleeve"]


@dataclass(frozen=True, slots=True)
class FlexibleSleeve:
    """The active bearing's flexible sleeve (SI units, angles in degrees).

    Parameters
    ----------
    radius_m : mid-surface radius R, m (inner face at R − d/2 faces the film).
    thickness_m : radial thickness d, m, in (0, radius_m).
    width_m : axial width b (the bearing length), m.
    arc_deg : arc ψ of the sleeve, deg, in (0, 360].
    clamp_deg : β, angle of the clamped end from the top of the bearing in the direction of
        rotation, deg (the clamp is at film angle φ = 90° + β).
    young_pa, density_kg_m3, poisson : material (E > 0, ρ > 0, ν in (−1, 0.5)).
    n_elements : number of equal curved-beam elements (paper: 20).
    master_stations : node numbers of the radial master coordinates, counted from the clamp
        (node 0) to the free end (node ``n_elements``), strictly increasing.
    plane_strain : use E/(1 − ν²) (a wide sleeve in cylindrical bending); the paper's beam
        model is ``False``.
    shear, extension, rotary_inertia : element effects (all on by default).
    """

    radius_m: float
    thickness_m: float
    width_m: float
    arc_deg: float
    clamp_deg: float
    young_pa: float
    density_kg_m3: float
    poisson: float
    n_elements: int = 20
    master_stations: tuple[int, ...] = (7, 14, 20)
    plane_strain: bool = False
    shear: bool = True
    extension: bool = True
    rotary_inertia: bool = True

    def __post_init__(self):
        f = "sleeve"
        r = v.positive(f"{f}.radius_m", self.radius_m)
        d = v.positive(f"{f}.thickness_m", self.thickness_m)
        if d >= r:
            raise InputError(
                f"{f}.thickness_m: expected a value in (0, radius_m = {r!r}), got {d!r}"
            )
        v.positive(f"{f}.width_m", self.width_m)
        arc = v.finite(f"{f}.arc_deg", self.arc_deg)
        if not 0.0 < arc <= 360.0:
            raise InputError(f"{f}.arc_deg: expected a value in (0, 360], got {self.arc_deg!r}")
        v.finite(f"{f}.clamp_deg", self.clamp_deg)
        v.positive(f"{f}.young_pa", self.young_pa)
        v.positive(f"{f}.density_kg_m3", self.density_kg_m3)
        nu = v.finite(f"{f}.poisson", self.poisson)
        if not -1.0 < nu < 0.5:
            raise InputError(f"{f}.poisson: expected a value in (-1, 0.5), got {self.poisson!r}")
        n = self.n_elements
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= 10000:
            raise InputError(f"{f}.n_elements: expected an integer in [2, 10000], got {n!r}")
        if arc / n > 180.0:
            raise InputError(
                f"{f}.n_elements: each element must span at most 180 deg; expected at least "
                f"{math.ceil(arc / 180.0)}, got {n}"
            )
        ms = self.master_stations
        if not isinstance(ms, tuple) or not ms:
            raise InputError(
                f"{f}.master_stations: expected a non-empty tuple of node numbers, got {ms!r}"
            )
        for i, k in enumerate(ms):
            if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= n:
                raise InputError(
                    f"{f}.master_stations[{i}]: expected a node number in [1, {n}] "
                    f"(0 is the clamp), got {k!r}"
                )
            if i and k <= ms[i - 1]:
                raise InputError(
                    f"{f}.master_stations: expected strictly increasing node numbers, got {ms!r}"
                )
        for name in ("plane_strain", "shear", "extension", "rotary_inertia"):
            if not isinstance(getattr(self, name), bool):
                raise InputError(f"{f}.{name}: expected True or False, got "
                                 f"{getattr(self, name)!r}")

    @property
    def clamp_phi_rad(self) -> float:
        """Film angle φ of the clamped end, rad (90° + β)."""
        return math.radians(90.0 + self.clamp_deg)

    @property
    def arc_rad(self) -> float:
        """Sleeve arc ψ, rad."""
        return math.radians(self.arc_deg)

    @property
    def free_end_phi_rad(self) -> float:
        """Film angle of the free end, rad (clamp + ψ, not wrapped)."""
        return self.clamp_phi_rad + self.arc_rad

    def to_core(self) -> Any:
        """The C++ ``SleeveModel`` (SI units, rad)."""
        g = _core.SleeveGeometry()
        g.radius = float(self.radius_m)
        g.arc = self.arc_rad
        g.clamp_angle = self.clamp_phi_rad
        o = _core.CurvedBeamOptions()
        o.plane_strain = self.plane_strain
        o.shear = self.shear
        o.extension = self.extension
        o.rotary_inertia = self.rotary_inertia
        s = _core.CurvedBeamSection()
        s.thickness = float(self.thickness_m)
        s.width = float(self.width_m)
        s.young = float(self.young_pa)
        s.density = float(self.density_kg_m3)
        s.poisson = float(self.poisson)
        s.options = o
        m = _core.SleeveModel()
        m.geometry = g
        m.section = s
        m.n_elements = self.n_elements
        m.master_nodes = list(self.master_stations)
        return m

    def condense(self) -> SleeveResult:
        """Build the clamped sleeve FEM and apply the paper's three-step Guyan condensation."""
        c = _core.condense_sleeve(self.to_core())
        nodes = np.asarray(c.mesh.node_angles, dtype=float)
        return SleeveResult(
            sleeve=self,
            freq_full_hz=np.asarray(c.freq_full_hz),
            freq_step1_hz=np.asarray(c.freq_xy_hz),
            freq_condensed_hz=np.asarray(c.freq_condensed_hz),
            mass_matrix=np.asarray(c.Ms),
            stiffness_matrix=np.asarray(c.Ks),
            transformation=np.asarray(c.T),
            full_mass_matrix=np.asarray(c.M_full),
            full_stiffness_matrix=np.asarray(c.K_full),
            node_phi_rad=nodes,
            master_phi_rad=np.asarray(c.master_angles),
            _core_result=c,
        )


@dataclass(frozen=True, slots=True)
class SleeveResult:
    """Full and condensed sleeve model (paper eq. 1: ``Ms r̈_s + Ks r_s = H_s + C_s``).

    Attributes
    ----------
    freq_full_hz : (3n,) natural frequencies of the full clamped FEM (n = n_elements).
    freq_step1_hz : (2n,) after step 1 (rotations eliminated).
    freq_condensed_hz : (n_m,) of the condensed model.
    mass_matrix, stiffness_matrix : (n_m, n_m) Ms (kg) and Ks (N/m) on the inward radial
        master coordinates r_s (m).
    transformation : (3n, n_m) full DOFs (x, y, v of nodes 1 … n) = T r_s.
    full_mass_matrix, full_stiffness_matrix : (3n, 3n) clamped full FEM, global DOFs
        (x_g, y_g, v_g) of nodes 1 … n.
    node_phi_rad : (n + 1,) film angles of the nodes, clamp first (not wrapped).
    master_phi_rad : (n_m,) film angles of the master stations.
    """

    sleeve: FlexibleSleeve
    freq_full_hz: np.ndarray
    freq_step1_hz: np.ndarray
    freq_condensed_hz: np.ndarray
    mass_matrix: np.ndarray
    stiffness_matrix: np.ndarray
    transformation: np.ndarray
    full_mass_matrix: np.ndarray
    full_stiffness_matrix: np.ndarray
    node_phi_rad: np.ndarray
    master_phi_rad: np.ndarray
    _core_result: Any = field(repr=False, compare=False)

    def interpolation_matrix(self, phi_rad) -> np.ndarray:
        """(n_phi, n_m) matrix W: the sleeve's inward radial displacement at film angles
        ``phi_rad`` (any real values; wrapped) is ``w = W @ r_s`` (m per m). Uses the exact
        element shape functions; rows for angles outside the sleeve are zero (rigid bush).
        ``∂w(φ)/∂r_s,j = W[:, j]`` is the virtual displacement for H_s = ∫ p ∂w/∂r_s dA."""
        phi = np.atleast_1d(np.asarray(phi_rad, dtype=float))
        if phi.ndim != 1:
            raise InputError(f"phi_rad: expected a 1-D array of angles, got shape {phi.shape}")
        if not np.all(np.isfinite(phi)):
            raise InputError("phi_rad: expected finite angles")
        return np.asarray(self._core_result.interpolation(phi))

    def interpolation_matrix_full(self, phi_rad) -> np.ndarray:
        """(n_phi, 3n) the same on the full DOFs: ``interpolation_matrix = this @ T``."""
        phi = np.atleast_1d(np.asarray(phi_rad, dtype=float))
        if phi.ndim != 1 or not np.all(np.isfinite(phi)):
            raise InputError(f"phi_rad: expected a 1-D array of finite angles, got {phi!r}")
        return np.asarray(self._core_result.interpolation_full(phi))

    def radial_displacement(self, r_s, phi_rad) -> np.ndarray:
        """Inward radial displacement w (m) at ``phi_rad`` for master coordinates ``r_s`` (m)."""
        return self.interpolation_matrix(phi_rad) @ self._masters(r_s)

    def expand(self, r_s) -> np.ndarray:
        """(3n,) full nodal DOFs (x, y in m, v in rad of nodes 1 … n) from ``r_s``."""
        return self.transformation @ self._masters(r_s)

    def chamber_load(self, start_phi_rad: float | None = None,
                     end_phi_rad: float | None = None) -> np.ndarray:
        """(n_m,) generalized force on the masters per unit chamber pressure, m²: a uniform
        pressure p_c on the outer face (radius R + d/2, width b) over the film-angle arc
        [start_phi_rad, end_phi_rad] gives C_s0 = p_c · c_s (eq. 11, virtual work, positive =
        pushes the sleeve inward). Default: the whole sleeve. The chamber arc must lie inside
        the sleeve's (end > start, angles may be given modulo 2π)."""
        s = self.sleeve
        a = s.clamp_phi_rad if start_phi_rad is None else v.finite("start_phi_rad", start_phi_rad)
        b = s.free_end_phi_rad if end_phi_rad is None else v.finite("end_phi_rad", end_phi_rad)
        return np.asarray(self._core_result.chamber_load(a, b))

    def modal_assurance(self) -> np.ndarray:
        """(n_m, n_m) mass-weighted MAC between the first n_m full-model modes (rows) and the
        condensed modes expanded with T (columns); 1 on the diagonal means the condensed model
        reproduces the full mode shape (the paper: "almost identical eigenvectors up to the
        second mode")."""
        from scipy.linalg import eigh

        n_m = self.mass_matrix.shape[0]
        M = self.full_mass_matrix
        _, vf = eigh(self.full_stiffness_matrix, M, subset_by_index=[0, n_m - 1])
        _, vc = eigh(self.stiffness_matrix, self.mass_matrix)
        ve = self.transformation @ vc
        cross = vf.T @ M @ ve
        return cross**2 / np.outer(np.einsum("ij,ik,kj->j", vf, M, vf),
                                   np.einsum("ij,ik,kj->j", ve, M, ve))

    def chamber_load_full(self, start_phi_rad: float | None = None,
                          end_phi_rad: float | None = None) -> np.ndarray:
        """(3n,) the same chamber load as consistent nodal loads on the full DOFs (x, y, v of
        nodes 1 … n), m² (N and N·m per Pa); ``chamber_load = transformation.T @ this``."""
        s = self.sleeve
        a = s.clamp_phi_rad if start_phi_rad is None else v.finite("start_phi_rad", start_phi_rad)
        b = s.free_end_phi_rad if end_phi_rad is None else v.finite("end_phi_rad", end_phi_rad)
        return np.asarray(self._core_result.chamber_load_full(a, b))

    def _masters(self, r_s) -> np.ndarray:
        r = np.asarray(r_s, dtype=float)
        n_m = self.mass_matrix.shape[0]
        if r.shape[0] != n_m:
            raise InputError(f"r_s: expected shape ({n_m},) or ({n_m}, k), got {r.shape}")
        return r

    def to_frame(self) -> pd.DataFrame:
        """Tidy table: one row per (stage, mode) with ``freq_hz``; stages ``full`` (3n DOF),
        ``rotations_eliminated`` (2n DOF, step 1) and ``condensed`` (n_m DOF)."""
        import pandas as pd
        rows = []
        for stage, f in (("full", self.freq_full_hz), ("rotations_eliminated", self.freq_step1_hz),
                         ("condensed", self.freq_condensed_hz)):
            for i, val in enumerate(f):
                rows.append((stage, i + 1, float(val)))
        df = pd.DataFrame(rows, columns=["stage", "mode", "freq_hz"])
        df["stage"] = pd.Categorical(df["stage"],
                                     categories=["full", "rotations_eliminated", "condensed"])
        df["mode"] = df["mode"].astype("int64")
        return df


def paper_rig_sleeve(**changes) -> FlexibleSleeve:
    """The paper's rig sleeve (§6) with the calibrated unknowns, as in
    ``rotordyn.models.paper_rig()``: d = 5 mm, ψ = 160°, β = 105°, b = L = 40 mm (given);
    mid-radius 27.8 mm (inner face at R_bearing + c = 25.3 mm); masters at nodes 7, 14, 20 of
    20 (docs/sleeve.md); E = 62 GPa fitted to the paper's Table 1 (static compliance) and
    ρ = 5890 kg/m³ fitted so that E/ρ matches the condensed frequencies (docs/paper-rig.md,
    "Active bearing and equilibrium"); ν = 0.34. Condensed 508.2, 1736.9, 6013.6 Hz against
    the paper's 490.2, 1754.2, 6175.8 Hz. The bronze of docs/sleeve.md §6 is
    ``paper_rig_sleeve(young_pa=1e11, density_kg_m3=8930.0)``. Keyword arguments override
    fields."""
    base = dict(
        radius_m=0.0253 + 0.0025,
        thickness_m=0.005,
        width_m=0.040,
        arc_deg=160.0,
        clamp_deg=105.0,
        young_pa=6.2e10,
        density_kg_m3=5890.0,
        poisson=0.34,
        n_elements=20,
        master_stations=(7, 14, 20),
    )
    base.update(changes)
    return FlexibleSleeve(**base)
