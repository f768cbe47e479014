"""A stage command frame handled, packet by packet, and the echo that answers it
(docs/protocols.md §1).

A written parameter goes to :class:`~protocol.emulator.stage_parameters.
StageParameters`, every other command to its handler in
:class:`~protocol.emulator.stage_commands.StageCommands`; each handled command
but a NOP is logged.  The echo carries one packet per command (an axis's
status and position where the handler left them out) and the subscriber the
frame asked for.  The firmware calls this under its lock, in its control cycle.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

from protocol.emulator.stage_board import StageBoard, fit_data
from protocol.emulator.stage_commands import UNKNOWN, Handler, Reply, StageCommands
from protocol.emulator.stage_parameters import StageParameters
from protocol.stage.codec import (
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoPacket,
    encode_echo,
    written_parameter,
)

#: Commands kept for inspection: enough for a test or the developer pane, bounded
#: so that an emulator left running for days does not grow.
COMMAND_LOG_LENGTH = 1000


@dataclass(frozen=True, slots=True)
class ExecutedCommand:
    """One command packet the firmware handled (NOPs are not recorded)."""

    time: float
    axis: int
    command: int
    data: int
    accepted: bool


@dataclass(frozen=True, slots=True)
class PendingEcho:
    """A frame's replies, echoed at the end of the cycle that handled it."""

    subscriber: int
    replies: tuple[Reply, ...]


class StageDispatch:
    """The command handlers of one stage firmware, and the log of what they did."""

    def __init__(
        self, commands: StageCommands, parameters: StageParameters, board: StageBoard
    ) -> None:
        self._parameters = parameters
        self._board = board
        self.log: deque[ExecutedCommand] = deque(maxlen=COMMAND_LOG_LENGTH)
        self._handlers: dict[int, Handler] = {
            CommandId.NOP: commands.nop,
            CommandId.STOP: commands.stop,
            CommandId.JOG: commands.jog,
            CommandId.MOVE_ABS: commands.move_abs,
            CommandId.MOVE_REL: commands.move_rel,
            CommandId.HOME: commands.home,
            CommandId.SET_POS: commands.set_pos,
            CommandId.SPEED: commands.speed,
            CommandId.ESTOP: commands.estop,
            CommandId.SLEEP: commands.sleep,
            CommandId.READ: parameters.read,
        }

    def handle(self, frame: CommandFrame, now: float) -> PendingEcho:
        replies = tuple(
            self.packet(index, packet, now) for index, packet in enumerate(frame.packets)
        )
        return PendingEcho(frame.subscriber, replies)

    def packet(self, index: int, packet: CommandPacket, now: float) -> Reply:
        parameter = written_parameter(packet.command)
        if parameter is not None:
            reply = self._parameters.write(index, parameter, packet.data)
        else:
            handler = self._handlers.get(packet.command)
            reply = UNKNOWN if handler is None else handler(index, packet.data, now)
        if packet.command != CommandId.NOP:
            self.log.append(
                ExecutedCommand(now, index, packet.command, packet.data, reply.accepted)
            )
        return reply

    def echo(self, echo: PendingEcho, *, session_open: bool, rejected: int) -> bytes:
        """The echo frame's bytes, as of the end of the cycle."""
        packets = tuple(self.echo_packet(i, reply) for i, reply in enumerate(echo.replies))
        subscriber, sdata = self._board.subscriber(
            echo.subscriber, session_open=session_open, rejected=rejected
        )
        return encode_echo(EchoFrame(packets, subscriber, sdata))

    def echo_packet(self, index: int, reply: Reply) -> EchoPacket:
        board = self._board
        status = reply.status if reply.status is not None else board.axis_status(index)
        data = reply.data if reply.data is not None else board.axes[index].position_quantised_um
        return EchoPacket(reply.type, status, fit_data(data))
