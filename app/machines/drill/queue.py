"""The drill's command queue: one command out at a time, each judged by the motion gate first.

Split from :class:`~app.machines.drill.session.DrillSession`, which is built
on :class:`DrillQueue` (through :class:`~app.machines.drill.jogging.DrillJogging`):
every intent reaches the queue through :meth:`DrillQueue._enqueue`, the next
command goes out once the one in flight is done, and the model shows what the
commands started and finished.  The module docstring of the session says why.
The state is the session's, set in its ``__init__`` and declared here.
"""

from __future__ import annotations

from collections import deque
from decimal import Decimal

from PySide6.QtCore import QCoreApplication

from app.machines.drill.conversion import mm_to_microsteps
from app.machines.drill.unasked import ReplyLedger
from app.machines.session import MachineSession
from protocol.drill.codec import POSITION_LETTERS, Command, encode_command

#: Seconds the device has to acknowledge (``R``) a command: it does so in its next cycle.
RECEIPT_TIMEOUT_S = 1.0
#: A reply is late (the link shown stale) after this share of the receipt's time.
RECEIPT_LATE_SHARE = 0.5
#: The largest position the wire carries (six digits, docs/protocols.md §3.2).
MAX_POSITION = 999_999


class DrillQueue(MachineSession):
    """The queue, the conversions and the model half of the drill's session."""

    _ledger: ReplyLedger
    _queue: deque[Command]
    _in_flight: Command | None
    _received: bool
    _deadline: float | None
    _waiting_since: float | None
    _late_at: float | None
    _refused_lines: int
    _homed_here: bool
    _per_mm: list[Decimal]

    @property
    def busy(self) -> bool:
        """A command is out or waiting."""
        return self._in_flight is not None or bool(self._queue)

    # --- conversions -----------------------------------------------------------

    def microsteps_per_mm(self, axis: int) -> float:
        return float(self._per_mm[axis])

    def to_microsteps(self, axis: int, mm: float) -> int:
        """Nearest microstep to ``mm``, half away from zero, computed in decimal."""
        return mm_to_microsteps(mm, self._per_mm[axis])

    def to_mm(self, axis: int, microsteps: int) -> float:
        return microsteps / float(self._per_mm[axis])

    # --- the queue ---------------------------------------------------------------

    def _refuse_line(self, line: str, reason: str) -> bool:
        self._refused_lines += 1
        self.model.message.emit(
            QCoreApplication.translate(
                "DrillSession", "Not sent: {0} is not a drill command ({1})"
            ).format(repr(line), reason)
        )
        return False

    def why_refused(self, command: Command) -> str | None:
        """What the motion gate says against ``command`` now, or None: it may go.

        The one judgement every command passes before the queue (:meth:`_enqueue`),
        also asked by the step-through to show a refusal beside its button.
        """
        reason = self.model.motion_lock_reason()
        if reason is not None:
            return QCoreApplication.translate("Session", "Motion refused: {0}").format(reason)
        if command.letter in POSITION_LETTERS and command.value is not None:
            axis = self._axes_named(command.letter)
            if axis:
                return self.position_refusal(axis[0], command.value)
        return None

    def position_refusal(self, axis: int, microsteps: int) -> str | None:
        """What the motion gate says against ``axis`` going to ``microsteps``, or None.

        Any whole number is judged, one the wire cannot even carry (a negative
        position) too: by the travel it leaves.
        """
        refusal = self.gate.refuse_target(axis, self.to_mm(axis, microsteps))
        if refusal is not None:
            return QCoreApplication.translate("MotionGate", "Motion refused: {0}").format(refusal)
        if not 0 <= microsteps <= MAX_POSITION:
            return QCoreApplication.translate(
                "DrillSession", "Motion refused: {0} is no drill position (0…{1})"
            ).format(microsteps, MAX_POSITION)
        return None

    def _enqueue(self, command: Command) -> bool:
        """Every command reaches the queue here: a position outside the travel never does."""
        reason = self.why_refused(command)
        if reason is not None:
            self.model.message.emit(reason)
            return False
        self._queue.append(command)
        self._send_next()
        return True

    def _send_next(self) -> None:
        if self._in_flight is not None or not self._queue or not self.link.is_open:
            return
        command = self._queue.popleft()
        self._in_flight = command
        self._received = False
        self._expect(RECEIPT_LATE_SHARE * RECEIPT_TIMEOUT_S, RECEIPT_TIMEOUT_S)
        raw = encode_command(command)
        self.link.write(raw)
        self.frameSent.emit(command, raw)
        self._show_started(command)

    def _clear(self) -> None:
        if self._in_flight is not None:
            self._ledger.abandoned(self._in_flight.letter)
        self._queue.clear()
        self._in_flight = None
        self._received = False
        self._expect(None)

    def _expect(self, late_s: float | None, lost_s: float = 0.0) -> None:
        """A reply is due: late (amber) after ``late_s``, the link lost after ``lost_s``."""
        now = self.clock.now()
        if late_s is None:
            self._waiting_since = self._late_at = self._deadline = None
            return
        self._waiting_since = now
        self._late_at = now + late_s
        self._deadline = now + lost_s

    # --- model --------------------------------------------------------------------

    def _axes_named(self, letters: str) -> list[int]:
        return [i for i, a in enumerate(self.model.profile.axes) if a.name in letters]

    def _show_started(self, command: Command) -> None:
        status = {"X": "moving", "Y": "moving", "N": "homing", "P": "parking"}.get(command.letter)
        if status is None:
            return
        letters = command.letter if command.letter in POSITION_LETTERS else POSITION_LETTERS
        for axis in self._axes_named(letters):
            self.model.update_axis(axis, status_text=status, moving=True)

    def _show_done(self, command: Command) -> None:
        if command.letter in POSITION_LETTERS and command.value is not None:
            for axis in self._axes_named(command.letter):
                self.model.update_axis(
                    axis,
                    position=self.to_mm(axis, command.value),
                    status_text="idle",
                    moving=False,
                    velocity=0.0,
                )
        elif command.letter == "N":
            self._homed_here = True
            for axis in self._axes_named(POSITION_LETTERS):
                self.model.update_axis(
                    axis, position=0.0, status_text="idle", moving=False, velocity=0.0
                )
        elif command.letter == "P":
            # Park runs X to 0 and Y to the back of the machine, then switches the motors off.
            for axis in self._axes_named(POSITION_LETTERS):
                name = self.model.profile.axes[axis].name
                travel = self.model.profile.axes[axis].travel
                self.model.update_axis(
                    axis,
                    position=0.0 if name == "X" else travel,
                    status_text="parked",
                    moving=False,
                    velocity=0.0,
                )

    def _show_stopped(self) -> None:
        for axis in range(self.axis_count):
            if self.model.axes[axis].moving:
                self.model.update_axis(axis, status_text="idle", moving=False, velocity=0.0)
