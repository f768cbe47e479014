"""A running job's feed: one lock for everything the reader thread writes.

The job's lines are encoded and queued on the transport's reader thread while
the window's thread sends its own lines (console, panels, jogs).  What must
hold however the two interleave: lines are numbered in the order they are
queued (a serial taken outside the hold could be queued after a later one),
and the distance mode the console judges in is the last queued line's (a
note written outside the hold could be overwritten by a stale one).  The
stress below runs both threads flat out with a tiny switch interval; with
either write moved outside the lock it fails within a few hundred lines.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Iterator
from itertools import pairwise

import pytest
from pytestqt.qtbot import QtBot

from app.machines.gcode.line_targets import line_motion
from app.machines.gcode.session import GcodeSession, SentLine
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from tests.helpers.fake_transport import UnannouncedPort

#: Lines the window's thread sends while the reader thread streams the job.
WINDOW_LINES = 1500


def _relative_after(text: str) -> bool:
    return line_motion(text, False, {}, ()).relative_after


class _EndlessJob:
    """A job of lines that switch the distance mode back and forth, never ending."""

    def __init__(self) -> None:
        self.taken = 0
        self.counted = 0

    def next_lines(self, count: int) -> list[tuple[int, str]]:
        out = []
        for _ in range(count):
            index, self.taken = self.taken, self.taken + 1
            out.append((index, "G91 G1 X0.001 F100" if index % 2 else "G90 G1 X1 F100"))
        return out

    def refuse(self, index: int, why: str) -> None:
        raise AssertionError(f"line {index} refused: {why}")

    def count_answer(self, sent: SentLine) -> bool:
        if sent.origin != "job":
            return False
        self.counted += 1
        return True

    def reported(self) -> object:
        return None


@pytest.fixture
def session(qtbot: QtBot) -> Iterator[GcodeSession]:
    station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    port = UnannouncedPort()
    station.connect_transport(port)
    port.listener.connection_made()
    built = station.gcode_session
    assert built is not None
    try:
        yield built
    finally:
        station.shutdown()


def test_lines_from_both_threads_are_numbered_and_judged_in_queue_order(
    session: GcodeSession, monkeypatch: pytest.MonkeyPatch
) -> None:
    queued: list[SentLine] = []
    bad_mode: list[str] = []
    original = session.streamer.queue

    def recording(raw: bytes, tag: SentLine) -> None:
        original(raw, tag)
        queued.append(tag)  # under the lock: the order is the queue's

    monkeypatch.setattr(session.streamer, "queue", recording)
    job = _EndlessJob()
    feed = session.start_job(job)
    feed.pull()
    done = threading.Event()
    failures: list[BaseException] = []

    def reader() -> None:
        try:
            while not done.is_set():
                session.feeder.receive(b"ok\r\n")  # each answer lets the job's next lines go
        except BaseException as exc:  # pragma: no cover - reported below
            failures.append(exc)

    switch = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    thread = threading.Thread(target=reader, daemon=True)
    thread.start()
    try:
        for k in range(WINDOW_LINES):
            text = "G91 G0 X0" if k % 3 else "G90 G0 X0"
            assert session.send_line(text, "intent")
            with session.feeder.lock:
                last = queued[-1].text
                if session.console.relative != _relative_after(last):
                    bad_mode.append(f"after {last!r}: relative={session.console.relative}")
            with session.feeder.lock:
                session.streamer.discard_queued()  # keep the queue short: answers keep coming
                feed.pull()
    finally:
        done.set()
        thread.join(timeout=10)
        sys.setswitchinterval(switch)
    assert not failures
    assert job.counted > 0 and any(tag.origin == "job" for tag in queued)  # both threads queued
    serials = [tag.serial for tag in queued]
    out_of_order = [(a, b) for a, b in pairwise(serials) if b <= a]
    assert out_of_order == []
    assert bad_mode == []


def test_a_single_step_sends_the_one_line_the_pull_would_have_sent(
    session: GcodeSession,
) -> None:
    job = _EndlessJob()
    feed = session.start_job(job)
    feed.step()
    with feed.locked() as source:
        assert source is job and job.taken == 1
    assert session.streamer.in_flight == 1 and session.streamer.queued == 0
    assert not session.feeder.pulling  # a step lets nothing more go on the reader thread
    session.feeder.receive(b"ok\r\n")
    assert job.counted == 1 and job.taken == 1


def test_a_released_feed_is_no_longer_followed(session: GcodeSession) -> None:
    first = session.start_job(_EndlessJob())
    second = session.start_job(_EndlessJob())
    first.release()  # another job's feed followed since: left alone
    assert session.feeder.job is second
    second.release()
    assert session.feeder.job is None
