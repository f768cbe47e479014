"""The emulator on a pseudo-terminal: in-process through its loop, and as its own process."""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
import serial

from protocol.clock import ManualClock
from protocol.emulator.__main__ import LinkError, main, make_link, open_pty, pump, remove_link
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
from protocol.usb3.codec import (
    GetSettings,
    ReplyDecoder,
    StepSize,
    StepSizes,
    Thread,
    Threads,
    encode,
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


Emulator = tuple[subprocess.Popen[bytes], str]
EMULATOR = [sys.executable, "-m", "protocol.emulator", "--profile", "xy-stage"]


@contextmanager
def running_emulator(*options: str, profile: str = "xy-stage") -> Iterator[Emulator]:
    """The emulator process and the device path it printed; always ended on the way out."""
    command = [sys.executable, "-m", "protocol.emulator", "--profile", profile, *options]
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


@pytest.fixture
def emulator() -> Iterator[Emulator]:
    with running_emulator("--pty") as started:
        yield started


def _ask_version(path: str | Path) -> EchoFrame:
    with serial.Serial(str(path), 115200, timeout=REPLY_TIMEOUT) as port:
        port.write(VERSION_QUERY)
        return _decode_one(port.read_until(b"\n"))


@pytest.mark.parametrize("stop_signal", [signal.SIGTERM, signal.SIGINT])
def test_emulator_process_answers_over_a_serial_port_and_exits_cleanly(
    emulator: Emulator, stop_signal: signal.Signals
) -> None:
    process, path = emulator
    assert path.startswith("/dev/"), path
    echo = _ask_version(path)
    assert (echo.subscriber, echo.sdata) == (Subscriber.FIRMWARE_VERSION, 10200)
    process.send_signal(stop_signal)
    assert process.wait(timeout=5) == 0
    assert process.stderr is not None
    assert b"Traceback" not in process.stderr.read()


def test_usb3_emulator_process_answers_get_settings_over_a_serial_port(tmp_path: Path) -> None:
    link = tmp_path / "usb3"
    with running_emulator("--link", str(link), profile="usb3") as (process, path):
        assert path.startswith("/dev/") and os.readlink(link) == path
        with serial.Serial(str(link), 19200, timeout=REPLY_TIMEOUT) as port:
            port.write(encode(GetSettings()))
            reply = port.read_until(b";") + port.read_until(b";")
        assert ReplyDecoder().feed(reply) == [
            StepSizes((StepSize.EIGHTH,) * 3),
            Threads((Thread.M6,) * 3),
        ]
        assert reply == b"M333;T444;"
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=5) == 0
        assert process.stderr is not None
        assert b"usb3 emulator on" in process.stderr.read()


# --- --link: a fixed path for a pty that changes with every start -------------------


def test_make_link_points_the_path_at_the_device(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    make_link(link, "/dev/pts/77")
    assert os.readlink(link) == "/dev/pts/77"
    assert [p.name for p in tmp_path.iterdir()] == ["stage"]  # no staging file left


def test_make_link_replaces_a_symlink_left_behind(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    link.symlink_to("/dev/pts/dead")
    make_link(link, "/dev/pts/78")
    assert os.readlink(link) == "/dev/pts/78"


def test_make_link_never_overwrites_a_regular_file(tmp_path: Path) -> None:
    precious = tmp_path / "stage"
    precious.write_text("notes")
    with pytest.raises(LinkError, match="not a symlink"):
        make_link(precious, "/dev/pts/79")
    assert precious.read_text() == "notes"


def test_make_link_in_a_missing_directory_says_so(tmp_path: Path) -> None:
    with pytest.raises(LinkError, match="cannot create the link"):
        make_link(tmp_path / "no-such-dir" / "stage", "/dev/pts/80")


def test_remove_link_leaves_a_link_another_emulator_took_over(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    link.symlink_to("/dev/pts/81")
    remove_link(link, "/dev/pts/80")
    assert link.is_symlink()
    remove_link(link, "/dev/pts/81")
    assert not link.exists() and not link.is_symlink()


def test_link_is_in_the_help(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["--help"])
    assert "--link PATH" in capsys.readouterr().out


def test_emulator_process_serves_through_its_link_and_removes_it_on_exit(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    link.symlink_to("/dev/pts/left-by-a-killed-emulator")
    with running_emulator("--link", str(link)) as (process, path):
        assert os.readlink(link) == path
        echo = _ask_version(link)
        assert (echo.subscriber, echo.sdata) == (Subscriber.FIRMWARE_VERSION, 10200)
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=5) == 0
    assert not link.is_symlink()


def test_a_restarted_emulator_takes_over_the_same_path(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    with running_emulator("--link", str(link)) as (process, _):
        process.kill()  # no chance to clean up: the link is left dangling
        process.wait(timeout=5)
    assert link.is_symlink()
    with running_emulator("--link", str(link)) as (_, path):
        assert os.readlink(link) == path
        assert _ask_version(link).sdata == 10200


def test_the_emulator_refuses_to_replace_a_regular_file(tmp_path: Path) -> None:
    precious = tmp_path / "stage"
    precious.write_text("notes")
    result = subprocess.run(
        [*EMULATOR, "--link", str(precious)], cwd=ROOT, capture_output=True, timeout=30
    )
    assert result.returncode == 2
    assert b"not a symlink" in result.stderr
    assert b"Traceback" not in result.stderr
    assert result.stdout == b""
    assert precious.read_text() == "notes"
