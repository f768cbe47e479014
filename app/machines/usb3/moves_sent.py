"""The usb3 unit's moves sent and what its reports must show of them (docs/protocols.md §2).

Split from :class:`~app.machines.usb3.session.Usb3Session`, which is built on
:class:`Usb3MovesSent`: this base writes the messages (the jog's leads, the
questions), keeps where each move sent is heading, judges every position
report against the path of those moves (:mod:`app.machines.envelope`), and
tells an axis stopped at an end switch, or a move the unit could not read, from
one still under way.  The module docstring of the session says why each is
done the way it is.  The state is the session's, set in its ``__init__`` and
declared here.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

from PySide6.QtCore import QCoreApplication, Signal

from app.local_numbers import local_number
from app.machines.envelope import Deviation, Envelope, Fault
from app.machines.session import MachineSession
from app.machines.supervision import MotionFault, fault_text
from app.machines.usb3.direction_twice import with_reversals_twice
from app.machines.usb3.question_hold import QuestionHold
from protocol.usb3.codec import (
    TOP_PULSE_RATE,
    AxisId,
    GetSettings,
    Message,
    Move,
    SetDirection,
    StepSize,
    StopAll,
    Thread,
    Triple,
    ZeroAll,
    count_per_mm,
    count_to_mm,
    encode,
    move_commands,
)

#: An axis that has not reported for this long after a report has stopped.
STILL_AFTER_S = 0.25

_T = TypeVar("_T")


class Usb3MovesSent(MachineSession):
    """The sending and supervising half of the usb3 session (its state is set by its init)."""

    #: An axis stopped at an end switch: axis index, "low" or "high", position in mm.
    endSwitchHit = Signal(int, str, float)
    #: The unit answered ``?;`` and an axis never left where its move began: the move was
    #: the command it could not read.  Axis index, position in mm.
    moveRefused = Signal(int, float)

    step_sizes: list[StepSize]
    threads: list[Thread]
    _counts: list[int]
    _zeroing: list[bool]
    _asking: list[bool]
    _jog_end: list[float | None]
    _heading: list[tuple[int, int, float] | None]
    _move_from: list[int | None]
    _refused_at: float | None
    _signs: list[int]
    _reported_at: list[float | None]
    _envelopes: list[Envelope]
    _last_heard: float
    _asked_at: float | None
    _held: QuestionHold
    _last_report: list[float | None]

    def request_positions(self, axes: Sequence[int]) -> None:
        """Ask where ``axes`` stand: a move of nothing ends at once, and an ended move reports.

        The unit has no position query; this is how a job re-examines the axes
        after a lost link without moving them.
        """
        wanted = [AxisId(axis) for axis in axes if 0 <= axis < min(3, self.axis_count)]
        if wanted and self.link.is_open:
            for axis in wanted:
                self._asking[axis] = True
                if self._at_rest(axis):
                    per_pulse = self.step_sizes[axis].counts_per_pulse
                    self._held.asked(axis, self.clock.now(), per_pulse)
            self._send(SetDirection((1, 1, 1)), *(Move(axis, 0) for axis in wanted))

    def request_settings(self) -> None:
        self._send(GetSettings())

    # --- the wire ---------------------------------------------------------------

    def _send_jog_lead(self, seconds: float, axes: Sequence[int] | None = None) -> None:
        """More of the held jog, never past the travel: the leads sent are added up per axis."""
        counts = [0] * 3
        for axis, direction in enumerate(self._jog):
            if not direction or (axes is not None and axis not in axes) or axis >= 3:
                continue
            thread = self.threads[axis]
            pulses = max(1, round(TOP_PULSE_RATE * seconds))
            wanted = count_to_mm(
                direction * pulses * self.step_sizes[axis].counts_per_pulse, thread
            )
            here = self._jog_end[axis]
            if here is None:
                here = self.model.axes[axis].position
            room = self.gate.clamp(axis, here + wanted) - here
            per_pulse = self.step_sizes[axis].counts_per_pulse
            # Whole pulses, rounded toward zero: the lead ends inside the travel.
            count = int(room / count_to_mm(per_pulse, thread)) * per_pulse
            self._jog_end[axis] = here + count_to_mm(count, thread)
            counts[axis] = count
        if any(counts):
            self._send(*move_commands(counts))

    def _send(self, *messages: Message) -> None:
        if not self.link.is_open:
            return
        for message in with_reversals_twice(messages, self._signs):
            self._track(message)
            raw = encode(message)
            self.link.write(raw)
            self.frameSent.emit(message, raw)

    def _track(self, message: Message) -> None:
        """Follow where the moves sent take each axis, as the unit counts them."""
        if isinstance(message, SetDirection):
            self._signs = list(message.signs)
        elif isinstance(message, Move) and message.count:
            axis = int(message.axis)
            heading = self._heading[axis]
            base = heading[0] if heading is not None else self._counts_of(axis)
            if heading is None and axis < self.axis_count and self._zeroing[axis]:
                base = 0  # counted from the zero C; set, whose report is still to come
            sign = self._signs[axis]
            self._move_from[axis] = base if heading is None else None
            self._held.release(axis)
            self._heading[axis] = (base + sign * message.count, sign, self.clock.now())
            self._expect(axis, heading is None, base, base + sign * message.count)
        elif isinstance(message, StopAll | ZeroAll):
            # Stopped on purpose, or counted from a new zero: no target to fall short of.
            self._heading = [None] * 3
            self._held.release()
            for envelope in self._envelopes:
                if isinstance(message, ZeroAll):
                    envelope.anchor((0,))  # every count starts again from 0
                else:
                    envelope.loosen("stopped by S;")  # somewhere on the way it was going

    # --- supervision: the reports follow the moves sent ----------------------------------

    def _scale_envelope(self, axis: int) -> None:
        """The tolerance and travel in counts, which the thread turns into millimetres."""
        per_mm = count_per_mm(self.threads[axis]) if axis < self.axis_count else 6400.0
        envelope = self._envelopes[axis]
        envelope.tolerance = self.model.profile.supervision_tolerance_mm * per_mm
        if axis < self.axis_count:
            low, high = self.gate.limits(axis)
            envelope.limits = ((low * per_mm, high * per_mm),)

    def _expect(self, axis: int, fresh: bool, base: int, target: int) -> None:
        """A move to ``target`` went out: the axis's reports must follow it there."""
        envelope = self._envelopes[axis]
        name = self.model.axes[axis].name if axis < self.axis_count else AxisId(axis).name
        mm = count_to_mm(target - base, self.threads[axis])
        label = QCoreApplication.translate("Usb3Session", "{0} {1} mm, {2} counts").format(
            name, local_number(mm, "+.3f"), f"{target - base:+d}"
        )
        if fresh:
            if self._reported_at[axis] is None:
                envelope.release()  # not heard on this link yet: where it starts is not known
                return
            braking = envelope.legs[-1] if envelope.in_flight else None
            if braking is not None and braking.low is not None and braking.high is not None:
                # Sent while the axis still brakes from S; somewhere in that box: the move
                # counts from wherever it stops, so it ends in the box shifted by its count.
                delta = target - base
                envelope.add_box(
                    (braking.low[0] + min(0, delta),),
                    (braking.high[0] + max(0, delta),),
                    (target,),
                    label,
                )
                return
            envelope.anchor((base,))
        envelope.add_line((target,), label)

    def _judge_report(self, axis: int, count: int) -> bool:
        """Whether a report is where the moves sent allow; if not the unit is stopped."""
        envelope = self._envelopes[axis]
        if not envelope.known or (self._zeroing[axis] and not envelope.in_flight):
            envelope.anchor((count,))  # the first word of this axis, or a new zero
            return True
        deviation = envelope.check((count,))
        if deviation is None:
            return True
        name = self.model.axes[axis].name
        text = fault_text(deviation, [name], scale=1 / count_per_mm(self.threads[axis]))
        for each in self._envelopes:
            each.release()  # stopped: the next reports say where it stands
        self.stop_for_fault(MotionFault(text))
        return False

    def _at_rest(self, axis: int) -> bool:
        """No move of the station's under way and not heard moving: asked where it stands, it
        must stand.  (An axis that may still run out a move sent before the link dropped
        may run to that move's target: see :meth:`_on_connected`.)"""
        return self._heading[axis] is None and self._last_report[axis] is None

    def _judge_answer(self, axis: int, count: int) -> None:
        """An axis only asked where it stands moves on: the question ran as a move; stop it."""
        stood = self._held.report(axis, count, self.clock.now())
        if stood is None:
            return
        name = self.model.axes[axis].name
        label = QCoreApplication.translate(
            "Usb3Session", "{0} asked where it stands, a move of nothing"
        ).format(name)
        deviation = Deviation(Fault.MOVED_AT_REST, (count,), (stood,), abs(count - stood), label)
        text = fault_text(deviation, [name], scale=1 / count_per_mm(self.threads[axis]))
        for each in self._envelopes:
            each.release()  # stopped: the next reports say where it stands
        self.stop_for_fault(MotionFault(text))

    def _counts_of(self, axis: int) -> int:
        return self._counts[axis] if axis < self.axis_count else 0

    def _check_end_switches(self, now: float) -> None:
        """An axis silent short of where the station's moves were taking it is at a switch."""
        if self.silent_since is not None:
            return  # the whole unit was silent: it is asked where its axes stand first
        for axis, heading in enumerate(self._heading):
            reported = self._reported_at[axis]
            if heading is None or axis >= self.axis_count:
                continue
            target, sign, sent_at = heading
            if reported is None or reported < sent_at or now - reported < STILL_AFTER_S:
                continue  # not heard since the move went out, or not silent long enough
            count = self._counts[axis]
            if self._refused(axis, sent_at, count):
                continue
            if (target - count) * sign < StepSize.FULL.counts_per_pulse:
                # There, past it (the unit's joystick took over), or less than a full step
                # short: a unit whose step size changed on its menu rounds a move down.
                self._heading[axis] = None
                continue
            if self._last_heard - reported < STILL_AFTER_S:
                # Nothing at all heard since the axis fell silent: the link may be what went
                # quiet, not the axis.  A harmless question decides: the unit's answer proves
                # it is there (a switch), and no answer is a lost link, with no false alarm.
                if self._asked_at is None or now - self._asked_at >= STILL_AFTER_S:
                    self._asked_at = now
                    self.request_settings()
                continue
            self._heading[axis] = None
            # Its move may only have been held back on the way (the line slow, not a
            # switch): asked where it stands, it may yet run to that target.
            self._held.late(axis, target)
            which = "high" if sign > 0 else "low"
            position = count_to_mm(count, self.threads[axis])
            name = self.model.axes[axis].name
            short = count_to_mm(abs(target - count), self.threads[axis])
            stopped = (
                QCoreApplication.translate(
                    "Usb3Session",
                    "{0} stopped at its high end switch at {1} mm, {2} mm short of its target",
                )
                if sign > 0
                else QCoreApplication.translate(
                    "Usb3Session",
                    "{0} stopped at its low end switch at {1} mm, {2} mm short of its target",
                )
            )
            self.model.message.emit(
                stopped.format(name, local_number(position, ".3f"), local_number(short, ".3f"))
            )
            self.endSwitchHit.emit(axis, which, position)

    def _refused(self, axis: int, sent_at: float, count: int) -> bool:
        """An axis silent where its move began, after a ``?;`` since the move went out: the
        unit could not read the move (a byte lost or flipped on the wire), so it never ran.

        Not an end switch, and not a move still to come: the axis counts from where it
        stands again, and whoever sent the move hears of it (:attr:`moveRefused`).
        """
        refused_at = self._refused_at
        if refused_at is None or refused_at < sent_at or self._move_from[axis] != count:
            return False
        self._heading[axis] = None
        self._move_from[axis] = None
        self._envelopes[axis].anchor((count,))
        position = count_to_mm(count, self.threads[axis])
        name = self.model.axes[axis].name
        self.model.message.emit(
            QCoreApplication.translate(
                "Usb3Session",
                "The unit could not read the move of {0} (it answered ?;) and did not "
                "move it: {0} stands at {1} mm",
            ).format(name, local_number(position, ".3f"))
        )
        self.moveRefused.emit(axis, position)
        return True

    def _ask_after_refusal(self) -> None:
        """``?;``: an axis sent a move and not heard since may be the one that did not take it;
        asked where it stands, its answer (and then its silence) tells."""
        waiting = []
        for axis, heading in enumerate(self._heading[: self.axis_count]):
            reported = self._reported_at[axis]
            if heading is not None and (reported is None or reported < heading[2]):
                waiting.append(axis)
        if waiting:
            self.request_positions(waiting)

    @staticmethod
    def _triple(values: Sequence[_T], default: _T) -> Triple[_T]:
        """Three values for the wire, whatever the profile's axis count."""
        padded = [*values[:3], *[default] * (3 - len(values))]
        return (padded[0], padded[1], padded[2])
