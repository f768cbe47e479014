"""The drill codec against docs/protocols.md §3: exact bytes, round trips, resynchronisation.

Commands end with CR, replies with CR LF; every byte sequence below is
written out by hand from the contract, not produced by the encoder under test.
"""

from __future__ import annotations

from collections.abc import Callable

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.drill.codec import (
    COMMAND_LETTERS,
    DRILL,
    HOME,
    MAX_POSITION,
    PARK,
    PEN_DOWN,
    PEN_UP,
    Command,
    CommandDecoder,
    DecodeResult,
    Rejected,
    Reply,
    ReplyDecoder,
    ReplyKind,
    decode_command,
    decode_reply,
    encode_command,
    encode_reply,
    error_letter,
    error_reply,
    move_x,
    move_y,
)

ALL_COMMANDS = [HOME, move_x(0), move_x(1234), move_y(999_999), DRILL, PEN_DOWN, PEN_UP, PARK]
ALL_REPLIES = [
    *(Reply(kind, letter) for kind in (ReplyKind.RECEIVED, ReplyKind.DONE) for letter in "NXYVKZP"),
    Reply(ReplyKind.ERROR, "Q"),
    Reply(ReplyKind.ERROR, "x"),
    Reply(ReplyKind.ERROR, "?"),
]


# -- encoding: exact bytes ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("command", "wire"),
    [
        (HOME, b"N\r"),
        (move_x(1234), b"X1234\r"),
        (move_x(0), b"X0\r"),
        (move_y(3000), b"Y3000\r"),
        (move_y(999_999), b"Y999999\r"),
        (DRILL, b"V\r"),
        (PEN_DOWN, b"K\r"),
        (PEN_UP, b"Z\r"),
        (PARK, b"P\r"),
    ],
)
def test_commands_encode_to_the_contracts_bytes(command: Command, wire: bytes) -> None:
    assert encode_command(command) == wire


@pytest.mark.parametrize(
    ("reply", "wire"),
    [
        (Reply(ReplyKind.RECEIVED, "X"), b"RX\r\n"),
        (Reply(ReplyKind.DONE, "N"), b"DN\r\n"),
        (Reply(ReplyKind.ERROR, "Q"), b"EQ\r\n"),
        (Reply(ReplyKind.ERROR, "?"), b"E?\r\n"),
    ],
)
def test_replies_encode_to_the_contracts_bytes(reply: Reply, wire: bytes) -> None:
    assert encode_reply(reply) == wire


@pytest.mark.parametrize(
    ("letter", "value"),
    [
        ("X", None),
        ("Y", -1),
        ("X", MAX_POSITION + 1),
        ("X", True),
        ("N", 5),
        ("V", 0),
        ("Q", None),
        ("x", 10),
        ("", None),
        ("XY", 1),
    ],
)
def test_invalid_commands_cannot_be_built(letter: str, value: int | None) -> None:
    with pytest.raises(ValueError):
        Command(letter, value)


@pytest.mark.parametrize(
    ("kind", "letter"),
    [
        (ReplyKind.RECEIVED, "Q"),
        (ReplyKind.DONE, "?"),
        (ReplyKind.ERROR, "1"),
        (ReplyKind.ERROR, ""),
    ],
)
def test_invalid_replies_cannot_be_built(kind: ReplyKind, letter: str) -> None:
    with pytest.raises(ValueError):
        Reply(kind, letter)


# -- decoding: round trips and splits ----------------------------------------------------------


@pytest.mark.parametrize("command", ALL_COMMANDS, ids=str)
def test_every_command_round_trips(command: Command) -> None:
    wire = encode_command(command)
    assert decode_command(wire) == (len(wire), command)


@pytest.mark.parametrize("reply", ALL_REPLIES, ids=str)
def test_every_reply_round_trips(reply: Reply) -> None:
    wire = encode_reply(reply)
    assert decode_reply(wire) == (len(wire), reply)


def test_a_reply_without_its_cr_is_accepted() -> None:
    assert decode_reply(b"DX\n") == (3, Reply(ReplyKind.DONE, "X"))


def test_an_lf_after_a_commands_cr_is_skipped_as_nothing() -> None:
    assert decode_command(b"X12\r\nN\r") == (4, move_x(12))
    assert decode_command(b"\nN\r") == (1, None)
    assert CommandDecoder().feed(b"X12\r\nN\r\n") == [move_x(12), HOME]


def test_leading_zeros_are_the_same_position() -> None:
    assert decode_command(b"X000100\r") == (8, move_x(100))


@pytest.mark.parametrize("partial", [b"", b"X", b"X12", b"X999999", b"N"])
def test_a_command_without_its_cr_needs_more(partial: bytes) -> None:
    assert decode_command(partial) == (0, None)


@pytest.mark.parametrize("partial", [b"", b"R", b"RX", b"RX\r"])
def test_a_reply_without_its_lf_needs_more(partial: bytes) -> None:
    assert decode_reply(partial) == (0, None)


def _feed_in_pieces(decoder: CommandDecoder | ReplyDecoder, wire: bytes, cut: int) -> list[object]:
    return [*decoder.feed(wire[:cut]), *decoder.feed(wire[cut:])]


COMMAND_STREAM = b"".join(encode_command(c) for c in ALL_COMMANDS)
REPLY_STREAM = b"".join(encode_reply(r) for r in ALL_REPLIES)


@pytest.mark.parametrize("cut", range(len(COMMAND_STREAM) + 1))
def test_commands_split_anywhere_decode_the_same(cut: int) -> None:
    decoder = CommandDecoder()
    assert _feed_in_pieces(decoder, COMMAND_STREAM, cut) == ALL_COMMANDS
    assert (decoder.messages, decoder.rejected) == (len(ALL_COMMANDS), 0)


@pytest.mark.parametrize("cut", range(len(REPLY_STREAM) + 1))
def test_replies_split_anywhere_decode_the_same(cut: int) -> None:
    decoder = ReplyDecoder()
    assert _feed_in_pieces(decoder, REPLY_STREAM, cut) == ALL_REPLIES
    assert (decoder.messages, decoder.rejected) == (len(ALL_REPLIES), 0)


def test_byte_by_byte_decodes_the_same() -> None:
    commands, replies = CommandDecoder(), ReplyDecoder()
    got_commands = [m for b in COMMAND_STREAM for m in commands.feed(bytes([b]))]
    got_replies = [m for b in REPLY_STREAM for m in replies.feed(bytes([b]))]
    assert got_commands == ALL_COMMANDS
    assert got_replies == ALL_REPLIES


# -- malformed input -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("line", "letter"),
    [
        (b"Q\r", "Q"),  # unknown letter
        (b"X\r", "X"),  # X without digits
        (b"Xabc\r", "X"),
        (b"X-5\r", "X"),  # negative
        (b"X+5\r", "X"),
        (b"X 5\r", "X"),
        (b"X1234567\r", "X"),  # 7 digits: more than any position
        (b"N1\r", "N"),  # a value where none belongs
        (b"x100\r", "x"),  # the contract's letters are upper case
        (b"-5\r", "?"),
        (b"5\r", "?"),
        (b"\xff\r", "?"),
    ],
)
def test_malformed_command_lines_are_rejected_with_the_letter_to_answer(
    line: bytes, letter: str
) -> None:
    used, result = decode_command(line)
    assert used == len(line)
    assert isinstance(result, Rejected) and result.raw == line
    assert error_reply(result) == Reply(ReplyKind.ERROR, letter)
    assert encode_reply(error_reply(result)) == b"E" + letter.encode("latin-1") + b"\r\n"


@pytest.mark.parametrize("line", [b"RQ\r\n", b"D?\r\n", b"E1\r\n", b"QX\r\n", b"R\r\n", b"RXX\r\n"])
def test_malformed_reply_lines_are_rejected(line: bytes) -> None:
    used, result = decode_reply(line)
    assert used == len(line)
    assert isinstance(result, Rejected) and result.raw == line


def test_garbage_is_counted_once_per_line_and_the_next_command_decodes() -> None:
    decoder = CommandDecoder()
    results = decoder.feed(b"Xabc\rQ\rX100\r")
    assert results[2:] == [move_x(100)]
    assert all(isinstance(r, Rejected) for r in results[:2])
    assert (decoder.messages, decoder.rejected) == (1, 2)
    assert decoder.last_rejected == Rejected(b"Q\r", "unknown command")


def test_an_over_long_run_costs_one_reject_and_is_dropped_to_its_cr() -> None:
    decoder = CommandDecoder()
    results = decoder.feed(b"X" + b"9" * 50)
    assert len(results) == 1 and isinstance(results[0], Rejected)
    assert results[0].raw == b"X" + b"9" * 50  # everything held, no CR in 8 bytes or more
    assert error_reply(results[0]) == Reply(ReplyKind.ERROR, "X")
    assert decoder.feed(b"9" * 50) == []
    assert decoder.feed(b"99\rN\r") == [HOME]
    assert (decoder.messages, decoder.rejected) == (1, 1)


def test_garbage_replies_are_counted_and_the_next_reply_decodes() -> None:
    decoder = ReplyDecoder()
    results = decoder.feed(b"hello world\r\nRX\r\n")
    assert len(results) == 2 and isinstance(results[0], Rejected)
    assert results[1] == Reply(ReplyKind.RECEIVED, "X")
    assert (decoder.messages, decoder.rejected) == (1, 1)


def test_empty_lines_are_neither_messages_nor_rejects() -> None:
    decoder = CommandDecoder()
    assert decoder.feed(b"\r\r\n\rV\r") == [DRILL]
    assert (decoder.messages, decoder.rejected) == (1, 0)


def test_reset_forgets_a_partial_line() -> None:
    decoder = CommandDecoder()
    assert decoder.feed(b"X12") == []
    decoder.reset()
    assert decoder.feed(b"34\r") == [Rejected(b"34\r", "unknown command")]


@pytest.mark.parametrize(("raw", "letter"), [(b"\r\nK9\r", "K"), (b"", "?"), (b"\r", "?")])
def test_error_letter_skips_line_ends(raw: bytes, letter: str) -> None:
    assert error_letter(raw) == letter


# -- never raises on wire input -------------------------------------------------------------


Decode = Callable[[bytes], DecodeResult[object]]


@pytest.mark.parametrize("decode", [decode_command, decode_reply])
@given(data=st.binary(max_size=64))
def test_pure_decoders_never_raise_and_consume_within_the_buffer(
    decode: Decode, data: bytes
) -> None:
    used, result = decode(data)
    assert 0 <= used <= len(data)
    if used == 0:
        assert result is None


@given(chunks=st.lists(st.binary(max_size=20), max_size=20))
def test_stream_decoders_never_raise_and_resynchronise(chunks: list[bytes]) -> None:
    commands, replies = CommandDecoder(), ReplyDecoder()
    for chunk in chunks:
        commands.feed(chunk)
        replies.feed(chunk)
    # Whatever came before, a fresh line after a line end decodes.
    assert commands.feed(b"\rN\r")[-1:] == [HOME]
    assert replies.feed(b"\nDN\r\n")[-1:] == [Reply(ReplyKind.DONE, "N")]


@given(
    st.sampled_from(COMMAND_LETTERS),
    st.integers(0, MAX_POSITION),
)
def test_any_valid_command_round_trips(letter: str, value: int) -> None:
    command = Command(letter, value if letter in "XY" else None)
    wire = encode_command(command)
    assert CommandDecoder().feed(wire) == [command]
