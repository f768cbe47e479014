"""Why a usb3 move sent to a farther target than the station's cannot be stopped short of it.

The unit takes relative moves and adds a repeated one to its target; the
wire has no checksum, so a move that arrives twice, or with a digit changed,
runs to a farther target than the station sent.  The unit acknowledges no
move: all the station sees are the position reports (every 100 ms while an
axis moves).  Those of the farther move are the healthy move's, byte for byte,
until the healthy one would start braking onto its target — and from there,
braking as hard as the unit can (``S;``), it stops past the target.  So no
rule over the reports (the braking distance, the speed, the target) can stop
it on the target's side; the best is the first report that shows it is not
braking, which is what this shows on the emulated unit (docs/link-faults.md).
"""

from __future__ import annotations

import pytest

from protocol.clock import ManualClock
from protocol.emulator.usb3_firmware import Usb3Firmware
from protocol.usb3.codec import AxisId, Command, Move, SetDirection, StopAll, encode

CYCLE = 0.005
#: From top speed (300 pulses/s) to the start speed (9.375) at 600 pulses/s², in counts at
#: 1/8 step (4 counts a pulse): (300² - 9.375²) / 1200 pulses.
BRAKING_COUNTS = (300.0**2 - 9.375**2) / 1200 * 4


class Unit:
    def __init__(self) -> None:
        self.clock = ManualClock(start=100.0)
        self.fw = Usb3Firmware(self.clock)
        self.out = bytearray()
        self.fw.set_output(self.out.extend)

    def send(self, *commands: Command) -> None:
        self.fw.receive(b"".join(encode(c) for c in commands))

    def cycle(self) -> bytes:
        self.clock.advance(CYCLE)
        self.fw.run_until(self.clock.now())
        sent = bytes(self.out)
        self.out.clear()
        return sent


def _reports(count: int, cycles: int) -> list[bytes]:
    unit = Unit()
    unit.send(SetDirection((1, 1, 1)), Move(AxisId.X, count))
    return [unit.cycle() for _ in range(cycles)]


@pytest.mark.parametrize("sent", [1600, 3200, 4800])
@pytest.mark.parametrize("ran", ["twice", "a digit changed"])
def test_a_farther_target_reports_the_same_bytes_until_the_move_sent_would_brake(
    sent: int, ran: str
) -> None:
    farther = 2 * sent if ran == "twice" else sent + 1_000_000_000
    healthy, wrong = _reports(sent, 1000), _reports(farther, 1000)
    differ = next(i for i, (a, b) in enumerate(zip(healthy, wrong, strict=True)) if a != b)
    # Up to there the station could not tell them apart; the healthy move was already
    # within its braking distance of the target (the unit had started braking onto it).
    unit = Unit()
    unit.send(SetDirection((1, 1, 1)), Move(AxisId.X, sent))
    for _ in range(differ):
        unit.cycle()
    assert unit.fw.positions[0] > sent - BRAKING_COUNTS
    # The farther move, stopped as early as anything could tell (S; in the very cycle after
    # the first report that differs, no time for the wire or the station), ends past it.
    unit = Unit()
    unit.send(SetDirection((1, 1, 1)), Move(AxisId.X, farther))
    for _ in range(differ + 1):
        unit.cycle()
    unit.send(StopAll())
    for _ in range(400):
        unit.cycle()
    assert not unit.fw.moving(AxisId.X)
    assert sent < unit.fw.positions[0] < sent + BRAKING_COUNTS
