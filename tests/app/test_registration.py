"""Board registration: a known rotation and offset recovered from measured points, mirroring.

The measured points are made by putting the job's reference holes through a
known transform (and, for the scale check, a known stretch or a jog error);
the fit must give the transform back to within a micrometre at every hole.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.formats.excellon.reader import build_drill_program, read_drill_file
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.registration import (
    SCALE_TOLERANCE,
    Registration,
    RegistrationError,
    extent,
    mirrored,
    register,
    registered,
)

MICROMETRE = 0.001
WHERE = SourceRef("board.drl", 1)


def holes_program(points: list[tuple[float, float]]) -> Program:
    ops: list[Operation] = []
    for x, y in points:
        ops += [move(WHERE, X=x, Y=y), Operation(OpKind.DRILL, WHERE)]
    return Program("board", tuple(ops))


def move_points(program: Program) -> list[tuple[float, float]]:
    return [(op.target["X"], op.target["Y"]) for op in program if op.kind is OpKind.MOVE]


def test_two_points_recover_a_known_rotation_and_offset_at_every_hole() -> None:
    truth = Registration(math.radians(1.7), (12.345, -3.21))
    holes = [(0.0, 0.0), (50.8, 10.16), (25.4, 30.48), (80.0, 2.5)]
    job_refs = [holes[0], holes[3]]
    measured = [truth.apply(*p) for p in job_refs]

    fit = register(job_refs, measured)

    assert fit.angle_rad == pytest.approx(truth.angle_rad, abs=1e-9)
    assert fit.scale_ok() and fit.warning() == ""
    moved = move_points(registered(holes_program(holes), fit))
    for (x, y), (u, v) in zip(holes, moved, strict=True):
        assert math.dist(truth.apply(x, y), (u, v)) < MICROMETRE


@settings(max_examples=200, deadline=None)
@given(
    angle=st.floats(-math.pi, math.pi),
    dx=st.floats(-300, 300),
    dy=st.floats(-300, 300),
    points=st.lists(st.tuples(st.floats(-100, 100), st.floats(-100, 100)), min_size=3, max_size=3),
    three=st.booleans(),
)
def test_any_rigid_transform_is_recovered_to_a_micrometre(
    angle: float,
    dx: float,
    dy: float,
    points: list[tuple[float, float]],
    three: bool,
) -> None:
    refs = points if three else points[:2]
    if max(math.dist(a, b) for a in refs for b in refs) < 5.0:
        return  # holes too close to register; refused, tested below
    truth = Registration(angle, (dx, dy))
    fit = register(refs, [truth.apply(*p) for p in refs])
    assert fit.scale == pytest.approx(1.0, abs=1e-9)
    assert fit.residual_mm < MICROMETRE
    for corner in ((-100.0, -100.0), (100.0, 100.0), (100.0, -100.0)):
        assert math.dist(fit.apply(*corner), truth.apply(*corner)) < MICROMETRE
        assert math.dist(fit.inverse(*fit.apply(*corner)), corner) < MICROMETRE


def test_a_stretched_measurement_is_reported_as_a_scale_error_and_warned() -> None:
    truth = Registration(math.radians(-0.5), (5.0, 7.0))
    refs = [(0.0, 0.0), (100.0, 0.0)]
    # The second hole measured 0.5 mm too far along the board's edge: +0.5 %.
    far = truth.apply(100.5, 0.0)
    fit = register(refs, [truth.apply(*refs[0]), far])
    assert fit.scale_error == pytest.approx(0.005, abs=1e-9)
    assert not fit.scale_ok()
    assert "+0.500 %" in fit.warning()
    assert fit.angle_rad == pytest.approx(truth.angle_rad, abs=1e-9)
    program = registered(holes_program(refs), fit)
    assert "warning" in program.notes[-1]
    # Within the tolerance no warning.
    near = truth.apply(100.0 + 100 * SCALE_TOLERANCE / 2, 0.0)
    assert register(refs, [truth.apply(*refs[0]), near]).warning() == ""


def test_a_third_point_that_disagrees_shows_in_the_residual() -> None:
    truth = Registration(math.radians(3.0), (1.0, 2.0))
    refs = [(0.0, 0.0), (60.0, 0.0), (0.0, 40.0)]
    measured = [truth.apply(*p) for p in refs]
    measured[2] = (measured[2][0] + 0.3, measured[2][1])
    fit = register(refs, measured)
    assert 0.1 < fit.residual_mm < 0.3


@pytest.mark.parametrize(
    ("job", "machine", "reason"),
    [
        ([(0.0, 0.0)], [(0.0, 0.0)], "2 or 3 points"),
        ([(0.0, 0.0), (1.0, 1.0)], [(0.0, 0.0)], "measured point"),
        ([(0.0, 0.0), (0.2, 0.0)], [(0.0, 0.0), (0.2, 0.0)], "closer than"),
        ([(0.0, 0.0), (10.0, 0.0)], [(0.0, 0.0), (math.nan, 0.0)], "not a number"),
    ],
)
def test_points_that_cannot_register_a_board_are_refused(
    job: list[tuple[float, float]], machine: list[tuple[float, float]], reason: str
) -> None:
    with pytest.raises(RegistrationError, match=reason):
        register(job, machine)


@pytest.mark.parametrize("about", ["X", "Y"])
def test_mirroring_about_the_extent_round_trips_and_keeps_the_board_in_place(
    about: str,
) -> None:
    holes = [(10.0, 5.0), (60.0, 5.0), (20.0, 45.0), (33.3, 12.1)]
    program = holes_program(holes)
    flipped = mirrored(program, "X" if about == "X" else "Y")
    assert extent(flipped) == extent(program)
    assert move_points(flipped) != holes
    if about == "X":
        assert move_points(flipped)[0] == pytest.approx((60.0, 5.0))
    else:
        assert move_points(flipped)[2] == pytest.approx((20.0, 5.0))
    back = mirrored(flipped, "X" if about == "X" else "Y")
    assert all(math.dist(a, b) < 1e-9 for a, b in zip(move_points(back), holes, strict=True))
    assert [op.kind for op in back] == [op.kind for op in program]


def test_moves_on_one_axis_are_completed_and_other_operations_kept() -> None:
    program = Program(
        "p",
        (
            move(WHERE, X=10.0, Y=0.0, Z=3.0),
            Operation(OpKind.WAIT, WHERE, message="insert T01"),
            move(WHERE, Y=20.0),
            Operation(OpKind.DRILL, WHERE),
        ),
    )
    quarter = Registration(math.pi / 2, (100.0, 0.0))
    out = registered(program, quarter)
    assert out[0].target["Z"] == 3.0
    assert (out[0].target["X"], out[0].target["Y"]) == pytest.approx((100.0, 10.0))
    assert (out[2].target["X"], out[2].target["Y"]) == pytest.approx((80.0, 10.0))
    assert out[1] == program[1] and out[3] == program[3]
    with pytest.raises(RegistrationError, match="before both are known"):
        registered(Program("q", (move(WHERE, X=1.0),)), quarter)


def test_the_sample_board_registered_keeps_every_hole_and_tool_prompt(data_dir: Path) -> None:
    job = read_drill_file(data_dir / "samples/pcb-driver/driver")
    program = build_drill_program(job)
    truth = Registration(math.radians(-2.0), (15.0, 20.0))
    out = registered(program, truth)
    assert len(out) == len(program)
    assert [op.kind for op in out] == [op.kind for op in program]
    for before, after in zip(move_points(program), move_points(out), strict=True):
        assert math.dist(truth.apply(*before), after) < 1e-9
    assert out.fingerprint() != program.fingerprint()
