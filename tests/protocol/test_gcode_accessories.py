"""GRBL's ``A:`` field read, and the spindle state lines leave, as GRBL 1.1h's gcode.c has it."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from protocol.clock import ManualClock
from protocol.emulator.gcode_firmware import GcodeFirmware, grbl_plotter_config
from protocol.gcode.accessories import (
    AT_RESET,
    CCW,
    CW,
    OFF,
    UNKNOWN,
    Spindle,
    SpindleWords,
    reported_spindle,
    spindle_words,
)
from protocol.gcode.codec import StatusReport, decode


def _fields(report: str) -> dict[str, str]:
    _, reply = decode(report.encode("ascii") + b"\n")
    assert isinstance(reply, StatusReport), reply
    return dict(reply.fields)


def test_a_report_says_the_spindle_only_beside_ov() -> None:
    assert reported_spindle(_fields("<Idle|MPos:0.000,0.000,0.000|FS:0,0>")) is None
    # A: never comes without Ov: in GRBL; alone it is not read as anything.
    assert reported_spindle(_fields("<Idle|MPos:0.000,0.000,0.000|FS:0,0|A:S>")) is None
    base = "<Run|MPos:1.000,2.000,0.000|FS:3000,1000|Ov:100,100,100"
    assert reported_spindle(_fields(base + ">")) == ""
    assert reported_spindle(_fields(base + "|A:S>")) == "S"
    assert reported_spindle(_fields(base + "|A:C>")) == "C"
    assert reported_spindle(_fields(base + "|A:SF>")) == "S"
    assert reported_spindle(_fields(base + "|A:F>")) == ""  # flood only: the spindle is off
    for bad in ("|A:Q>", "|A:SC>", "|A:SS>", "|A:s>"):
        assert reported_spindle(_fields(base + bad)) is None, bad


def test_lines_as_grbl_reads_them() -> None:
    assert spindle_words("M3 S1000") == SpindleWords(CW, 1000.0)
    assert spindle_words("m03s1000 (pen down)") == SpindleWords(CW, 1000.0)
    assert spindle_words("M5") == SpindleWords(OFF)
    assert spindle_words("M4 S500 G1 X1") == SpindleWords(CCW, 500.0)
    assert spindle_words("G1 X10 Y10 F3000") == SpindleWords()
    assert spindle_words("(M3 S1000)") == SpindleWords()  # a comment
    assert spindle_words("M30") == SpindleWords(program_end=True)
    assert spindle_words("$C").unknown
    assert spindle_words("$J=G91 X1 F100") == SpindleWords()
    assert spindle_words("$SLP") == SpindleWords(OFF)
    assert not spindle_words("G4 P0.5").touches


def test_what_a_report_shows_after_lines() -> None:
    on = AT_RESET.after(spindle_words("M3 S1000"))
    assert on.seen == "S"
    assert on.after(spindle_words("S0")).seen == ""  # S0: the PWM off
    assert on.after(spindle_words("M4")).seen == "C"
    assert on.after(spindle_words("M5")).seen == ""
    assert on.after(spindle_words("M2")).seen == ""
    assert AT_RESET.after(spindle_words("M3")).seen == ""  # S is 0 after a reset
    assert UNKNOWN.after(spindle_words("M3")).seen is None  # S not known
    assert UNKNOWN.after(spindle_words("M5")).seen == ""
    assert UNKNOWN.after(spindle_words("M3 S1000")).seen == "S"


def test_which_lines_make_grbl_report_at_once() -> None:
    off, on = AT_RESET, AT_RESET.after(spindle_words("M3 S1000"))
    assert off.refreshes(spindle_words("M3 S1000")) is True
    assert on.refreshes(spindle_words("M3 S1000")) is False  # nothing changes: no sync
    assert on.refreshes(spindle_words("S500")) is True  # the speed while on
    assert off.refreshes(spindle_words("S500")) is False  # kept for the next M3
    assert off.refreshes(spindle_words("M5")) is False
    assert off.refreshes(spindle_words("M2")) is True
    assert UNKNOWN.refreshes(spindle_words("M3 S1000")) is None


_LINES = st.sampled_from(
    ["M3 S1000", "M3", "M4 S200", "M5", "S0", "S700", "M2", "G1 X1", "M3 S0", "$C"]
)


@settings(deadline=None)  # the shared machine: no timing here
@given(st.lists(_LINES, max_size=12), st.lists(_LINES, min_size=1, max_size=6))
def test_every_change_a_report_can_show_is_one_grbl_reports_at_once(
    first: list[str], then: list[str]
) -> None:
    """The watch's rule: a pen line that changes A: is one after which Ov: comes at once."""
    state: Spindle = AT_RESET
    for line in first:
        state = state.after(spindle_words(line))
    for line in then:
        words = spindle_words(line)
        before, state = state, state.after(words)
        assert state.seen in (None, "", "S", "C")
        if before.seen is not None and state.seen is not None and state.seen != before.seen:
            assert before.refreshes(words) is True
        if before.refreshes(words) is False:
            assert state.seen == before.seen


def test_grbl_answers_a_pen_line_once_the_moves_before_it_ran_and_the_pen_moved() -> None:
    """spindle_sync: the ok of M3 comes after the move before it; a line with a pen change and
    a move is answered once the pen moved, its own move queued (not waited for)."""
    clock = ManualClock(start=0.0)
    fw = GcodeFirmware(clock, grbl_plotter_config())
    out = bytearray()
    fw.set_output(out.extend)
    clock.advance(0.005)
    fw.run_until(clock.now())  # booted
    out.clear()
    fw.receive(b"G1 X20 F600\nM3 S1000\nG0 X40 M5\n?")
    answers: list[tuple[float, int]] = []
    reports: list[str] = []
    while clock.now() < 10.0:
        clock.advance(0.005)
        fw.run_until(clock.now())
        for line in out.decode("ascii").split():
            if line == "ok":
                answers.append((clock.now(), fw.position()["X"]))
            elif line.startswith("<"):
                reports.append(line)
        out.clear()
    assert len(answers) == 3
    assert answers[0][1] < 1.0  # the move is queued: answered at once
    assert answers[1][1] == 20.0  # M3: once the move before it ran
    assert answers[2][1] < 21.0  # M5 with a move: once the pen is up, the move just begun
    assert "|A:" not in reports[0]  # asked while the first move ran: the pen still up
