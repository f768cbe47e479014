"""Ping-pong and character counting (docs/protocols.md §4), as pure bookkeeping."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.gcode import LineStreamer, StreamMode, encode_line


def line(length: int) -> bytes:
    """An encoded line of exactly ``length`` bytes, its LF included."""
    return b"G" * (length - 1) + b"\n"


def test_counting_sends_while_the_unacknowledged_bytes_stay_within_127() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    for i in range(5):
        streamer.queue(line(40), i)
    # 40 + 40 + 40 = 120; a fourth would make 160 > 127.
    assert [tag for _, tag in streamer.sendable()] == [0, 1, 2]
    assert (streamer.in_flight, streamer.in_flight_bytes, streamer.queued) == (3, 120, 2)
    assert streamer.sendable() == []
    assert streamer.acknowledge() == (line(40), 0)
    assert [tag for _, tag in streamer.sendable()] == [3]
    assert streamer.in_flight_bytes == 120


def test_counting_fills_to_exactly_127_never_128() -> None:
    streamer: LineStreamer[str] = LineStreamer(StreamMode.COUNTING)
    streamer.queue(line(100), "a")
    streamer.queue(line(27), "b")
    streamer.queue(line(1), "c")
    assert [tag for _, tag in streamer.sendable()] == ["a", "b"]
    assert streamer.in_flight_bytes == 127
    assert streamer.sendable() == []


def test_a_smaller_buffer_is_respected() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, rx_buffer=64)
    streamer.queue(line(63), 0)
    streamer.queue(line(1), 1)
    assert [tag for _, tag in streamer.sendable()] == [0]
    with pytest.raises(ValueError, match="never fits"):
        streamer.queue(line(64), 2)


def test_ping_pong_sends_one_line_at_a_time() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.PING_PONG)
    for i in range(3):
        streamer.queue(encode_line(f"G1 X{i}"), i)
    assert streamer.sendable() == [(b"G1 X0\n", 0)]
    assert streamer.sendable() == []
    assert streamer.acknowledge() == (b"G1 X0\n", 0)
    assert streamer.sendable() == [(b"G1 X1\n", 1)]
    assert streamer.acknowledge() == (b"G1 X1\n", 1)
    assert streamer.sendable() == [(b"G1 X2\n", 2)]
    assert streamer.acknowledge() == (b"G1 X2\n", 2)
    assert streamer.idle


def test_acknowledgements_are_fifo_and_a_stray_one_is_none() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    assert streamer.acknowledge() is None
    for i in range(3):
        streamer.queue(line(10), i)
    streamer.sendable()
    assert [streamer.acknowledge() for _ in range(4)] == [
        (line(10), 0),
        (line(10), 1),
        (line(10), 2),
        None,
    ]
    assert streamer.in_flight_bytes == 0 and streamer.idle


def test_clear_after_a_reset_returns_every_tag_oldest_first() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    for i in range(6):
        streamer.queue(line(50), i)
    streamer.sendable()  # 0 and 1 in flight (100 bytes)
    assert streamer.clear() == [0, 1, 2, 3, 4, 5]
    assert (streamer.in_flight, streamer.in_flight_bytes, streamer.queued) == (0, 0, 0)
    assert streamer.idle and streamer.acknowledge() is None


def test_discard_queued_keeps_the_lines_in_flight() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    for i in range(4):
        streamer.queue(line(50), i)
    streamer.sendable()
    assert streamer.discard_queued() == [2, 3]
    assert (streamer.in_flight, streamer.queued, streamer.idle) == (2, 0, False)
    assert streamer.acknowledge() == (line(50), 0)


def test_lines_that_could_never_go_are_refused_at_queue() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    with pytest.raises(ValueError, match="never fits"):
        streamer.queue(line(128), 0)
    with pytest.raises(ValueError, match="ends with"):
        streamer.queue(b"G1 X1", 0)
    streamer.queue(line(127), 1)
    assert streamer.sendable() == [(line(127), 1)]


@given(
    lengths=st.lists(st.integers(min_value=1, max_value=127), min_size=1, max_size=60),
    acks=st.lists(st.integers(min_value=0, max_value=4), max_size=80),
)
def test_counting_never_exceeds_127_and_delivers_everything_in_order(
    lengths: list[int], acks: list[int]
) -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    for i, n in enumerate(lengths):
        streamer.queue(line(n), i)
    sent: list[int] = []
    acked: list[int] = []
    outstanding: list[int] = []  # what the board has received and not yet answered
    script = iter(acks)
    while len(acked) < len(lengths):
        for data, tag in streamer.sendable():
            sent.append(tag)
            outstanding.append(len(data))
        assert sum(outstanding) == streamer.in_flight_bytes <= 127
        # Acknowledge as many as the script says (at least one, so the stream progresses).
        for _ in range(max(next(script, 1), 1)):
            entry = streamer.acknowledge()
            if entry is None:
                break
            acked.append(entry[1])
            assert len(entry[0]) == outstanding.pop(0)
    assert sent == acked == list(range(len(lengths)))
    assert streamer.idle


@given(st.lists(st.integers(min_value=1, max_value=127), min_size=1, max_size=30))
def test_ping_pong_never_has_two_lines_in_flight(lengths: list[int]) -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.PING_PONG)
    for i, n in enumerate(lengths):
        streamer.queue(line(n), i)
    order: list[int] = []
    while not streamer.idle:
        out = streamer.sendable()
        assert len(out) == 1 and streamer.in_flight == 1
        entry = streamer.acknowledge()
        assert entry is not None
        order.append(entry[1])
    assert order == list(range(len(lengths)))


def test_a_spare_line_keeps_room_for_a_copy_of_the_longest_in_flight() -> None:
    """A line or an ok arriving twice (no checksum on the wire) overflows nothing."""
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, spare_line=True)
    for i in range(5):
        streamer.queue(line(30), i)
    # 30 + 30 + 30 = 90, and 30 spare: 120; a fourth would leave no room for a copy.
    assert [tag for _, tag in streamer.sendable()] == [0, 1, 2]
    streamer.acknowledge()
    assert [tag for _, tag in streamer.sendable()] == [3]
    assert streamer.in_flight_bytes == 90


def test_a_spare_line_still_lets_a_long_line_go_alone() -> None:
    streamer: LineStreamer[str] = LineStreamer(StreamMode.COUNTING, spare_line=True)
    streamer.queue(line(100), "long")
    streamer.queue(line(10), "short")
    assert [tag for _, tag in streamer.sendable()] == ["long"]  # no room for a copy: alone
    streamer.acknowledge()
    assert [tag for _, tag in streamer.sendable()] == ["short"]


@given(
    lengths=st.lists(st.integers(min_value=1, max_value=127), min_size=1, max_size=60),
    acks=st.lists(st.integers(min_value=0, max_value=4), max_size=80),
)
def test_with_a_spare_line_one_copy_of_any_line_in_flight_still_fits(
    lengths: list[int], acks: list[int]
) -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, spare_line=True)
    for i, n in enumerate(lengths):
        streamer.queue(line(n), i)
    acked: list[int] = []
    outstanding: list[int] = []
    script = iter(acks)
    while len(acked) < len(lengths):
        for data, _ in streamer.sendable():
            outstanding.append(len(data))
        if len(outstanding) > 1:
            assert sum(outstanding) + max(outstanding) <= 127
        for _ in range(max(next(script, 1), 1)):
            entry = streamer.acknowledge()
            if entry is None:
                break
            acked.append(entry[1])
            outstanding.pop(0)
    assert acked == list(range(len(lengths)))
