"""What every dialect's session offers the widgets: operator intents and trace signals.

Widgets hold a :class:`MachineSession` and never need to know the dialect;
an intent a machine cannot carry out (absolute moves on the usb3 unit, sleep
on a plotter) is refused with a message rather than silently ignored.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.link import Link
from app.machine import LinkState, MachineModel
from app.machines.motion_gate import MotionGate
from app.machines.supervision import MotionFault
from protocol.clock import Clock
from protocol.sniff import sounds_like

#: Seconds a device has to give its first valid reply before the operator is told.
ANSWER_WAIT_S = 3.0
#: Bytes of unrecognised replies kept to tell which machine is there instead.
_HEARD_KEPT = 512
#: A held jog with no sign for this long that the key or button is still held ends (the
#: station's dead-man).  Longer than a keyboard's auto-repeat delay (0.25 to 0.66 s), whose
#: repeats are the sign for a key; a held button is polled for it.
JOG_DEADMAN_S = 1.0
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


#: :meth:`MachineSession._recovery_verdict`'s "not yet".
PENDING = _Pending()


class MachineSession(QObject):
    frameSent = Signal(object, bytes)  # decoded message, raw bytes
    frameReceived = Signal(object, bytes)  # decoded message or a rejected one, raw bytes
    linkLost = Signal()  # the device fell silent (port open): it is asked on until it answers
    ticked = Signal()  # one period passed (station-clock time for whoever waits on the device)
    #: A held jog ended without a release (dead-man or travel end): forget what is held.
    jogEnded = Signal(str)
    # The machine went where no move sent it and was stopped (a MotionFault): a job fails.
    motionFault = Signal(object)
    #: The device answers again after a silence with its port open: None when its state is
    #: intact (nothing can have been lost), else what does not match (a reset, a position).
    recovered = Signal(object)

    def __init__(
        self, model: MachineModel, link: Link, clock: Clock, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self.model = model
        self.link = link
        self.clock = clock
        self.axis_count = len(model.axes)
        self._jog = [0] * self.axis_count
        self._jog_evidence_at: float | None = None  # last sign the jog is still held
        self.gate = MotionGate(model)
        self._fast_selected = True
        # Share of its usual jog speed a held jog asks for (a gamepad's stick half pushed).
        self.jog_speed_share = 1.0
        self._device_heard = False  # a valid reply in this dialect came since the link opened
        self._awaiting_since: float | None = None
        self._told_no_answer = False
        self._unrecognised = bytearray()
        #: Since when the device has been silent with its port open, once that was a lost
        #: link (None: it is not); and whether it has answered since.
        self._silent_since: float | None = None
        self._answered_after_silence = False
        self._probed_at: float | None = None
        #: Whether a late tick's lateness is the station's own, not counted as the device's
        #: silence (set by dialects whose ticks come from a real-time timer).
        self.discounts_stalls = False
        self._ticked_at: float | None = None

    # --- state the widgets read ------------------------------------------------

    @property
    def jog_vector(self) -> tuple[int, ...]:
        return tuple(self._jog)

    @property
    def fast_selected(self) -> bool:
        return self._fast_selected

    @property
    def period_ms(self) -> int:
        return 100

    @property
    def homes_before_job(self) -> bool:
        """A job run now would home the machine first (the drill, not seen homing yet)."""
        return False

    def top_speeds_mm_s(self) -> dict[str, float] | None:
        """Axis speeds where the machine's own settings decide them (None: from the profile)."""
        return None

    @property
    def rejected(self) -> int:
        """Malformed replies dropped so far (shown in the status bar)."""
        return 0

    # --- intents: what a dialect cannot do is refused with a message ------------

    def set_jog(self, directions: Sequence[int]) -> None:
        if any(directions):
            self._unsupported(QCoreApplication.translate("Session", "jogging"))

    def stop_all(self) -> None:
        self._unsupported(QCoreApplication.translate("Session", "stop command"))

    def step_jog(self, axis: int, direction: int, step: float) -> bool:
        """One tap of an arrow key in step mode: ``step`` that way, or what is left of the travel.

        Sent as a relative move, so it passes the motion gate like any other;
        at the travel's end it says so instead of moving.
        """
        if not 0 <= axis < self.axis_count or direction not in (-1, 1) or step <= 0:
            return False
        if self._refuse_jog():
            return False
        distance = min(step, self.gate.room(axis, direction))
        if distance <= 1e-6:
            name = self.model.axes[axis].name
            self.model.message.emit(
                QCoreApplication.translate("Session", "{0} is at the end of its travel").format(
                    name
                )
            )
            return False
        return self.move_relative(axis, direction * distance)

    # --- the dead-man: a held jog needs signs that it is still held -------------------

    def set_jog_speed(self, share: float) -> None:
        """How fast a held jog goes, as a share (0…1] of its usual speed: where the dialect
        chooses its jog's speed (a G-code board's feed), the next step goes at it; the others
        jog at the speed the machine has selected."""
        self.jog_speed_share = min(1.0, max(0.01, share)) if math.isfinite(share) else 1.0

    def forget_jog(self) -> None:
        """The held arrows are let go (a stop, a lost link): nothing jogs until pressed anew."""
        self._jog = [0] * self.axis_count

    def keep_jogging(self) -> None:
        """A sign that the held key or button is still held (a key repeat, a button poll)."""
        if any(self._jog):
            self._jog_evidence_at = self.clock.now()

    def _jog_started(self) -> None:
        """Sessions call this when a jog begins or changes: that is a sign too."""
        self._jog_evidence_at = self.clock.now() if any(self._jog) else None

    def _check_deadman(self) -> None:
        """Called each tick: a jog whose holding shows no sign of life ends."""
        since = self._jog_evidence_at
        if not any(self._jog) or since is None:
            return
        silent = self.clock.now() - since
        if silent > JOG_DEADMAN_S:
            self._jog_evidence_at = None
            self.set_jog((0,) * self.axis_count)
            reason = (
                f"Jog ended: no sign for {silent:.1f} s that the key or button is still held "
                "(press it again to jog on)"
            )
            self.model.message.emit(reason)
            self.jogEnded.emit(reason)

    def motion_stopped(self) -> bool:
        """Whether the device's reports show every axis still (a stop is confirmed by this)."""
        return not self.model.any_moving

    def move_relative(self, axis: int, delta: float) -> bool:
        return self._unsupported(QCoreApplication.translate("Session", "relative moves"))

    def set_shift(self, held: bool) -> None:
        """Shift selects the other jog speed where the machine has two."""

    def select_speed(self, fast: bool) -> None:
        self._fast_selected = fast

    def move_absolute(self, axis: int, position: float) -> bool:
        return self._unsupported(QCoreApplication.translate("Session", "absolute moves"))

    def home(self, axis: int) -> bool:
        return self._unsupported("homing")

    def set_sleep(self, sleep: bool) -> None:
        self._unsupported("sleep")

    def set_period_ms(self, period_ms: int) -> None:
        """Only periodic dialects have a period."""

    def tick(self) -> None:
        """One period of a periodic dialect (the harness calls it on the test clock)."""

    def shutdown(self) -> None:
        """Stop timers; the link is closed by the station."""

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

    def stop_for_fault(self, fault: MotionFault) -> None:
        """A report left the envelope of the moves sent: stop now, say why, tell the job."""
        self.stop_all()
        self.model.message.emit(fault.text)
        self.motionFault.emit(fault)

    def _unsupported(self, what: str) -> bool:
        self.model.message.emit(
            QCoreApplication.translate("Session", "{0} has no {1}").format(
                self.model.profile.shown_title, what
            )
        )

        return False

    def _jog_wanted(self, directions: Sequence[int]) -> list[int]:
        """The held directions, one per axis (-1, 0 or 1); none at all where a jog is refused."""
        wanted = [max(-1, min(1, int(d))) for d in directions[: self.axis_count]]
        wanted += [0] * (self.axis_count - len(wanted))
        if any(wanted) and self._refuse_jog():
            return [0] * self.axis_count
        return wanted

    def _refuse_jog(self) -> bool:
        """A jog is the operator's alone: refused while a job owns the machine, too."""
        reason = self.model.jog_lock_reason
        if reason is not None:
            self.model.message.emit(
                QCoreApplication.translate("Session", "Jog refused: {0}").format(reason)
            )
            return True
        return self._refuse_motion()

    def _refuse_motion(self) -> bool:
        reason = self.model.motion_lock_reason()
        if reason is not None:
            self.model.message.emit(
                QCoreApplication.translate("Session", "Motion refused: {0}").format(reason)
            )
            return True
        return False
