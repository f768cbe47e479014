"""The three-axis USB unit's session (docs/protocols.md §2).

The unit takes relative moves in 1/32-step counts and reports positions
while it moves; it has no jog command, so a held key becomes a stream of
short moves that keeps the axis a fraction of a second ahead of the key, and
the release sends ``S;`` (where the profile declares that extension) so the
axis stops at once rather than running out its lead.

The unit speaks only while an axis moves or when asked, so a link that went
quiet is asked: after :data:`POLL_AFTER_S` without a reply the session sends
``G;`` (report settings: it moves nothing), once per such interval.  An
unanswered question shows the link stale (amber) at :data:`STALE_AFTER_S`
and lost (red: a job pauses) at :data:`LOST_AFTER_S`; an answer before that
turns it green again.  A lost unit is still asked ``G;`` every second, the
port kept open; once it answers, it is asked where its axes stand, and its
state is intact when each stands between where it was last reported and
where the moves sent were taking it.  A report that repeats what the session
already holds changes nothing (no ``settingsChanged``), so the questions do
not make a running job forget where the axes stand.

The unit reports an axis's position only while it moves and when it stops, so
when it first answers the session asks every axis where it stands (a move of
nothing, which ends at once and reports): the axes show their real positions,
idle, from the start instead of "unknown" at 0 until they first move.

End switches (FIDELITY S4-18): the unit stops the axis whose switch is
pressed and reports where it stands, nothing more; the wire has no word for
"end switch".  So the session keeps where each move it sent is heading (the
unit adds a move sent while the axis still runs to its target): an axis that
falls silent short of that target, in the direction it was heading, with no
``S;`` sent, stopped at its switch on that side.  The session says so
(``endSwitchHit`` and a message naming the axis and the end), so a job in
progress pauses instead of sending the next step blindly.  Silence, not a
repeated count, decides, as for a job: at its slowest speed a pulse takes
longer than a report period.  Silence of the whole link is not a switch: when
nothing at all was heard since the axis fell silent, the session first asks a
harmless ``G;``; the answer proves the unit is there, and no answer ends as a
lost link.

Every position report is judged against the path of the moves the session
sent (:mod:`app.machines.envelope`, in counts, one path per axis: the unit
runs its axes independently): from the count the axis was last seen at,
through each move's target.  The wire has no checksum, so a corrupted digit
can turn a 3 mm move into a run of a kilometre; a report past the target (or
off the way back after a reversal) by more than the profile's tolerance stops
the unit at once (``S;``) and says which move, what was seen and what was
expected.  At rest the unit's joystick may move an axis: only the station's
own moves are judged, from the report that shows the axis moving until it
falls silent.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TypeVar

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.link import Link
from app.local_numbers import local_number
from app.machine import LinkState, MachineModel
from app.machines.envelope import Deviation, Envelope, Fault
from app.machines.session import PENDING, MachineSession
from app.machines.supervision import MotionFault, fault_text
from app.machines.usb3.question_hold import QuestionHold
from protocol.clock import Clock
from protocol.usb3.codec import (
    TOP_PULSE_RATE,
    AxisId,
    GetSettings,
    Message,
    Move,
    NotUnderstood,
    Position,
    Rejected,
    ReplyDecoder,
    SetDirection,
    StepSize,
    StepSizes,
    StopAll,
    Thread,
    Threads,
    Triple,
    ZeroAll,
    count_per_mm,
    count_to_mm,
    encode,
    move_commands,
    nearest_reachable_count,
    top_speed_mm_s,
)

#: How far ahead of the key a jog keeps the axis, in seconds of travel at top rate.
JOG_LEAD_S = 0.3
#: An axis that has not reported for this long after a report has stopped.
STILL_AFTER_S = 0.25
TICK_MS = 100
#: Seconds without any reply before the unit is asked ``G;``, then late (amber), then lost.
POLL_AFTER_S = 1.0
STALE_AFTER_S = 1.5
LOST_AFTER_S = 3.0
DEFAULT_STEP = StepSize.EIGHTH
DEFAULT_THREAD = Thread.M6

_T = TypeVar("_T")


class Usb3Session(MachineSession):
    """frameSent/frameReceived carry usb3 messages (or Rejected) with their bytes."""

    settingsChanged = Signal()
    #: An axis stopped at an end switch: axis index, "low" or "high", position in mm.
    endSwitchHit = Signal(int, str, float)
    #: The unit answered ``?;`` and an axis never left where its move began: the move was
    #: the command it could not read.  Axis index, position in mm.
    moveRefused = Signal(int, float)

    def __init__(
        self,
        model: MachineModel,
        link: Link,
        clock: Clock,
        *,
        autotick: bool = True,
        stop_command: bool = True,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(model, link, clock, parent)
        self.decoder = ReplyDecoder()
        self.not_understood = 0
        self.step_sizes: list[StepSize] = [DEFAULT_STEP] * self.axis_count
        self.threads: list[Thread] = [DEFAULT_THREAD] * self.axis_count
        self._counts = [0] * self.axis_count
        self._last_report: list[float | None] = [None] * self.axis_count
        #: ``C;`` was sent and the axis has not reported since: its next report is a new zero.
        self._zeroing = [False] * self.axis_count
        #: Asked where it stands (a move of nothing) and not answered yet: its next report
        #: is where it stands, not a motion.
        self._asking = [False] * self.axis_count
        #: Axes asked where they stand at rest, which must stand (a question run as a move).
        self._held = QuestionHold()
        #: Where the jog leads sent so far take each axis (None: from its position).
        self._jog_end: list[float | None] = [None] * self.axis_count
        #: Per axis: the count the moves sent are heading for, their direction and when the
        #: last was sent (None: no move of the station's under way).
        self._heading: list[tuple[int, int, float] | None] = [None] * 3
        #: Per axis: the count it stood at when a move was sent to it at rest (None: none).
        self._move_from: list[int | None] = [None] * 3
        #: Station-clock time of the unit's last ``?;`` (None: none on this link).
        self._refused_at: float | None = None
        #: The direction register as the station last set it (``D``).
        self._signs: list[int] = [1, 1, 1]
        #: Station-clock time of each axis's last position report.
        self._reported_at: list[float | None] = [None] * 3
        #: Per axis, the path (in counts) of the moves sent that the reports must follow.
        self._envelopes = [
            Envelope([(-math.inf, math.inf)], 1.0, hold_at_rest=False, travel_at_rest=True)
            for _ in range(3)
        ]
        for axis in range(3):
            self._scale_envelope(axis)
        self._last_heard = clock.now()
        self._asked_at: float | None = None  # the last G; asked because the unit was quiet
        #: After a silence: per axis, the counts the unit may stand at (from where it was to
        #: where the moves sent take it), and whether it has been asked where it stands.
        self._books: list[tuple[int, int] | None] = []
        #: Each axis's count when the silence began (what it answers if nothing sent meanwhile ran).
        self._before: list[int] = []
        self._recovery_asked = False
        #: Which settings reports came since the link opened (the first always counts).
        self._reported: set[str] = set()
        self._stop_command = stop_command
        self._autotick = autotick
        self.discounts_stalls = autotick  # a real-time timer ticks: its lateness is ours
        self._timer = QTimer(self)
        self._timer.setInterval(TICK_MS)
        self._timer.timeout.connect(self.tick)
        link.connected.connect(self._on_connected)
        link.disconnected.connect(self._on_disconnected)
        link.dataReceived.connect(self._on_data)

    @property
    def rejected(self) -> int:
        return self.decoder.rejected + self.not_understood

    # --- conversions the panel shows -------------------------------------------

    def reachable(self, axis: int, mm: float) -> float:
        """The distance a move of ``mm`` really covers with this axis's step size and thread."""
        count = nearest_reachable_count(mm, self.step_sizes[axis], self.threads[axis])
        return count_to_mm(count, self.threads[axis])

    def speed_mm_s(self, axis: int) -> float:
        """Top speed of the axis at its present step size and thread."""
        return top_speed_mm_s(self.step_sizes[axis], self.threads[axis])

    def top_speeds_mm_s(self) -> dict[str, float]:
        return {axis.name: self.speed_mm_s(i) for i, axis in enumerate(self.model.axes)}

    # --- intents ----------------------------------------------------------------

    def move_relative(self, axis: int, delta: float, *, start: float | None = None) -> bool:
        """A move by ``delta`` mm, judged from ``start`` where the caller knows better."""
        if self._refuse_motion():
            return False
        if self.gate.refuse(self.gate.refuse_relative(axis, delta, start)):
            return False
        counts = [0] * 3
        counts[axis] = nearest_reachable_count(delta, self.step_sizes[axis], self.threads[axis])
        if not counts[axis]:
            self.model.message.emit(
                QCoreApplication.translate(
                    "Usb3Session", "{0}: {1} mm is less than one step"
                ).format(self.model.axes[axis].name, local_number(delta))
            )
            return False
        self._send(*move_commands(counts))
        return True

    def move_relative_axes(self, deltas: Sequence[float]) -> bool:
        """Every axis by its ``deltas`` mm in one command, as the unit's own tool's one Send.

        All or nothing: an axis the gate refuses sends none of them, so the
        axes never end up half moved.  An axis of less than one step stays.
        """
        if self._refuse_motion():
            return False
        deltas = list(deltas)[: min(3, self.axis_count)]
        for axis, delta in enumerate(deltas):
            if delta and self.gate.refuse(self.gate.refuse_relative(axis, delta, None)):
                return False
        counts = [0] * 3
        for axis, delta in enumerate(deltas):
            counts[axis] = nearest_reachable_count(delta, self.step_sizes[axis], self.threads[axis])
        if not any(counts):
            self.model.message.emit(
                QCoreApplication.translate(
                    "Usb3Session", "Nothing to move: every distance is less than one step"
                )
            )
            return False
        self._send(*move_commands(counts))
        return True

    def set_jog(self, directions: Sequence[int]) -> None:
        wanted = self._jog_wanted(directions)
        if wanted == self._jog:
            return
        previous, self._jog = self._jog, wanted
        self._jog_started()
        for axis, (old, new) in enumerate(zip(previous, wanted, strict=True)):
            if old != new:
                self._jog_end[axis] = None  # a new jog counts from where the axis is
        released = any(old and not new for old, new in zip(previous, wanted, strict=True))
        stopped_all = released and self._stop_command
        if stopped_all:
            # S; stops every axis, so axes still held are started again right after.
            self._send(StopAll())
        # Only axes that start (or were just stopped) get a lead: the others already have one,
        # and a second would only lengthen the run-out on a unit without S;.
        starting = [
            axis
            for axis, direction in enumerate(wanted)
            if direction and (stopped_all or direction != previous[axis])
        ]
        self._send_jog_lead(JOG_LEAD_S, starting)

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
                    self._held.asked(axis, self.clock.now())
            self._send(SetDirection((1, 1, 1)), *(Move(axis, 0) for axis in wanted))

    def stop_all(self) -> None:
        self._jog = [0] * self.axis_count
        self._jog_end = [None] * self.axis_count
        if self._stop_command:
            self._send(StopAll())
        else:
            self.model.message.emit(
                QCoreApplication.translate(
                    "Usb3Session", "This unit has no stop command: it finishes its move"
                )
            )

    def zero_all(self) -> None:
        if self.link.is_open:
            self._zeroing = [True] * self.axis_count
        self._send(ZeroAll())

    def request_settings(self) -> None:
        self._send(GetSettings())

    def set_step_size(self, axis: int, size: StepSize) -> None:
        self.step_sizes[axis] = size
        self._send(StepSizes(self._triple(self.step_sizes, DEFAULT_STEP)))
        self.settingsChanged.emit()
        # A report asked for earlier (at connect) still carries the old values and would
        # undo this one on arrival: the unit's answer to a fresh G; comes after it.
        self.request_settings()

    def set_thread(self, axis: int, thread: Thread) -> None:
        self.threads[axis] = thread
        self._scale_envelope(axis)
        self._send(Threads(self._triple(self.threads, DEFAULT_THREAD)))
        self._refresh_positions()
        self.settingsChanged.emit()
        self.request_settings()  # see set_step_size

    # --- time -------------------------------------------------------------------

    def tick(self) -> None:
        """Keep held jogs fed and notice axes that stopped reporting."""
        self._check_answer()
        self._check_deadman()
        if any(self._jog):
            self._send_jog_lead(TICK_MS / 1000)
        now = self.clock.now()
        self._keep_alive(now)
        self._check_end_switches(now)
        for axis, last in enumerate(self._last_report):
            if last is not None and now - last > STILL_AFTER_S:
                self._last_report[axis] = None
                if self._heading[axis] is None and self._envelopes[axis].known:
                    # Still where the moves sent ended: at rest, the joystick's to move.
                    self._envelopes[axis].anchor((self._counts[axis],))
                self.model.update_axis(axis, status_text="idle", moving=False, velocity=0.0)
        self.ticked.emit()

    def _keep_alive(self, now: float) -> None:
        """Ask a quiet unit ``G;``; a question left unanswered is a silent link."""
        # Time the station itself was not running is nobody's silence.
        self._last_heard = min(now, self._last_heard + self._station_stall(now))
        silent = now - self._last_heard
        if not self.device_answered or not self.link.is_open or self.silent_since is not None:
            return  # given up as silent: the session's probe asks it
        asked = self._asked_at
        if silent >= POLL_AFTER_S and (asked is None or now - asked >= POLL_AFTER_S):
            self._asked_at = now
            self.request_settings()
        self._watch_silence(silent, STALE_AFTER_S, LOST_AFTER_S)

    def shutdown(self) -> None:
        self._timer.stop()

    # --- a silent unit --------------------------------------------------------------

    def _silence_began(self) -> str:
        """Where each axis may stand when the unit answers again: between where it was last
        reported and where the moves sent were taking it (it runs them out meanwhile).
        An axis not heard of since the link opened has no such place (None)."""
        self._books = []
        self._before = [self._counts[axis] for axis in range(min(3, self.axis_count))]
        for axis in range(min(3, self.axis_count)):
            if self._reported_at[axis] is None:
                self._books.append(None)
                continue
            heading = self._heading[axis]
            here = self._counts[axis]
            there = heading[0] if heading is not None else here
            self._books.append((min(here, there), max(here, there)))
        self._recovery_asked = False
        return ""

    def _probe(self) -> None:
        """``G;`` (it moves nothing); once it answered, the question about an axis whose
        answer did not come is asked again."""
        waiting = [axis for axis in range(len(self._books)) if self._asking[axis]]
        if self._recovery_asked and waiting:
            self.request_positions(waiting)
        else:
            self.request_settings()

    def _after_silence(self) -> None:
        """The unit answered after a silence: ask where its axes stand, to check the books."""
        if not self._recovery_asked:
            self._recovery_asked = True
            self.request_positions(range(len(self._books)))
        self.check_recovery()

    def _recovery_verdict(self) -> object:
        """Intact when every axis stands where the books allow (a unit switched off and on
        counts from 0 again; a joystick moved it): known once every axis has answered."""
        if not self._recovery_asked or any(self._asking[: len(self._books)]):
            return PENDING
        moved = []
        for axis, books in enumerate(self._books):
            if books is None:
                continue  # nothing to contradict: a job asks where it stands before moving it
            low, high = books
            count = self._counts[axis]
            if not low <= count <= high:
                thread = self.threads[axis]
                moved.append(
                    f"{self.model.axes[axis].name} is at {count_to_mm(count, thread):.3f} mm, "
                    f"not {count_to_mm(low, thread):.3f}"
                    + (f"…{count_to_mm(high, thread):.3f}" if high != low else "")
                    + " mm"
                )
        if moved:
            return "its position does not match: " + ", ".join(moved)
        self._forget_moves_lost_in_silence()
        return None

    def _forget_moves_lost_in_silence(self) -> None:
        """An axis that answers where it was last heard before the silence never got the
        moves sent meanwhile (it would have run them in the seconds of silence): the bytes
        were lost.  Counting them would shift every later move's target (a job sends the
        move again), so the axis is judged from where it stands."""
        for axis, books in enumerate(self._books):
            heading = self._heading[axis]
            if books is None or axis >= len(self._before) or heading is None:
                continue
            if self._counts[axis] == self._before[axis]:
                self._held.late(axis, heading[0])  # if it was only held back, it runs yet
                self._heading[axis] = None
                self._envelopes[axis].anchor((self._counts[axis],))

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
        for message in messages:
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

    # --- link events and replies ------------------------------------------------

    def _on_connected(self) -> None:
        self.decoder.reset()
        self._jog = [0] * self.axis_count
        self._zeroing = [False] * self.axis_count
        self._asking = [False] * self.axis_count
        self._held.release()
        for axis, heading in enumerate(self._heading):
            if heading is not None:
                self._held.late(axis, heading[0])  # the unit may still run it out
        self._heading = [None] * 3
        self._move_from = [None] * 3
        self._refused_at = None
        self._reported_at = [None] * 3
        for envelope in self._envelopes:
            envelope.release()
        self._last_heard = self.clock.now()
        self._asked_at = None
        self._reported.clear()
        self.await_device()
        if self._autotick:
            self._timer.start()
        self.request_settings()

    def _on_disconnected(self, reason: object) -> None:
        self._timer.stop()
        self._jog = [0] * self.axis_count
        if reason is None:
            self.model.set_link_state(LinkState.DISCONNECTED)
        else:
            self.model.set_link_state(LinkState.LOST, str(reason))
            self.model.message.emit(
                QCoreApplication.translate("Session", "Link lost: {0}").format(reason)
            )

    def _on_data(self, data: bytes) -> None:
        self.heard_unrecognised(data)  # kept until the device answers: whose words?
        for reply in self.decoder.feed(data):
            raw = reply.raw if isinstance(reply, Rejected) else encode(reply)
            if isinstance(reply, NotUnderstood):
                # Counted before the frame is announced, so a listener reading
                # ``rejected`` (the status bar) sees this one too, as it does a Rejected.
                self.not_understood += 1
            self.frameReceived.emit(reply, raw)
            if isinstance(reply, Rejected):
                self.model.message.emit(
                    QCoreApplication.translate(
                        "Usb3Session", "Garbage from the unit dropped: {0}"
                    ).format(repr(reply.raw))
                )
                continue
            self._last_heard = self.clock.now()
            first = not self.device_answered
            self.device_replied(proof=False)  # after a silence, the positions decide
            if first:
                # The unit reports positions only when an axis stops: without asking, every
                # axis would read "unknown" at 0 until it first moved.
                self.request_positions(range(self.axis_count))
            if isinstance(reply, Position):
                self._apply_position(reply.axis, reply.count)
            elif isinstance(reply, StepSizes):
                sizes = list(reply.sizes)[: self.axis_count]
                if self._news("M", sizes != self.step_sizes[: self.axis_count]):
                    self.step_sizes[: self.axis_count] = sizes
                    self.settingsChanged.emit()
            elif isinstance(reply, Threads):
                threads = list(reply.threads)[: self.axis_count]
                if self._news("T", threads != self.threads[: self.axis_count]):
                    self.threads[: self.axis_count] = threads
                    self._refresh_positions()
                    self.settingsChanged.emit()
            elif isinstance(reply, NotUnderstood):
                self.model.message.emit(
                    QCoreApplication.translate(
                        "Usb3Session", "The unit did not understand a command (?;)"
                    )
                )
                self._refused_at = self._last_heard
                self._ask_after_refusal()
            # Any word from the unit settles an axis left silent short of its target: a
            # switch, said before a job's own question about that axis is answered.
            self._check_end_switches(self._last_heard)
            if self.silent_since is not None:
                self._after_silence()

    def _news(self, report: str, changed: bool) -> bool:
        """Whether a settings report is news: a change, or the first since the link opened."""
        first = report not in self._reported
        self._reported.add(report)
        return changed or first

    def _apply_position(self, axis: AxisId, count: int) -> None:
        if axis >= self.axis_count:
            return
        self._judge_answer(axis, count)
        self._judge_report(axis, count)
        now = self.clock.now()
        self._reported_at[axis] = now
        heading = self._heading[axis]
        if heading is not None and count == heading[0]:
            self._heading[axis] = None  # arrived where the moves sent were taking it
        moved = count != self._counts[axis]
        last = self._last_report[axis]
        delta_mm = count_to_mm(count - self._counts[axis], self.threads[axis])
        self._counts[axis] = count
        position = count_to_mm(count, self.threads[axis])
        if self._asking[axis] and last is None:
            # The answer to "where are you?": where it stands, not a move to there (and the
            # new zero, when C; went before the question).
            self._asking[axis] = False
            self._zeroing[axis] = False
            self.model.update_axis(
                axis, position=position, velocity=0.0, status_text="idle", moving=False
            )
            return
        self._asking[axis] = False
        if self._zeroing[axis]:
            # The report C; asks for: the axis got a new origin, it did not move there.
            self._zeroing[axis] = False
            if last is None:
                self.model.update_axis(
                    axis, position=position, velocity=0.0, status_text="idle", moving=False
                )
            else:  # zeroed on the way: still moving, its speed measured from here on
                self._last_report[axis] = now
                self.model.update_axis(axis, position=position)
            return
        if not moved:
            # A report that repeats the last count: the axis is standing still.
            self._last_report[axis] = None
            self.model.update_axis(
                axis, position=position, velocity=0.0, status_text="idle", moving=False
            )
            return
        velocity = delta_mm / (now - last) if last is not None and now > last else 0.0
        self._last_report[axis] = now
        self.model.update_axis(
            axis, position=position, velocity=velocity, status_text="moving", moving=True
        )

    def _refresh_positions(self) -> None:
        for axis in range(self.axis_count):
            self.model.update_axis(
                axis, position=count_to_mm(self._counts[axis], self.threads[axis])
            )
