"""Starting part-way: which operation a line or number names, and the state rebuilt there.

The property test writes random plotter files in the modal words the
grbl-plotter takes (units, distance mode, feed, motion, G92, the pen) and
compares the state :func:`plan_start` works out at a random line with a
plain interpreter of the lines before it, written here from GRBL's rules.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.gcode_stream import texts_matching
from app.jobs.run.start_point import (
    MODAL_HINT,
    StartRefused,
    operation_at_line,
    operation_numbered,
    plan_start,
)
from app.profiles import GcodeSettings, load_profile

PROFILE = load_profile("grbl-plotter")
SETTINGS = PROFILE.gcode
assert SETTINGS is not None
AXES = [a.name for a in PROFILE.axes]
INCH = 25.4


def load(tmp_path: Path, lines: list[str], gcode: GcodeSettings = SETTINGS) -> Program:
    source = tmp_path / "job.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return load_job(source, AXES, JobOptions(gcode=gcode))


# --- the property: the state at a line is the lines before it, read as GRBL reads them ------

coordinate = st.integers(min_value=-40, max_value=40).map(lambda v: v / 4)
feed = st.integers(min_value=1, max_value=90).map(lambda v: v * 50)


@st.composite
def modal_line(draw: st.DrawFn) -> str:
    kind = draw(
        st.sampled_from(
            ["G20", "G21", "G90", "G91", "F", "G0", "G1", "bare", "G1F", "up", "down", "G92"]
        )
    )
    if kind in ("G20", "G21", "G90", "G91"):
        return kind
    if kind == "F":
        return f"F{draw(feed)}"
    if kind == "G1F":
        return f"G1 F{draw(feed)}"
    if kind == "up":
        return "M5"
    if kind == "down":
        return "M3 S1000"
    x, y = draw(coordinate), draw(coordinate)
    prefix = {"G0": "G0 ", "G1": "G1 ", "bare": "", "G92": "G92 "}[kind]
    return f"{prefix}X{x:g} Y{y:g}"


def reference(lines: list[str]) -> dict[str, object]:
    """GRBL's modal state after ``lines`` (machine mm, starting at 0, 0 with no offset)."""
    inches = relative = pen = False
    motion: str | None = None
    feed_mm = math.nan
    position = [0.0, 0.0]
    offset = [0.0, 0.0]
    for line in lines:
        words = line.split()
        scale = INCH if inches else 1.0
        if "G20" in words or "G21" in words:
            inches = "G20" in words
            scale = INCH if inches else 1.0
        if "G90" in words or "G91" in words:
            relative = "G91" in words
        for word in words:
            if word in ("G0", "G1"):
                motion = word
            elif word.startswith("F"):
                feed_mm = float(word[1:]) * scale
        if words[0] == "M5":
            pen = False
        elif words[0] == "M3":
            pen = True
        axes = {w[0]: float(w[1:]) * scale for w in words if w[0] in "XY"}
        if "G92" in words:
            for i, a in enumerate("XY"):
                offset[i] = position[i] - axes[a]
        elif axes:
            for i, a in enumerate("XY"):
                position[i] = position[i] + axes[a] if relative else axes[a] + offset[i]
    return {
        "inches": inches,
        "relative": relative,
        "pen": pen,
        "motion": motion,
        "feed": None if math.isnan(feed_mm) else feed_mm / (INCH if inches else 1.0),
        "position": position,
        "offset": offset,
    }


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(body=st.lists(modal_line(), min_size=1, max_size=25), pick=st.integers(0, 1000))
def test_the_state_at_a_line_is_what_the_lines_before_it_made(
    tmp_path: Path, body: list[str], pick: int
) -> None:
    lines = ["G21 G90 F1000 G0 X0 Y0", *body]
    program = load(tmp_path, lines)
    line = 2 + pick % len(body)
    index = operation_at_line(program, line)
    plan = plan_start(program, index, AXES)
    state = plan.state
    expected = reference(lines[: program[index].source.line - 1])
    assert state.inches == expected["inches"]
    assert state.relative == expected["relative"]
    assert state.resume.pen_down == expected["pen"]
    assert state.motion == expected["motion"]
    assert state.feed == pytest.approx(expected["feed"], rel=1e-9)
    position = expected["position"]
    offset = expected["offset"]
    assert isinstance(position, list) and isinstance(offset, list)
    assert [state.resume.position[a] for a in "XY"] == pytest.approx(position, abs=1e-9)
    assert [state.offset[a] for a in "XY"] == pytest.approx(offset, abs=1e-9)


# --- the lines that rebuild it ----------------------------------------------------------


def test_the_way_there_is_in_mm_with_the_pen_up_and_the_files_state_comes_after(
    tmp_path: Path,
) -> None:
    program = load(
        tmp_path,
        ["G21 G90", "G0 X10 Y10", "G92 X0 Y0", "G20", "G1 X1 Y1 F10", "M3 S1000", "X2 Y2"],
    )
    index = operation_at_line(program, 7)
    lines = plan_start(program, index, AXES).lines(SETTINGS)
    # Pen up, set up in mm, there (machine 10 + 25.4), the G92 the file made, then its state.
    assert lines == [
        "M5",
        "G90 G21 G17",
        "G0 X35.400 Y35.400",
        "G92 X25.400 Y25.400",
        "G20",
        "G1 F10",
        "M3 S1000",
    ]


@pytest.mark.parametrize("g92", ["G92 X0 Y0", "G 92 X0 Y0", "g092 x0 y0", "G1 G92 X0 Y0"])
def test_the_files_g92_is_followed_however_it_is_spelled_and_a_coordinate_ending_in_92_is_none(
    tmp_path: Path, g92: str
) -> None:
    program = load(tmp_path, ["G21 G90", "G0 X10.92 Y92", g92, "G0 X1.092 Y1", "X2 Y2"])
    state = plan_start(program, operation_at_line(program, 5), AXES).state
    assert state.offset == pytest.approx({"X": 10.92, "Y": 92.0})
    plain = load(tmp_path, ["G21 G90", "G0 X10.92 Y92", "G1 X92 Y1.92 F92", "X2 Y2"])
    assert plan_start(plain, operation_at_line(plain, 4), AXES).state.offset == {
        "X": 0.0,
        "Y": 0.0,
    }


def test_a_plan_is_remembered_for_its_program_and_start_and_so_is_a_refusal(
    tmp_path: Path,
) -> None:
    program = load(tmp_path, ["G21 G90", "G0 X1 Y1", "G55", "G0 X2 Y2", "X3 Y3"])
    first = operation_at_line(program, 2)
    plan = plan_start(program, first, AXES)
    assert plan_start(program, first, AXES) is plan  # worked out once (a worker may have)
    later = operation_at_line(program, 5)
    with pytest.raises(StartRefused, match=r"job\.gcode:3: G55") as refused:
        plan_start(program, later, AXES)
    with pytest.raises(StartRefused) as again:
        plan_start(program, later, AXES)
    assert str(again.value) == str(refused.value)
    # Another program (the same lines loaded again) is worked out for itself.
    other = load(tmp_path, ["G21 G90", "G0 X1 Y1", "G0 X2 Y2"])
    assert plan_start(other, operation_at_line(other, 3), AXES).index == 2


def test_a_start_inside_an_arc_sequence_puts_the_arc_word_before_its_first_move(
    tmp_path: Path,
) -> None:
    program = load(
        tmp_path, ["G21 G90 F300", "G0 X50 Y50", "G2 X60 Y50 I5 J0", "X50 Y50 I-5 J0", "G0 X0"]
    )
    index = operation_at_line(program, 4)
    plan = plan_start(program, index, AXES)
    assert plan.state.motion == "G2"
    assert plan.lead == (index, "G2")
    assert not any(line.startswith("G2") for line in plan.lines(SETTINGS))  # no arc alone
    # A line that says its own motion needs nothing in front.
    assert plan_start(program, operation_at_line(program, 3), AXES).lead is None


# --- refusals -------------------------------------------------------------------------------


def test_a_line_beyond_the_end_or_before_the_first_is_refused_with_file_and_line(
    tmp_path: Path,
) -> None:
    program = load(tmp_path, ["G21 G90", "G0 X1 Y1", "(the end)", ""])
    with pytest.raises(StartRefused, match=r"job\.gcode:9: beyond the end"):
        operation_at_line(program, 9)
    with pytest.raises(StartRefused, match=r"job\.gcode:0: lines count from 1"):
        operation_at_line(program, 0)


def test_a_comment_line_starts_at_the_next_line_that_runs(tmp_path: Path) -> None:
    program = load(tmp_path, ["G21 G90", "(a comment)", "", "G0 X1 Y1"])
    assert program[operation_at_line(program, 3)].source.line >= 3
    assert program[operation_at_line(program, 4)].source.line == 4


@pytest.mark.parametrize(
    ("word", "line"),
    [("G10 L20 P1 X0 Y0", "G10"), ("G55", "G55"), ("G10 L2 P1 X5 Y5", "G10")],
)
def test_a_coordinate_system_the_file_changed_is_refused_at_its_line(
    tmp_path: Path, word: str, line: str
) -> None:
    gcode = replace(SETTINGS, words=(*SETTINGS.words, "G10", "G54", "G55", "L", "P"))
    program = load(tmp_path, ["G21 G90 F500", "G0 X5 Y5", word, "G1 X10 Y10", "G1 X20 Y20"], gcode)
    index = operation_at_line(program, 5)
    with pytest.raises(StartRefused, match=rf"job\.gcode:3: {line} before the start"):
        plan_start(program, index, AXES)
    # Before it nothing is refused.
    plan_start(program, operation_at_line(program, 2), AXES)


def test_a_drill_hole_starts_with_its_move_and_its_lines_are_no_start(tmp_path: Path) -> None:
    ops = (
        Operation(OpKind.WAIT, SourceRef("board.drl", 1), message="insert T01"),
        move(SourceRef("board.drl", 9), X=1.0, Y=1.0),
        Operation(OpKind.DRILL, SourceRef("board.drl", 9)),
        move(SourceRef("board.drl", 5), X=2.0, Y=2.0),
        Operation(OpKind.DRILL, SourceRef("board.drl", 5)),
    )
    program = Program("board", ops)
    assert operation_numbered(program, 5) == 3  # the drill cycle: from its move
    assert operation_numbered(program, 4) == 3
    with pytest.raises(StartRefused, match="operations 1 to 5"):
        operation_numbered(program, 6)
    with pytest.raises(StartRefused, match="operation number instead"):
        operation_at_line(program, 5)
    plan = plan_start(program, 3, AXES)
    assert plan.state.prompt == "insert T01"
    assert plan.state.resume.position == {"X": 1.0, "Y": 1.0}


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(
    body=st.lists(
        st.one_of(
            modal_line(),
            st.sampled_from(
                [
                    *("(G20 in a comment)", "G1 X20 Y92 ; G91", "", "G4 P0.2", "M5 (up)"),
                    *("g20", "G 21", "g91", "G092 X1 Y1", "g1 x20 y21"),
                ]
            ),
        ),
        min_size=1,
        max_size=30,
    ),
    stop=st.integers(0, 40),
)
def test_searching_the_file_bytes_finds_the_lines_the_texts_would(
    tmp_path: Path, body: list[str], stop: int
) -> None:
    """The fast search of a G-code file's texts (its bytes at once) against the plain one."""
    program = load(tmp_path, ["G21 G90 F1000", *body])
    texts = program.data.sent  # type: ignore[attr-defined]
    g92 = (re.compile(r"92(?![0-9])"), re.compile(r"[Gg][ \t]*0*2[01](?![0-9])"))
    for patterns in (MODAL_HINT, g92):
        fast = texts_matching(texts, patterns, stop)
        assert fast == texts_matching(list(texts), patterns, stop)
