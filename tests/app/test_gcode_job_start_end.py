"""A G-code job's start and end, decided where the board's words are read (issue #33).

The set-up (``G90 G21 G17``, then ``$G``) still goes before every job, and no
line of the job goes before the ``[GC:…]`` answering that ``$G`` shows the
machine set up; what changed is that a confirming answer lets the job go on
the reader thread, a window turn sooner.  What the operator relies on, proven
here with the window not told (``read_unseen``): a wrong answer, a refused
set-up, a board that restarted, a pause, a single step or another ``$G``'s
answer lets nothing of the job go; and whatever happened between two jobs (a
console ``G91`` or ``G20``, a jog, a restart), the next one is set up and
confirmed again before any of its lines.

At the end, the answer that leaves nothing of the job unanswered asks for the
board's status where it is read, so the job's end (the machine seen idle)
costs no window turn before the question goes.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QCoreApplication

from app.jobs.run.runner import JobRunner, JobState
from app.station import Station
from tests.app.test_gcode_job_pulled import (
    IDLE,
    MODES,
    BoardPort,
    board,
    job,
    read,
    read_unseen,
    session_of,
    tell,
)

__all__ = ["board"]  # the fixture, used by name

BANNER = b"\r\nGrbl 1.1h ['$' for help]\r\n"
#: ``[GC:…]`` answers that show the set-up did not take (each misses one of its words).
NOT_SET_UP = {
    "relative": b"[GC:G0 G54 G17 G21 G91 G94 M5 M9 T0 F0 S0]\r\n",
    "inches": b"[GC:G0 G54 G17 G20 G90 G94 M5 M9 T0 F0 S0]\r\n",
    "XZ plane": b"[GC:G0 G54 G18 G21 G90 G94 M5 M9 T0 F0 S0]\r\n",
}
SET_UP = [b"G90 G21 G17", b"$G"]


def begun(station: Station, port: BoardPort, tmp_path: Path, ops: int = 40) -> JobRunner:
    """A job started: its set-up written, nothing of it answered yet."""
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(ops)) == []
    runner.start()
    assert [line.strip() for line in port.lines()] == SET_UP
    return runner


def answer_all(station: Station, port: BoardPort) -> None:
    """The board answers every line written, one ``ok`` at a time, the window told of each."""
    while len(port.lines()) > port.answered:
        port.answered += 1
        read(station, b"ok\r\n")


def test_a_confirming_answer_lets_the_job_go_where_it_is_read(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    seen = read_unseen(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    assert port.job_ops()[:3] == [0, 1, 2]  # before the window has heard of the answer
    tell(station, seen)
    assert runner.state is JobState.RUNNING
    answer_all(station, port)
    read(station, IDLE)
    assert runner.state is JobState.DONE
    assert port.job_ops() == list(range(40))  # every line once, in order


@pytest.mark.parametrize("modes", NOT_SET_UP.values(), ids=NOT_SET_UP.keys())
def test_an_answer_showing_the_set_up_did_not_take_lets_nothing_go(
    board: tuple[Station, BoardPort], tmp_path: Path, modes: bytes
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    messages: list[str] = []
    runner.message.connect(messages.append)
    seen = read_unseen(station, b"ok\r\n" + modes + b"ok\r\n")
    assert port.job_ops() == []
    tell(station, seen)
    assert runner.state is JobState.FAILED
    assert any("still not in" in text for text in messages), messages
    read(station, b"ok\r\n" + MODES + b"ok\r\n" + IDLE)  # a later right answer changes nothing
    assert port.job_ops() == []


def test_a_refused_set_up_lets_nothing_go_though_the_modes_then_look_right(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    seen = read_unseen(station, b"error:20\r\n" + MODES + b"ok\r\n")
    assert port.job_ops() == []
    tell(station, seen)
    assert runner.state is JobState.FAILED
    assert port.job_ops() == []


def test_a_board_that_restarted_before_its_answer_lets_nothing_go(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    seen = read_unseen(station, b"ok\r\n" + BANNER + MODES + b"ok\r\n")
    assert port.job_ops() == []
    tell(station, seen)
    assert runner.state is not JobState.DONE
    assert port.job_ops() == []  # the window looks at the machine before anything goes


def test_a_pause_before_the_answer_lets_nothing_go(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    runner.pause()
    seen = read_unseen(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    assert port.job_ops() == []
    tell(station, seen)
    read(station, IDLE)
    assert runner.state is JobState.PAUSED
    assert port.job_ops() == []
    runner.resume()
    answer_all(station, port)
    read(station, IDLE)
    assert port.job_ops() == list(range(40))
    assert runner.state is JobState.DONE


def test_a_single_step_lets_one_operation_go_after_the_answer(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(40)) == []
    runner.step()
    assert [line.strip() for line in port.lines()] == SET_UP
    seen = read_unseen(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    assert port.job_ops() == []  # the reader thread never steps
    tell(station, seen)
    answer_all(station, port)
    read(station, IDLE)
    assert port.job_ops() == [0]
    assert runner.state is JobState.PAUSED


def test_another_g_answer_lets_a_paused_job_go_nowhere(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path)
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    runner.pause()
    answer_all(station, port)
    read(station, IDLE)
    assert runner.state is JobState.PAUSED
    sent = port.job_ops()
    assert session_of(station).send_line("$G", "console")  # the operator asks for the modes
    read_unseen(station, MODES + b"ok\r\n")
    assert port.job_ops() == sent
    QCoreApplication.processEvents()
    assert port.job_ops() == sent
    assert runner.state is JobState.PAUSED


BETWEEN_JOBS = {
    "console G91": ["G91"],
    "console G20": ["G20"],
    "console G91 G20 G18": ["G91 G20 G18"],
    "a jog": ["$J=G91 X1 F600"],
}


@pytest.mark.parametrize("lines", BETWEEN_JOBS.values(), ids=BETWEEN_JOBS.keys())
def test_whatever_went_between_two_jobs_the_next_is_set_up_and_confirmed_again(
    board: tuple[Station, BoardPort], tmp_path: Path, lines: list[str]
) -> None:
    station, port = board
    first = begun(station, port, tmp_path, ops=5)
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    answer_all(station, port)
    read(station, IDLE)
    assert first.state is JobState.DONE
    session = session_of(station)
    for line in lines:
        assert session.send_line(line, "console", confirmed=True)
    answer_all(station, port)
    read(station, IDLE)
    before = len(port.lines())
    first.start()  # the same job again
    assert [line.strip() for line in port.lines()[before:]] == SET_UP
    # The board still in what the console left (the set-up lost on the way, say).
    seen = read_unseen(station, b"ok\r\n" + NOT_SET_UP["relative"] + b"ok\r\n")
    assert [line.strip() for line in port.lines()[before:]] == SET_UP
    tell(station, seen)
    assert first.state is JobState.FAILED
    assert [line.strip() for line in port.lines()[before:]] == SET_UP


def test_a_restart_between_two_jobs_the_next_is_set_up_and_confirmed_again(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = board
    runner = begun(station, port, tmp_path, ops=5)
    read(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = 2
    answer_all(station, port)
    read(station, IDLE)
    assert runner.state is JobState.DONE
    read(station, BANNER + IDLE)  # the board restarted (its reset button)
    before = len(port.lines())
    runner.start()
    assert [line.strip() for line in port.lines()[before:]] == SET_UP
    seen = read_unseen(station, b"ok\r\n" + MODES + b"ok\r\n")
    port.answered = before + 2
    assert len(port.job_ops()) > 5  # confirmed: the job goes where the answer was read
    tell(station, seen)
    answer_all(station, port)
    read(station, IDLE)
    assert runner.state is JobState.DONE


def test_the_reader_thread_lets_the_job_go_only_on_the_answer_to_its_own_g(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """An operator's ``$G`` still unanswered as the job starts: its ``[GC:…]`` shows the
    modes before the set-up, and decides nothing where it is read."""
    station, port = board
    assert session_of(station).send_line("$G", "console")
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(40)) == []
    runner.start()
    assert [line.strip() for line in port.lines()] == [b"$G", *SET_UP]
    read_unseen(station, MODES + b"ok\r\n")  # the operator's $G answered
    assert port.job_ops() == []
    read_unseen(station, b"ok\r\n" + NOT_SET_UP["inches"] + b"ok\r\n")  # the set-up's
    assert port.job_ops() == []


def test_the_window_judges_the_set_up_by_the_answer_to_its_own_g(
    board: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """The window's check, as the reader thread's: an operator's ``$G`` answered first, with
    the modes from before the set-up, neither fails a job whose set-up took, nor lets go
    one whose set-up did not."""
    station, port = board
    assert session_of(station).send_line("$G", "console")
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(job(5)) == []
    runner.start()
    assert [line.strip() for line in port.lines()] == [b"$G", *SET_UP]
    read(station, NOT_SET_UP["relative"] + b"ok\r\n")  # the operator's, before the set-up
    assert runner.state is JobState.RUNNING
    read(station, b"ok\r\n" + MODES + b"ok\r\n")  # the set-up's own: it took
    port.answered = 3
    answer_all(station, port)
    read(station, IDLE)
    assert runner.state is JobState.DONE
    assert port.job_ops() == list(range(5))

    assert session_of(station).send_line("$G", "console")
    before = len(port.lines())
    runner.start()
    read(station, MODES + b"ok\r\n")  # the operator's looks right...
    read(station, b"ok\r\n" + NOT_SET_UP["inches"] + b"ok\r\n")  # ...the set-up's did not take
    assert runner.state is JobState.FAILED
    assert [line.strip() for line in port.lines()[before - 1 :]] == [b"$G", *SET_UP]
