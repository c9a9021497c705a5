"""One point of a sweep inside a chunk: the model variant of its model-field axes (a fresh
solver per chunk), its options and operating values, its equilibrium and eigen-analysis, and the
identity columns and failure rows every analysis's rows start from (used by :mod:`.work` and
:mod:`.lines`)."""

from __future__ import annotations

import copy

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED  # noqa: F401 - statuses of a converged equilibrium
from rotordyn._common.whirl import WHIRL_NAMES
from rotordyn.analysis.assembly import Assembled
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.errors import InputError, RotordynError
from rotordyn.results.modes import mode_stable
from rotordyn.model.system import System
from rotordyn.sweep.paths import set_fields
from rotordyn.units import hz_to_rad_s


STATUS = ["ok", "no_equilibrium", "contact", "not_converged", "no_crossing", "error", "rub",
          "starved"]

_BASE: dict = {}


def base_system(model_toml: str):
    """The model of a sweep (parsed once per process and model text)."""
    sysm = _BASE.get(model_toml)
    if sysm is None:
        _BASE.clear()
        sysm = _BASE[model_toml] = System.from_toml(model_toml, is_text=True)
    return sysm


_ASM: dict = {}  # (model text, model-axis values) -> Assembled (stateless parts reused)


class Variants:
    """The model for each combination of model-field axes met in this chunk, each with a
    solver built fresh for this chunk (the reduction and sleeve condensation are cached per
    process; the solver, which keeps warm starts, is not shared between chunks)."""

    def __init__(self, base, model_toml: str):
        self.base = base
        self.model_toml = model_toml
        self.cache = {}

    @staticmethod
    def _key(p: dict) -> tuple:
        return tuple((k, val) for k, val in p.items() if "." in k and not k.startswith(
            "options.") or k == "gravity_m_s2")

    def _fresh(self, key, build):
        """This chunk's copy of the process-wide assembled model ``key`` (built by
        ``build()`` once per process), with a solver of its own."""
        hit = self.cache.get(key)
        if hit is None:
            proto = _ASM.get((self.model_toml, key))
            if proto is None:
                proto = build()
                if len(_ASM) > 8:
                    _ASM.clear()
                _ASM[(self.model_toml, key)] = proto
            hit = copy.copy(proto)
            hit.solver = _core.SystemSolver(proto.model)
            hit.last_r = None
            m = proto.model
            hit.mats = tuple(np.asarray(x) for x in (m.M, m.C, m.G, m.K))
            if len(self.cache) > 4:
                self.cache.clear()
            self.cache[key] = hit
        return hit

    def get(self, p: dict):
        key = self._key(p)

        def build():
            return Assembled(set_fields(self.base, key))

        return self._fresh(key, build)

    def refined(self, p: dict):
        """The model of ``p`` with every film grid refined twice (n_circ, n_axial × 2:
        :func:`rotordyn.analysis.hopf.refined`, the ``hopf`` analysis's ``grid_check``),
        with a solver of its own built fresh for this chunk."""
        from rotordyn.analysis.hopf import refined

        return self._fresh(("refined",) + self._key(p),
                           lambda: Assembled(refined(self.get(p).system)))


def point_options(job, p: dict) -> dict:
    opts = job.options
    keys = [k for k in p if k.startswith("options.")]
    if not keys:
        return opts
    opts = copy.deepcopy(opts)
    for k in keys:
        parts = k.split(".")[1:]
        if len(parts) == 1:
            opts[parts[0]] = p[k]
            continue
        cur = opts[parts[0]]
        for q in parts[1:-1]:
            cur = cur[int(q)]
        cur[int(parts[-1])] = p[k]
    return opts


def operating(asm, p: dict, memo: dict | None = None):
    """speed (Hz), p_c (Pa), configuration vector; InputError on a bad value. ``memo``: a dict
    kept by the caller for one chunk, in which the configuration vector of each (model, a_y,
    a_x) is built once (a line over p_c or the speed shares one; the vector is read-only)."""
    f = v.finite("speed_hz", p.get("speed_hz", 50.0))
    pc = v.non_negative("chamber_pressure_pa", p.get("chamber_pressure_pa", 0.0))
    ay, ax = p.get("config_ay_m"), p.get("config_ax_m")
    if memo is None:
        return f, pc, asm.config_vector(ay, ax)
    key = (id(asm), ay, ax)
    a = memo.get(key)
    if a is None:
        a = memo[key] = asm.config_vector(ay, ax)
        a.flags.writeable = False
    return f, pc, a


def ref_bearing(asm, name: str | None = None):
    """The bearing whose journal the rows' ``journal_*``/``config_ay_m`` columns describe
    (column ``journal_bearing``): the one named by the option ``bearing``, else the active
    bearing, else the first."""
    if name is not None:
        for bc in asm.bearings:
            if getattr(asm.system.bearings[bc.index], "name", None) == name:
                return bc
        raise InputError(f"options.bearing: {name!r} is not a bearing of the model")
    act = [bc for bc in asm.bearings if bc.active]
    return (act or asm.bearings)[0] if asm.bearings else None


def equilibrium_options(opts):
    """The C++ equilibrium options of a sweep's analysis options (automatic P_m, thin-film
    contact at 2 % of c)."""

    o = _core.EquilibriumOptions()
    o.method = opts.get("method", "newton")
    o.tol = float(opts.get("tol", 1e-10))
    o.max_iter = int(opts.get("max_iter", 100))
    o.pm = -1.0
    o.contact_fraction = 0.02
    return o


def solve_equilibrium(asm, f, pc, a, r0, opts):
    o = equilibrium_options(opts)
    return asm.solver.equilibrium(hz_to_rad_s(f), pc, a, np.zeros(0) if r0 is None else r0, o)


def eigen(asm, e, f, opts, n_modes):
    """Eigenvalues, modes (n, k), whirl, kind of eq. 19 at equilibrium ``e``."""

    w = hz_to_rad_s(f)
    r = np.asarray(e.r)
    if opts.get("linearization", "perturbation") == "perturbation":
        lin = asm.solver.linearize(r, np.zeros(asm.n), w)
    else:
        lin = asm.solver.linearize_fd(r, w, FD_REL_STEP)
    M, C0, G, K0 = asm.mats
    if asm.model.has_table_mass():  # bearing tables' mass coefficients: M(Ω)
        M = np.asarray(asm.model.mass_at(w))
    D = C0 + w * G + np.asarray(lin.DH)
    K = K0 + np.asarray(lin.KH)
    if not (np.all(np.isfinite(K)) and np.all(np.isfinite(D))):
        raise ArithmeticError("non-finite bearing coefficients")
    res = _core.modal(M, D, K, asm.rotor.xy_pairs(), int(n_modes or asm.n), True,
                      asm.rotor.rot_pairs())
    lam = np.asarray(res.eigenvalues)
    phi = np.asarray(res.modes)
    if not np.all(np.isfinite(lam)):  # never a non-finite eigenvalue with status ok
        raise ArithmeticError("non-finite eigenvalues")
    sl = [i for bc in asm.bearings for i in bc.sleeve]
    kin = np.real(np.einsum("ik,ij,jk->k", phi.conj(), M, phi))
    kin_s = (np.real(np.einsum("ik,ij,jk->k", phi[sl].conj(), M[np.ix_(sl, sl)], phi[sl]))
             if sl else np.zeros(len(lam)))
    kind = mode_kind(asm, M, phi, np.where(kin_s > 0.5 * kin, "sleeve", "rotor"))
    whirl = np.array([WHIRL_NAMES[int(x)] for x in res.whirl])
    return lam, phi, whirl, kind


def mode_kind(asm, M, phi, kind) -> np.ndarray:
    """``kind`` ("rotor"/"sleeve" per mode) with "pad" where the tilting pads' own coordinates
    carry more than half of the mode's kinetic energy — the rule of ``rotordyn.stability``
    (analysis/linear.py), so a sweep row and the API name a mode alike (before, the sweep
    called the generator's 2.30 Hz and 52.06 Hz pad roots "rotor")."""
    kind = np.asarray(kind).astype(object)
    pads = [i for bc in asm.bearings for i in getattr(bc, "extra", ())]
    if not pads or phi.shape[1] == 0:
        return kind
    M = np.asarray(M)
    kin = np.real(np.einsum("ik,ij,jk->k", phi.conj(), M, phi))
    kin_p = np.real(np.einsum("ik,ij,jk->k", phi[pads].conj(), M[np.ix_(pads, pads)],
                              phi[pads]))
    kind[kin_p > 0.5 * kin] = "pad"
    return kind


def stable_modes(lam) -> np.ndarray:
    """Per mode: Re λ below the round-off band (the rule of StabilityResult.stable)."""
    return mode_stable(lam)


def job_model_ay(asm, bc):
    """The configuration a_y (m) of the model's bearing ``bc``."""
    return float(asm.system.bearings[bc.index].config_ay_m)


def _model_key(k: str) -> bool:
    return "." in k and not k.startswith("options.") or k == "gravity_m_s2"


def point_list(job, variants, pids, asms: list) -> list:
    """Per point of ``pids``: [p, asm, opts, same_line, error] (as :func:`points`, without
    the row dict: the columnar chunks build their identity columns at once); ``asms[k]``
    is set to the point's model (None for a model-variant error). The indices and line flags
    are computed for all points at once; without model-field or option axes every point
    shares the chunk's one model and the analysis's options."""
    n = len(pids)
    if n == 0:
        return []
    idx = np.unravel_index(np.asarray(pids, dtype=np.int64), job.shape)
    names, vals = list(job.axes), list(job.axes.values())
    cols = [ix.tolist() for ix in idx]
    line = np.zeros(n, bool)
    line[1:] = True
    for d, ix in enumerate(idx):
        if d != job.line_pos:
            line[1:] &= ix[1:] == ix[:-1]
    line = line.tolist()
    ps = [{a: v[c[k]] for a, v, c in zip(names, vals, cols)} for k in range(n)]
    shared = not any(_model_key(a) or a.startswith("options.") for a in names)
    out = []
    for k, p in enumerate(ps):
        if shared and k > 0:
            asm, err = out[0][1], out[0][4]
        else:
            try:
                asm, err = variants.get(p), None
            except RotordynError as exc:
                asm, err = None, str(exc)
        asms[k] = asm
        out.append([p, asm, job.options if shared else point_options(job, p), line[k], err])
    return out


def segments(items, errs):
    """Runs [i, j) of consecutive points without an error sharing one model and one set of
    options (one C++ call each), with the error points between them as (i, i + 1, False)."""
    i, n = 0, len(items)
    while i < n:
        if errs[i]:
            yield i, i + 1, False
            i += 1
            continue
        j = i + 1
        while j < n and not errs[j] and items[j][1] is items[i][1] and \
                items[j][2] == items[i][2]:
            j += 1
        yield i, j, True
        i = j
