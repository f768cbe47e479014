"""The G-code link opening, closing and the board's resets, as the session's parts see them.

Each of these throws away what the board may have lost: the unanswered lines
(handed back as not run), the path they drew, the console's distance mode,
the byte count, a jog under way.  Written in one place so that what a reset
forgets and what a lost link forgets cannot drift apart.  The session
composes it; it runs on the GUI thread, holding the feeder's lock for what the
reader thread also writes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from app.machine import LinkState
from app.machines.gcode.lines import SentLine

if TYPE_CHECKING:
    from app.machines.gcode.ports import GcodeCore


class LinkEvents:
    """What one G-code session forgets as its link or its board starts again."""

    def __init__(self, session: GcodeCore) -> None:
        self._session = session

    def forget_stream(self, *, by_device: bool) -> list[SentLine]:
        """The board was reset (``by_device``: by itself): every unanswered line is gone."""
        session = self._session
        session.reset_by_device = by_device
        # GRBL forgets its G92 offset on a reset; its next report carries the offset it has.
        session.work_offset = None
        session.envelope.release()  # judged again from where it stands once idle
        session.follower.planned.reset_modes()
        session.follower.pen.reset()
        with session.feeder.lock:
            session.console.reset()  # GRBL's power-on and reset mode is G90
            lost = session.feeder.clear()
            session.seen_idle = False
        session.follower.byte_count.forget()
        session.jogger.lines_gone()
        session.reset.emit()
        return lost

    def forget_jog_and_lines(self) -> list[SentLine]:
        """A jog under way ends and the unanswered lines are handed back (as not run): the
        board may have lost them, so nothing counts them until it is looked at again."""
        session = self._session
        session.forget_jog()
        session.jogger.forget_cancel()
        session.stops.quiet = False
        session.follower.byte_count.forget()
        session.follower.pen.lines_lost()
        with session.feeder.lock:
            return session.feeder.clear()

    def connected(self) -> None:
        session = self._session
        # The decoder is not reset here: the reader thread may already have decoded the
        # board's first words (a banner, a status) before this runs, and a reset now
        # would cut a reply in half.  It starts fresh, and is reset when a link ends.
        with session.feeder.lock:
            session.feeder.clear()
            session.feeder.reset_halt()
            session.seen_idle = False
            session.feeder.reset_sent_at = None
            session.zeroing.released = False
        session.follower.byte_count.forget()
        session.status_asked_at = None
        session.stops.requested_at = None
        session.envelope.release()
        session.follower.planned.reset_modes()
        session.last_heard = session.clock.now()
        session.await_device()
        if session.autotick:
            session.timer.start()
        session.query_status()

    def disconnected(self, reason: object) -> None:
        session = self._session
        session.timer.stop()
        session.stops.requested_at = None
        with session.feeder.lock:
            session.feeder.reset_sent_at = None
        lost = self.forget_jog_and_lines()
        with session.feeder.lock:
            # No reader runs until the station opens the link again (after this): a reply
            # cut by the loss is not glued to the next link's first bytes.
            session.decoder.reset()
        for axis in range(session.axis_count):
            session.model.update_axis(axis, moving=False, velocity=0.0)
        if reason is None:
            session.model.set_link_state(LinkState.DISCONNECTED)
        else:
            session.model.set_link_state(LinkState.LOST, str(reason))
            if lost:
                text = QCoreApplication.translate(
                    "GcodeSession", "Link lost: {0}; {1} unanswered line(s)"
                ).format(reason, len(lost))
            else:
                text = QCoreApplication.translate("GcodeSession", "Link lost: {0}").format(reason)
            session.model.message.emit(text)
