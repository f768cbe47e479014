"""The pen watch on its own: lines written and answered, reports read, in every order.

A GRBL plotter's pen is its spindle; :class:`PenWatch` judges a report's ``A:`` only
where the lines answered leave one state, and never on a board without ``Ov:``.
"""

from __future__ import annotations

import itertools
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.machines.gcode.lines import SentLine
from app.machines.gcode.pen_watch import PenWatch, pen_is_spindle
from app.profiles import GcodeSettings, load_profile
from protocol.gcode.codec import StatusReport, decode

BANNER = "Grbl 1.1h ['$' for help]"


def _settings(profile: str = "grbl-plotter") -> GcodeSettings:
    gcode = load_profile(profile).gcode
    assert gcode is not None
    return gcode


def _report(fields: str = "", state: str = "Run") -> StatusReport:
    _, reply = decode(f"<{state}|MPos:1.000,2.000,0.000|FS:3000,0{fields}>\n".encode())
    assert isinstance(reply, StatusReport)
    return reply


OV = "|Ov:100,100,100"
DOWN = OV + "|A:S"


class Wire:
    """Lines through a watch, in order, with their serials."""

    def __init__(self, watch: PenWatch) -> None:
        self.watch = watch
        self._serials = itertools.count(1)

    def write(self, text: str, op: int | None = None) -> SentLine:
        sent = SentLine(next(self._serials), text, "job", op)
        self.watch.written(text.encode("ascii") + b"\n", sent)
        return sent

    def run(self, text: str, op: int | None = None) -> SentLine:
        sent = self.write(text, op)
        self.watch.answered(sent, True)
        return sent


@pytest.fixture
def wire(qapp: object) -> Wire:
    watch = PenWatch(_settings())
    watch.restarted(BANNER)
    assert watch.judge(_report("|WCO:0.000,0.000,0.000", "Idle")) is None
    assert watch.judge(_report(OV, "Idle")) is None
    return Wire(watch)


def test_only_a_pen_that_is_the_spindle_is_watched() -> None:
    assert pen_is_spindle(_settings("grbl-plotter"))
    assert not pen_is_spindle(_settings("corexy-plotter"))  # M3 up, M4 down: its own firmware
    assert not pen_is_spindle(replace(_settings(), pen_down="G0 Z0", pen_up="G0 Z5"))


def test_a_pen_line_lost_on_the_way_is_named(wire: Wire) -> None:
    wire.run("M3 S1000", op=36)  # answered, but the board never had it
    wire.run("G1 X10 Y0 F3000", op=37)
    mismatch = wire.watch.judge(_report(OV))
    assert mismatch is not None
    assert (mismatch.expected, mismatch.seen, mismatch.op_index) == ("S", "", 36)
    assert "'M3 S1000'" in mismatch.text() and "the spindle (the pen servo) off" in mismatch.text()
    assert wire.watch.judge(_report(OV)) is None  # one stop, one message


def test_the_reports_that_agree_pass(wire: Wire) -> None:
    wire.run("M3 S1000")
    assert wire.watch.judge(_report(DOWN)) is None
    wire.run("G1 X10 F3000")
    assert wire.watch.judge(_report()) is None  # no Ov: nothing said
    wire.run("M5")
    assert wire.watch.judge(_report(OV)) is None
    wire.run("M4 S300")
    assert wire.watch.judge(_report(OV + "|A:C")) is None
    mismatch = wire.watch.judge(_report(DOWN))  # the wrong way round
    assert mismatch is not None and mismatch.seen == "S" and mismatch.expected == "C"


def test_a_board_without_ov_is_never_judged(qapp: object) -> None:
    watch = PenWatch(_settings())
    watch.restarted("Grbl 1.1f ['$' for help]")  # FluidNC says so too
    wire = Wire(watch)
    for line in ("M3 S1000", "G1 X1 F100", "M5", "G0 X0", "M3 S1000", "M5"):
        wire.run(line)
        for _ in range(3):
            assert watch.judge(_report()) is None


def test_a_report_before_the_pen_line_is_answered_is_not_judged(wire: Wire) -> None:
    sent = wire.write("M3 S1000")
    wire.write("G1 X10 F3000")
    assert wire.watch.judge(_report(OV)) is None  # it may not have run yet
    assert wire.watch.judge(_report(DOWN)) is None  # or it has
    wire.watch.answered(sent, True)
    assert wire.watch.judge(_report(DOWN)) is None
    mismatch = wire.watch.judge(_report(OV))
    assert mismatch is not None and mismatch.seen == ""


def test_pen_up_and_down_racing_a_report(wire: Wire) -> None:
    wire.run("M3 S1000")
    assert wire.watch.judge(_report(DOWN)) is None
    up = wire.write("M5")
    down = wire.write("M3 S1000")
    for fields in (OV, DOWN):  # either may have run
        assert wire.watch.judge(_report(fields)) is None
    wire.watch.answered(up, True)
    assert wire.watch.judge(_report(OV)) is None  # the down on its way may not have run
    wire.watch.answered(down, True)
    assert wire.watch.judge(_report(DOWN)) is None


def test_a_refused_pen_line_runs_not(wire: Wire) -> None:
    wire.run("M3 S1000")
    refused = wire.write("M5 X")
    wire.watch.answered(refused, False)
    assert wire.watch.judge(_report(DOWN)) is None
    assert wire.watch.judge(_report(OV)) is not None


def test_nothing_is_known_before_a_reset_or_a_pen_line(qapp: object) -> None:
    watch = PenWatch(_settings())  # connected to a board found running: no banner
    wire = Wire(watch)
    wire.run("G1 X1 F100")
    assert watch.judge(_report(DOWN)) is None
    assert watch.judge(_report(OV)) is None
    wire.run("M5")
    assert watch.judge(_report(DOWN)) is not None


def test_a_link_that_lost_lines_knows_nothing_until_the_next_pen_line(wire: Wire) -> None:
    wire.run("M3 S1000")
    wire.watch.lines_lost()
    assert wire.watch.judge(_report(OV)) is None
    wire.run("M5")
    assert wire.watch.judge(_report(OV)) is None


def test_an_alarm_stops_the_spindle(wire: Wire) -> None:
    wire.run("M3 S1000")
    wire.watch.alarmed()
    assert wire.watch.judge(_report(OV, "Alarm")) is None
    assert wire.watch.judge(_report(OV, "Idle")) is None


def test_a_pen_change_grbl_never_reported_stops_at_the_second_report(wire: Wire) -> None:
    wire.run("M3 S1000", op=4)  # GRBL sends Ov: in the first report after a change
    assert wire.watch.judge(_report("|WCO:0.000,0.000,0.000")) is None  # or the second
    mismatch = wire.watch.judge(_report())
    assert mismatch is not None and mismatch.unreported and mismatch.op_index == 4
    assert (mismatch.expected, mismatch.seen) == ("S", "")
    assert "did not report the change" in mismatch.text()


def test_the_change_reported_in_time_passes(wire: Wire) -> None:
    wire.run("M3 S1000")
    wire.write("M5")  # on its way: the rule still holds for the down
    assert wire.watch.judge(_report(DOWN)) is None
    assert wire.watch.judge(_report()) is None


def test_no_refresh_rule_on_a_board_that_did_not_say_it_is_grbl_1_1(qapp: object) -> None:
    watch = PenWatch(_settings())
    watch.restarted("Grbl 0.9j ['$' for help]")
    wire = Wire(watch)
    wire.run("M3 S1000")
    assert watch.judge(_report()) is None
    assert watch.judge(_report()) is None


_STEPS = st.lists(
    st.tuples(st.sampled_from(["M3 S1000", "M5", "G1 X1", "G0 X2"]), st.booleans()),
    max_size=25,
)


@settings(max_examples=60, deadline=None)  # the shared machine: no timing here
@given(_STEPS, st.data())
def test_a_board_that_runs_every_line_sent_is_never_stopped(
    qapp: object, steps: list[tuple[str, bool]], data: st.DataObject
) -> None:
    """An honest GRBL: answers in order, reports A: as its spindle is, Ov: at once after a
    change, whenever a report comes (between any two events)."""
    watch = PenWatch(_settings())
    watch.restarted(BANNER)
    wire = Wire(watch)
    spindle, refresh = "", False
    waiting: list[tuple[SentLine, str]] = []
    for text, answer_now in steps:
        waiting.append((wire.write(text), text))
        while waiting and (answer_now or len(waiting) > 3):
            sent, line = waiting.pop(0)
            new = {"M3 S1000": "S", "M5": ""}.get(line, spindle)
            refresh = refresh or new != spindle
            spindle = new
            watch.answered(sent, True)
            answer_now = data.draw(st.booleans())
        if data.draw(st.booleans()):
            carry = refresh or data.draw(st.booleans())
            refresh = False
            fields = (OV + (f"|A:{spindle}" if spindle else "")) if carry else ""
            assert watch.judge(_report(fields)) is None


def test_a_pen_line_on_its_way_the_machine_has_not_reached_cannot_have_run(wire: Wire) -> None:
    wire.run("M3 S1000")
    wire.run("G1 X60 F3000")
    wire.run("M4 S1000")  # changed on the wire: the board turns the other way
    wire.write("G0 X10 Y20")
    up_next = wire.write("M3 S1000")
    # Placed on the path short of the moves before the pen line on its way: judged.
    mismatch = wire.watch.judge(_report(DOWN), reached=lambda mark: False)
    assert mismatch is not None and (mismatch.expected, mismatch.seen) == ("C", "S")
    assert up_next.text == "M3 S1000"


def test_a_pen_line_on_its_way_the_machine_may_have_reached_is_not_judged(wire: Wire) -> None:
    wire.run("M5")
    wire.write("G0 X10 Y20")
    wire.write("M3 S1000")
    assert wire.watch.judge(_report(DOWN), reached=lambda mark: True) is None
    assert wire.watch.judge(_report(DOWN)) is None  # not placed: it may have run


def test_lines_sent_as_the_banner_is_read_go_after_the_reset(wire: Wire) -> None:
    """The reader thread sends what waited for the reset's banner as it reads it: their note
    of writing may come before the banner's (relay seed 18: the resume's pen down)."""
    wire.run("M3 S1000")
    wire.watch.reset()  # the station's soft reset: the lines unanswered are gone
    down = wire.write("M3 S1000")
    wire.watch.restarted(BANNER)
    wire.watch.answered(down, True)
    assert wire.watch.judge(_report(DOWN)) is None
    mismatch = wire.watch.judge(_report(OV))
    assert mismatch is not None and mismatch.line == down


def test_a_mismatch_right_after_a_reset_names_it(wire: Wire) -> None:
    mismatch = wire.watch.judge(_report(DOWN))
    assert mismatch is not None and mismatch.line is None
    assert "after the board's reset ran" in mismatch.text()
