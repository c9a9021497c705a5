"""Every test starts without figures left open by the tests before it: matplotlib warns past
20 open figures, and with warnings as errors the test that happened to open the 21st failed
depending on which tests ran before it in the same worker."""

import sys

import pytest


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")
