"""The usb3 codec against docs/protocols.md §2: exact bytes, round trips, resynchronisation.

Numbers are worked out by hand from the contract: a count is 1/32 step, 200
full steps turn the screw once, so 1 mm is 6400 / pitch counts.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.usb3.codec import (
    MAX_COUNT,
    AxisId,
    Command,
    CommandDecoder,
    GetSettings,
    Move,
    NotUnderstood,
    Position,
    Rejected,
    Reply,
    ReplyDecoder,
    SetDirection,
    StepSize,
    StepSizes,
    StopAll,
    Thread,
    Threads,
    ZeroAll,
    count_per_mm,
    count_to_mm,
    decode_command,
    decode_reply,
    encode,
    encode_settings,
    move_commands,
    nearest_reachable_count,
)

# -- exact strings -------------------------------------------------------------------------


def test_500_full_steps_on_y_is_the_documented_string() -> None:
    # 500 full steps = 2.5 mm on a 1 mm pitch: 500 x 32 counts
    count = nearest_reachable_count(2.5, StepSize.FULL, Thread.M6)
    assert count == 16_000
    assert encode(Move(AxisId.Y, count)) == b"Y000000000016000;"


def test_500_steps_at_1_32_on_y_is_the_documented_string() -> None:
    # 500 / 32 full steps = 0.078125 mm on a 1 mm pitch
    count = nearest_reachable_count(0.078125, StepSize.THIRTY_SECOND, Thread.M6)
    assert count == 500
    assert encode(Move(AxisId.Y, count)) == b"Y000000000000500;"


@pytest.mark.parametrize(
    ("message", "wire"),
    [
        (SetDirection((1, -1, 1)), b"D+-+;"),
        (SetDirection((-1, -1, -1)), b"D---;"),
        (Move(AxisId.X, 0), b"X000000000000000;"),
        (Move(AxisId.Z, MAX_COUNT), b"Z999999999999999;"),
        (StepSizes((StepSize.FULL, StepSize.EIGHTH, StepSize.THIRTY_SECOND)), b"M035;"),
        (Threads((Thread.M2, Thread.M6, Thread.M10)), b"T046;"),
        (ZeroAll(), b"C;"),
        (GetSettings(), b"G;"),
        (StopAll(), b"S;"),
        (Position(AxisId.X, 80_000), b"X80000;"),
        (Position(AxisId.Y, -3_200), b"Y-3200;"),
        (Position(AxisId.Z, 0), b"Z0;"),
        (NotUnderstood(), b"?;"),
    ],
)
def test_messages_encode_exactly(message: Command | Reply, wire: bytes) -> None:
    assert encode(message) == wire


def test_settings_report_is_both_messages() -> None:
    sizes = (StepSize.EIGHTH, StepSize.EIGHTH, StepSize.HALF)
    threads = (Thread.M6, Thread.M8, Thread.M3)
    assert encode_settings(sizes, threads) == b"M331;T451;"


@pytest.mark.parametrize(
    "bad",
    [
        lambda: Move(AxisId.X, -1),
        lambda: Move(AxisId.X, MAX_COUNT + 1),
        lambda: SetDirection((1, 0, 1)),
        lambda: Position(AxisId.X, -(MAX_COUNT + 1)),
    ],
)
def test_values_the_wire_cannot_carry_are_programming_errors(bad: Callable[[], object]) -> None:
    with pytest.raises(ValueError):
        bad()


# -- enums and conversions -------------------------------------------------------------------


def test_step_sizes_know_their_pulse() -> None:
    assert [s.exponent for s in StepSize] == [0, 1, 2, 3, 4, 5]
    assert [s.divisor for s in StepSize] == [1, 2, 4, 8, 16, 32]
    assert [s.counts_per_pulse for s in StepSize] == [32, 16, 8, 4, 2, 1]
    assert [s.label for s in StepSize] == ["1", "1/2", "1/4", "1/8", "1/16", "1/32"]


def test_threads_know_their_pitch() -> None:
    assert [t.name for t in Thread] == ["M2", "M3", "M4", "M5", "M6", "M8", "M10"]
    assert [t.pitch_mm for t in Thread] == [0.4, 0.5, 0.7, 0.8, 1.0, 1.25, 1.5]


def test_counts_per_mm_depend_on_the_thread_only() -> None:
    assert count_per_mm(Thread.M6) == 6400
    assert count_per_mm(Thread.M2) == 16_000
    assert count_per_mm(Thread.M10) == pytest.approx(4266.666_666_7)


def test_count_to_mm() -> None:
    assert count_to_mm(80_000, Thread.M6) == 12.5
    assert count_to_mm(16_000, Thread.M2) == pytest.approx(1.0)
    assert count_to_mm(-6_400, Thread.M10) == pytest.approx(-1.5)


def test_nearest_reachable_count_rounds_to_whole_pulses() -> None:
    # 12.5 mm at M6 is 80000 counts: 20000 pulses of 4 at 1/8 step, 2500 of 32 at full step
    assert nearest_reachable_count(12.5, StepSize.EIGHTH, Thread.M6) == 80_000
    # 0.01 mm at M6 = 64 counts = 2 full steps; 0.012 mm = 76.8 counts -> 2 full steps (64)
    assert nearest_reachable_count(0.012, StepSize.FULL, Thread.M6) == 64
    # 0.014 mm = 89.6 counts = 2.8 full steps -> 3 (96)
    assert nearest_reachable_count(0.014, StepSize.FULL, Thread.M6) == 96
    assert nearest_reachable_count(-0.014, StepSize.FULL, Thread.M6) == -96
    # 1 mm at M10 = 4266.67 counts: 1/32 step rounds to 4267, 1/2 step (16) to 4272
    assert nearest_reachable_count(1.0, StepSize.THIRTY_SECOND, Thread.M10) == 4267
    assert nearest_reachable_count(1.0, StepSize.HALF, Thread.M10) == 4272
    assert nearest_reachable_count(0.0, StepSize.FULL, Thread.M2) == 0


def test_nearest_reachable_count_refuses_non_finite_distances() -> None:
    with pytest.raises(ValueError):
        nearest_reachable_count(math.nan, StepSize.FULL, Thread.M6)


@given(
    mm=st.floats(min_value=-500.0, max_value=500.0, allow_nan=False),
    step_size=st.sampled_from(StepSize),
    thread=st.sampled_from(Thread),
)
def test_reachable_count_round_trip_within_half_a_pulse(
    mm: float, step_size: StepSize, thread: Thread
) -> None:
    count = nearest_reachable_count(mm, step_size, thread)
    unit = step_size.counts_per_pulse
    assert count % unit == 0
    pulse_mm = count_to_mm(unit, thread)
    assert abs(count_to_mm(count, thread) - mm) <= pulse_mm / 2 + 1e-9
    assert nearest_reachable_count(-mm, step_size, thread) == -count


# -- round trips ----------------------------------------------------------------------------

COMMANDS: list[Command] = [
    *(SetDirection((x, y, z)) for x in (1, -1) for y in (1, -1) for z in (1, -1)),
    *(Move(axis, count) for axis in AxisId for count in (0, 1, 16_000, MAX_COUNT)),
    *(StepSizes((s, s, s)) for s in StepSize),
    StepSizes((StepSize.FULL, StepSize.QUARTER, StepSize.SIXTEENTH)),
    *(Threads((t, t, t)) for t in Thread),
    Threads((Thread.M10, Thread.M3, Thread.M5)),
    ZeroAll(),
    GetSettings(),
    StopAll(),
]

REPLIES: list[Reply] = [
    *(Position(axis, count) for axis in AxisId for count in (0, 1, -1, 80_000, -MAX_COUNT)),
    *(StepSizes((s, s, s)) for s in StepSize),
    *(Threads((t, t, t)) for t in Thread),
    NotUnderstood(),
]


@pytest.mark.parametrize("command", COMMANDS, ids=repr)
def test_every_command_round_trips(command: Command) -> None:
    wire = encode(command)
    assert decode_command(wire) == (len(wire), command)


@pytest.mark.parametrize("reply", REPLIES, ids=repr)
def test_every_reply_round_trips(reply: Reply) -> None:
    wire = encode(reply)
    assert decode_reply(wire) == (len(wire), reply)


@given(st.sampled_from(AxisId), st.integers(-MAX_COUNT, MAX_COUNT))
def test_any_position_round_trips(axis: AxisId, count: int) -> None:
    wire = encode(Position(axis, count))
    assert decode_reply(wire) == (len(wire), Position(axis, count))


@pytest.mark.parametrize(
    ("wire", "reply"),
    [
        (b"X+12;", Position(AxisId.X, 12)),
        (b"Y-0007;", Position(AxisId.Y, -7)),
        (b"Z-0;", Position(AxisId.Z, 0)),
    ],
)
def test_replies_accept_the_forms_a_signed_count_may_take(wire: bytes, reply: Reply) -> None:
    assert decode_reply(wire) == (len(wire), reply)


def test_move_commands_set_all_directions_then_move() -> None:
    commands = move_commands([-160, 0, 32])
    assert commands == [SetDirection((-1, 1, 1)), Move(AxisId.X, 160), Move(AxisId.Z, 32)]
    assert b"".join(encode(c) for c in commands) == b"D-++;X000000000000160;Z000000000000032;"
    assert move_commands([0, 0, 0]) == []
    with pytest.raises(ValueError):
        move_commands([1, 2])


# -- malformed input -------------------------------------------------------------------------

BAD_COMMANDS = {
    "garbage": b"hello;",
    "empty": b";",
    "short count": b"X16000;",
    "long count": b"X0000000000000001;",
    "signed count": b"X-00000000000001;",
    "count with a space": b"X00000000000 001;",
    "two directions": b"D+-;",
    "direction not a sign": b"D+0+;",
    "step size above 5": b"M036;",
    "thread above 6": b"T047;",
    "two step sizes": b"M33;",
    "lower case": b"g;",
    "C with data": b"C1;",
    "a reply sent to the unit": b"?;",
}

BAD_REPLIES = {
    "garbage": b"ok;",
    "empty position": b"X;",
    "sign only": b"X-;",
    "16 digits": b"X1000000000000000;",
    "space": b"X 12;",
    "step size above 5": b"M306;",
    "a command sent to the host": b"G;",
}


@pytest.mark.parametrize("name", list(BAD_COMMANDS))
def test_malformed_command_is_rejected_counted_and_the_next_one_decodes(name: str) -> None:
    decoder = CommandDecoder()
    results = decoder.feed(BAD_COMMANDS[name] + b"G;")
    assert isinstance(results[0], Rejected)
    assert results[0].raw == BAD_COMMANDS[name]
    assert results[1:] == [GetSettings()]
    assert (decoder.rejected, decoder.messages) == (1, 1)
    assert decoder.last_rejected == results[0]


@pytest.mark.parametrize("name", list(BAD_REPLIES))
def test_malformed_reply_is_rejected_counted_and_the_next_one_decodes(name: str) -> None:
    decoder = ReplyDecoder()
    results = decoder.feed(BAD_REPLIES[name] + b"X5;")
    assert isinstance(results[0], Rejected)
    assert results[1:] == [Position(AxisId.X, 5)]
    assert (decoder.rejected, decoder.messages) == (1, 1)


def test_need_more_uses_nothing() -> None:
    assert decode_command(b"X00000000001") == (0, None)
    assert decode_command(b"") == (0, None)
    assert decode_reply(b"M33") == (0, None)


def test_whitespace_between_messages_is_skipped_not_rejected() -> None:
    assert decode_command(b"\r\nG;") == (2, None)
    decoder = CommandDecoder()
    assert decoder.feed(b"G;\r\nC;\n") == [GetSettings(), ZeroAll()]
    assert decoder.rejected == 0


def test_a_long_garbage_run_ending_in_a_terminator_is_one_reject() -> None:
    decoder = CommandDecoder()
    results = decoder.feed(b"x" * 100 + b";G;")
    assert len(results) == 2 and isinstance(results[0], Rejected)
    assert results[1] == GetSettings()


@pytest.mark.parametrize("whole", [True, False], ids=["one chunk", "byte by byte"])
def test_an_endless_run_without_terminator_is_dropped_as_one_reject(whole: bool) -> None:
    decoder = CommandDecoder()
    noise = b"x" * 1000
    chunks = [noise] if whole else [bytes([b]) for b in noise]
    results = [r for chunk in chunks for r in decoder.feed(chunk)]
    assert len(results) == 1 and isinstance(results[0], Rejected)
    # the rest of the run, up to its ';', is discarded without another reject
    assert decoder.feed(b"xxxx;G;") == [GetSettings()]
    assert decoder.rejected == 1


def test_the_buffer_stays_bounded_under_noise() -> None:
    decoder = CommandDecoder()
    for _ in range(100):
        decoder.feed(b"y" * 50)
    assert len(decoder._buffer) < 20
    decoder.reset()
    assert decoder.feed(b"S;") == [StopAll()]


# -- streams in arbitrary pieces ----------------------------------------------------------

STREAM_COMMANDS: list[Command] = [
    SetDirection((1, -1, 1)),
    Move(AxisId.Y, 16_000),
    StepSizes((StepSize.EIGHTH, StepSize.FULL, StepSize.THIRTY_SECOND)),
    GetSettings(),
    ZeroAll(),
]
COMMAND_STREAM = b"".join(encode(c) for c in STREAM_COMMANDS)

STREAM_REPLIES: list[Reply] = [
    Position(AxisId.X, 12),
    Position(AxisId.Y, -3200),
    StepSizes((StepSize.EIGHTH,) * 3),
    Threads((Thread.M6,) * 3),
    NotUnderstood(),
]
REPLY_STREAM = b"".join(encode(r) for r in STREAM_REPLIES)


def _feed_commands(chunks: list[bytes]) -> tuple[list[Command | Rejected], CommandDecoder]:
    decoder = CommandDecoder()
    return [r for chunk in chunks for r in decoder.feed(chunk)], decoder


def _feed_replies(chunks: list[bytes]) -> list[Reply | Rejected]:
    decoder = ReplyDecoder()
    return [r for chunk in chunks for r in decoder.feed(chunk)]


@pytest.mark.parametrize("cut", range(1, len(COMMAND_STREAM)))
def test_commands_split_in_two_at_every_position(cut: int) -> None:
    results, decoder = _feed_commands([COMMAND_STREAM[:cut], COMMAND_STREAM[cut:]])
    assert results == STREAM_COMMANDS
    assert decoder.rejected == 0


@pytest.mark.parametrize("cut", range(1, len(REPLY_STREAM)))
def test_replies_split_in_two_at_every_position(cut: int) -> None:
    assert _feed_replies([REPLY_STREAM[:cut], REPLY_STREAM[cut:]]) == STREAM_REPLIES


def test_commands_byte_by_byte() -> None:
    results, decoder = _feed_commands([bytes([b]) for b in COMMAND_STREAM])
    assert results == STREAM_COMMANDS
    assert decoder.rejected == 0


def test_noise_between_messages_costs_one_reject_byte_by_byte() -> None:
    # "D+-+;" + "Y000000000016000;" is 22 bytes: the noise lands between two messages
    stream = COMMAND_STREAM[:22] + b"zz;" + COMMAND_STREAM[22:]
    results, decoder = _feed_commands([bytes([b]) for b in stream])
    assert results == [
        *STREAM_COMMANDS[:2],
        Rejected(b"zz;", "unknown command"),
        *STREAM_COMMANDS[2:],
    ]
    assert decoder.rejected == 1


def test_noise_inside_a_message_spoils_it_and_the_rest_of_it_byte_by_byte() -> None:
    # The ';' in the noise ends the half-sent move; its other half is garbage up to its own ';'
    stream = COMMAND_STREAM[:10] + b"zz;" + COMMAND_STREAM[10:]
    results, decoder = _feed_commands([bytes([b]) for b in stream])
    assert results[0] == STREAM_COMMANDS[0]
    assert [r.raw for r in results[1:3] if isinstance(r, Rejected)] == [
        b"Y0000zz;",
        b"00000016000;",
    ]
    assert results[3:] == STREAM_COMMANDS[2:]
    assert decoder.rejected == 2


def test_replies_byte_by_byte() -> None:
    assert _feed_replies([bytes([b]) for b in REPLY_STREAM]) == STREAM_REPLIES


@given(st.binary(max_size=200))
def test_arbitrary_bytes_never_raise_and_resync(noise: bytes) -> None:
    commands = CommandDecoder()
    replies = ReplyDecoder()
    for decoder in (commands, replies):
        decoder.feed(noise)
        decoder.feed(b";")  # a terminator ends whatever the noise left open
    assert commands.feed(b"G;") == [GetSettings()]
    assert replies.feed(b"X-5;") == [Position(AxisId.X, -5)]
