"""The report of a model (the main job of ``make run``): the text report with comparison marks
from stated tolerances (:mod:`.text`) and the self-contained HTML report with its checks and
figures (:mod:`.html`)."""

from rotordyn.report.html import write_html
from rotordyn.report.text import mark, run

__all__ = ["mark", "run", "write_html"]
