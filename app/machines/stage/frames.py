"""The stage's command frames: which packet each axis's slot carries, and when frames go out.

Split from :class:`~app.machines.stage.session.StageSession`, which is built
on :class:`StageFrames`: the session takes the operator's intents and the
echoes; this base empties its queues into frames (urgent packets first, then
the held jog, its release, a background read), turns a jog about to reach the
travel's end into a move that stops before it, and chooses each frame's
subscriber.  The queues are the session's, set in its ``__init__`` and
declared here.
"""

from __future__ import annotations

from collections import deque

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.machines.session import MachineSession
from app.machines.stage.supervision import StageSupervisor
from protocol.stage.codec import (
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoType,
    Subscriber,
    encode_command,
)

#: What the info panel shows; each is asked for at least once a second.
INFO_SUBSCRIBERS: tuple[Subscriber, ...] = (
    Subscriber.BATTERY_CHARGE,
    Subscriber.BATTERY_VOLTAGE,
    Subscriber.BOARD_TEMPERATURE,
    Subscriber.DEVICE_FLAGS,
    Subscriber.CHARGING_CURRENT,
)

MAX_BURST = 16
#: Until the stage's own dynamics are read: its documented defaults (docs/protocols.md §1.4).
DEFAULT_FAST_UM_S = 10_000
DEFAULT_SLOW_UM_S = 2_000
DEFAULT_ACCELERATION_UM_S2 = 20_000
#: Periods between a frame leaving and its effect being seen (frame out, echo back), on top
#: of the braking distance when a jog is turned into a stop at the travel end.
JOG_LATENCY_PERIODS = 2
#: A jog stopped at the travel's end stops this far inside it: the stage's end switches sit
#: at the travel's ends, and a jog is to stop before them, not on them.
JOG_END_MARGIN_MM = 0.1


class SubscriberScheduler:
    """Chooses the SS of each frame: info values at least once a second, the rest plotted."""

    def __init__(self, period_s: float) -> None:
        self.period_s = period_s
        self.plotted: int | None = None
        self._last: dict[int, float] = {}

    def next(self, now: float) -> int:
        due = [s for s in INFO_SUBSCRIBERS if now - self._last.get(s, -1e9) >= 1.0 - self.period_s]
        if due:
            choice: int = min(due, key=lambda s: self._last.get(s, -1e9))
        elif self.plotted is not None:
            choice = self.plotted
        else:
            choice = min(INFO_SUBSCRIBERS, key=lambda s: self._last.get(s, -1e9))
        self._last[choice] = now
        return choice


class StageFrames(MachineSession):
    """The frame-building half of the stage's session (its state is set by its init)."""

    subscribers: SubscriberScheduler
    supervisor: StageSupervisor
    _period_ms: int
    _release_repeats: list[int]
    _jog_limited: list[int]
    _urgent: list[deque[CommandPacket]]
    _background: list[deque[CommandPacket]]
    _read_in_last_frame: list[bool]
    _shift_held: bool
    _device_fast: bool | None
    _frames_sent: int
    _unproven: list[tuple[int, CommandPacket] | None]

    def _send_now(self) -> None:
        """Send at once: every urgent packet, then the jog state, without waiting for a tick."""
        if not self.link.is_open:
            return
        for _ in range(MAX_BURST):
            self._send_frame()
            if not any(self._urgent):
                break

    def _send_frame(self) -> None:
        packets = tuple(self._next_packet(axis) for axis in range(self.axis_count))
        frame = CommandFrame(packets, self.subscribers.next(self.clock.now()))
        raw = encode_command(frame)
        self.supervisor.sent(packets)
        self._frames_sent += 1
        for axis, packet in enumerate(packets):
            if packet.command == CommandId.MOVE_ABS:
                self._unproven[axis] = (self._frames_sent, packet)
            elif packet.command in SUPERSEDING:
                self._unproven[axis] = None
        self.link.write(raw)
        self.frameSent.emit(frame, raw)

    def _next_packet(self, axis: int) -> CommandPacket:
        if self._urgent[axis]:
            self._read_in_last_frame[axis] = False
            packet = self._urgent[axis].popleft()
            if packet.command in MOTION_COMMANDS:
                self._release_repeats[axis] = 0
            return packet
        if self._jog[axis]:
            self._read_in_last_frame[axis] = False
            if self._jog_limited[axis]:
                return CommandPacket(CommandId.NOP)  # the move to the travel end runs
            if self._must_brake(axis, self._jog[axis]):
                self._jog_limited[axis] = self._jog[axis]
                low, high = self.gate.limits(axis)
                if self._jog[axis] > 0:
                    end = max(low, high - JOG_END_MARGIN_MM)
                else:
                    end = min(high, low + JOG_END_MARGIN_MM)
                self.model.message.emit(
                    QCoreApplication.translate(
                        "StageSession", "{0} jog ends before the travel's end, at {1} mm"
                    ).format(self.model.axes[axis].name, local_number(end))
                )
                return CommandPacket(CommandId.MOVE_ABS, to_um(end))
            return CommandPacket(CommandId.JOG, self._jog[axis])
        if self._release_repeats[axis]:
            self._read_in_last_frame[axis] = False
            self._release_repeats[axis] -= 1
            return CommandPacket(CommandId.JOG, 0)
        # A READ answer takes the axis's position slot in the echo, so reads go out at most
        # every other frame: the info panel keeps following the axis while they run.
        if self._background[axis] and not self._read_in_last_frame[axis]:
            self._read_in_last_frame[axis] = True
            return self._background[axis].popleft()
        self._read_in_last_frame[axis] = False
        return CommandPacket(CommandId.NOP)

    def _jog_dynamics(self, axis: int) -> tuple[float, float]:
        """Speed and acceleration (mm/s, mm/s²) a jog of the axis runs with: the device's own."""
        fast = self._fast_selected != self._shift_held
        kind = EchoType.FAST_SPEED if fast else EchoType.SLOW_SPEED
        default = DEFAULT_FAST_UM_S if fast else DEFAULT_SLOW_UM_S
        speed = self.model.parameter(axis, kind).value or default
        acceleration = (
            self.model.parameter(axis, EchoType.ACCELERATION).value or DEFAULT_ACCELERATION_UM_S2
        )
        moving = abs(self.model.axes[axis].velocity)
        return max(speed / 1000, moving), acceleration / 1000

    def _must_brake(self, axis: int, direction: int) -> bool:
        """Whether a jog must now become a stop at the travel end to end before it.

        The device stops a jog only at its end switch, at full speed: so the
        station turns the jog into a move to the travel's end once the room left
        is what braking from the jog's speed needs, plus the distance covered
        while a frame goes out and its echo comes back.
        """
        speed, acceleration = self._jog_dynamics(axis)
        braking = speed * speed / (2 * acceleration)
        latency = speed * JOG_LATENCY_PERIODS * self._period_ms / 1000
        room = self.gate.room(axis, direction) - JOG_END_MARGIN_MM
        return room <= braking + latency

    def _motion(self, axis: int, packet: CommandPacket) -> bool:
        if self._refuse_motion():
            return False
        self._urgent[axis].append(packet)
        self._send_now()
        return True

    def _sync_speed(self) -> None:
        fast = self._fast_selected != self._shift_held
        if fast == self._device_fast:
            return
        self._device_fast = fast
        for queue in self._urgent:
            queue.append(CommandPacket(CommandId.SPEED, 1 if fast else 0))


MOTION_COMMANDS = frozenset(
    {CommandId.MOVE_ABS, CommandId.MOVE_REL, CommandId.HOME, CommandId.STOP, CommandId.ESTOP}
)
#: Commands after which an earlier MOVE_ABS of their axis no longer decides where it goes.
SUPERSEDING = frozenset(
    {
        CommandId.MOVE_REL,
        CommandId.HOME,
        CommandId.STOP,
        CommandId.ESTOP,
        CommandId.SET_POS,
        CommandId.JOG,
        CommandId.SLEEP,
    }
)


def to_um(mm: float) -> int:
    """Millimetres as the wire's micrometres."""
    return round(mm * 1000)
