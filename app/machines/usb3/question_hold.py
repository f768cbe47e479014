"""An axis asked where it stands must stand: the usb3 question is a move of nothing.

The unit has no position query, so the session asks with a move of 0 counts
(``Y000000000000000;``), which ends at once and reports.  The wire has no
checksum: one flipped bit turns that question into a move of twenty million
counts (the relay's seed 134), and the unit runs it.  The envelope cannot see
it: no move of the station's is in flight, so the reports look like the
unit's joystick at rest, judged only against the travel, which a run at top
speed takes a minute to leave.

So an axis asked while no move of the station's was under way is *held*:
its answer is where it stands, and reports that carry it on away from there
(the unit reports a moving axis every 100 ms, a stopped one once) mean the
question ran as a move; the session stops the unit.  Away means farther than
the braking from top speed (:data:`BRAKING_PULSES` at the axis's step size:
eight times less at 1/8 step than at full steps, where a question run as a
move at connect got past the job's first target before it was stopped,
relay seed 134 of h-relay6): on a loaded computer the reports of an axis still
braking from the last move can come late enough for the session to take it
for standing (the relay's seed 4 was stopped 0.003 mm from its answer), and
the question is then asked of an axis that still creeps to its stop.  And a
move the session took for lost in a silent line (the axis answered unmoved)
may only have been held back on the way and arrive after all (seed 3): the
axis may run on to that move's target (:meth:`QuestionHold.late`).  The hold ends
when the axis has said nothing for :data:`HELD_FOR_S` after its answer (from
then on its motion is the joystick's), when the station sends it a move or
``S;``/``C;``, or when the answer does not come within :data:`ANSWER_DUE_S`.
"""

from __future__ import annotations

from dataclasses import dataclass

#: After its answer, an axis silent this long stood: the unit reports a moving axis every
#: 100 ms, so a question run as a move shows within it.
HELD_FOR_S = 0.25
#: A question whose answer has not come by then is no longer waited on (it may be lost).
ANSWER_DUE_S = 1.0
#: How far an axis may still go after its answer, in pulses: the braking from top speed
#: (75 pulses), and two for the stop on a whole pulse.  Times the counts a pulse moves at the
#: axis's step size: 2400 counts (0.375 mm on an M6 thread) at full steps, 300 at 1/8 step.
#: A question run as a long move passes it within a report or two.
BRAKING_PULSES = 77
#: The most it can be, at full steps (32 counts a pulse).
BRAKING_COUNTS = BRAKING_PULSES * 32


@dataclass
class _Held:
    asked_at: float
    braking: int = BRAKING_COUNTS  # counts: the braking at the axis's step size
    late: int | None = None  # the target of a move taken for lost, which may yet arrive
    count: int | None = None  # the answer: where it stands
    heard_at: float | None = None


class QuestionHold:
    """Per axis: asked where it stands, and whether its reports since say it stood."""

    def __init__(self) -> None:
        self._held: dict[int, _Held] = {}
        self._late: dict[int, int] = {}

    def late(self, axis: int, target: int) -> None:
        """A move to ``target`` was taken for lost in a silence; it may still arrive and run."""
        self._late[axis] = target

    def asked(self, axis: int, now: float, counts_per_pulse: int = 32) -> None:
        """A move of nothing went to ``axis`` while no move of the station's was under way;
        a pulse moves ``counts_per_pulse`` at its step size (the braking scales with it)."""
        held = self._held.get(axis)
        if held is not None and held.heard_at is not None and now - held.heard_at <= HELD_FOR_S:
            return  # asked again just after its answer: it still has to stand there
        braking = BRAKING_PULSES * max(1, counts_per_pulse)
        self._held[axis] = _Held(now, braking, self._late.get(axis))

    def release(self, axis: int | None = None) -> None:
        """The station moved (or stopped, or zeroed) the axis: its reports are judged otherwise."""
        if axis is None:
            self._held.clear()
            self._late.clear()
        else:
            self._held.pop(axis, None)
            self._late.pop(axis, None)

    def report(self, axis: int, count: int, now: float) -> int | None:
        """The axis reported ``count``: where it answered it stood, when it has moved since."""
        held = self._held.get(axis)
        if held is None:
            return None
        if held.count is None or held.heard_at is None:
            if now - held.asked_at > ANSWER_DUE_S:
                del self._held[axis]  # not the answer: a late report of another kind
                return None
            held.count, held.heard_at = count, now
            return None
        if now - held.heard_at > HELD_FOR_S:
            del self._held[axis]  # it stood; what moves it now is the joystick
            return None
        ends = (held.count,) if held.late is None else (held.count, held.late)
        if min(ends) - held.braking <= count <= max(ends) + held.braking:
            held.heard_at = now
            return None
        del self._held[axis]
        return held.count
