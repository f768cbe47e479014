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
