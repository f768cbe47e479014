"""Feed and rapid overrides on a GRBL board: the bytes that reach a percentage, checked by ``Ov:``.

GRBL 1.1 has no "feed 50 %" command, only real-time bytes that step the
override (:mod:`protocol.gcode.overrides`), and they are flags: several of one
kind that reach the board between two passes of its real-time loop count
once.  So the station computes the bytes from the last ``Ov:`` the board
reported and sends them at once (a board whose real-time loop sees each byte
is there at once), then looks at what the board reports once its answer can
show them: two reports later (a report asked for in the same pass as the
bytes is made before they act; ``Ov:`` comes in the first report after a
change).  If it is short it sends one step of each kind still needed per
round — one byte of a kind cannot overshoot however the board merges them —
and says so if it never gets there.

An override changes speeds, never a path, so it goes while a job runs (that
is what it is for) and needs only the link; a firmware without overrides (the
CoreXY plotter's) refuses it with the reason.  Which machine has them is the
dialect registry's word (:mod:`app.machines.registry`), handed in as
:attr:`OverrideControl.available`.
"""

from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QCoreApplication, SignalInstance

from app.link import Link
from app.machine import MachineModel
from protocol.gcode.codec import StatusReport
from protocol.gcode.overrides import (
    BYTE_NAMES,
    FEED_MAX,
    FEED_MIN,
    FEED_RESET,
    RAPID_LEVELS,
    Overrides,
    feed_bytes,
    rapid_byte,
)

#: Status reports after the bytes before their effect is judged (see the module).
REPORTS_BEFORE_CHECK = 2
#: Rounds of sending what is missing before the station gives up and says so: from 10 to
#: 200 % a step of 10 and one of 1 at a time, on a board that merged the whole first burst.
ROUNDS = 22


class OverridePort(Protocol):
    """What the overrides use of their session (the G-code session)."""

    @property
    def model(self) -> MachineModel: ...
    @property
    def statusChanged(self) -> SignalInstance: ...
    @property
    def reset(self) -> SignalInstance: ...
    @property
    def link(self) -> Link: ...
    def send_realtime(self, byte: bytes, name: str) -> None: ...


class OverrideControl:
    """One G-code session's overrides: what the board reports, and what is asked of it."""

    def __init__(self, session: OverridePort) -> None:
        self._session = session
        #: The firmware has GRBL's overrides (the registry says; False until it does).
        self.available = False
        #: The last ``Ov:`` heard; None before any (or after a reset: 100 % then).
        self.reported: Overrides | None = None
        self._wanted: tuple[int, int] | None = None
        self._reports_left = 0
        self._rounds_left = 0
        session.statusChanged.connect(self._on_report)
        session.reset.connect(self._on_reset)

    @property
    def wanted(self) -> tuple[int, int] | None:
        """Feed and rapid percentages asked for and not yet reported, if any."""
        return self._wanted

    def set(self, feed: int | None = None, rapid: int | None = None) -> bool:
        """Ask for ``feed`` (10…200 %) and/or ``rapid`` (25, 50, 100 %); False when refused
        (said on the status bar): no overrides on this firmware, no link, a percentage
        GRBL cannot take."""
        model = self._session.model
        refusal = self._refusal(feed, rapid)
        if refusal is not None:
            model.message.emit(
                QCoreApplication.translate("Overrides", "Override not sent: {0}").format(refusal)
            )
            return False
        # Bytes still on their way (a second click before the board showed the first): they
        # will have taken it to what was asked then, so the new ones go from there.
        base = self._wanted
        if base is None and self.reported is not None:
            base = (self.reported.feed, self.reported.rapid)
        now = base or (100, 100)
        self._wanted = (now[0] if feed is None else feed, now[1] if rapid is None else rapid)
        self._rounds_left = ROUNDS
        self._send(base)
        return True

    def _refusal(self, feed: int | None, rapid: int | None) -> str | None:
        if not self.available:
            return QCoreApplication.translate(
                "Overrides", "this machine's firmware has no feed or rapid override"
            )
        if not self._session.link.is_open:
            return QCoreApplication.translate("Overrides", "not connected")
        if feed is not None and not FEED_MIN <= feed <= FEED_MAX:
            return QCoreApplication.translate(
                "Overrides", "a feed override of {0} % is outside {1}…{2} %"
            ).format(feed, FEED_MIN, FEED_MAX)
        if rapid is not None and rapid not in RAPID_LEVELS:
            return QCoreApplication.translate(
                "Overrides", "a rapid override of {0} % is none of 25, 50 and 100 %"
            ).format(rapid)
        return None

    def _send(self, base: tuple[int, int] | None, *, burst: bool = True) -> None:
        """The bytes from ``base`` (feed, rapid: where the board is or will be; None: not
        known) to what is wanted; ``burst``: all of them, else one of each kind needed."""
        assert self._wanted is not None
        feed, rapid = self._wanted
        # Not known: from a reset, whatever the board has now.
        codes = FEED_RESET + feed_bytes(100, feed) if base is None else feed_bytes(base[0], feed)
        if not burst:
            codes = bytes(sorted(set(codes)))  # one byte of each kind
        if base is None or base[1] != rapid:
            codes += rapid_byte(rapid)
        for code in codes:
            byte = bytes((code,))
            self._session.send_realtime(byte, BYTE_NAMES[byte])
        self._reports_left = REPORTS_BEFORE_CHECK

    def _on_report(self, report: StatusReport) -> None:
        if report.overrides is not None:
            self.reported = report.overrides
        if self._wanted is None:
            return
        if self._reports_left > 0:
            self._reports_left -= 1
            return
        now = self.reported
        if now is not None and (now.feed, now.rapid) == self._wanted:
            self._wanted = None
            return
        if self._rounds_left > 1:
            self._rounds_left -= 1
            self._send(None if now is None else (now.feed, now.rapid), burst=False)
            return
        feed, rapid = self._wanted
        self._wanted = None
        self._session.model.message.emit(
            QCoreApplication.translate(
                "Overrides", "The board did not take the override: feed {0} %, rapid {1} % asked"
            ).format(feed, rapid)
        )

    def _on_reset(self) -> None:
        """A reset (GRBL's) puts both back to 100 %; what was asked is forgotten."""
        self.reported = Overrides() if self.available else None
        self._wanted = None
