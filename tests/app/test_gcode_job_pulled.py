"""A running G-code job is pulled and counted where the board's answers are read.

What the operator relies on: the wire stays full while the window is busy
(the reader thread sends the job's next lines itself as ``ok``\\ s free room,
with no help from the window's thread), and that costs nothing in safety —
a pause, a stop, an error or a board that reset itself stops the pulling at
once, on whichever thread learns of it first, and nothing of the job is ever
written twice or skipped.

The board here is a script: a thread (or the test itself) answers the lines
the port was given, exactly as the serial reader thread hands a real board's
bytes to the station.
"""

from __future__ import annotations

import re
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.gcode_stream import GcodeStream
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode.feeder import Received
from app.machines.gcode.job_feed import JobFeed
from app.machines.gcode.session import GcodeSession, SentLine
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from tests.helpers.fake_transport import UnannouncedPort

#: More lines than the window's thread ever queued ahead of the board (200).
JOB_OPS = 600
IDLE = b"<Idle|MPos:0.000,0.000,0.000|Bf:15,127|FS:0,0>\r\n"
MODES = b"[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]\r\n"
_X = re.compile(rb"^G1 ?X([0-9.]+)")
#: Millimetres between the moves of consecutive operations (the travel is 300 mm).
PITCH = 0.25


class BoardPort(UnannouncedPort):
    """A port whose board is the test: what was written, as lines and as job operations."""

    def __init__(self) -> None:
        super().__init__("/dev/ttyUSB0 @ 115200")
        #: Lines the test (the board) has answered so far.
        self.answered = 0

    def start_over(self) -> None:
        """Forget what was written and answered so far (a fresh link's count)."""
        with self.sent_lock:
            self.sent.clear()
        self.answered = 0

    def lines(self) -> list[bytes]:
        """Every line written so far (real-time bytes left out)."""
        with self.sent_lock:
            joined = b"".join(self.sent)
        joined = re.sub(rb"[?!~\x18\x80-\xff]", b"", joined)  # GRBL's real-time bytes
        return [line for line in re.split(rb"(?<=\n)", joined) if line.endswith(b"\n")]

    def job_ops(self) -> list[int]:
        """The operations of the job lines written, in order (each move tells its own)."""
        found = (_X.match(line) for line in self.lines())
        return [round(float(hit.group(1)) / PITCH) for hit in found if hit is not None]


def job(ops: int = JOB_OPS) -> Program:
    """A move per operation, each to its own X (so the wire tells which it is)."""
    moves = (move(SourceRef("pulled", n + 1), X=n * PITCH, Y=1.0) for n in range(ops))
    return Program("pulled", tuple(moves))


@pytest.fixture
def board(qtbot: QtBot) -> Iterator[tuple[Station, BoardPort]]:
    station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    port = BoardPort()
    station.connect_transport(port)
    port.listener.connection_made()
    read(station, IDLE)
    assert station.model.link_state is LinkState.CONNECTED
    try:
        yield station, port
    finally:
        station.shutdown()


def session_of(station: Station) -> GcodeSession:
    session = station.gcode_session
    assert session is not None
    return session


def read(station: Station, data: bytes) -> None:
    """The board's bytes read and handed to the window at once (a quiet window)."""
    link = station.link
    assert link is not None
    link.received.emit(session_of(station).feeder.receive(data))


def read_unseen(station: Station, data: bytes) -> Received[SentLine]:
    """The board's bytes read on the reader thread, the window not yet told (:func:`tell`)."""
    return session_of(station).feeder.receive(data)


def tell(station: Station, *received: Received[SentLine]) -> None:
    """What the reader thread read, handled by the window now."""
    link = station.link
    assert link is not None
    for each in received:
        link.received.emit(each)


def started(station: Station, port: BoardPort, tmp_path: Path, ops: int = JOB_OPS) -> JobRunner:
    """A job started and its set-up confirmed: from here on its lines are pulled."""
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(ops)) == []
    runner.start()
    assert [line.strip() for line in port.lines()] == [b"G90 G21 G17", b"$G"]
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    assert runner.state is JobState.RUNNING
    return runner


def unanswered(port: BoardPort, answered: int) -> int:
    return len(port.lines()) - answered


def answer(station: Station, port: BoardPort, most: int) -> int:
    """The board answers its lines one ``ok`` at a time (each lets more go), ``most`` at most;
    the window hears of each at once.  Returns how many it answered."""
    done = 0
    while done < most and unanswered(port, port.answered):
        port.answered += 1
        done += 1
        read(station, b"ok\r\n")
    return done


def test_the_wire_stays_full_while_the_window_does_not_run_at_all(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = started(station, port, tmp_path)
    link = station.link
    assert link is not None
    answered = [2]  # the set-up's two lines

    def the_board() -> None:
        """Answers every line written, from its own thread, as a serial reader hands them."""
        deadline = time.monotonic() + 20
        while answered[0] < JOB_OPS + 2 and time.monotonic() < deadline:
            for _ in range(unanswered(port, answered[0])):
                answered[0] += 1
                link.data_received(b"ok\r\n")

    reader = threading.Thread(target=the_board)
    reader.start()
    reader.join()  # the window's thread is held here the whole time: it handles nothing
    assert port.job_ops() == list(range(JOB_OPS))  # every line, once, in order
    assert runner.done < JOB_OPS  # the window has not heard of it yet
    QApplication.processEvents()  # now it hears of every answer at once
    assert runner.done == JOB_OPS
    read(station, IDLE)
    assert runner.state is JobState.DONE


def test_a_pause_stops_the_pulling_even_while_answers_keep_coming(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = started(station, port, tmp_path)
    assert answer(station, port, 50) == 50
    runner.pause()
    assert runner.state is JobState.PAUSING
    written = port.job_ops()
    # The lines the board has, answered on the reader thread: not one more line is pulled.
    late = [read_unseen(station, b"ok\r\n") for _ in range(unanswered(port, port.answered))]
    assert late
    assert port.job_ops() == written
    tell(station, *late)
    assert runner.state is JobState.PAUSED
    assert runner.done == len(written)
    runner.resume()
    assert port.job_ops()[len(written)] == len(written)  # on from the first not sent


def test_a_stop_leaves_nothing_more_to_pull(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = started(station, port, tmp_path)
    assert answer(station, port, 20) == 20
    runner.abort()
    written = port.job_ops()
    read(station, b"ok\r\n" * unanswered(port, port.answered))
    assert port.job_ops() == written
    assert runner.state is JobState.ABORTED


@pytest.mark.parametrize(
    ("board_says", "then"),
    [
        (b"\r\nGrbl 1.1h ['$' for help]\r\nok\r\nok\r\n", JobState.PAUSED),
        (b"error:20\r\nok\r\nok\r\n", JobState.FAILED),
    ],
    ids=["the board reset itself", "an error"],
)
def test_what_stops_the_job_stops_the_pulling_before_the_window_knows(
    board: tuple[Station, BoardPort], tmp_path: Path, board_says: bytes, then: JobState
) -> None:
    station, port = board
    runner = started(station, port, tmp_path)
    assert answer(station, port, 20) == 20
    written = port.job_ops()
    late = read_unseen(station, board_says)
    assert port.job_ops() == written  # held on the reader side, the window not yet told
    tell(station, late)
    read(station, IDLE)
    assert runner.state is then
    read(station, b"ok\r\n" * 5)
    assert port.job_ops() == written


def test_a_line_that_cannot_go_fails_the_job_there_with_its_reason(
    board: tuple[Station, BoardPort], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    station, port = board
    assert session_of(station) is not None
    messages: list[str] = []
    made = JobFeed._encode

    def refusing(feed: JobFeed, text: str, index: int) -> tuple[bytes, SentLine] | str:
        return "a line the board cannot take" if index == 30 else made(feed, text, index)

    monkeypatch.setattr(JobFeed, "_encode", refusing)
    runner = JobRunner(station, tmp_path / "checkpoints")
    runner.message.connect(messages.append)
    assert runner.load(job()) == []
    runner.start()
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    answer(station, port, JOB_OPS)
    assert port.job_ops() == list(range(30))
    assert runner.state is JobState.FAILED
    assert any("a line the board cannot take" in text for text in messages)


def test_a_report_read_before_answers_proves_nothing_about_them() -> None:
    """The window handles a report after answers read later: those may still be planned."""
    stream = GcodeStream(job(10), load_profile("grbl-plotter"), 0)
    lines = [
        SentLine(serial, text, "job", index)
        for serial, (index, text) in enumerate(stream.next_lines(10), 1)
    ]
    for sent in lines[:5]:
        assert stream.count_answer(sent)
    seen = stream.reported()  # five lines still unanswered as the report is read
    for sent in lines[5:]:
        assert stream.count_answer(sent)
    stream.status("Idle", None, 0, None, seen)
    assert stream.answered == 10
    assert stream.executed == 0  # the idle report was made with lines still to come
    stream.status("Idle", None, 0, None, stream.reported())
    assert stream.executed == 10


def test_only_the_jobs_own_answers_are_counted_by_the_job() -> None:
    stream = GcodeStream(job(3), load_profile("grbl-plotter"), 0)
    stream.next_lines(3)
    assert not stream.count_answer(SentLine(7, "G90", "console", None))
    assert not stream.count_answer(SentLine(2, "G1 X0.5 Y1", "job", 2))  # not the oldest
    assert stream.count_answer(SentLine(0, "G1 X0 Y1", "job", 0))
    assert stream.answered == 1


def test_a_wait_stops_the_pull_until_the_operator_confirms() -> None:
    ops: list[Operation] = [move(SourceRef("w", n), X=float(n)) for n in range(3)]
    ops.append(Operation(OpKind.WAIT, SourceRef("w", 4), message="change the pen"))
    ops.append(move(SourceRef("w", 5), X=9.0))
    stream = GcodeStream(Program("w", tuple(ops)), load_profile("grbl-plotter"), 0)
    assert [index for index, _text in stream.next_lines(10)] == [0, 1, 2]
    assert stream.next_lines(10) == []
    assert stream.waiting_at == 3


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.one_of(
            st.tuples(st.just("answer"), st.integers(1, 40)),
            st.tuples(st.sampled_from(["deliver", "pause", "resume", "report"]), st.just(0)),
        ),
        max_size=30,
    )
)
def test_any_mix_of_answers_pauses_and_resumes_writes_every_line_once_in_order(
    qapp: QApplication, steps: list[tuple[str, int]]
) -> None:
    """Whatever the window does when, and however late it hears of the answers, the board
    gets the job's lines exactly once, in order, and none from a pause until the resume."""
    with _board_for_hypothesis() as (station, port, runner):
        link = station.link
        assert link is not None
        feeder = session_of(station).feeder
        inbox: list[object] = []  # read on the reader thread, not yet handled by the window
        answered = 2
        paused_at: int | None = None

        def deliver() -> None:
            while inbox:
                link.received.emit(inbox.pop(0))

        for action, count in steps:
            if action == "answer":
                count = min(count, unanswered(port, answered))
                answered += count
                inbox.append(feeder.receive(b"ok\r\n" * count))
            elif action == "deliver":
                deliver()
            elif action == "report":
                inbox.append(feeder.receive(IDLE if unanswered(port, answered) == 0 else b""))
            elif action == "pause":
                runner.pause()
                if runner.state in (JobState.PAUSING, JobState.PAUSED):
                    paused_at = len(port.job_ops())
            elif runner.state in (JobState.PAUSING, JobState.PAUSED):
                runner.resume()
                paused_at = None
            ops = port.job_ops()
            assert ops == list(range(len(ops)))  # nothing repeated, nothing skipped
            if paused_at is not None:
                assert len(ops) == paused_at  # nothing of the job goes during a pause
        # Then the job is run out: every line once, in order, and the job done.
        for _ in range(JOB_OPS):
            deliver()
            if runner.state is JobState.DONE:
                break
            if runner.state is JobState.PAUSED:
                runner.resume()
            waiting = unanswered(port, answered)
            answered += waiting
            inbox.append(feeder.receive(b"ok\r\n" * waiting if waiting else IDLE))
        assert port.job_ops() == list(range(JOB_OPS))
        assert runner.state is JobState.DONE


class _board_for_hypothesis:
    """The ``board`` fixture and a started job, per example (hypothesis runs many)."""

    def __enter__(self) -> tuple[Station, BoardPort, JobRunner]:
        import tempfile

        self._folder = tempfile.TemporaryDirectory()
        self.station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
        port = BoardPort()
        self.station.connect_transport(port)
        port.listener.connection_made()
        read(self.station, IDLE)
        runner = started(self.station, port, Path(self._folder.name))
        self.runner = runner
        return self.station, port, runner

    def __exit__(self, *exc: object) -> None:
        self.runner.deleteLater()
        self.station.shutdown()
        self._folder.cleanup()


def test_reads_taken_together_keep_every_line_told_as_sent_before_its_answer(
    board: tuple[Station, BoardPort], qtbot: QtBot
) -> None:
    """The window takes a streaming board's reads some thirty times a second, many at once:
    as one, in the order they happened (each line sent before its answer)."""
    station, _port = board
    session = session_of(station)
    link = station.link
    assert link is not None
    told: list[str] = []
    session.frameSent.connect(lambda text, raw: told.append(f"sent {text}"))
    session.frameReceived.connect(lambda reply, raw: told.append(f"read {raw.strip().decode()}"))
    heard: list[object] = []
    link.received.connect(heard.append)
    long = "G1 X1." + "0" * 30 + " Y1." + "0" * 30  # two of them overfill the buffer
    for _ in range(3):
        assert session.send_line(long, "intent")
    assert told == [f"sent {long}"]

    def the_board() -> None:
        for _ in range(3):
            link.data_received(b"ok\r\n")

    reader = threading.Thread(target=the_board)
    reader.start()
    reader.join()
    qtbot.waitUntil(lambda: len(told) == 6, timeout=2000)
    assert len(heard) == 1  # three reads, heard of as one
    assert told == [f"sent {long}", "read ok"] * 3


#: A console line of 42 bytes: two of them fill the board's buffer as far as the station
#: fills it (84 of 127 bytes, and room kept for a copy of one: LineStreamer's spare line).
BUSY = "G0 X1." + "0" * 16 + " Y1." + "0" * 15
#: Where the machine stands when the cable is back: off the job's path.
STANDING = b"<Idle|MPos:3.000,1.000,0.000|Bf:15,127|FS:0,0>\r\n"


def resumed_after_a_pulled_cable(
    station: Station, port: BoardPort, runner: JobRunner, *, busy: bool = False
) -> list[bytes]:
    """Twenty lines run, the cable pulled and put back, Resume: the lines sent (returned).

    ``busy``: two console lines fill the board's buffer first, so the way back waits.
    """
    assert answer(station, port, 20) == 20
    for _ in range(2):  # the planner empty: the twenty lines have run
        read(station, b"<Run|MPos:4.750,1.000,0.000|Bf:15,127|FS:0,0>\r\n")
    port.close()
    assert runner.state is JobState.PAUSED
    link = station.link
    assert link is not None
    link.open()
    port.listener.connection_made()
    # The board's first report says where it stands (the station judges every later report
    # against the path from there).
    read(station, STANDING)
    port.start_over()
    if busy:
        for _ in range(2):
            assert session_of(station).send_line(BUSY, "console", confirmed=True)
    runner.resume()
    read(station, STANDING)
    return [line.strip() for line in port.lines()]


def test_the_resumed_job_waits_for_its_way_back_to_be_answered(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """A line of the job behind the way back would run even if the way back were refused."""
    station, port = board
    runner = started(station, port, tmp_path)
    way_back = resumed_after_a_pulled_cable(station, port, runner)
    assert b"G0 X4.750 Y1.000" in way_back
    assert port.job_ops() == []
    for _ in way_back[:-1]:
        read(station, b"ok\r\n")
        assert port.job_ops() == []
    read(station, b"ok\r\n")
    assert port.job_ops()[0] == 20  # then on from where it stopped
    assert runner.state is JobState.RUNNING


def test_a_pause_that_takes_back_the_way_back_looks_at_the_machine_again_on_resume(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """Half a way back would leave the machine somewhere the job does not expect: a pause that
    takes back any of it makes the resume look where the machine stands and go back anew."""
    station, port = board
    runner = started(station, port, tmp_path)
    assert resumed_after_a_pulled_cable(station, port, runner, busy=True) == [BUSY.encode()] * 2
    runner.pause()  # the way back still queued behind the console's lines: taken back
    assert runner.state is JobState.PAUSED
    read(station, b"ok\r\nok\r\n" + STANDING)
    assert len(port.lines()) == 2  # nothing of the way back, nothing of the job
    port.answered = 2
    runner.resume()  # asks where the machine stands (a status query) before anything else
    assert len(port.lines()) == 2
    read(station, STANDING)
    way_back = [line.strip() for line in port.lines()[2:]]
    assert b"G0 X4.750 Y1.000" in way_back
    assert port.job_ops() == []
    read(station, b"ok\r\n" * len(way_back))
    assert port.job_ops()[0] == 20  # then on from where it stopped
    assert runner.state is JobState.RUNNING


def test_a_refused_way_back_fails_the_resumed_job_before_any_of_its_lines(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """Resuming, the machine is taken back to the program's place first; a board that refuses
    the way back (say error:15, beyond its travel) would draw the rest somewhere else."""
    station, port = board
    runner = started(station, port, tmp_path)
    messages: list[str] = []
    runner.message.connect(messages.append)
    way_back = resumed_after_a_pulled_cable(station, port, runner)
    refused = way_back.index(b"G0 X4.750 Y1.000")
    for k in range(len(way_back)):
        read(station, b"error:15\r\n" if k == refused else b"ok\r\n")
    assert runner.state is JobState.FAILED
    assert any("refused the way back" in text for text in messages)
    read(station, b"ok\r\n" * 5)
    assert port.job_ops() == []  # not one line of the job went


def test_a_single_step_after_a_wait_sends_one_operation_only(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    ops: list[Operation] = [move(SourceRef("w", n + 1), X=n * PITCH, Y=1.0) for n in range(4)]
    ops.append(Operation(OpKind.WAIT, SourceRef("w", 5), message="change the pen"))
    ops += [move(SourceRef("w", n + 1), X=n * PITCH, Y=1.0) for n in range(5, 40)]
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(Program("w", tuple(ops))) == []
    runner.start()
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    answer(station, port, 10)
    read(station, IDLE)
    assert runner.state is JobState.WAITING
    assert port.job_ops() == [0, 1, 2, 3]
    runner.pause()
    runner.step()  # the operator steps on through the wait, one operation at a time
    runner.confirm()  # the wait was the step
    read(station, b"ok\r\n")  # a stray answer pumps the feeder: nothing is pulled
    assert port.job_ops() == [0, 1, 2, 3]
    runner.step()
    answer(station, port, 10)
    read(station, IDLE)
    read(station, b"ok\r\n")
    assert port.job_ops() == [0, 1, 2, 3, 5]
    assert runner.state is JobState.PAUSED


def test_a_pause_that_takes_back_the_set_up_sends_it_again_before_the_job(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    session = session_of(station)
    for _ in range(2):
        assert session.send_line(BUSY, "console", confirmed=True)
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(40)) == []
    runner.start()
    assert [line.strip() for line in port.lines()] == [BUSY.encode()] * 2  # set-up queued
    runner.pause()  # before the set-up could go: taken back with the job
    assert runner.state is JobState.PAUSED
    read(station, b"ok\r\nok\r\n" + IDLE)
    assert len(port.lines()) == 2  # nothing went during the pause
    port.answered = 2
    runner.resume()
    assert [line.strip() for line in port.lines()[2:]] == [b"G90 G21 G17", b"$G"]
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 4
    answer(station, port, 60)
    read(station, IDLE)
    assert port.job_ops() == list(range(40))
    assert runner.state is JobState.DONE
