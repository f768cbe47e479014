"""The stage's echoes judged against the moves the station sent (see app/machines/envelope.py).

Each axis of the stage runs on its own, so each has its own path, in
millimetres: from where it was last seen at rest through each ``MOVE_ABS`` and
``MOVE_REL`` sent.  An echoed position off that path (past the target, or
outside the travel) by more than the profile's tolerance is a stage doing what
nobody asked for.  Motion the station cannot place releases the path until the
axis is next seen at rest: a jog (it runs while held, as far as the operator
holds it), homing (to its switch), a stop (it brakes where it is),
``SET_POS`` (its position redefined).
"""

from __future__ import annotations

from collections.abc import Sequence

from app.machine import MachineModel
from app.machines.envelope import Envelope
from app.machines.motion_gate import MotionGate
from app.machines.supervision import MotionFault, fault_text
from protocol.stage.codec import MOVING_STATUSES, CommandId, CommandPacket, EchoFrame, EchoType

_RELEASES = frozenset(
    {CommandId.JOG, CommandId.HOME, CommandId.STOP, CommandId.ESTOP, CommandId.SET_POS}
)


class StageSupervisor:
    """One path per axis, fed with the packets sent and judged on the positions echoed."""

    def __init__(self, model: MachineModel, gate: MotionGate) -> None:
        self.model = model
        tolerance = model.profile.supervision_tolerance_mm
        self.paths = [
            Envelope([gate.limits(axis)], tolerance, hold_at_rest=False)
            for axis in range(len(model.axes))
        ]

    def release(self) -> None:
        """Nothing known of where the axes go (a new link, a stop after a fault)."""
        for path in self.paths:
            path.release()

    def sent(self, packets: Sequence[CommandPacket]) -> None:
        """A frame went out: its motion packets join (or release) their axis's path."""
        for axis, packet in enumerate(packets[: len(self.paths)]):
            path = self.paths[axis]
            command = packet.command
            if command in _RELEASES and not (command == CommandId.JOG and packet.data == 0):
                path.release()
                continue
            end = path.end
            if end is None or command not in (CommandId.MOVE_ABS, CommandId.MOVE_REL):
                continue
            if command == CommandId.MOVE_REL and path.in_flight:
                # Counted by the stage from where it is when the packet lands, somewhere on
                # the way: judged again once the axis is seen at rest.
                path.release()
                continue
            mm = packet.data / 1000
            target = mm if command == CommandId.MOVE_ABS else end[0] + mm
            name = self.model.axes[axis].name
            kind = "MOVE_ABS" if command == CommandId.MOVE_ABS else "MOVE_REL"
            path.add_line((target,), f"{name} {kind} {mm:.3f} mm")

    def judge(self, echo: EchoFrame) -> MotionFault | None:
        """The first position of ``echo`` off its axis's path, as a fault (None: all fit)."""
        for axis, packet in enumerate(echo.packets[: len(self.paths)]):
            if packet.type != EchoType.POSITION:
                continue
            path = self.paths[axis]
            here = (packet.data / 1000,)
            still = packet.status not in MOVING_STATUSES
            if not path.known:
                if still:
                    path.anchor(here)  # seen at rest: the moves sent from now on start here
                continue
            deviation = path.check(here)
            if deviation is not None:
                self.release()  # one stop, one message: judged again once at rest
                name = self.model.axes[axis].name
                return MotionFault(fault_text(deviation, [name]))
            end = path.end
            if still and end is not None and abs(here[0] - end[0]) <= path.tolerance:
                path.anchor(here)  # arrived and standing: at rest there
        return None
