"""GRBL's lock after a hard or soft limit: silent by design until a soft reset.

GRBL 1.1h treats ``ALARM:1`` (hard limit) and ``ALARM:2`` (soft limit) as a
critical event (protocol.c, ``EXEC_CRITICAL_EVENT``): it says ``[MSG:Reset to
continue]`` and then answers nothing at all, not even a status report, and loses
every byte but 0x18, until it gets that reset; after its banner it is still in
alarm (``[MSG:'$H'|'$X' to unlock]``).  Read as any other silence, the board
would be shown "lost", and an Unlock's ``$X`` would go nowhere.  So while the
board is in that lock its silence is the alarm's (the link shows "in alarm:
reset to continue"), and Unlock and Home reset it first: the feeder holds their
line until the reset's banner.  A reset moves nothing, nor does ``$X``.

Any reply but those two ends the lock (a banner, a status report): a firmware
that says ``ALARM:1`` without locking is judged by its own answers.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from app.machine import LinkState
from protocol.gcode.codec import AlarmReply, Feedback

if TYPE_CHECKING:
    from app.machines.gcode.ports import GcodeCore

#: The alarms after which GRBL waits for a reset (protocol.c): hard and soft limits.
CRITICAL_ALARMS = frozenset({1, 2})
#: GRBL's words after them (report.c, ``MESSAGE_CRITICAL_EVENT``).
RESET_TO_CONTINUE = "[MSG:Reset to continue]"


def locks(reply: object) -> bool:
    """Whether ``reply`` says the board is now in GRBL's critical-event lock."""
    if isinstance(reply, AlarmReply):
        return reply.code in CRITICAL_ALARMS
    return isinstance(reply, Feedback) and reply.text == RESET_TO_CONTINUE


def waiting_text() -> str:
    """The link's detail while the board waits for its reset (translated)."""
    return QCoreApplication.translate("GcodeSession", "in alarm: reset to continue")


class LimitLock:
    """Whether the board waits in GRBL's lock for a reset (GUI thread)."""

    def __init__(self, session: GcodeCore) -> None:
        self._session = session
        #: ALARM:1/2 or "Reset to continue" came, and no reply since.
        self.waiting = False

    def heard(self, reply: object) -> None:
        """A reply from the board: the lock begins with its words and ends with any other."""
        if locks(reply):
            if not self.waiting:
                self.waiting = True
                self._show(waiting_text())
                self._stopped()
        elif self.waiting:
            self.waiting = False
            self._show(self._session.link.describe())

    def silence_is_expected(self) -> bool:
        """The board's silence is the lock's, not a lost link (asked each tick)."""
        return self.waiting

    def reset(self) -> None:
        """0x18 through the session's own reset: the board restarts, still in alarm."""
        self._session.soft_reset()

    def unlock(self) -> bool:
        """``$X`` (nothing moves), after the reset a locked board needs first."""
        self.before_clearing()
        return self._session.send_line("$X", "intent")

    def before_clearing(self) -> None:
        """Unlock or Home: a locked board takes neither before its reset, so it is reset
        first; the feeder holds the line that follows until the reset's banner."""
        if self.waiting:
            self.reset()

    def _stopped(self) -> None:
        """GRBL stopped its steppers as it raised the alarm (mc_reset), and no report will
        say so before the reset: the axes are shown in alarm, not as the last report left
        them (running, say)."""
        session = self._session
        for axis in range(session.axis_count):
            session.model.update_axis(axis, status_text="alarm", moving=False)

    def _show(self, detail: str) -> None:
        model = self._session.model
        if model.link_state in (LinkState.CONNECTED, LinkState.STALE):
            model.set_link_state(LinkState.CONNECTED, detail)
