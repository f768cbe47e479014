"""The fault relay does to the bytes exactly the one fault it was given, and nothing else.

A pty pair stands in for the device; the test writes at the station's end
(the relay's link) and reads what the device gets, and the other way.
"""

from __future__ import annotations

import os
import select
import time
import tty
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from tests.helpers.fault_bridge import Direction
from tests.helpers.fault_relay import FAULT_KINDS, Fault, FaultKind, FaultRelay, random_fault

# The relay and the emulator sit on pseudo-terminals, which only POSIX systems have
# (Windows: see docs/manual/windows-macos.md); every Linux CI run has them.
pytestmark = pytest.mark.skipif(not hasattr(os, "openpty"), reason="no pseudo-terminals here")

MESSAGE = b"G1 X10 Y20\nG1 X30 Y40\nG1 X50 Y60\n"


class Cable:
    """A relay between a fake device (a pty pair) and the station's end (its link)."""

    def __init__(self, tmp_path: Path, fault: Fault | None) -> None:
        self.device_master, device_slave = os.openpty()
        tty.setraw(device_slave)
        tty.setraw(self.device_master)
        self.device_slave = device_slave
        self.relay = FaultRelay(
            os.ttyname(device_slave),
            tmp_path / "port",
            fault,
            to_device_end=b"\n",
            to_host_end=b"\n",
        )
        self.station = self.open_station()

    def open_station(self) -> int:
        fd = os.open(self.relay.link, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(fd)
        return fd

    def close(self) -> None:
        self.relay.close()
        for fd in (self.station, self.device_master, self.device_slave):
            try:
                os.close(fd)
            except OSError:
                pass


#: Bounds a wait for bytes that should come (a loaded machine is slow, never early).
ARRIVAL_S = 10.0
#: How long bytes that should not come are looked for: well inside the faults' times.
QUIET_S = 0.3


def read_for(fd: int, seconds: float, want: int | None = None) -> bytes:
    """What ``fd`` gives within ``seconds``, or as soon as ``want`` bytes are in."""
    got = b""
    deadline = time.monotonic() + seconds
    while (left := deadline - time.monotonic()) > 0 and (want is None or len(got) < want):
        if select.select([fd], [], [], left)[0]:
            try:
                got += os.read(fd, 4096)
            except OSError:
                break
    return got


def arrives(fd: int, count: int) -> bytes:
    """``count`` bytes (waited for), and anything else that follows at once."""
    return read_for(fd, ARRIVAL_S, count) + read_for(fd, QUIET_S)


def wait_until(condition: Callable[[], bool], what: str) -> None:
    deadline = time.monotonic() + ARRIVAL_S
    while not condition():
        assert time.monotonic() < deadline, what
        time.sleep(0.01)


@pytest.fixture
def cable(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[Cable]:
    built = Cable(tmp_path, request.param)
    yield built
    built.close()


def _to_device(kind: FaultKind, at: int, amount: float) -> Fault:
    return Fault(kind, Direction.TO_DEVICE, at, amount)


@pytest.mark.parametrize("cable", [None], indirect=True)
def test_without_a_fault_every_byte_arrives_both_ways(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    assert arrives(cable.device_master, len(MESSAGE)) == MESSAGE
    os.write(cable.device_master, b"ok\nok\n")
    assert arrives(cable.station, 6) == b"ok\nok\n"


@pytest.mark.parametrize("cable", [_to_device(FaultKind.DROP, 13, 4)], indirect=True)
def test_drop_loses_that_many_bytes_from_that_byte(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    assert arrives(cable.device_master, len(MESSAGE) - 4) == MESSAGE[:13] + MESSAGE[17:]


@pytest.mark.parametrize("cable", [_to_device(FaultKind.CORRUPT, 5, 0)], indirect=True)
def test_corrupt_flips_one_bit_of_that_byte(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    got = arrives(cable.device_master, len(MESSAGE))
    assert got == MESSAGE[:5] + bytes([MESSAGE[5] ^ 1]) + MESSAGE[6:]


@pytest.mark.parametrize("cable", [_to_device(FaultKind.DUPLICATE, 15, 0)], indirect=True)
def test_duplicate_sends_the_message_holding_that_byte_twice(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    twice = b"G1 X10 Y20\nG1 X30 Y40\nG1 X30 Y40\nG1 X50 Y60\n"
    assert arrives(cable.device_master, len(twice)) == twice


@pytest.mark.parametrize("cable", [_to_device(FaultKind.DELAY, 11, 3.0)], indirect=True)
def test_delay_holds_one_direction_then_lets_it_all_through_in_order(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    assert arrives(cable.device_master, 11) == MESSAGE[:11]
    os.write(cable.device_master, b"ok\n")  # the other way is not held
    assert arrives(cable.station, 3) == b"ok\n"
    assert arrives(cable.device_master, len(MESSAGE) - 11) == MESSAGE[11:]
    assert cable.relay.fired_at is not None and cable.relay.ended_at is not None
    assert cable.relay.ended_at - cable.relay.fired_at >= 3.0


@pytest.mark.parametrize("cable", [_to_device(FaultKind.SILENCE, 11, 3.0)], indirect=True)
def test_silence_carries_nothing_either_way_for_its_time(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    assert arrives(cable.device_master, 11) == MESSAGE[:11]
    os.write(cable.device_master, b"ok\n")
    assert read_for(cable.station, QUIET_S) == b""
    wait_until(lambda: cable.relay.ended_at is not None, "the silence never ended")
    os.write(cable.station, b"?\n")
    assert arrives(cable.device_master, 2) == b"?\n"


@pytest.mark.parametrize("cable", [_to_device(FaultKind.REOPEN, 11, 1.0)], indirect=True)
def test_reopen_pulls_the_port_and_brings_it_back_at_the_same_path(cable: Cable) -> None:
    os.write(cable.station, MESSAGE)
    assert arrives(cable.device_master, 11) == MESSAGE[:11]
    assert not cable.relay.link.exists()
    wait_until(cable.relay.link.exists, "the port never came back")
    os.close(cable.station)
    cable.station = cable.open_station()
    os.write(cable.station, b"?\n")
    assert arrives(cable.device_master, 2) == b"?\n"


def test_a_seed_names_one_fault_and_six_seeds_in_a_row_try_every_kind() -> None:
    traffic = {Direction.TO_DEVICE: 500, Direction.TO_HOST: 800}
    assert random_fault(17, traffic, "usb3") == random_fault(17, traffic, "usb3")
    assert {random_fault(s, traffic, "usb3").kind for s in range(6)} == set(FAULT_KINDS)
    for seed in range(60):
        fault = random_fault(seed, traffic, "xy-stage")
        assert 0 <= fault.at_byte < traffic[fault.direction]
        if fault.kind is FaultKind.DROP:
            assert 1 <= fault.amount <= 20
        elif fault.kind is FaultKind.DELAY:
            assert 2.0 <= fault.amount <= 5.0
        elif fault.kind is FaultKind.SILENCE:
            assert 3.0 <= fault.amount <= 8.0


def test_a_board_that_restarts_on_open_restarts_when_the_station_opens_the_port_again(
    tmp_path: Path,
) -> None:
    """As an Arduino (DTR): not as the port comes back, so its banner reaches the station."""
    old_master, old_slave = os.openpty()
    new_master, new_slave = os.openpty()
    for fd in (old_master, old_slave, new_master, new_slave):
        tty.setraw(fd)
    restarted: list[float] = []

    def restart() -> str:
        restarted.append(time.monotonic())
        os.write(new_master, b"Grbl 1.1h ['$' for help]\n")  # the new board's banner
        return os.ttyname(new_slave)

    relay = FaultRelay(
        os.ttyname(old_slave),
        tmp_path / "port",
        _to_device(FaultKind.REOPEN, 11, 1.0),
        to_device_end=b"\n",
        to_host_end=b"\n",
        on_reopen=restart,
        restart_on_open=True,
    )
    station = os.open(relay.link, os.O_RDWR | os.O_NOCTTY)
    try:
        tty.setraw(station)
        os.write(station, MESSAGE)
        assert arrives(old_master, 11) == MESSAGE[:11]
        wait_until(relay.link.exists, "the port never came back")
        os.write(old_master, b"ok\n")  # the old board runs on, unheard
        assert read_for(station, QUIET_S) == b""
        assert restarted == [] and relay.restarts == 0  # back, but nobody opened it yet
        os.close(station)
        station = os.open(relay.link, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(station)
        assert arrives(station, 25) == b"Grbl 1.1h ['$' for help]\n"
        assert len(restarted) == 1 and relay.restarts == 1
        os.write(station, b"?\n")
        assert arrives(new_master, 2) == b"?\n"
    finally:
        relay.close()
        for fd in (station, old_master, old_slave, new_master, new_slave):
            try:
                os.close(fd)
            except OSError:
                pass
