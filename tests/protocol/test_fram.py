"""The emulated FRAM: documented addresses, LSB-first words, the shared current register."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.emulator.fram import Fram
from protocol.stage.codec import EchoType


@pytest.fixture
def fram() -> Fram:
    return Fram(axes=2)


def test_addresses_follow_the_documented_map(fram: Fram) -> None:
    """FIDELITY S3-14: the original stores the acceleration from address 0x0000."""
    assert fram.address_of(0, EchoType.ACCELERATION) == 0x00
    assert fram.address_of(0, EchoType.FAST_SPEED) == 0x08
    assert fram.address_of(0, EchoType.SLOW_SPEED) == 0x04
    assert fram.address_of(1, EchoType.ACCELERATION) == 0x40
    assert fram.address_of(1, EchoType.TRAVEL) == 0x64
    assert fram.address_of(0, EchoType.IRUN) == fram.address_of(0, EchoType.IHOLD) == 0x10


def test_encoder_and_missing_axes_have_no_address(fram: Fram) -> None:
    with pytest.raises(ValueError):
        fram.address_of(0, EchoType.ENCODER)
    with pytest.raises(ValueError):
        fram.address_of(2, EchoType.FAST_SPEED)


def test_words_are_stored_lsb_first(fram: Fram) -> None:
    assert fram.write(1, EchoType.ACCELERATION, 20000)
    assert fram.dump(0x40, 4) == bytes([0x20, 0x4E, 0x00, 0x00])
    assert fram.read(1, EchoType.ACCELERATION) == 20000
    assert fram.read(0, EchoType.ACCELERATION) == 0


def test_irun_write_keeps_ihold_and_ihold_delay(fram: Fram) -> None:
    assert fram.write(0, EchoType.IHOLD, 8)
    assert fram.write(0, EchoType.IRUN, 12)
    assert fram.read(0, EchoType.IHOLD) == 8
    assert fram.read(0, EchoType.IRUN) == 12
    # IHOLD bits 0-4 = 8, IRUN bits 8-12 = 12, IHOLDDELAY bits 16-19 = 6
    assert fram.ihold_irun(0) == 0x06_0C_08
    assert fram.dump(0x10, 4) == bytes([0x08, 0x0C, 0x06, 0x00])


def test_currents_that_do_not_fit_five_bits_are_refused(fram: Fram) -> None:
    with pytest.raises(ValueError):
        fram.write(0, EchoType.IRUN, 32)


def test_verification_fault_undoes_the_write(fram: Fram) -> None:
    assert fram.write(0, EchoType.FAST_SPEED, 10000)
    before = fram.dump(0, 0x40)
    fram.verification_fault = True
    assert not fram.write(0, EchoType.FAST_SPEED, 12345)
    assert not fram.write(0, EchoType.IRUN, 31)
    assert fram.dump(0, 0x40) == before
    assert fram.read(0, EchoType.FAST_SPEED) == 10000
    fram.verification_fault = False
    assert fram.write(0, EchoType.FAST_SPEED, 12345)
    assert fram.read(0, EchoType.FAST_SPEED) == 12345


@given(
    axis=st.integers(0, 1),
    parameter=st.sampled_from([t for t in EchoType if EchoType.FAST_SPEED <= t <= EchoType.TRAVEL]),
    value=st.integers(0, 999_999),
)
def test_any_write_reads_back_and_touches_only_its_own_word(
    axis: int, parameter: EchoType, value: int
) -> None:
    fram = Fram(axes=2)
    if parameter in (EchoType.IRUN, EchoType.IHOLD):
        value %= 32
    address = fram.address_of(axis, parameter)
    before = fram.dump(0, len(fram.memory))
    assert fram.write(axis, parameter, value)
    assert fram.read(axis, parameter) == value
    after = fram.dump(0, len(fram.memory))
    assert after[:address] == before[:address]
    assert after[address + 4 :] == before[address + 4 :]
