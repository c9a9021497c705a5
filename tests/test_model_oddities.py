"""Guards issue 18's model-file oddities, each on the compressor models (not the paper rig):

* unit-slip warnings (viscosity in mPa·s typed as Pa·s, clearance in mm) were given only for
  plain and active journal bearings: every fluid-film element with a clearance and a viscosity
  (tilting-pad, fixed-geometry, squeeze-film) now warns, once, naming the key's path;
* ``tilt_stiffness_nm_per_rad`` ("nm" reads as nanometres against the ``_n_per_m``
  vocabulary) is ``tilt_stiffness_n_m_per_rad``; the old key is still read, with a
  deprecation warning naming its path, and written under the new name;
* ``reduction.n_modes`` was silently ignored unless ``method = "craig-bampton"``: refused;
* a disk given by its geometry without a ``station`` raised a KeyError (an internal error on
  the command line), and a bad geometry value was named ``disk.width_m``, not by its path.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import pytest

import rotordyn as rd
from rotordyn.errors import RotordynDeprecationWarning, UnitWarning

MODELS = Path(__file__).parent / "data" / "models"
TP = (MODELS / "compressor_tilting_pad.toml").read_text()
LIN = (MODELS / "compressor_linear.toml").read_text()
PLAIN = (MODELS / "compressor_plain.toml").read_text()


def _load(text):
    return rd.System.from_toml(text, is_text=True)


def _as_type(kind: str, extra: str = "") -> str:
    """The tilting-pad compressor with its first bearing turned into ``kind``."""
    i = TP.index("[[bearing]]")
    j = TP.index("[[bearing]]", i + 1)
    first = {"fixed_geometry": 'type = "fixed_geometry"\nname = "NDE bearing"\nstation = 1\n'
                               'diameter_m = 0.1\nlength_m = 0.05\nclearance_m = 1.0e-4\n'
                               'viscosity_pa_s = VISC\nkind = "elliptical"\npreload = 0.5\n',
             "squeeze_film_damper": 'type = "squeeze_film_damper"\nname = "NDE damper"\n'
                                    'station = 1\ndiameter_m = 0.1\nlength_m = 0.02\n'
                                    'clearance_m = 1.5e-4\nviscosity_pa_s = VISC\n'
                                    'centring_spring_n_per_m = 5.0e7\n'}[kind]
    return TP[:i] + "[[bearing]]\n" + first + extra + "\n" + TP[j:]


@pytest.mark.parametrize("kind", ["tilting_pad", "fixed_geometry", "squeeze_film_damper"])
def test_unit_slip_warnings_on_every_film_element(kind):
    text = (TP.replace("viscosity_pa_s = 0.018", "viscosity_pa_s = VISC", 1)
            if kind == "tilting_pad" else _as_type(kind))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _load(text.replace("VISC", "0.018"))  # a real oil: silent
    with pytest.warns(UnitWarning) as rec:
        _load(text.replace("VISC", "18.0"))  # 18 mPa·s typed as Pa·s
    msgs = [str(w.message) for w in rec if issubclass(w.category, UnitWarning)]
    assert len(msgs) == 1 and msgs[0].startswith("bearing[0].viscosity_pa_s = 18 Pa·s"), msgs
    with pytest.warns(UnitWarning, match=r"bearing\[0\]\.clearance_m = 1e-07 m is 2e-06 of "
                                         r"the journal radius"):
        i = text.index("[[bearing]]")
        j = text.index("[[bearing]]", i + 1)  # the first bearing's table only
        first = re.sub(r"^clearance_m = .*$", "clearance_m = 1e-7", text[i:j], count=1,
                       flags=re.MULTILINE)
        _load((text[:i] + first + text[j:]).replace("VISC", "0.018"))


def test_gravity_in_mm_per_s2_warns():
    with pytest.warns(UnitWarning, match=r"gravity_m_s2 = 9810 m/s² .* mm/s²"):
        _load("gravity_m_s2 = 9810.0\n" + LIN)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _load("gravity_m_s2 = 9.81\n" + LIN)
        _load("gravity_m_s2 = 0.0\n" + LIN)  # weightless: deliberate, silent


def test_journal_bearing_warns_once():
    with pytest.warns(UnitWarning) as rec:
        _load(PLAIN.replace("viscosity_pa_s = 0.018", "viscosity_pa_s = 18.0", 1))
    msgs = [str(w.message) for w in rec]
    assert len(msgs) == 1 and msgs[0].startswith("bearing[0].viscosity_pa_s"), msgs


def test_tilt_stiffness_key_renamed_old_one_still_read():
    new = _load(TP.replace('load = "between"', 'load = "between"\n'
                                               'tilt_stiffness_n_m_per_rad = 25.0', 1))
    with pytest.warns(RotordynDeprecationWarning,
                      match=r"bearing\[0\]\.tilt_stiffness_nm_per_rad is renamed "
                            r"tilt_stiffness_n_m_per_rad"):
        old = _load(TP.replace('load = "between"', 'load = "between"\n'
                                                   'tilt_stiffness_nm_per_rad = 25.0', 1))
    assert old == new and old.bearings[0].tilt_stiffness_n_m_per_rad == 25.0
    text = old.to_toml()
    assert "tilt_stiffness_n_m_per_rad = 25.0" in text and "_nm_per_rad" not in text
    with pytest.raises(rd.InputError, match=r"bearing\[0\]\.tilt_stiffness_nm_per_rad: the old "
                                            "name"):
        _load(TP.replace('load = "between"', 'load = "between"\ntilt_stiffness_nm_per_rad = 1.0'
                                             '\ntilt_stiffness_n_m_per_rad = 1.0', 1))
    with pytest.warns(RotordynDeprecationWarning):  # the Python keyword too
        b = rd.bearings.TiltingPadBearing(station=1, diameter_m=0.1, length_m=0.05,
                                          clearance_m=1e-4, viscosity_pa_s=0.02,
                                          tilt_stiffness_nm_per_rad=3.0)
    assert b.tilt_stiffness_n_m_per_rad == 3.0 and b.tilt_stiffness_nm_per_rad is None


def test_n_modes_without_craig_bampton_is_refused():
    red = re.search(r"\[reduction\]\n", LIN).end()
    with pytest.raises(rd.InputError, match=r"^reduction\.n_modes: only method "
                                            r"\"craig-bampton\".*method 'guyan'"):
        _load(LIN[:red] + "n_modes = 4\n" + LIN[red:])
    cb = _load(LIN[:red] + "n_modes = 4\n" + LIN[red:].replace('"guyan"', '"craig-bampton"', 1))
    assert cb.reduction.n_modes == 4
    with pytest.raises(rd.InputError, match="reduction.n_modes"):
        _load(LIN[:red] + "n_modes = 2\n" + LIN[red:].replace('"guyan"', '"irs"', 1))


def test_disk_geometry_errors_are_named_by_path():
    inertias = "station = 2\nmass_kg = 30.0\nip_kg_m2 = 0.60\nid_kg_m2 = 0.32"
    assert inertias in LIN
    geo = 'outer_diameter_m = 0.4\nwidth_m = 0.05\nmaterial = "steel"'
    with pytest.raises(rd.InputError, match=r"^disk\[0\]\.station: missing"):
        _load(LIN.replace(inertias, geo, 1))
    with pytest.raises(rd.InputError, match=r"^disk\[0\]\.width_m: expected a number"):
        _load(LIN.replace(inertias, "station = 2\n" + geo.replace("0.05", '"5"'), 1))
    with pytest.raises(rd.InputError, match=r"^disk\[0\]: the inertias come as all of"):
        _load(LIN.replace(inertias, "station = 2\nmass_kg = 30.0\n" + geo, 1))
