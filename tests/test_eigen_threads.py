"""Eigen's own threads in the core: one process-wide setting (docs/performance.md, "Threads").

Default 1 at import; ``set_eigen_threads(None)`` gives Eigen's default (OpenMP's count, 0 in
the core); bad values are InputErrors naming ``n``; a change made while an analysis runs is
applied only when the last running one returns (no core call sees the value change under it).
"""

import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn._common.threads import limited_blas
from rotordyn.errors import InputError


def test_default_set_and_bad_input():
    assert rd.get_eigen_threads() == 1 and _core.eigen_threads() == 1
    try:
        rd.set_eigen_threads(None)
        assert rd.get_eigen_threads() is None and _core.eigen_threads() == 0
        rd.set_eigen_threads(2)
        assert rd.get_eigen_threads() == 2 and _core.eigen_threads() == 2
        for bad in (0, -1, 1.5, True, "2"):
            with pytest.raises(InputError, match="^n: "):
                rd.set_eigen_threads(bad)
        with pytest.raises(InputError, match="eigen threads"):
            _core.set_eigen_threads(-1)
    finally:
        rd.set_eigen_threads(1)
    assert _core.eigen_threads() == 1


def test_a_change_during_an_analysis_waits_for_its_end():
    seen = []

    @limited_blas
    def analysis():
        rd.set_eigen_threads(3)
        seen.append((_core.eigen_threads(), rd.get_eigen_threads()))

    try:
        analysis()
        assert seen == [(1, 3)]  # inside: unchanged in the core, the pending value reported
        assert _core.eigen_threads() == 3
    finally:
        rd.set_eigen_threads(1)
