"""Every public analysis of the top-level API runs as one public call (``limited_blas``: the
BLAS thread limit and the outermost-call epoch that keeps a call from starting at an earlier
call's warm state). A helper inserted between the decorator and ``statespace`` had taken it
(review, 2026-12-06): ``statespace`` then ran unlimited and its inner calls opened epochs of
their own."""

import inspect

import rotordyn as rd


def test_every_public_analysis_is_one_public_call():
    funcs = {k: getattr(rd, k) for k in rd.__all__}
    analyses = {k: f for k, f in funcs.items()
                if inspect.isfunction(f) and f.__module__.startswith("rotordyn.analysis")}
    assert {"statespace", "equilibrium", "stability", "transient", "periodic_orbit"} <= \
        set(analyses)
    assert [k for k, f in analyses.items() if not hasattr(f, "__wrapped__")] == []
