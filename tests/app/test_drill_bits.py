"""Bit changes: one prompt per distinct drill naming tool, diameter and hole count.

Duplicate diameters share a bit and are flagged; a tool without a diameter is
flagged and its holes left out; smallest first reorders the prompts and
still drills every hole once.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from app.jobs.formats.excellon.reader import (
    DrillJob,
    Hole,
    Tool,
    build_drill_program,
    read_drill_file,
)
from app.jobs.program import OpKind, Program, SourceRef


def job_of(tools: list[tuple[str, float, int]]) -> DrillJob:
    """A job with ``count`` holes per (name, diameter, count), each hole on its own line."""
    built_tools: list[Tool] = []
    holes: list[Hole] = []
    line = 20
    for number, (name, diameter, count) in enumerate(tools, start=1):
        built_tools.append(Tool(name, number, diameter, SourceRef("b.drl", number + 2)))
        for k in range(count):
            line += 1
            holes.append(
                Hole(float(number * 10), float(k), name, diameter, SourceRef("b.drl", line))
            )
    return DrillJob(
        name="b",
        path=Path("b.drl"),
        unit="mm",
        number_format=(3, 3),
        zeros="leading suppressed (TZ)",
        format_from="the file",
        tools=tuple(built_tools),
        holes=tuple(holes),
    )


def waits(program: Program) -> list[str]:
    return [op.message for op in program if op.kind is OpKind.WAIT]


def drilled_lines(program: Program) -> Counter[int]:
    return Counter(op.source.line for op in program if op.kind is OpKind.DRILL)


def test_each_bit_is_prompted_with_tool_diameter_and_hole_count_in_file_order() -> None:
    job = job_of([("T01", 1.0, 3), ("T02", 0.8, 34), ("T03", 0.6, 1)])
    program = build_drill_program(job)
    assert waits(program) == [
        "insert T01, 1.00 mm, 3 holes",
        "insert T02, 0.80 mm, 34 holes",
        "insert T03, 0.60 mm, 1 hole",
    ]
    # Each prompt is followed by exactly its tool's holes.
    wait_at = [i for i, op in enumerate(program) if op.kind is OpKind.WAIT]
    assert sum(op.kind is OpKind.DRILL for op in program[wait_at[1] : wait_at[2]]) == 34


def test_smallest_first_orders_the_prompts_and_drills_every_hole_once() -> None:
    job = job_of([("T01", 1.0, 3), ("T02", 0.8, 4), ("T03", 0.6, 2), ("T04", 3.0, 1)])
    program = build_drill_program(job, smallest_first=True)
    assert waits(program) == [
        "insert T03, 0.60 mm, 2 holes",
        "insert T02, 0.80 mm, 4 holes",
        "insert T01, 1.00 mm, 3 holes",
        "insert T04, 3.00 mm, 1 hole",
    ]
    assert drilled_lines(program) == Counter(h.source.line for h in job.holes)
    assert set(drilled_lines(program).values()) == {1}


def test_a_duplicate_diameter_shares_the_first_tools_bit_and_is_flagged() -> None:
    job = job_of([("T01", 0.8, 5), ("T02", 1.0, 2), ("T03", 0.8, 4), ("T04", 0.8, 0)])
    program = build_drill_program(job)
    assert waits(program) == [
        "insert T01, 0.80 mm, 9 holes (also T03)",
        "insert T02, 1.00 mm, 2 holes",
    ]
    assert drilled_lines(program) == Counter(h.source.line for h in job.holes)
    flags = [n for n in program.notes if "like T01" in n]
    assert flags == [
        "b.drl:5: T03 is 0.80 mm like T01: its 4 hole(s) are drilled with T01's bit, no change"
    ]
    # An unused tool of the same size is no mistake: not flagged.
    assert not any("T04" in n for n in program.notes)


def test_a_tool_without_a_diameter_is_flagged_not_prompted_and_its_holes_left_out() -> None:
    job = job_of([("T01", 0.8, 2), ("T02", 0.0, 3)])
    program = build_drill_program(job)
    assert waits(program) == ["insert T01, 0.80 mm, 2 holes"]
    assert "b.drl:4: T02 has no diameter: its 3 hole(s) are not drilled" in "\n".join(program.notes)
    assert sum(drilled_lines(program).values()) == 2


def test_the_sample_board_smallest_first_drills_the_same_holes(data_dir: Path) -> None:
    job = read_drill_file(data_dir / "samples" / "pcb-driver" / "driver")
    plain = build_drill_program(job)
    small = build_drill_program(job, smallest_first=True)
    assert drilled_lines(small) == drilled_lines(plain)
    sizes = [float(m.split(", ")[1].split()[0]) for m in waits(small)]
    assert sizes == sorted(sizes) and len(sizes) >= 2


def test_s2_40_one_bit_for_all_holes_drills_every_hole_without_a_prompt() -> None:
    """FIDELITY S2-40: the original drilled with one bit, "nepocita s vymenou vrtaku"."""
    job = job_of([("T01", 1.0, 3), ("T02", 0.8, 4), ("T03", 0.8, 2), ("T04", 0.0, 2)])
    program = build_drill_program(job, one_bit=True)
    assert waits(program) == []
    # Every hole once, duplicates and the tool without a diameter too: one bit drills all.
    assert drilled_lines(program) == Counter(h.source.line for h in job.holes)
    assert set(drilled_lines(program).values()) == {1}
    assert not any("like T02" in n or "no diameter" in n for n in program.notes)
    # Drawn, no pen prompt either.
    assert waits(build_drill_program(job, mode="draw", one_bit=True)) == []


def test_s2_40_a_profiles_drill_one_bit_reaches_the_loaded_job(
    tmp_path: Path, data_dir: Path
) -> None:
    from app.jobs.loaders import JobOptions, load_job
    from app.profiles import MACHINES_DIR, ProfileError, load_profile

    shipped = (MACHINES_DIR / "pcb-drill.toml").read_text(encoding="utf-8")
    one_bit = tmp_path / "one-bit-drill.toml"
    one_bit.write_text(shipped + "\n[drill]\none_bit = true\n", encoding="utf-8")
    assert not load_profile("pcb-drill").drill_one_bit  # the station's prompts by default
    profile = load_profile(one_bit)
    assert profile.drill_one_bit
    board = data_dir / "samples" / "pcb-driver" / "driver"
    program = load_job(board, ["X", "Y"], JobOptions(one_bit=profile.drill_one_bit))
    assert waits(program) == []
    assert len(waits(load_job(board, ["X", "Y"], JobOptions()))) > 1
    bad = tmp_path / "bad.toml"
    bad.write_text(shipped + "\n[drill]\none_bit = 1\n", encoding="utf-8")
    try:
        load_profile(bad)
    except ProfileError as exc:
        assert "one_bit must be true or false" in str(exc)
    else:
        raise AssertionError("a one_bit that is no truth value was taken")
