"""Excellon drill files from real CAD tools read into the right holes, and refused when broken.

Expected counts, sizes and coordinates were worked out by hand from the files
(``tests/data/realdata/excellon`` and the EAGLE pair in ``tests/data/samples``),
not from the reader: 1/10000 inch with leading zeros suppressed (``TZ``) means
``X18350`` is 1.8350 inch = 46.609 mm.
"""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from app.jobs.formats.excellon.reader import (
    DrillJob,
    build_drill_program,
    plan_drilling,
    read_drill_file,
    sniff_excellon,
)
from app.jobs.loaders import load_job
from app.jobs.program import JobFileError, OpKind

INCH = 25.4


def board(data_dir: Path, name: str) -> Path:
    if name == "driver":
        return data_dir / "samples" / "pcb-driver" / "driver"
    return data_dir / "realdata" / "excellon" / name


# name → unit, {tool: (holes, diameter in mm)}
EXPECTED: dict[str, tuple[str, dict[str, tuple[int, float]]]] = {
    "driver": (
        "inch",
        {
            "T01": (20, 0.0315 * INCH),
            "T02": (6, 0.0320 * INCH),
            "T03": (4, 0.0394 * INCH),
            "T04": (2, 0.0400 * INCH),
            "T05": (4, 0.0630 * INCH),
        },
    ),
    "tracespace_eagle_arduino-uno.drd": (
        "inch",
        {
            "T01": (72, 0.0240 * INCH),
            "T02": (62, 0.0335 * INCH),
            "T03": (20, 0.0374 * INCH),
            "T04": (9, 0.0512 * INCH),
            "T05": (2, 0.0866 * INCH),
            "T06": (4, 0.1260 * INCH),
        },
    ),
    "tracespace_eagle_BusPirate-v3.6a-SSOP.drd": (
        "inch",
        {
            "T01": (80, 0.0200 * INCH),
            "T02": (2, 0.0250 * INCH),
            "T03": (4, 0.0300 * INCH),
            "T04": (2, 0.0354 * INCH),
            "T05": (15, 0.0400 * INCH),
            "T06": (4, 0.1260 * INCH),
        },
    ),
    "tracespace_core.TXT": (
        "inch",
        {"T01": (66, 0.0118 * INCH), "T02": (2, 0.0236 * INCH), "T03": (24, 0.0350 * INCH)},
    ),
    "tracespace_kicad_mchck.drl": (
        "mm",
        {"T01": (32, 0.300), "T02": (40, 1.016), "T03": (1, 3.401)},
    ),
    "pcb2gcode_kicad4_slots_G85.drl": (
        "mm",
        {"T01": (10, 0.400), "T02": (12, 1.001), "T03": (0, 3.000), "T04": (0, 4.000)},
    ),
}

# name → (file line, tool, x mm, y mm), each computed by hand from the line's text
COORDINATES = [
    ("driver", 11, "T01", 1.8350 * INCH, 2.2100 * INCH),  # X18350Y22100
    ("driver", 50, "T05", 0.5000 * INCH, 0.7300 * INCH),  # X5000Y7300
    ("tracespace_eagle_arduino-uno.drd", 14, "T01", 1.6910 * INCH, 1.0810 * INCH),
    ("tracespace_eagle_arduino-uno.drd", 187, "T06", 1.4450 * INCH, 2.9700 * INCH),
    ("tracespace_eagle_BusPirate-v3.6a-SSOP.drd", 13, "T01", 0.7536 * INCH, 0.4995 * INCH),
    ("tracespace_eagle_BusPirate-v3.6a-SSOP.drd", 121, "T06", 2.6434 * INCH, 1.7593 * INCH),
    ("tracespace_core.TXT", 10, "T01", 0.1743 * INCH, 0.1155 * INCH),  # X1743Y1155
    ("tracespace_core.TXT", 77, "T02", 0.6011 * INCH, 1.2928 * INCH),  # X6011Y12928
    ("tracespace_kicad_mchck.drl", 10, "T01", 41.7, -51.7),
    ("tracespace_kicad_mchck.drl", 30, "T01", 55.0, -52.375),  # X55.Y-52.375
    ("tracespace_kicad_mchck.drl", 84, "T03", 64.5, -51.7),
    ("pcb2gcode_kicad4_slots_G85.drl", 15, "T01", 86.36, -72.39),
    ("pcb2gcode_kicad4_slots_G85.drl", 37, "T02", 119.38, -74.93),
]


@pytest.mark.parametrize("name", list(EXPECTED))
def test_every_board_loads_with_its_tools_and_hole_counts(data_dir: Path, name: str) -> None:
    unit, tools = EXPECTED[name]
    job = read_drill_file(board(data_dir, name))
    assert job.unit == unit
    assert job.hole_counts() == {tool: count for tool, (count, _) in tools.items()}
    for tool, (_, diameter) in tools.items():
        assert job.tool(tool).diameter_mm == pytest.approx(diameter, abs=1e-6)
    assert all(hole.diameter_mm == job.tool(hole.tool).diameter_mm for hole in job.holes)


def test_totals_match_sources_md(data_dir: Path) -> None:
    uno = read_drill_file(board(data_dir, "tracespace_eagle_arduino-uno.drd"))
    core = read_drill_file(board(data_dir, "tracespace_core.TXT"))
    assert (len(uno.holes), len(uno.tools)) == (169, 6)
    assert (len(core.holes), len(core.tools)) == (92, 3)


@pytest.mark.parametrize(("name", "line", "tool", "x", "y"), COORDINATES)
def test_coordinates_checked_by_hand(
    data_dir: Path, name: str, line: int, tool: str, x: float, y: float
) -> None:
    job = read_drill_file(board(data_dir, name))
    [hole] = [h for h in job.holes if h.source.line == line]
    assert hole.source.file == board(data_dir, name).name
    assert hole.tool == tool
    assert (hole.x_mm, hole.y_mm) == (pytest.approx(x, abs=1e-6), pytest.approx(y, abs=1e-6))


def test_eagle_pair_takes_units_and_tools_from_the_dri(data_dir: Path) -> None:
    folder = data_dir / "samples" / "pcb-driver"
    from_drill = read_drill_file(folder / "driver")
    from_dri = read_drill_file(folder / "driver.dri")
    assert from_drill.info_file == from_dri.info_file == folder / "driver.dri"
    assert from_dri.path == folder / "driver"
    assert from_dri.holes == from_drill.holes
    assert from_dri.number_format == (2, 4)
    assert "driver.dri" in from_dri.format_from


def test_dri_that_disagrees_with_its_drill_file_is_refused(data_dir: Path, tmp_path: Path) -> None:
    folder = data_dir / "samples" / "pcb-driver"
    (tmp_path / "driver").write_text((folder / "driver").read_text())
    dri = (folder / "driver.dri").read_text().replace("T02   0.0320inch      6", "T02 0.0320inch 7")
    (tmp_path / "driver.dri").write_text(dri)
    with pytest.raises(JobFileError) as caught:
        read_drill_file(tmp_path / "driver.dri")
    assert caught.value.file == "driver.dri"
    assert caught.value.line == 31
    assert "T02 drills 7 holes" in caught.value.reason


def test_g85_slots_are_read_with_both_ends(data_dir: Path) -> None:
    job = read_drill_file(board(data_dir, "pcb2gcode_kicad4_slots_G85.drl"))
    ends = [(s.tool, s.source.line, s.x0_mm, s.y0_mm, s.x1_mm, s.y1_mm) for s in job.slots]
    assert ends == [
        ("T02", 39, 96.901, -65.701, 96.901, -67.7),
        ("T02", 41, 102.599, -63.701, 100.601, -63.701),
        ("T03", 44, 102.599, -69.7, 100.601, -60.7),
    ]


def test_excellon_step_applies_to_a_file_without_format(data_dir: Path) -> None:
    core = board(data_dir, "tracespace_core.TXT")
    job = read_drill_file(core, excellon_step_inch=1e-3)
    first = job.holes[0]
    assert (first.x_mm, first.y_mm) == (pytest.approx(1.743 * INCH), pytest.approx(1.155 * INCH))
    assert "step" in job.format_from
    # a file with its own format line ignores the setting
    uno = read_drill_file(
        board(data_dir, "tracespace_eagle_arduino-uno.drd"), excellon_step_inch=1e-3
    )
    assert uno.holes[0].x_mm == pytest.approx(1.6910 * INCH)


def test_drill_program_waits_for_each_tool_then_moves_and_drills(data_dir: Path) -> None:
    job = read_drill_file(board(data_dir, "pcb2gcode_kicad4_slots_G85.drl"))
    program = build_drill_program(job, mode="drill")
    waits = [op.message for op in program if op.kind is OpKind.WAIT]
    assert waits == [
        "insert T01, 0.40 mm, 10 holes",
        "insert T02, 1.00 mm, 16 holes",  # 12 holes + two slots drilled at their ends
        "insert T03, 3.00 mm, 2 holes",
    ]
    drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]
    assert len(drills) == len(job.holes) + 2 * len(job.slots)
    for index in drills:
        before = program[index - 1]
        assert before.kind is OpKind.MOVE
        assert program[index].source == before.source
    drilled = {
        (round(program[i - 1].target["X"], 6), round(program[i - 1].target["Y"], 6)) for i in drills
    }
    assert {(round(h.x_mm, 6), round(h.y_mm, 6)) for h in job.holes} <= drilled
    assert (102.599, -69.7) in drilled and (100.601, -60.7) in drilled


def test_every_hole_drilled_once_and_ops_keep_their_line(data_dir: Path) -> None:
    job = read_drill_file(board(data_dir, "tracespace_eagle_arduino-uno.drd"))
    program = build_drill_program(job)
    lines = [op.source.line for op in program if op.kind is OpKind.DRILL]
    assert sorted(lines) == sorted(h.source.line for h in job.holes)
    for op in program:
        if op.kind is OpKind.MOVE:
            [hole] = [h for h in job.holes if h.source.line == op.source.line]
            assert dict(op.target) == {"X": hole.x_mm, "Y": hole.y_mm}


def test_cross_mode_draws_a_cross_per_hole(data_dir: Path) -> None:
    job = read_drill_file(board(data_dir, "driver"))
    program = build_drill_program(job, mode="cross")
    assert not any(op.kind is OpKind.DRILL for op in program)
    assert sum(op.kind is OpKind.PEN_DOWN for op in program) == 2 * len(job.holes)
    strokes = [
        (index, where) for index, where, pen_down in program.positions() if pen_down
    ]  # each pen-down move ends a stroke as wide as its hole
    assert len(strokes) == 2 * len(job.holes)


def test_s2_12_draw_mode_puts_the_pen_down_at_each_bits_first_hole_and_draws_along_the_rest(
    data_dir: Path,
) -> None:
    job = read_drill_file(board(data_dir, "driver"))
    plan = plan_drilling(job)
    program = build_drill_program(job, mode="draw")
    assert not any(op.kind is OpKind.DRILL for op in program)
    kinds = [op.kind for op in program if op.kind is not OpKind.MOVE]
    # Per bit: its prompt, Kresli at the first hole, Zvedni after the last.
    assert kinds == [OpKind.WAIT, OpKind.PEN_DOWN, OpKind.PEN_UP] * len(plan.tools)
    # What the pen draws, per bit: where it went down, then where each move took it.
    pen_paths: list[list[tuple[float, float]]] = []
    where: dict[str, float] = {}
    for op in program:
        if op.kind is OpKind.MOVE:
            where.update(op.target)
            if pen_paths and pen_paths[-1][-1:] != [(-1.0, -1.0)]:
                pen_paths[-1].append((where["X"], where["Y"]))
        elif op.kind is OpKind.PEN_DOWN:
            pen_paths.append([(where["X"], where["Y"])])
        elif op.kind is OpKind.PEN_UP:
            pen_paths[-1].append((-1.0, -1.0))  # ended: later moves are travel
    for tool_plan, path in zip(plan.tools, pen_paths, strict=True):
        holes = [(h.x_mm, h.y_mm) for h in tool_plan.holes]
        # From hole to hole an X stroke, then a Y stroke (none where the axis stays).
        expected = [holes[0]]
        for (x0, y0), (x1, y1) in itertools.pairwise(holes):
            expected += [(x1, y0)] if x1 != x0 else []
            expected += [(x1, y1)] if y1 != y0 else []
        assert path == [*expected, (-1.0, -1.0)]


def test_plan_is_never_longer_than_file_order(data_dir: Path) -> None:
    job: DrillJob = read_drill_file(board(data_dir, "driver"))
    plan = plan_drilling(job)
    assert plan.travel_mm <= plan.file_travel_mm
    assert sorted(h.source.line for t in plan.tools for h in t.holes) == sorted(
        h.source.line for h in job.holes
    )


@pytest.mark.parametrize(
    "name",
    ["driver", "driver.dri", "tracespace_core.TXT", "tracespace_kicad_mchck.drl", "uno"],
)
def test_loader_registry_opens_drill_files(data_dir: Path, name: str) -> None:
    path = {
        "driver": board(data_dir, "driver"),
        "driver.dri": board(data_dir, "driver").with_suffix(".dri"),
        "uno": board(data_dir, "tracespace_eagle_arduino-uno.drd"),
    }.get(name, board(data_dir, name))
    program = load_job(path, ("X", "Y", "Z"))
    assert any(op.kind is OpKind.DRILL for op in program)
    assert program.axes == ("X", "Y")


def test_sniffer() -> None:
    assert sniff_excellon("%\nM48\nM72\nT01C0.0315\n")
    assert sniff_excellon("INCH,TZ\n%\nT01C0.02\n")
    assert sniff_excellon("M48\nINCH\n%\nT1\nX100Y100\n")
    assert not sniff_excellon("M48\n%\n")  # a header without a tool is no drill job
    assert not sniff_excellon("1.0, 2.0\n3.0, 4.0\n")


MALFORMED = {
    "unknown tool": ("M48\nINCH,TZ\nT01C0.0315\n%\nT02\nX1000Y1000\nM30\n", 5, "unknown tool"),
    "coordinates before a tool": (
        "M48\nINCH,TZ\nT01C0.0315\n%\nX1000Y1000\nT01\nX2000Y1000\nM30\n",
        5,
        "before any tool",
    ),
    "garbage line": (
        "M48\nINCH,TZ\nT01C0.0315\n%\nT01\nX1000Y1000\nHELLO WORLD\nM30\n",
        7,
        "not an Excellon statement",
    ),
    "bad coordinate": ("M48\nINCH,TZ\nT01C0.0315\n%\nT01\nX12Q5\nM30\n", 6, "not an Excellon"),
    "no holes": ("M48\nINCH,TZ\nT01C0.0315\n%\nM30\n", 0, "no holes"),
    "metric integers without format": (
        "M48\nMETRIC,TZ\nT01C0.8\n%\nT01\nX1000Y1000\nM30\n",
        6,
        "no number format",
    ),
}


@pytest.mark.parametrize("case", list(MALFORMED))
def test_malformed_files_are_refused_with_file_line_and_reason(tmp_path: Path, case: str) -> None:
    text, line, reason = MALFORMED[case]
    path = tmp_path / "bad.drl"
    path.write_text(text)
    with pytest.raises(JobFileError) as caught:
        read_drill_file(path)
    assert (caught.value.file, caught.value.line) == ("bad.drl", line)
    assert reason in caught.value.reason
    with pytest.raises(JobFileError):
        load_job(path, ("X", "Y"))
