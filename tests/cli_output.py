"""The lines of a CLI run's stderr that are not its progress report: on a loaded machine a
command that takes over 3 s writes "rotordyn X: running (3 s so far)…" and "… done/stopped
after 3.6 s" around its one error line (rotordyn._common.progress)."""

import re

_PROGRESS = re.compile(r"rotordyn [\w-]+: (running \(|done after |stopped after )")


def error_lines(stderr: str) -> list[str]:
    """stderr's lines without the progress lines."""
    return [ln for ln in stderr.strip().splitlines() if not _PROGRESS.match(ln)]
