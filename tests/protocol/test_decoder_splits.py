"""Whether a frame is accepted cannot depend on where the transport split its bytes.

Serial reads and BLE notifications cut a stream anywhere: every decoder is fed
the same bytes whole, one byte at a time and in random pieces, and must
accept the same messages and reject the same number of runs.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

from hypothesis import given, settings
from hypothesis import strategies as st

from protocol.drill.codec import ReplyDecoder as DrillReplyDecoder
from protocol.framing import Rejected
from protocol.gcode.codec import Ok
from protocol.gcode.codec import make_decoder as gcode_decoder
from protocol.stage.codec import (
    DATA_MAX,
    DATA_MIN,
    EchoFrame,
    EchoPacket,
    StageDecoder,
    encode_echo,
)
from protocol.usb3.codec import ReplyDecoder as Usb3ReplyDecoder

Feed = Callable[[bytes], list[object]]


def outcome(make: Callable[[], object], pieces: Sequence[bytes]) -> tuple[list[object], int]:
    decoder = make()
    accepted: list[object] = []
    rejected = 0
    for piece in pieces:
        for result in decoder.feed(piece):  # type: ignore[attr-defined]
            if isinstance(result, Rejected):
                rejected += 1
            else:
                accepted.append(result)
    return accepted, rejected


def split(data: bytes, cuts: list[int]) -> list[bytes]:
    points = sorted({c % (len(data) + 1) for c in cuts})
    edges = [0, *points, len(data)]
    return [data[a:b] for a, b in itertools.pairwise(edges) if b > a]


echo = st.builds(
    lambda packets, sub, data: encode_echo(EchoFrame(tuple(packets), sub, data)),
    st.lists(
        st.builds(
            EchoPacket,
            st.integers(0, 15),
            st.integers(0, 15),
            st.integers(DATA_MIN, DATA_MAX),
        ),
        min_size=2,
        max_size=2,
    ),
    st.integers(0, 255),
    st.integers(DATA_MIN, DATA_MAX),
)
gcode_replies = st.sampled_from(
    [b"ok\r\n", b"error:9\r\n", b"<Idle|MPos:0.000,0.000,0.000|Bf:15,128|FS:0,0>\r\n",
     b"[MSG:Reset to continue]\r\n", b"Grbl 1.1h ['$' for help]\r\n", b"ALARM:1\r\n",
     b"$10=1\r\n", b"\r\n"]
)  # fmt: skip
drill_replies = st.sampled_from([b"RV\r\n", b"DV\r\n", b"EX\r\n", b"RX\r\n", b"DN\r\n"])
usb3_replies = st.sampled_from([b"X12;", b"Y-5;", b"Z0;", b"M533;T444;", b"?;"])
noise = st.binary(min_size=0, max_size=300)


def mutate(stream: list[bytes], garbage: list[bytes]) -> bytes:
    mixed: list[bytes] = []
    for i, part in enumerate(stream):
        mixed.append(part)
        if i < len(garbage):
            mixed.append(garbage[i])
    return b"".join(mixed)


def check(make: Callable[[], object], data: bytes, cuts: list[int]) -> None:
    whole = outcome(make, [data])
    assert outcome(make, split(data, cuts)) == whole
    assert outcome(make, [data[i : i + 1] for i in range(len(data))]) == whole


@settings(max_examples=300, deadline=None)
@given(st.lists(echo, max_size=6), st.lists(noise, max_size=3), st.lists(st.integers(0, 4000)))
def test_stage_frames_do_not_depend_on_the_split(
    frames: list[bytes], garbage: list[bytes], cuts: list[int]
) -> None:
    check(StageDecoder, mutate(frames, garbage), cuts)


@settings(max_examples=300, deadline=None)
@given(
    st.lists(gcode_replies, max_size=8), st.lists(noise, max_size=3), st.lists(st.integers(0, 4000))
)
def test_gcode_replies_do_not_depend_on_the_split(
    replies: list[bytes], garbage: list[bytes], cuts: list[int]
) -> None:
    check(gcode_decoder, mutate(replies, garbage), cuts)


@settings(max_examples=200, deadline=None)
@given(
    st.lists(drill_replies, max_size=8), st.lists(noise, max_size=3), st.lists(st.integers(0, 4000))
)
def test_drill_replies_do_not_depend_on_the_split(
    replies: list[bytes], garbage: list[bytes], cuts: list[int]
) -> None:
    check(DrillReplyDecoder, mutate(replies, garbage), cuts)


@settings(max_examples=200, deadline=None)
@given(
    st.lists(usb3_replies, max_size=8), st.lists(noise, max_size=3), st.lists(st.integers(0, 4000))
)
def test_usb3_replies_do_not_depend_on_the_split(
    replies: list[bytes], garbage: list[bytes], cuts: list[int]
) -> None:
    check(Usb3ReplyDecoder, mutate(replies, garbage), cuts)


def test_a_valid_frame_glued_to_long_garbage_is_rejected_wherever_the_cut_falls() -> None:
    """Garbage longer than any frame, then a frame, one line: rejected whole, so also split."""
    frame = encode_echo(EchoFrame((EchoPacket(1, 0, 5), EchoPacket(1, 0, 7)), 0, 0))
    data = b"#" * 400 + frame
    whole = outcome(StageDecoder, [data])
    assert whole == ([], 1)
    for cut in (200, 206, 300, 400):
        assert outcome(StageDecoder, [data[:cut], data[cut:]]) == whole, cut


def test_a_long_gcode_reply_is_refused_whole_as_it_is_in_pieces() -> None:
    line = b"[MSG:" + b"x" * 300 + b"]\r\n"
    whole = outcome(gcode_decoder, [line])
    assert whole == ([], 1)
    assert outcome(gcode_decoder, [line[:100], line[100:]]) == whole
    assert outcome(gcode_decoder, [line[:280], line[280:] + b"ok\r\n"]) == ([Ok()], 1)
