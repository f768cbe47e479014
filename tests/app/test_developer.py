"""The developer pane's models: echo parsing and injection, the frame log, emulator controls.

Driven through the station harness on its manual clock, so every frame, echo
and fault happens at a known emulated time.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.developer.emulator_controls import EmulatorControls, SimulationRefused
from app.developer.frame_log import FrameLog, LogDirection
from app.developer.raw_text import escape_raw
from app.developer.stage import (
    AxisFields,
    EchoFields,
    InjectError,
    describe_command,
    describe_echo,
    inject_echo,
    parse_echo,
)
from app.machine import LinkState
from protocol.stage.codec import (
    AxisStatus,
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoPacket,
    EchoType,
    Subscriber,
    encode_echo,
)
from tests.helpers.fake_transport import SilentPort
from tests.helpers.harness import StationHarness

NAMES, UNITS = ("X", "Y"), ("mm", "mm")


def _fields(x_data: str | int = "0", **x: str | int) -> EchoFields:
    return EchoFields([AxisFields(data=x_data, **x), AxisFields()])  # type: ignore[arg-type]


def _charger_echo() -> EchoFields:
    return EchoFields([AxisFields("0", "9", "12345"), AxisFields("0", "9", "0")], "01", "3712")


@pytest.fixture
def log(harness: StationHarness) -> FrameLog:
    return FrameLog(harness.station)


@pytest.fixture
def controls(harness: StationHarness) -> EmulatorControls:
    return EmulatorControls(harness.station)


@pytest.fixture
def connected(harness: StationHarness) -> StationHarness:
    """The harness connected to its emulator, past the parameter read at connect."""
    harness.connect()
    harness.run(1.5)
    return harness


# --- parsing ------------------------------------------------------------------------


def test_fields_as_typed_or_chosen_parse_into_the_echo() -> None:
    fields = EchoFields(
        [AxisFields("9 blocked: charger connected", "0x1", "-42"), AxisFields(2, 0xE, " 500 ")],
        "01 battery voltage",
        "+3712",
    )
    assert parse_echo(fields) == EchoFrame(
        (EchoPacket(9, 1, -42), EchoPacket(2, 0xE, 500)), Subscriber.BATTERY_VOLTAGE, 3712
    )


@pytest.mark.parametrize(
    ("subscriber", "code"),
    [("battery_charge", 2), ("ROTATION", 5), ("ff", 0xFF), ("3C", 0x3C), (0x0B, 0x0B)],
)
def test_a_subscriber_is_a_name_or_any_id_up_to_ff(subscriber: str | int, code: int) -> None:
    assert parse_echo(EchoFields([AxisFields()], subscriber)).subscriber == code


@pytest.mark.parametrize(
    ("fields", "expected"),
    [
        (_fields("12.5"), "X DATA: '12.5' is not a whole number"),
        (_fields("abc"), "X DATA: 'abc' is not a whole number"),
        (_fields(""), "X DATA is empty"),
        (_fields("1000000"), "X DATA: 1000000 is outside -99999…999999"),
        (_fields(-100000), "X DATA: -100000 is outside"),
        (_fields(type="D"), "X TYPE: D is outside 0…C"),
        (_fields(type=13), "X TYPE: D is outside 0…C"),
        (_fields(type="zz"), "X TYPE: 'zz' is not a hexadecimal number"),
        (_fields(status="D"), "X STATUS: D is not a known status"),
        (EchoFields([AxisFields()], "100"), "subscriber ID: 100 is outside 00…FF"),
        (EchoFields([AxisFields()], "battery", "0"), "subscriber ID: 'battery'"),
        (EchoFields([AxisFields()], "01", "3.7"), "subscriber DATA: '3.7' is not a whole"),
    ],
)
def test_malformed_fields_are_refused_with_a_message(fields: EchoFields, expected: str) -> None:
    with pytest.raises(InjectError) as refused:
        parse_echo(fields, NAMES)
    assert expected in refused.value.message


def test_axes_without_names_are_numbered() -> None:
    with pytest.raises(InjectError, match="axis 2 DATA"):
        parse_echo(EchoFields([AxisFields(), AxisFields(data="x")]))


# --- injecting ------------------------------------------------------------------------


def test_an_injected_echo_reaches_the_model_without_a_link(
    qtbot: QtBot, harness: StationHarness, log: FrameLog
) -> None:
    model = harness.station.model
    with qtbot.waitSignal(harness.station.echoInjected) as injected:
        echo = inject_echo(harness.station, _charger_echo())
    assert injected.args == [echo]
    assert model.axes[0].position == 12.345
    assert model.axes[0].status_text == "blocked: charger connected"
    assert model.block_reason == "blocked: charger connected"
    assert model.telemetry["battery_voltage"] == pytest.approx(3.712)
    [entry] = log.entries
    assert entry.direction is LogDirection.INJ
    assert entry.raw == escape_raw(encode_echo(echo))
    assert entry.decoded == (
        "X pos 12.345 mm blocked: charger connected | Y pos 0.000 mm blocked: charger connected"
        " | battery voltage 3712 mV"
    )


def test_a_charger_echo_locks_motion_on_a_live_link(connected: StationHarness) -> None:
    model = connected.station.model
    inject_echo(connected.station, _charger_echo())
    assert model.motion_lock_reason() == "blocked: charger connected"
    connected.session.set_jog([1, 0])
    assert connected.session.jog_vector == (0, 0)


@pytest.mark.parametrize("data", ["12.5", "abc", "1000000"])
def test_a_malformed_echo_injects_nothing(
    qtbot: QtBot, harness: StationHarness, log: FrameLog, data: str
) -> None:
    model = harness.station.model
    before = [(a.position, a.status_text) for a in model.axes]
    with qtbot.assertNotEmitted(harness.station.echoInjected), pytest.raises(InjectError):
        inject_echo(harness.station, _fields(data, status="9"))
    assert [(a.position, a.status_text) for a in model.axes] == before
    assert model.block_reason is None
    assert len(log) == 0


def test_an_echo_for_the_wrong_axis_count_is_refused(harness: StationHarness) -> None:
    with pytest.raises(InjectError, match="2 axes, the echo 1"):
        inject_echo(harness.station, EchoFields([AxisFields()]))


# --- describing frames ---------------------------------------------------------------


def test_the_protocol_example_echo_in_words() -> None:
    echo = EchoFrame((EchoPacket(0, 1, 12345), EchoPacket(0, 0, 0)), 1, 3712)
    assert encode_echo(echo).startswith(b"<010123450000000001003712*")  # docs/protocols.md §1.1
    assert describe_echo(echo, NAMES, UNITS) == (
        "X pos 12.345 mm accelerating | Y pos 0.000 mm idle | battery voltage 3712 mV"
    )


@pytest.mark.parametrize(
    ("packets", "subscriber", "words"),
    [
        (((CommandId.JOG, 1), (CommandId.NOP, 0)), 1, "X JOG +1 | Y NOP | SS battery voltage"),
        (((CommandId.JOG, -1), (CommandId.JOG, 0)), 0, "X JOG -1 | Y JOG 0 | SS none"),
        (
            ((CommandId.MOVE_ABS, 12345), (CommandId.MOVE_REL, -500)),
            5,
            "X MOVE_ABS 12.345 mm | Y MOVE_REL -0.500 mm | SS rotation",
        ),
        (
            ((CommandId.READ, EchoType.IRUN), (CommandId.WRITE_FAST_SPEED, 12000)),
            7,
            "X READ run current (IRUN) | Y WRITE fast speed 12.000 mm/s | SS device flags",
        ),
        (
            ((CommandId.SPEED, 0), (CommandId.SLEEP, 1)),
            0x3C,
            "X SPEED slow | Y SLEEP on | SS 3C",
        ),
        (((0x3A, 7), (CommandId.HOME, 0)), 0, "X ID 3A 7 | Y HOME | SS none"),
    ],
)
def test_command_frames_in_words(
    packets: tuple[tuple[int, int], ...], subscriber: int, words: str
) -> None:
    frame = CommandFrame(tuple(CommandPacket(c, d) for c, d in packets), subscriber)
    assert describe_command(frame, NAMES, UNITS) == words


@pytest.mark.parametrize(
    ("packet", "subscriber", "sdata", "words"),
    [
        (EchoPacket(1, 2, 2000), 4, 2512, "X vel 2.000 mm/s constant speed | board temperature"),
        (EchoPacket(2, 0xE, 10000), 7, 0x11, "X fast speed 10.000 mm/s parameter rejected"),
        (EchoPacket(0, 0xD, 0), 0xFF, 0x3C, "X pos 0.000 mm status D | unknown subscriber 3C"),
        (EchoPacket(0, 7, 5000), 10, 10200, "X pos 5.000 mm end switch hit | firmware version"),
    ],
)
def test_echoes_in_words(packet: EchoPacket, subscriber: int, sdata: int, words: str) -> None:
    described = describe_echo(EchoFrame((packet,), subscriber, sdata), NAMES, UNITS)
    assert described.startswith(words)


@pytest.mark.parametrize(
    ("subscriber", "sdata", "words"),
    [
        (Subscriber.BOARD_TEMPERATURE, 2512, "board temperature 25.12 °C"),
        (Subscriber.FIRMWARE_VERSION, 10200, "firmware version 1.2.0"),
        (Subscriber.ROTATION, -4550, "rotation -45.50°"),
        (Subscriber.X_ENCODER, 12345, "X encoder 12.345 mm"),
        (Subscriber.DEVICE_FLAGS, 0b10001, "device flags 0x11 (charger, data session)"),
    ],
)
def test_subscriber_values_in_their_units(subscriber: int, sdata: int, words: str) -> None:
    echo = EchoFrame((EchoPacket(0, 0, 0),), subscriber, sdata)
    assert describe_echo(echo, NAMES, UNITS) == f"X pos 0.000 mm idle | {words}"


def test_raw_bytes_are_escaped_onto_one_line() -> None:
    assert escape_raw(b">00*3F\r\n") == ">00*3F\\r\\n"
    assert escape_raw(b"<\x01\xff\t\\") == "<\\x01\\xFF\\t\\\\"


# --- the frame log --------------------------------------------------------------------


def test_sent_and_received_frames_are_logged_in_words(
    connected: StationHarness, log: FrameLog
) -> None:
    connected.session.set_jog([1, 0])
    connected.run(0.5)
    tx = [e for e in log.entries if e.direction is LogDirection.TX]
    rx = [e for e in log.entries if e.direction is LogDirection.RX]
    assert any("X JOG +1 | Y NOP" in e.decoded for e in tx)
    assert any("X pos" in e.decoded and "accelerating" in e.decoded for e in rx)
    assert [e.raw for e in tx] == [escape_raw(raw) for raw in connected.written[-len(tx) :]]
    times = [e.time for e in log.entries]
    assert times == sorted(times)
    period = connected.session.period_ms / 1000
    assert log.origin <= times[0]
    assert connected.clock.now() - period <= times[-1] <= connected.clock.now()
    assert log.entries[-1].line.startswith(f"{times[-1] - log.origin:9.3f}  ")


def test_rejected_bytes_are_logged_with_the_reason(
    connected: StationHarness, log: FrameLog, controls: EmulatorControls
) -> None:
    controls.corrupt_next(1)
    connected.run(0.2)
    [bad] = [e for e in log.entries if e.direction is LogDirection.BAD]
    assert bad.decoded == "rejected: checksum mismatch"


def test_the_log_follows_a_new_session_and_leaves_the_old_one(
    connected: StationHarness, log: FrameLog
) -> None:
    connected.station.close_link()
    start, written = len(log), len(connected.written)
    connected.connect()
    connected.run(0.5)
    tx = [e for e in log.entries[start:] if e.direction is LogDirection.TX]
    assert len(tx) == len(connected.written) - written > 1


def test_pause_holds_the_signal_not_the_entries(
    qtbot: QtBot, connected: StationHarness, log: FrameLog
) -> None:
    log.set_paused(True)
    seq = log.last_seq
    with qtbot.assertNotEmitted(log.entriesAdded):
        connected.run(0.5)
    assert log.last_seq > seq
    assert log.entries_since(seq)[0].seq == seq + 1
    with qtbot.waitSignal(log.entriesAdded):
        log.set_paused(False)


def test_the_log_is_bounded_and_says_what_it_lost(connected: StationHarness) -> None:
    log = FrameLog(connected.station, capacity=50)
    connected.run(5.0)
    assert len(log) == 50
    newest = log.entries_since(0)
    assert len(newest) == 50 and newest[-1].seq == log.last_seq
    assert newest[0].seq > 1  # the gap a view reports
    assert log.entries_since(log.last_seq) == []
    assert [e.seq for e in log.entries_since(log.last_seq - 3)] == [
        log.last_seq - 2,
        log.last_seq - 1,
        log.last_seq,
    ]


def test_the_filter_wants_every_word_in_any_case(connected: StationHarness, log: FrameLog) -> None:
    connected.session.set_jog([1, 0])
    connected.run(0.5)
    jogs = log.filtered("tx  jog +1")
    assert jogs and all(e.direction is LogDirection.TX and "JOG +1" in e.decoded for e in jogs)
    assert all("accelerating" in e.line for e in log.filtered("RX Accelerating"))
    assert log.filtered("") == log.entries
    assert log.filtered("no such thing") == []


def test_clear_empties_the_log(qtbot: QtBot, connected: StationHarness, log: FrameLog) -> None:
    connected.run(0.3)
    with qtbot.waitSignal(log.cleared):
        log.clear()
    assert len(log) == 0
    connected.run(0.3)
    assert len(log) > 0


def test_save_writes_the_entries_all_or_filtered(
    tmp_path: Path, connected: StationHarness, log: FrameLog
) -> None:
    connected.session.set_jog([1, 0])
    connected.run(0.5)
    every, jogs = tmp_path / "all.log", tmp_path / "jogs.log"
    assert log.save(every) == len(log)
    lines = every.read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith(f"# StepDeck frame log, xy-stage: {len(log)} entries")
    assert lines[2:] == [e.line for e in log.entries]
    count = log.save(jogs, "jog +1")
    saved = jogs.read_text(encoding="utf-8").splitlines()[2:]
    assert count == len(saved) > 0 and all("JOG +1" in line for line in saved)


# --- emulator controls ---------------------------------------------------------------


def test_controls_are_available_only_with_the_emulator_connected(
    qtbot: QtBot, harness: StationHarness, controls: EmulatorControls
) -> None:
    assert not controls.available and controls.state() is None
    controls.set_charger(True)  # ignored, no emulator
    with qtbot.waitSignal(controls.availabilityChanged) as changed:
        harness.connect()
    assert changed.args == [True] and controls.available
    state = controls.state()
    # the emulator starts at 80 % and drains only slowly while the link waits for its answer
    assert state is not None and 79.9 < state.battery_percent <= 80.0 and not state.charger
    with qtbot.waitSignal(controls.availabilityChanged) as changed:
        harness.station.close_link()
    assert changed.args == [False] and not controls.available


def test_a_fresh_emulator_is_announced_even_when_one_was_there(
    qtbot: QtBot, connected: StationHarness, controls: EmulatorControls
) -> None:
    first = connected.emulator
    with qtbot.waitSignal(controls.availabilityChanged):
        connected.station.connect_emulator()
    assert connected.emulator is not first and controls.available


def test_charger_and_usb_block_the_machine(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    model = connected.station.model
    controls.set_charger(True)
    assert connected.emulator.charger_connected
    connected.run(0.3)
    assert model.block_reason == "blocked: charger connected"
    controls.set_charger(False)
    controls.set_usb(True)
    connected.run(0.3)
    assert model.block_reason == "blocked: USB connected"
    controls.set_usb(False)
    connected.run(0.3)
    assert model.motion_lock_reason() is None


def test_battery_temperature_and_rotation_reach_the_device(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    controls.set_battery(3)
    controls.set_temperature(41.5)
    controls.set_rotation_rate(10.0)
    connected.run(1.0)
    emulator = connected.emulator
    assert emulator.board_temperature_c == 41.5
    assert emulator.yaw_deg == pytest.approx(10.0, abs=0.01)
    model = connected.station.model
    assert model.block_reason == "blocked: battery low"
    assert model.telemetry["board_temperature"] == pytest.approx(41.5)


def test_an_end_switch_stops_the_axis(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    connected.session.move_absolute(0, 40.0)
    connected.run(0.5)
    controls.press_end_switch(0, "high")
    connected.run(0.2)
    axis = connected.station.model.axes[0]
    assert axis.status_code == AxisStatus.END_SWITCH and not axis.moving
    assert axis.position < 40.0


def test_a_driver_fault_and_a_verification_fault(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    controls.set_driver_fault(1, True)
    controls.set_verification_fault(True)
    assert connected.emulator.snapshot().driver_faults[1] and connected.emulator.verification_fault
    connected.run(0.3)
    assert connected.station.model.axes[1].status_text == "driver fault"
    state = controls.state()
    assert state is not None and state.driver_faults == (False, True)


def test_a_dropped_link_is_lost_then_back(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    model = connected.station.model
    controls.drop_link()
    assert model.link_state is LinkState.LOST
    assert controls.available  # the emulator is still there, behind a cut cable
    connected.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=2)


def test_corrupting_n_frames_rejects_exactly_n(
    connected: StationHarness, controls: EmulatorControls
) -> None:
    decoder = connected.session.decoder
    before = decoder.rejected
    controls.corrupt_next(2)
    controls.corrupt_next(1)  # adds up
    assert controls.corruptions_pending == 3
    connected.run(1.0)
    assert decoder.rejected == before + 3
    assert controls.corruptions_pending == 0
    assert connected.session.rejected == decoder.rejected
    assert connected.station.model.link_state is LinkState.CONNECTED
    controls.corrupt_next(1)  # the spent corrupter goes back on the link
    connected.run(1.0)
    assert decoder.rejected == before + 4


# --- simulation ------------------------------------------------------------------------


def test_simulation_connects_the_emulator_which_answers_a_jog(
    harness: StationHarness, controls: EmulatorControls
) -> None:
    controls.set_simulation(True)
    assert controls.simulating and harness.station.emulator is not None
    model = harness.station.model
    harness.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=1)
    harness.run(1.0)
    harness.session.set_jog([1, 0])
    harness.run(1.0)
    moved = harness.emulator.axes[0].position_um / 1000
    assert moved > 1.0
    assert model.axes[0].position == pytest.approx(moved, abs=0.2)
    controls.set_simulation(False)
    assert not controls.simulating and model.link_state is LinkState.DISCONNECTED


def test_simulation_never_replaces_a_real_device(
    harness: StationHarness, controls: EmulatorControls
) -> None:
    harness.station.connect_transport(SilentPort())
    with pytest.raises(SimulationRefused, match="ttyUSB0 @ 115200 is connected"):
        controls.set_simulation(True)
    controls.set_simulation(False)
    assert harness.station.link is not None and harness.station.link.is_open
    assert not controls.available
