"""The THD film's energy balance against its reported power loss (issue 20; docs/film-physics.md
"Heat of the inlet cells"): every watt of ``power_loss_w`` (Σ Φ over the film's cells; the
friction torque · ω on an ungrooved full film) goes into the oil or the walls. An ungrooved
film's inlet column (at its peak) holds the inlet temperature; its dissipation and its wall
exchange at T_in heat the oil passing it, a source in the inlet mixing. A supply groove's
nodes are not film (deep, their shear small): in neither the power loss nor the balance.

Balance, relative to the supply temperature T_s, from the reported numbers: the side leakage
ρc Q_s (T_side − T_s), the flow reaching the inlet that is not carried over
ρc (1 − λ) Q_r (T_r − T_s), and the heat to journal and bush. It holds to round-off (1e-9) on
mass-conserving films (full film, Elrod–Adams); before the inlet source the ungrooved full film
lost its inlet column's share (0.977, 0.989 at 36 × 8, 72 × 16) and the grooved Elrod–Adams
film's power held its groove's shear (0.935 at 72 × 16).

Closed form: Çengel & Ghajar, Heat and Mass Transfer, 5th ed., Problem 6-54 — a 6 cm shaft at
3000 rpm in a 20 cm long bearing, uniform clearance 0.2 mm, walls at 50 °C, μ = 0.05 Pa·s,
k = 0.17 W/(m K): the Couette film with a viscous heat source (Bird, Stewart & Lightfoot,
Transport Phenomena, §10.4): the cross-film parabola's mean exceeds the walls by μU²/(12k), the
power is μU²/c · πDL. The THD film (concentric, full film, the walls' film-side coefficient
from the film's own conduction, both walls fixed at 50 °C, a viscosity that does not vary)
carries its heat to the walls; with carry-over λ the oil's through-flow leaves (1 − λ) of it
unheated, so the mean rise tends to μU²/(12k) as λ → 1 (measured −0.853 (1 − λ) at 36, 72, 144
cells around; before the inlet source the walls took 0.971, 0.985, 0.992 of the power there).
"""

import math

import numpy as np
import pytest

from rotordyn.bearings import Groove, JournalBearing, Oil

VG32 = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0, nu2_mm2_s=5.4,
           density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
GEO = dict(diameter_m=0.1, length_m=0.05, clearance_m=1e-4)
RC = 870.0 * 2000.0
TS = 45.0


def heat_out(r, lam, ts, rc):
    """Convected (side leakage, the part of Q_r not carried over) + walls, W, relative to T_s."""
    conv = rc * (r.side_flow_m3_s * (r.side_temperature_c - ts)
                 + (1.0 - lam) * r.recirculation_flow_m3_s * (r.recirculation_temperature_c - ts))
    return conv + r.heat_to_journal_w + r.heat_to_bush_w


@pytest.mark.parametrize("cav, grooves", [("none", []),
                                          ("jfo", [Groove(center_deg=90.0, width_deg=20.0)])])
def test_heat_out_equals_the_power_loss(cav, grooves):
    b = JournalBearing(viscosity_pa_s=VG32.viscosity_pa_s(TS), n_circ=36, n_axial=8,
                       cavitation=cav, grooves=grooves, **GEO)
    run = dict(load_n=(0.0, -5000.0), speed_hz=100.0, oil=VG32, supply_temperature_c=TS,
               model="thd", carry_over=0.5)
    cases = [dict(), dict(journal_htc_w_m2k=2000.0, bush_htc_w_m2k=1000.0),
             dict(wall_htc="film", journal_wall="balance", bush_wall="conduction",
                  bush_thickness_m=0.01, bush_conductivity_w_per_m_k=50.0,
                  back_htc_w_m2k=500.0)]
    for kw in cases:
        r = b.thermal_equilibrium(**run, **kw)
        assert r.status == "ok"
        assert heat_out(r, 0.5, TS, RC) == pytest.approx(r.power_loss_w, rel=1e-9), kw
        if kw.get("journal_wall") == "balance":
            assert abs(r.heat_to_journal_w) < 1e-9 * r.power_loss_w
    if cav == "none":  # a full film: Σ Φ is the friction power (pᵀA p = pᵀb)
        assert r.power_loss_w == pytest.approx(r.friction_power_w, rel=1e-12)


def test_cengel_problem_6_54_couette_film_with_viscous_heating():
    D, L, c, rpm = 0.06, 0.20, 0.2e-3, 3000.0
    mu, k, tw = 0.05, 0.17, 50.0
    rc = 870.0 * 2000.0
    oil = Oil(viscosity_law="exponential", mu_ref_pa_s=mu, t_ref_c=tw, beta_1_per_k=1e-9,
              density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0, conductivity_w_per_m_k=k)
    n = rpm / 60.0
    U = math.pi * D * n
    rise = mu * U**2 / (12.0 * k)                 # BSL §10.4: mean of the cross-film parabola
    power = mu * U**2 / c * math.pi * D * L       # Petroff
    err = {}
    for lam in (0.99, 0.999):
        b = JournalBearing(diameter_m=D, length_m=L, clearance_m=c, viscosity_pa_s=mu,
                           n_circ=36, n_axial=8, cavitation="none")
        r = b.thermal_equilibrium(load_n=(0.0, -1e-3), speed_hz=n, oil=oil,
                                  supply_temperature_c=tw, carry_over=lam, model="thd",
                                  wall_htc="film", journal_wall="fixed",
                                  journal_temperature_c=tw, bush_wall="fixed",
                                  bush_temperature_c=tw)
        assert r.status == "ok"
        assert r.power_loss_w == pytest.approx(power, rel=1e-6)   # concentric: Petroff
        assert heat_out(r, lam, tw, rc) == pytest.approx(r.power_loss_w, rel=1e-9)
        err[lam] = (r.mean_temperature_c - tw) / rise - 1.0
        assert abs(err[lam]) < (1.0 - lam), (lam, err[lam])
    # → the closed form as λ → 1, at first order in 1 − λ (observed err ≈ −0.85 (1 − λ) on
    # every grid: ratio 0.1004 for a tenfold smaller 1 − λ)
    assert 0.09 < err[0.999] / err[0.99] < 0.11, err
