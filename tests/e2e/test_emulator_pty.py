"""The emulator on a pseudo-terminal: in-process through its loop, and as its own process."""

from __future__ import annotations

import io
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
from protocol.drill.codec import HOME as DRILL_HOME
from protocol.drill.codec import encode_command as encode_drill_command
from protocol.emulator.cli import ScaledClock, main
from protocol.emulator.controls import ControlChannel
from protocol.emulator.pty import LinkError, make_link, open_pty, pump, remove_link
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import ADC_CENTRE, Usb3Firmware
from protocol.stage.codec import (
    CommandFrame,
    CommandId,
    CommandPacket,
    DeviceFlag,
    EchoFrame,
    StageDecoder,
    Subscriber,
    encode_command,
)
from protocol.usb3.codec import (
    AxisId,
    GetSettings,
    ReplyDecoder,
    StepSize,
    StepSizes,
    Thread,
    Threads,
    encode,
)

ROOT = Path(__file__).resolve().parents[2]
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
    """The emulator process and the device path it printed; always ended on the way out.

    With ``--controls`` its standard input is a pipe the test writes control lines to.
    """
    command = [sys.executable, "-m", "protocol.emulator", "--profile", profile, *options]
    stdin = subprocess.PIPE if "--controls" in options else subprocess.DEVNULL
    with subprocess.Popen(
        command, cwd=ROOT, stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE
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


def test_drill_emulator_process_homes_with_receipt_then_done_and_logs_it(tmp_path: Path) -> None:
    log = tmp_path / "drill.log"
    # Homing from power-on takes 3.0378 s of machine time: 0.3 s at ten times real time.
    options = ("--pty", "--time-scale", "10", "--log", str(log))
    with running_emulator(*options, profile="pcb-drill") as (process, path):
        with serial.Serial(path, 19200, timeout=REPLY_TIMEOUT) as port:
            port.write(encode_drill_command(DRILL_HOME))
            assert port.read_until(b"\n") == b"RN\r\n"
            assert port.read_until(b"\n") == b"DN\r\n"
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=5) == 0
        assert process.stderr is not None
        assert b"pcb-drill emulator on" in process.stderr.read()
    words = [line.split()[1:] for line in log.read_text().splitlines()]
    # It homed by itself at power-on (FIDELITY S2-19), before the N it was sent could run.
    power_on = ["homed", "at", "power-on"]
    assert [w for w in words if w != power_on] == [["received", "N"], ["done", "N"]]
    assert words.count(power_on) == 1 and words.index(power_on) < words.index(["done", "N"])


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


# --- --controls: the device's own controls on standard input ----------------------------


@contextmanager
def control_pipe() -> Iterator[tuple[int, int]]:
    """``(read_end, write_end)`` of a pipe standing in for the emulator's standard input."""
    read_end, write_end = os.pipe()
    try:
        yield read_end, write_end
    finally:
        for fd in (read_end, write_end):
            try:
                os.close(fd)
            except OSError:
                pass  # the test closed it already (end of input)


def _feed(controls: ControlChannel, write_end: int, data: bytes) -> None:
    """Write ``data`` to the control input and let the channel take it (it is readable now)."""
    os.write(write_end, data)
    controls.read()


def _lines(errors: io.StringIO) -> list[str]:
    return errors.getvalue().splitlines()


def test_a_menu_line_reaches_the_host_as_the_units_own_report() -> None:
    master, slave, _ = open_pty()
    try:
        with control_pipe() as (read_end, write_end):
            clock = ManualClock()
            unit = Usb3Firmware(clock)
            outbox = bytearray()
            unit.set_output(outbox.extend)
            errors = io.StringIO()
            controls = ControlChannel(unit, read_end, errors)
            os.write(write_end, b"menu M5 3 3\n")

            pump(unit, master, clock, outbox, REPLY_TIMEOUT, controls)  # the line is read
            clock.advance(0.005)
            pump(unit, master, clock, outbox, 0.0, controls)  # a cycle sends the report

            assert unit.step_sizes == (StepSize.THIRTY_SECOND, StepSize.EIGHTH, StepSize.EIGHTH)
            with selectors.DefaultSelector() as selector:
                selector.register(slave, selectors.EVENT_READ)
                assert selector.select(REPLY_TIMEOUT), "no report on the terminal"
            assert os.read(slave, 4096) == b"M533;T444;"
            assert errors.getvalue() == ""
            assert (controls.applied, controls.refused) == (1, 0)
    finally:
        os.close(master)
        os.close(slave)


@pytest.mark.parametrize(
    ("line", "sizes", "threads"),
    [
        ("menu M533", (5, 3, 3), (4, 4, 4)),
        ("MENU m0 1 2", (0, 1, 2), (4, 4, 4)),
        ("menu T6 5 0", (3, 3, 3), (6, 5, 0)),
        ("menu M111 T222", (1, 1, 1), (2, 2, 2)),
        ("  menu   M 4 4 4  ", (4, 4, 4), (4, 4, 4)),
    ],
)
def test_menu_lines_set_step_sizes_and_threads_as_the_wire_digits(
    line: str, sizes: tuple[int, int, int], threads: tuple[int, int, int]
) -> None:
    unit = Usb3Firmware(ManualClock())
    errors = io.StringIO()
    controls = ControlChannel(unit, -1, errors)
    assert controls.execute(line)
    assert unit.step_sizes == tuple(StepSize(v) for v in sizes)
    assert unit.threads == tuple(Thread(v) for v in threads)
    assert errors.getvalue() == ""


def test_control_lines_split_across_reads_act_once_whole() -> None:
    clock = ManualClock()
    unit = Usb3Firmware(clock)
    with control_pipe() as (read_end, write_end):
        controls = ControlChannel(unit, read_end, io.StringIO())
        _feed(controls, write_end, b"joy")
        _feed(controls, write_end, b"stick X 10")
        assert unit.joystick(AxisId.X) == ADC_CENTRE  # not a whole line yet
        _feed(controls, write_end, b"23\nmenu T5")
        assert unit.joystick(AxisId.X) == 1023
        assert unit.threads == (Thread.M6,) * 3
        _feed(controls, write_end, b"55\r\n")  # a terminal's CR LF is fine too
        assert unit.threads == (Thread.M8,) * 3
        assert (controls.applied, controls.refused) == (2, 0)
    clock.advance(1.0)
    unit.run_until(clock.now())
    assert unit.moving(AxisId.X) and unit.positions[0] > 0  # the joystick drives the motor


USB3_BAD_LINES = [
    "bogus",
    "menu",
    "menu M6 3 3",  # step digits are 0…5
    "menu T7 0 0",  # thread digits are 0…6
    "menu M53",
    "menu X533",
    "menu M533 junk",
    "joystick",
    "joystick X",
    "joystick Q 600",
    "joystick X 2000",
    "joystick X -1",
    "joystick X fast",
    "charger on",  # the stage's, not the unit's
]


@pytest.mark.parametrize("line", USB3_BAD_LINES)
def test_a_line_that_is_no_usb3_control_is_reported_in_one_line_and_changes_nothing(
    line: str,
) -> None:
    clock = ManualClock()
    unit = Usb3Firmware(clock)
    out = bytearray()
    unit.set_output(out.extend)
    errors = io.StringIO()
    controls = ControlChannel(unit, -1, errors)

    assert not controls.execute(line)

    said = _lines(errors)
    assert len(said) == 1 and said[0].startswith("stepdeck-emulator: "), said
    assert (controls.applied, controls.refused) == (0, 1)
    assert unit.step_sizes == (StepSize.EIGHTH,) * 3
    assert unit.threads == (Thread.M6,) * 3
    assert all(unit.joystick(axis) == ADC_CENTRE for axis in AxisId)
    clock.advance(0.1)
    unit.run_until(clock.now())
    assert out == b""  # nothing reached the host


def test_stage_controls_set_the_firmwares_attributes() -> None:
    stage = StageFirmware(ManualClock())
    errors = io.StringIO()
    controls = ControlChannel(stage, -1, errors)
    for line in ("charger on", "usb ON", "battery 12.5", "temperature 41.5", "rotation -3"):
        assert controls.execute(line), line
    assert stage.charger_connected and stage.usb_connected
    assert stage.battery_charge == 12.5
    assert stage.board_temperature_c == 41.5
    assert stage.rotation_rate_dps == -3.0
    assert controls.execute("charger off") and controls.execute("usb off")
    assert not stage.charger_connected and not stage.usb_connected
    assert errors.getvalue() == ""


def test_s3_36_the_stages_button_and_kill_switch_are_controls() -> None:
    stage = StageFirmware(ManualClock())
    errors = io.StringIO()
    controls = ControlChannel(stage, -1, errors)
    assert controls.execute("button") and not stage.snapshot().powered
    assert controls.execute("button") and stage.snapshot().powered
    assert controls.execute("button long") and stage.snapshot().powered  # a reset: on again at once
    assert controls.execute("kill") and not stage.snapshot().powered
    assert not controls.execute("button twice") and not controls.execute("kill now")
    assert len(_lines(errors)) == 2


@pytest.mark.parametrize(
    "line",
    [
        "charger maybe",
        "charger",
        "usb on off",
        "battery 150",
        "battery nan",
        "temperature hot",
        "rotation",
        "menu M533",
        "joystick X 1023",
        "reboot",
    ],
)
def test_a_line_that_is_no_stage_control_is_reported_and_changes_nothing(line: str) -> None:
    stage = StageFirmware(ManualClock())
    before = (stage.charger_connected, stage.usb_connected, stage.battery_charge)
    errors = io.StringIO()
    assert not ControlChannel(stage, -1, errors).execute(line)
    assert len(_lines(errors)) == 1
    assert (stage.charger_connected, stage.usb_connected, stage.battery_charge) == before


def test_help_blank_lines_and_comments() -> None:
    errors = io.StringIO()
    controls = ControlChannel(Usb3Firmware(ManualClock()), -1, errors)
    assert controls.execute("")
    assert controls.execute("   ")
    assert controls.execute("# the operator sets X to 1/32")
    assert errors.getvalue() == ""
    assert controls.execute("help")
    (said,) = _lines(errors)
    assert "menu [M<mx><my><mz>] [T<tx><ty><tz>]" in said and "joystick X|Y|Z" in said
    assert (controls.applied, controls.refused) == (0, 0)


def test_the_end_of_the_control_input_applies_a_last_unfinished_line_and_stops_watching() -> None:
    master, slave, _ = open_pty()
    try:
        with control_pipe() as (read_end, write_end):
            clock = ManualClock()
            unit = Usb3Firmware(clock)
            outbox = bytearray()
            unit.set_output(outbox.extend)
            errors = io.StringIO()
            controls = ControlChannel(unit, read_end, errors)
            os.write(write_end, b"menu M000")  # no newline: the input ends here
            os.close(write_end)

            pump(unit, master, clock, outbox, REPLY_TIMEOUT, controls)
            pump(unit, master, clock, outbox, REPLY_TIMEOUT, controls)

            assert not controls.open
            assert unit.step_sizes == (StepSize.FULL,) * 3
            assert _lines(errors) == [
                "stepdeck-emulator: end of the control input; the device is still served"
            ]
            # The loop goes on serving the terminal without the (ever readable) input.
            clock.advance(0.005)
            pump(unit, master, clock, outbox, 0.0, controls)
            assert os.read(slave, 4096) == b"M000;T444;"
    finally:
        os.close(master)
        os.close(slave)


def test_an_over_long_control_line_is_dropped_whole_once() -> None:
    unit = Usb3Firmware(ManualClock())
    with control_pipe() as (read_end, write_end):
        errors = io.StringIO()
        controls = ControlChannel(unit, read_end, errors)
        _feed(controls, write_end, b"menu M" + b"5" * 2000)
        _feed(controls, write_end, b"5" * 2000)
        _feed(controls, write_end, b"55\nmenu M111\n")
        assert unit.step_sizes == (StepSize.HALF,) * 3  # the next line acts
        said = _lines(errors)
        assert len(said) == 1 and "longer than 1024 bytes" in said[0]
        assert (controls.applied, controls.refused) == (1, 1)


def test_scaled_clock_runs_faster_than_its_base() -> None:
    base = ManualClock(start=100.0)
    clock = ScaledClock(20, base)
    assert clock.now() == 100.0
    base.advance(0.5)
    assert clock.now() == pytest.approx(110.0)
    for factor in (0.0, -1.0, float("inf"), float("nan")):
        with pytest.raises(ValueError):
            ScaledClock(factor, base)


@pytest.mark.parametrize("factor", ["0", "-2", "fast", "inf"])
def test_a_time_scale_that_is_not_a_positive_number_is_refused(
    factor: str, capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["--pty", "--time-scale", factor])
    assert exit_info.value.code == 2
    assert "must be a positive number" in capsys.readouterr().err


def test_controls_and_time_scale_are_in_the_help(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["--help"])
    text = capsys.readouterr().out
    for expected in (
        "--controls",
        "--time-scale F",
        "menu [M<mx><my><mz>] [T<tx><ty><tz>]",
        "joystick X|Y|Z <0…1023>",
        "charger on|off",
        "usb on|off",
    ):
        assert expected in text, expected


def _control(process: subprocess.Popen[bytes], line: str) -> None:
    assert process.stdin is not None
    process.stdin.write(line.encode() + b"\n")
    process.stdin.flush()


def test_usb3_emulator_process_takes_control_lines_on_its_standard_input() -> None:
    with running_emulator("--pty", "--controls", profile="usb3") as (process, path):
        with serial.Serial(path, 19200, timeout=REPLY_TIMEOUT) as port:
            _control(process, "menu M5 3 3")
            assert port.read_until(b";") + port.read_until(b";") == b"M533;T444;"

            _control(process, "nonsense")  # reported, ignored: the next line still acts
            _control(process, "joystick X 1023")
            reports = ReplyDecoder().feed(port.read_until(b";") + port.read_until(b";"))
            assert [type(r).__name__ for r in reports] == ["Position", "Position"]
            _control(process, "joystick X 512")  # centred: the motor stops

            port.write(encode(GetSettings()))  # and the wire is served all along
            replies = port.read_until(b"M533;T444;")
            assert replies.endswith(b"M533;T444;")
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=5) == 0
        assert process.stderr is not None
        errors = process.stderr.read().decode()
    assert "Traceback" not in errors
    assert errors.count("unknown control") == 1
    assert "stepdeck-emulator: unknown control 'nonsense' (try help)" in errors.splitlines()


DEVICE_FLAGS_QUERY = encode_command(
    CommandFrame(
        (CommandPacket(CommandId.NOP), CommandPacket(CommandId.NOP)), Subscriber.DEVICE_FLAGS
    )
)


def test_stage_emulator_process_plugs_the_charger_in_from_its_standard_input() -> None:
    with running_emulator("--pty", "--controls") as (process, path):
        with serial.Serial(path, 115200, timeout=REPLY_TIMEOUT) as port:
            port.write(DEVICE_FLAGS_QUERY)
            assert not _decode_one(port.read_until(b"\n")).sdata & DeviceFlag.CHARGER
            _control(process, "charger on")
            # The control line and the query travel different pipes: ask until it shows,
            # a bounded number of times.
            for _ in range(20):
                port.write(DEVICE_FLAGS_QUERY)
                echo = _decode_one(port.read_until(b"\n"))
                assert echo.subscriber == Subscriber.DEVICE_FLAGS
                if echo.sdata & DeviceFlag.CHARGER:
                    break
            else:
                pytest.fail("the charger never showed in the device flags")
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=5) == 0
