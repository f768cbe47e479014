"""The stage codec against docs/protocols.md §1: exact bytes, round trips, resynchronisation."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.stage.codec import (
    AxisStatus,
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoPacket,
    EchoType,
    Rejected,
    StageDecoder,
    Subscriber,
    checksum,
    decode,
    decode_data,
    encode_command,
    encode_data,
    encode_echo,
    write_command,
    written_parameter,
)

JOG_X = CommandFrame(
    (CommandPacket(CommandId.JOG, 1), CommandPacket(CommandId.NOP, 0)), Subscriber.BATTERY_VOLTAGE
)
ECHO = EchoFrame(
    (
        EchoPacket(EchoType.POSITION, AxisStatus.ACCELERATING, 12345),
        EchoPacket(EchoType.POSITION, AxisStatus.IDLE, 0),
    ),
    Subscriber.BATTERY_VOLTAGE,
    3712,
)


def _ck(body: bytes) -> bytes:
    x = 0
    for b in body:
        x ^= b
    return b"%02X" % x


def test_command_frame_matches_the_documented_example() -> None:
    body = b">02000001" + b"00000000" + b"01"
    assert encode_command(JOG_X) == body + b"*" + _ck(body) + b"\n"
    assert len(encode_command(JOG_X)) == 23


def test_echo_frame_matches_the_documented_example() -> None:
    body = b"<01012345" + b"00000000" + b"01003712"
    assert encode_echo(ECHO) == body + b"*" + _ck(body) + b"\n"
    assert len(encode_echo(ECHO)) == 29


def test_checksum_includes_start_character() -> None:
    assert checksum(b">") == ord(">")
    assert checksum(b"<0") == ord("<") ^ ord("0")


@pytest.mark.parametrize(
    ("value", "text"),
    [(0, b"000000"), (999999, b"999999"), (12345, b"012345"), (-1, b"-00001"), (-99999, b"-99999")],
)
def test_data_encoding(value: int, text: bytes) -> None:
    assert encode_data(value) == text
    assert decode_data(text) == value


@pytest.mark.parametrize("value", [1_000_000, -100_000])
def test_data_out_of_range_is_a_programming_error(value: int) -> None:
    with pytest.raises(ValueError):
        encode_data(value)


@pytest.mark.parametrize(
    "text", [b"-00000", b"12345", b"1234567", b"+12345", b"12 345", b"--1234", b"00000a"]
)
def test_malformed_data_fields_are_refused(text: bytes) -> None:
    assert decode_data(text) is None


@pytest.mark.parametrize("command", list(CommandId))
def test_every_command_id_round_trips(command: CommandId) -> None:
    frame = CommandFrame(
        (CommandPacket(command, -42), CommandPacket(command, 7)), Subscriber.ROTATION
    )
    used, decoded = decode(encode_command(frame))
    assert used == 23
    assert decoded == frame
    assert isinstance(decoded, CommandFrame)
    assert CommandId(decoded.packets[0].command) is command


@pytest.mark.parametrize("echo_type", list(EchoType))
@pytest.mark.parametrize("status", list(AxisStatus))
def test_every_type_and_status_round_trips(echo_type: EchoType, status: AxisStatus) -> None:
    frame = EchoFrame(
        (EchoPacket(echo_type, status, 999999), EchoPacket(echo_type, status, -99999))
    )
    assert decode(encode_echo(frame)) == (29, frame)


@pytest.mark.parametrize("subscriber", list(Subscriber))
def test_every_subscriber_round_trips(subscriber: Subscriber) -> None:
    echo = EchoFrame((EchoPacket(0, 0, 0),) * 2, subscriber, 123)
    command = CommandFrame((CommandPacket(0, 0),) * 2, subscriber)
    assert decode(encode_echo(echo))[1] == echo
    assert decode(encode_command(command))[1] == command


@pytest.mark.parametrize("axes", [1, 2, 3, 6])
def test_frames_for_n_axes(axes: int) -> None:
    frame = EchoFrame(tuple(EchoPacket(0, 2, i * 1000) for i in range(axes)), 4, 2512)
    encoded = encode_echo(frame)
    assert len(encoded) == 13 + 8 * axes
    assert decode(encoded, axes) == (len(encoded), frame)
    # The same bytes read with the wrong axis count are a bad length, not a crash.
    used, result = decode(encoded, axes + 1)
    assert used == len(encoded) and isinstance(result, Rejected)


def test_write_ids_map_to_parameter_types() -> None:
    assert write_command(EchoType.ACCELERATION) == 0x12
    assert write_command(EchoType.TRAVEL) == 0x19
    assert written_parameter(0x10) is EchoType.FAST_SPEED
    assert written_parameter(CommandId.READ) is None
    with pytest.raises(ValueError):
        write_command(EchoType.ENCODER)


STREAM = encode_command(JOG_X) + encode_echo(ECHO) + encode_command(JOG_X)


def _feed_all(chunks: list[bytes]) -> tuple[list[object], StageDecoder]:
    decoder = StageDecoder()
    out: list[object] = []
    for chunk in chunks:
        out.extend(decoder.feed(chunk))
    return out, decoder


def test_need_more_returns_nothing_used() -> None:
    assert decode(encode_echo(ECHO)[:-1]) == (0, None)
    assert decode(b"") == (0, None)


def test_decode_whole_stream_in_one_chunk() -> None:
    frames, decoder = _feed_all([STREAM])
    assert frames == [JOG_X, ECHO, JOG_X]
    assert (decoder.frames, decoder.rejected) == (3, 0)


@pytest.mark.parametrize("cut", range(1, len(STREAM)))
def test_decode_split_in_two_at_every_position(cut: int) -> None:
    frames, decoder = _feed_all([STREAM[:cut], STREAM[cut:]])
    assert frames == [JOG_X, ECHO, JOG_X]
    assert decoder.rejected == 0


def test_decode_byte_by_byte() -> None:
    frames, _ = _feed_all([bytes([b]) for b in STREAM])
    assert frames == [JOG_X, ECHO, JOG_X]


def _sealed(body: bytes) -> bytes:
    """A body with a *correct* checksum, so only the field under test is wrong."""
    return body + b"*" + _ck(body) + b"\n"


def _corrupt(frame: bytes, index: int, byte: int) -> bytes:
    return frame[:index] + bytes([byte]) + frame[index + 1 :]


BAD_FRAMES = {
    # Index 20 is the first checksum digit ("3" for this frame); any other digit is wrong.
    "wrong checksum": _corrupt(encode_command(JOG_X), 20, ord("0")),
    "bad length": encode_command(JOG_X)[:10] + encode_command(JOG_X)[11:],
    "non-hex ID": _sealed(b">0G000001" + b"00000000" + b"01"),
    "lower-case hex ID": _sealed(b">0a000001" + b"00000000" + b"01"),
    "bad DATA": _sealed(b">0200x001" + b"00000000" + b"01"),
    "negative zero DATA": _sealed(b">02-00000" + b"00000000" + b"01"),
    "garbage line": b"hello\n",
    "no checksum mark": encode_command(JOG_X).replace(b"*", b"#"),
}


@pytest.mark.parametrize("name", list(BAD_FRAMES))
def test_malformed_frame_is_dropped_counted_and_the_next_one_decodes(name: str) -> None:
    frames, decoder = _feed_all([BAD_FRAMES[name] + encode_echo(ECHO)])
    assert frames[-1] == ECHO
    assert isinstance(frames[0], Rejected)
    assert decoder.rejected == 1
    assert decoder.frames == 1


def test_endless_garbage_without_terminator_is_dropped_up_to_its_line_end() -> None:
    """A frame on the same line as the garbage goes with it, as it would fed whole."""
    decoder = StageDecoder()
    results = decoder.feed(b"x" * 1000)
    assert len(results) == 1 and isinstance(results[0], Rejected)
    assert decoder.feed(encode_echo(ECHO)) == []
    assert decoder.feed(encode_echo(ECHO)) == [ECHO]
    assert decoder.rejected == 1


@given(
    index=st.integers(min_value=0, max_value=27),
    byte=st.integers(min_value=0, max_value=255),
)
def test_random_single_byte_corruption_never_yields_a_wrong_frame(index: int, byte: int) -> None:
    good = encode_echo(ECHO)
    bad = _corrupt(good, index, byte)
    frames, decoder = _feed_all([bad + good])
    # The good frame after the damage always decodes and nothing else ever does: one changed
    # byte always breaks the checksum, and a stray terminator splits the line into two rejects.
    decoded = [f for f in frames if not isinstance(f, Rejected)]
    expected_rejects = 0 if bad == good else 2 if byte == ord("\n") else 1
    assert decoded == [ECHO] * (2 if bad == good else 1)
    assert decoder.rejected == expected_rejects


@given(st.binary(max_size=200))
def test_arbitrary_bytes_never_raise_and_resync(noise: bytes) -> None:
    decoder = StageDecoder()
    decoder.feed(noise)
    # A terminator flushes whatever partial line the noise left behind.
    decoder.feed(b"\n")
    assert decoder.feed(encode_echo(ECHO)) == [ECHO]


@given(
    st.lists(st.tuples(st.integers(0, 255), st.integers(-99999, 999999)), min_size=2, max_size=2),
    st.integers(0, 255),
)
def test_command_round_trip_any_values(packets: list[tuple[int, int]], subscriber: int) -> None:
    frame = CommandFrame(tuple(CommandPacket(c, d) for c, d in packets), subscriber)
    assert decode(encode_command(frame))[1] == frame
