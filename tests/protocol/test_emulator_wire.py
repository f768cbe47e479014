"""``--baud``: the emulator's pty carries bytes no faster than a serial line would."""

from __future__ import annotations

import pytest

from protocol.emulator.wire import MAX_CREDIT_BYTES, PacedWire


def test_credit_grows_at_a_tenth_of_the_baud_rate_and_is_capped() -> None:
    wire = PacedWire(115200, now=0.0)
    assert wire.readable(0.0) == 0
    assert wire.readable(0.001) == 11  # 11.52 bytes a millisecond at 115200 baud
    wire.took(11)
    assert wire.readable(0.001) == 0  # spent; nothing new without time passing
    assert wire.readable(10.0) == MAX_CREDIT_BYTES  # an idle line is no burst reservoir
    assert wire.writable(0.0005) == 5  # the other direction has its own credit


def test_a_byte_rate_is_kept_over_a_long_transfer() -> None:
    wire = PacedWire(9600, now=0.0)
    moved = 0
    t = 0.0
    while t < 2.0:
        t += 0.0003
        n = wire.readable(t)
        wire.took(n)
        moved += n
    assert moved == pytest.approx(1920, abs=MAX_CREDIT_BYTES)  # 960 bytes/s for 2 s


def test_a_wire_needs_a_speed() -> None:
    with pytest.raises(ValueError):
        PacedWire(0, now=0.0)


class _Recorder:
    """A firmware stand-in that only records what the wire delivered to it."""

    def __init__(self) -> None:
        self.got = bytearray()

    def set_output(self, sink: object) -> None:
        pass

    def receive(self, data: bytes) -> None:
        self.got += data

    def run_until(self, t: float) -> None:
        pass


def test_a_paced_line_woken_once_a_cycle_delivers_at_the_wire_rate_not_faster(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The serving loop wakes per control cycle, not per byte: bytes waiting on the line
    count their whole time (no 16-byte cap between wakes), and never more than the rate."""
    from protocol.emulator import pty as emulator

    now = [100.0]
    monkeypatch.setattr(emulator.time, "monotonic", lambda: now[0])
    line = emulator.PacedLine(PacedWire(115200, now=now[0]))
    firmware = _Recorder()
    line.inbound += b"G1 X12.34 Y56.78\n" * 20  # 340 bytes written at once
    delivered = []
    for _ in range(6):  # six 5 ms cycles: 57.6 bytes each at 11 520 bytes/s
        line.deliver(firmware)
        delivered.append(len(firmware.got))
        now[0] += 0.005
    assert delivered[0] == 0  # nothing has crossed the wire yet
    # The wire's pace (57.6 bytes a cycle), not 16 bytes a wake, and never ahead of it.
    assert all(57.6 * k - 1 <= got <= 57.6 * k for k, got in enumerate(delivered))
    now[0] += 10.0
    line.deliver(firmware)
    assert len(firmware.got) == 340  # the rest, once its time has passed


def test_an_idle_paced_line_is_still_no_burst_reservoir(monkeypatch: pytest.MonkeyPatch) -> None:
    from protocol.emulator import pty as emulator

    now = [100.0]
    monkeypatch.setattr(emulator.time, "monotonic", lambda: now[0])
    line = emulator.PacedLine(PacedWire(115200, now=now[0]))
    firmware = _Recorder()
    now[0] += 10.0  # the line idle for 10 s, then 100 bytes written
    line.inbound += bytes(100)
    line.deliver(firmware)
    assert len(firmware.got) == MAX_CREDIT_BYTES
