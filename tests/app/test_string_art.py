"""String-art jobs: nail geometry, reading and checking the files, and the winder's program.

Expected values are worked out by hand from the original firmware's geometry (as
app/jobs/formats/string_art/geometry.py states it): nails sit 1.5 cm inside the
board's edge, so a board of radius R cm has its nails (or its polygon's corners)
on the circle of R·10 - 15 mm; a regular n-gon's edge midpoint is the closest a
point of it comes to the centre, (R·10 - 15)·cos(π/n) mm.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.formats.string_art.geometry import (
    nail_positions,
    polygon_min_radius_mm,
    shortest_turn,
)
from app.jobs.formats.string_art.program import (
    StringArtProgram,
    WindingSettings,
    build_program,
    move_seconds,
    winder_seconds,
)
from app.jobs.formats.string_art.reader import (
    NeedsNailCount,
    StringArtJob,
    StringArtParams,
    load_string_art,
    read_string_art,
    sniff_string_art,
)
from app.jobs.loaders import JobOptions, load_job, load_string_art_job, loader_for
from app.jobs.program import JobFileError, OpKind, Program
from app.profiles import load_profile

WINDER = ("A", "X", "Z")


def sample(data_dir: Path, name: str) -> Path:
    return data_dir / "samples" / f"string-art-{name}"


def realdata(data_dir: Path) -> Path:
    return data_dir / "realdata" / "stringart" / "threadArt_cat-sequence_160pins.txt"


def job_of(tvar: int, nails: int, radius_cm: float, sequence: list[int]) -> StringArtJob:
    return StringArtJob(StringArtParams(tvar, nails, radius_cm), tuple(sequence))


def pair(tmp_path: Path, param: str, poradi: str) -> Path:
    """A param.txt / poradi.txt pair in ``tmp_path``; returns the poradi.txt."""
    (tmp_path / "param.txt").write_bytes(param.encode())
    (tmp_path / "poradi.txt").write_bytes(poradi.encode())
    return tmp_path / "poradi.txt"


GOOD_PARAM = "tvar = 0\npocet_hrebiku = 200\npolomer_matrice = 14.5\n"


# --- geometry -------------------------------------------------------------------------------


def test_circle_nails_all_sit_15_mm_inside_the_edge_evenly_spaced() -> None:
    xy = nail_positions(0, 200, 14.5)
    assert np.allclose(np.hypot(xy[:, 0], xy[:, 1]), 130.0)
    assert xy[0] == pytest.approx([130.0, 0.0])
    angles = np.degrees(np.arctan2(xy[:, 1], xy[:, 0])) % 360
    assert np.allclose(np.diff(angles), 1.8)  # 360 / 200, counter-clockwise
    assert xy[50] == pytest.approx([0.0, 130.0], abs=1e-9)  # a quarter turn on: +Y


@pytest.mark.parametrize("sides", range(3, 13))
def test_polygon_nails_closest_approach_is_the_edge_midpoint(sides: int) -> None:
    """With 2·m·n nails, nail m sits on edge 0's midpoint: the minimum is exactly
    (R - 15 mm)·cos(π/n).  With an odd multiple of n no nail is on a midpoint; the
    minimum is then above it, by no more than half a nail spacing along the edge
    allows: sqrt(apothem² + (perimeter / 2N)²).  With N = n every nail is a corner."""
    radius_cm = 12.0
    r0 = 105.0
    apothem = r0 * math.cos(math.pi / sides)
    assert polygon_min_radius_mm(sides, radius_cm) == pytest.approx(apothem)
    perimeter = sides * 2 * r0 * math.sin(math.pi / sides)
    for multiple in (2, 4, 6):
        xy = nail_positions(sides, multiple * sides, radius_cm)
        assert np.hypot(xy[:, 0], xy[:, 1]).min() == pytest.approx(apothem, abs=1e-9)
    for nails in (3 * sides, 5 * sides, 101, 397):
        xy = nail_positions(sides, nails, radius_cm)
        lowest = np.hypot(xy[:, 0], xy[:, 1]).min()
        assert apothem - 1e-9 <= lowest <= math.hypot(apothem, perimeter / (2 * nails)) + 1e-9
    corners = nail_positions(sides, sides, radius_cm)
    assert np.allclose(np.hypot(corners[:, 0], corners[:, 1]), r0)


@pytest.mark.parametrize(("sides", "nails"), [(3, 10), (4, 7), (6, 120), (12, 101), (5, 400)])
def test_polygon_nails_are_evenly_spaced_along_the_perimeter(sides: int, nails: int) -> None:
    """Each nail lies on the edge its angle falls in, at perimeter distance k·L/N from corner 0."""
    r0 = 105.0
    corner = [
        np.array([r0 * math.cos(2 * math.pi * j / sides), r0 * math.sin(2 * math.pi * j / sides)])
        for j in range(sides + 1)
    ]
    side = 2 * r0 * math.sin(math.pi / sides)
    xy = nail_positions(sides, nails, 12.0)
    assert xy[0] == pytest.approx(corner[0])  # nail 0 on vertex 0, at angle 0
    for k, point in enumerate(xy):
        angle = math.degrees(math.atan2(point[1], point[0])) % 360
        edge = min(int(angle // (360 / sides)), sides - 1)
        if angle > 360 - 1e-9:
            edge = 0
        a, b = corner[edge], corner[edge + 1]
        cross = (b - a)[0] * (point - a)[1] - (b - a)[1] * (point - a)[0]
        assert abs(cross) / side < 1e-9  # on the edge's line
        along = edge * side + float(np.hypot(*(point - a)))
        assert along == pytest.approx(k * sides * side / nails)


def test_job_polar_matches_positions() -> None:
    job = job_of(6, 120, 12.0, [0, 1])
    angles, radii = job.nail_polar()
    xy = job.nail_positions()
    assert np.allclose(radii * np.cos(np.radians(angles)), xy[:, 0])
    assert np.allclose(radii * np.sin(np.radians(angles)), xy[:, 1])
    assert angles[0] == 0.0 and np.all(np.diff(angles) > 0)


def test_thread_length_is_the_sum_of_chords() -> None:
    # Four nails on a circle of 10 cm radius, nails at 85 mm: 0 → 2 is a diameter (170 mm),
    # 2 → 1 a quarter-circle chord (85·√2).
    job = job_of(0, 4, 10.0, [0, 2, 1])
    assert job.thread_length_mm() == pytest.approx(170 + 85 * math.sqrt(2))


# --- reading --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "params", "count", "start"),
    [
        ("cardioid", StringArtParams(0, 200, 14.5), 400, (0, 1, 68, 137, 4)),
        ("hexagon", StringArtParams(6, 120, 12.0), 300, (0, 43, 86, 9, 52)),
    ],
)
def test_samples_load_from_either_file_of_the_pair(
    data_dir: Path, name: str, params: StringArtParams, count: int, start: tuple[int, ...]
) -> None:
    folder = sample(data_dir, name)
    job = read_string_art(folder / "poradi.txt")
    assert job.params == params
    assert len(job.sequence) == count and job.sequence[:5] == start
    assert read_string_art(folder / "param.txt") == job
    program = load_job(folder / "param.txt", WINDER)
    assert isinstance(program, StringArtProgram) and program.job == job
    assert load_job(folder / "poradi.txt", WINDER).fingerprint() == program.fingerprint()


def test_a_generator_list_needs_the_board_then_loads(data_dir: Path) -> None:
    path = realdata(data_dir)
    with pytest.raises(NeedsNailCount) as caught:
        load_job(path, WINDER)
    assert caught.value.min_nails == 160  # indices 0…159
    assert caught.value.entries == 4001
    assert caught.value.file == path.name and caught.value.line == 0
    board = StringArtParams(0, 160, 30.0)
    job = load_string_art(path, board)
    assert job.params == board
    assert len(job.sequence) == 4001 and job.sequence[:6] == (0, 87, 9, 89, 11, 88)
    program = load_job(path, WINDER, JobOptions(string_art=board))
    assert isinstance(program, StringArtProgram) and program.job == job


def test_the_registry_tells_string_art_from_point_lists_and_drill_files(
    data_dir: Path, tmp_path: Path
) -> None:
    for path in (
        sample(data_dir, "cardioid") / "param.txt",
        sample(data_dir, "hexagon") / "poradi.txt",
        realdata(data_dir),
    ):
        assert loader_for(path) is load_string_art_job, path
    points = tmp_path / "points.txt"
    points.write_text("10, 20\n30, 40\n50, 60\n")
    assert loader_for(points) is not load_string_art_job
    assert not sniff_string_art("10,20\n30,40\n50,60\n")
    assert not sniff_string_art("M48\nT01C0.0315\n%\nT01\nX18350Y22100\n")
    assert sniff_string_art("0\n87\n9\n89\n11\n")  # one index a line
    assert sniff_string_art("TVAR=6\r\n")


def test_a_machine_without_the_winders_axes_is_refused(data_dir: Path) -> None:
    with pytest.raises(JobFileError, match="axes A, X and Z") as caught:
        load_job(sample(data_dir, "cardioid") / "poradi.txt", ("X", "Y"))
    assert caught.value.line == 0


def test_tolerated_spellings(tmp_path: Path) -> None:
    param = (
        "\ufeff# board\r\nTVAR=6 # hexagon\r\npocet_hrebiku: 12\r\n\r\npolomer_matrice = 10,5 ;\r\n"
    )
    poradi = "5 , 0;3\r\n7 ,\r\n\r\n1,,4,\r\n"
    job = read_string_art(pair(tmp_path, param, poradi))
    assert job.params == StringArtParams(6, 12, 10.5)
    assert job.sequence == (0, 3, 7, 1, 4)
    assert tuple(job.entry_lines) == (1, 1, 2, 4, 4)
    assert job.param_lines == {"tvar": 2, "pocet_hrebiku": 3, "polomer_matrice": 5}


def bad_pair(tmp_path: Path, param: str, poradi: str) -> JobFileError:
    with pytest.raises(JobFileError) as caught:
        read_string_art(pair(tmp_path, param, poradi))
    return caught.value


@pytest.mark.parametrize(
    ("param", "poradi", "file", "line", "words"),
    [
        # the count: 5 announced, 4 follow
        (GOOD_PARAM, "5,0,1,2,3\n", "poradi.txt", 1, "count says 5 nail indices, but 4 follow"),
        (GOOD_PARAM, "\n3\n0,1\n", "poradi.txt", 2, "count says 3"),
        # entry 4 (the count is not an entry) on line 3
        (GOOD_PARAM, "5\n0,1\n2,250,4\n", "poradi.txt", 3,
         "entry 4: nail 250 is out of range 0…199"),
        (GOOD_PARAM, "3,0,-1,2\n", "poradi.txt", 1, "entry 2: nail -1 is out of range"),
        (GOOD_PARAM, "4,0,5,5,7\n", "poradi.txt", 1, "entries 2 and 3: nail 5 twice in a row"),
        (GOOD_PARAM, "4,0,5\n7\n7\n", "poradi.txt", 3, "entries 3 and 4: nail 7 twice"),
        (GOOD_PARAM, "4,0,x,5,7\n", "poradi.txt", 1, "'x' is not a whole number"),
        (GOOD_PARAM, "4,0,1.5,5,7\n", "poradi.txt", 1, "'1.5' is not a whole number"),
        (GOOD_PARAM, "\n\n", "poradi.txt", 0, "no nail indices"),
        (GOOD_PARAM, "1,0\n", "poradi.txt", 1, "nothing to wind"),
        ("# shape\ntvar = 1\npocet_hrebiku = 200\npolomer_matrice = 14.5\n", "2,0,1\n",
         "param.txt", 2, "tvar = 1: the shape must be 0"),
        ("pocet_hrebiku = 200\npolomer_matrice = 14.5\n\ntvar = 2\n", "2,0,1\n",
         "param.txt", 4, "tvar = 2"),
        ("tvar = 0\npocet_hrebiku = 200\npolomer_matrice = 1.5\n", "2,0,1\n",
         "param.txt", 3, "larger than 1.5 cm"),
        ("tvar = 0\npocet_hrebiku = 200\npolomer_matrice = 0,8\n", "2,0,1\n",
         "param.txt", 3, "polomer_matrice = 0.8 cm"),
        ("tvar = 0\npocet_hrebiku = 2\npolomer_matrice = 14\n", "2,0,1\n",
         "param.txt", 2, "at least 3 nails"),
        ("tvar = 0\npocet_hrebiku = many\npolomer_matrice = 14\n", "2,0,1\n",
         "param.txt", 2, "is not a number"),
        ("tvar = 0\npocet_hrebiku = 20.5\npolomer_matrice = 14\n", "2,0,1\n",
         "param.txt", 2, "not a whole number"),
        ("tvar = 0\npolomer_matrice = 14\n", "2,0,1\n", "param.txt", 0, "no 'pocet_hrebiku"),
        ("tvar = 0\ntvar = 6\n", "2,0,1\n", "param.txt", 2, "tvar given twice (first on line 1)"),
        ("tvar 0\n", "2,0,1\n", "param.txt", 1, "expected 'key = value'"),
    ],
)  # fmt: skip
def test_each_problem_is_reported_on_its_line(
    tmp_path: Path, param: str, poradi: str, file: str, line: int, words: str
) -> None:
    error = bad_pair(tmp_path, param, poradi)
    assert (error.file, error.line) == (file, line), str(error)
    assert words in error.reason


def test_opening_param_txt_reports_its_own_problems_first(tmp_path: Path) -> None:
    pair(tmp_path, "tvar = 2\npocet_hrebiku = 10\npolomer_matrice = 5\n", "9,0\n")
    with pytest.raises(JobFileError) as caught:
        read_string_art(tmp_path / "param.txt")
    assert (caught.value.file, caught.value.line) == ("param.txt", 1)


def test_a_missing_partner_is_named(tmp_path: Path) -> None:
    (tmp_path / "param.txt").write_text(GOOD_PARAM)
    with pytest.raises(JobFileError, match=r"no poradi\.txt"):
        read_string_art(tmp_path / "param.txt")
    (tmp_path / "param.txt").unlink()
    (tmp_path / "poradi.txt").write_text("2,0,1\n")
    with pytest.raises(NeedsNailCount):
        read_string_art(tmp_path / "poradi.txt")


def test_a_bare_list_and_a_counted_one(tmp_path: Path) -> None:
    counted = tmp_path / "counted.txt"
    counted.write_text("3,5,6,7\n")
    bare = tmp_path / "bare.txt"
    bare.write_text("5,6,7,8\n")
    board = StringArtParams(0, 10, 10.0)
    assert load_string_art(counted, board).sequence == (5, 6, 7)
    assert load_string_art(bare, board).sequence == (5, 6, 7, 8)
    with pytest.raises(JobFileError, match="entry 4: nail 8 is out of range 0…7") as caught:
        load_string_art(bare, StringArtParams(0, 8, 10.0))
    assert (caught.value.file, caught.value.line) == ("bare.txt", 1)
    with pytest.raises(JobFileError, match="the board entered: tvar = 2"):
        load_string_art(bare, StringArtParams(2, 10, 10.0))


# --- the program ----------------------------------------------------------------------------


def a_moves(program: StringArtProgram) -> list[tuple[int, float]]:
    return [(i, op.target["A"]) for i, op in enumerate(program) if "A" in op.target]


def replay(program: StringArtProgram) -> list[dict[str, float]]:
    """Where A, X, Z are after each operation, from the operations alone."""
    where = {"A": 0.0, "X": 0.0, "Z": 0.0}
    states = []
    for op in program:
        where.update(op.target)
        states.append(dict(where))
    return states


@settings(max_examples=150, deadline=None)
@given(data=st.data())
def test_no_turn_exceeds_half_a_turn_and_the_nails_come_in_file_order(data: st.DataObject) -> None:
    """Any board and sequence: turns within half a turn, the nails in file order, the needle
    2 cm inside the innermost nail and 2 cm outside the nail it wraps (FIDELITY S0-20)."""
    nails = data.draw(st.integers(3, 400), label="nails")
    tvar = data.draw(st.sampled_from([0, *range(3, 13)]), label="tvar")
    # Room for the needle 2 cm inside a triangle's mid-edge nails: 8 cm and more.
    radius = data.draw(st.floats(8.0, 30.0), label="radius_cm")
    first = data.draw(st.integers(0, nails - 1), label="first")
    hops = data.draw(st.lists(st.integers(1, nails - 1), min_size=1, max_size=80), label="hops")
    sequence = [first]
    for hop in hops:
        sequence.append((sequence[-1] + hop) % nails)
    job = job_of(tvar, nails, radius, sequence)
    program = build_program(job)

    previous = 0.0  # the program starts with the base at A = 0
    for _index, angle in a_moves(program):
        assert abs(angle - previous) <= 180 + 1e-9
        previous = angle

    winding = program.entry_of_op >= 0
    visited = [int(n) for n in program.nail_of_op[winding]]
    order = [n for i, n in enumerate(visited) if i == 0 or n != visited[i - 1]]
    assert order == sequence

    # And each visit really wraps its nail: out 2 cm beyond it, across the nail's angle,
    # back in 2 cm inside every nail (FIDELITY S0-20: the firmware's radii).
    angles, radii = job.nail_polar()
    states = replay(program)
    moves = np.zeros(len(program), dtype=bool)
    moves[program.indices_of(OpKind.MOVE)] = True
    for entry in range(1, len(sequence)):
        ops = np.flatnonzero((program.entry_of_op == entry) & moves)
        turn, out, wrap, back = (states[i] for i in ops)
        nail = sequence[entry]
        assert turn["X"] == back["X"] == pytest.approx(radii.min() - 20.0)
        assert out["X"] == wrap["X"] == pytest.approx(radii[nail] + 20.0)
        swept = wrap["A"] - out["A"]
        to_nail = shortest_turn(out["A"], float(angles[nail]))
        assert 0 < abs(to_nail) < abs(swept) < 180 and to_nail * swept > 0


def test_drill_phase_as_the_firmware_then_drivers_off_wait_and_start_back_at_angle_0(
    data_dir: Path,
) -> None:
    """FIDELITY S0-15, S0-16, S0-18, S0-19, S0-25: the firmware's drilling and winding start.

    The drill starts 1 cm above the board (Z 0), goes 1 cm above plus 1 cm deep
    along the axis tilted 74.333° (20 / sin 74.333° = 20.773 mm of Z, of which
    10.386 mm past the surface), waits 250 ms, comes back; then the base turns
    back to nail 0 and the tool goes to its radius, every driver is switched off
    while the operator works, and the winding starts: needle out 2 cm beyond the
    board (``polomer_matrice_cm + 2.0``), turn towards the midpoint of it and the next
    nail, needle in, turn back to angle 0, the drill's driver off.
    """
    job = read_string_art(sample(data_dir, "hexagon") / "poradi.txt")
    program = build_program(job)
    angles, radii = job.nail_polar()
    states = replay(program)
    bottom = 20.0 / math.sin(math.radians(74.333))
    assert bottom - 10.0 / math.sin(math.radians(74.333)) == pytest.approx(10.386, abs=5e-4)
    first_move = program[program.indices_of(OpKind.MOVE)[0]]
    assert first_move.target == {"Z": 0.0}
    assert first_move.message == "drill 10 mm above the board"
    plunges = [i for i, op in enumerate(program) if "Z" in op.target and op.target["Z"] > 0]
    assert len(plunges) == 120
    for nail, i in enumerate(plunges):
        assert program[i].target["Z"] == pytest.approx(bottom)
        assert states[i]["A"] % 360 == pytest.approx(angles[nail] % 360, abs=1e-9)
        assert states[i]["X"] == pytest.approx(radii[nail])
        assert program[i + 1].kind is OpKind.GCODE and program[i + 1].line == "G4 S0.25"
        assert program[i + 2].target == {"Z": 0.0}  # back to 1 cm above at once
        assert program.nail_of_op[i] == nail
    assert np.array_equal(program.dwell_ops, [i + 1 for i in plunges])
    waits = program.indices_of(OpKind.WAIT)
    assert len(waits) == 1 and waits[0] == program.wait_index > plunges[-1]
    # Back to nail 0 (a whole turn on, the short way from the last nail) at its radius.
    assert states[waits[0]]["A"] == pytest.approx(360.0)
    assert states[waits[0]]["X"] == pytest.approx(radii[0])
    assert program[waits[0] - 1].line == "M18"  # every driver off while waiting
    assert program[waits[0]].message == "Insert the nails, tie the thread to nail 0"
    after = program.operations[waits[0] + 1 : waits[0] + 6]
    # Out beyond the board's edge: the firmware's ``polomer_matrice_cm + 2.0`` (S0-19).
    assert after[0].target["X"] == pytest.approx(job.params.radius_cm * 10.0 + 20.0)
    # Towards the midpoint of nails 0 and 1 (nail 1 on the hexagon's first edge, S0-26).
    xy = job.nail_positions()
    middle = (xy[0] + xy[1]) / 2
    toward = math.degrees(math.atan2(middle[1], middle[0]))
    assert after[1].target["A"] == pytest.approx(360.0 + toward)
    assert after[2].target["X"] == pytest.approx(radii.min() - 20.0)
    assert after[3].target["A"] == pytest.approx(360.0)  # back to angle 0
    assert after[4].line == "M18 Z0"  # the drill's driver off while winding
    assert all(op.target.get("Z", 0.0) == 0.0 for op in program.operations[waits[0] :])


def test_every_connection_is_wound_once_not_the_firmwares_off_by_one() -> None:
    """FIDELITY S0-22, a deliberate deviation: the firmware's loop winds entries 1…count-1
    (the tie nail, never the last); StepDeck ties to the first and winds all the others."""
    sequence = [0, 5, 2, 7, 3]
    program = build_program(job_of(0, 10, 12.0, sequence))
    winding = program.entry_of_op > 0
    wound = [int(n) for n in program.nail_of_op[winding]]
    order = [n for i, n in enumerate(wound) if i == 0 or n != wound[i - 1]]
    assert order == sequence[1:]  # the last nail (3) wound, the tie nail (0) not wrapped
    wraps = [op for op in program if op.message.endswith("round the nail")]
    assert len(wraps) == len(sequence) - 1


def test_sources_point_at_the_files(data_dir: Path) -> None:
    folder = sample(data_dir, "cardioid")
    program = build_program(read_string_art(folder / "poradi.txt"))
    drill = program[program.indices_of(OpKind.MOVE)[0]]
    assert str(drill.source) == "param.txt:2"  # pocet_hrebiku
    assert str(program[-1].source) == "poradi.txt:1"
    # G-code lines: the drill's dwells and the drivers switched off (FIDELITY S0-16, S0-25).
    assert program.kinds() == {OpKind.MOVE, OpKind.WAIT, OpKind.COMMENT, OpKind.GCODE}


def test_program_arrays_agree_with_the_operations(data_dir: Path) -> None:
    program = build_program(read_string_art(sample(data_dir, "cardioid") / "poradi.txt"))
    for axes in (("A", "X", "Z"), ("X", "Q")):
        fast, slow = program.path(axes), Program.path(program, axes)  # arrays vs operations
        assert np.array_equal(fast.ops, slow.ops)
        assert np.allclose(fast.coords, slow.coords, equal_nan=True)
        assert np.array_equal(fast.pen, slow.pen)
    for kind in OpKind:
        assert np.array_equal(program.indices_of(kind), Program.indices_of(program, kind))
    plane = program.preview_path("A", "X")
    states = replay(program)
    for k in (5, 900, len(plane) - 1):
        where = states[plane.ops[k]]
        assert plane.coords[k] == pytest.approx(
            [where["X"] * math.cos(math.radians(where["A"])),
             where["X"] * math.sin(math.radians(where["A"]))]
        )  # fmt: skip
    assert not plane.pen[plane.ops < program.wait_index].any()
    assert plane.pen[plane.ops > program.wait_index].all()


def test_winding_settings_and_a_board_too_small_for_the_needle() -> None:
    job = job_of(0, 10, 10.0, [0, 5])
    program = build_program(job, settings=WindingSettings(needle_in_mm=10, needle_out_mm=3))
    # In: 85 - 10; out: the start, 3 mm beyond the 100 mm board (FIDELITY S0-19).
    assert program.needle_in_radius_mm == 75.0 and program.needle_out_radius_mm == 103.0
    assert WindingSettings() == WindingSettings(needle_in_mm=20.0, needle_out_mm=20.0)
    with pytest.raises(JobFileError, match="no room for the needle"):
        build_program(job_of(3, 10, 2.0, [0, 5]))  # corners at 5 mm, mid-edges at 2.5 mm


def test_profile_axes_and_the_estimate() -> None:
    profile = load_profile("string-art")
    assert [a.name for a in profile.axes] == list(WINDER)
    # 9600 microsteps a turn, 32 a mm on X, 133.3 a mm on Z: steps_per_rev x microsteps / lead.
    per_unit = {a.name: a.steps_per_rev * a.microsteps / a.lead for a in profile.axes}
    assert per_unit["A"] * 360 == pytest.approx(9600)
    assert per_unit["X"] == pytest.approx(32)
    assert per_unit["Z"] == pytest.approx(133.3, abs=0.05)
    for axis in profile.axes:  # 2000 microsteps/s, 500 microsteps/s²
        assert axis.max_speed * per_unit[axis.name] == pytest.approx(2000)
        assert axis.max_acceleration * per_unit[axis.name] == pytest.approx(500)
    assert profile.gcode is not None and profile.gcode.kinematics == "cylindrical"
    assert profile.travel_limits()["A"] == (-math.inf, math.inf)
    # A 90° turn never reaches 75°/s at 18.75°/s² (that takes 300°): 2·√(90/18.75) s.
    assert move_seconds(np.array([90.0]), 75.0, 18.75)[0] == pytest.approx(2 * math.sqrt(4.8))
    # 300 mm on X passes the 250 mm ramp: 300/62.5 + 62.5/15.625 = 8.8 s.
    assert move_seconds(np.array([-300.0]), 62.5, 15.625)[0] == pytest.approx(8.8)
    job = job_of(0, 4, 10.0, [0, 2, 1])  # two threads: 0 to 2, 2 to 1
    program = build_program(job, profile)
    assert program.estimate_s == pytest.approx(winder_seconds(program, profile))
    assert program.estimate_s is not None and program.estimate_s > 0
    assert program.summary().startswith("4 nails on a circle of 10 cm radius, 2 connections")
    assert "about" in program.summary()
    with pytest.raises(ValueError, match="lacks the winder's axes"):
        build_program(job, load_profile("xy-stage"))


def test_the_estimate_counts_the_drills_dwells() -> None:
    """FIDELITY S0-16: the 250 ms at each hole's bottom is machine time, so it is estimated."""
    profile = load_profile("string-art")
    job = job_of(0, 12, 10.0, [0, 5, 9])
    program = build_program(job, profile)
    without = build_program(job, profile, WindingSettings(drill_dwell_s=0.0))
    assert program.estimate_s is not None and without.estimate_s is not None
    assert program.estimate_s - without.estimate_s == pytest.approx(12 * 0.25)
    timed = estimate_gcode(program, profile)
    assert timed.total_s == pytest.approx(program.estimate_s)
    first_dwell = int(program.dwell_ops[0])
    step = timed.cumulative_s[first_dwell] - timed.cumulative_s[first_dwell - 1]
    assert step == pytest.approx(0.25)


def test_summary_shows_the_totals(data_dir: Path) -> None:
    job = read_string_art(sample(data_dir, "cardioid") / "poradi.txt")
    text = job.summary(3725.0)
    # 400 nails visited, tied at the first: 399 threads between them, as the generator counts.
    assert len(job.sequence) == 400
    assert text.startswith("200 nails on a circle of 14.5 cm radius, 399 connections, thread ")
    assert text.endswith(", about 1:02:05")
    assert f"thread {job.thread_length_mm() / 1000:.1f} m" in text
    assert "about" not in job.summary(None)


_PARAM_LINES = st.lists(
    st.tuples(
        st.sampled_from(["tvar", "pocet_hrebiku", "polomer_matrice", "x", "", "TVAR"]),
        st.sampled_from([" = ", "=", ": ", " "]),
        st.sampled_from(["0", "3", "6", "1", "-2", "200", "14,5", "1.5", "1e9", "", "abc", "nan"]),
    ).map(lambda t: "".join(t)),
    max_size=5,
)
_PORADI = st.lists(
    st.one_of(st.integers(-3, 250).map(str), st.sampled_from(["", " ", "x", "1.5", "\n"])),
    max_size=30,
).map(",".join)


@settings(max_examples=300, deadline=None)
@given(
    st.one_of(_PARAM_LINES, st.just(["tvar = 0", "pocet_hrebiku = 200", "polomer_matrice = 14.5"])),
    st.one_of(_PORADI, st.just("3,0,1,2")),
)
def test_any_pair_of_files_loads_or_is_refused_with_file_and_line(
    tmp_path_factory: pytest.TempPathFactory, param_lines: list[str], poradi: str
) -> None:
    directory = tmp_path_factory.mktemp("pair")
    (directory / "param.txt").write_text("\n".join(param_lines) + "\n", encoding="utf-8")
    (directory / "poradi.txt").write_text(poradi + "\n", encoding="utf-8")
    profile = load_profile("string-art")
    axes = [axis.name for axis in profile.axes]
    for chosen in ("param.txt", "poradi.txt"):
        try:
            program = load_job(directory / chosen, axes, JobOptions())
        except JobFileError as exc:
            assert exc.file in ("param.txt", "poradi.txt") and exc.reason
            assert exc.line >= 0
            continue
        assert len(program) > 0
        program.preview_path("A", "X")
