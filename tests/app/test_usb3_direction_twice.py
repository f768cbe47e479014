"""A ``D`` that turns an axis round goes twice, so one copy lost on the wire reverses nothing."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.machines.supervision import MotionFault
from app.machines.usb3.direction_twice import with_reversals_twice
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from protocol.usb3.codec import AxisId, Move, SetDirection, StepSize, move_commands
from tests.helpers.harness import StationHarness

Y = 1


def test_only_a_direction_that_turns_a_moving_axis_round_is_doubled() -> None:
    down = move_commands([0, -3200, 0])
    assert with_reversals_twice(down, (1, 1, 1)) == [down[0], *down]
    assert with_reversals_twice(down, (1, -1, 1)) == down  # Y already goes down
    # X turns round in the register, but no move of X follows: nothing a loss could reverse.
    assert with_reversals_twice(down, (-1, -1, 1)) == down
    # A question (a move of nothing) has no direction to lose.
    question = [SetDirection((1, 1, 1)), Move(AxisId.Y, 0)]
    assert with_reversals_twice(question, (1, -1, 1)) == question
    # Each D is judged against the one before it, in the same batch too.
    batch = [
        SetDirection((1, -1, 1)),
        Move(AxisId.Y, 8),
        SetDirection((1, 1, 1)),
        Move(AxisId.Y, 8),
    ]
    doubled = with_reversals_twice(batch, (1, 1, 1))
    assert doubled == [batch[0], batch[0], batch[1], batch[2], batch[2], batch[3]]


@pytest.fixture
def unit(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("usb3"))
    harness.connect()
    harness.run(0.5)
    yield harness
    harness.close()


def test_a_direction_mangled_on_the_way_still_leaves_the_move_its_way(
    unit: StationHarness,
) -> None:
    """The relay's seed 98: ``D+-+;`` arrived as ``L+-+;`` (one bit), the unit answered
    ``?;`` and Y's move ran upward, stopped 0.027 mm the wrong way.  The copy sets it."""
    session, firmware = unit.usb3_session, unit.usb3_emulator
    faults: list[MotionFault] = []
    session.motionFault.connect(faults.append)
    session.set_step_size(Y, StepSize.FULL)
    unit.run(0.3)
    assert session.move_relative(Y, 1.0)
    unit.run_until(lambda: unit.station.model.axes[Y].position == 1.0, timeout=10.0)
    unit.run(0.5)
    start = firmware.positions[Y]
    mangled = False

    def noisy_cable(direction: Direction, data: bytes) -> bytes:
        nonlocal mangled
        if direction is Direction.TO_DEVICE and b"D+-+;" in data and not mangled:
            mangled = True
            return data.replace(b"D+-+;", b"L+-+;", 1)
        return data

    unit.loopback.set_manipulator(noisy_cable)
    rejected = firmware.rejected
    assert session.move_relative(Y, -0.5)
    unit.run_until(lambda: firmware.positions[Y] == start - 3200, timeout=10.0)
    unit.run(1.0)
    assert mangled and firmware.rejected == rejected + 1  # the unit said ?; for the copy lost
    assert firmware.positions[Y] == start - 3200  # down, as sent, and no farther
    assert faults == []
