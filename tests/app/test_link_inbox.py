"""A tap's results, read on the transport's thread, reach the window's thread in order, batched."""

from __future__ import annotations

import threading

from PySide6.QtCore import QCoreApplication
from pytestqt.qtbot import QtBot

from app.link import Link
from tests.helpers.fake_transport import SilentPort


def test_tap_results_from_the_reader_arrive_in_order_batched_and_before_the_loss(
    qtbot: QtBot,
) -> None:
    link = Link(SilentPort())
    link.set_tap(lambda data: data.decode())
    events: list[str] = []
    link.received.connect(lambda result: events.append(result))
    link.disconnected.connect(lambda reason: events.append(f"lost: {reason}"))
    posted: list[None] = []
    link._inboxFilled.connect(lambda: posted.append(None))  # counts the wake-ups

    def reader() -> None:  # the window's thread is not running events meanwhile
        for chunk in (b"ok 1", b"ok 2", b"ok 3"):
            link.data_received(chunk)
        link.connection_lost("unplugged")

    thread = threading.Thread(target=reader)
    thread.start()
    thread.join()
    assert events == []
    QCoreApplication.processEvents()
    assert events == ["ok 1", "ok 2", "ok 3", "lost: unplugged"]
    assert len(posted) == 1  # one wake-up of the window's thread for the three reads


def test_the_window_hears_at_most_thirty_times_a_second_merged_and_the_loss_last(
    qtbot: QtBot,
) -> None:
    """A streaming board is read hundreds of times a second: the window takes the reads in
    batches (merged as the tap says), and a loss waits behind a batch held back."""
    link = Link(SilentPort())
    link.set_tap(lambda data: data.decode(), lambda results: ["+".join(map(str, results))])
    events: list[str] = []
    link.received.connect(lambda result: events.append(result))
    link.disconnected.connect(lambda reason: events.append(f"lost: {reason}"))

    def read(*chunks: bytes, lost: str | None = None) -> None:
        def reader() -> None:
            for chunk in chunks:
                link.data_received(chunk)
            if lost is not None:
                link.connection_lost(lost)

        thread = threading.Thread(target=reader)
        thread.start()
        thread.join()

    read(b"ok 1")
    QCoreApplication.processEvents()
    assert events == ["ok 1"]
    read(b"ok 2", b"ok 3")  # right after: held back until a thirtieth of a second has passed
    QCoreApplication.processEvents()
    assert events == ["ok 1"]
    qtbot.waitUntil(lambda: len(events) == 2, timeout=1000)
    assert events == ["ok 1", "ok 2+ok 3"]
    read(b"ok 4", lost="unplugged")  # held back again, and the loss behind it
    QCoreApplication.processEvents()
    assert events == ["ok 1", "ok 2+ok 3", "ok 4", "lost: unplugged"]
