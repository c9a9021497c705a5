"""Guards issue 18's "a way to save and reload a result": every result family saved with
``result.save(path)`` and read back with ``rotordyn.load_result(path)`` (or
``Class.load(path)``) is equal to the one saved, field by field (arrays bit-identical, tables
with their dtypes and categories, nested linear model and equilibrium), on models that are
not the paper rig; a file from a newer schema, of another kind, or not a result at all is
refused with an InputError naming the file."""

from __future__ import annotations

import dataclasses
import json
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.results import store

MODELS = Path(__file__).parent / "data" / "models"


def assert_same(a, b, where="result"):
    """Recursive equality of results: same types, arrays equal (NaN = NaN, same dtype kind)."""
    assert type(a) is type(b), (where, type(a), type(b))
    if dataclasses.is_dataclass(a):
        for f in dataclasses.fields(a):
            assert_same(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif isinstance(a, np.ndarray):
        assert a.shape == b.shape and a.dtype == b.dtype, (where, a.dtype, b.dtype)
        if a.dtype.kind in "fc":
            np.testing.assert_array_equal(a, b, err_msg=where)
        else:
            assert (a == b).all(), where
    elif isinstance(a, pd.DataFrame):
        pd.testing.assert_frame_equal(a, b, obj=where)
    elif isinstance(a, dict):
        assert list(a) == list(b), where
        for k in a:
            assert_same(a[k], b[k], f"{where}[{k!r}]")
    elif isinstance(a, (tuple, list)):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{where}[{i}]")
    elif isinstance(a, float) and np.isnan(a):
        assert np.isnan(b), where
    else:
        assert a == b, (where, a, b)


@pytest.fixture(scope="module")
def results():
    tp = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    pl = rd.System.from_toml(MODELS / "compressor_plain.toml")
    lin = rd.System.from_toml(MODELS / "compressor_linear.toml")
    return {
        "equilibrium": rd.equilibrium(pl, 100.0),
        "stability": rd.stability(tp, 150.0),
        "modes": rd.modes(lin, 50.0, n_modes=4),
        "campbell": rd.campbell(pl, np.linspace(40, 160, 4)),
        "rotor campbell": rd.rotor_campbell(lin, np.linspace(0, 200, 5), n_modes=4),
        "unbalance": rd.unbalance_response(lin, [(3, 1e-4, 0.0)], np.linspace(100, 200, 11),
                                           stations=[1, 3], operating_speed_hz=(140, 170),
                                           refine=False),
        "static": rd.static(pl, 120.0),
        "threshold": rd.threshold(pl, "speed_hz", bounds=(60.0, 160.0), n_scan=5),
        "statespace": rd.statespace(pl, inputs=[("force", 3)], speed_hz=100.0),
        "transient": rd.transient(pl, 0.01, 100.0, n_out=20),
    }


NAMES = ["equilibrium", "stability", "modes", "campbell", "rotor campbell", "unbalance",
         "static", "threshold", "statespace", "transient"]


@pytest.mark.parametrize("name", NAMES)
def test_round_trip(results, name, tmp_path):
    r = results[name]
    p = r.save(tmp_path / "r.npz")
    back = rd.load_result(p)
    assert_same(r, back)
    assert_same(r, type(r).load(p))
    pd.testing.assert_frame_equal(r.to_frame(), back.to_frame())
    assert repr(back) == repr(r)


def test_refuses_newer_schema_wrong_kind_and_other_files(results, tmp_path):
    p = results["equilibrium"].save(tmp_path / "e.npz")
    with pytest.raises(rd.InputError, match="holds a EquilibriumResult, expected a "
                                            "CampbellResult"):
        rd.CampbellResult.load(p)
    with pytest.raises(rd.InputError, match="expected a StaticResult"):
        rd.load_result(p, kind="StaticResult")
    # the same file with a newer schema version in its metadata
    with np.load(p, allow_pickle=False) as z:
        arrays = {k: z[k] for k in z.files}
    meta = json.loads(arrays[store.META_KEY].tobytes())
    meta["schema"] = f"{store.SCHEMA}/{store.SCHEMA_VERSION + 1}"
    arrays[store.META_KEY] = np.frombuffer(json.dumps(meta).encode(), dtype=np.uint8)
    newer = tmp_path / "newer.npz"
    np.savez(newer, **arrays)
    with pytest.raises(rd.InputError, match="schema version 2 is newer"):
        rd.load_result(newer)
    # a class outside rotordyn.results is never imported from a file
    meta["schema"] = f"{store.SCHEMA}/1"
    meta["value"]["$dataclass"] = "os:system"
    arrays[store.META_KEY] = np.frombuffer(json.dumps(meta).encode(), dtype=np.uint8)
    np.savez(newer, **arrays)
    with pytest.raises(rd.InputError, match="not a rotordyn result class"):
        rd.load_result(newer)
    plain = tmp_path / "plain.npz"
    np.savez(plain, x=np.arange(3))
    with pytest.raises(rd.InputError, match="not a saved rotordyn result"):
        rd.load_result(plain)
    junk = tmp_path / "junk.npz"
    junk.write_text("not a zip")
    with pytest.raises(rd.InputError, match="not a saved rotordyn result"):
        rd.load_result(junk)
    with pytest.raises(rd.InputError, match="no such file"):
        rd.load_result(tmp_path / "missing.npz")
    with pytest.raises(rd.InputError, match="expected a rotordyn result"):
        store.save_result({"a": 1}, tmp_path / "x.npz")
    assert zipfile.is_zipfile(p)  # an ordinary .npz: numpy reads its arrays directly


def test_point_message_with_none_round_trips(tmp_path):
    """``point_message`` is an object array of str (a failed point) and None (a converged
    one): saved and loaded as it was (the store refused object arrays that were not all
    text, so every Campbell and unbalance result failed to save once None marked the
    converged points)."""
    from rotordyn.results.campbell import CampbellResult
    from rotordyn.results.store import load_result, save_result

    c = CampbellResult(np.array([1.0, 2.0]), np.full((2, 1), 1j),
                       np.zeros((2, 1), dtype=np.int64), point_status=np.array(["ok", "error"]),
                       point_message=np.array([None, "ConvergenceError: x"], dtype=object))
    back = load_result(save_result(c, tmp_path / "c.npz"))
    assert back.point_message.dtype == object
    assert list(back.point_message) == [None, "ConvergenceError: x"]
