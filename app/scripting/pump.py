"""How a script's blocking calls let the station's Qt objects run: the script's thread pumps.

Sessions, links and the job runner are QObjects fed by Qt signals and
timers.  Rather than run a Qt event loop in a second thread (QObjects belong
to the thread that made them, so every call would have to be marshalled
across, and an exception raised in a slot is printed and lost), the script's
own thread runs the loop *while it waits*: each blocking call sends its
intent, then pumps events until the device's reports say it is done.  Ctrl+C
reaches the script as an ordinary KeyboardInterrupt, raised between two pumps
(:class:`CtrlC`): left to Python, it would as often be raised inside a slot
the pump is running, where Qt prints it and drops it, and the job would go on
moving the machine.  Every user callback runs in plain Python, never inside a
Qt slot.

Two pumps: :class:`RealtimePump` for real links and the real-time emulator
(it sleeps in Qt's dispatcher until an event or a 5 ms wake-up), and
:class:`SimulatedPump` for the emulator on a manual clock, stepped as the
test harness steps it (time runs as fast as the computer, exactly reproducibly).
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable
from types import FrameType
from typing import Protocol

from PySide6.QtCore import QCoreApplication, QEventLoop, QTimer

from app.main_thread_gc import MainThreadCollector
from app.station import Station
from protocol.clock import ManualClock

#: The longest a blocking wait sleeps in Qt's dispatcher before looking again (and before a
#: pending Ctrl+C is raised).
WAKE_MS = 5
#: Emulated seconds per step of the simulated pump (the harness's step).
SIM_STEP_S = 0.005

_APP: list[QCoreApplication] = []


def ensure_qt() -> None:
    """A QCoreApplication for the station's timers and queued signals (no display needed)."""
    if QCoreApplication.instance() is None:
        _APP.append(QCoreApplication([]))
        # Cycles are freed in the script's thread, between pumps, not in a transport thread
        # (app.main_thread_gc says why).
        collector = MainThreadCollector(_APP[0])
        collector.start()


class CtrlC:
    """Ctrl+C while the pump runs Qt is held, and raised by the pump once Qt has returned.

    Outside the pump (the script's own code) it raises at once, as Python would.
    Installed by the first pump, put back by the last one closed; only the main
    thread can take signals, so a pump elsewhere leaves Python's handling alone.
    """

    def __init__(self) -> None:
        self.pumping = 0
        self.pending = False
        self._users = 0
        self._previous: object = None

    def install(self) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        if self._users == 0:
            self._previous = signal.signal(signal.SIGINT, self._noted)
        self._users += 1

    def uninstall(self) -> None:
        if self._users == 0:
            return
        self._users -= 1
        if self._users == 0:
            signal.signal(signal.SIGINT, self._previous)  # type: ignore[arg-type]
            self._previous = None

    def _noted(self, signum: int, frame: FrameType | None) -> None:
        if self.pumping:
            self.pending = True  # raised by the pump, in plain Python
            return
        raise KeyboardInterrupt

    def run(self, events: Callable[[], object]) -> None:
        """``events()`` (Qt dispatching), then a Ctrl+C that came meanwhile."""
        self.pumping += 1
        try:
            events()
        finally:
            self.pumping -= 1
        if self.pending and not self.pumping:
            self.pending = False
            raise KeyboardInterrupt


#: The one Ctrl+C guard of the process (a signal has one handler).
CTRL_C = CtrlC()


class Pump(Protocol):
    def step(self, *, block: bool = True) -> None:
        """Let the station run a little: deliver what arrived, fire due timers."""

    def close(self) -> None:
        """The machine is closed: nothing is waited for any more."""


class RealtimePump:
    """Real time: Qt's own timers tick the session; a wait sleeps until something happens."""

    def __init__(self) -> None:
        self._wake = QTimer()
        self._wake.setInterval(WAKE_MS)
        self._wake.start()
        self._closed = False
        CTRL_C.install()

    def step(self, *, block: bool = True) -> None:
        flag = (
            QEventLoop.ProcessEventsFlag.WaitForMoreEvents
            if block
            else QEventLoop.ProcessEventsFlag.AllEvents
        )
        CTRL_C.run(lambda: QCoreApplication.processEvents(flag))

    def close(self) -> None:
        self._wake.stop()
        if not self._closed:
            self._closed = True
            CTRL_C.uninstall()


class SimulatedPump:
    """A manual clock: each step advances it, ticks the session, runs the emulator to now."""

    def __init__(self, station: Station, clock: ManualClock) -> None:
        self.station = station
        self.clock = clock
        self._next_tick = clock.now()
        self._closed = False
        CTRL_C.install()

    def step(self, *, block: bool = True) -> None:
        self.clock.advance(SIM_STEP_S)
        CTRL_C.run(self._events)

    def _events(self) -> None:
        session = self.station.session
        if session is not None and self.clock.now() >= self._next_tick - 1e-9:
            self._next_tick = self.clock.now() + session.period_ms / 1000
            session.tick()
        self.station.poll()
        loopback = self.station.loopback
        if loopback is not None:
            loopback.pump()
        QCoreApplication.processEvents()

    def close(self) -> None:
        """Nothing runs on its own on a manual clock; Ctrl+C is Python's again."""
        if not self._closed:
            self._closed = True
            CTRL_C.uninstall()
