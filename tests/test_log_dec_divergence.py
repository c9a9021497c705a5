"""One log decrement of a growing real root (a divergence): −inf in the API and in the
stability and boundary sweeps' rows (the rows said NaN, "unknown", for a known divergence).
The runs of tests/test_verdict_one_rule.py: compressor_linear.toml without support damping
and a pull support at the middle impeller, k_xx = −1e9 N/m (a divergence in x)."""

import numpy as np
import pytest

import rotordyn as rd  # noqa: F401
from rotordyn.results.modes import log_dec

from test_verdict_one_rule import DIVERGENT_PULL, PULL, STABLE_PULL, _api, runs  # noqa: F401


@pytest.mark.parametrize("speed", [20.0, 60.0])
def test_a_divergence_has_log_dec_minus_inf_in_the_api_and_both_sweeps(runs, speed):
    d, fr = runs
    st = _api(d, DIVERGENT_PULL, speed)
    i = int(np.argmax(st.eigenvalues.real))
    assert st.eigenvalues[i].imag == 0.0 and st.eigenvalues[i].real > 1.0
    assert st.log_dec[i] == -np.inf
    for k in ("st", "bd"):
        rows = fr[k][(fr[k][PULL] == DIVERGENT_PULL) & (fr[k]["speed_hz"] == speed)]
        div = rows[rows["freq_hz"] == 0.0]
        assert len(div) == 1, k
        assert div["log_dec"].iloc[0] == -np.inf, k  # a known divergence, not NaN
        assert not div["mode_stable"].iloc[0]
        assert div["damping_ratio"].iloc[0] == pytest.approx(-1.0, rel=1e-12)
        # the rest of the rows keep finite values
        assert np.isfinite(rows.loc[rows["freq_hz"] > 0, "log_dec"]).all()
    # the API's and the rows' log dec are one function's (the same numbers per mode)
    rows = fr["st"][(fr["st"][PULL] == DIVERGENT_PULL) & (fr["st"]["speed_hz"] == speed)]
    lam = rows["eig_real_1_per_s"].to_numpy() + 2j * np.pi * rows["freq_hz"].to_numpy()
    assert np.array_equal(rows["log_dec"].to_numpy(), log_dec(lam))


def test_minus_inf_survives_the_dataset_and_sorts_first(runs):
    """parquet keeps −inf (not NaN); a sort on log dec puts the divergence first and a min
    finds it, where NaN was skipped as unknown."""
    _, fr = runs
    st = fr["st"]
    assert st["log_dec"].min() == -np.inf
    first = st.sort_values("log_dec").iloc[0]
    assert first[PULL] == DIVERGENT_PULL and first["freq_hz"] == 0.0
    assert not st["log_dec"].isna().any()


def test_an_undamped_point_has_log_dec_plus_zero(runs):
    """The conservative points: every log dec exactly +0 in the rows (the rows printed −0,
    the API's function never does)."""
    _, fr = runs
    for k in ("st", "bd"):
        rows = fr[k][fr[k][PULL] == STABLE_PULL]
        assert len(rows) and (rows["log_dec"] == 0.0).all(), k
        assert not np.signbit(rows["log_dec"]).any(), k
