"""ROSS 2.3's thermal ``PlainJournal`` and this package's THD plain film on equal inputs (issue 20;
docs/film-physics.md, "Side by side with ROSS 2.3: the plain journal bearing"). The case, both
sides and the comparison, shared by ``benchmarks/bench_thd_plain.py`` and
``tests/test_film_thd_ross.py`` (which loads this file by its path). Not a test itself.

The case: a two-axial-groove bearing, D = 0.1 m, L = 0.05 m, c = 0.1 mm, two pads of 150°
centred at 90° and 270° (ROSS's ``n_pad=2``, ``pad_arc_length=150``; ours: two 30° grooves at 0°
and 180° held at 0 Pa), 20 Hz, 2 kN downwards, ROSS's ISO VG 68 supplied at 40 °C, flooded,
every pad fed with fresh oil only (ROSS ``groove_factor = 1``; ours ``carry_over = 0``).

Equal physics where both models allow it:

* viscosity: ROSS fits μ = a T^b (T in °C) through its lubricant's two points; ours is the same
  power law (``viscosity_law = "power"`` through two points of ROSS's fit, :func:`ours`; equal
  to round-off, printed);
* density, specific heat: ROSS's lubricant's; adiabatic walls on both sides;
* cavitation: ROSS clips the full-film pressure (p < 0 → 0) = ours ``cavitation="gumbel"``;
* laminar: ROSS switches its eddy-viscosity model on where its Reynolds number
  ρ ω R c h̄ /(L μ) exceeds 500; the case keeps it below (``re_max``, checked);
* grid: ROSS's volumes per pad (``n_circ``·150/360 around, ``n_axial`` along) against our nodes
  (``n_circ`` intervals around, ``n_axial`` along): the same spacing.

What still differs (the comparison measures it): ROSS keeps heat conduction in the film plane
(ours neglects it), convects axially by central differences (ours upwind), takes full-film
Couette flow and dissipation in the cavitated zone (ours the streamers: the same temperature
along them), stops its temperature iteration at a 1 % relative change and its Nelder–Mead
equilibrium at ``tol=0.8``; its K, C are force differences with the temperature re-solved at
every perturbed position and velocity (ours: the field frozen). Both sides solve the
equilibrium from the load.
"""

from __future__ import annotations

import contextlib
import io
import math
import warnings

import numpy as np

D_M, L_M, C_M = 0.1, 0.05, 1e-4
PAD_ARC_DEG = 150.0
GROOVE_DEG = 180.0 - PAD_ARC_DEG
SPEED_HZ = 20.0
LOAD_N = (0.0, -2000.0)
LUBRICANT = "ISOVG68"
SUPPLY_C = 40.0


def ross_bearing(ross, n_circ: int, n_axial: int):
    """ROSS's PlainJournal of the case; ``n_circ`` our intervals around (ROSS: n_circ·150/360
    volumes per pad), ``n_axial`` volumes along. Builds (and so solves) the whole bearing:
    equilibrium from the load, then K, C by its perturbation method."""
    n_pad_vol = n_circ * PAD_ARC_DEG / 360.0
    if abs(n_pad_vol - round(n_pad_vol)) > 1e-9 or (n_circ * GROOVE_DEG / 360.0) % 1 > 1e-9:
        raise ValueError(f"n_circ = {n_circ}: the 150° pads and 30° grooves need whole intervals")
    Q_ = ross.Q_
    from ross.bearings.plain_journal import PlainJournal

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        return PlainJournal(
            n=0, axial_length=L_M, journal_radius=D_M / 2, radial_clearance=C_M,
            elements_circumferential=int(round(n_pad_vol)), elements_axial=n_axial, n_pad=2,
            pad_arc_length=PAD_ARC_DEG, preload=0.0, geometry="circular",
            reference_temperature=SUPPLY_C, frequency=Q_([SPEED_HZ * 60.0], "RPM"),
            fxs_load=LOAD_N[0], fys_load=LOAD_N[1], groove_factor=[1.0, 1.0],
            lubricant=LUBRICANT, initial_guess=[0.1, -0.1], method="perturbation",
            operating_type="flooded")


def ross_outputs(rb) -> dict:
    """What the comparison needs from a solved ROSS bearing ``rb``: its equilibrium, the
    temperature field at it (re-solved there: after its coefficients ROSS's last field is that
    of a perturbed velocity), its reported K, C, the stiffness from its own force differences
    (the same eight ``_forces`` calls as its perturbation method: −ΔF/Δq, −ΔF/Δq̇) and the
    factors by which its reported K, C differ from them (``K_ross_scale``, ``C_ross_scale``),
    its film force (its trapezoid rule and the midpoint rule over its volumes), its viscosity
    law and its largest Reynolds number."""
    from ross.bearings.lubricants import lubricants_dict

    w = 2.0 * math.pi * SPEED_HZ
    eps, att = (float(x) for x in rb.equilibrium_pos)
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        xe, ye = eps * C_M * math.cos(att), eps * C_M * math.sin(att)
        # the perturbations of ROSS's _perturbation_method (dE = 0.001)
        ex, ey = abs(1e-3 * C_M * math.cos(att)), abs(1e-3 * C_M * math.sin(att))
        f1 = np.array(rb._forces(xe + ex, w, ye, 0, 0), dtype=float)
        f2 = np.array(rb._forces(xe - ex, w, ye, 0, 0), dtype=float)
        f3 = np.array(rb._forces(xe, w, ye + ey, 0, 0), dtype=float)
        f4 = np.array(rb._forces(xe, w, ye - ey, 0, 0), dtype=float)
        va = w * D_M / 2  # and its velocity perturbations, 1e-6 of the surface speed
        vx, vy = abs(1e-6 * va * math.sin(att)), abs(1e-6 * va * math.cos(att))
        f5 = np.array(rb._forces(xe, w, ye, vx, 0), dtype=float)
        f6 = np.array(rb._forces(xe, w, ye, -vx, 0), dtype=float)
        f7 = np.array(rb._forces(xe, w, ye, 0, vy), dtype=float)
        f8 = np.array(rb._forces(xe, w, ye, 0, -vy), dtype=float)
        f_eq = np.array(rb._forces([eps, att], w), dtype=float)
        lub = lubricants_dict[LUBRICANT]  # ROSS's own fit of μ = a T^b (its OptimizeWarning)
        a, b = rb._get_interp_coeffs(lub["temperature1"] - 273.15, lub["temperature2"] - 273.15,
                                     lub["liquid_viscosity1"], lub["liquid_viscosity2"])
    t_eq = np.array(rb.Tdim_last, dtype=float)  # (n_axial, n_pad_vol, n_pad), °C
    p_eq = np.array(rb.Pdim_last, dtype=float)
    k_fd = -np.column_stack([(f1 - f2) / (2 * ex), (f3 - f4) / (2 * ey)])
    # ROSS 2.3 scales each entry by |W| over a "Sommerfeld" force built from the components it
    # passes: (F1x, F2y) for kxx, (F3x, F4y) for kxy, but (F1y, F2y) for kyx and (F3y, F4y) for
    # kyy — for a vertical load √2 |F| — so its y row is the force differences / √2
    w_load = math.hypot(*LOAD_N)
    k_scale = w_load / np.array([[math.hypot(f1[0], f2[1]), math.hypot(f3[0], f4[1])],
                                 [math.hypot(f1[1], f2[1]), math.hypot(f3[1], f4[1])]])
    c_fd = -np.column_stack([(f5 - f6) / (2 * vx), (f7 - f8) / (2 * vy)])
    c_scale = w_load / np.array([[math.hypot(f5[0], f6[1]), math.hypot(f7[0], f8[1])],
                                 [math.hypot(f5[0], f6[1]), math.hypot(f7[0], f8[1])]])
    theta = np.array(rb.theta_range, dtype=float)  # (n_pad, n_pad_vol) volume centres, rad
    h = 1.0 - eps * np.cos(theta - att)  # h/c at the centres
    mu = a * t_eq ** b  # (n_axial, n_pad_vol, n_pad)
    re = rb.rho * w * (D_M / 2) * (h.T[None] / L_M) * C_M / mu  # ROSS's Reyn (>500: eddies)
    # its film force by the midpoint rule over its volumes (ROSS integrates by the trapezoid
    # rule over the volume centres of all pads together, across the grooves between them)
    da = (D_M / 2) * (theta[0, 1] - theta[0, 0]) * L_M / t_eq.shape[0]
    f_mid = -da * np.array([np.sum(p_eq * np.cos(theta.T)[None]),
                            np.sum(p_eq * np.sin(theta.T)[None])])
    return dict(
        eps=eps, attitude_deg=math.degrees(att) % 360.0, force_n=f_eq, force_midpoint_n=f_mid,
        temperature_c=t_eq, theta_rad=theta, z=np.array(rb.Z[1:-1], dtype=float),
        K=np.array([[rb.kxx[0], rb.kxy[0]], [rb.kyx[0], rb.kyy[0]]], dtype=float),
        C=np.array([[rb.cxx[0], rb.cxy[0]], [rb.cyx[0], rb.cyy[0]]], dtype=float),
        K_force_differences=k_fd, K_ross_scale=k_scale, C_force_differences=c_fd,
        C_ross_scale=c_scale, mu_a=float(a), mu_b=float(b), density=float(rb.rho),
        specific_heat=float(rb.Cp), conductivity=float(rb.k_t), re_max=float(re.max()))


def ours(ross_out: dict, n_circ: int, n_axial: int):
    """Our bearing and oil for the case: (JournalBearing, Oil, largest relative difference of
    our law from ROSS's power law between the supply and ROSS's T_max: round-off)."""
    import rotordyn
    from rotordyn.bearings import Groove, Oil

    a, b = ross_out["mu_a"], ross_out["mu_b"]
    t_hi = float(ross_out["temperature_c"].max())
    mu_s = a * SUPPLY_C ** b
    # ROSS's own law, exactly: the power law through two of its points (ours is μ1 (T/T1)^b,
    # a T^b to round-off)
    oil = Oil(viscosity_law="power", t1_c=SUPPLY_C, mu1_pa_s=mu_s, t2_c=100.0,
              mu2_pa_s=a * 100.0 ** b, t_min_c=1.0, density_kg_m3=ross_out["density"],
              specific_heat_j_per_kg_k=ross_out["specific_heat"])
    tg = np.linspace(SUPPLY_C, t_hi, 101)
    dev = float(np.max(np.abs(oil.viscosity_pa_s(tg) / (a * tg ** b) - 1.0)))
    jb = rotordyn.JournalBearing(
        diameter_m=D_M, length_m=L_M, clearance_m=C_M, viscosity_pa_s=mu_s, n_circ=n_circ,
        n_axial=n_axial, cavitation="gumbel",
        grooves=[Groove(0.0, GROOVE_DEG), Groove(180.0, GROOVE_DEG)])
    return jb, oil, dev


def thd(jb, oil, load_n=LOAD_N):
    """Our THD equilibrium of the case under ``load_n`` with K, C at the frozen field."""
    return jb.thermal_equilibrium(load_n=load_n, speed_hz=SPEED_HZ, oil=oil,
                                  supply_temperature_c=SUPPLY_C, carry_over=0.0, model="thd")


def field_following_stiffness(jb, oil, rel: float = 0.01) -> np.ndarray:
    """Our static stiffness with the temperature following the journal (ROSS's definition):
    K = (∂q/∂W)⁻¹ from central differences of our THD equilibrium under loads W ± rel·|W| in
    x and y (the film force is −W at each)."""
    w = math.hypot(*LOAD_N) * rel
    J = np.zeros((2, 2))
    for j in range(2):
        q = []
        for s in (1.0, -1.0):
            load = list(LOAD_N)
            load[j] += s * w
            r = thd(jb, oil, load)
            if r.status != "ok":
                raise RuntimeError(f"THD equilibrium at a perturbed load: {r.status}")
            q.append(np.array([r.x_m, r.y_m]))
        J[:, j] = (q[0] - q[1]) / (2 * w)
    return np.linalg.inv(J)


def field_at_ross_centres(res, ross_out: dict) -> np.ndarray:
    """Our node temperatures at ROSS's volume centres, (n_axial, n_pad_vol, n_pad): linear in φ
    between our film nodes of each pad (extrapolated from the two end nodes over the half
    interval next to a groove, whose nodes hold the supply temperature), linear in z."""
    t = np.asarray(res.temperature_c)  # (n_circ, n_axial + 1)
    n_circ, k1 = t.shape
    phi = np.arange(n_circ) * 2 * math.pi / n_circ
    z = np.linspace(0.0, 1.0, k1)
    film = ~np.asarray(res.inlet_mask).any(axis=1)  # columns of film nodes
    zc = ross_out["z"]
    out = np.empty_like(ross_out["temperature_c"])
    for p, th in enumerate(ross_out["theta_rad"]):
        lo, hi = th[0], th[-1]
        cols = [j for j in range(n_circ) if film[j] and lo - 1e-9 <= phi[j] % (2 * math.pi)
                <= hi + 1e-9]
        ph = phi[cols]
        for i, zz in enumerate(zc):
            tz = np.array([np.interp(zz, z, t[j]) for j in cols])
            v = np.interp(th, ph, tz)
            for end, (a, b) in ((th < ph[0], (0, 1)), (th > ph[-1], (-1, -2))):
                v[end] = tz[a] + (tz[a] - tz[b]) * (th[end] - ph[a]) / (ph[a] - ph[b])
            out[i, :, p] = v
    return out


def compare(res, ross_out: dict, k_ff: np.ndarray | None = None) -> dict:
    """Differences of our THD result ``res`` from ROSS's outputs: position; temperatures (the
    field at ROSS's centres: largest |ΔT| overall, per pad and without the end rows; the pads'
    outlet temperatures as ROSS averages them, over the axial centres of the last volume); K
    (field frozen, and ``k_ff`` with the field following) and C against ROSS's force
    differences, as fractions of their largest entry."""
    rise = float(ross_out["temperature_c"].max()) - SUPPLY_C
    tc = field_at_ross_centres(res, ross_out)
    dt = tc - ross_out["temperature_c"]
    att = math.degrees(math.atan2(res.y_m, res.x_m)) % 360.0
    kf, cf = ross_out["K_force_differences"], ross_out["C_force_differences"]
    out = dict(
        d_eps=res.eccentricity_ratio - ross_out["eps"],
        d_attitude_deg=att - ross_out["attitude_deg"],
        attitude_deg=att, rise_k=rise, d_max_temperature_k=res.max_temperature_c - rise - SUPPLY_C,
        d_field_max_k=float(np.abs(dt).max()), d_field_rel=float(np.abs(dt).max()) / rise,
        d_field_pad_max_k=np.abs(dt).max(axis=(0, 1)),
        d_field_inner_max_k=float(np.abs(dt[1:-1]).max()),
        outlet_ross_c=ross_out["temperature_c"][:, -1, :].mean(axis=0),
        outlet_ours_c=tc[:, -1, :].mean(axis=0),
        dK_frozen=(res.K - kf) / np.abs(kf).max(), dC=(res.C - cf) / np.abs(cf).max())
    if k_ff is not None:
        out["dK_following"] = (k_ff - kf) / np.abs(kf).max()
    return out
