"""The BLE transport against a fake bleak client backed by the real stage firmware.

Notifications arrive on the BLE loop thread as they would from bleak, so
every wait here is bounded on a condition (no sleeps), and every test ends
with the loop thread gone — the autouse fixture fails it otherwise.
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Callable, Iterator

import pytest
from bleak.exc import (
    BleakBluetoothNotAvailableError,
    BleakBluetoothNotAvailableReason,
    BleakCharacteristicNotFoundError,
    BleakDBusError,
    BleakDeviceNotFoundError,
    BleakError,
)

from protocol.clock import ManualClock
from protocol.emulator.stage_firmware import StageFirmware
from protocol.stage.codec import (
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoPacket,
    EchoType,
    Frame,
    Rejected,
    StageDecoder,
    echo_frame_length,
    encode_command,
    encode_echo,
)
from protocol.transport.base import open_transports
from protocol.transport.ble import (
    LOOP_STOPPED_MESSAGE,
    MICROCHIP_UART,
    NO_ADAPTER_MESSAGE,
    NORDIC_UART,
    BleDevice,
    BleLinkError,
    BleLoop,
    BleTransport,
    BleUuids,
    describe_ble_error,
    scan,
)
from tests.helpers.fake_bleak import WAIT_S, FakePeripheral, FakeRadio, wait_until

STAGE = "C0:FF:EE:00:00:01"
NOT_FOUND = "No XY-STAGE device found — is it powered and advertising?"


def read(parameter: EchoType) -> bytes:
    """A 23-byte command frame asking both axes for one parameter."""
    packet = CommandPacket(CommandId.READ, parameter)
    return encode_command(CommandFrame((packet, packet)))


class Listener:
    """Records what the transport reports and decodes the byte stream as the session would."""

    def __init__(self) -> None:
        self.changed = threading.Condition()
        self.events: list[str] = []
        self.lost: list[str | None] = []
        self.chunks: list[bytes] = []
        self.frames: list[Frame | Rejected] = []
        self.threads: set[str] = set()
        self._decoder = StageDecoder()

    def connection_made(self) -> None:
        self._record("made")

    def data_received(self, data: bytes) -> None:
        with self.changed:
            self.chunks.append(data)
            self.frames.extend(self._decoder.feed(data))
        self._record("data")

    def connection_lost(self, reason: str | None) -> None:
        with self.changed:
            self.lost.append(reason)
        self._record("lost")

    def _record(self, event: str) -> None:
        with self.changed:
            self.events.append(event)
            self.threads.add(threading.current_thread().name)
            self.changed.notify_all()

    def wait(self, predicate: Callable[[], bool]) -> bool:
        return wait_until(self.changed, predicate)

    def wait_made(self, times: int = 1) -> bool:
        return self.wait(lambda: self.events.count("made") >= times)

    def wait_lost(self, times: int = 1) -> bool:
        return self.wait(lambda: len(self.lost) >= times)

    def wait_frames(self, count: int) -> bool:
        return self.wait(lambda: len(self.frames) >= count)


class Bench:
    """A stage (firmware on a manual clock) behind a fake BLE module, and a transport to it."""

    def __init__(
        self, *, max_write: int | None = 20, notify_size: int = 20, frames_per_notification: int = 1
    ) -> None:
        self.clock = ManualClock(start=10.0)
        self.firmware = StageFirmware(self.clock)
        self.stage = FakePeripheral(
            STAGE,
            firmware=self.firmware,
            max_write=max_write,
            notify_size=notify_size,
            frames_per_notification=frames_per_notification,
        )
        self.radio = FakeRadio(self.stage)
        self.listener = Listener()
        self.transport: BleTransport | None = None

    def make(
        self,
        address: str | None = STAGE,
        *,
        loop: BleLoop | None = None,
        connect_timeout: float = 5.0,
    ) -> BleTransport:
        self.transport = BleTransport(
            address,
            MICROCHIP_UART,
            name_prefix="XY-STAGE",
            loop=loop,
            client_factory=self.radio.client_factory,
            scanner=self.radio.scanner,
            connect_timeout=connect_timeout,
        )
        self.transport.set_listener(self.listener)
        return self.transport

    def connect(self, address: str | None = STAGE) -> BleTransport:
        transport = self.make(address)
        transport.open()
        assert self.listener.wait_made(), self.listener.lost
        return transport

    def exchange(self, *frames: bytes) -> None:
        """Write command frames and run the firmware until it has answered all of them."""
        assert self.transport is not None
        before = sum(map(len, self.stage.chunks))
        for frame in frames:
            self.transport.write(frame)
        assert self.stage.wait_received(before + sum(map(len, frames)))
        self.firmware.run_until(self.clock.advance(0.01))


@pytest.fixture
def bench() -> Iterator[Bench]:
    bench = Bench()
    yield bench
    if bench.transport is not None:
        bench.transport.close()


@pytest.fixture
def ble_loop() -> Iterator[BleLoop]:
    loop = BleLoop()
    yield loop
    assert loop.stop()


def ble_threads() -> list[str]:
    return [t.name for t in threading.enumerate() if t.name == "ble-loop"]


# --- the loop thread --------------------------------------------------------------------


async def answer(value: int) -> int:
    return value


def test_loop_runs_coroutines_on_its_own_thread_and_stops_cleanly() -> None:
    loop = BleLoop()

    async def where() -> str:
        return threading.current_thread().name

    assert not loop.running and not ble_threads()
    assert loop.submit(where()).result(timeout=WAIT_S) == "ble-loop"
    assert loop.stop()
    assert not loop.running and not ble_threads()
    # A stopped loop starts again on demand (the station reopens after a close).
    assert loop.submit(answer(7)).result(timeout=WAIT_S) == 7
    assert loop.stop()
    assert loop.stop(), "stopping twice is harmless"
    assert not ble_threads()


def test_stopping_the_loop_cancels_what_still_runs(ble_loop: BleLoop) -> None:
    import asyncio

    started = threading.Event()

    async def forever() -> None:
        started.set()
        await asyncio.Event().wait()

    future = ble_loop.submit(forever())
    assert started.wait(WAIT_S)
    assert ble_loop.stop()
    assert future.cancelled()
    assert not ble_loop.call_soon(print), "nothing runs on a stopped loop"


# --- scanning --------------------------------------------------------------------------


def test_scan_keeps_stages_by_service_or_name_strongest_first(ble_loop: BleLoop) -> None:
    radio = FakeRadio(
        FakePeripheral("00:00:00:00:00:0A", "bridge-a", -70),  # advertises the service
        FakePeripheral("00:00:00:00:00:0B", "XY-STAGE-2", -40, advertised_uuids=()),
        FakePeripheral("00:00:00:00:00:0C", "headphones", -30, advertised_uuids=("180f",)),
        FakePeripheral("00:00:00:00:00:0D", None, -55),  # no name, but the service
        FakePeripheral("00:00:00:00:00:0E", "nordic", -20, advertised_uuids=(NORDIC_UART.service,)),
    )
    results: list[list[BleDevice] | str] = []
    done = threading.Event()

    def on_done(result: list[BleDevice] | str) -> None:
        results.append(result)
        done.set()

    future = scan(
        ble_loop,
        uuids=MICROCHIP_UART,
        name_prefix="XY-STAGE",
        timeout=0.1,
        on_done=on_done,
        scanner=radio.scanner,
    )
    assert done.wait(WAIT_S)
    assert results == [
        [
            BleDevice("XY-STAGE-2", "00:00:00:00:00:0B", -40),
            BleDevice("", "00:00:00:00:00:0D", -55),
            BleDevice("bridge-a", "00:00:00:00:00:0A", -70),
        ]
    ]
    assert future.result(timeout=WAIT_S) == results[0]


def test_service_uuids_match_whatever_their_case(ble_loop: BleLoop) -> None:
    radio = FakeRadio(
        FakePeripheral("00:00:00:00:00:0A", "n", -50, advertised_uuids=(NORDIC_UART.service,))
    )
    result = scan(
        ble_loop,
        uuids=BleUuids(NORDIC_UART.service.lower(), NORDIC_UART.write, NORDIC_UART.notify),
        name_prefix="",
        timeout=0.1,
        on_done=lambda _: None,
        scanner=radio.scanner,
    ).result(timeout=WAIT_S)
    assert result == [BleDevice("n", "00:00:00:00:00:0A", -50)]


def test_scan_without_an_adapter_reports_the_fix_and_leaves_no_thread() -> None:
    radio = FakeRadio()
    radio.adapter_error = FileNotFoundError(2, "No such file or directory")
    loop = BleLoop()
    results: list[list[BleDevice] | str] = []
    done = threading.Event()

    def on_done(result: list[BleDevice] | str) -> None:
        results.append(result)
        done.set()

    scan(
        loop,
        uuids=MICROCHIP_UART,
        name_prefix="XY-STAGE",
        timeout=0.1,
        on_done=on_done,
        scanner=radio.scanner,
    )
    assert done.wait(WAIT_S)
    assert results == [NO_ADAPTER_MESSAGE]
    assert loop.stop()
    assert not ble_threads()


# --- connecting ------------------------------------------------------------------------


def test_a_given_address_is_connected_straight_away_without_scanning(bench: Bench) -> None:
    transport = bench.connect(STAGE)
    assert bench.radio.scans == 0
    assert [c.address for c in bench.radio.clients] == [STAGE]
    assert transport.is_open
    assert transport.describe() == f"BLE {STAGE}"
    assert bench.listener.events == ["made"]
    assert bench.listener.threads == {"ble-loop"}


def test_without_an_address_the_strongest_stage_is_taken(bench: Bench) -> None:
    far = FakePeripheral("C0:FF:EE:00:00:02", "XY-STAGE-02", -80)
    bench.radio.peripherals[far.address] = far
    transport = bench.make(None)
    assert transport.describe() == "BLE XY-STAGE"
    transport.open()
    assert bench.listener.wait_made()
    assert bench.radio.scans == 1
    assert bench.stage.client is not None and far.client is None
    assert transport.describe() == "BLE XY-STAGE-01"
    assert transport.device == BleDevice("XY-STAGE-01", STAGE, -60)


def test_no_stage_in_range_is_reported_as_not_found(bench: Bench) -> None:
    bench.radio.peripherals.clear()
    bench.make(None).open()
    assert bench.listener.wait_lost()
    assert bench.listener.lost == [NOT_FOUND]
    assert bench.listener.events == ["lost"]


@pytest.mark.parametrize(
    ("setup", "message"),
    [
        pytest.param(
            lambda b: setattr(b.radio, "adapter_error", FileNotFoundError(2, "No such file")),
            NO_ADAPTER_MESSAGE,
            id="no-system-bus",
        ),
        pytest.param(
            lambda b: setattr(
                b.radio,
                "adapter_error",
                BleakBluetoothNotAvailableError(
                    "No Bluetooth adapters found.", BleakBluetoothNotAvailableReason.NO_BLUETOOTH
                ),
            ),
            NO_ADAPTER_MESSAGE,
            id="no-adapter",
        ),
        pytest.param(lambda b: b.radio.peripherals.clear(), NOT_FOUND, id="unknown-address"),
        pytest.param(
            lambda b: setattr(b.stage, "has_uart", False),
            f"Device has no transparent-UART service {MICROCHIP_UART.service}",
            id="no-uart-service",
        ),
    ],
)
def test_a_failed_connect_is_one_clear_line(
    bench: Bench, setup: Callable[[Bench], None], message: str
) -> None:
    setup(bench)
    transport = bench.make()
    transport.open()
    assert bench.listener.wait_lost()
    assert bench.listener.lost == [message]
    assert bench.listener.events == ["lost"]
    assert not transport.is_open
    transport.close()
    assert bench.listener.lost == [message], "a finished attempt is not reported again"
    assert not ble_threads()


def test_a_connect_that_hangs_times_out(bench: Bench) -> None:
    bench.radio.hang_connect = True
    bench.make(connect_timeout=0.05).open()
    assert bench.listener.wait_lost()
    assert bench.listener.lost == [
        "Connecting timed out — is the device in range and not connected to another host?"
    ]


# --- carrying bytes --------------------------------------------------------------------


@pytest.mark.parametrize(
    ("notify_size", "frames_per_notification"),
    [
        pytest.param(20, 1, id="each-echo-in-20-byte-pieces"),
        pytest.param(244, 2, id="two-echoes-per-notification"),
        pytest.param(20, 3, id="pieces-straddling-echoes"),
    ],
)
def test_echoes_reach_the_listener_whole_and_in_order(
    notify_size: int, frames_per_notification: int
) -> None:
    bench = Bench(notify_size=notify_size, frames_per_notification=frames_per_notification)
    try:
        bench.connect()
        asked = [EchoType.FAST_SPEED, EchoType.SLOW_SPEED, EchoType.ACCELERATION]
        asked = asked[: max(2, frames_per_notification)]
        bench.exchange(*(read(p) for p in asked))
        assert bench.listener.wait_frames(len(asked))
        frames = bench.listener.frames
        assert all(isinstance(f, EchoFrame) for f in frames), frames
        echoes = [f for f in frames if isinstance(f, EchoFrame)]
        assert [e.packets[0].type for e in echoes] == asked
        assert [e.packets[1].data for e in echoes] == [
            bench.firmware.parameter(1, p) for p in asked
        ]
        # The link really did cut and glue: the listener saw the notifications as sent.
        assert bench.listener.chunks == bench.stage.notifications
        assert all(len(n) <= notify_size for n in bench.stage.notifications)
        chunks = bench.listener.chunks
        if notify_size < echo_frame_length(2):
            assert len(chunks) > len(asked), "echoes were cut into pieces"
        if frames_per_notification == 2:
            assert chunks[0].count(b"\n") == 2, "two whole echoes in one notification"
        if frames_per_notification == 3:
            assert any(b"\n" in c[:-1] for c in chunks), "an echo ends mid-notification"
    finally:
        if bench.transport is not None:
            bench.transport.close()


@pytest.mark.parametrize(
    ("max_write", "sizes"),
    [
        pytest.param(20, [20, 3, 20, 3], id="20-bytes"),
        pytest.param(None, [20, 3, 20, 3], id="unknown-falls-back-to-20"),
        pytest.param(0, [20, 3, 20, 3], id="zero-falls-back-to-20"),
        pytest.param(64, [23, 23], id="large-mtu"),
    ],
)
def test_writes_go_out_in_order_in_chunks_the_link_takes(
    max_write: int | None, sizes: list[int]
) -> None:
    bench = Bench(max_write=max_write)
    try:
        bench.connect()
        first, second = read(EchoType.FAST_SPEED), read(EchoType.TRAVEL)
        assert len(first) == 23
        bench.exchange(first, second)
        assert [len(c) for c in bench.stage.chunks] == sizes
        assert bench.stage.received() == first + second
        assert bench.stage.write_modes == [False] * len(sizes), "write without response"
    finally:
        if bench.transport is not None:
            bench.transport.close()


def test_bytes_notified_while_subscribing_follow_connection_made() -> None:
    bench = Bench()
    bench.stage.greeting = encode_echo(EchoFrame((EchoPacket(0, 0, 0), EchoPacket(0, 0, 0))))
    try:
        bench.connect()
        assert bench.listener.wait_frames(1)
        assert bench.listener.events == ["made", "data"]
        assert isinstance(bench.listener.frames[0], EchoFrame)
    finally:
        if bench.transport is not None:
            bench.transport.close()


def test_writes_before_the_connection_are_dropped(bench: Bench) -> None:
    bench.radio.hang_connect = True
    transport = bench.make()
    transport.write(read(EchoType.FAST_SPEED))
    transport.open()
    transport.write(read(EchoType.FAST_SPEED))
    transport.close()
    assert bench.stage.chunks == []


# --- losing and regaining the link ---------------------------------------------------------


def test_a_drop_is_reported_once_and_open_reconnects_with_a_fresh_client(bench: Bench) -> None:
    transport = bench.connect()
    bench.stage.drop()
    assert bench.listener.wait_lost()
    assert bench.listener.lost == [f"Bluetooth link to {STAGE} lost"]
    assert not transport.is_open
    transport.write(read(EchoType.FAST_SPEED))  # dropped silently

    transport.open()
    assert bench.listener.wait_made(2)
    assert len(bench.radio.clients) == 2
    assert bench.radio.clients[0] is not bench.radio.clients[1]
    bench.exchange(read(EchoType.SLOW_SPEED))
    assert bench.listener.wait_frames(1)
    (echo,) = bench.listener.frames
    assert isinstance(echo, EchoFrame) and echo.packets[0].type == EchoType.SLOW_SPEED
    assert bench.listener.events.count("lost") == 1
    assert bench.listener.events[:3] == ["made", "lost", "made"]


def test_a_failing_write_ends_the_link_once(bench: Bench) -> None:
    transport = bench.connect()
    bench.stage.write_error = BleakError("Write failed: Not connected")
    transport.write(read(EchoType.FAST_SPEED))
    assert bench.listener.wait_lost()
    assert bench.listener.lost == ["Bluetooth error: Write failed: Not connected"]
    # The client is disconnected as the attempt unwinds; its callback adds nothing.
    assert bench.stage.wait_client(connected=False)
    transport.close()
    assert bench.listener.lost == ["Bluetooth error: Write failed: Not connected"]


def test_reopening_while_connected_does_nothing(bench: Bench) -> None:
    transport = bench.connect()
    transport.open()
    bench.exchange(read(EchoType.FAST_SPEED))
    assert bench.listener.wait_frames(1)
    assert len(bench.radio.clients) == 1
    assert bench.listener.events.count("made") == 1


# --- closing ---------------------------------------------------------------------------------


def test_close_disconnects_reports_once_and_leaves_nothing_behind(bench: Bench) -> None:
    transport = bench.connect()
    assert open_transports() == [transport]
    transport.close()
    assert bench.listener.lost == [None]
    assert bench.stage.client is None, "the owned loop finished the disconnect before stopping"
    assert not transport.is_open
    assert open_transports() == []
    assert not ble_threads()
    transport.close()
    assert bench.listener.lost == [None], "close is idempotent"


def test_close_while_still_connecting_ends_the_attempt(bench: Bench) -> None:
    bench.radio.hang_connect = True
    transport = bench.make()
    transport.open()
    transport.close()
    assert bench.listener.lost == [None]
    assert bench.listener.events == ["lost"]
    assert not ble_threads()


def test_a_closed_transport_can_be_opened_again(bench: Bench) -> None:
    transport = bench.connect()
    transport.close()
    transport.open()
    assert bench.listener.wait_made(2)
    bench.exchange(read(EchoType.FAST_SPEED))
    assert bench.listener.wait_frames(1)


def test_a_shared_loop_outlives_the_transport(ble_loop: BleLoop) -> None:
    bench = Bench()
    transport = bench.make(loop=ble_loop)
    transport.open()
    assert bench.listener.wait_made()
    bench.exchange(read(EchoType.FAST_SPEED))  # its echo is on its way as we close
    transport.close()
    events_at_close = list(bench.listener.events)
    assert bench.listener.lost == [None]
    assert ble_loop.running, "the app's loop is the app's to stop"
    # The disconnect runs on the loop after the echo's notifications were handled there.
    assert bench.stage.wait_client(connected=False)
    assert bench.listener.events == events_at_close, "nothing reaches the listener after close"
    assert events_at_close[-1] == "lost"


def test_a_loop_stopped_under_a_live_link_ends_it_once(ble_loop: BleLoop) -> None:
    bench = Bench()
    transport = bench.make(loop=ble_loop)
    transport.open()
    assert bench.listener.wait_made()
    assert ble_loop.stop()
    assert bench.listener.lost == [LOOP_STOPPED_MESSAGE]
    assert not transport.is_open
    transport.close()
    assert bench.listener.lost == [LOOP_STOPPED_MESSAGE]


# --- errors in one line ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("exc", "message"),
    [
        (FileNotFoundError(2, "No such file or directory"), NO_ADAPTER_MESSAGE),
        (ConnectionRefusedError(111, "Connection refused"), NO_ADAPTER_MESSAGE),
        (BleakError("No Bluetooth adapters found."), NO_ADAPTER_MESSAGE),
        (
            BleakBluetoothNotAvailableError(
                "No powered Bluetooth adapters found.",
                BleakBluetoothNotAvailableReason.POWERED_OFF,
            ),
            NO_ADAPTER_MESSAGE,
        ),
        (
            BleakBluetoothNotAvailableError(
                "Bluetooth access denied", BleakBluetoothNotAvailableReason.DENIED_BY_SYSTEM
            ),
            "Bluetooth access was denied: Bluetooth access denied",
        ),
        (
            BleakDBusError("org.freedesktop.DBus.Error.ServiceUnknown", ["not provided"]),
            NO_ADAPTER_MESSAGE,
        ),
        (BleakDBusError("org.bluez.Error.NotReady", ["Resource Not Ready"]), NO_ADAPTER_MESSAGE),
        (
            BleakDBusError("org.bluez.Error.Failed", ["le-connection-abort-by-local"]),
            "Bluetooth error: [org.bluez.Error.Failed] le-connection-abort-by-local",
        ),
        (BleakDeviceNotFoundError(STAGE, "not found"), NOT_FOUND),
        (
            BleakCharacteristicNotFoundError(MICROCHIP_UART.notify),
            f"Device has no transparent-UART characteristic {MICROCHIP_UART.notify}",
        ),
        (
            TimeoutError(),
            "Connecting timed out — is the device in range and not connected to another host?",
        ),
        (BleLinkError("Already worded\nfor you"), "Already worded for you"),
        (ValueError("odd\n  thing"), "Bluetooth error: ValueError: odd thing"),
    ],
)
def test_describe_ble_error_gives_one_clear_line(exc: BaseException, message: str) -> None:
    assert describe_ble_error(exc) == message


def test_describe_ble_error_names_the_device_looked_for() -> None:
    exc = BleakDeviceNotFoundError(STAGE, "not found")
    assert describe_ble_error(exc, device="PLOTTER") == (
        "No PLOTTER device found — is it powered and advertising?"
    )


# --- the real bleak, where this machine has no Bluetooth at all --------------------------------

NO_SYSTEM_BUS = (
    sys.platform == "linux"
    and "DBUS_SYSTEM_BUS_ADDRESS" not in os.environ
    and not os.path.exists("/run/dbus/system_bus_socket")
    and not os.path.exists("/var/run/dbus/system_bus_socket")
)


# Skipped where BlueZ runs: there the outcome depends on the machine's adapter and on
# whatever advertises nearby, so nothing could be asserted. The fake covers those paths;
# this test pins real bleak's API on machines (like CI) where the answer is known.
@pytest.mark.skipif(not NO_SYSTEM_BUS, reason="needs a Linux machine without a D-Bus system bus")
def test_real_bleak_without_bluez_reports_no_adapter() -> None:
    """The default client and scanner, unmocked: the API calls match bleak's."""
    listener = Listener()
    transport = BleTransport(STAGE, MICROCHIP_UART, name_prefix="XY-STAGE")
    transport.set_listener(listener)
    transport.open()
    assert listener.wait_lost()
    assert listener.lost == [NO_ADAPTER_MESSAGE]

    loop = BleLoop()
    try:
        result = scan(
            loop, uuids=MICROCHIP_UART, name_prefix="XY-STAGE", timeout=0.1, on_done=lambda _: None
        ).result(timeout=WAIT_S)
    finally:
        loop.stop()
        transport.close()
    assert result == NO_ADAPTER_MESSAGE
    assert not ble_threads()
