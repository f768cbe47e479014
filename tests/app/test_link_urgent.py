"""A tap's urgent result reaches the window at once, with the batch that waited before it.

The window hears of a tapped link's reads at most 30 times a second; a G-code
job's end (a status report read with nothing unanswered) should not wait up to
a thirtieth of a second more for that (issue #33's delivery time).
"""

from __future__ import annotations

import threading

from PySide6.QtCore import QCoreApplication
from pytestqt.qtbot import QtBot

from app.link import Link
from app.machines.gcode.feeder import LineFeeder, settles
from protocol.clock import ManualClock
from protocol.gcode.codec import encode_line, make_decoder
from protocol.gcode.streaming import LineStreamer, StreamMode
from tests.helpers.fake_transport import SilentPort

IDLE = b"<Idle|MPos:0.000,0.000,0.000|Bf:15,127|FS:0,0>\r\n"


def read_on_a_thread(link: Link, *chunks: bytes) -> None:
    def reader() -> None:
        for chunk in chunks:
            link.data_received(chunk)

    thread = threading.Thread(target=reader)
    thread.start()
    thread.join()


def test_an_urgent_result_goes_at_once_with_what_waited_before_it(qtbot: QtBot) -> None:
    link = Link(SilentPort())
    link.set_tap(
        lambda data: data.decode(),
        lambda results: ["+".join(map(str, results))],
        lambda result: result == "done",
    )
    events: list[str] = []
    link.received.connect(events.append)
    read_on_a_thread(link, b"ok 1")
    QCoreApplication.processEvents()
    assert events == ["ok 1"]
    read_on_a_thread(link, b"ok 2")  # within the thirtieth of a second: held back
    QCoreApplication.processEvents()
    assert events == ["ok 1"]
    read_on_a_thread(link, b"done")
    QCoreApplication.processEvents()  # no timer waited for
    assert events == ["ok 1", "ok 2+done"]
    read_on_a_thread(link, b"ok 3")  # and batching goes on after it
    QCoreApplication.processEvents()
    assert events == ["ok 1", "ok 2+done"]
    qtbot.waitUntil(lambda: len(events) == 3, timeout=1000)
    assert events[-1] == "ok 3"


def test_only_a_report_read_with_nothing_unanswered_is_urgent() -> None:
    streamer: LineStreamer[str] = LineStreamer(StreamMode.COUNTING, 128)
    written: list[bytes] = []
    feeder = LineFeeder(streamer, make_decoder(), ManualClock(), written.append)
    assert settles(feeder.receive(IDLE))  # nothing sent: a report that may end a wait
    streamer.queue(encode_line("G1 X1"), "a line")
    feeder.pump()
    assert not settles(feeder.receive(IDLE))  # its line unanswered: it proves nothing
    assert not settles(feeder.receive(b"ok\r\n"))  # an answer alone
    assert settles(feeder.receive(IDLE))
    assert not settles("not a read of this feeder")
