"""docs/protocols.md against the code it describes: tables, examples and figures.

The document is the project's wire contract for people; the codecs, the
emulator and the sessions are the contract for machines.  These tests read
the document's tables and the figures its prose quotes and hold them to the
constants in the code, so that changing one without the other fails here,
naming the section to fix.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from app.machines.drill import session as drill_session
from app.machines.gcode import session as gcode_session
from app.machines.session import JOG_DEADMAN_S
from app.machines.stage import session as stage_session
from app.machines.usb3 import session as usb3_session
from app.profiles import GcodeSettings
from app.station import RECONNECT_DELAYS
from protocol.drill import codec as drill_codec
from protocol.drill import timing as drill_timing
from protocol.emulator.stage_firmware import PARAMETER_RANGES, XY_STAGE_PARAMETERS, StageConfig
from protocol.gcode import codec as gcode_codec
from protocol.gcode import overrides as gcode_overrides
from protocol.gcode.streaming import LineStreamer, StreamMode
from protocol.stage import codec as stage_codec
from protocol.transport.ble import DEFAULT_NAME_PREFIX, MICROCHIP_UART, NORDIC_UART
from protocol.usb3 import codec as usb3_codec

DOC = Path(__file__).resolve().parents[2] / "docs" / "protocols.md"


def _sections() -> dict[str, str]:
    """Each numbered section's text (``"1.4"``, ``"2"`` for a dialect's intro), by number."""
    sections: dict[str, str] = {}
    number = ""
    for line in DOC.read_text(encoding="utf-8").splitlines():
        heading = re.match(r"#{2,3} (\d+(?:\.\d+)?)[. ]", line)
        if heading is not None:
            number = heading[1]
            sections[number] = ""
        elif number:
            sections[number] += line + "\n"
    return sections


SECTIONS = _sections()


def section(number: str) -> str:
    assert number in SECTIONS, f"docs/protocols.md has no section {number}"
    return SECTIONS[number]


def table(number: str) -> list[list[str]]:
    """The rows of the section's tables, cells stripped, header and rule rows left out."""
    rows = []
    for line in section(number).splitlines():
        if not line.startswith("|") or set(line) <= set("|- "):
            continue
        rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
    return rows[1:] if rows else rows


def _codes(cell: str) -> list[int]:
    """The hex codes a cell names: `` `0F` ``, `` `10`…`19` ``, `` `08`, `09` ``."""
    found = [int(code, 16) for code in re.findall(r"`([0-9A-F]{1,2})`", cell)]
    if "…" in cell and len(found) == 2:
        return list(range(found[0], found[1] + 1))
    return found


def _number(text: str) -> int:
    return int(text.replace(" ", "").replace("\u202f", ""))


def test_every_command_id_and_only_those() -> None:
    ids = [code for row in table("1.2") for code in _codes(row[0])]
    assert sorted(ids) == sorted(int(c) for c in stage_codec.CommandId)


def test_the_write_ids_are_the_parameter_types_plus_0e() -> None:
    assert "TYPE = ID \u2212 `0E`" in section("1.2")
    for row in table("1.4"):
        (parameter,) = _codes(row[0])
        if parameter == stage_codec.EchoType.ENCODER:
            assert row[1] == "—"
            continue
        (write,) = _codes(row[1])
        assert write == stage_codec.write_command(stage_codec.EchoType(parameter))


def test_the_parameter_ranges_and_defaults() -> None:
    rows = {_codes(row[0])[0]: row for row in table("1.4")}
    assert set(rows) == set(stage_codec.PARAMETERS)
    for parameter, (low, high) in PARAMETER_RANGES.items():
        accepts, default = rows[parameter][4], rows[parameter][5]
        found = re.match(r"([\d ]+)…([\d ]+)", accepts)
        assert found is not None, accepts
        assert (_number(found[1]), _number(found[2])) == (low, high), parameter.name
        assert _number(default) == XY_STAGE_PARAMETERS[parameter], parameter.name
    assert "powers of two" in rows[stage_codec.EchoType.MICROSTEPS][4]


def test_every_echo_type_and_every_status_and_only_those() -> None:
    types = [code for row in table("1.3") if len(row) == 2 for code in _codes(row[0])]
    assert sorted(types) == sorted(int(t) for t in stage_codec.EchoType)
    status_rows = [row for row in table("1.3") if len(row) == 4]
    codes = sorted(code for row in status_rows for cell in row[::2] for code in _codes(cell))
    assert codes == sorted(int(s) for s in stage_codec.AxisStatus)


def test_every_subscriber_and_only_those() -> None:
    codes = sorted(code for row in table("1.5") for code in _codes(row[0]))
    known = sorted(int(s) for s in stage_codec.Subscriber if s != stage_codec.Subscriber.UNKNOWN)
    assert codes == known
    assert "SS `FF`" in section("1.5")


def test_the_device_flag_bits() -> None:
    row = next(
        row for row in table("1.5") if _codes(row[0]) == [stage_codec.Subscriber.DEVICE_FLAGS]
    )
    bits = {int(bit) for bit in re.findall(r"(\d) [A-Za-z]", row[2].split("(")[0])}
    assert bits == {int(flag).bit_length() - 1 for flag in stage_codec.DeviceFlag}
    assert f"within the last {StageConfig().session_timeout:g} s" in row[2]


def _frames(number: str) -> list[bytes]:
    return [
        (match[1] + "\n").encode("ascii")
        for match in re.finditer(r"^([<>][0-9A-F*-]+)\\n", section(number), re.M)
    ]


def test_the_framing_examples_decode_to_what_the_text_says() -> None:
    command, echo = _frames("1.1")
    assert stage_codec.decode(command) == (
        len(command),
        stage_codec.CommandFrame(
            (stage_codec.CommandPacket(stage_codec.CommandId.JOG, 1), stage_codec.CommandPacket(0)),
            stage_codec.Subscriber.BATTERY_VOLTAGE,
        ),
    )
    assert stage_codec.decode(echo) == (
        len(echo),
        stage_codec.EchoFrame(
            (
                stage_codec.EchoPacket(0, stage_codec.AxisStatus.ACCELERATING, 12_345),
                stage_codec.EchoPacket(0, stage_codec.AxisStatus.IDLE, 0),
            ),
            stage_codec.Subscriber.BATTERY_VOLTAGE,
            3712,
        ),
    )
    text = section("1.1")
    assert f"({stage_codec.command_frame_length(2)} for N = 2)" in text
    assert f"({stage_codec.echo_frame_length(2)} for N = 2)" in text


@pytest.mark.parametrize(
    ("number", "figure"),
    [
        ("1.6", f"*stale* after {stage_session.STALE_PERIODS} periods"),
        ("1.6", f"*lost* after {stage_session.LOST_AFTER_S:g} s"),
        ("1.6", f"burst of up to {stage_session.MAX_BURST} frames"),
        ("1.6", f"{StageConfig().jog_watchdog * 1000:g} ms"),
        ("1.6", f"every {StageConfig().control_cycle * 1000:g} ms"),
        ("1.6", f"{stage_session.JOG_END_MARGIN_MM:g} mm inside"),
        ("1.6", f"after {JOG_DEADMAN_S:g} s with no sign"),
        ("1.8", f"longer than {stage_codec.MAX_LINE} bytes"),
        ("2.5", f"After {usb3_session.POLL_AFTER_S:g} s without any reply"),
        ("2.5", f"*stale* after {usb3_session.STALE_AFTER_S:g} s"),
        ("2.5", f"*lost* after {usb3_session.LOST_AFTER_S:g} s"),
        ("2.5", f"{usb3_session.JOG_LEAD_S:g} s"),
        ("2.6", f"{usb3_codec.MAX_MESSAGE} bytes without a `;`"),
        ("3.5", f"within {drill_session.RECEIPT_TIMEOUT_S:g} s"),
        ("3.5", f"after {drill_session.RECEIPT_LATE_SHARE * drill_session.RECEIPT_TIMEOUT_S:g} s"),
        ("3.5", f"plus {drill_session.DONE_MARGIN_S:g} s"),
        ("3.5", f"late {drill_session.DONE_LATE_S:g} s past"),
        ("3.5", f"sends `{drill_session.PROBE_LETTER}\\r`"),
        ("3.6", f"{drill_codec.MAX_COMMAND} bytes without a CR"),
        ("4.1", f"at most {gcode_codec.MAX_LINE_BYTES} bytes"),
        ("4.4", f"{LineStreamer(StreamMode.COUNTING).capacity} for a {gcode_codec.RX_BUFFER}-byte"),
        ("4.6", f"every `status_ms` ({GcodeSettings().status_ms} ms by default)"),
        ("4.6", f"after {gcode_session.STALE_QUERIES} unanswered"),
        ("4.6", f"(at least {gcode_session.STALE_AFTER_MIN_S:g} s)"),
        ("4.6", f"*lost* after {gcode_session.SILENCE_S:g} s"),
        ("4.6", f"after {gcode_session.RESET_AFTER_S:g} s at the latest"),
        ("4.6", f"fewer than {gcode_session.JOG_BLOCKS_AHEAD} blocks"),
        ("4.7", f"{gcode_codec.MAX_REPLY_BYTES} bytes"),
    ],
)
def test_a_figure_the_text_quotes_is_the_codes(number: str, figure: str) -> None:
    assert figure in " ".join(section(number).split()), f"§{number} should say {figure!r}"


def test_the_reconnection_delays() -> None:
    *first, last = RECONNECT_DELAYS
    text = " ".join(section("0").split())
    assert f"after {', '.join(f'{d:g}' for d in first)}, then every {last:g} s" in text


def test_the_drill_timing() -> None:
    text = " ".join(section("3.4").split())
    periods = drill_timing.STEP_PERIODS_S
    assert (
        f"X {periods['X'] * 1000:g} ms, Y {periods['Y'] * 1000:g} ms, Z {periods['Z'] * 1000:g} ms"
        in text
    )
    assert f"about {drill_timing.DRILL_CYCLE_S:.2f} s per hole" in text
    assert f"{drill_timing.FIRST_DRILL_CYCLE_S:.2f} s for the first one" in text
    assert f"climbs {drill_timing.RETURN_FULL_STEPS} full steps" in text
    offsets = drill_timing.ZERO_OFFSETS
    assert f"X {offsets['X']}, Y {offsets['Y']} microsteps" in " ".join(section("3.2").split())


def test_the_usb3_settings_digits() -> None:
    text = " ".join(section("2.2").split())
    pitches = ", ".join(str(thread.pitch_mm) for thread in usb3_codec.Thread)
    names = ", ".join(thread.name for thread in usb3_codec.Thread)
    assert f"digit 0…{max(usb3_codec.Thread)} = {names} (pitch {pitches} mm" in text
    assert f"*m* = 0…{max(usb3_codec.StepSize)} means 1/2^m step" in text
    assert f"exactly {usb3_codec.MOVE_DIGITS} digits" in text
    assert usb3_codec.encode(usb3_codec.Move(usb3_codec.AxisId.Y, 500 * 32)).decode() in text


def test_the_ble_identifiers() -> None:
    text = section("1.7")
    for uuid in (MICROCHIP_UART.service, MICROCHIP_UART.write, MICROCHIP_UART.notify):
        assert f"`{uuid}`" in text
    assert f"`{NORDIC_UART.service}`" in text
    assert f"default `{DEFAULT_NAME_PREFIX}`" in text


def test_the_realtime_bytes() -> None:
    rows = table("4.3")
    named = {re.findall(r"`([^`]+)`", row[0])[0] for row in rows}
    wanted = {"?", "!", "~", "0x18", "0x85", "0x90", "0x95"}  # the overrides: 0x90…0x97
    assert named == wanted
    assert gcode_codec.REALTIME_BYTES == frozenset(b"?!~\x18\x85")
    assert set(gcode_overrides.BYTE_NAMES) == {bytes((b,)) for b in range(0x90, 0x98)}


def test_the_gcode_examples_of_replies_are_read_as_the_table_says() -> None:
    decode = gcode_codec.decode
    assert isinstance(decode(b"OK\r\n")[1], gcode_codec.Ok)
    assert decode(b"error: Bad number format\n")[1] == gcode_codec.ErrorReply(0)
    assert isinstance(decode(b"FluidNC v3.7\n")[1], gcode_codec.Banner)
    assert isinstance(decode(b">G54:ok\n")[1], gcode_codec.Feedback)
    text = section("4.2")
    assert "read as code 0" in text
    for prefix in gcode_codec.BANNER_PREFIXES:
        assert f"`{prefix}`" in text.lower()
