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
from app.machine import MachineModel
from app.machines.answer_watch import ANSWER_WAIT_S as ANSWER_WAIT_S  # re-exported
from app.machines.answer_watch import PENDING as PENDING
from app.machines.answer_watch import PROBE_EVERY_S as PROBE_EVERY_S
from app.machines.answer_watch import STALL_GRACE_S as STALL_GRACE_S
from app.machines.answer_watch import AnswerWatch
from app.machines.motion_gate import MotionGate
from app.machines.supervision import MotionFault
from protocol.clock import Clock

#: A held jog with no sign for this long that the key or button is still held ends (the
#: station's dead-man).  Longer than a keyboard's auto-repeat delay (0.25 to 0.66 s), whose
#: repeats are the sign for a key; a held button is polled for it.
JOG_DEADMAN_S = 1.0


class MachineSession(AnswerWatch):
    frameSent = Signal(object, bytes)  # decoded message, raw bytes
    frameReceived = Signal(object, bytes)  # decoded message or a rejected one, raw bytes
    ticked = Signal()  # one period passed (station-clock time for whoever waits on the device)
    #: A held jog ended without a release (dead-man or travel end): forget what is held.
    jogEnded = Signal(str)
    # The machine went where no move sent it and was stopped (a MotionFault): a job fails.
    motionFault = Signal(object)

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
