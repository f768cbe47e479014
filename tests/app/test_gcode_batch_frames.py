"""A batch of a running job's answers costs the window one pass, not one per line, and a
frame log still sees every frame.

The window hears of a streaming job's reads in batches (the link's inbox):
what a batch of the job's counted ``ok``\\ s does to the session (heard now,
the link up, an answer heard) is done once for the run of them, and what
nobody listens to (the frame log closed) is not emitted per line at all.
What must not change: with a frame log open, every reply and every line is
a frame, in order; the job counts every line once; work zero still learns a
line's coordinate system from the batch it was written in.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QObject, Signal
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobState
from app.listened import listened
from app.machines.gcode.feeder import Received, merged
from app.machines.gcode.session import GcodeSession, SentLine
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from tests.app.test_gcode_job_pulled import (
    IDLE,
    JOB_OPS,
    BoardPort,
    read,
    read_unseen,
    session_of,
    started,
    tell,
    unanswered,
)


class _Speaker(QObject):
    said = Signal(object)


def test_listened_tells_whether_a_signal_has_a_receiver_now(qapp: object) -> None:
    speaker = _Speaker()
    assert not listened(speaker, "said")

    def heard(_value: object) -> None:
        pass

    speaker.said.connect(heard)
    assert listened(speaker, "said")
    speaker.said.disconnect(heard)
    assert not listened(speaker, "said")
    assert listened(object(), "said")  # no QObject: cannot tell, so emitted to as before


@pytest.fixture
def board(qtbot: QtBot) -> Iterator[tuple[Station, BoardPort]]:
    station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    port = BoardPort()
    station.connect_transport(port)
    port.listener.connection_made()
    read(station, IDLE)
    try:
        yield station, port
    finally:
        station.shutdown()


def _batch(station: Station, port: BoardPort) -> Received[SentLine]:
    """Everything the board has unanswered, answered on the reader thread one ``ok`` a read
    (each lets the next lines go), and merged as the window's inbox merges it."""
    reads: list[object] = []
    while unanswered(port, port.answered):
        port.answered += 1
        reads.append(read_unseen(station, b"ok\r\n"))
    (batch,) = merged(reads)
    assert isinstance(batch, Received)
    return batch


def test_a_frame_log_sees_every_reply_and_line_of_a_batch_in_order(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    session: GcodeSession = session_of(station)
    frames: list[tuple[str, object]] = []
    session.frameReceived.connect(lambda reply, raw: frames.append(("in", raw)))
    session.frameSent.connect(lambda text, raw: frames.append(("out", raw)))
    runner = started(station, port, tmp_path)
    frames.clear()
    written_before = len(port.lines())
    batch = _batch(station, port)
    answers = sum(1 for reply, _verdict in batch.replies if type(reply).__name__ == "Ok")
    assert answers > 1  # a run of counted answers, one behind the other
    tell(station, batch)
    assert [raw for way, raw in frames if way == "in"] == [b"ok"] * answers
    sent = [raw for way, raw in frames if way == "out" and raw.endswith(b"\n")]  # no "?"
    assert sent == port.lines()[written_before:]  # each line written, once, in order
    assert runner.done == answers


def test_without_a_frame_log_a_batch_counts_the_same(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    session = session_of(station)
    assert not listened(session, "frameSent")  # no frame log: the lines are not emitted
    runner = started(station, port, tmp_path)
    while runner.done < JOB_OPS:
        session.last_heard = -1.0
        tell(station, _batch(station, port))
        assert session.last_heard == station.clock.now()  # heard in this batch
    assert port.job_ops() == list(range(JOB_OPS))  # every line once, in order
    read(station, IDLE)
    assert runner.state is JobState.DONE


def test_work_zero_learns_the_system_from_the_batch_a_line_was_written_in(
    board: tuple[Station, BoardPort],
) -> None:
    station, _port = board
    session = session_of(station)
    session.work.available = True
    session.work.system = "G54"
    session.send_line("G55", "console")
    assert session.work.system == "G55"
