"""First Lyapunov coefficient and Hopf type (issue 19): Kuznetsov's projection formula with
finite-difference multilinear forms against closed forms, and rotordyn.hopf on film models
against the continued limit-cycle branches (tests/test_continuation.py's models)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.lyapunov import central_second, central_third, first_lyapunov
import coarse_models  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


def test_l1_of_a_planar_field_equals_guckenheimer_holmes():
    """ẋ = −ωy + f(x, y), ẏ = ωx + g(x, y) with quadratic, cubic and quartic terms: the
    Guckenheimer–Holmes coefficient (Nonlinear Oscillations, Dynamical Systems, and
    Bifurcations of Vector Fields, 1983, eq. 3.4.11) a = ṙ/r³ of the polar normal form;
    with ⟨q, q⟩ = 1, q = (1, −i)/√2, r² = 2|z|² and l1 = 2a/ω. The quartic terms do not
    enter l1 but make the O(h²) difference error visible (h = 1e-2): within 1e-3."""
    w = 1.3
    c = dict(fxx=0.7, fxy=-0.4, fyy=0.9, gxx=-0.3, gxy=0.5, gyy=0.2, fxxx=0.6, fxyy=-1.1,
             gxxy=0.4, gyyy=-0.8)

    def f(X):
        x, y = X
        F = (0.5 * c["fxx"] * x * x + c["fxy"] * x * y + 0.5 * c["fyy"] * y * y
             + c["fxxx"] * x ** 3 / 6 + 0.5 * c["fxyy"] * x * y * y + 0.8 * x ** 4)
        G = (0.5 * c["gxx"] * x * x + c["gxy"] * x * y + 0.5 * c["gyy"] * y * y
             + 0.5 * c["gxxy"] * x * x * y + c["gyyy"] * y ** 3 / 6 - 0.6 * x * y ** 3)
        return np.array([-w * y + F, w * x + G])

    a = ((c["fxxx"] + c["fxyy"] + c["gxxy"] + c["gyyy"]) / 16
         + (c["fxy"] * (c["fxx"] + c["fyy"]) - c["gxy"] * (c["gxx"] + c["gyy"])
            - c["fxx"] * c["gxx"] + c["fyy"] * c["gyy"]) / (16 * w))
    A = np.array([[0.0, -w], [w, 0.0]])
    x0 = np.zeros(2)
    r = first_lyapunov(A, w, central_second(f, x0, f(x0), 1e-2), central_third(f, x0, 1e-2))
    assert r["l1"] == pytest.approx(2 * a / w, rel=1e-3)
    # the quartic terms are seen by a coarse step: the comparison can fail
    r = first_lyapunov(A, w, central_second(f, x0, f(x0), 0.3), central_third(f, x0, 0.3))
    assert abs(r["l1"] / (2 * a / w) - 1) > 1e-3


def jeffcott(m=2.0, k=8.0, c=0.1, c3=0.3, c5=0.5):
    """Jeffcott rotor (x, y, ẋ, ẏ) on a support with damping c, cross-coupled stiffness
    q (k_xy = q = −k_yx) and isotropic cubic (c3) and quintic (c5) damping
    −(c3 |ṙ|² + c5 |ṙ|⁴) ṙ, at its Hopf point q_H = c ω, ω² = k/m."""
    om = np.sqrt(k / m)
    qH = c * om

    def f(X, q=qH):
        x, y, u, v = X
        s = u * u + v * v
        d = c3 * s + c5 * s * s
        return np.array([u, v, (-c * u - k * x - q * y - d * u) / m,
                         (-c * v - k * y + q * x - d * v) / m])
    A = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [-k / m, -qH / m, -c / m, 0],
                  [qH / m, -k / m, 0, -c / m]])
    return f, A, om, qH


def test_l1_of_a_jeffcott_rotor_with_cubic_damping_equals_the_closed_form():
    """The circular forward whirl r = R e^{iωt} solves the Jeffcott rotor exactly:
    ω² = k/m and c ω + c3 ω³ R² + c5 ω⁵ R⁴ = q, so R² = (q − q_H)/(c3 ω³) to leading order.
    With dRe λ/dq = 2mω/(c² + 4m²ω²) (forward root of mλ² + cλ + k − iq = 0) and
    q = (1, −i, iω, ω)/|·| (|q_x|² = 1/(2 + 2ω²)), the normal form's |z|² = R²/(4|q_x|²)
    gives l1 = −4 α' |q_x|² c3 ω² (supercritical). Within 1e-3 (h = 1e-2; the quintic term
    is the difference error); and the predicted slope dR²/dq against 1/(c3 ω³)."""
    m, c, c3 = 2.0, 0.1, 0.3
    f, A, om, qH = jeffcott(m=m, c=c, c3=c3)
    ap = 2 * m * om / (c ** 2 + 4 * m * m * om * om)
    l1_cf = -4 * ap * c3 * om ** 2 / (2 + 2 * om ** 2)
    x0 = np.zeros(4)
    r = first_lyapunov(A, om, central_second(f, x0, x0, 1e-2), central_third(f, x0, 1e-2))
    assert r["l1"] == pytest.approx(l1_cf, rel=1e-3)
    # leading-order amplitude: R² = −α' (q − q_H)/(ω l1) · 4|q_x|²
    qx2 = abs(r["q"][0]) ** 2
    slope = -ap / (om * r["l1"]) * 4 * qx2
    assert slope == pytest.approx(1 / (c3 * om ** 3), rel=1e-3)


def test_negative_cubic_damping_gives_a_subcritical_l1():
    """The same Jeffcott rotor with c3 < 0 (a softening damper): the closed form changes
    sign, l1 = −4 α' |q_x|² c3 ω² > 0 (subcritical: the circular whirl R² = (q − q_H)/(c3 ω³)
    exists below q_H, on the stable side); within 1e-3."""
    m, c, c3 = 2.0, 0.1, -0.3
    f, A, om, qH = jeffcott(m=m, c=c, c3=c3)
    ap = 2 * m * om / (c ** 2 + 4 * m * m * om * om)
    l1_cf = -4 * ap * c3 * om ** 2 / (2 + 2 * om ** 2)
    x0 = np.zeros(4)
    r = first_lyapunov(A, om, central_second(f, x0, x0, 1e-2), central_third(f, x0, 1e-2))
    assert l1_cf > 0 and r["l1"] == pytest.approx(l1_cf, rel=1e-3)


@pytest.fixture(scope="module")
def coarse_rig():
    """The paper rig with a 36 × 6 film grid (as tests/test_continuation.py), whose film
    force is smooth over ±2 % of the clearance about the Hopf point's equilibrium (l1 from
    fits over ±1 % and ±2 %: −0.074505 both; the default ±5 %: −0.0732)."""
    return coarse_models.paper_rig()


def test_rig_hopf_is_supercritical_and_predicts_the_start_of_the_cycle_branch(coarse_rig):
    """The rig at a_y = −1.85 mm, 50 Hz (36 × 6 grid): the Hopf point is the linear
    threshold (rotordyn.threshold, same bounds), supercritical (cycles below p_H, stable);
    the leading-order amplitude A² = κ (p_H − p) against the cycles found by shooting from
    it at 12 and 25 Pa below p_H (the start of the continued branch, A ≈ 5 and 7 µm =
    0.02 c): A²/(p_H − p) within 5 % of κ (measured 0.05 % and 0.3 %), the period within
    0.5 % of the whirl period, the cycles stable."""
    from rotordyn.analysis.hopf import hopf_cycle

    h = rd.hopf(coarse_rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0, config_ay_m=-1.85e-3)
    th = rd.threshold(coarse_rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0,
                      config_ay_m=-1.85e-3)
    assert h.ok, h.message
    assert h.value == pytest.approx(th.value, rel=1e-9)
    assert h.whirl_frequency_hz == pytest.approx(th.whirl_frequency_hz, rel=1e-3)
    assert h.type == "supercritical" and h.l1 < 0 and h.cycle_side == "below"
    assert h.stable_side == "above" and h.alpha_prime < 0
    assert abs(h.l1) > 3 * h.l1_error
    for d in (12.0, 25.0):
        o = hopf_cycle(coarse_rig, h, h.value - d, rtol=1e-7, tol=1e-5)
        assert o.ok and o.stable, o.message
        a = o.amplitude(0)
        assert a * a / d == pytest.approx(h.amplitude_coefficient[0], rel=0.05)
        assert h.amplitude(h.value - d) == pytest.approx(a, rel=0.03)
        assert o.period_s == pytest.approx(1 / h.whirl_frequency_hz, rel=5e-3)
    df = h.to_frame()
    assert list(df["type"]) == ["supercritical"] and df["chamber_pressure_pa"][0] == h.value
    assert "supercritical" in repr(h)
    with pytest.raises(rd.InputError, match="value"):
        h.cycle_state(h.value + 100.0)  # no cycles on the stable side


def test_hopf_of_the_compressor_over_speed_and_bad_input(capsys):
    """A model that is not the rig: the compressor on plain bearings (36 × 6 grid) over the
    speed: the Hopf point is its threshold (whirl ≈ half speed), l1's sign resolved
    (|l1| > 3 × its difference estimate); the CLI prints the same; bad input names the
    field."""
    from rotordyn.cli import main

    s = coarse_models.compressor_plain()
    h = rd.hopf(s, "speed_hz", bounds=(100.0, 150.0))
    th = rd.threshold(s, "speed_hz", bounds=(100.0, 150.0))
    assert h.ok and h.value == pytest.approx(th.value, rel=1e-9)
    assert 0.45 < h.whirl_frequency_hz / h.value < 0.55
    assert h.type in ("supercritical", "subcritical") and abs(h.l1) > 3 * h.l1_error
    assert h.alpha_prime > 0 and h.stable_side == "below"
    at = rd.hopf(s, "speed_hz", at=h.value)
    assert at.l1 == pytest.approx(h.l1, rel=1e-6)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax = h.plot()
    assert len(ax.lines) == 4  # cycle, stable and unstable equilibrium, the Hopf point
    plt.close("all")
    x, period = h.cycle_state(h.value + (1.0 if h.cycle_side == "above" else -1.0))
    assert x.shape == h.x_equilibrium.shape and period == pytest.approx(
        1 / h.whirl_frequency_hz)
    assert np.isnan(h.amplitude(h.value + (-1.0 if h.cycle_side == "above" else 1.0)))
    with pytest.raises(rd.InputError, match="bounds, at"):
        rd.hopf(s, "speed_hz")
    with pytest.raises(rd.InputError, match="vary"):
        rd.hopf(s, "clearance", bounds=(1, 2))
    with pytest.raises(rd.InputError, match="fd_step"):
        rd.hopf(s, "speed_hz", at=h.value, fd_step=0.0)
    model = str(MODELS / "compressor_plain.toml")
    assert main(["hopf", model, "--vary", "speed_hz", "--bounds", "100", "150",
                 "--json"]) == 0
    out = capsys.readouterr().out
    assert '"type"' in out and '"l1"' in out
    assert main(["hopf", model, "--vary", "speed_hz"]) == 2


SWEEP = """schema = "rotordyn/sweep/1"
name = "hopf-small"
model = "paper-rig"
analysis = "hopf"
chunk_size = 1

[grid]
config_ay_m = [-2.0e-3, -1.85e-3, -1.5e-3]
chamber_pressure_pa = {start = 0.0, stop = 0.12e6, num = 13}
speed_hz = 50.0

[options]
vary = "chamber_pressure_pa"
"""


def test_hopf_sweep_rows_are_deterministic_and_equal_rotordyn_hopf(tmp_path):
    """The ``hopf`` sweep analysis (a threshold line per a_y with l1 at every crossing):
    one row per crossing; the same rows bit for bit with 1 thread and with 2 worker processes;
    each crossing's l1, dRe λ/dp and type equal rotordyn.hopf at that value (1e-6); the line
    without a crossing is a ``no_crossing`` row; ``rotordyn plot --kind hopf-map`` draws it."""
    import pandas as pd

    import rotordyn.sweep as sw
    from rotordyn.cli import main
    from rotordyn.sweep import run_sweep

    spec = tmp_path / "h.toml"
    spec.write_text(SWEEP)
    assert run_sweep(spec, tmp_path / "a", threads=1, progress=False).complete
    assert run_sweep(spec, tmp_path / "b", workers=2, progress=False).complete
    fa, fb = sw.open(tmp_path / "a").frame, sw.open(tmp_path / "b").frame
    pd.testing.assert_frame_equal(fa, fb, check_exact=True)
    assert len(fa) >= 3 and fa["status"].iloc[-1] == "no_crossing"
    assert (fa["status"].iloc[:-1] == "ok").all()
    rig = rd.models.paper_rig()
    for _, row in fa[fa["status"] == "ok"].iterrows():
        h = rd.hopf(rig, at=row["value"], speed_hz=50.0, config_ay_m=row["config_ay_m"])
        assert row["l1"] == pytest.approx(h.l1, rel=1e-6)
        assert row["alpha_prime"] == pytest.approx(h.alpha_prime, rel=1e-3)
        assert row["hopf_type"] == h.type
        assert row["amplitude_coefficient_m2"] == pytest.approx(h.amplitude_coefficient[0],
                                                                rel=1e-3)
    fig = tmp_path / "map.png"
    assert main(["plot", str(tmp_path / "a"), "--kind", "hopf-map", "--out", str(fig)]) == 0
    assert fig.stat().st_size > 0


def test_branch_started_at_the_hopf_point(coarse_rig):
    """hopf_branch: the cycle shot from the leading-order cycle 25 Pa below the rig's Hopf
    point (36 × 6 grid), continued away from it: p_c falls and the amplitude grows along the
    branch, its first point is the leading-order amplitude within 5 % and stable
    (supercritical). (Measured: between 7 and 16 µm the branch folds twice within 40 Pa —
    an unstable middle cycle where the film's cavitation pattern starts to switch along the
    orbit; docs/nonlinear.md.)"""
    from rotordyn.analysis.hopf import hopf_branch

    h = rd.hopf(coarse_rig, bounds=(0.04e6, 0.08e6), speed_hz=50.0, config_ay_m=-1.85e-3)
    br = hopf_branch(coarse_rig, h, (0.04e6, 0.08e6), distance=25.0, max_points=3,
                     rtol=1e-7, tol=1e-5, ds=0.02)
    assert br.ok and len(br) == 3, br.message
    assert br.parameter[0] == pytest.approx(h.value - 25.0)
    assert np.all(np.diff(br.parameter) < 0) and np.all(np.diff(br.amplitude_m[:, 0]) > 0)
    assert br.amplitude_m[0, 0] == pytest.approx(h.amplitude(h.value - 25.0), rel=0.05)
    assert br.stable[0]
    with pytest.raises(rd.InputError, match="result"):
        hopf_branch(coarse_rig, None, (0.04e6, 0.08e6))
