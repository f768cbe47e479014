"""A G-code stop: a feed hold at once, then a soft reset once the machine stands.

A reset while the axes still move makes GRBL raise ALARM:3 and forget its
position, so the reset waits for a status report saying the hold is complete
(``Hold:0``) or the machine idle, or for :data:`RESET_AFTER_S`.  The stop's
own state (when its reset is due, whether it is quiet, whether a report has
shown the board standing since) lives here; the session composes it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from protocol.gcode.codec import StatusReport

if TYPE_CHECKING:
    from app.machines.gcode.ports import GcodeCore

#: A stop resets the device this long after its hold at the latest, standing or not.
RESET_AFTER_S = 2.0


class StopSequence:
    """The hold, then the reset, of one G-code session (GUI thread)."""

    def __init__(self, session: GcodeCore) -> None:
        self._session = session
        #: The stop under way ends a jog: no "lines not run" message for it.
        self.quiet = False
        #: When the hold went out, while its reset has not (None: no stop under way).
        self.requested_at: float | None = None
        self.dropped = 0
        #: A stop went out and no report since its reset has shown the board standing: on a
        #: silent line its hold and reset may both have been lost.
        self.unconfirmed = False

    def stop(self, *, keep_jog: bool = False, quiet: bool = False) -> None:
        """Hold at once; reset once the machine stands, so buffered lines are dropped.

        ``quiet``: the stop ends a jog, no "lines not run" message for it.
        """
        session = self._session
        if quiet:
            self.quiet = True
        if not keep_jog:
            session.forget_jog()
            session.jogger.forget()
            # A job owns the machine (its jog lock): the job says what ran, in its operations;
            # a count of lines here beside it read as a second, different figure.
            self.quiet = session.model.jog_lock_reason is not None
        if not session.link.is_open:
            return
        with session.feeder.lock:  # nothing more is fed from here on
            self.dropped = len(session.feeder.discard_queued())
            session.feed_hold()
        self.requested_at = session.clock.now()
        self.unconfirmed = True  # until a report shows the board standing
        session.query_status()

    def reset_now(self) -> None:
        """The hold is complete (or waited for long enough): the reset goes out."""
        session = self._session
        self.requested_at = None
        lost = len(session.soft_reset()) + self.dropped
        self.dropped = 0
        quiet, self.quiet = self.quiet, False
        if lost and not quiet:
            session.model.message.emit(
                QCoreApplication.translate("GcodeSession", "Stopped: {0} line(s) not run").format(
                    lost
                )
            )

    def due(self, now: float) -> None:
        """Each tick: no report of a finished hold came in time, so reset anyway."""
        requested = self.requested_at
        if (
            requested is not None
            and now - requested > RESET_AFTER_S
            and self._session.silent_since is None
        ):
            self.reset_now()

    def reported(self, report: StatusReport) -> None:
        """A status report: a stop whose hold is complete (or idle, or in alarm) resets."""
        if self.requested_at is None:
            return
        held = report.state == "Hold" and report.substate in (None, "0")
        if held or report.state in ("Idle", "Alarm"):
            self.reset_now()
        else:
            self.ask_again()  # still braking: ask again at once

    def confirm(self, report: StatusReport) -> None:
        """A report after the reset showing the board standing: the stop is carried out."""
        if (
            self.unconfirmed
            and self._session.silent_since is None
            and self.requested_at is None
            and report.state in ("Idle", "Alarm")
        ):
            self.unconfirmed = False  # held and reset: it stands

    def ask_again(self) -> None:
        """A status report soon: asks now unless a question is already on its way."""
        session = self._session
        asked = session.status_asked_at
        if asked is None or session.clock.now() - asked > session.settings.status_ms / 1000:
            session.query_status()

    def after_silence(self) -> None:
        """A stop asked for before or during the silence is carried out now: its hold may
        have been lost on the way, so it goes again, and the reset follows once it holds."""
        session = self._session
        if (self.requested_at is not None or self.unconfirmed) and session.link.is_open:
            session.feed_hold()
            self.requested_at = session.clock.now()
            session.query_status()
