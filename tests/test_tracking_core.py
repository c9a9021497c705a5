"""Mode tracking in the C++ core (issue 22: the NumPy/SciPy loop was ~10 % of a sweep's
stability chunk) gives the ids of the former NumPy/SciPy code (tests/tracking_reference.py,
SciPy's ``linear_sum_assignment``) on random lines (modes appearing, leaving, reordered; several
lines in one call) and on the Campbell lines of models that are not the paper rig (the
compressor on plain and on tilting-pad bearings, whose pads add modes); the one-call form of a
sweep chunk equals one call per line. Tolerance: none (the same ids)."""

import importlib
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.analysis.tracking import track_lines, track_modes
from rotordyn.errors import InputError
from tracking_reference import track_modes_reference

campbell_mod = importlib.import_module("rotordyn.analysis.campbell")  # the module, not the function

MODELS = Path(__file__).parent / "data" / "models"


def _random_line(rng, n_pts, n, k):
    """Modes drifting smoothly along a line, slots shuffled, some slots empty."""
    lam0 = -rng.uniform(0.1, 5, k) + 1j * rng.uniform(10, 200, k)
    dlam = -rng.uniform(0, 0.3, k) + 1j * rng.uniform(-8, 8, k)
    q, _ = np.linalg.qr(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n)))
    base = q[:, :k]
    rot = 0.05 * (rng.standard_normal((n, k)) + 1j * rng.standard_normal((n, k)))
    lam = np.full((n_pts, k), np.nan + 0j)
    phi = np.full((n_pts, n, k), np.nan + 0j)
    for i in range(n_pts):
        perm = rng.permutation(k)
        keep = rng.uniform(size=k) > 0.15
        lam[i, :] = np.where(keep, lam0 + i * dlam, np.nan)[perm]
        phi[i] = (base + i * rot)[:, perm] * np.exp(1j * rng.uniform(0, 6.3, k))
    return lam, phi


@pytest.mark.parametrize("seed", range(12))
def test_random_lines_equal_the_scipy_reference(seed):
    rng = np.random.default_rng(seed)
    n, k = 6, int(rng.integers(2, 7))
    a = rng.standard_normal((n, n))
    w = a @ a.T + n * np.eye(n)
    lines = [_random_line(rng, int(rng.integers(1, 14)), n, k) for _ in range(3)]
    want = [track_modes_reference(lam, phi, weight=w) for lam, phi in lines]
    for (lam, phi), ref in zip(lines, want):
        np.testing.assert_array_equal(track_modes(lam, phi, weight=w), ref)
        np.testing.assert_array_equal(track_modes(lam), track_modes_reference(lam))
    # all lines in one call, each restarting at id 0
    lam = np.concatenate([x[0] for x in lines])
    phi = [p for x in lines for p in x[1]]
    starts = np.concatenate([np.arange(len(x[0])) == 0 for x in lines])
    np.testing.assert_array_equal(track_lines(lam, phi, w, starts), np.concatenate(want))


@pytest.mark.parametrize("model", ["plain", "tilting_pad"])
def test_compressor_campbell_ids_equal_the_scipy_reference(model, monkeypatch):
    seen = []

    def spy(lam, shapes, weight=None, **kw):
        seen.append((lam, shapes, weight))
        return track_modes(lam, shapes, weight=weight, **kw)

    monkeypatch.setattr(campbell_mod, "track_modes", spy)
    s = rd.System.from_toml(str(MODELS / f"compressor_{model}.toml"))
    res = rd.campbell(s, np.linspace(20.0, 160.0, 15), n_modes=8)
    (lam, shapes, weight), = seen
    ref = track_modes_reference(lam, shapes, weight=weight)
    np.testing.assert_array_equal(res.mode_id, ref)
    assert ref.max() >= 7  # the line has real work: at least the 8 modes tracked


def test_bad_input_is_named():
    lam = np.zeros((3, 2), complex)
    with pytest.raises(InputError, match="shapes"):
        track_modes(lam, [np.zeros((4, 2))] * 2)
    with pytest.raises(InputError, match="shapes"):
        track_modes(lam, [np.zeros((4, 3))] * 3)
    with pytest.raises(InputError, match="min_mac"):
        track_modes(lam, min_mac=-1.0)
    with pytest.raises(rd.RotordynError, match="weight"):
        track_modes(lam, np.zeros((3, 4, 2)), weight=np.eye(3))
