"""The per-model cache of the rotor analyses (issue 22): the constrained/reduced matrices and
the modal operator (sparse pencil, K's factorisation) are kept per System value, and the
unbalance response of a rotor without bearing elements is one C++ call over its speeds.

What is guarded: a cached call gives the answer of a fresh one bit for bit (same numbers
through the same solver); a changed model (System is a frozen dataclass: a change is a new
object, dataclasses.replace) never meets the old entry; the cached matrices cannot be altered
by a caller; the operator agrees with the stand-alone ``_core.modal`` to round-off (1e-12
relative: K is factorised alone instead of inside K + 0 D + 0 M, so the ordering may differ);
the one-call unbalance response equals the per-speed loop (linearise, then the stand-alone
sparse solve) to round-off (1e-12 of the peak).
Models: the compressor rotor of tests/data/models on its linear supports (not the paper rig)
and a 100-element rotor with disks.
"""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.modes import clear_cache, rotor_matrices

MODELS = Path(__file__).parent / "data" / "models"


def _compressor():
    return rd.System.from_toml(MODELS / "compressor_linear.toml")


def _beam(n_el=60, k=1e7):
    secs = tuple(rd.ShaftSection(0.015, 0.05) for _ in range(n_el))
    sups = tuple(rd.Support(s, "linear", kxx_n_per_m=k, kyy_n_per_m=k, cxx_n_s_per_m=200.0,
                            cyy_n_s_per_m=200.0) for s in (0, n_el))
    disks = (rd.Disk(n_el // 4, 12.0, ip_kg_m2=0.04, id_kg_m2=0.022),
             rd.Disk(n_el // 2, 20.0, ip_kg_m2=0.08, id_kg_m2=0.045))
    return rd.System(rotor=rd.Rotor(secs, disks=disks), supports=sups,
                     reduction=rd.Reduction(method="none"), gravity_m_s2=0.0)


@pytest.mark.parametrize("make", [_compressor, _beam])
def test_cached_call_equals_fresh_call_bit_for_bit(make):
    s = make()
    clear_cache()
    fresh = rd.modes(s, 120.0, reduction="none", n_modes=6, without_bearings=True)
    # other models and speeds in between: the cache holds them too
    rd.modes(_beam(40), 10.0, reduction="none", n_modes=12)
    rd.modes(s, 30.0, reduction="none", n_modes=12, without_bearings=True)
    again = rd.modes(make(), 120.0, reduction="none", n_modes=6, without_bearings=True)
    np.testing.assert_array_equal(again.eigenvalues, fresh.eigenvalues)
    np.testing.assert_array_equal(again.shapes, fresh.shapes)
    assert list(again.whirl) == list(fresh.whirl)


def test_changed_model_never_meets_the_old_entry():
    """System and its parts are frozen: a change is a new value, so a new key; its modes
    are those of a fresh computation and differ from the old model's."""
    s = _beam()
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.gravity_m_s2 = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.supports[0].kxx_n_per_m = 1.0
    old = rd.modes(s, 50.0, reduction="none", n_modes=6)
    stiff = dataclasses.replace(s, supports=tuple(dataclasses.replace(
        p, kxx_n_per_m=5e7, kyy_n_per_m=5e7) for p in s.supports))
    disk = s.rotor.disks[1]
    heavy = dataclasses.replace(s, rotor=dataclasses.replace(
        s.rotor, disks=(s.rotor.disks[0], dataclasses.replace(disk, mass_kg=30.0))))
    for changed in (stiff, heavy):
        got = rd.modes(changed, 50.0, reduction="none", n_modes=6)
        clear_cache()
        want = rd.modes(changed, 50.0, reduction="none", n_modes=6)
        np.testing.assert_array_equal(got.eigenvalues, want.eigenvalues)
        assert np.max(np.abs(got.eigenvalues - old.eigenvalues)
                      / np.abs(old.eigenvalues)) > 1e-3
    assert rotor_matrices(stiff, "none") is not rotor_matrices(s, "none")
    assert rotor_matrices(_beam(), "none") is rotor_matrices(s, "none")  # equal value


def test_cached_matrices_are_read_only():
    s = _compressor()
    for method in ("none", s.reduction.method):
        for a in rotor_matrices(s, method).matrices():
            with pytest.raises(ValueError):
                a[0, 0] = 1.0
    xy = rotor_matrices(s, "none").xy_pairs()
    xy.clear()  # a caller's copy: the cached pairs are untouched
    assert rotor_matrices(s, "none").xy_pairs()


@pytest.mark.parametrize("make", [_compressor, _beam])
def test_operator_matches_standalone_modal(make):
    """ModalOperator.modal(Ω) against _core.modal(M, C + ΩG, K): eigenvalues and whirl;
    at rest and at speed, 3 and 12 modes."""
    rm = rotor_matrices(make(), "none")
    M, K, C, G = rm.matrices()
    op = rm.operator()
    assert op.factored and op.size == M.shape[0] > 48
    for w in (0.0, 900.0):
        for k in (3, 12):
            a = op.modal(w, rm.xy_pairs(), k, True, rm.rot_pairs())
            b = _core.modal(M, C + w * G, K, rm.xy_pairs(), k, True, rm.rot_pairs())
            la, lb = np.asarray(a.eigenvalues), np.asarray(b.eigenvalues)
            assert la.shape == lb.shape == (k,)
            np.testing.assert_allclose(la, lb, rtol=1e-12, atol=1e-12 * np.abs(lb).max())
            assert list(a.whirl) == list(b.whirl)


def test_operator_rejects_bad_shapes():
    with pytest.raises(rd.InputError, match="G"):
        _core.ModalOperator(np.eye(3), np.eye(3), np.eye(2), np.eye(3))
    with pytest.raises(rd.InputError, match="D"):
        _core.modal(np.eye(60), np.eye(59), np.eye(60), [], 3)


def _loop(s, ub, sp, stations):
    """The former per-speed path: linearise at each speed, then the stand-alone sparse solve
    (K - Ω² M + iΩ D) q = Ω² F₁ and the station outputs."""
    from rotordyn.analysis.assembly import assembled

    asm = assembled(s)
    F1 = asm.unbalance_load(ub)
    O = np.concatenate([asm.station_output_matrix(st) for st in stations])
    out = []
    for f in sp:
        lm = rd.linearize(s, f)
        w = 2 * np.pi * f
        q = np.asarray(_core.harmonic_response(lm.M, lm.D, lm.K, w, (w**2 * F1)[:, None]))
        out.append(O @ q[:, 0])
    Z = np.array(out)
    return Z[:, 0::2], Z[:, 1::2]


@pytest.mark.parametrize("make", [_compressor, _beam])
def test_unbalance_one_call_equals_per_speed_loop(make):
    """A rotor without bearing elements: the one-call response against the per-speed loop,
    over speeds through the first criticals; refinement adds the same speeds."""
    s = make()
    sp = np.linspace(5.0, 300.0, 60)
    st = 3 if make is _compressor else 15
    ub = [(st, 1e-4, 30.0)]
    a = rd.unbalance_response(s, ub, sp, stations=[st, 1], refine=False)
    assert list(a.point_status) == ["ok"] * len(sp)
    X, Y = _loop(s, ub, sp, [st, 1])
    for got, want in ((a.x, X), (a.y, Y)):
        assert np.max(np.abs(got - want)) <= 1e-12 * np.max(np.abs(want))
    c = rd.unbalance_response(s, ub, sp[::4], stations=[st])
    assert c.speeds_hz.size > sp[::4].size  # peaks refined
    X, _ = _loop(s, ub, c.speeds_hz, [st])
    assert np.max(np.abs(c.x - X)) <= 1e-12 * np.max(np.abs(X))


def test_shared_operator_from_threads():
    """Threads share one cached model (the GIL is released in the modal call): each thread's
    answers equal the serial ones bit for bit (the kept LU is only read)."""
    from concurrent.futures import ThreadPoolExecutor

    s = _beam()
    speeds = [0.0, 20.0, 55.0, 90.0] * 3
    serial = [rd.modes(s, f, reduction="none", n_modes=6).eigenvalues for f in speeds]
    with ThreadPoolExecutor(4) as ex:
        par = list(ex.map(lambda f: rd.modes(s, f, reduction="none", n_modes=6).eigenvalues,
                          speeds))
    for a, b in zip(serial, par):
        np.testing.assert_array_equal(a, b)
