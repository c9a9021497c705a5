"""Exports that stay right in other tools (issue 24):

- the plant's and the laws' python-control systems (balanced: states scaled by powers of two,
  exact) are evaluated by python-control through SLICOT's TB05AD (slycot installed) and
  through its own dense solve (slycot's routine made to fail, python-control's fallback)
  equal to rotordyn's frequency response within 1e-8 relative, and rotordyn's own response
  equals an independent second-order evaluation q = (s²I − sA₂₂ − A₂₁)⁻¹(…) from the
  state matrix's blocks (1e-10); SciPy's ``freqresp`` on ``Plant.to_scipy()`` (factors from
  the balanced model) within 1e-8;
- ``Plant.to_control()`` names every input (command, disturbance forces) and output
  (measurements, performance) and keeps a reduced plant's feedthrough;
- a discrete law's JSON and C-header coefficients, evaluated independently (parsed JSON in
  numpy; the header compiled by the C compiler into a program that steps the law), give
  the law's outputs to round-off; the ZOH coefficients equal e^{AT} of the original law
  (frequency response at z = e^{iωT}, 1e-8), the Tustin ones K((2/T)(z − 1)/(z + 1)).
- not the rig: the compressor on plain bearings exported by ``statespace().to_control()``.
"""

import json
import shutil
import subprocess

import numpy as np
import pytest
from scipy.linalg import expm

import rotordyn as rd
from rotordyn.control import export
from rotordyn.control.lqr import lqg
from rotordyn.control.plant import plant
from rotordyn.control.reduction import modal_truncation
from rotordyn.errors import InputError

control = pytest.importorskip("control")
AY, PC = -1.85e-3, 0.05e6
F = np.geomspace(1.0, 2000.0, 37)


@pytest.fixture(scope="module")
def rig_plant():
    return plant(rd.models.paper_rig(), 50.0, PC, AY, measurements=[("journal", 0)],
                 disturbance_stations=[4, 6])


def pc_response(sys_, f, slycot: bool, monkeypatch=None):
    """python-control's own evaluation, through slycot or its fallback."""
    if not slycot:
        def no_slycot(self, x):
            raise ImportError("slycot disabled for this test")
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(control.StateSpace, "slycot_laub", no_slycot)
            return np.moveaxis(sys_(2j * np.pi * f), 2, 0)
    return np.moveaxis(sys_(2j * np.pi * f), 2, 0)


def rel_err(X, R):
    return max(np.linalg.norm(X[i] - R[i]) / np.linalg.norm(R[i]) for i in range(len(R)))


def second_order_reference(p, f):
    """G of the full plant from the blocks of A: q̈ = A₂₁q + A₂₂q̇ + A₂₃x_a + B_d d,
    ẋ_a = A_a x_a + B_a u."""
    A, n = p.A, p.n_mech
    na = A.shape[0] - 2 * n
    A21, A22, A23, Aa = A[n:2 * n, :n], A[n:2 * n, n:2 * n], A[n:2 * n, 2 * n:], A[2 * n:, 2 * n:]
    nd = p.Bd.shape[1]
    out = []
    for fi in f:
        s = 2j * np.pi * fi
        xa = np.linalg.solve(s * np.eye(na) - Aa, p.B[2 * n:])
        q = np.linalg.solve(s * s * np.eye(n) - s * A22 - A21,
                            np.hstack([A23 @ xa, p.Bd[n:2 * n]]))
        X = np.vstack([q, s * q, np.hstack([xa, np.zeros((na, nd))])])
        out.append(np.vstack([p.C, p.C_perf]) @ X)
    return np.array(out)


@pytest.mark.parametrize("slycot", [True, False])
def test_plant_export_evaluates_to_round_off(rig_plant, slycot):
    pytest.importorskip("slycot") if slycot else None
    p = rig_plant
    R = second_order_reference(p, F)
    G = p.frequency_response(F)
    assert rel_err(G, R) < 1e-10
    sys_ = p.to_control()
    assert rel_err(pc_response(sys_, F, slycot), G) < 1e-8
    # names: command, then the disturbance forces; measurements, then performance
    assert list(sys_.input_labels) == ["chamber_pressure_command_pa", "force_x_n[4]",
                                       "force_y_n[4]", "force_x_n[6]", "force_y_n[6]"]
    assert list(sys_.output_labels) == ["journal_x_m[0]", "journal_y_m[0]",
                                        "performance_journal_x_m[0]",
                                        "performance_journal_y_m[0]"]
    # the reduced plant keeps every feedthrough term (the dropped modes' static part)
    pr, _ = modal_truncation(p, 500.0)
    sr = pr.to_control()
    assert np.abs(sr.D).max() > 0 and np.array_equal(sr.D, pr.matrices()[3])
    Gr = pr.frequency_response(F)
    assert rel_err(pc_response(sr, F, slycot), Gr) < 1e-8
    A, B, C, D = pr.matrices()
    dense = np.array([C @ np.linalg.solve(2j * np.pi * fi * np.eye(A.shape[0]) - A, B) + D
                      for fi in F])
    assert rel_err(Gr, dense) < 1e-9


def test_plant_to_scipy_factors(rig_plant):
    import scipy.signal as sig

    p = rig_plant
    R = second_order_reference(p, F)
    for i, j in ((1, 0), (0, 0), (0, 1), (3, 4)):
        _, h = sig.freqresp(p.to_scipy(i, j), 2 * np.pi * F)
        assert np.max(np.abs(h - R[:, i, j]) / np.abs(R[:, i, j])) < 1e-8
    with pytest.raises(InputError, match="output"):
        p.to_scipy(9, 0)


@pytest.mark.parametrize("slycot", [True, False])
def test_lqg_law_export_evaluates_to_round_off(rig_plant, slycot):
    pytest.importorskip("slycot") if slycot else None
    from rotordyn.control import lti

    k = lqg(modal_truncation(rig_plant, 500.0)[0])
    ref = np.array([k.C @ np.linalg.solve(2j * np.pi * fi * np.eye(k.n_states) - k.A, k.B)
                    + k.D for fi in F])
    mine = lti.freqresp(lti.balanced(lti.SS(k.A, k.B, k.C, k.D)), 2 * np.pi * F)
    assert rel_err(mine, ref) < 1e-9
    assert rel_err(pc_response(k.to_control(), F, slycot), mine) < 1e-8


def test_compressor_statespace_export():
    """Not the rig: the compressor on plain bearings (force in, displacement out)."""
    sysc = rd.System.from_toml("tests/data/models/compressor_plain.toml")
    ss = rd.statespace(sysc, inputs=[("force", 3)], outputs=[("displacement", 3)],
                       speed_hz=100.0)
    G = ss.frequency_response(F)
    for slycot in (True, False):
        assert rel_err(pc_response(ss.to_control(), F, slycot), G) < 1e-8
    assert list(ss.to_control().input_labels) == list(ss.input_names)


@pytest.fixture(scope="module")
def lqg_law(rig_plant):
    return lqg(modal_truncation(rig_plant, 500.0)[0])


@pytest.mark.parametrize("method", ["zoh", "tustin"])
def test_discrete_law_against_its_continuous_law(lqg_law, method):
    k, T = lqg_law, 1e-4
    kd = export.discretise(k, T, method)
    assert kd.sample_time_s == T and kd.discrete
    f = np.geomspace(1.0, 0.45 / T, 25)
    z = np.exp(2j * np.pi * f * T)
    Kd = np.array([kd.C @ np.linalg.solve(zi * np.eye(kd.n_states) - kd.A, kd.B) + kd.D
                   for zi in z])
    if method == "zoh":  # the original (unbalanced) law discretised by the test
        n, m = k.n_states, k.n_inputs
        E = expm(np.block([[k.A, k.B], [np.zeros((m, n + m))]]) * T)
        Ad, Bd = E[:n, :n], E[:n, n:]
        ref = np.array([k.C @ np.linalg.solve(zi * np.eye(n) - Ad, Bd) + k.D for zi in z])
    else:
        s = 2 / T * (z - 1) / (z + 1)
        ref = np.array([k.C @ np.linalg.solve(si * np.eye(k.n_states) - k.A, k.B) + k.D
                        for si in s])
    # 1e-8: e^{AT} of the law's unscaled states (entries over 16 decades) is itself only
    # good to ~5e-9 (observed 4.7e-9 ZOH; Tustin, no exponential, 1e-12)
    assert rel_err(Kd, ref) < (1e-8 if method == "zoh" else 1e-10)


def test_discrete_law_json_and_c_header(lqg_law, tmp_path):
    kd = export.discretise(lqg_law, 1e-4)
    y = np.random.default_rng(7).normal(scale=1e-6, size=(200, kd.n_inputs))
    u = export.simulate(kd, y)
    # JSON: parsed independently, stepped in numpy
    export.to_json(kd, tmp_path / "law.json")
    c = json.loads((tmp_path / "law.json").read_text())
    assert c["sample_time_s"] == 1e-4 and c["format"] == export.FORMAT
    assert [s["unit"] for s in c["inputs"]] == ["m", "m"]
    A, B, C, D = (np.array(c[x]) for x in "ABCD")
    assert np.array_equal(A, kd.A) and np.array_equal(D, kd.D)  # exact round trip
    x = np.zeros(A.shape[0])
    uj = []
    for yi in y:
        uj.append(float((C @ x + D @ yi)[0]))
        x = A @ x + B @ yi
    assert np.array_equal(np.array(uj), u)
    # C header: compiled and run
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler")
    export.to_c_header(kd, tmp_path / "law.h", prefix="lqg")
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "law.h"\nint main(void){double x[LQG_NX>0?LQG_NX:1]='
        '{0};double y[LQG_NY];int k,j;for(k=0;;++k){for(j=0;j<LQG_NY;++j)'
        'if(scanf("%lf",&y[j])!=1)return 0;printf("%.17g\\n",lqg_step(x,y));}}\n')
    exe = tmp_path / "law"
    subprocess.run([cc, "-std=c99", "-O2", "-Wall", "-Werror", "-o", str(exe),
                    str(tmp_path / "main.c")], check=True, capture_output=True)
    text = "\n".join(" ".join(f"{v:.17g}" for v in r) for r in y)
    out = subprocess.run([str(exe)], input=text, capture_output=True, text=True,
                         check=True).stdout.split()
    uc = np.array([float(s) for s in out])
    assert uc.size == len(y)
    assert np.max(np.abs(uc - u)) <= 1e-12 * np.abs(u).max()
    assert "#define LQG_SAMPLE_TIME_S 0.0001" in (tmp_path / "law.h").read_text()


def test_export_bad_input(lqg_law):
    with pytest.raises(InputError, match="sample_time_s"):
        export.discretise(lqg_law, -1e-4)
    with pytest.raises(InputError, match="sample_time_s"):
        export.discretise(lqg_law, float("nan"))
    with pytest.raises(InputError, match="method"):
        export.discretise(lqg_law, 1e-4, "euler")
    with pytest.raises(InputError, match="controller.sample_time_s"):
        export.to_json(lqg_law)
    with pytest.raises(InputError, match="prefix"):
        export.to_c_header(export.discretise(lqg_law, 1e-4), prefix="1law")
    with pytest.raises(InputError, match="balanced"):
        lqg_law.to_control(balanced="yes")


def test_discrete_law_with_anti_windup_json_and_c_header(tmp_path):
    """A sample-and-hold PID with anti-windup (issue 24): the JSON carries L and the mode, the
    C header an <prefix>_anti_windup(x, excess) to call once u[k] is applied; stepping the
    JSON in numpy and the compiled header with the valve's clip reproduces simulate() with
    u_range (1e-12), and the correction acts (the saturated run differs from the plain law)."""
    from rotordyn.control.antiwindup import with_anti_windup
    from rotordyn.control.pid import pid

    kd = with_anti_windup(export.discretise(pid(1e9, 2.5e6, 5e10), 5e-4), mode="conditioning")
    y = np.random.default_rng(3).normal(scale=2e-6, size=(300, kd.n_inputs)) + 3e-6
    lo, hi = -1e3, 1e3
    u = export.simulate(kd, y, (lo, hi))
    assert np.abs(u).max() > hi  # saturated
    plain = export.simulate(kd.with_options(anti_windup_gain=None,
                                            anti_windup_mode="back-calculation"), y, (lo, hi))
    assert np.abs(plain - u).max() > 0.1 * hi
    export.to_json(kd, tmp_path / "law.json")
    c = json.loads((tmp_path / "law.json").read_text())
    assert c["anti_windup"]["mode"] == "conditioning"
    A, B, C, D = (np.array(c[x]) for x in "ABCD")
    L = np.array(c["anti_windup"]["L"])
    assert np.array_equal(L, kd.anti_windup_gain)
    x, uj = np.zeros(A.shape[0]), []
    for yi in y:
        uk = float((C @ x + D @ yi)[0])
        uj.append(uk)
        x = A @ x + B @ yi + L * (min(max(uk, lo), hi) - uk)
    assert np.array_equal(np.array(uj), u)
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler")
    export.to_c_header(kd, tmp_path / "law.h", prefix="pid")
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "law.h"\nint main(void){double x[PID_NX]={0};'
        'double y[PID_NY],u,d;int j;for(;;){for(j=0;j<PID_NY;++j)'
        'if(scanf("%lf",&y[j])!=1)return 0;u=pid_step(x,y);'
        f'd=(u<{lo!r}?{lo!r}:(u>{hi!r}?{hi!r}:u))-u;pid_anti_windup(x,d);'
        'printf("%.17g\\n",u);}}\n')
    exe = tmp_path / "law"
    subprocess.run([cc, "-std=c99", "-O2", "-Wall", "-Werror", "-o", str(exe),
                    str(tmp_path / "main.c")], check=True, capture_output=True)
    text = "\n".join(" ".join(f"{v:.17g}" for v in r) for r in y)
    out = subprocess.run([str(exe)], input=text, capture_output=True, text=True,
                         check=True).stdout.split()
    uc = np.array([float(s) for s in out])
    assert uc.size == len(y)
    assert np.max(np.abs(uc - u)) <= 1e-12 * np.abs(u).max()
