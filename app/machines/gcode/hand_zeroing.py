"""Zeroing by hand (the winder's white buttons, FIDELITY S0-24): release, turn, declare.

The machine turns about a centre (X measured from it), can release its
motors (``M18``) and take a position declared (``G92``): the operator turns
the base and moves the needle by hand, then says "here is the zero".  A zero
declared after any other line went out would no longer be where the operator
put the axes, so every line queued ends the release (:meth:`HandZeroing.line_queued`,
under the feeder's lock: a job's lines are queued on the reader thread).
"""

from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.machine import MachineModel
from app.machines.gcode.jogger import reports_moving
from app.machines.gcode.lines import SentLine
from app.machines.motion_gate import MotionGate
from app.profiles import GcodeSettings
from protocol.gcode.codec import StatusReport
from protocol.gcode.streaming import LineStreamer


def zeroes_by_hand(settings: GcodeSettings) -> bool:
    """Whether the machine is zeroed by hand (the winder, S0-24): it turns about a centre
    (X measured from it) and can release its motors and take a position declared
    (``M18``, ``G92``)."""
    words = settings.words
    return settings.kinematics == "cylindrical" and "M18" in words and "G92" in words


class ZeroingPort(Protocol):
    """What zeroing by hand uses of its session (the G-code session)."""

    @property
    def model(self) -> MachineModel: ...
    @property
    def gate(self) -> MotionGate: ...
    @property
    def status(self) -> StatusReport | None: ...
    @property
    def stopping(self) -> bool: ...
    @property
    def jog_vector(self) -> tuple[int, ...]: ...
    @property
    def streamer(self) -> LineStreamer[SentLine]: ...
    def send_line(self, text: str, origin: str) -> bool: ...


def not_at_rest(session: ZeroingPort) -> str | None:
    """Why the machine is not at rest by the session's own account (None: it is): a stop
    under way, a jog held, lines unanswered, a report showing motion or a hold."""
    if session.stopping:
        return "a stop is under way"
    if any(session.jog_vector):
        return "a jog is held"
    status = session.status
    held = status is not None and status.state == "Hold"
    if not session.streamer.idle or reports_moving(status) or held:
        return "the machine is still running what it was sent"
    return None


class HandZeroing:
    """The two white buttons of one G-code session."""

    def __init__(self, session: ZeroingPort) -> None:
        self._session = session
        #: The motors were released for zeroing by hand and nothing was sent since.
        self.released = False

    def line_queued(self) -> None:
        """A line went to the board: it may move an axis (switching its driver on)."""
        self.released = False

    def _busy(self) -> str | None:
        return not_at_rest(self._session)

    def release_motors(self) -> bool:
        """Zeroing by hand, first step: every driver off (``M18``), the axes free to turn.

        The winder's first white-button press: its holding current off, so the
        operator turns the base and moves the needle by hand.  No motion is
        sent; refused (with the reason) while a job is under way or the machine
        moves or has anything left to run.
        """
        session = self._session
        refusal = session.gate.refuse_release(self._busy())
        if refusal is not None:
            session.model.message.emit(
                QCoreApplication.translate("HandZeroing", "Not released: {0}").format(refusal)
            )
            return False
        if not session.send_line("M18", "intent"):
            return False
        self.released = True
        session.model.message.emit(
            QCoreApplication.translate(
                "HandZeroing", "Motors released: turn the axes by hand to the zero, then Zero here"
            )
        )
        return True

    def zero_here(self, board_radius: float) -> bool:
        """Zeroing by hand, second step: the axes stand at the zero (``G92``), nothing moves.

        The winder's second white-button press: the base's angle is 0, the
        needle's X is the board radius (the original's linear zero is
        ``polomer_matrice``; X here is measured from the centre), Z is 0.
        Only after :meth:`release_motors` with nothing sent since, and under
        the same conditions; a radius outside X's travel is refused.
        """
        session = self._session
        model = session.model
        if not self.released:
            model.message.emit(
                QCoreApplication.translate("HandZeroing", "Not zeroed: release the motors first")
            )
            return False
        refusal = session.gate.refuse_release(self._busy())
        names = [a.name for a in model.profile.axes]
        if refusal is None and "X" in names:
            refusal = session.gate.refuse_target(names.index("X"), board_radius)
        if refusal is not None:
            model.message.emit(
                QCoreApplication.translate("HandZeroing", "Not zeroed: {0}").format(refusal)
            )
            return False
        words = " ".join(f"{name}{board_radius if name == 'X' else 0.0:.3f}" for name in names)
        if not session.send_line(f"G92 {words}", "intent"):
            return False
        model.message.emit(
            QCoreApplication.translate(
                "HandZeroing", "Zeroed by hand: X is the board radius, {0} mm"
            ).format(local_number(board_radius))
        )
        return True
