"""G-code files: the real ones per plotter, the modal model, arcs, pens, refusals, arrays."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.estimate import estimate
from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.formats.gcode.loader import (
    PARAMETER_REASON,
    GcodeProgram,
    load_gcode,
    sniff_gcode,
)
from app.jobs.loaders import JobOptions, load_job, loader_for
from app.jobs.program import JobFileError, OpKind
from app.profiles import AxisProfile, GcodeSettings, MachineProfile, load_profile
from widgets.jobs.preview import ProgramGeometry

BUNNY = "CNC-Drawinger_unicorn_BUNNY.gcode"
ESCRIBA = "Escriba_gcodetools_calibration.gcode"
MAKELANGELO = "Makelangelo_polargraph_multi_shapes_path-circle-line-rect.gcode"
PLOTTERS = ("corexy-plotter", "grbl-plotter")
XY = ("X", "Y")


def real(data_dir: Path, name: str) -> Path:
    return data_dir / "realdata" / "gcode" / name


def load_for(path: Path, profile_name: str, **options: bool) -> GcodeProgram:
    """``path`` read for a shipped profile, as the jobs dock does it."""
    profile = load_profile(profile_name)
    program = load_job(
        path,
        [axis.name for axis in profile.axes],
        JobOptions(gcode=profile.gcode, machine_title=profile.title, **options),
    )
    assert isinstance(program, GcodeProgram)
    return program


def write(tmp_path: Path, text: str, name: str = "job.gcode") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def grbl(path: Path, **options: bool) -> GcodeProgram:
    """A file for a GRBL board with X and Y (no profile: GRBL words and pen conventions)."""
    return load_gcode(path, XY, **options)


def file_lines(path: Path) -> list[str]:
    return path.read_text(encoding="utf-8").splitlines()


def numbered(path: Path, pattern: str) -> list[int]:
    """Line numbers (1-based) of the lines of ``path`` matching ``pattern``."""
    regex = re.compile(pattern)
    return [n for n, line in enumerate(file_lines(path), start=1) if regex.search(line)]


def of_kind(program: GcodeProgram, kind: OpKind) -> list[int]:
    return [int(i) for i in program.indices_of(kind)]


def unsupported_lines(program: GcodeProgram) -> list[int]:
    return sorted({p.line for p in program.unsupported})


# --- the real files ------------------------------------------------------------------


@pytest.mark.parametrize("profile", PLOTTERS)
@pytest.mark.parametrize("name", [BUNNY, ESCRIBA, MAKELANGELO])
def test_every_real_file_loads_for_both_plotters(data_dir: Path, profile: str, name: str) -> None:
    program = load_for(real(data_dir, name), profile)
    assert len(program) > 100
    assert sum(1 for _ in program) == len(program)
    assert [p.line for p in program.unsupported] == sorted(p.line for p in program.unsupported)
    moves = of_kind(program, OpKind.MOVE)
    assert moves and all(program[i].line for i in moves)  # every move is sent as a line
    # Every operation points at a real line of the file, in file order.
    lines = [op.source.line for op in program]
    assert lines == sorted(lines) and lines[-1] <= len(file_lines(real(data_dir, name)))


def test_bunny_pen_is_the_servo_and_is_translated(data_dir: Path) -> None:
    path = real(data_dir, BUNNY)
    downs = numbered(path, r"^M300 S30(\.0*)?\b")
    ups = numbered(path, r"^M300 S50(\.0*)?\b")
    assert len(downs) == 184 and len(ups) == 185
    for profile, down_text, up_text in (
        ("corexy-plotter", "M4", "M3"),
        ("grbl-plotter", "M3 S1000", "M5"),
    ):
        program = load_for(path, profile)
        pen_down = of_kind(program, OpKind.PEN_DOWN)
        pen_up = of_kind(program, OpKind.PEN_UP)
        assert [program[i].source.line for i in pen_down] == downs
        assert [program[i].source.line for i in pen_up] == ups
        assert {program[i].line for i in pen_down} == {down_text}
        assert {program[i].line for i in pen_up} == {up_text}
        assert any(
            f"369 pen lines sent as the {load_profile(profile).title}'s" in n for n in program.notes
        )
        assert any("S30 lowers the pen, S50 lifts it" in n for n in program.notes)
        wait = program[of_kind(program, OpKind.WAIT)[0]]
        assert wait.source.line == 12 and wait.message == "Was registration test successful?"
        dwells = [op for op in program if op.line == "G4 P150"]
        assert len(dwells) == len(numbered(path, r"^G4 P150"))


def test_bunny_unsupported_lines_on_the_corexy_plotter(data_dir: Path) -> None:
    path = real(data_dir, BUNNY)
    program = load_for(path, "corexy-plotter")
    assert file_lines(path)[10].startswith("M18")  # line 11, the first M18
    assert [(p.line, p.text) for p in program.unsupported] == [
        (11, "M18"),
        (13, "M17"),
        (4304, "M300 S255"),  # servo off: neither of the pen's two levels
        (4308, "M18"),
    ]
    assert program.unsupported[0].reason == "the CoreXY pen plotter cannot execute M18 (error:20)"
    assert program.unsupported[2].reason == "the CoreXY pen plotter cannot execute M300 (error:20)"
    # G21 is not sent (the plotter works in mm), noted; G92's Z (no pen here) is dropped.
    at_line = {op.source.line: op for op in program}
    assert at_line[3].kind is OpKind.COMMENT and "G21" in at_line[3].message
    assert any("1 G21 line not sent" in note for note in program.notes)
    assert at_line[5].line == "G92 X0.00 Y0.00"
    assert at_line[4306].kind is OpKind.GCODE and at_line[4306].line == "G1 F150.00"


def test_bunny_on_the_grbl_plotter_keeps_g21(data_dir: Path) -> None:
    program = load_for(real(data_dir, BUNNY), "grbl-plotter")
    first = program[1]  # after the two comment lines' first
    assert [op.line for op in program if op.source.line == 3] == ["G21"]
    assert unsupported_lines(program) == [11, 13, 4304, 4308]
    assert first.kind is OpKind.COMMENT


def escriba_arcs(path: Path) -> dict[int, tuple[float, float]]:
    """Line → written X, Y of every G02/G03 line (by hand: the file's own numbers)."""
    arcs = {}
    for number, line in enumerate(file_lines(path), start=1):
        if re.match(r"G0[23] ", line):
            x = float(re.search(r"X(-?[\d.]+)", line).group(1))  # type: ignore[union-attr]
            y = float(re.search(r"Y(-?[\d.]+)", line).group(1))  # type: ignore[union-attr]
            arcs[number] = (x, y)
    return arcs


def test_escriba_arcs_end_where_written(data_dir: Path) -> None:
    path = real(data_dir, ESCRIBA)
    arcs = escriba_arcs(path)
    assert len(arcs) == 151
    for profile in PLOTTERS:
        program = load_for(path, profile)
        found = {
            op.source.line: op
            for op in program
            if op.kind is OpKind.MOVE and op.source.line in arcs
        }
        assert len(found) == 151
        for number, (x, y) in arcs.items():
            assert dict(found[number].target) == pytest.approx({"X": x, "Y": y})
        # The preview has several vertices per arc, all with the arc's operation.
        path_ = program.path(XY)
        arc_ops = [
            i for i, op in enumerate(program) if op.source.line in arcs and op.kind is OpKind.MOVE
        ]
        counts = np.bincount(path_.ops, minlength=len(program))
        assert (counts[arc_ops] >= 4).all()


def test_escriba_arcs_refused_on_corexy_sent_on_grbl(data_dir: Path) -> None:
    path = real(data_dir, ESCRIBA)
    arcs = escriba_arcs(path)
    corexy = load_for(path, "corexy-plotter")
    reasons = {(p.line, p.reason) for p in corexy.unsupported}
    for number in arcs:
        word = "G2" if file_lines(path)[number - 1].startswith("G02") else "G3"
        assert (number, f"the CoreXY pen plotter cannot execute {word} (error:20)") in reasons
    others = {p.line: p.reason for p in corexy.unsupported if p.line not in arcs}
    assert others == {
        1: "the CoreXY pen plotter cannot execute $I (error:3)",
        2: "the CoreXY pen plotter cannot execute $G (error:3)",
        3: "the CoreXY pen plotter cannot execute $$ (error:3)",
        6: "the CoreXY pen plotter cannot execute M8 (error:20)",
        3914: "the CoreXY pen plotter cannot execute M9 (error:20)",
    }

    grbl_plotter = load_for(path, "grbl-plotter")
    # GRBL answers $I, $G and $$ itself, and takes the coolant M8/M9 (G7-04: `ok` in its
    # check mode too, test_preflight_vs_grbl_check.py).
    assert unsupported_lines(grbl_plotter) == []
    first_arc = next(op for op in grbl_plotter if op.source.line == 15)
    # Sent as written; the Z height is the pen on this machine, so it went out as M3 S1000/M5.
    assert first_arc.line == "G02 X274.184715 Y30.541697 I-0.862823 J0.766100 F800"
    status = next(op for op in grbl_plotter if op.source.line == 4)
    assert status.kind is OpKind.COMMENT and status.line == ""
    assert any("Z heights are the pen" in note for note in grbl_plotter.notes)


def test_escriba_z_heights_are_the_pen(data_dir: Path) -> None:
    program = load_for(real(data_dir, ESCRIBA), "grbl-plotter")
    at_line = {}
    for op in program:
        at_line.setdefault(op.source.line, []).append(op)
    assert [op.kind for op in at_line[10]] == [OpKind.PEN_UP]  # G00 Z5.000000
    assert at_line[10][0].line == "M5"
    assert file_lines(real(data_dir, ESCRIBA))[27] == "G01 Z-0.125000 F100.0(Penetrate)"
    penetrate = at_line[28]
    assert [op.kind for op in penetrate] == [OpKind.PEN_DOWN, OpKind.GCODE]
    assert [op.line for op in penetrate] == ["M3 S1000", "G01 F100.0"]


def test_makelangelo_waits_home_and_servo(data_dir: Path) -> None:
    path = real(data_dir, MAKELANGELO)
    downs = numbered(path, r"^M280 P0 S25\b")
    ups = numbered(path, r"^M280 P0 S90\b")
    for profile in PLOTTERS:
        program = load_for(path, profile)
        waits = [program[i] for i in of_kind(program, OpKind.WAIT)]
        assert [(w.source.line, w.message) for w in waits] == [
            (11, "Ready black and click"),
            (13, "Ready black and click"),
        ]
        home = next(op for op in program if op.source.line == 9)
        assert home.kind is OpKind.MOVE and home.line == "G28"
        assert dict(home.target) == {"X": 0.0, "Y": 0.0}
        assert [program[i].source.line for i in of_kind(program, OpKind.PEN_DOWN)] == downs
        assert [program[i].source.line for i in of_kind(program, OpKind.PEN_UP)] == ups
        assert program.unsupported == ()
        # Drawn around the origin: the plotters' travel starts at 0, the limit check says so.
        violations = program.limit_violations(load_profile(profile).travel_limits())
        assert violations and all(v.value < 0 for v in violations)


# --- the modal model -----------------------------------------------------------------


def targets(program: GcodeProgram) -> list[tuple[int, dict[str, float]]]:
    return [(op.source.line, dict(op.target)) for op in program if op.kind is OpKind.MOVE]


def test_relative_offsets_inches_and_continued_motion(tmp_path: Path) -> None:
    text = "\n".join(
        [
            "G90 G21",  # 1
            "G0 X10 Y10",  # 2
            "G91",  # 3
            "G1 X1 Y2 F100",  # 4
            "X1 Y2",  # 5  coordinates only: still G1, still relative
            "G90",  # 6
            "G92 X0 Y0",  # 7  here (12, 14) is called (0, 0)
            "G1 X5 Y5",  # 8
            "G20",  # 9
            "G1 X1 Y0.5",  # 10 inch, still offset
            "G21",  # 11
            "X3",  # 12 only X
        ]
    )
    program = grbl(write(tmp_path, text))
    assert targets(program) == [
        (2, {"X": 10.0, "Y": 10.0}),
        (4, {"X": 11.0, "Y": 12.0}),
        (5, {"X": 12.0, "Y": 14.0}),
        (8, {"X": 17.0, "Y": 19.0}),
        (10, {"X": pytest.approx(12 + 25.4), "Y": pytest.approx(14 + 12.7)}),
        (12, {"X": 15.0}),
    ]
    assert program.path(XY).coords[-1].tolist() == [15.0, pytest.approx(14 + 12.7)]
    assert program.unsupported == ()


def test_s1_07_a_bare_g92_on_the_corexy_plotter_makes_here_the_origin(tmp_path: Path) -> None:
    """The preview and the travel check follow the firmware: bare G92 = "here is 0, 0"."""
    text = "G90\nG0 X20 Y10\nG92\nG1 X5 Y5 F1000\nG0 X0 Y0\n"
    program = load_for(write(tmp_path, text), "corexy-plotter")
    assert targets(program) == [
        (2, {"X": 20.0, "Y": 10.0}),
        (4, {"X": 25.0, "Y": 15.0}),
        (5, {"X": 20.0, "Y": 10.0}),
    ]
    # GRBL refuses it (error:26): the job is refused at load, not mid-job.
    with pytest.raises(JobFileError) as caught:
        load_for(write(tmp_path, text, "grbl.gcode"), "grbl-plotter")
    assert "error:26" in str(caught.value) and ":3:" in str(caught.value)


def test_plain_and_full_parser_agree(tmp_path: Path) -> None:
    """The fast path (plain lines) and the full parser (same lines with comments) agree."""
    rng = np.random.default_rng(3)
    body = []
    for k in range(300):
        if k % 50 == 10:
            body.append(rng.choice(["G91", "G90", "G20", "G21", "G92 X1 Y2", "M3 S1000", "M5"]))
        x, y = rng.uniform(-5, 5, 2)
        body.append(f"G{k % 2} X{x:.3f} Y{y:.3f}" + (" F1200" if k % 3 == 0 else ""))
    plain = grbl(write(tmp_path, "\n".join(body), "plain.gcode"))
    commented = grbl(write(tmp_path, "\n".join(f"{line} ; c" for line in body), "full.gcode"))
    assert targets(plain) == targets(commented)
    assert [op.line for op in plain] == [op.line for op in commented]
    np.testing.assert_array_equal(plain.data.feed, commented.data.feed)
    np.testing.assert_array_equal(plain.data.pen, commented.data.pen)


def test_word_forms_numbers_checksums_and_comments(tmp_path: Path) -> None:
    text = "\n".join(
        [
            "%",  # 1 tape marker: nothing
            "N10 G1X10Y-2.5 F300*57",  # 2 compact, numbered, checksum
            "G01 X 20 Y 5 (spaced) ; and a comment",  # 3
            "n20 g0 x1 y1",  # 4 lower case
            "",  # 5 blank: nothing
            "(only a comment)",  # 6
            "; another",  # 7
            "G1 X2 (mid) Y3",  # 8 comment inside the line
            "G00X0Y0",  # 9
        ]
    )
    program = grbl(write(tmp_path, text))
    assert [(op.source.line, op.kind, op.line) for op in program] == [
        (2, OpKind.MOVE, "G1X10Y-2.5 F300"),
        (3, OpKind.MOVE, "G01 X 20 Y 5"),
        (4, OpKind.MOVE, "g0 x1 y1"),
        (6, OpKind.COMMENT, ""),
        (7, OpKind.COMMENT, ""),
        (8, OpKind.MOVE, "G1 X2 Y3"),
        (9, OpKind.MOVE, "G00X0Y0"),
    ]
    assert program[0].target == {"X": 10.0, "Y": -2.5}
    assert program[1].target == {"X": 20.0, "Y": 5.0}
    assert program[3].message == "only a comment"
    assert program.data.motion[[0, 2, 5]].tolist() == [1, 0, 1]


def test_crlf_and_bom(tmp_path: Path) -> None:
    path = tmp_path / "dos.nc"
    path.write_bytes(b"\xef\xbb\xbfG21\r\nG1 X1 Y2 F100\r\nG1 X3 Y4\r\n")
    program = grbl(path)
    assert [op.line for op in program] == ["G21", "G1 X1 Y2 F100", "G1 X3 Y4"]
    assert program[2].target == {"X": 3.0, "Y": 4.0}


# --- arcs ------------------------------------------------------------------------------


def arc_vertices(program: GcodeProgram, op: int) -> np.ndarray:
    path = program.path(XY)
    return path.coords[path.ops == op]


def assert_on_circle(points: np.ndarray, start: tuple[float, float], cx: float, cy: float) -> None:
    """Vertices on the circle; chords' midpoints within the 0.02 mm chord error."""
    radius = math.hypot(start[0] - cx, start[1] - cy)
    distance = np.hypot(points[:, 0] - cx, points[:, 1] - cy)
    np.testing.assert_allclose(distance, radius, atol=1e-9)
    chain = np.vstack([start, points])
    middle = (chain[1:] + chain[:-1]) / 2
    sagitta = radius - np.hypot(middle[:, 0] - cx, middle[:, 1] - cy)
    assert sagitta.max() <= 0.02 + 1e-12


@pytest.mark.parametrize(
    ("arc", "centre"),
    [
        ("G3 X0 Y10 I-10 J0", (0.0, 0.0)),  # counter-clockwise quarter, centre by offsets
        ("G3 X0 Y10 R10", (0.0, 0.0)),  # the same by radius
        ("G2 X0 Y-10 I-10 J0", (0.0, 0.0)),  # clockwise quarter
        ("G2 X0 Y10 R-10", (0.0, 0.0)),  # clockwise, the long way round (R < 0)
    ],
)
def test_arc_is_flattened_on_its_circle(
    tmp_path: Path, arc: str, centre: tuple[float, float]
) -> None:
    program = grbl(write(tmp_path, f"G0 X10 Y0 F600\n{arc}\n"))
    points = arc_vertices(program, 1)
    assert len(points) >= 4
    end = {"X": float(points[-1, 0]), "Y": float(points[-1, 1])}
    assert end == pytest.approx(dict(program[1].target))
    assert program[1].line == arc
    assert_on_circle(points, (10.0, 0.0), *centre)
    angles = np.unwrap(np.arctan2(points[:, 1], points[:, 0]))
    sweep = abs(angles[-1])
    expected = math.pi * 1.5 if "R-" in arc else math.pi / 2
    assert sweep == pytest.approx(expected, abs=1e-9)


def test_full_circle_with_offsets(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G0 X10 Y0\nG2 X10 Y0 I-5 J0 F600\n"))
    points = arc_vertices(program, 1)
    assert_on_circle(points, (10.0, 0.0), 5.0, 0.0)
    angles = np.unwrap(np.arctan2(points[:, 1], points[:, 0] - 5.0))
    assert angles[-1] == pytest.approx(-2 * math.pi)  # clockwise, all the way round
    assert points[-1].tolist() == [10.0, 0.0]


def test_arc_in_inches_and_relative(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G20 G0 X1 Y0\nG91 G3 X-1 Y1 I-1 J0 F20\n"))
    assert program[1].target == pytest.approx({"X": 0.0, "Y": 25.4})
    assert_on_circle(arc_vertices(program, 1), (25.4, 0.0), 0.0, 0.0)


def test_arc_without_centre_is_refused(tmp_path: Path) -> None:
    with pytest.raises(JobFileError) as caught:
        grbl(write(tmp_path, "G0 X0 Y0\nG2 X10 Y0\n"))
    assert caught.value.line == 2


# --- pens -------------------------------------------------------------------------------


def kinds_and_lines(program: GcodeProgram) -> list[tuple[OpKind, str]]:
    return [(op.kind, op.line) for op in program]


def test_grbl_servo_convention_and_the_profiles_own_mapping_wins(tmp_path: Path) -> None:
    path = write(tmp_path, "M3 S1000\nM03 S500\nM5\nM3\n")
    assert kinds_and_lines(load_for(path, "grbl-plotter")) == [
        (OpKind.PEN_DOWN, "M3 S1000"),  # the profile's own: as written
        (OpKind.PEN_DOWN, "M3 S1000"),  # GRBL convention, S > 0: the profile's level
        (OpKind.PEN_UP, "M5"),
        (OpKind.GCODE, "M3"),  # no S: not a pen level
    ]
    # The CoreXY plotter lifts with M3 and lowers with M4: its mapping wins over GRBL's.
    assert kinds_and_lines(load_for(path, "corexy-plotter")) == [
        (OpKind.PEN_UP, "M3"),
        (OpKind.PEN_UP, "M3"),
        (OpKind.GCODE, "M5"),
        (OpKind.PEN_UP, "M3"),
    ]


def test_a_single_servo_level_says_nothing_about_the_pen(tmp_path: Path) -> None:
    program = load_for(write(tmp_path, "M300 S30\nG1 X1 Y1 F100\nM300 S30\n"), "grbl-plotter")
    assert of_kind(program, OpKind.PEN_DOWN) == of_kind(program, OpKind.PEN_UP) == []
    assert [p.line for p in program.unsupported] == [1, 3]  # sent as written: GRBL has no M300


def test_repeated_lines_follow_the_units_in_force(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "F100\nG20\nF100\nG1 X1 Y1\nG4 P0.1\nG4 P0.1\n"))
    assert program.data.feed.tolist() == pytest.approx([100, 100, 2540, 2540, 2540, 2540])
    assert program.data.dwell_s.tolist() == [0.1, 0.1]


def test_real_time_bytes_on_a_line(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G1 X1 Y1 F100\n?\n!\n"))
    assert program[1].kind is OpKind.COMMENT and program[1].line == ""
    assert [(p.line, p.text) for p in program.unsupported] == [(3, "!")]


def test_pen_lines_sent_as_written_when_not_translated(data_dir: Path) -> None:
    program = load_for(real(data_dir, BUNNY), "corexy-plotter", translate_pen=False)
    downs = of_kind(program, OpKind.PEN_DOWN)
    assert program[downs[0]].line == "M300 S30"
    refused = {
        p.line for p in program.unsupported if p.reason.endswith("cannot execute M300 (error:20)")
    }
    assert len(refused) == 184 + 185 + 1  # every servo line, and the S255
    assert not any("pen lines sent as" in note for note in program.notes)


def test_z_pen_moves_split_the_line(tmp_path: Path) -> None:
    text = "G0 Z5\nG0 X10 Y10\nG1 X20 Y10 Z-1 F300\nG1 X20 Y20 Z-1\nG0 Z2\nG0 X0 Y0\n"
    program = load_for(write(tmp_path, text), "corexy-plotter")
    assert [(op.source.line, op.kind, op.line) for op in program] == [
        (1, OpKind.PEN_UP, "M3"),
        (2, OpKind.MOVE, "G0 X10 Y10"),
        (3, OpKind.PEN_DOWN, "M4"),
        (3, OpKind.MOVE, "G1 X20 Y10 F300"),
        (4, OpKind.MOVE, "G1 X20 Y20"),
        (5, OpKind.PEN_UP, "M3"),
        (5, OpKind.GCODE, "G0"),  # the motion mode changes, so the rest of the line is sent
        (6, OpKind.MOVE, "G0 X0 Y0"),
    ]
    assert program.unsupported == ()
    geometry = ProgramGeometry(program, "X", "Y")
    work = set(zip(geometry.work.x.tolist(), geometry.work.y.tolist(), strict=True))
    travel = set(zip(geometry.travel.x.tolist(), geometry.travel.y.tolist(), strict=True))
    assert {(10.0, 10.0), (20.0, 10.0), (20.0, 20.0)} <= work
    assert (0.0, 0.0) in travel and (0.0, 0.0) not in work


def test_axes_the_machine_lacks(tmp_path: Path) -> None:
    path = write(tmp_path, "G1 X1 Y1 Z-1 F100\nG1 A90\n")
    settings = GcodeSettings(z_is_pen=False)
    program = load_gcode(path, XY, settings, machine_title="XY plotter")
    assert [(p.line, p.reason) for p in program.unsupported] == [
        (1, "the XY plotter has no Z axis"),
        (2, "the XY plotter has no A axis"),
    ]


# --- what a machine executes -----------------------------------------------------------


def test_words_are_compared_normalised(tmp_path: Path) -> None:
    path = write(tmp_path, "G00 X1 Y1\nG01 X2 Y2 F100\nM05\nG20\nG21\nM18\n")
    program = load_for(path, "corexy-plotter")
    assert [(p.line, p.reason) for p in program.unsupported] == [
        (4, "the CoreXY pen plotter cannot execute G20 (error:20)"),
        (6, "the CoreXY pen plotter cannot execute M18 (error:20)"),
    ]
    assert program[2].line == "M05" and program[2].kind is OpKind.GCODE
    assert program[4].kind is OpKind.COMMENT  # G21: not sent


def test_skipping_unsupported_lines(data_dir: Path) -> None:
    program = load_for(real(data_dir, BUNNY), "corexy-plotter", skip_unsupported=True)
    assert program.unsupported == ()
    skipped = [op for op in program if op.source.line in (11, 13, 4304, 4308)]
    assert all(op.kind is OpKind.COMMENT and op.line == "" for op in skipped)
    assert (
        skipped[0].message == "not sent: M18 (the CoreXY pen plotter cannot execute M18 (error:20))"
    )
    assert any(
        "skipped 2 line(s): the CoreXY pen plotter cannot execute M18 (error:20) (lines 11, 4308)"
        in note
        for note in program.notes
    )


def test_one_skipped_line_is_named_as_one(tmp_path: Path) -> None:
    """Not "(lines 2)" for a single line."""
    path = write(tmp_path, "G1 X1 Y1 F100\nM18\nG1 X2 Y2\n")
    program = load_for(path, "corexy-plotter", skip_unsupported=True)
    expected = "skipped 1 line: the CoreXY pen plotter cannot execute M18 (error:20) (line 2)"
    assert expected in program.notes


def test_skipped_lines_do_not_move_the_model(tmp_path: Path) -> None:
    path = write(tmp_path, "G1 X1 Y1 F100\nG2 X3 Y1 I1 J0\nG91\nG1 X1 Y1\n")
    program = load_for(path, "corexy-plotter", skip_unsupported=True)
    assert program[1].kind is OpKind.COMMENT
    assert program[3].target == {"X": 2.0, "Y": 2.0}  # relative to (1, 1): the arc never ran


def test_long_lines_are_refused(tmp_path: Path) -> None:
    long = "G1 X1.000000000000000000000000000000 Y2.000000000000000000000000000000 F1000.000000"
    program = grbl(write(tmp_path, f"G1 X0 Y0 F1000\n{long}\n"))
    assert [p.line for p in program.unsupported] == [2]
    assert "at most 79" in program.unsupported[0].reason


@pytest.mark.parametrize("line", ["#1=5", "G1 X[1+2]", "O100 SUB", "G65 P9010", "G1 X#1"])
def test_parameters_and_expressions_are_unsupported(tmp_path: Path, line: str) -> None:
    program = grbl(write(tmp_path, f"G0 X0 Y0 F1000\n{line}\nG1 X1 Y1\n"))
    assert [(p.line, p.text, p.reason) for p in program.unsupported] == [
        (2, line, PARAMETER_REASON)
    ]


@pytest.mark.parametrize("line", ["G1 X1..2", "G1 X", "G1 X1 Q", "Hello"])
def test_malformed_lines_refuse_the_file(tmp_path: Path, line: str) -> None:
    with pytest.raises(JobFileError) as caught:
        grbl(write(tmp_path, f"G0 X0 Y0\n\n{line}\n"))
    assert caught.value.line == 3
    assert str(caught.value).startswith("job.gcode:3:")


def test_non_utf8_is_refused_with_its_line(tmp_path: Path) -> None:
    path = tmp_path / "latin.gcode"
    path.write_bytes(b"G0 X0 Y0\n(caf\xe9)\nG1 X1 Y1\n")
    with pytest.raises(JobFileError) as caught:
        grbl(path)
    assert caught.value.line == 2 and "UTF-8" in caught.value.reason


def test_system_commands_and_program_end(tmp_path: Path) -> None:
    path = write(tmp_path, "$H\nG1 X1 Y1 F100\n$X\nM2\nM30\n")
    program = load_for(path, "grbl-plotter")
    assert kinds_and_lines(program)[0] == (OpKind.GCODE, "$H")
    assert [op.kind for op in program][3:] == [OpKind.COMMENT, OpKind.COMMENT]
    assert program.unsupported == ()
    corexy = load_for(path, "corexy-plotter")
    assert [(p.line, p.reason) for p in corexy.unsupported] == [
        (3, "the CoreXY pen plotter cannot execute $X (error:3)")
    ]


# --- the lazy operations and the arrays ------------------------------------------------


def test_operations_are_built_on_access(tmp_path: Path) -> None:
    text = "G21\nG0 X1 Y2\nM3 S1000\nG1 X3 Y4 F600\nG4 P500\nM0 (swap pens)\nM5\n"
    program = grbl(write(tmp_path, text))
    assert len(program) == 7
    assert sum(1 for _ in program) == 7
    move = program[3]
    assert (move.kind, dict(move.target), move.line) == (
        OpKind.MOVE,
        {"X": 3, "Y": 4},
        "G1 X3 Y4 F600",
    )
    assert str(move.source) == "job.gcode:4"
    assert program[-1].kind is OpKind.PEN_UP and program[-1].line == "M5"
    assert program[5].kind is OpKind.WAIT and program[5].message == "swap pens"
    assert [op.line for op in program.operations[1:3]] == ["G0 X1 Y2", "M3 S1000"]
    with pytest.raises(IndexError):
        program[7]
    assert program.kinds() == {
        OpKind.GCODE,
        OpKind.MOVE,
        OpKind.PEN_DOWN,
        OpKind.PEN_UP,
        OpKind.WAIT,
    }
    assert of_kind(program, OpKind.MOVE) == [1, 3]
    assert program.axes == ("X", "Y")
    assert [index for index, _where, _pen in program.positions()] == [1, 3]
    assert list(program.positions())[1] == (3, {"X": 3.0, "Y": 4.0}, True)


def test_limit_violations_name_the_line(tmp_path: Path) -> None:
    text = "G0 X10 Y10\nG1 X400 Y10 F100\nG0 X260 Y100\nG3 X260 Y199 I0 J49.5\n"
    program = grbl(write(tmp_path, text))
    limits = load_profile("grbl-plotter").travel_limits()
    violations = program.limit_violations(limits)
    assert [(v.index, v.axis) for v in violations] == [(1, "X"), (3, "X")]
    assert violations[0].value == 400 and violations[0].operation.source.line == 2
    assert "job.gcode:2" in str(violations[0])
    # The arc ends inside but bulges beyond X 300 on its way (to 309.5, within the chord error).
    assert violations[1].value == pytest.approx(309.5, abs=0.02)
    assert program.limit_violations({"X": (0, 400), "Y": (0, 300)}) == []


def test_fingerprint_follows_what_is_sent(data_dir: Path) -> None:
    path = real(data_dir, BUNNY)
    a = load_for(path, "corexy-plotter").fingerprint()
    assert a == load_for(path, "corexy-plotter").fingerprint()
    assert a != load_for(path, "grbl-plotter").fingerprint()  # other pen commands


# --- the preview ---------------------------------------------------------------------------


def test_preview_of_bunny_has_work_and_travel(data_dir: Path) -> None:
    program = load_for(real(data_dir, BUNNY), "corexy-plotter")
    geometry = ProgramGeometry(program, "X", "Y")
    assert np.isfinite(geometry.work.x).sum() > 3000
    assert np.isfinite(geometry.travel.x).sum() > 100
    assert len(geometry.markers.x) == 0  # a pen program has no point markers


def test_preview_without_pen_commands(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G0 X0 Y0\nG0 X10 Y0\nG1 X10 Y10 F100\nG0 X20 Y20\n"))
    geometry = ProgramGeometry(program, "X", "Y")
    assert geometry.work.x[np.isfinite(geometry.work.x)].tolist() == [10.0, 10.0]
    assert geometry.work.y[np.isfinite(geometry.work.y)].tolist() == [0.0, 10.0]
    assert (20.0, 20.0) in set(
        zip(geometry.travel.x.tolist(), geometry.travel.y.tolist(), strict=True)
    )
    assert any("no pen commands" in note for note in program.notes)


# --- registry ---------------------------------------------------------------------------------


def test_registered_by_extension_and_content(data_dir: Path, tmp_path: Path) -> None:
    for extension in (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap"):
        assert loader_for(tmp_path / f"x{extension}").__name__ == "load_gcode_job"
    head = real(data_dir, BUNNY).read_text(encoding="utf-8")[:4096]
    assert sniff_gcode(head)
    assert sniff_gcode(real(data_dir, ESCRIBA).read_text(encoding="utf-8")[:4096])
    assert sniff_gcode(real(data_dir, MAKELANGELO).read_text(encoding="utf-8")[:4096])
    assert not sniff_gcode("M48\nINCH,TZ\nT01C0.0315\n%\nT01\nX18350Y22100\n")
    assert not sniff_gcode("1.0, 2.0\n3.0, 4.0\n")
    extensionless = tmp_path / "plot"
    extensionless.write_text(head, encoding="utf-8")
    assert loader_for(extensionless).__name__ == "load_gcode_job"


# --- the estimate -----------------------------------------------------------------------------


def plotter(speed: float = 200.0, acceleration: float = 500.0) -> MachineProfile:
    axes = tuple(
        AxisProfile(name, travel=300.0, max_speed=speed, max_acceleration=acceleration)
        for name in XY
    )
    return MachineProfile("p", "plotter", "gcode", axes, gcode=GcodeSettings())


def test_estimate_single_move_is_a_trapezoid(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G1 X100 F6000\n"))
    # 100 mm/s feed under the 200 mm/s limit; 500 mm/s²: 0.2 s up, 0.2 s down (20 mm),
    # 80 mm cruising in 0.8 s.
    result = estimate_gcode(program, plotter())
    assert result.total_s == pytest.approx(1.2)
    assert result.remaining_after(0) == pytest.approx(1.2)
    assert result.remaining_after(1) == 0.0


def test_estimate_triangle_rapid_and_dwell(tmp_path: Path) -> None:
    text = "G1 X4 F6000\nG4 P0.5\nG0 X104\nG1 Y3 F60\n"  # GRBL: P in seconds
    result = estimate_gcode(grbl(write(tmp_path, text)), plotter())
    short = 2 * math.sqrt(4 / 500)  # never reaches 100 mm/s within 4 mm
    rapid = 100 / 200 + 200 / 500  # at the axis limit: 0.4 s ramps, 60 mm at 200 mm/s
    slow = 3 / 1 + 1 / 500
    steps = np.diff(np.concatenate([[0.0], result.cumulative_s]))
    np.testing.assert_allclose(steps, [short, 0.5, rapid, slow])


@pytest.mark.parametrize(
    ("profile", "seconds"),
    [("grbl-plotter", 150.0), ("corexy-plotter", 0.15), ("string-art", 0.15)],
)
def test_g4_p_is_read_in_the_unit_of_the_machines_firmware(
    tmp_path: Path, profile: str, seconds: float
) -> None:
    """G8-01: GRBL 1.1 reads ``G4 P`` as seconds; the plotters' own firmwares as ms."""
    program = load_for(write(tmp_path, "G4 P150\nG4 S2\n"), profile)
    assert program.data.dwell_s.tolist() == pytest.approx([seconds, 2.0])
    result = estimate(program, load_profile(profile), {}, 0.1)
    assert result.total_s == pytest.approx(seconds + 2.0)


def test_the_unicorn_files_dwells_are_seconds_on_grbl_and_the_operator_is_told(
    data_dir: Path,
) -> None:
    """G8-01: 369 x G4 P150 (meant as ms) wait over 15 hours on a GRBL board."""
    program = load_for(real(data_dir, BUNNY), "grbl-plotter", skip_unsupported=True)
    assert program.data.dwell_s.sum() == pytest.approx(369 * 150)
    assert any("G4 P is seconds" in note and "15 h 22 min" in note for note in program.notes)
    assert not any(
        "G4 P" in note for note in load_for(real(data_dir, BUNNY), "corexy-plotter").notes
    )


def test_estimate_diagonal_is_limited_per_axis(tmp_path: Path) -> None:
    program = grbl(write(tmp_path, "G0 X300 Y300\n"))
    # Each axis at 200 mm/s: the diagonal at 200·√2 mm/s, accelerating at 500·√2 mm/s².
    v, a, s = 200 * math.sqrt(2), 500 * math.sqrt(2), 300 * math.sqrt(2)
    assert estimate_gcode(program, plotter()).total_s == pytest.approx(s / v + v / a)


def test_dry_run_estimate_dispatches_to_gcode(data_dir: Path) -> None:
    profile = load_profile("corexy-plotter")
    program = load_for(real(data_dir, BUNNY), "corexy-plotter")
    result = estimate(program, profile, {}, 0.1)
    assert len(result.cumulative_s) == len(program)
    dwells = 369 * 0.15  # the file's G4 P150 after every pen move
    assert result.total_s > dwells
    assert result.remaining_after(len(program) // 2) < result.total_s


def test_the_plotters_own_bare_value_words_are_sent_as_written(tmp_path: Path) -> None:
    """``M98 <µs>`` and ``M99 <pwm>`` carry a value with no letter (docs/protocols.md §4)."""
    path = write(tmp_path, "M98 800\nM99 90\nG1 X10 Y10 F3000\n")
    program = load_for(path, "corexy-plotter")
    assert [(op.kind, op.line) for op in program] == [
        (OpKind.GCODE, "M98 800"),
        (OpKind.GCODE, "M99 90"),
        (OpKind.MOVE, "G1 X10 Y10 F3000"),
    ]
    assert program.unsupported == ()
    on_grbl = grbl(path)  # GRBL has no M98/M99: refused there, with the line
    assert unsupported_lines(on_grbl) == [1, 2]


@pytest.mark.parametrize(
    "text",
    [
        "G1 X" + "1" * 80 + " Y1\nG2 X2 Y1 I5 J0 F100\n",  # a radius whose chord step rounds to 0
        "G1 X" + "9" * 400 + " Y1\nG2 X2 Y1 I5 J0 F100\n",  # a coordinate beyond any float
    ],
)
def test_absurd_coordinates_before_an_arc_are_refused_or_drawn_never_a_crash(
    tmp_path: Path, text: str
) -> None:
    path = write(tmp_path, text)
    try:
        program = grbl(path)
    except JobFileError as exc:
        # Too large to draw, or (GRBL's own rule) an end that is not on the arc's circle.
        assert exc.line == 2 and ("too large" in exc.reason or "error:33" in exc.reason)
    else:
        # Loaded: the move far outside any travel is what the runner refuses, by line.
        limits = {"X": (0.0, 300.0), "Y": (0.0, 200.0)}
        assert {v.operation.source.line for v in program.limit_violations(limits)} >= {1}


_FUZZ_WORDS = st.sampled_from(
    ["G0", "G1", "G2", "G3", "G4", "G20", "G21", "G90", "G91", "G92", "G28", "M0", "M3", "M5",
     "M4", "M300", "M280", "M98", "M99", "$H", "$$", "#1=", "[", "(c)", ";x", "N10", "*7", "%",
     "X", "Y", "Z", "A", "I", "J", "R", "F", "P", "S", "T", "?", "~", "\t", " "]
)  # fmt: skip
_FUZZ_NUMBERS = st.one_of(
    st.integers(-(10**6), 10**6).map(str),
    st.floats(allow_nan=False, allow_infinity=False, width=32).map(lambda v: f"{v:g}"),
    st.sampled_from(["", "-", ".", "1..2", "1e400", "0.0000001", "-.5"]),
)


@settings(max_examples=300, deadline=None)
@given(
    st.lists(
        st.lists(st.tuples(_FUZZ_WORDS, _FUZZ_NUMBERS), max_size=6).map(
            lambda words: "".join(w + n + " " for w, n in words)
        ),
        min_size=1,
        max_size=12,
    ),
    st.sampled_from(["corexy-plotter", "grbl-plotter", "string-art"]),
    st.booleans(),
)
def test_any_text_loads_or_is_refused_with_a_line_never_a_crash(
    tmp_path_factory: pytest.TempPathFactory, lines: list[str], profile: str, skip: bool
) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "fuzz.gcode"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    machine = load_profile(profile)
    axes = [axis.name for axis in machine.axes]
    try:
        program = load_gcode(
            path, axes, machine.gcode, skip_unsupported=skip, machine_title=machine.title
        )
    except JobFileError as exc:
        assert 0 <= exc.line <= len(lines) and exc.reason
        return
    # Whatever loaded can be previewed, checked and estimated.
    program.preview_path(axes[0], axes[1])
    program.limit_violations(machine.travel_limits())
    estimate(program, machine, {}, 0.1)
    assert all(1 <= problem.line <= len(lines) for problem in program.unsupported)
