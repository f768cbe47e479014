"""Ctrl+C in a script reaches the script, not a Qt slot that would drop it.

Left to Python, SIGINT raises at the next bytecode, and while the pump runs
Qt that is as often inside a slot (a session reading the device's bytes):
PySide prints the KeyboardInterrupt and drops it, and a `stepdeck run` job
went on to its end with the machine moving after the operator's Ctrl+C.
"""

from __future__ import annotations

import signal

import pytest
from PySide6.QtCore import QTimer

from app.scripting.pump import CTRL_C, RealtimePump


def test_ctrl_c_during_a_slot_is_raised_by_the_pump_after_the_slot_has_finished(
    qapp: object,
) -> None:
    pump = RealtimePump()
    finished: list[str] = []

    def slot() -> None:
        signal.raise_signal(signal.SIGINT)  # Ctrl+C lands while Qt runs this slot
        finished.append("slot ran to its end")

    try:
        QTimer.singleShot(0, slot)
        with pytest.raises(KeyboardInterrupt):
            for _ in range(200):  # the wake-up timer keeps each step short
                pump.step()
        assert finished == ["slot ran to its end"]  # not cut short inside Qt, where it is lost
        assert not CTRL_C.pending
    finally:
        pump.close()


def test_ctrl_c_outside_the_pump_raises_at_once_and_python_has_it_back_after_close(
    qapp: object,
) -> None:
    before = signal.getsignal(signal.SIGINT)
    pump = RealtimePump()
    try:
        with pytest.raises(KeyboardInterrupt):
            signal.raise_signal(signal.SIGINT)  # the script's own code: as Python would
    finally:
        pump.close()
    assert signal.getsignal(signal.SIGINT) is before
