"""One stability verdict rule for the API and every sweep row (the round-off band of Re λ,
``rotordyn.results.modes.ROUND_OFF_REL``, the C++ core's ``kRoundOffRel``).

A conservative rotor (undamped linear supports, no material damping: the compressor of
tests/data/models/compressor_linear.toml without its support damping) has max Re λ exactly 0
(its roots are made exactly imaginary from their vectors) or round-off of it: the stability
rows and ``rd.stability`` called it stable, the boundary rows (``max Re λ < 0``) unstable.
A negative-stiffness support at the middle impeller (an unbalanced magnetic pull larger than
the supports' stiffness) makes a divergence, a growing real root: unstable everywhere.
The log decrement of that root: tests/test_log_dec_divergence.py.
"""

import re
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.results.modes import ROUND_OFF_REL, point_stable
from rotordyn.sweep import run_sweep
import rotordyn.sweep as sw

MODELS = Path(__file__).parent / "data" / "models"
PULL = "supports.2.kxx_n_per_m"
STABLE_PULL, DIVERGENT_PULL = -1.0e6, -1.0e9  # the shaft and supports hold 1e8 N/m each


def _model_text(pull_n_per_m: float) -> str:
    """compressor_linear.toml with isotropic undamped supports and a pull support at the
    middle impeller (x only: a divergence in x when it exceeds the supports' stiffness)."""
    t = (MODELS / "compressor_linear.toml").read_text()
    t = re.sub(r"c(xx|yy)_n_s_per_m = .*\n", "", t)
    t = t.replace("kyy_n_per_m = 1.5e8", "kyy_n_per_m = 1.0e8")
    return t + ("\n[[support]]\ntype = \"linear\"\nname = \"pull\"\nstation = 3\n"
                f"kxx_n_per_m = {pull_n_per_m!r}\nkyy_n_per_m = 0.0\n")


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    d = tmp_path_factory.mktemp("verdict")
    model = d / "m.toml"
    model.write_text(_model_text(STABLE_PULL))
    grid = (f'[grid]\n"{PULL}" = [{DIVERGENT_PULL!r}, {STABLE_PULL!r}]\n'
            "speed_hz = [20.0, 60.0]\n")
    head = f'schema = "rotordyn/sweep/1"\nmodel = "{model.as_posix()}"\n'
    (d / "st.toml").write_text(head + 'name = "st"\nanalysis = "stability"\n' + grid)
    (d / "bd.toml").write_text(head + 'name = "bd"\nanalysis = "boundary"\n' + grid
                               + f'[options]\nx = "{PULL}"\ny = "speed_hz"\nresolution = 3\n')
    out = {}
    for k in ("st", "bd"):
        assert run_sweep(d / f"{k}.toml", d / k, threads=1, progress=False).complete
        out[k] = sw.open(d / k).frame
    return d, out


def _api(d, pull, speed):
    p = d / f"m{pull:g}.toml"
    p.write_text(_model_text(pull))
    return rd.stability(rd.System.from_toml(p), speed)


def test_the_band_is_the_cores():
    assert ROUND_OFF_REL == _core.ROUND_OFF_REL == 1e-9
    # a root within the band is stable whatever its sign; one past it is not
    lam = 1e3j + np.array([5e-7, -5e-7, 2e-6])
    assert point_stable(lam[:2]) and not point_stable(lam)


@pytest.mark.parametrize("speed", [20.0, 60.0])
def test_a_conservative_point_is_stable_in_the_api_and_both_sweeps(runs, speed):
    d, fr = runs
    st = _api(d, STABLE_PULL, speed)
    assert st.stable
    # the test can fail: max Re λ is not below 0 (exactly 0 or round-off above it), so
    # the boundary rows' former rule (max Re λ < 0) called the point unstable
    lam = np.asarray(st.all_eigenvalues if st.all_eigenvalues is not None else st.eigenvalues)
    assert lam.real.max() >= 0.0
    for k in ("st", "bd"):
        rows = fr[k][(fr[k][PULL] == STABLE_PULL) & (fr[k]["speed_hz"] == speed)]
        assert len(rows) and (rows["status"] == "ok").all()
        assert rows["point_stable"].astype(bool).all(), k
        assert rows["mode_stable"].astype(bool).all(), k
        assert np.abs(rows["max_real_1_per_s"]).max() <= ROUND_OFF_REL * np.abs(lam).max()


@pytest.mark.parametrize("speed", [20.0, 60.0])
def test_a_divergence_is_unstable_in_the_api_and_both_sweeps(runs, speed):
    d, fr = runs
    st = _api(d, DIVERGENT_PULL, speed)
    assert not st.stable
    lam0 = st.eigenvalues[int(np.argmax(st.eigenvalues.real))]
    assert lam0.imag == 0.0 and lam0.real > 1.0  # the static divergence: a real root
    for k in ("st", "bd"):
        rows = fr[k][(fr[k][PULL] == DIVERGENT_PULL) & (fr[k]["speed_hz"] == speed)]
        assert len(rows) and not rows["point_stable"].astype(bool).any(), k
        assert rows["max_real_1_per_s"].iloc[0] == pytest.approx(lam0.real, rel=1e-9)
