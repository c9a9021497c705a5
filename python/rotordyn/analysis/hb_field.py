"""The harmonic-balance corrector of a branch of periodic orbits over a model field
(``rd.continuation(system, "bearings.0.viscosity_pa_s", bounds, start=orbit,
method="harmonic_balance")``; docs/nonlinear.md, "Branches over a model field").

The core varies p_c, Ω and a_y inside its corrector (``_core.hb_continuation_step``); a model
field (a clearance, a viscosity, a support stiffness) changes the assembled model itself, so
the system is re-assembled at every value the corrector visits (:class:`FieldSystems`) and
the bordered Newton runs here, around whole C++ evaluations (``_core.hb_evaluate``: one AFT
residual, M film solves, or with its Jacobian M film linearisations), as the equilibrium
branch over a field does. The unknowns, conditions, scaling, step cap, line search and
convergence test are those of the C++ corrector (cpp/src/hb_continuation.cpp), with ∂R/∂p a
central difference of two residual evaluations on the systems at p ± h. The converged point's
checks and Floquet multipliers are the C++ corrector's (``_core.hb_orbit_point``: from the
last evaluation's film linearisations or by Hill's method on its Jacobian, one CVODES flow
near the unit circle). The branch loop
is :func:`rotordyn.analysis.hb_continuation.hb_branch`'s: this corrector returns what
``_core.hb_continuation_step`` returns."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn.errors import InputError

#: the line search's halvings and the step cap (the C++ corrector's)
LINE_SEARCH, CAP_Z, CAP_W, CAP_P = 8, 0.25, 0.1, 0.25


class _Orbit:
    """A corrected orbit as the branch loop reads it: the core's PeriodicOrbitResult (None for
    a failure) with this corrector's status, message, iterations and residuals."""

    def __init__(self, core=None, **own):
        self._core = core
        self.__dict__.update(own)

    def __getattr__(self, name):
        if self._core is None:
            raise AttributeError(name)
        return getattr(self._core, name)


@dataclasses.dataclass
class _HB:
    """The harmonic-balance part of a corrector step (``_core.HarmonicBalanceResult``'s)."""

    orbit: _Orbit
    coefficients: np.ndarray
    frequency: float
    harmonic_amplitudes: np.ndarray
    harmonics: int
    time_points: int
    evaluations: int = 0
    linearizations: int = 0


@dataclasses.dataclass
class FieldStep:
    """One corrector step over a field (``_core.HbContinuationStep``'s attributes)."""

    hb: _HB
    p: float
    tangent: np.ndarray
    floquet_route: str = ""
    screen_critical_modulus: float = float("nan")
    screen_trivial_error: float = float("nan")
    fd_evaluations: int = 0


class FieldCorrector:
    """``corrector(z, w, p, y_prev, tangent, ds)``: one pseudo-arclength corrector step of the
    branch ``setup`` (a model field) by harmonic balance; the layout of
    ``_core.hb_continuation_step`` (z the (2H + 1)·n coefficients row by row, ω, p; y_prev
    unscaled, the tangent scaled by (L, D_ω, D_p); an empty tangent holds p: the first
    point). ``ho``, ``opt``: the core's harmonic-balance and corrector options (their
    length_scale is L)."""

    def __init__(self, setup, ho, opt, scale, fd_step: float, direction: int):
        self.setup, self.ho, self.opt = setup, ho, opt
        self.H, self.M = int(ho.harmonics), int(ho.time_points)
        self.n = setup.n
        self.nb = 2 * self.H + 1
        self.nn = self.nb * self.n
        self.autonomous = setup.kind == "autonomous"
        self.L, self.Dw, self.Dp = (float(x) for x in scale)
        self.h = float(fd_step) * self.Dp
        self.direction = int(direction)
        self.w_forced = 2 * np.pi / float(setup.base.period)
        self.evaluations = self.linearizations = self.solves = 0
        self._inputs: dict = {}

    # -- the system at a field value
    def _input(self, p: float):
        key = float(p)
        inp = self._inputs.get(key)
        if inp is None:
            inp = self.setup.input_at(key)
            if len(self._inputs) >= 6:
                self._inputs.pop(next(iter(self._inputs)))
            self._inputs[key] = inp
        return inp

    def evaluate(self, p: float, Z: np.ndarray, w: float, jacobian: bool):
        """One AFT evaluation on the system with the field at ``p`` (``_core.HbEvaluation``);
        a value the model refuses is an evaluation that failed, with the model's message."""
        try:
            asm = self.setup.field.at(p)
            inp = self._input(p)
        except InputError as exc:
            return _Refused(f"the model refuses {self.setup.vary} = {p:.6g}: {exc}")
        ev = _core.hb_evaluate(asm.solver, inp, np.ascontiguousarray(Z), float(w), self.ho,
                               bool(jacobian))
        self.evaluations += 1
        self.linearizations += int(ev.linearizations)
        self.solves += int(ev.reynolds_solves)
        return ev

    def _scaled(self, R: np.ndarray, rowscale: np.ndarray) -> np.ndarray:
        return (R.reshape(self.nb, self.n) / rowscale).ravel() / self.L

    # -- one corrector step
    def __call__(self, z, w, p, y_prev, tangent, ds) -> FieldStep:
        n, nb, nn, L, Dw, Dp = self.n, self.nb, self.nn, self.L, self.Dw, self.Dp
        auto = self.autonomous
        first = np.size(tangent) == 0
        U = nn + 2 if auto else nn + 1
        iw, ip = nn, U - 1
        self.evaluations = self.linearizations = self.solves = 0
        fd = 0
        sfull = np.concatenate([np.full(nn, L), [Dw, Dp]])
        y_prev = np.asarray(y_prev, dtype=float)

        def to_unknowns(full):
            return np.concatenate([full[:nn], [full[nn]], [full[nn + 1]]]) if auto else \
                np.concatenate([full[:nn], [full[nn + 1]]])

        uprev = to_unknowns(y_prev / sfull)
        t_prev = None if first else to_unknowns(np.asarray(tangent, dtype=float))
        Z = np.asarray(z, dtype=float).reshape(nb, n).copy()
        p = float(p)
        w = float(w) if auto else self.w_forced
        residuals: list = []

        def fail(status, message, it=0):
            return self._failed(Z, w, p, status, message, it, residuals, fd)

        phi = None
        if auto:  # the integral phase condition against the previous point, normalised
            Zp = y_prev[:nn].reshape(nb, n)
            phi = np.zeros((nb, n))
            k = np.arange(1, self.H + 1)[:, None]
            phi[1::2] = k * Zp[2::2]
            phi[2::2] = -k * Zp[1::2]
            phi = phi.ravel()
            pn = np.linalg.norm(phi)
            if not pn > 0:
                return fail("not_converged", "the previous point has no harmonics (an "
                            "equilibrium): no phase condition")
            phi /= pn

        def unknowns(Zc, wc, pc):
            head = Zc.ravel() / L
            return np.concatenate([head, [wc / Dw, pc / Dp]] if auto else [head, [pc / Dp]])

        def conditions(u):
            g = [float(phi @ u[:nn])] if auto else []
            g.append(0.0 if first else float(t_prev @ (u - uprev)) - ds)
            return np.array(g)

        cur = self.evaluate(p, Z, w, True)
        if not cur.ok:
            return fail("rub" if cur.contact else "not_converged",
                        "harmonic balance at the predicted point: " + cur.message)
        rowscale = np.asarray(cur.row_scale, dtype=float)

        def dRdp(Zc, wc, pc):
            nonlocal fd
            ep = self.evaluate(pc + self.h, Zc, wc, False)
            em = self.evaluate(pc - self.h, Zc, wc, False)
            fd += 2
            if not (ep.ok and em.ok):
                return None
            return (np.asarray(ep.residual) - np.asarray(em.residual)) / (2 * self.h)

        def rows(ev, drdp):
            J = np.zeros((nn + 1 if auto else nn, U))
            inv = np.tile(1.0 / rowscale, nb)[:, None]
            J[:nn, :nn] = inv * np.asarray(ev.jacobian)
            J[:nn, ip] = self._scaled(drdp, rowscale) * Dp
            if auto:
                J[:nn, iw] = self._scaled(np.asarray(ev.d_frequency), rowscale) * Dw
                J[nn, :nn] = phi
            return J

        converged, drdp_conv, it = False, None, 0
        while True:
            Rs = self._scaled(np.asarray(cur.residual), rowscale)
            g = conditions(unknowns(Z, w, p))
            res = max(float(np.abs(Rs).max()), float(np.abs(g).max()))
            residuals.append(res)
            if not np.isfinite(res):
                return fail("error", "non-finite harmonic-balance residual", it)
            drdp = dRdp(Z, w, p)
            if drdp is None:
                return fail("not_converged", f"corrector iteration {it}: a residual at p ± h "
                            "for the parameter derivative failed", it)
            if res < self.ho.tol:
                converged, drdp_conv = True, drdp
                break
            if it >= self.ho.max_iter:
                break
            J = np.zeros((U, U))
            Jr = rows(cur, drdp)
            J[:Jr.shape[0]] = Jr
            b = np.zeros(U)
            b[:nn] = -Rs
            if auto:
                b[nn] = -g[0]
            if first:
                J[U - 1, ip] = 1.0
            else:
                J[U - 1] = t_prev
                b[U - 1] = -g[-1]
            try:
                d = np.linalg.solve(J, b)
            except np.linalg.LinAlgError:
                d = np.full(U, np.nan)
            if not np.all(np.isfinite(d)) or np.linalg.norm(J @ d - b) > \
                    1e-6 * max(np.linalg.norm(b), 1e-300) + 1e-12:
                return fail("not_converged", f"corrector iteration {it}: singular bordered "
                            "Newton matrix (a branch point, or a step too long)", it)
            cap = max(1.0, float(np.abs(d[:nn]).max()) / CAP_Z,
                      abs(d[iw]) * Dw / (CAP_W * w) if auto else 0.0, abs(d[ip]) / CAP_P)
            d /= cap
            m0 = float(np.hypot(np.linalg.norm(Rs), np.linalg.norm(g)))
            lam, trial = 1.0, None
            for ls in range(LINE_SEARCH):
                Zt = Z + lam * L * d[:nn].reshape(nb, n)
                pt = p + lam * d[ip] * Dp
                wt = w + lam * d[iw] * Dw if auto else w
                trial = self.evaluate(pt, Zt, wt, True)
                if trial.ok:
                    mt = float(np.hypot(np.linalg.norm(self._scaled(
                        np.asarray(trial.residual), rowscale)),
                        np.linalg.norm(conditions(unknowns(Zt, wt, pt)))))
                    if mt < (1.0 - 1e-4 * lam) * m0 or ls == LINE_SEARCH - 1:
                        break  # (the smallest step is accepted: a kink of the film)
                lam *= 0.5
            if not trial.ok:
                return fail("rub" if trial.contact else "not_converged",
                            f"corrector iteration {it}: {trial.message}", it)
            if auto and not wt > 0:
                return fail("not_converged", f"corrector iteration {it}: the frequency fell "
                            "to ≤ 0", it)
            Z, w, p, cur = Zt, wt, pt, trial
            it += 1
        if not converged:
            return fail("not_converged", f"corrector did not converge in {self.ho.max_iter} "
                        f"Newton iterations: residual {res:.6g} (tol {self.ho.tol:g}); "
                        "shorten the step", it)
        # the converged point: samples, checks and multipliers by the core (from the last
        # evaluation's film linearisations), on the system at p
        pt_core = _core.hb_orbit_point(self.setup.field.at(p).solver, self._input(p), cur,
                                       self.opt)
        o = pt_core.hb.orbit
        if o.status != "ok":
            return fail(o.status, o.message, it)
        # the tangent: the null vector of the rows (R̃, phase) bordered by the previous
        # tangent (first point: by e_p), oriented along it (first point: by direction)
        B = np.zeros((U, U))
        Jr = rows(cur, drdp_conv)
        B[:Jr.shape[0]] = Jr
        if first:
            B[U - 1, ip] = 1.0
        else:
            B[U - 1] = t_prev
        e_u = np.zeros(U)
        e_u[-1] = 1.0
        try:
            tz = np.linalg.solve(B, e_u)
        except np.linalg.LinAlgError:
            tz = np.full(U, np.nan)
        if not np.all(np.isfinite(tz)) or np.linalg.norm(tz) == 0 or \
                np.linalg.norm(B @ tz - e_u) > 1e-8:
            return fail("not_converged", "no tangent at the corrected point (singular "
                        "bordered matrix: a branch point)", it)
        tz /= np.linalg.norm(tz)
        if first and tz[ip] * self.direction < 0:
            tz = -tz
        tangent_full = np.zeros(nn + 2)
        tangent_full[:nn] = tz[:nn]
        if auto:
            tangent_full[nn] = tz[iw]
        tangent_full[nn + 1] = tz[ip]
        orbit = _Orbit(o, status="ok", message="", iterations=it, residuals=list(residuals),
                       residual=residuals[-1], reynolds_solves=self.solves + o.reynolds_solves)
        hb = _HB(orbit=orbit, coefficients=Z, frequency=w,
                 harmonic_amplitudes=np.asarray(pt_core.hb.harmonic_amplitudes),
                 harmonics=self.H, time_points=self.M,
                 evaluations=self.evaluations + int(pt_core.hb.evaluations),
                 linearizations=self.linearizations + int(pt_core.hb.linearizations))
        return FieldStep(hb=hb, p=p, tangent=tangent_full, floquet_route=pt_core.floquet_route,
                         screen_critical_modulus=float(pt_core.screen_critical_modulus),
                         screen_trivial_error=float(pt_core.screen_trivial_error),
                         fd_evaluations=fd)

    def _failed(self, Z, w, p, status, message, it, residuals, fd) -> FieldStep:
        orbit = _Orbit(None, status=status, message=message, iterations=it,
                       residuals=list(residuals), residual=residuals[-1] if residuals
                       else float("nan"))
        hb = _HB(orbit=orbit, coefficients=Z, frequency=w,
                 harmonic_amplitudes=np.zeros(self.H + 1), harmonics=self.H,
                 time_points=self.M, evaluations=self.evaluations,
                 linearizations=self.linearizations)
        return FieldStep(hb=hb, p=p, tangent=np.zeros(0), fd_evaluations=fd)


class _Refused:
    """An evaluation at a field value the model refuses (e.g. a clearance ≤ 0)."""

    ok = False
    contact = False

    def __init__(self, message: str):
        self.message = message
