"""Whether an ``ALARM:n`` the board sends is news: said once while nothing changes.

A board in alarm repeats it (GRBL on each reset while locked, a switch that
bounces, a reply line repeated on a noisy wire); a status-bar message and a
job pause for each copy drown the one thing the operator must read, and a
job told twice would pause twice.  An alarm is news when the board was not
in alarm, or in another one; it is over once a status report shows the board
out of its alarm (unlocked, homed).
"""

from __future__ import annotations


class AlarmNotice:
    """The alarm the board is known to be in, if any (GUI thread)."""

    def __init__(self) -> None:
        #: The code of the alarm said last, while the board has not left it.
        self.code: int | None = None

    def heard(self, code: int) -> bool:
        """``ALARM:<code>`` read: True when it is to be said (not the one said already)."""
        if self.code == code:
            return False
        self.code = code
        return True

    def reported(self, state: str) -> None:
        """A status report's state: out of ``Alarm``, the alarm said is over."""
        if state != "Alarm":
            self.code = None
