"""The G-code feeder: the streaming loop on the transport's reader thread.

What the operator relies on: a board's first words count however the reader
thread and the window's thread interleave at connect; nothing more is written
after an ``error`` until the window has seen every one; and a fault in
reading the replies stops the machine instead of silencing the link.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.gcode.feeder import LineFeeder
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from protocol.gcode.codec import FEED_HOLD, make_decoder
from protocol.gcode.streaming import LineStreamer, StreamMode
from tests.helpers.fake_transport import UnannouncedPort
from tests.helpers.harness import StationHarness


@pytest.fixture
def station(qtbot: QtBot) -> Iterator[Station]:
    built = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    try:
        yield built
    finally:
        built.shutdown()


def test_a_first_report_read_across_the_connect_still_connects(station: Station) -> None:
    # The reader thread reads the board's first bytes as soon as the port opens; the
    # window hears of the connection later.  A report cut in two around that moment
    # is still one report (GRBL on a pty that had it buffered, or a slow window).
    port = UnannouncedPort()
    station.connect_transport(port)
    session = station.gcode_session
    assert session is not None and station.link is not None
    first = session.feeder.receive(b"<Idle|MPos:1.000,2.000,0.000|FS:0,0")
    port.listener.connection_made()  # the window runs its connect handling now
    second = session.feeder.receive(b">\r\n")
    station.link.received.emit(first)
    station.link.received.emit(second)
    assert station.model.link_state is LinkState.CONNECTED
    assert session.rejected == 0
    assert session.machine_state == "Idle"


def test_a_reply_cut_by_a_lost_link_is_not_glued_to_the_next_links_first(
    station: Station,
) -> None:
    port = UnannouncedPort()
    station.connect_transport(port)
    session = station.gcode_session
    assert session is not None and station.link is not None
    port.listener.connection_made()
    station.link.received.emit(session.feeder.receive(b"<Idle|MPos:0.000,0.000,0.000|FS:0,0>\r\n"))
    assert station.model.link_state is LinkState.CONNECTED
    station.link.received.emit(session.feeder.receive(b"<Idle|MPos:5.0"))  # then the cable goes
    port.close()
    station.link.open()
    port.listener.connection_made()
    station.link.received.emit(session.feeder.receive(b"<Idle|MPos:7.000,8.000,0.000|FS:0,0>\r\n"))
    assert station.model.link_state is LinkState.CONNECTED
    assert session.rejected == 0
    assert [axis.position for axis in station.model.axes][:2] == [7.0, 8.0]


def test_after_two_errors_nothing_is_written_until_the_window_has_seen_both() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, 128)
    written: list[bytes] = []
    feeder = LineFeeder(streamer, make_decoder(), ManualClock(), written.append)
    for tag, line in enumerate((b"G0 X1\n", b"G7 X1\n", b"G7 X2\n")):
        streamer.queue(line, tag)
    assert [raw for raw, _ in feeder.pump()] == [b"G0 X1\n", b"G7 X1\n", b"G7 X2\n"]
    streamer.queue(b"G0 X9\n", 3)
    received = feeder.receive(b"ok\r\nerror:20\r\nerror:20\r\n")
    assert received.written == []
    assert feeder.pump() == []
    assert feeder.release() == []  # the window has seen the first error, not the second
    assert written == [b"G0 X1\n", b"G7 X1\n", b"G7 X2\n"]
    assert feeder.release() == [(b"G0 X9\n", 3)]
    assert written[-1] == b"G0 X9\n"


def test_a_fault_reading_the_replies_stops_the_machine_and_sends_nothing_queued(
    qtbot: QtBot, monkeypatch: pytest.MonkeyPatch
) -> None:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(0.05)
    try:
        session = harness.gcode_session
        messages: list[str] = []
        harness.station.model.message.connect(messages.append)
        for x in range(1, 40):
            assert session.send_line(f"G1 X{x} F600")
        harness.run(0.02)
        assert session.streamer.queued > 0
        before = len(harness.written)

        def broken(data: bytes) -> list[object]:
            raise RuntimeError("decoder bug")

        monkeypatch.setattr(session.decoder, "feed", broken)
        session.receive_injected(b"ok\r\n")
        after = b"".join(harness.written[before:])
        assert FEED_HOLD in after
        assert b"G1" not in after
        assert session.streamer.queued == 0
        assert any("could not be read" in text and "decoder bug" in text for text in messages)
    finally:
        harness.close()


def test_the_lines_an_answer_lets_go_are_written_where_it_was_read_in_one_write() -> None:
    """On the reader thread the freed lines go in one write (one system call, no thread woken);
    lines the window's thread pumps still go through the queued write, one by one."""
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, 20)
    queued: list[bytes] = []
    here: list[list[bytes]] = []
    feeder = LineFeeder(streamer, make_decoder(), ManualClock(), queued.append, here.append)
    for tag, line in enumerate((b"G0 X10 Y10 Z1\n", b"G0 X2\n", b"G0 X3\n", b"G0 X4\n")):
        streamer.queue(line, tag)
    assert [raw for raw, _ in feeder.pump()] == [b"G0 X10 Y10 Z1\n"]  # 14 of 19 bytes
    assert queued == [b"G0 X10 Y10 Z1\n"] and here == []
    received = feeder.receive(b"ok\r\n")  # 14 bytes freed: the other three fit
    assert [raw for raw, _ in received.written] == [b"G0 X2\n", b"G0 X3\n", b"G0 X4\n"]
    assert here == [[b"G0 X2\n", b"G0 X3\n", b"G0 X4\n"]]
    assert queued == [b"G0 X10 Y10 Z1\n"]


class _Job:
    """Three job lines, the second one the board will refuse."""

    def __init__(self) -> None:
        self.lines = [b"G1 X1\n", b"G1 X2 G0\n", b"G0 X30 Y30\n"]

    def take(self, count: int) -> list[tuple[bytes, int]]:
        taken = [(line, index) for index, line in enumerate(self.lines[:count])]
        self.lines = self.lines[count:]
        return taken

    def count_answer(self, tag: int) -> bool:
        return True

    def reported(self) -> object:
        return None


def test_a_job_line_refused_mid_stream_holds_the_board_where_the_refusal_is_read() -> None:
    """Relay corexy-plotter seed 19: a duplicated line overflowed the board's buffer, the
    board refused the line it mangled and went straight on to the lines behind it; the hold
    came a GUI-thread turn later, after a pen-down travel the job never had."""
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, 128)
    written: list[bytes] = []
    feeder = LineFeeder(streamer, make_decoder(), ManualClock(), written.append)
    feeder.follow(_Job())
    feeder.pull()
    assert written == [b"G1 X1\n", b"G1 X2 G0\n", b"G0 X30 Y30\n"]
    feeder.receive(b"ok\r\nerror:21\r\n")
    assert written[-1] == FEED_HOLD  # at once, on the reader's side
    assert not feeder.pulling  # and nothing more of the job is pulled


def test_a_console_line_refused_outside_a_job_holds_nothing() -> None:
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING, 128)
    written: list[bytes] = []
    feeder = LineFeeder(streamer, make_decoder(), ManualClock(), written.append)
    streamer.queue(b"G7\n", 0)
    feeder.pump()
    feeder.receive(b"error:20\r\n")
    assert FEED_HOLD not in written


def test_a_job_line_refused_while_the_job_is_not_pulled_still_holds_the_board() -> None:
    """Relay corexy-plotter seed 7: the job's last lines all queued, nothing more to pull,
    and the refusal was held 0.7 s later, after two strokes the job never had."""
    streamer: LineStreamer[str] = LineStreamer(StreamMode.COUNTING, 128)
    written: list[list[bytes]] = []
    feeder = LineFeeder(
        streamer,
        make_decoder(),
        ManualClock(),
        lambda raw: written.append([raw]),
        written.append,
        holds_on_refusal=lambda tag: tag == "job",
    )
    streamer.queue(b"G1 X26.G1 X29 Y5\n", "job")
    streamer.queue(b"G1 X32 Y7\n", "job")
    feeder.pump()
    assert not feeder.pulling
    feeder.receive(b"error:21\r\n")
    assert written[-1] == [FEED_HOLD]  # in one write where it was read
