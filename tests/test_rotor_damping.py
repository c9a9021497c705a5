"""Material (proportional) damping of the shaft: C_e = α M_e + β K_e per element.

References:
- Proportional (Rayleigh) damping decouples the undamped modes: a mode of circular frequency
  ω gets the damping ratio ζ = α/(2ω) + βω/2 and the eigenvalue
  λ = −ζω ± iω√(1 − ζ²), |λ| = ω (Friswell, Penny, Garvey & Lees, Dynamics of Rotating
  Machines, Cambridge 2010, on proportional damping; Géradin & Rixen, Mechanical
  Vibrations, 3rd ed. 2015). Exact for the rotor at rest (G does not act) on rigid
  supports (K is the shaft's alone), and for its Guyan reduction too (T'(αM + βK)T =
  αM_r + βK_r).
- ROSS ``ShaftElement(alpha=..., beta=...)`` adds the same α M_e + β K_e (compared when
  ross-rotordynamics is installed, skipped otherwise).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.modes import rotor_matrices, turn_matrix

MODELS = Path(__file__).parent / "data" / "models"
ALPHA, BETA = 20.0, 2.0e-5  # 1/s, s: ζ of 1 % to 13 % over the modes below


def _compressor(alpha=0.0, beta=0.0, method="none", masters=(), disks=True):
    """The compressor rotor (tests/data/models/compressor_linear.toml: 1.2 m, three 30 kg
    impellers) on rigid supports at its bearing stations 1 and 5, no bearing element."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    rotor = dataclasses.replace(s.rotor, damping_alpha_1_per_s=alpha, damping_beta_s=beta,
                                disks=s.rotor.disks if disks else ())
    return dataclasses.replace(s, rotor=rotor, bearings=(),
                               supports=(rd.Support(1), rd.Support(5)),
                               reduction=rd.Reduction(master_stations=masters, method=method))


@pytest.mark.parametrize("method,masters,disks", [("none", (), False), ("guyan", (2, 3, 4), False),
                                                  ("none", (), True), ("guyan", (2, 3, 4), True)])
def test_damping_ratio_of_proportional_damping_is_the_closed_form(method, masters, disks):
    """α M_e + β K_e of the shaft: with the disks (whose mass takes no α, as in ROSS) the
    closed form holds for β alone; the bare shaft takes both. ω from scipy's eigh of the
    undamped (K, M), independent of the package's eigen-solver (the full model's
    shift-invert Arnoldi: |λ| to 4e-8 seen, so ζ ~ 0.1 to ~4e-7)."""
    from scipy.linalg import eigh

    n = 8
    alpha = 0.0 if disks else ALPHA
    M, K = rotor_matrices(_compressor(method=method, masters=masters,
                                      disks=disks)).matrices()[:2]
    omega = np.sqrt(eigh(K, M, eigvals_only=True)[:n])  # undamped, rad/s (x/y pairs)
    lam = rd.modes(_compressor(alpha, BETA, method, masters, disks), 0.0,
                   n_modes=n).eigenvalues
    zeta = alpha / (2 * omega) + BETA * omega / 2
    assert zeta.min() > 0.002 and zeta.max() < 0.3  # a case where the terms count
    if not disks:
        assert (alpha / (2 * omega[0])) > 0.1 * zeta[0]  # α's share is not negligible
    np.testing.assert_allclose(np.abs(lam), omega, rtol=2e-7)
    np.testing.assert_allclose(-lam.real / np.abs(lam), zeta, rtol=2e-6)


def test_assembled_damping_is_alpha_m_plus_beta_k_of_the_shaft():
    """Free-free shaft without supports: C = αM + βK; disks take no damping."""
    s = _compressor(ALPHA, BETA)
    s = dataclasses.replace(s, supports=(), rotor=dataclasses.replace(s.rotor, disks=()))
    C, M, K = (x.toarray() for x in (s.C(), s.M(), s.K()))
    np.testing.assert_allclose(C, ALPHA * M + BETA * K, rtol=1e-14, atol=1e-12 * np.abs(C).max())
    with_disks = _compressor(ALPHA, BETA)
    with_disks = dataclasses.replace(with_disks, supports=())
    np.testing.assert_array_equal(with_disks.C().toarray(), C)  # disks add M only


def test_a_section_value_replaces_the_rotors():
    s = _compressor(0.0, BETA)
    secs = s.rotor.sections
    # every section naming the rotor's value: the same matrix, bit for bit
    same = dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, damping_beta_s=0.0,
        sections=tuple(dataclasses.replace(x, damping_beta_s=BETA) for x in secs)))
    np.testing.assert_array_equal(same.C().toarray(), s.C().toarray())
    # the first section (2 elements) undamped: its own nodes 0, 1 lose their C rows
    first = dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, sections=(dataclasses.replace(secs[0], damping_beta_s=0.0),) + secs[1:]))
    C = first.C().toarray()
    assert not np.any(C[:8]) and np.any(C[8:12]) and np.any(s.C().toarray()[:8])


def test_zero_damping_adds_no_entry():
    """α = β = 0 (given or default) assembles C from the supports alone: the same sparse
    matrix and the same analysis results, bit for bit."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    z = dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, damping_alpha_1_per_s=0.0, damping_beta_s=0.0,
        sections=tuple(dataclasses.replace(x, damping_alpha_1_per_s=0.0, damping_beta_s=0.0)
                       for x in s.rotor.sections)))
    C0, Cz = s.C(), z.C()
    assert Cz.nnz == C0.nnz == 8  # the two supports' 2 × 2 blocks
    np.testing.assert_array_equal(Cz.toarray(), C0.toarray())
    a, b = rd.modes(s, 100.0).eigenvalues, rd.modes(z, 100.0).eigenvalues
    np.testing.assert_array_equal(a, b)


def test_damping_enters_the_linear_system_reduced_like_the_supports_c():
    """The stability analysis's structural C of a Guyan-reduced rotor on fluid-film bearings
    (the compressor on plain bearings) is the undamped one plus T'(βK_shaft)T."""
    from coarse_models import compressor_plain

    s0 = compressor_plain()
    s1 = dataclasses.replace(s0, rotor=dataclasses.replace(s0.rotor, damping_beta_s=BETA))
    l0 = rd.linearize(s0, 80.0)
    l1 = rd.linearize(s1, 80.0)
    rm = rotor_matrices(s0)  # no supports: the constrained K is the shaft's alone
    expected = np.asarray(rm.reduction.reduce(BETA * np.asarray(rm.full.K)))
    nr = expected.shape[0]
    dC = l1.C_structure - l0.C_structure
    np.testing.assert_allclose(dC[:nr, :nr], expected, rtol=1e-10,
                               atol=1e-12 * np.abs(expected).max())
    assert not np.any(dC[nr:]) and not np.any(dC[:, nr:])
    # the equilibrium does not see C (to its warm start's round-off: 2e-14 seen in the
    # suite); the eigenvalues do: the bending modes above 1 kHz much more damped
    np.testing.assert_allclose(l1.equilibrium.r, l0.equilibrium.r, rtol=1e-10)
    e0 = rd.stability(s0, 80.0).eigenvalues
    e1 = rd.stability(s1, 80.0).eigenvalues
    hi0, hi1 = e0[e0.imag > 2 * np.pi * 1e3], e1[e1.imag > 2 * np.pi * 1e3]
    assert hi0.size == hi1.size > 0
    assert np.all(hi1.real < 2 * hi0.real)


def test_transient_steady_state_is_the_unbalance_response_with_damping():
    """The transient right-hand side and Jacobian carry C: on linear supports the settled
    unbalance orbit equals the harmonic solution (K − Ω²M + iΩ(C + ΩG)) X = F, C including
    β K, at 160 Hz near the first bending critical (~170 Hz) where β = 2e-4 s lowers the
    amplitude by a third. The orbit's harmonic amplitudes are fitted by least squares over the
    last 10 of 40 revolutions."""
    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    s = dataclasses.replace(s, rotor=dataclasses.replace(s.rotor, damping_beta_s=2e-4),
                            gravity_m_s2=0.0)
    und = dataclasses.replace(s, rotor=dataclasses.replace(s.rotor, damping_beta_s=0.0))
    ub, f = [(3, 1e-3, 0.0)], 160.0
    u1 = rd.unbalance_response(s, ub, [f], stations=[3], refine=False)
    u0 = rd.unbalance_response(und, ub, [f], stations=[3], refine=False)
    X = np.array([u1.x[0, 0], u1.y[0, 0]])
    assert abs(u1.major_m[0, 0] / u0.major_m[0, 0] - 1) > 0.3  # β matters at this speed
    tr = rd.transient(s, 40 / f, f, unbalances=ub, n_out=4001)
    assert tr.status == "ok"
    late = tr.t > 30 / f
    w = 2 * np.pi * f * tr.t[late]
    A = np.column_stack([np.cos(w), np.sin(w)])
    i3 = 2 * list(s.reduction.master_stations).index(3)  # station 3's x, y in r
    fit = np.linalg.lstsq(A, tr.r[late][:, i3:i3 + 2], rcond=None)[0]  # (cos, sin) × (x, y)
    Xt = fit[0] - 1j * fit[1]  # x = Re(X e^{iΩt})
    np.testing.assert_allclose(np.abs(Xt), np.abs(X), rtol=2e-3)


@pytest.mark.parametrize("field,value", [("damping_alpha_1_per_s", -1.0),
                                         ("damping_beta_s", float("nan")),
                                         ("damping_beta_s", float("inf")),
                                         ("damping_alpha_1_per_s", "a")])
def test_bad_damping_names_the_field(field, value):
    s = _compressor()
    with pytest.raises(rd.InputError, match=rf"rotor\.{field}"):
        dataclasses.replace(s.rotor, **{field: value})
    with pytest.raises(rd.InputError, match=rf"rotor\.section\[0\]\.{field}"):
        rd.Rotor((rd.ShaftSection(0.5, 0.05, **{field: value}),))
    text = s.to_toml().replace("[rotor]\n", f"[rotor]\n{field} = {_toml(value)}\n", 1)
    with pytest.raises(rd.InputError, match=rf"rotor\.{field}"):
        rd.System.from_toml(text, is_text=True)
    e = _core.ShaftElement()
    e.length, e.outer_diameter, e.density, e.young, e.shear_modulus = 0.1, 0.05, 7850, 2e11, 8e10
    m = _core.RotorModel()
    if isinstance(value, float):
        setattr(e, "damping_alpha" if "alpha" in field else "damping_beta", value)
        m.elements = [e]
        with pytest.raises(rd.InputError, match=r"elements\[0\]\.damping_"):
            m.validate()


def _toml(value) -> str:
    if isinstance(value, str):
        return f'"{value}"'
    return {math.inf: "inf"}.get(value, "nan" if value != value else repr(value))


def test_toml_round_trip_and_zero_writes_nothing():
    s = _compressor(ALPHA, BETA)
    secs = s.rotor.sections
    s = dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, sections=(dataclasses.replace(secs[0], damping_beta_s=1e-4),) + secs[1:]))
    text = s.to_toml()
    assert f"damping_alpha_1_per_s = {ALPHA!r}" in text and "damping_beta_s = 0.0001" in text
    back = rd.System.from_toml(text, is_text=True)
    assert back == s
    np.testing.assert_array_equal(back.C().toarray(), s.C().toarray())
    assert "damping" not in _compressor().to_toml()  # undamped files stay as they were
    with pytest.raises(rd.InputError, match=r"rotor\.damping_gamma: unknown key"):
        rd.System.from_toml(text.replace("damping_alpha_1_per_s", "damping_gamma"), is_text=True)


def test_beta_from_loss_factor():
    beta = rd.Rotor.beta_from_loss_factor(0.004, 150.0)
    assert beta == pytest.approx(0.004 / (2 * math.pi * 150.0), rel=1e-15)
    # the viscous β matches the hysteretic ζ = η/2 at the reference frequency only
    assert beta * (2 * math.pi * 150.0) / 2 == pytest.approx(0.002, rel=1e-14)
    with pytest.raises(rd.InputError, match="reference_hz"):
        rd.Rotor.beta_from_loss_factor(0.004, 0.0)
    with pytest.raises(rd.InputError, match="loss_factor"):
        rd.Rotor.beta_from_loss_factor(-0.1, 10.0)


@pytest.mark.ross
def test_modes_equal_ross_with_shaft_damping():
    """ROSS's run_modal on a shaft with alpha, beta against rotordyn's modes of the imported
    rotor (its lateral eigenvalues: ROSS's elements also carry axial and torsional DOFs)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rs = pytest.importorskip("ross")
        steel = rs.Material(name="Steel_damping", rho=7810, E=211e9, G_s=81.2e9)
        shaft = [rs.ShaftElement(0.25, 0.0, 0.05, material=steel, shear_effects=True,
                                 rotary_inertia=True, gyroscopic=True, alpha=ALPHA, beta=BETA)
                 for _ in range(6)]
        disk = rs.DiskElement.from_geometry(n=3, material=steel, width=0.07, i_d=0.05,
                                            o_d=0.28)
        brg = [rs.BearingElement(n, kxx=1e7, kyy=1e7, cxx=0.0, cyy=0.0) for n in (0, 6)]
        rotor = rs.Rotor(shaft, [disk], brg)
        ev = np.asarray(rotor.run_modal(0.0, num_modes=24).evalues)
    from rotordyn.model import system_from_ross

    s = system_from_ross(rotor)
    assert s.rotor.sections[0].damping_beta_s == BETA
    ours = rd.modes(s, 0.0, n_modes=6).eigenvalues
    ross = ev[ev.imag > 0]
    for lam in ours:
        assert np.min(np.abs(ross - lam)) <= 1e-6 * abs(lam)


# -- rotating (internal) damping ---------------------------------------------------------------
def _jeffcott(c_e, beta, rotating=True):
    """A Jeffcott-like rotor: Ø 20 mm steel shaft, 0.6 m between rigid supports, a 9.9 kg
    disk at mid-span (station 1) where a linear support adds the external damping c_e only;
    Guyan-reduced to the disk's x, y (its rotations vanish there by symmetry)."""
    steel = rd.Material("steel", 7850.0, 2.1e11, 0.3)
    secs = tuple(rd.ShaftSection(0.3, 0.02, n_elements=4) for _ in range(2))
    disk = rd.Disk.from_geometry(1, steel, width_m=0.04, outer_diameter_m=0.2,
                                 inner_diameter_m=0.02)
    rotor = rd.Rotor(secs, (disk,), damping_beta_s=beta, damping_rotating=rotating)
    sup = (rd.Support(0), rd.Support(2),
           rd.Support(1, "linear", cxx_n_s_per_m=c_e, cyy_n_s_per_m=c_e))
    return rd.System(rotor=rotor, materials=(steel,), supports=sup,
                     reduction=rd.Reduction(master_stations=(1,), method="guyan"))


def test_circulatory_matrix_is_skew_and_turns_with_the_shaft():
    s = _jeffcott(20.0, 1e-4)
    rm = rotor_matrices(s, "none")
    kc = rm.circulatory()
    np.testing.assert_allclose(kc, -kc.T, atol=1e-12 * np.abs(kc).max())
    J = turn_matrix(4 * (s.rotor.n_elements + 1)).toarray()
    Kb = 1e-4 * (dataclasses.replace(s, supports=(), rotor=dataclasses.replace(
        s.rotor, disks=())).K().toarray())
    np.testing.assert_allclose(Kb @ J, J @ Kb, atol=1e-12 * np.abs(Kb).max())  # isotropic
    assert rotor_matrices(_jeffcott(20.0, 1e-4, rotating=False), "none").circulatory() is None


def test_jeffcott_internal_damping_threshold():
    """Rigid-support Jeffcott rotor with external damping c_e and internal (rotating) damping
    c_i: stable below Ω_th = ω_n (1 + c_e/c_i), the forward mode unstable above (Friswell
    et al. 2010, Dynamics of Rotating Machines, on rotating damping; Genta 2005, Dynamics of
    Rotating Systems). In complex form m z̈ + (c_e + c_i) ż + (k − iΩc_i) z = 0; at the
    threshold λ = iω, whose imaginary part gives ω = Ω c_i/(c_e + c_i) and real part
    k = m ω². Here ω_n = √(k/m) and c_i = β k of the reduced
    model (its C is c_e + βk exactly). The shaft's own gyroscopic coupling g (reduced
    G = [[0, g], [−g, 0]], Ø 20 mm shaft beside a 9.9 kg disk) adds −iΩg ż: the same two
    conditions then give Ω_th = √(k/(mρ² − gρ)), ρ = c_i/(c_e + c_i), 7e-5 above the classic
    value; found to 1e-8 of that form, and to 1e-4 of the classic one."""
    from scipy.optimize import brentq

    c_e, beta = 20.0, 1.0e-4
    s = _jeffcott(c_e, beta)
    M, K, C, G = rotor_matrices(s).matrices()
    m, k = M[0, 0], K[0, 0]
    assert M[1, 1] == pytest.approx(m, rel=1e-12) and K[1, 1] == pytest.approx(k, rel=1e-12)
    c_i = beta * k
    np.testing.assert_allclose(C, (c_e + c_i) * np.eye(2), rtol=1e-12)
    wn = math.sqrt(k / m)
    omega_th = wn * (1 + c_e / c_i)

    def growth(f_hz, whirl="forward"):
        r = rd.modes(s, f_hz, reduction="guyan")
        return r.eigenvalues.real[r.whirl == whirl].max()

    f_th = brentq(growth, 1.05 * wn / (2 * math.pi), 2.0 * omega_th / (2 * math.pi),
                  xtol=1e-10)
    assert 2 * math.pi * f_th == pytest.approx(omega_th, rel=1e-4)
    g, rho = G[0, 1], c_i / (c_e + c_i)
    assert G[1, 0] == -g and 0 < g < 1e-3 * m
    assert 2 * math.pi * f_th == pytest.approx(math.sqrt(k / (m * rho**2 - g * rho)), rel=1e-8)
    above = rd.modes(s, 1.2 * f_th, reduction="guyan")
    assert above.eigenvalues.real[above.whirl == "forward"].max() > 0
    assert above.eigenvalues.real[above.whirl == "backward"].max() < 0
    # stationary β damping (the same C) never destabilises
    still = rd.modes(_jeffcott(c_e, beta, rotating=False), 3 * f_th, reduction="guyan")
    assert still.eigenvalues.real.max() < 0
    # the rotor Campbell diagram crosses at the same speed
    camp = rd.rotor_campbell(s, [0.9 * f_th, 1.1 * f_th], reduction="guyan")
    ev = camp.eigenvalues
    assert ev[0].real.max() < 0 < ev[1].real.max()


def _jeffcott_constants(c_e, beta):
    """m, k, c_i = βk, the shaft's gyroscopic g and Ω_th of :func:`_jeffcott` (the closed form
    of test_jeffcott_internal_damping_threshold, with g kept)."""
    M, K, C, G = rotor_matrices(_jeffcott(c_e, beta)).matrices()
    m, k, g = M[0, 0], K[0, 0], G[0, 1]
    c_i = beta * k
    rho = c_i / (c_e + c_i)
    return m, k, c_i, math.sqrt(k / (m * rho**2 - g * rho))


def test_jeffcott_system_analyses_carry_rotating_damping():
    """The system analyses of the Jeffcott rotor on its linear (damper) support: stability
    equals the rotor-alone modes at zero film (no bearing elements) below and above the
    threshold, the speed threshold and the Campbell diagram cross at the closed-form
    Ω_th, and the static equilibrium under gravity moves sideways by the circulatory force:
    K r + Ω K_c r = Q with K = k I, K_c = c_i [[0, 1], [−1, 0]] (the reduced form; −Ω K_c r
    = Ω c_i J r, i.e. +iΩc_i z in complex notation) gives
    y = y₀ k²/(k² + Ω²c_i²), x = −y₀ k Ω c_i/(k² + Ω²c_i²) (y₀ = −mg/k at rest): the shaft
    deflects towards +x, the way the bottom of the spinning shaft moves."""
    c_e, beta = 20.0, 1.0e-4
    s = _jeffcott(c_e, beta)
    m, k, c_i, w_th = _jeffcott_constants(c_e, beta)
    f_th = w_th / (2 * math.pi)
    from rotordyn.analysis.assembly import assembled

    np.testing.assert_allclose(np.asarray(assembled(s).model.Kc),
                               c_i * np.array([[0.0, 1.0], [-1.0, 0.0]]), rtol=1e-10,
                               atol=1e-12 * c_i)
    for f in (0.8 * f_th, 1.2 * f_th):
        sys_lam = np.sort_complex(rd.stability(s, f).eigenvalues)
        rot_lam = np.sort_complex(rd.modes(s, f, reduction="guyan").eigenvalues)
        rot_lam = np.sort_complex(np.concatenate([rot_lam, rot_lam.conj()]))
        sys_lam = np.sort_complex(np.concatenate([sys_lam, sys_lam.conj()]))
        np.testing.assert_allclose(sys_lam, rot_lam, rtol=1e-10)
    th = rd.threshold(s, "speed_hz", bounds=(0.5 * f_th, 1.5 * f_th), xtol=1e-9 * f_th)
    assert th.status == "ok" and th.stable_side == "below"
    assert th.value == pytest.approx(f_th, rel=1e-7)
    camp = rd.campbell(s, [0.95 * f_th, 1.05 * f_th])
    ev = np.asarray(camp.eigenvalues)
    assert ev[0].real.max() < 0 < ev[1].real.max()
    # the sideways static shift (gravity along −y)
    y0 = rd.equilibrium(s, 0.0).r[1]
    assert y0 < 0
    for f in (0.5 * f_th, 2.0 * f_th):
        w = 2 * math.pi * f
        e = rd.equilibrium(s, f)
        d = k * k + (w * c_i) ** 2
        assert e.status == "ok"
        np.testing.assert_allclose(e.r, [-y0 * k * w * c_i / d, y0 * k * k / d],
                                   rtol=1e-10, atol=1e-12 * abs(y0))
    # stationary β damping: no sideways shift, no threshold
    e_still = rd.equilibrium(_jeffcott(c_e, beta, rotating=False), 2.0 * f_th)
    assert abs(e_still.r[0]) <= 1e-12 * abs(y0)


def test_jeffcott_transient_and_orbits_follow_the_linear_model():
    """Above the threshold the nonlinear integrator (CVODE: right-hand side −Ω K_c r, its
    Jacobian Ω K_c) started at the equilibrium plus ε Re(φ), ε Re(λφ) of the unstable
    forward mode follows ε Re(φ e^{λt}) (the system is linear without films), so its growth
    rate is Re λ; below it the unbalance-forced periodic orbit (shooting, monodromy by
    sensitivities, and harmonic balance) is the equilibrium plus the unbalance response, and
    its Floquet multipliers are e^{λT} of the linear model."""
    c_e, beta = 20.0, 1.0e-4
    s = _jeffcott(c_e, beta)
    f_th = _jeffcott_constants(c_e, beta)[3] / (2 * math.pi)
    f = 1.3 * f_th
    lm = rd.linearize(s, f)
    lam, vec = np.linalg.eig(lm.state_matrix())
    i = int(np.argmax(lam.real))
    assert lam[i].real > 0
    eps = 1e-6 / np.abs(vec[:2, i]).max()
    e = lm.equilibrium
    T = min(3.0 / lam[i].real, 40.0 / f)  # three e-foldings or 40 revolutions
    tr = rd.transient(s, T, f, r0=e.r + eps * vec[:2, i].real, v0=eps * vec[2:, i].real,
                      n_out=201, rtol=1e-9, atol_m=1e-16)
    assert tr.status == "ok"
    lin = eps * (vec[:2, i][None, :] * np.exp(lam[i] * tr.t)[:, None]).real
    amp = np.abs(lin).max()
    assert np.abs(tr.r - e.r - lin).max() <= 1e-5 * amp
    rad = np.hypot(*(tr.r - e.r).T)
    growth = np.polyfit(tr.t[100:], np.log(rad[100:]), 1)[0]
    assert growth == pytest.approx(lam[i].real, rel=1e-3)
    # below the threshold: the forced orbit and its multipliers
    f = 0.8 * f_th
    ub = [(1, 1e-4, 0.0)]
    orb = rd.periodic_orbit(s, f, kind="forced", unbalances=ub, n_out=65)
    assert orb.status == "ok"
    u = rd.unbalance_response(s, ub, [f], stations=[1])
    e = rd.equilibrium(s, f)
    w = 2 * math.pi * f
    ph = np.exp(1j * w * (orb.t - orb.t[0]))
    amp = abs(u.x[0, 0])
    np.testing.assert_allclose(orb.r[:, 0] - e.r[0], (u.x[0, 0] * ph).real, atol=1e-5 * amp)
    np.testing.assert_allclose(orb.r[:, 1] - e.r[1], (u.y[0, 0] * ph).real, atol=1e-5 * amp)
    lam_b = np.linalg.eigvals(rd.linearize(s, f).state_matrix())
    mu = np.sort_complex(np.exp(lam_b * orb.period_s))
    np.testing.assert_allclose(np.sort_complex(np.asarray(orb.multipliers)), mu, atol=1e-6)
    # harmonic balance (K_H of the solver at the samples): the same orbit and multipliers
    hb = rd.periodic_orbit(s, f, kind="forced", unbalances=ub, n_out=65,
                           method="harmonic_balance", harmonics=2)
    assert hb.status == "ok"
    ph = np.exp(1j * w * (hb.t - hb.t[0]))
    np.testing.assert_allclose(hb.r[:, 0] - e.r[0], (u.x[0, 0] * ph).real, atol=1e-9 * amp)
    np.testing.assert_allclose(np.sort_complex(np.asarray(hb.multipliers)), mu, atol=1e-9)


def test_rotating_damping_on_the_compressor():
    """Non-rig models. compressor_linear (Guyan, two anisotropic linear supports): stability
    equals the rotor-alone modes at every speed (no film), the unbalance response is the
    direct solve of (K + ΩK_c − Ω²M + iΩ(C + ΩG)) X = Ω² F₁, and the same β rotating damps
    the forward modes less and the backward ones more than stationary. compressor_plain (two plain journal
    bearings): the equilibrium satisfies K r + ΩK_c r = H_films + Q with film_force_n the
    films' own force, the shaft's sag turns sideways by the closed form below, K by differences
    equals the perturbation one, and the Campbell diagram equals the point stability."""
    from coarse_models import compressor_plain
    from rotordyn.analysis.assembly import assembled

    def rot(s, rotating=True, beta=4e-5):
        return dataclasses.replace(s, rotor=dataclasses.replace(
            s.rotor, damping_beta_s=beta, damping_rotating=rotating))

    lin = rd.System.from_toml(MODELS / "compressor_linear.toml")
    s = rot(lin)
    f = 150.0
    st = rd.stability(s, f)
    a = np.sort_complex(st.eigenvalues)
    b = rd.modes(s, f, reduction="guyan", n_modes=a.size).eigenvalues
    b = np.sort_complex(b)
    np.testing.assert_allclose(a, b, rtol=1e-9)
    # the same β rotating damps forward whirl less and backward whirl more than stationary
    still = rd.stability(rot(lin, False), f)

    def least(r, whirl):
        return r.eigenvalues.real[r.whirl == whirl].max()

    assert least(st, "forward") > least(still, "forward") + 10.0
    assert least(st, "backward") < least(still, "backward") - 0.5
    asm = assembled(s)
    ub = [(3, 1e-3, 0.0)]
    u = rd.unbalance_response(s, ub, [f], stations=[3])
    m = asm.model
    w = 2 * math.pi * f
    Z = (np.asarray(m.K) + w * np.asarray(m.Kc) - w * w * np.asarray(m.M)
         + 1j * w * (np.asarray(m.C) + w * np.asarray(m.G)))
    X = np.linalg.solve(Z, w * w * asm.unbalance_load(ub))
    O = asm.station_output_matrix(3)
    np.testing.assert_allclose([u.x[0, 0], u.y[0, 0]], O @ X, rtol=1e-9)

    plain = compressor_plain()
    s = rot(plain)
    f = 100.0
    w = 2 * math.pi * f
    e = rd.equilibrium(s, f)
    assert e.status == "ok"
    asm = assembled(s)
    m = asm.model
    res = (np.asarray(m.K) + w * np.asarray(m.Kc)) @ e.r - e.film_force_n - np.asarray(m.Q)
    assert np.abs(res).max() <= 1e-8 * np.abs(np.asarray(m.Q)).max()
    # The circulatory forces have no resultant (K_β holds the rigid-body motions), so the two
    # bearings of this symmetric rotor carry the same loads and the journals stay put; with one
    # β on an isotropic shaft K_c = −β K J, and the elastic sag d₀ relative to the journals
    # turns and shrinks to d = d₀/(1 − iΩβ) (complex z = x + iy): sideways by Ωβ = 2.5 %.
    e_still = rd.equilibrium(rot(plain, False), f)
    np.testing.assert_allclose(e.journal_x_m, e_still.journal_x_m, rtol=1e-10)
    np.testing.assert_allclose(e.journal_y_m, e_still.journal_y_m, rtol=1e-10)
    z0 = e_still.r[0::2] + 1j * e_still.r[1::2]
    z1 = e.r[0::2] + 1j * e.r[1::2]
    d0 = z0 - z0[0]
    np.testing.assert_allclose(z1 - z1[0], d0 / (1 - 1j * w * 4e-5), rtol=0,
                               atol=1e-10 * np.abs(d0).max())
    assert np.abs((z1 - z1[0]).real).max() > 0.02 * np.abs(d0).max()
    lp = rd.linearize(s, f)
    lf = rd.linearize(s, f, method="finite_difference")
    np.testing.assert_allclose(lp.K_structure, np.asarray(m.K) + w * np.asarray(m.Kc))
    np.testing.assert_allclose(lf.K, lp.K, atol=1e-5 * np.abs(lp.K).max())
    st = rd.stability(s, f)
    camp = rd.campbell(s, [90.0, f])
    row = np.asarray(camp.eigenvalues)[1]
    for lam in st.eigenvalues:  # the Campbell row also lists the overdamped real roots
        assert np.nanmin(np.abs(row - lam)) <= 1e-6 * abs(lam)


def test_rotating_damping_toml_and_bad_flag():
    from coarse_models import compressor_plain

    s = compressor_plain()
    s = dataclasses.replace(s, rotor=dataclasses.replace(s.rotor, damping_beta_s=1e-5,
                                                         damping_rotating=True))
    # static and housing offsets carry it (tests/test_rotating_damping_offsets.py)
    back = rd.System.from_toml(s.to_toml(), is_text=True)
    assert back == s and "damping_rotating = true" in s.to_toml()
    with pytest.raises(rd.InputError, match=r"rotor\.damping_rotating"):
        dataclasses.replace(s.rotor, damping_rotating="yes")

def test_a_stability_sweep_carries_rotating_damping(tmp_path):
    """The sweep's per-point work (its own equilibria and eigen-analysis in the core) over
    speed through the Jeffcott threshold: max Re λ per speed equals rotordyn.stability's, and
    it is zero at the closed-form Ω_th (the middle point)."""
    import pandas as pd
    from rotordyn.sweep.runner import run_sweep

    s = _jeffcott(20.0, 1.0e-4)
    f_th = _jeffcott_constants(20.0, 1.0e-4)[3] / (2 * math.pi)
    (tmp_path / "j.toml").write_text(s.to_toml())
    (tmp_path / "spec.toml").write_text(
        'schema = "rotordyn/sweep/1"\nname = "jeffcott"\nmodel = "j.toml"\n'
        'analysis = "stability"\nchunk_size = 5\n[grid]\n'
        f"speed_hz = {{start = {0.8 * f_th!r}, stop = {1.2 * f_th!r}, num = 5}}\n")
    run_sweep(tmp_path / "spec.toml", tmp_path / "out", threads=1, progress=False)
    df = pd.read_parquet(tmp_path / "out").groupby("speed_hz")["max_real_1_per_s"].max()
    ref = [rd.stability(s, f).eigenvalues.real.max() for f in df.index]
    np.testing.assert_allclose(df.to_numpy(), ref, rtol=1e-9, atol=1e-9)
    assert abs(df.iloc[2]) < 1e-6 * abs(df.iloc[0]) and df.iloc[0] < 0 < df.iloc[4]
