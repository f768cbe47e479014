"""How a script's blocking calls let the station's Qt objects run: the script's thread pumps.

Sessions, links and the job runner are QObjects fed by Qt signals and
timers.  Rather than run a Qt event loop in a second thread (QObjects belong
to the thread that made them, so every call would have to be marshalled
across, and an exception raised in a slot is printed and lost), the script's
own thread runs the loop *while it waits*: each blocking call sends its
intent, then pumps events until the device's reports say it is done.  Ctrl+C
lands between two pumps as an ordinary KeyboardInterrupt, and every user
callback runs in plain Python, never inside a Qt slot.

Two pumps: :class:`RealtimePump` for real links and the real-time emulator
(it sleeps in Qt's dispatcher until an event or a 5 ms wake-up), and
:class:`SimulatedPump` for the emulator on a manual clock, stepped as the
test harness steps it (time runs as fast as the computer, exactly reproducibly).
"""

from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QCoreApplication, QEventLoop, QTimer

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

    def step(self, *, block: bool = True) -> None:
        flag = (
            QEventLoop.ProcessEventsFlag.WaitForMoreEvents
            if block
            else QEventLoop.ProcessEventsFlag.AllEvents
        )
        QCoreApplication.processEvents(flag)

    def close(self) -> None:
        self._wake.stop()


class SimulatedPump:
    """A manual clock: each step advances it, ticks the session, runs the emulator to now."""

    def __init__(self, station: Station, clock: ManualClock) -> None:
        self.station = station
        self.clock = clock
        self._next_tick = clock.now()

    def step(self, *, block: bool = True) -> None:
        self.clock.advance(SIM_STEP_S)
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
        """Nothing runs on its own on a manual clock."""
