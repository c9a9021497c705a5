"""The report's API unbalance on an overhung rotor (QA pass qa21).

API 617 (8th ed., 2014) and API 684 (2nd ed., 2005) §2.8: U = 6350 W/N g·mm, with W the
journal static weight load, "or for bending modes where the maximum deflection occurs at the
shaft ends, the overhung weight load (that is the weight outboard of the bearing)". The
report took the whole rotor's mass for every mode: on a 275 kg overhung fan whose first forward
mode is largest at the fan, U came out 971 g·mm instead of 733 g·mm (the 208 kg outboard of
the inboard bearing), 33 % too large.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import rotordyn as rd
from rotordyn.report.criteria import api_unbalance

MODELS = Path(__file__).parent / "data" / "models"


def test_overhung_mode_takes_the_overhung_weight():
    s = rd.System.from_toml(MODELS / "fan_overhung_table.toml")
    n_mc = 30.0
    station, u_kgm, why = api_unbalance(s, n_mc, n_mc, 0.0, None)
    assert station == 3  # the fan, outboard of the inboard bearing (station 2)
    # by hand: the 180 kg fan and the 0.45 m of Ø 0.1 m shaft beyond station 2
    overhung = 180.0 + 7850.0 * math.pi / 4 * 0.1**2 * 0.45
    assert overhung == pytest.approx(207.745, abs=1e-3)
    assert u_kgm == pytest.approx(6350.0 * overhung / (60 * n_mc) * 1e-6, rel=1e-9)
    assert "overhung" in why


def test_mode_between_the_bearings_keeps_the_rotor_weight():
    s = rd.System.from_toml(MODELS / "compressor_table.toml")
    n_mc = 150.0
    station, u_kgm, why = api_unbalance(s, n_mc, n_mc, 0.0, None)
    bearings = [b.station for b in s.bearings]
    assert min(bearings) < station < max(bearings)
    assert u_kgm == pytest.approx(6350.0 * s.mass_kg / (60 * n_mc) * 1e-6, rel=1e-12)
