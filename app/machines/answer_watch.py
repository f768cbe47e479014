"""Whether the device answers: "connected" once it does, amber then red when it falls silent.

Every dialect's session is built on :class:`AnswerWatch` (through
:class:`~app.machines.session.MachineSession`): the port being open is not
the link being up; the device must answer in its dialect first.  A device
that falls silent with its port open is given up (a job pauses) and asked its
dialect's harmless question until it answers; the dialect then says whether
its state survived.  The dialect's hooks (``_silence_began``, ``_probe``,
``_recovery_verdict``, ``_back_after_silence``) have harmless defaults here.
The state is the session's, set in its ``__init__`` and declared here.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.link import Link
from app.machine import LinkState, MachineModel
from protocol.clock import Clock
from protocol.sniff import sounds_like

#: Seconds a device has to give its first valid reply before the operator is told.
ANSWER_WAIT_S = 3.0
#: Bytes of unrecognised replies kept to tell which machine is there instead.
_HEARD_KEPT = 512
#: A device silent with its port open, or not answering since the link opened, is asked its
#: dialect's harmless question this often: the devices that speak only when asked (usb3, the
#: drill) would otherwise never be heard again once the line works.
PROBE_EVERY_S = 1.0
#: A tick this much later than its period means the station itself was not running (a busy
#: computer, a stalled event loop): that time is not counted as the device's silence.
STALL_GRACE_S = 0.25


class _Pending:
    """The device answers again after a silence, and whether its state is intact is not
    known yet (a report that proves it is still to come)."""

    def __repr__(self) -> str:
        return "PENDING"


#: :meth:`AnswerWatch._recovery_verdict`'s "not yet".
PENDING = _Pending()


class AnswerWatch(QObject):
    """The link-liveness half of every session (its state is set by the session's init)."""

    linkLost = Signal()  # the device fell silent (port open): it is asked on until it answers
    #: The device answers again after a silence with its port open: None when its state is
    #: intact (nothing can have been lost), else what does not match (a reset, a position).
    recovered = Signal(object)

    model: MachineModel
    link: Link
    clock: Clock
    discounts_stalls: bool
    _device_heard: bool
    _awaiting_since: float | None
    _told_no_answer: bool
    _unrecognised: bytearray
    _silent_since: float | None
    _answered_after_silence: bool
    _probed_at: float | None
    _ticked_at: float | None

    @property
    def period_ms(self) -> int:
        return 100

    # --- "connected" means the device answers ----------------------------------------

    @property
    def device_answered(self) -> bool:
        return self._device_heard

    def await_device(self) -> None:
        """The port is open: motion stays locked until the device answers in this dialect."""
        self._device_heard = False
        self._awaiting_since = self.clock.now()
        self._probed_at = self._awaiting_since  # each dialect asks once as the link opens
        self._told_no_answer = False
        self._unrecognised.clear()
        self._silent_since = None
        self._answered_after_silence = False
        self.model.set_link_state(
            LinkState.CONNECTING, f"{self.link.describe()} — waiting for the device…"
        )

    def device_replied(self, *, proof: bool = True) -> None:
        """A valid reply in this dialect: the link is up (and back, after silence).

        ``proof``: the reply can show whether the device's state survived a
        silence (a status report); a dialect whose every reply can passes True.
        """
        if not self._device_heard:
            self._device_heard = True
            self._awaiting_since = None
            self.model.set_link_state(LinkState.CONNECTED, self.link.describe())
        elif self._silent_since is not None:
            self._answered_after_silence = True
            if proof:
                self.check_recovery()
        elif self.model.link_state is LinkState.STALE:
            # Replies are back before the link was given up: green again, nothing reopened.
            self.model.set_link_state(LinkState.CONNECTED, self.link.describe())

    # --- a silent link: amber, then red, then asked until it answers ------------------------

    @property
    def silent_since(self) -> float | None:
        """Since when (station clock) the device has been given up as silent, port open."""
        return self._silent_since

    def _watch_silence(
        self, silent_s: float, stale_after_s: float, lost_after_s: float, why: str = ""
    ) -> None:
        """Called each tick with how long the reply due has been missing.

        Past ``stale_after_s`` the link is shown *stale* (amber, "no reply for
        N s", motion still allowed: a reply may only be late); past
        ``lost_after_s`` it is *lost* (red, :meth:`_lost_to_silence`).  Any
        valid reply before that turns it green again
        (:meth:`device_replied`).  Each dialect says what is due and when.
        """
        if not self._device_heard or self.model.link_state not in (
            LinkState.CONNECTED,
            LinkState.STALE,
        ):
            return
        detail = f"no reply for {silent_s:.1f} s{f' ({why})' if why else ''}"
        if silent_s > lost_after_s:
            self._lost_to_silence(detail)
        elif silent_s > stale_after_s:
            self.model.set_link_state(LinkState.STALE, detail)

    def _lost_to_silence(self, detail: str) -> None:
        """The device fell silent with its port open: the link is lost (red, a job pauses).

        The port stays open (reopening a USB board's port restarts many of
        them: its position would go with it) and the device is asked its
        dialect's harmless question every :data:`PROBE_EVERY_S` until it
        answers; the dialect then says whether its state is intact.
        """
        now = self.clock.now()
        self._silent_since = now
        self._answered_after_silence = False
        self._probed_at = None
        forgotten = self._silence_began()
        self.model.set_link_state(LinkState.LOST, detail)
        self.model.message.emit(
            QCoreApplication.translate(
                "Session", "The device is silent ({0}){1}; asking it every {2} s"
            ).format(detail, forgotten, f"{PROBE_EVERY_S:g}")
        )
        self.linkLost.emit()
        self._probe_if_due(now)

    def _silence_began(self) -> str:
        """What the dialect forgets when the device is given up as silent (port still open);
        returns what the operator should hear of it (", 3 unanswered line(s) …"), or ""."""
        return ""

    def _probe(self) -> None:
        """Ask the device something harmless that it answers (the dialect's own question)."""

    def _recovery_verdict(self) -> object:
        """After a silence, once the device answers: None when its state is intact, a str
        saying what does not match, or :data:`PENDING` while the proof is still to come."""
        return None

    def _back_after_silence(self) -> None:
        """The device is heard again after a silence: what a restart would have undone is
        set again (harmless when it did not restart)."""

    def _probe_if_due(self, now: float) -> None:
        """Ask a device given up as silent, or one that never answered since the link opened."""
        asking = self._silent_since is not None or (
            not self._device_heard and self._awaiting_since is not None
        )
        if not asking or not self.link.is_open:
            return
        if self._probed_at is not None and now - self._probed_at < PROBE_EVERY_S:
            return
        self._probed_at = now
        self._probe()

    def check_recovery(self) -> None:
        """The device answered after a silence: back, once its state is known."""
        since = self._silent_since
        if since is None or not self._answered_after_silence:
            return
        verdict = self._recovery_verdict()
        if verdict is PENDING:
            self.model.set_link_state(
                LinkState.LOST,
                QCoreApplication.translate("Session", "the device answers again; checking it…"),
            )
            return
        self._silent_since = None
        self._answered_after_silence = False
        self._back_after_silence()
        silent = f"{self.clock.now() - since:.1f}"
        self.model.set_link_state(LinkState.CONNECTED, self.link.describe())
        # A job that owns the machine says what it does next itself, in one message.
        if self.model.jog_lock_reason is None:
            if verdict is None:
                text = QCoreApplication.translate(
                    "Session",
                    "The device answers again ({0} s after it was given up), its state intact",
                ).format(silent)
            else:
                text = QCoreApplication.translate(
                    "Session", "The device answers again ({0} s after it was given up), but {1}"
                ).format(silent, verdict)
            self.model.message.emit(text)
        self.recovered.emit(verdict)

    def _station_stall(self, now: float) -> float:
        """Seconds since the last tick during which the station itself was not running.

        A real-time tick that comes much later than its period was held up by
        the computer (another process, a busy window): replies that came
        meanwhile may not have been read yet, so that time is nobody's silence.
        """
        last, self._ticked_at = self._ticked_at, now
        if not self.discounts_stalls or last is None:
            return 0.0
        return max(0.0, now - last - self.period_ms / 1000 - STALL_GRACE_S)

    def heard_unrecognised(self, raw: bytes) -> None:
        """Bytes from the device before it answered: kept to tell which machine it is."""
        if not self._device_heard:
            self._unrecognised += raw
            del self._unrecognised[:-_HEARD_KEPT]

    def _check_answer(self) -> None:
        """Called each tick: a silent device is asked again, and one that never answered (or
        speaks another dialect) is named once."""
        self._probe_if_due(self.clock.now())
        self.check_recovery()
        since = self._awaiting_since
        if self._device_heard or since is None or self._told_no_answer:
            return
        if self.clock.now() - since < ANSWER_WAIT_S:
            return
        self._told_no_answer = True
        profile = self.model.profile
        other = sounds_like(bytes(self._unrecognised), besides=profile.dialect)
        heard = (
            QCoreApplication.translate("Session", "; its replies sound like {0}").format(other)
            if other
            else ""
        )
        detail = QCoreApplication.translate(
            "Session", "no answer: is this a {0}? Check the profile, baud and port{1}"
        ).format(profile.shown_title, heard)
        self.model.set_link_state(LinkState.CONNECTING, detail)
        self.model.message.emit(f"{self.link.describe()}: {detail}")
