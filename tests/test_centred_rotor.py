"""A stiff rotor on two plain journal bearings without gravity sits at the bearing centres
(ε = 0), where the Swift–Stieber cavitation set is degenerate. Issue 11 saw the perturbation
method give max Re λ = +1.18 1/s against +2.33 1/s from finite differences there (the
perturbation K/C were the full-film values). The linearisation at a degenerate set is now the
central-difference limit (docs/journal-bearing.md), so both methods give the same eigenvalues:
to the finite differences' truncation (steps 1e-6 c, first order at the kink: measured
1.3e-5 relative on max Re λ), tolerance 1e-4 relative."""

import numpy as np

import rotordyn as rd


def test_centred_rotor_perturbation_equals_finite_differences():
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.1, outer_diameter_m=0.1) for _ in range(4))
    films = tuple(rd.FluidFilmBearing(s, diameter_m=0.05, length_m=0.025, clearance_m=1e-4,
                                      viscosity_pa_s=0.03) for s in (0, 4))
    system = rd.System(rotor=rd.Rotor(shaft, ()), materials=(steel,), bearings=films,
                       gravity_m_s2=0.0,
                       reduction=rd.Reduction(master_stations=(0, 4), method="guyan"))
    p = rd.stability(system, 40.0, method="perturbation")
    f = rd.stability(system, 40.0, method="finite_difference")
    assert p.status == f.status == "ok"
    assert np.abs(p.linear.equilibrium.r).max() < 1e-12  # centred: ε = 0
    assert p.max_real_1_per_s > 0  # above its threshold: the half-frequency whirl
    np.testing.assert_allclose(p.max_real_1_per_s, f.max_real_1_per_s, rtol=1e-4)
    np.testing.assert_allclose(np.sort_complex(p.eigenvalues), np.sort_complex(f.eigenvalues),
                               rtol=1e-4)
