"""The G-code profiles of ``stepdeck-emulator`` as their own process on a pseudo-terminal."""

from __future__ import annotations

import io
import json
import signal
import subprocess
import time
from pathlib import Path

import pytest
import serial

from protocol.clock import ManualClock
from protocol.emulator.cli import PROFILES
from protocol.emulator.controls import ControlChannel
from protocol.emulator.gcode_firmware import GcodeFirmware
from protocol.gcode import (
    AlarmReply,
    Banner,
    Feedback,
    GcodeReply,
    Ok,
    Rejected,
    StatusReport,
    encode_line,
    make_decoder,
)
from protocol.gcode.codec import GRBL_BANNER, PLOTTER_BANNER
from tests.e2e.test_emulator_pty import REPLY_TIMEOUT, running_emulator

#: How long a reply may take before the emulator counts as not answering: a bound only
#: against a hang (a reply ends the wait at once), long enough for an emulator process that
#: a busy computer gets to run only now and then.
ANSWER_BOUND_S = 30.0


class Port:
    """A serial port and a reader of the board's replies, one at a time."""

    def __init__(self, port: serial.Serial) -> None:
        self.port = port
        self.decoder = make_decoder()
        self.pending: list[GcodeReply] = []

    def next(self) -> GcodeReply:
        deadline = time.monotonic() + ANSWER_BOUND_S
        while not self.pending:
            assert time.monotonic() < deadline, "no reply from the emulator"
            data = self.port.read_until(b"\n")
            for reply in self.decoder.feed(data):
                assert not isinstance(reply, Rejected), reply
                self.pending.append(reply)
        return self.pending.pop(0)

    def send(self, *lines: str) -> None:
        self.port.write(b"".join(encode_line(line) for line in lines))

    def status(self) -> StatusReport:
        self.port.write(b"?")
        while True:
            reply = self.next()
            if isinstance(reply, StatusReport):
                return reply


def _stop(process: subprocess.Popen[bytes]) -> bytes:
    process.send_signal(signal.SIGTERM)
    assert process.wait(timeout=5) == 0
    assert process.stderr is not None
    err = process.stderr.read()
    assert b"Traceback" not in err
    return err


def test_the_gcode_profiles_are_registered() -> None:
    for name in ("corexy-plotter", "grbl-plotter", "string-art"):
        assert name in PROFILES


def test_corexy_plotter_process_draws_and_logs_it(tmp_path: Path) -> None:
    log = tmp_path / "plotter.log"
    options = ("--pty", "--time-scale", "50", "--log", str(log))
    with running_emulator(*options, profile="corexy-plotter") as (process, path):
        with serial.Serial(path, 115200, timeout=REPLY_TIMEOUT) as raw:
            port = Port(raw)
            assert port.next() == Banner(PLOTTER_BANNER)
            port.send("G1 X10 Y10", "M4", "G1 X20", "M3")
            assert [port.next() for _ in range(4)] == [Ok()] * 4
            deadline = time.monotonic() + ANSWER_BOUND_S
            while (report := port.status()).state != "Idle":
                assert time.monotonic() < deadline, report
            assert report.mpos == (20.0, 10.0, 0.0)
        assert b"corexy-plotter emulator on" in _stop(process)
    events = [json.loads(line) for line in log.read_text().splitlines()]
    assert [e["text"] for e in events if e["event"] == "line"] == [
        "G1 X10 Y10",
        "M4",
        "G1 X20",
        "M3",
    ]
    assert [e["text"] for e in events if e["event"] == "reply"] == ["OK"] * 4
    assert [(e["pos"]["X"], e["pos"]["Y"], e["pen"]) for e in events if e["event"] == "move"] == [
        (10.0, 10.0, False),
        (20.0, 10.0, True),
    ]
    assert [e["down"] for e in events if e["event"] == "pen"] == [True, False]


def test_grbl_plotter_process_takes_the_alarm_control() -> None:
    with running_emulator("--pty", "--controls", profile="grbl-plotter") as (process, path):
        with serial.Serial(path, 115200, timeout=REPLY_TIMEOUT) as raw:
            port = Port(raw)
            assert port.next() == Banner(GRBL_BANNER)
            assert process.stdin is not None
            process.stdin.write(b"alarm 2\n")
            process.stdin.flush()
            assert port.next() == AlarmReply(2)
            assert port.next() == Feedback("[MSG:Reset to continue]")
            # GRBL's lock after a limit: neither answered nor kept (the banner comes first).
            raw.write(b"?$X\n")
            raw.write(b"\x18")
            assert port.next() == Banner(GRBL_BANNER)
            assert port.next() == Feedback("[MSG:'$H'|'$X' to unlock]")
            assert port.status().state == "Alarm"
        _stop(process)


@pytest.mark.parametrize("profile", ["grbl-plotter", "string-art"])
def test_every_gcode_profile_answers_ok(profile: str) -> None:
    with running_emulator("--pty", profile=profile) as (process, path):
        with serial.Serial(path, 115200, timeout=REPLY_TIMEOUT) as raw:
            port = Port(raw)
            assert port.next() == Banner(GRBL_BANNER)
            port.send("G0 X1")
            assert port.next() == Ok()
        _stop(process)


def test_the_controls_reach_the_gcode_firmware() -> None:
    board = PROFILES["grbl-plotter"](ManualClock())
    assert isinstance(board, GcodeFirmware)
    errors = io.StringIO()
    channel = ControlChannel(board, fd=-1, errors=errors)
    assert channel.execute("hold")
    assert board.state == "Hold"
    assert channel.execute("resume")
    assert board.state == "Idle"
    assert not channel.execute("alarm x")
    assert "alarm code" in errors.getvalue()
    assert channel.execute("alarm")
    assert board.alarm == 1
