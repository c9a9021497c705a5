"""Fluid-film journal bearing: finite-length Reynolds solver (paper eq. 2-5, 18-20).

Frame and conventions (DESIGN.md §3): x horizontal, y up, the journal spins counter-clockwise
(from +x to +y) for ``speed_hz > 0``; the film angle φ is measured from +x with the rotation;
the film thickness is ``h = c - x cos φ - y sin φ``. Forces are the film forces **on the
journal**, N. Linear coefficients are defined by ``dF = -K dq - C dq̇``.

The numerical work is done by :class:`rotordyn._core.ReynoldsSolver` (C++; the GIL is released
in every solve). A :class:`JournalBearing` keeps one solver per thread, so one bearing object
can be shared by threads, and it pickles by its parameters (dask workers rebuild the solver).

Example
-------
>>> import rotordyn
>>> b = rotordyn.JournalBearing(diameter_m=0.05, length_m=0.04, clearance_m=3e-4,
...                             viscosity_pa_s=0.04, n_circ=36, n_axial=8)
>>> f = b.forces(x_m=0.0, y_m=-1e-4, speed_hz=50.0)
>>> f.shape
(2,)
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from typing import Iterable, Sequence

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import CAVITATION_MODELS, SystemParts, check_turbulence, set_turbulence
from rotordyn.bearings.coefficients import coefficient_table
from rotordyn.bearings.journal_results import BearingEquilibrium, FilmResult, PressureField
from rotordyn.bearings.thermal import Oil, run_thermal_equilibrium
from rotordyn.bearings.thd import film_thermal_options, run_thd_equilibrium
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi


# Ranges accepted at the boundary (the C++ core checks the same; beyond them a film has no
# physical meaning and its pressures overflow).
MAX_SPEED_HZ = 1e5
MAX_VELOCITY_M_S = 1e3
MAX_GRID = 1 << 20  # nodes in one direction
MAX_FILM_NODES = 1 << 22  # n_circ * (n_axial + 1)
MAX_THREADS = 1024


def _finite(value, name: str) -> float:
    """A finite real number: int/float/numpy scalar; text, None and bools are rejected (the
    rule of the model classes, rotordyn._common.validate)."""
    return v.finite(name, value)


def _positive(value, name: str) -> float:
    return v.positive(name, value)


def _integer(value, name: str, lo: int, hi: int = MAX_GRID) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise InputError(f"{name}: expected an integer in [{lo}, {hi}], got {value!r}")
    if not lo <= int(value) <= hi:
        raise InputError(f"{name}: expected an integer in [{lo}, {hi}] (grid too coarse below "
                         f"{lo}), got {value}")
    return int(value)


def _speed(value) -> float:
    f = _finite(value, "speed_hz")
    if not abs(f) <= MAX_SPEED_HZ:
        raise InputError(f"speed_hz: expected |speed_hz| <= {MAX_SPEED_HZ:g} Hz, got {f!r}")
    return f


def _velocity(value, name: str) -> float:
    u = _finite(value, name)
    if not abs(u) <= MAX_VELOCITY_M_S:
        raise InputError(f"{name}: expected |{name}| <= {MAX_VELOCITY_M_S:g} m/s, got {u!r}")
    return u


MAX_SUPPLY_FLOW_M3_S = 1e3  # the core's bound (reynolds.hpp)


def check_supply_flow(value, cavitation: str, grooves, where: str = "") -> float | None:
    """The metered supply of a journal film, m³/s: None or 0 (flooded grooves) or a finite
    flow in (0, 1e3] on a ``cavitation="jfo"`` film with at least one groove. Returns None or
    the flow as a float; InputError naming ``{where}supply_flow_m3_s`` otherwise."""
    name = f"{where}supply_flow_m3_s"
    if value is None:
        return None
    q = v.in_range(name, value, 0.0, MAX_SUPPLY_FLOW_M3_S)
    if q > 0.0 and cavitation != "jfo":
        raise InputError(f"{name}: a metered supply (starved film) needs cavitation = 'jfo' "
                         f"(the mass-conserving film), got {cavitation!r}")
    if q > 0.0 and not tuple(grooves):
        raise InputError(f"{name}: a metered supply needs at least one groove to feed")
    return q


def _float_array(value, name: str) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected numbers (a scalar or an array), got {value!r}") from None
    return a


@dataclass(frozen=True, slots=True)
class Groove:
    """Axial supply groove fixed in the bearing frame.

    Parameters
    ----------
    center_deg : angle φ of the groove centre from +x, with the rotation, deg.
    width_deg : angular width, deg; 0 is a supply line at the nearest grid angle.
    pressure_pa : supply pressure (gauge), Pa, held on the groove over the interior length.
    """

    center_deg: float
    width_deg: float = 0.0
    pressure_pa: float = 0.0

    def __post_init__(self) -> None:
        # numbers only (text is rejected as in the model classes), stored as floats so that
        # Groove(90) == Groove(90.0)
        c = _finite(self.center_deg, "Groove.center_deg")
        w = v.in_range("Groove.width_deg", self.width_deg, 0.0, 360.0, hi_open=True)
        p = v.in_range("Groove.pressure_pa", self.pressure_pa, 0.0, 1e9)
        object.__setattr__(self, "center_deg", c)
        object.__setattr__(self, "width_deg", w)
        object.__setattr__(self, "pressure_pa", p)

    def to_core(self) -> _core.Groove:
        return _core.Groove(float(self.center_deg), float(self.width_deg), float(self.pressure_pa))


class JournalBearing:
    """360° plain journal bearing with optional axial grooves, solved on an (φ, z) grid.

    Parameters
    ----------
    diameter_m, length_m, clearance_m : journal diameter D, length L, radial clearance c, m.
    viscosity_pa_s : dynamic viscosity μ (isoviscous), Pa·s.
    n_circ : grid nodes around the circumference (periodic), >= 12.
    n_axial : grid intervals along the length (n_axial + 1 node rows including both ends), >= 2.
    cavitation : "reynolds" (Swift–Stieber, default), "gumbel" (half-Sommerfeld), "jfo"
        (mass-conserving Elrod–Adams, steady) or "none" (full Sommerfeld).
    grooves : sequence of :class:`Groove`.
    turbulence : "laminar" (default) or "ng_pan": turbulent lubrication (Ng–Pan–Elrod
        coefficients, switched on by the local film Reynolds number ρ|ω|R h/μ;
        docs/film-physics.md).
    density_kg_m3 : oil density ρ, kg/m³ (needed by ``turbulence = "ng_pan"``).
    turbulence_onset_re, turbulence_full_re : optional laminar-to-turbulent transition: the
        Re_h at which the turbulent corrections start and are full (0 <= onset < full; both
        or neither; None: the model acts at every Re_h > 0).
    supply_flow_m3_s : metered oil supply to the groove(s), m³/s (``cavitation="jfo"`` with
        a groove only; None or 0: flooded grooves). Below what the flooded film draws, the
        film is starved: the grooves' pressure falls to 0 and the oil enters as a partial
        film of fill θ_in < 1 found so that the inflow equals the supply
        (docs/film-physics.md, "A starved film"). The thermal models do not take it yet.
    """

    def __init__(
        self,
        *,
        diameter_m: float,
        length_m: float,
        clearance_m: float,
        viscosity_pa_s: float,
        n_circ: int = 72,
        n_axial: int = 16,
        cavitation: str = "reynolds",
        grooves: Iterable[Groove] = (),
        turbulence: str = "laminar",
        density_kg_m3: float | None = None,
        turbulence_onset_re: float | None = None,
        turbulence_full_re: float | None = None,
        supply_flow_m3_s: float | None = None,
    ) -> None:
        self.diameter_m = _positive(diameter_m, "diameter_m")
        self.length_m = _positive(length_m, "length_m")
        self.clearance_m = _positive(clearance_m, "clearance_m")
        if not self.clearance_m < 0.5 * self.diameter_m:
            raise InputError(
                f"clearance_m: expected 0 < clearance_m < diameter_m/2 = {0.5 * self.diameter_m},"
                f" got {self.clearance_m}"
            )
        self.viscosity_pa_s = _positive(viscosity_pa_s, "viscosity_pa_s")
        self.n_circ = _integer(n_circ, "n_circ", 12)
        self.n_axial = _integer(n_axial, "n_axial", 2)
        nodes = self.n_circ * (self.n_axial + 1)
        if nodes > MAX_FILM_NODES:
            raise InputError(
                f"n_circ, n_axial: expected at most {MAX_FILM_NODES} film nodes"
                f" n_circ*(n_axial+1), got {nodes} (about {nodes * 400 / 1e9:.3g} GB before the"
                " factorisation's fill)"
            )
        if not isinstance(cavitation, str) or cavitation not in CAVITATION_MODELS:
            raise InputError(f"cavitation: expected one of {CAVITATION_MODELS}, got {cavitation!r}")
        self.cavitation = cavitation
        if isinstance(grooves, (str, bytes)) or not isinstance(grooves, Iterable):
            raise InputError(f"grooves: expected a sequence of rotordyn.Groove, got {grooves!r}")
        gs = tuple(grooves)
        for i, g in enumerate(gs):
            if not isinstance(g, Groove):
                raise InputError(f"grooves[{i}]: expected a rotordyn.Groove, got {g!r}")
        # a supply is checked first: on a film without a groove it is the field to name
        self.supply_flow_m3_s = check_supply_flow(supply_flow_m3_s, cavitation, gs)
        if cavitation == "jfo" and not gs:
            raise InputError(
                "grooves: cavitation='jfo' needs at least one supply groove (without a supply"
                " the steady mass-conserving film content is undetermined)"
            )
        self.grooves = gs
        check_turbulence("JournalBearing", turbulence, density_kg_m3, turbulence_onset_re,
                         turbulence_full_re)
        self.turbulence = turbulence
        self.density_kg_m3, self.turbulence_onset_re, self.turbulence_full_re = (
            None if x is None else float(x)
            for x in (density_kg_m3, turbulence_onset_re, turbulence_full_re))
        self._local = threading.local()

    # -- plumbing ------------------------------------------------------------------------
    def _params(self) -> dict:
        return dict(
            diameter_m=self.diameter_m,
            length_m=self.length_m,
            clearance_m=self.clearance_m,
            viscosity_pa_s=self.viscosity_pa_s,
            n_circ=self.n_circ,
            n_axial=self.n_axial,
            cavitation=self.cavitation,
            grooves=self.grooves,
            turbulence=self.turbulence,
            density_kg_m3=self.density_kg_m3,
            turbulence_onset_re=self.turbulence_onset_re,
            turbulence_full_re=self.turbulence_full_re,
            supply_flow_m3_s=self.supply_flow_m3_s,
        )

    def __getstate__(self) -> dict:
        return self._params()

    def __setstate__(self, state: dict) -> None:
        self.__init__(**state)

    def __eq__(self, other) -> bool:
        return isinstance(other, JournalBearing) and self._params() == other._params()

    def __hash__(self) -> int:
        return hash(tuple(self._params().items()))

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self._params().items())
        return f"JournalBearing({args})"

    def to_core(self) -> tuple[_core.JournalBearingGeometry, _core.FilmGrid]:
        """The C++ geometry and grid structs."""
        g = _core.JournalBearingGeometry()
        g.diameter_m = self.diameter_m
        g.length_m = self.length_m
        g.clearance_m = self.clearance_m
        g.viscosity_pa_s = self.viscosity_pa_s
        g.grooves = [gr.to_core() for gr in self.grooves]
        set_turbulence(g, self.turbulence, self.density_kg_m3, self.turbulence_onset_re,
                       self.turbulence_full_re)
        if self.supply_flow_m3_s is not None:
            g.supply_flow_m3_s = self.supply_flow_m3_s
        return g, _core.FilmGrid(self.n_circ, self.n_axial)

    def solver(self) -> _core.ReynoldsSolver:
        """This thread's C++ solver (built on first use: pattern analysis, warm-start state)."""
        s = getattr(self._local, "solver", None)
        if s is None:
            g, grid = self.to_core()
            s = _core.ReynoldsSolver(g, grid, self.cavitation)
            self._local.solver = s
        return s

    def _position(self, x_m, y_m) -> tuple[float, float]:
        x = _finite(x_m, "x_m")
        y = _finite(y_m, "y_m")
        eps = math.hypot(x, y) / self.clearance_m
        if not eps < 1.0:
            raise InputError(
                f"eccentricity ratio sqrt(x_m^2 + y_m^2)/clearance_m: expected < 1, got {eps:.6g}"
            )
        return x, y

    # -- single operating point ----------------------------------------------------------
    def forces(
        self, *, x_m: float, y_m: float, speed_hz: float, vx_m_s: float = 0.0, vy_m_s: float = 0.0
    ) -> np.ndarray:
        """Film force ``[Fx, Fy]`` on the journal, N (rigid journal at (x, y) moving at (vx, vy))."""
        x, y = self._position(x_m, y_m)
        w = TWO_PI * _speed(speed_hz)
        vx, vy = _velocity(vx_m_s, "vx_m_s"), _velocity(vy_m_s, "vy_m_s")
        return np.asarray(self.solver().force(x, y, vx, vy, w), dtype=float)

    def solve(
        self, *, x_m: float, y_m: float, speed_hz: float, vx_m_s: float = 0.0, vy_m_s: float = 0.0
    ) -> FilmResult:
        """Every scalar output of one solve: force, friction torque, flows, minimum film."""
        x, y = self._position(x_m, y_m)
        w = TWO_PI * _speed(speed_hz)
        r = self.solver().rigid(x, y, _velocity(vx_m_s, "vx_m_s"), _velocity(vy_m_s, "vy_m_s"), w)
        return FilmResult(
            force_n=np.asarray(r.force_n, dtype=float),
            friction_torque_n_m=float(r.friction_torque_nm),
            inlet_flow_m3_s=float(r.inlet_flow_m3_s),
            side_flow_m3_s=float(r.side_flow_m3_s),
            h_min_m=float(r.h_min_m),
            h_min_angle_deg=float(r.h_min_angle_deg),
            iterations=int(r.iterations),
            inlet_fill=float(r.inlet_fill),
            groove_pressure_factor=float(r.groove_pressure_factor),
            starved=bool(r.starved),
            full_film_start_deg=float(r.full_film_start_deg),
        )

    def pressure(
        self, *, x_m: float, y_m: float, speed_hz: float, vx_m_s: float = 0.0, vy_m_s: float = 0.0
    ) -> PressureField:
        """Pressure field and its grid, shapes (n_circ,), (n_axial+1,), (n_circ, n_axial+1)."""
        x, y = self._position(x_m, y_m)
        w = TWO_PI * _speed(speed_hz)
        s = self.solver()
        r = s.rigid(x, y, _velocity(vx_m_s, "vx_m_s"), _velocity(vy_m_s, "vy_m_s"), w)
        return PressureField(
            phi_rad=np.asarray(s.phi_rad),
            z_m=np.asarray(s.z_m),
            p_pa=np.array(r.p_pa),
            h_m=np.array(r.h_m),
            theta=np.array(r.theta),
            force_n=np.asarray(r.force_n, dtype=float),
        )

    def coefficients(
        self, *, x_m: float, y_m: float, speed_hz: float, method: str = "perturbation",
        rel_step: float = 1e-6,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Stiffness K (N/m) and damping C (N·s/m), 2×2, with dF = -K dq - C dq̇ (eq. 18).

        ``method="perturbation"`` differentiates the discrete Reynolds system (one factorisation,
        four right-hand sides); ``"finite_difference"`` takes central differences of the force
        with steps ``rel_step·c`` and ``rel_step·c·ω``.
        """
        x, y = self._position(x_m, y_m)
        w = TWO_PI * _speed(speed_hz)
        if method == "perturbation":
            dc = self.solver().coefficients(x, y, w)
        elif method == "finite_difference":
            step = v.in_range("rel_step", rel_step, 1e-10, 0.1, hi_open=True)
            dc = self.solver().coefficients_fd(x, y, w, step)
        else:
            raise InputError(
                f"method: expected 'perturbation' or 'finite_difference', got {method!r}"
            )
        return np.array(dc.K), np.array(dc.C)

    def static_equilibrium(
        self,
        *,
        load_n: Sequence[float],
        speed_hz: float,
        x0_m: float | None = None,
        y0_m: float | None = None,
        rtol: float = 1e-10,
    ) -> BearingEquilibrium:
        """Journal position where the film force balances the static load ``load_n`` (N).

        Newton iteration with the perturbation Jacobian (in C++), converged to
        ``|F + load| <= rtol·|load|``.
        """
        if isinstance(load_n, (str, bytes)) or not isinstance(load_n, (Sequence, np.ndarray)) \
                or len(load_n) != 2:
            raise InputError(f"load_n: expected two numbers (Fx, Fy) in N, got {load_n!r}")
        lx, ly = _finite(load_n[0], "load_n[0]"), _finite(load_n[1], "load_n[1]")
        W = math.hypot(lx, ly)
        if not math.isfinite(W):
            raise InputError(f"load_n: expected a finite load, got {load_n!r}")
        f = _speed(speed_hz)
        if f == 0.0:
            raise InputError("speed_hz: static equilibrium needs 0 < |speed_hz| <= 1e5, got 0")
        x0 = y0 = 0.0
        if x0_m is not None or y0_m is not None:
            x0, y0 = self._position(0.0 if x0_m is None else x0_m, 0.0 if y0_m is None else y0_m)
        tol = v.in_range("rtol", rtol, 1e-14, 1e-2)
        e = self.solver().equilibrium(lx, ly, TWO_PI * f, x0, y0, tol)
        x, y = float(e.x_m), float(e.y_m)
        eps = math.hypot(x, y) / self.clearance_m
        # attitude: angle from the load direction to the line of centres, + with the rotation
        if W > 0.0 and (x != 0.0 or y != 0.0):
            dx, dy = lx / W, ly / W
            att = math.degrees(math.atan2(dx * y - dy * x, dx * x + dy * y))
            if f < 0:
                att = -att
        else:
            att = float("nan")  # no load direction (zero load: the concentric journal)
        R = 0.5 * self.diameter_m
        S = (
            self.viscosity_pa_s * abs(f) * self.length_m * self.diameter_m / W
            * (R / self.clearance_m) ** 2
        ) if W > 0.0 else math.inf
        return BearingEquilibrium(
            x_m=x,
            y_m=y,
            eccentricity_ratio=eps,
            attitude_angle_deg=att,
            sommerfeld=S,
            load_n=(lx, ly),
            speed_hz=f,
            force_n=np.asarray(e.force_n, dtype=float),
            residual_rel=float(e.residual_rel),
            iterations=int(e.iterations),
        )

    def thermal_equilibrium(self, *, load_n: Sequence[float], speed_hz: float, oil: Oil,
                            supply_temperature_c: float, supply_flow_m3_s: float = 0.0,
                            carry_over: float = 0.0, effective_factor: float = 0.5,
                            tol_k: float = 1e-6, model: str = "effective",
                            theta_x_rad: float = 0.0, theta_y_rad: float = 0.0,
                            tilt: bool = False, **thd):
        """Effective-temperature (thermal) equilibrium under ``load_n`` (N) at ``speed_hz``:
        the film is isoviscous at μ(T_eff) of ``oil`` (:class:`rotordyn.bearings.Oil`), T_eff
        from a global heat balance with the supply at ``supply_temperature_c`` (°C), the fresh
        ``supply_flow_m3_s`` (0: the film's own demand), the hot-oil ``carry_over`` fraction
        λ ∈ [0, 1] and ``effective_factor`` k ∈ [0.5, 1] (T_eff = T_in + k ΔT); iterated with
        the Reynolds equilibrium in one C++ call to |ΔT_eff| <= ``tol_k``. K, C at the thermal
        equilibrium with the temperature frozen. Returns a
        :class:`rotordyn.bearings.ThermalEquilibriumResult` (docs/film-physics.md).
        ``viscosity_pa_s`` of this bearing is not used (the oil's law replaces it).

        ``model="thd"``: the thermo-hydrodynamic film instead (:mod:`rotordyn.bearings.thd`):
        the temperature field from the energy equation, μ(T) per node; ``effective_factor`` is
        not used; keyword options ``journal_htc_w_m2k``, ``bush_htc_w_m2k`` (W/(m² K), 0:
        adiabatic), ``journal_temperature_c``, ``bush_temperature_c`` (None: the supply
        temperature). Returns a :class:`rotordyn.bearings.thd.ThdEquilibriumResult`.

        ``theta_x_rad``, ``theta_y_rad`` (rad; inputs: the result names them
        ``journal_theta_*``), or ``tilt=True``: the journal tilted relative to the bearing (:func:`rotordyn.bearings.tilt_thermal.plain_tilted_thermal_equilibrium`:
        adds the moments, edge film and K4, C4 at the frozen temperature)."""
        if self.supply_flow_m3_s:
            raise InputError(
                "supply_flow_m3_s: the starved (metered-supply) film is not coupled to the "
                "thermal models yet; pass the supply to thermal_equilibrium(supply_flow_m3_s=...)"
                " of a bearing without the field (docs/film-physics.md, \"A starved film\")")
        opts = film_thermal_options(model, thd, supply_temperature_c=supply_temperature_c,
                                    supply_flow_m3_s=supply_flow_m3_s, carry_over=carry_over,
                                    effective_factor=effective_factor, tol_k=tol_k)
        load = self._load(load_n)
        f = _speed(speed_hz)
        if f == 0.0:
            raise InputError("speed_hz: the thermal equilibrium needs 0 < |speed_hz| <= 1e5, got 0")
        tx, ty = _finite(theta_x_rad, "theta_x_rad"), _finite(theta_y_rad, "theta_y_rad")
        if v.boolean("tilt", tilt) or tx != 0.0 or ty != 0.0:
            from rotordyn.bearings.tilt_thermal import plain_tilted_thermal_equilibrium

            return plain_tilted_thermal_equilibrium(self, theta_x_rad=tx, theta_y_rad=ty,
                                                    oil=oil, opts=opts, load_n=load,
                                                    speed_hz=f)
        s = getattr(self._local, "thermal_solver", None)
        if s is None:  # its own solver: the thermal iteration changes its viscosity
            g, grid = self.to_core()
            s = _core.ReynoldsSolver(g, grid, self.cavitation)
            self._local.thermal_solver = s
        if model == "thd":
            return run_thd_equilibrium(s, oil, opts, load, f, self.clearance_m)
        return run_thermal_equilibrium(s, oil, opts, load, f, self.clearance_m)

    @staticmethod
    def _load(load_n) -> tuple[float, float]:
        if isinstance(load_n, (str, bytes)) or not isinstance(load_n, (Sequence, np.ndarray)) \
                or len(load_n) != 2:
            raise InputError(f"load_n: expected two numbers (Fx, Fy) in N, got {load_n!r}")
        lx, ly = _finite(load_n[0], "load_n[0]"), _finite(load_n[1], "load_n[1]")
        if not math.hypot(lx, ly) > 0.0:
            raise InputError(f"load_n: expected a nonzero load, got {load_n!r}")
        return lx, ly

    def coefficient_table(self, speeds_hz, load_n, *, n_threads: int = 1):
        """Static equilibrium under ``load_n`` (N, on the journal) and K, C at each speed in
        ``speeds_hz`` (Hz), in one C++ call parallel over speeds (``n_threads``, 0: all
        cores): a :class:`rotordyn.bearings.CoefficientTable` (``.to_frame()``,
        ``.to_csv()``; a failing speed is a NaN row with its status)."""
        g, grid = self.to_core()
        f = _core.FilmCoupling()
        f.name, f.geometry, f.grid, f.cavitation = "bearing", g, grid, self.cavitation
        f.coords = [0, 1]
        phi = TWO_PI * np.arange(self.n_circ) / self.n_circ
        f.shape = np.column_stack([-np.cos(phi), -np.sin(phi)])
        return coefficient_table(SystemParts(films=[f], tables=[]), load_n, speeds_hz,
                                 self.clearance_m, n_threads=n_threads)

    # -- batches -------------------------------------------------------------------------
    _STATUS_ERRORS = {1: "InputError", 2: "ContactError", 3: "ConvergenceError", 4: "RotordynError"}

    def _batch_result(self, res, on_error: str):
        values = np.asarray(res.values)
        status = np.asarray(res.status)
        bad = np.flatnonzero(status)
        if bad.size and on_error == "raise":
            import rotordyn.errors as errors

            i = int(bad[0])
            exc = getattr(errors, self._STATUS_ERRORS.get(int(status[i]), "RotordynError"))
            raise exc(f"point {i} (of {bad.size} failing): {res.message[i]}")
        return values, status, list(res.message)

    @staticmethod
    def _check_batch_options(n_threads, on_error):
        if on_error not in ("raise", "nan"):
            raise InputError(f"on_error: expected 'raise' or 'nan', got {on_error!r}")
        if isinstance(n_threads, bool) or not isinstance(n_threads, (int, np.integer)) \
                or not 0 <= n_threads <= MAX_THREADS:
            raise InputError(
                f"n_threads: expected an integer in [0, {MAX_THREADS}] (0: all cores), got "
                f"{n_threads!r}"
            )

    @staticmethod
    def _broadcast(**arrays):
        vals = [_float_array(a, k) for k, a in arrays.items()]
        try:
            return np.broadcast_arrays(*vals)
        except ValueError:
            shapes = ", ".join(f"{k} {a.shape}" for k, a in zip(arrays, vals))
            raise InputError(f"{', '.join(arrays)}: shapes do not broadcast ({shapes})") from None

    def forces_batch(self, *, x_m, y_m, speed_hz, vx_m_s=0.0, vy_m_s=0.0, n_threads: int = 1,
                     on_error: str = "raise") -> np.ndarray:
        """Forces (n, 2) for broadcast arrays of states, in one C++ call (GIL released).

        ``n_threads`` > 1 splits the points over threads, each with its own solver (0: all
        cores). ``on_error="raise"`` raises the first failing point's error (after the batch);
        ``"nan"`` leaves NaN rows for failing points.
        """
        self._check_batch_options(n_threads, on_error)
        x, y, f, vx, vy = self._broadcast(x_m=x_m, y_m=y_m, speed_hz=speed_hz, vx_m_s=vx_m_s,
                                          vy_m_s=vy_m_s)
        states = np.ascontiguousarray(np.stack([x.ravel(), y.ravel(), vx.ravel(), vy.ravel()], 1))
        if on_error == "raise":
            if not np.all(np.isfinite(states)) or not np.all(np.isfinite(f)):
                raise InputError("x_m, y_m, vx_m_s, vy_m_s, speed_hz: expected finite values")
            eps = np.hypot(states[:, 0], states[:, 1]) / self.clearance_m
            if np.any(eps >= 1.0):
                raise InputError(
                    f"eccentricity ratio: expected < 1 at every point, got max {eps.max():.6g}"
                )
        res = self.solver().batch_forces(states, TWO_PI * f.ravel(), int(n_threads))
        return self._batch_result(res, on_error)[0]

    def coefficients_batch(self, *, x_m, y_m, speed_hz, n_threads: int = 1,
                           on_error: str = "raise") -> dict[str, np.ndarray]:
        """Forces (n, 2), K (n, 2, 2), C (n, 2, 2) by perturbation, in one C++ call, with
        ``status`` (n,) (0 ok, 1 bad input, 2 contact, 3 not converged) and ``message``."""
        self._check_batch_options(n_threads, on_error)
        x, y, f = self._broadcast(x_m=x_m, y_m=y_m, speed_hz=speed_hz)
        pos = np.ascontiguousarray(np.stack([x.ravel(), y.ravel()], 1))
        if on_error == "raise":
            if not np.all(np.isfinite(pos)) or not np.all(np.isfinite(f)):
                raise InputError("x_m, y_m, speed_hz: expected finite values")
            eps = np.hypot(pos[:, 0], pos[:, 1]) / self.clearance_m
            if np.any(eps >= 1.0):
                raise InputError(
                    f"eccentricity ratio: expected < 1 at every point, got max {eps.max():.6g}"
                )
        res = self.solver().batch_coefficients(pos, TWO_PI * f.ravel(), int(n_threads))
        out, status, message = self._batch_result(res, on_error)
        return {
            "force_n": out[:, 0:2],
            "K": out[:, 2:6].reshape(-1, 2, 2),
            "C": out[:, 6:10].reshape(-1, 2, 2),
            "status": status,
            "message": message,
        }




__all__ = [
    "CAVITATION_MODELS",
    "Groove",
    "JournalBearing",
    "FilmResult",
    "PressureField",
    "BearingEquilibrium",
]
