"""The emulator on a pseudo-terminal: in-process through its loop, and as its own process."""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
import serial

from protocol.clock import ManualClock
from protocol.emulator.__main__ import main, open_pty, pump
from protocol.emulator.stage_firmware import StageFirmware
from protocol.stage.codec import (
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    StageDecoder,
    Subscriber,
    encode_command,
)

ROOT = Path(__file__).resolve().parent.parent
STARTUP_TIMEOUT = 10.0
REPLY_TIMEOUT = 2.0

VERSION_QUERY = encode_command(
    CommandFrame(
        (CommandPacket(CommandId.MOVE_ABS, 100), CommandPacket(CommandId.NOP)),
        Subscriber.FIRMWARE_VERSION,
    )
)


def _decode_one(line: bytes) -> EchoFrame:
    frames = StageDecoder(2).feed(line)
    assert len(frames) == 1
    echo = frames[0]
    assert isinstance(echo, EchoFrame), echo
    return echo


def test_the_loop_answers_through_the_terminal() -> None:
    master, slave, path = open_pty()
    try:
        assert path.startswith("/dev/")
        clock = ManualClock()
        firmware = StageFirmware(clock)
        outbox = bytearray()
        firmware.set_output(outbox.extend)
        os.write(slave, VERSION_QUERY)
        pump(firmware, master, clock, outbox, timeout=REPLY_TIMEOUT)
        clock.advance(0.005)
        pump(firmware, master, clock, outbox, timeout=0.0)
        selector = selectors.DefaultSelector()
        selector.register(slave, selectors.EVENT_READ)
        assert selector.select(REPLY_TIMEOUT), "no echo on the terminal"
        selector.close()
        echo = _decode_one(os.read(slave, 4096))
        assert (echo.subscriber, echo.sdata) == (Subscriber.FIRMWARE_VERSION, 10200)
        assert echo.packets[0].status == 1  # accelerating towards 100 µm
    finally:
        os.close(master)
        os.close(slave)


def test_without_pty_it_prints_usage_and_exits_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--profile", "xy-stage"]) == 2
    assert "usage" in capsys.readouterr().err


def test_unknown_profiles_are_refused() -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["--profile", "no-such-machine", "--pty"])
    assert exit_info.value.code == 2


@pytest.fixture
def emulator() -> Iterator[tuple[subprocess.Popen[bytes], str]]:
    command = [sys.executable, "-m", "protocol.emulator", "--profile", "xy-stage", "--pty"]
    with subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    ) as process:
        try:
            assert process.stdout is not None
            selector = selectors.DefaultSelector()
            selector.register(process.stdout, selectors.EVENT_READ)
            ready = selector.select(STARTUP_TIMEOUT)
            selector.close()
            assert ready, "the emulator printed no device path"
            path = process.stdout.readline().decode().strip()
            yield process, path
        finally:
            if process.poll() is None:
                process.terminate()
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


@pytest.mark.parametrize("stop_signal", [signal.SIGTERM, signal.SIGINT])
def test_emulator_process_answers_over_a_serial_port_and_exits_cleanly(
    emulator: tuple[subprocess.Popen[bytes], str], stop_signal: signal.Signals
) -> None:
    process, path = emulator
    assert path.startswith("/dev/"), path
    with serial.Serial(path, 115200, timeout=REPLY_TIMEOUT) as port:
        port.write(VERSION_QUERY)
        line = port.read_until(b"\n")
    echo = _decode_one(line)
    assert (echo.subscriber, echo.sdata) == (Subscriber.FIRMWARE_VERSION, 10200)
    process.send_signal(stop_signal)
    assert process.wait(timeout=5) == 0
    assert process.stderr is not None
    assert b"Traceback" not in process.stderr.read()
