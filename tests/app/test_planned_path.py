"""G-code lines read as the board runs them: the path every status report must follow.

Each case feeds lines as the session writes them and checks, with reports the
board would send, what passes and what trips: work offsets (G92 both ways),
modes (G91, G20), arcs (their box), jogs, and the commands the station cannot
follow, which release the envelope instead of guessing.
"""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from app.machines.envelope import Envelope, Fault
from app.machines.gcode.planned_path import PlannedPath

TOL = 0.5


def path(*, grbl: bool = True, at: tuple[float, float] = (0.0, 0.0)) -> PlannedPath:
    planned = PlannedPath(
        Envelope([(0.0, 300.0), (0.0, 200.0)], TOL, hold_at_rest=False), ("X", "Y"), grbl=grbl
    )
    planned.anchor(at, (0.0, 0.0))
    return planned


def test_the_mangled_plotter_line_trips_and_the_line_sent_is_named() -> None:
    planned = path(at=(5.0, 5.0))
    planned.line("G1 X18.000 Y18.000 F3000", "G1 X18.000 Y18.000 F3000", 7)
    envelope = planned.envelope
    # What the board ran: "G1 X18.F3000", along Y = 5.
    deviation = envelope.check((12.0, 5.0))
    assert deviation is not None and deviation.fault is Fault.OFF_PATH
    assert deviation.tag == 7


def test_a_grbl_work_offset_shifts_the_targets_and_not_the_machine() -> None:
    planned = path(at=(10.0, 10.0))
    planned.line("G92 X0 Y0", "G92")
    planned.line("G1 X5 Y0 F600", "G1 X5")
    envelope = planned.envelope
    assert envelope.check((10.0, 10.0)) is None
    assert envelope.check((15.0, 10.0)) is None  # work X5 is machine X15
    assert envelope.check((5.0, 0.0)) is not None  # not the work position


def test_the_plotters_g92_moves_the_reports_and_a_bare_one_makes_the_origin() -> None:
    planned = path(grbl=False, at=(10.0, 10.0))
    planned.line("G92", "G92")  # the CoreXY plotter: here is the origin now
    planned.line("G1 X5 Y0", "G1 X5")
    envelope = planned.envelope
    assert envelope.check((10.0, 10.0)) is None  # before the G92 ran
    assert envelope.check((0.0, 0.0)) is None  # its reports jump
    assert envelope.check((5.0, 0.0)) is None
    assert envelope.check((15.0, 10.0)) is not None


def test_relative_inch_and_machine_coordinates_are_followed() -> None:
    planned = path(at=(1.0, 1.0))
    planned.line("G91 G1 X2 F100", "a")
    planned.line("G1 Y3", "b")  # still relative
    planned.line("G90 G20 G1 X1", "c")  # an inch: 25.4 mm
    planned.line("G21 G53 G0 Y50", "d")
    envelope = planned.envelope
    for seen in [(3.0, 1.0), (3.0, 4.0), (25.4, 4.0), (25.4, 50.0)]:
        assert envelope.check(seen) is None, seen
    assert envelope.end == (25.4, 50.0)


def test_a_jog_leaves_the_boards_modes_alone() -> None:
    planned = path(at=(5.0, 5.0))
    planned.line("$J=G91 G21 X1.000 F3000", "jog")
    planned.line("G1 X2 F100", "absolute still")
    envelope = planned.envelope
    assert envelope.check((6.0, 5.0)) is None
    assert envelope.check((2.0, 5.0)) is None
    assert envelope.end == (2.0, 5.0)


def test_lines_are_read_as_grbl_reads_them() -> None:
    """Spaces do not count (a spaced jog is a jog, a spaced number one number), and an
    unclosed comment hides the rest of its line (tests/test_gcode_lexer.py)."""
    planned = path(at=(5.0, 5.0))
    planned.line(" $ J = G91 X 1 F3000", "spaced jog")
    planned.line("G1 X1 0 F100 (Y90", "spaced number")
    envelope = planned.envelope
    assert envelope.check((6.0, 5.0)) is None
    assert envelope.end == (10.0, 5.0)


def test_drivers_off_dwell_and_settings_are_no_motion() -> None:
    planned = path(at=(5.0, 5.0))
    for line in ("M18 X0", "G4 P0.5", "$$", "M3 S1000", "F3000", "$X"):
        planned.line(line, line)
    assert planned.envelope.in_flight == 0 and planned.envelope.known


def test_what_cannot_be_followed_releases_the_envelope() -> None:
    for line in ("$H", "G28", "G30", "G54", "G10 L20 P1 X0", "G38.2 Z-5 F10", "G92.1", "G18"):
        planned = path()
        planned.line(line, line)
        assert not planned.envelope.known, line
        planned.line("G1 X100 F100", "after")  # nothing to add it to
        assert planned.envelope.check((250.0, 150.0)) is None


def test_the_plotters_g28_goes_home_through_its_point() -> None:
    planned = path(grbl=False, at=(10.0, 10.0))
    planned.line("G28 X20", "G28 X20")
    envelope = planned.envelope
    assert envelope.check((20.0, 10.0)) is None
    assert envelope.check((10.0, 5.0)) is None
    assert envelope.end == (0.0, 0.0)


@settings(max_examples=200, deadline=None)
@given(
    st.floats(5.0, 40.0),
    st.floats(-math.pi, math.pi),
    st.floats(0.1, 2 * math.pi - 0.1),
    st.booleans(),
    st.booleans(),
)
def test_every_point_of_an_arc_passes_and_the_path_goes_on_from_its_end(
    radius: float, start_angle: float, sweep: float, clockwise: bool, by_radius: bool
) -> None:
    centre = (150.0, 100.0)
    turn = -sweep if clockwise else sweep
    start = (centre[0] + radius * math.cos(start_angle), centre[1] + radius * math.sin(start_angle))
    end_angle = start_angle + turn
    end = (centre[0] + radius * math.cos(end_angle), centre[1] + radius * math.sin(end_angle))
    planned = path(at=start)
    word = "G2" if clockwise else "G3"
    if by_radius:
        r = radius if sweep <= math.pi else -radius
        line = f"{word} X{end[0]:.4f} Y{end[1]:.4f} R{r:.4f}"
    else:
        i, j = centre[0] - start[0], centre[1] - start[1]
        line = f"{word} X{end[0]:.4f} Y{end[1]:.4f} I{i:.4f} J{j:.4f}"
    planned.line(line, line)
    planned.line("G1 X150 Y100", "to the centre")
    envelope = planned.envelope
    for k in range(11):
        a = start_angle + turn * k / 10
        seen = (centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a))
        assert envelope.check(seen) is None, (k, seen)
    assert envelope.check(centre) is None


@settings(max_examples=500, deadline=None)
@given(
    st.lists(
        st.one_of(
            st.sampled_from(["G0", "G1", "G2", "G3", "G20", "G21", "G53", "G90", "G91", "G92"]),
            st.sampled_from(["X", "Y", "I", "J", "R", "F", "$J=", "M18", "G92.1", "(c)", ";"]),
            st.floats(-1e6, 1e6, allow_nan=False).map(lambda v: f"{v:.3f}"),
            st.text(alphabet="GXYIJRF.-+ 0123456789$=", max_size=8),
        ),
        max_size=10,
    ),
    st.booleans(),
)
def test_any_line_is_read_without_an_exception(parts: list[str], grbl: bool) -> None:
    planned = path(grbl=grbl, at=(10.0, 10.0))
    planned.line("".join(parts), "fuzz")
    planned.line(" ".join(parts), "fuzz")
    end = planned.envelope.end
    assert end is None or len(end) == 2
