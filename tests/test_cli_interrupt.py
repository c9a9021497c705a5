"""Ctrl-C is never raised inside the import machinery (a CI run of the sweep's Ctrl-C test
exited 1 with "internal error: AssertionError" after the KeyboardInterrupt was swallowed in
importlib's module-lock callback and left the lock broken)."""

from __future__ import annotations

import signal
import threading
import time
import types

import pytest

from rotordyn._common import interrupt


def _frame(filename: str):
    return types.SimpleNamespace(f_code=types.SimpleNamespace(co_filename=filename))


def test_an_interrupt_inside_the_import_machinery_is_delivered_after_it():
    with interrupt.safe_interrupts():
        h = signal.getsignal(signal.SIGINT)
        assert h is interrupt.handler
        t0 = time.monotonic()
        # what Python does when SIGINT lands in <frozen importlib._bootstrap>: no exception there
        assert h(signal.SIGINT, _frame("<frozen importlib._bootstrap>")) is None
        # ... but the signal comes again RETRY_S later, outside, as a KeyboardInterrupt
        with pytest.raises(KeyboardInterrupt):
            time.sleep(5.0)
        assert time.monotonic() - t0 < 2.0
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_an_interrupt_elsewhere_is_raised_at_once():
    with interrupt.safe_interrupts():
        h = signal.getsignal(signal.SIGINT)
        with pytest.raises(KeyboardInterrupt):
            h(signal.SIGINT, _frame(__file__))
        with pytest.raises(KeyboardInterrupt):
            h(signal.SIGINT, None)


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


def test_the_cli_runs_under_the_safe_handler(monkeypatch):
    from rotordyn import cli

    seen = []
    monkeypatch.setattr(cli, "_main", lambda argv: seen.append(signal.getsignal(
        signal.SIGINT)) or 0)
    assert cli.main(["info"]) == 0
    assert seen == [interrupt.handler]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
