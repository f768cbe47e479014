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

from PySide6.QtCore import QCoreApplication, QObject, QTimer, Signal

from app.link import Link
from app.local_numbers import local_number
from app.machine import LinkState, MachineModel
from app.machines.envelope import Envelope
from app.machines.session import PENDING
from app.machines.usb3.moves_sent import STILL_AFTER_S as STILL_AFTER_S  # re-exported
from app.machines.usb3.moves_sent import Usb3MovesSent
from app.machines.usb3.question_hold import QuestionHold
from protocol.clock import Clock
from protocol.usb3.codec import (
    AxisId,
    NotUnderstood,
    Position,
    Rejected,
    ReplyDecoder,
    StepSize,
    StepSizes,
    StopAll,
    Thread,
    Threads,
    ZeroAll,
    count_to_mm,
    encode,
    move_commands,
    nearest_reachable_count,
    top_speed_mm_s,
)

#: How far ahead of the key a jog keeps the axis, in seconds of travel at top rate.
JOG_LEAD_S = 0.3
TICK_MS = 100
#: Seconds without any reply before the unit is asked ``G;``, then late (amber), then lost.
POLL_AFTER_S = 1.0
STALE_AFTER_S = 1.5
LOST_AFTER_S = 3.0
DEFAULT_STEP = StepSize.EIGHTH
DEFAULT_THREAD = Thread.M6


class Usb3Session(Usb3MovesSent):
    """frameSent/frameReceived carry usb3 messages (or Rejected) with their bytes."""

    settingsChanged = Signal()

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
            Envelope([(-math.inf, math.inf)], 1.0, hold_at_rest=False) for _ in range(3)
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
