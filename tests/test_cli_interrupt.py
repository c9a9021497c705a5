"""Ctrl-C is never raised inside the import machinery (a CI run of the sweep's Ctrl-C test
exited 1 with "internal error: AssertionError" after the KeyboardInterrupt was swallowed in
importlib's module-lock callback and left the lock broken), is not deferred for ever (an
import blocked on another thread's lock), and is not lost at the end of the work."""

from __future__ import annotations

import signal
import threading
import time
import types

import pytest

from rotordyn._common import interrupt

IMPORTLIB = "<frozen importlib._bootstrap>"


def _frame(filename: str):
    return types.SimpleNamespace(f_code=types.SimpleNamespace(co_filename=filename))


def test_an_interrupt_inside_the_import_machinery_is_delivered_after_it():
    with interrupt.safe_interrupts() as guard:
        h = signal.getsignal(signal.SIGINT)
        assert h == guard.handler
        t0 = time.monotonic()
        # what Python does when SIGINT lands in <frozen importlib._bootstrap>: no exception there
        assert h(signal.SIGINT, _frame(IMPORTLIB)) is None
        assert guard.pending
        # ... but the signal comes again RETRY_S later, outside, as a KeyboardInterrupt
        with pytest.raises(KeyboardInterrupt):
            time.sleep(5.0)
        assert time.monotonic() - t0 < 2.0
        assert not guard.pending
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_an_interrupt_elsewhere_is_raised_at_once():
    with interrupt.safe_interrupts() as guard:
        with pytest.raises(KeyboardInterrupt):
            guard.handler(signal.SIGINT, _frame(__file__))
        with pytest.raises(KeyboardInterrupt):
            guard.handler(signal.SIGINT, None)
        assert not guard.pending


def test_a_deferral_ends_after_max_defer_s():
    """An import blocked on another thread's lock keeps the main thread in the machinery: the
    interrupt is raised there after MAX_DEFER_S instead of being deferred for ever."""
    with interrupt.safe_interrupts() as guard:
        guard.handler(signal.SIGINT, _frame(IMPORTLIB))
        guard.timer.cancel()
        guard.since -= interrupt.MAX_DEFER_S  # as if the import had held it that long
        with pytest.raises(KeyboardInterrupt):
            guard.handler(signal.SIGINT, _frame(IMPORTLIB))
        assert not guard.pending


def test_a_deferral_pending_at_the_end_is_reported_not_raised_later():
    with interrupt.safe_interrupts() as guard:
        guard.handler(signal.SIGINT, _frame(IMPORTLIB))
    assert guard.pending
    time.sleep(5 * interrupt.RETRY_S)  # the re-send was cancelled: nothing raised here


def test_a_resend_while_sigint_is_ignored_waits_for_it():
    """The sweep ignores SIGINT while its worker processes start: a re-send landing then is
    sent again after, not lost."""
    with interrupt.safe_interrupts() as guard:
        guard.handler(signal.SIGINT, _frame(IMPORTLIB))
        old = signal.signal(signal.SIGINT, signal.SIG_IGN)
        time.sleep(10 * interrupt.RETRY_S)
        assert guard.pending
        signal.signal(signal.SIGINT, old)
        with pytest.raises(KeyboardInterrupt):
            time.sleep(5.0)


def test_a_handler_the_caller_installed_is_left_alone():
    def mine(signum, frame):
        pass

    old = signal.signal(signal.SIGINT, mine)
    try:
        with interrupt.safe_interrupts():
            assert signal.getsignal(signal.SIGINT) is mine
    finally:
        signal.signal(signal.SIGINT, old)
    out = []

    def other_thread():
        with interrupt.safe_interrupts():  # signal.signal would raise off the main thread
            out.append(signal.getsignal(signal.SIGINT))

    th = threading.Thread(target=other_thread)
    th.start()
    th.join()
    assert out == [signal.default_int_handler]


def test_the_cli_runs_under_the_safe_handler_and_reports_a_late_interrupt(monkeypatch, capsys):
    from rotordyn import cli

    seen = []

    def work(argv):
        h = signal.getsignal(signal.SIGINT)
        seen.append(h)
        if argv == ["late"]:  # Ctrl-C inside an import as the work ends
            h(signal.SIGINT, _frame(IMPORTLIB))
        return 0

    monkeypatch.setattr(cli, "_main", work)
    assert cli.main(["info"]) == 0
    assert getattr(seen[0], "__func__", None) is interrupt.Guard.handler
    assert cli.main(["late"]) == 130
    assert capsys.readouterr().err.strip() == "rotordyn: interrupted"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
