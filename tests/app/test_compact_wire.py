"""A GRBL job's lines go on the wire compact (as grbl's stream.py sends them), told as written.

What the operator relies on: the board reads the same line in fewer bytes,
the character counting counts the bytes really sent (the board's 128-byte
buffer never overflows, and never sits emptier than it could), the 80-byte
line limit is the compact line's, and everything the operator sees — the
frame log, the operation's line, the checkpoint — keeps the line as written.
The CoreXY plotter, whose firmware reads spaces (``M98 500``), is sent lines
as written.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode.job_feed import wire_text
from app.machines.gcode.session import GcodeSession, SentLine
from app.profiles import load_profile
from app.station import Station
from protocol.clock import ManualClock
from tests.app.test_gcode_job_pulled import IDLE, MODES, BoardPort

#: The set-up the runner sends before a job's first line (as written, not a job line).
SET_UP = [b"G90 G21 G17\n", b"$G\n"]


def test_wire_text_is_grbl_s_own_reading_of_the_line() -> None:
    assert wire_text("G1 X12.34 Y56.78") == "G1X12.34Y56.78"
    assert wire_text("g1 x1 (to the corner) y2") == "G1X1Y2"
    assert wire_text("M3 S1000 ; pen down") == "M3S1000"
    assert wire_text("$J=G91 X1 F100") == "$J=G91X1F100"
    assert wire_text("/") == "/"  # nothing left: as written, the board answers it the same


def station_on(profile: str, qtbot: QtBot) -> tuple[Station, BoardPort]:
    station = Station(load_profile(profile), ManualClock(), realtime=False)
    port = BoardPort()
    station.connect_transport(port)
    port.listener.connection_made()
    read(station, IDLE)
    assert station.model.link_state is LinkState.CONNECTED
    return station, port


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[tuple[Station, BoardPort]]:
    station, port = station_on("grbl-plotter", qtbot)
    try:
        yield station, port
    finally:
        station.shutdown()


def session_of(station: Station) -> GcodeSession:
    session = station.gcode_session
    assert session is not None
    return session


def read(station: Station, data: bytes) -> None:
    link = station.link
    assert link is not None
    link.received.emit(session_of(station).feeder.receive(data))


def start(station: Station, port: BoardPort, tmp_path: Path, text: str) -> JobRunner:
    """``text`` as a job file, loaded for the station's machine, started past its set-up."""
    path = tmp_path / "job.gcode"
    path.write_text(text, encoding="ascii")
    profile = station.model.profile
    options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
    runner = JobRunner(station, tmp_path / "checkpoints")
    assert runner.load(load_job(path, ["X", "Y"], options)) == []
    runner.start()
    set_up = port.lines()
    assert set_up == (SET_UP if profile.gcode and profile.gcode.compact_lines else [b"G90\n"])
    read(station, b"".join(MODES + b"ok\r\n" if ln == b"$G\n" else b"ok\r\n" for ln in set_up))
    port.answered = len(set_up)
    assert runner.state is JobState.RUNNING
    return runner


def test_a_grbl_job_goes_compact_and_is_told_as_written(
    grbl: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = grbl
    session = session_of(station)
    told: list[SentLine] = []
    logged: list[str] = []
    batches: list[list[SentLine]] = []
    session.lineSent.connect(told.append)
    session.linesSent.connect(batches.append)
    session.frameSent.connect(lambda text, _raw: logged.append(text))
    start(station, port, tmp_path, "G1 X1.5 Y2 F600 (corner)\nx 3   y 4\nM5 ; pen up\n")
    # The batches the window hears carry every line sent, once, in order.
    assert [sent for batch in batches for sent in batch] == told
    assert port.lines()[2:] == [b"G1X1.5Y2F600\n", b"X3Y4\n", b"M5\n"]
    job = [sent.text for sent in told if sent.origin == "job"]
    assert job == ["G1 X1.5 Y2 F600", "x 3   y 4", "M5"]
    assert logged[-3:] == job  # the frame log shows the line as written
    # The count is of the bytes sent: 13 + 5 + 3, not the 16 + 11 + 3 written.
    assert session.streamer.in_flight_bytes == 21


def test_the_buffer_is_filled_by_the_compact_bytes(
    grbl: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """The window holds 127 compact bytes, less room for a copy of the longest line in flight
    (a line or an ok may arrive twice): more lines than their written length would let go."""
    station, port = grbl
    session = session_of(station)
    written = "G1 X12.34 Y56.78 F600\n" + "G1 X12.34 Y56.78\n" * 40
    start(station, port, tmp_path, written)
    sent = port.lines()[2:]
    assert sent[1] == b"G1X12.34Y56.78\n"
    in_flight = sum(len(line) for line in sent)
    assert in_flight == session.streamer.in_flight_bytes
    assert in_flight <= 127
    # 15 bytes each compact: the first (19 bytes) and 5 more fit beside room for a copy of
    # the first (94 + 19); written, 17 each beside a 22-byte first, only 5.
    assert len(sent) == 6
    read(station, b"ok\r\n")
    assert len(port.lines()[2:]) == 8  # the 19-byte line and the room for its copy: two
    read(station, b"ok\r\n")
    assert len(port.lines()[2:]) == 9  # then one ok frees one compact line's room, not more


def test_the_line_limit_is_the_compact_line_s(
    grbl: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    """A line of 90 bytes as written, 19 compact, fits GRBL's 80-byte line: it goes."""
    station, port = grbl
    long = (" " * 24).join(["G1", "X1.000", "Y2.000", "F600"])
    assert len(long) == 90
    runner = start(station, port, tmp_path, long + "\n")
    assert port.lines()[2:] == [b"G1X1.000Y2.000F600\n"]
    assert runner.state is JobState.RUNNING


def test_the_corexy_plotter_gets_its_lines_as_written(qtbot: QtBot, tmp_path: Path) -> None:
    station, port = station_on("corexy-plotter", qtbot)
    try:
        start(station, port, tmp_path, "G1 X1 Y2\nM98 500\n")
        assert port.lines()[1:] == [b"G1 X1 Y2\n", b"M98 500\n"]
    finally:
        station.shutdown()
