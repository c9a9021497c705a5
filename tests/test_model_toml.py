"""Model description: TOML round trip, unknown keys rejected, and error paths that name the
field (issue 2 acceptance: negative length, a disk at a station that does not exist, an
unknown TOML key, a non-positive density)."""

import dataclasses

import numpy as np
import pytest
import scipy.sparse as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rotordyn as rd


@pytest.mark.parametrize("name", ["paper-rig", "friswell-5.9.1"])
def test_round_trip_is_lossless(name, tmp_path):
    s = rd.models.load(name)
    path = tmp_path / "m.toml"
    s.to_toml(path)
    assert rd.System.from_toml(path) == s
    assert rd.System.from_toml(s.to_toml(), is_text=True).to_toml() == s.to_toml()


MINIMAL = """
schema = "rotordyn/model/1"
[material.steel]
density_kg_m3 = 7850.0
young_pa = 2.1e11
[rotor]
[[rotor.section]]
length_m = 0.5
outer_diameter_m = 0.03
[[rotor.section]]
length_m = 0.5
outer_diameter_m = 0.03
[[support]]
station = 0
[[support]]
station = 2
"""


def test_minimal_model_reads():
    s = rd.System.from_toml(MINIMAL, is_text=True)
    assert s.rotor.n_stations == 3
    assert s.mass_kg == pytest.approx(7850 * np.pi / 4 * 0.03**2 * 1.0)


@pytest.mark.parametrize(
    ("text", "field"),
    [
        (MINIMAL.replace("length_m = 0.5", "length_m = -0.5", 1), "rotor.section[0].length_m"),
        (MINIMAL.replace("density_kg_m3 = 7850.0", "density_kg_m3 = 0.0"),
         "material.steel.density_kg_m3"),
        (MINIMAL + "[[disk]]\nstation = 7\nmass_kg = 1.0\nip_kg_m2 = 0.0\nid_kg_m2 = 0.0\n",
         "disk[0].station"),
        (MINIMAL.replace("young_pa = 2.1e11", "young_pa = 2.1e11\nyoungs = 1.0"),
         "material.steel.youngs"),
        (MINIMAL.replace("outer_diameter_m = 0.03", "outer_diameter_m = 0.03\ncolor = 'red'", 1),
         "rotor.section[0].color"),
        (MINIMAL + "[reduction]\nmethod = 'magic'\n", "reduction.method"),
        (MINIMAL.replace('schema = "rotordyn/model/1"', 'schema = "other"'), "schema"),
        (MINIMAL.replace("[[support]]\nstation = 2", "[[support]]\nstation = 2\ntype = 'rigid'\n"
                         "kxx_n_per_m = 5.0"), "support[1].kxx_n_per_m"),
    ],
)
def test_bad_input_names_the_field(text, field):
    with pytest.raises(rd.InputError, match=field.replace("[", r"\[").replace("]", r"\]")):
        rd.System.from_toml(text, is_text=True)


def test_python_api_validates_too():
    with pytest.raises(rd.InputError, match="length_m"):
        rd.Rotor((rd.ShaftSection(-1.0, 0.02),))
    with pytest.raises(rd.InputError, match=r"inner_diameter_m.*\[0, outer_diameter_m"):
        rd.Rotor((rd.ShaftSection(1.0, 0.02, inner_diameter_m=0.03),))
    with pytest.raises(rd.InputError, match="density_kg_m3"):
        rd.Material("x", -1.0, 2e11)
    with pytest.raises(rd.InputError, match="material"):
        rd.System(rotor=rd.Rotor((rd.ShaftSection(1.0, 0.02, material="unobtainium"),)))
    with pytest.raises(rd.InputError, match="nan"):
        rd.Rotor((rd.ShaftSection(float("nan"), 0.02),))


def test_rigid_master_is_rejected():
    s = rd.System.from_toml(MINIMAL, is_text=True)
    with pytest.raises(rd.InputError, match="master_stations"):
        dataclasses.replace(s, reduction=rd.Reduction(master_stations=(0, 1)))


def test_free_free_guyan_needs_enough_masters():
    rotor = rd.Rotor((rd.ShaftSection(1.0, 0.02, n_elements=4),))
    s = rd.System(rotor=rotor, reduction=rd.Reduction(master_stations=(0,)))
    with pytest.raises(rd.InputError, match="singular"):
        rd.modes(s, reduction="guyan", without_bearings=True)


def test_sparse_matrices_have_rotordynamic_structure():
    s = rd.models.friswell_5_9_1()
    M, K, G = s.M(), s.K(), s.G()
    assert sp.issparse(M) and M.shape == (28, 28)
    assert abs(M - M.T).max() < 1e-12 * abs(M).max()
    assert abs(K - K.T).max() < 1e-9 * abs(K).max()
    assert abs(G + G.T).max() < 1e-15 + 1e-12 * abs(G).max()
    assert np.linalg.eigvalsh(M.toarray()).min() > 0


@settings(max_examples=40, deadline=None)
@given(
    length=st.floats(0.01, 1.0),
    do=st.floats(0.005, 0.3),
    ratio=st.floats(0.0, 0.9),
)
def test_element_matrices_properties(length, do, ratio):
    """Any circular section: M symmetric positive definite, K symmetric positive semidefinite
    with exactly the 4 rigid-body modes of a free element, G skew-symmetric."""
    sec = rd.ShaftSection(length, do, inner_diameter_m=ratio * do)
    M, K, G = sec.M(), sec.K(), sec.G()
    np.testing.assert_allclose(M, M.T, atol=1e-14 * np.abs(M).max())
    np.testing.assert_allclose(G, -G.T, atol=1e-14 * np.abs(G).max())
    np.testing.assert_allclose(K, K.T, rtol=1e-12, atol=1e-12 * np.abs(K).max())
    assert np.linalg.eigvalsh(M).min() > 0
    ev = np.linalg.eigvalsh(K)
    assert np.sum(np.abs(ev) < 1e-9 * ev.max()) == 4
