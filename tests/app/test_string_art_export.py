"""Writing string-art jobs back for the SD card and as G-code, and rendering G-code lines."""

from __future__ import annotations

import re
from pathlib import Path
from types import MappingProxyType

import pytest

from app.jobs.formats.string_art.export import export_gcode, export_sd_files
from app.jobs.formats.string_art.program import build_program
from app.jobs.formats.string_art.reader import (
    StringArtJob,
    StringArtParams,
    load_string_art,
    read_string_art,
)
from app.jobs.program import Operation, OpKind, SourceRef, move
from app.jobs.render.gcode import comment, feed_for, format_number, render_operation
from app.profiles import GcodeSettings, load_profile

AT = SourceRef("job.nc", 7)


def sample(data_dir: Path, name: str) -> Path:
    return data_dir / "samples" / f"string-art-{name}"


@pytest.mark.parametrize("name", ["cardioid", "hexagon"])
def test_sd_files_come_out_as_the_samples_are_written(
    data_dir: Path, tmp_path: Path, name: str
) -> None:
    folder = sample(data_dir, name)
    job = read_string_art(folder / "poradi.txt")
    param, poradi = export_sd_files(job, tmp_path / "sd")
    assert (param.name, poradi.name) == ("param.txt", "poradi.txt")
    assert param.read_bytes() == (folder / "param.txt").read_bytes()
    assert poradi.read_bytes() == (folder / "poradi.txt").read_bytes()


@pytest.mark.parametrize("name", ["cardioid", "hexagon"])
def test_export_then_load_gives_back_the_same_job(
    data_dir: Path, tmp_path: Path, name: str
) -> None:
    job = read_string_art(sample(data_dir, name) / "param.txt")
    profile = load_profile("string-art")
    export_sd_files(job, tmp_path)
    again = read_string_art(tmp_path / "param.txt")
    assert again == job
    assert build_program(again, profile).fingerprint() == build_program(job, profile).fingerprint()


def test_a_generator_list_exports_as_a_counted_pair(data_dir: Path, tmp_path: Path) -> None:
    path = data_dir / "realdata" / "stringart" / "threadArt_cat-sequence_160pins.txt"
    job = load_string_art(path, StringArtParams(0, 160, 30.55))
    export_sd_files(job, tmp_path)
    assert (tmp_path / "poradi.txt").read_text().startswith("4001,0,87,9,89,")
    assert "polomer_matrice = 30.55\n" in (tmp_path / "param.txt").read_text()
    assert read_string_art(tmp_path / "poradi.txt") == job


def test_gcode_export(data_dir: Path, tmp_path: Path) -> None:
    profile = load_profile("string-art")
    job = read_string_art(sample(data_dir, "hexagon") / "poradi.txt")
    program = build_program(job, profile)
    path = export_gcode(program, tmp_path / "hexagon.nc", profile)
    raw = path.read_bytes()
    assert raw.endswith(b"\n") and b"\r" not in raw
    lines = raw.split(b"\n")[:-1]
    assert max(len(line) + 1 for line in lines) <= 80  # with its newline
    text = [line.decode("ascii") for line in lines]
    assert sum(line.startswith("M0") for line in text) == 1
    assert "M0 (Insert the nails, tie the thread to nail 0)" in text
    first_move = next(i for i, line in enumerate(text) if line.startswith("G1"))
    assert "G90" in text[:first_move] and all(line.startswith("(") for line in text[:3])
    # Replaying the moves gives the program's positions to the written 3 decimals, with each
    # axis' top speed as the feed: A 75°/s, X 62.5 mm/s, Z 15 mm/s → F4500, F3750, F900.
    feeds = {"A": "4500", "X": "3750", "Z": "900"}
    moves = [line for line in text if line.startswith("G1")]
    expected = [op.target for op in program if op.kind is OpKind.MOVE]
    assert len(moves) == len(expected)
    for line, target in zip(moves, expected, strict=True):
        words = dict(re.findall(r"([AXZF])(-?[\d.]+)", line))
        feed = words.pop("F")
        assert set(words) == set(target)
        for axis, value in words.items():
            assert float(value) == pytest.approx(target[axis], abs=5e-4)
            assert feed == feeds[axis]


def test_render_moves() -> None:
    settings = GcodeSettings()
    op = move(AT, A=12.5, X=-0.0001, Z=3.0)
    assert render_operation(op, settings) == "G0 X0.000 Z3.000 A12.500"
    assert render_operation(op, settings, 4500.0) == "G1 X0.000 Z3.000 A12.500 F4500"
    assert render_operation(op, settings, 937.5, axis_order=("A", "X", "Z")) == (
        "G1 A12.500 X0.000 Z3.000 F937.5"
    )
    assert render_operation(move(AT, Y=-1.23456), settings, 100.25) == "G1 Y-1.235 F100.25"
    assert render_operation(Operation(OpKind.MOVE, AT), settings) is None  # no axes: no line
    with pytest.raises(ValueError, match="no G-code axis word"):
        render_operation(move(AT, X1=3.0), settings)
    with pytest.raises(ValueError, match="must be positive"):
        render_operation(move(AT, X=3.0), settings, 0.0)


def test_render_other_operations() -> None:
    settings = GcodeSettings(pen_up="M3", pen_down="M4")
    assert render_operation(Operation(OpKind.PEN_UP, AT), settings) == "M3"
    assert render_operation(Operation(OpKind.PEN_DOWN, AT), settings) == "M4"
    for kind in (OpKind.WAIT, OpKind.COMMENT):
        # The station handles these itself (asks the operator, shows the text).
        assert render_operation(Operation(kind, AT, message="look", line="M0"), settings) is None
    assert render_operation(Operation(OpKind.GCODE, AT), settings) is None
    assert render_operation(Operation(OpKind.GCODE, AT, line="G4 P250"), settings) == "G4 P250"
    as_written = Operation(OpKind.MOVE, AT, MappingProxyType({"X": 1.0}), line="G1 X1 F300")
    assert render_operation(as_written, settings, 9000.0) == "G1 X1 F300"
    pen = Operation(OpKind.PEN_DOWN, AT, line="M3 S1000")
    assert render_operation(pen, settings) == "M3 S1000"
    with pytest.raises(ValueError, match=r"job.nc:7: G-code has no drill cycle"):
        render_operation(Operation(OpKind.DRILL, AT), settings)


def test_feed_is_the_slowest_axis_top_speed() -> None:
    profile = load_profile("string-art")  # A 75 deg/s, X 62.5 mm/s, Z 15 mm/s
    assert feed_for({"A": 1.0}, profile) == 4500.0
    assert feed_for({"A": 1.0, "X": 2.0}, profile) == 3750.0
    assert feed_for({"X": 1.0, "Z": 2.0}, profile) == 900.0
    assert feed_for({"Q": 1.0}, profile) is None


def test_numbers_and_comments() -> None:
    assert format_number(-0.0004) == "0.000"
    assert format_number(-0.0006) == "-0.001"
    assert format_number(123456.7894) == "123456.789"
    assert comment("tie (nail 0)") == "(tie [nail 0])"
    assert comment("Žlutý kůň") == "(Zluty kun)"  # a translated message keeps its letters
    assert comment("→ ok") == "(? ok)"
    long = comment("x" * 200, prefix="M0 ")
    assert len(long) == 79 and long.startswith("M0 (xxx") and long.endswith("...)")


def test_a_long_unwrapped_angle_still_fits(tmp_path: Path) -> None:
    profile = load_profile("string-art")
    job = StringArtJob(StringArtParams(0, 400, 30.0), tuple([0, 199] * 2000))
    program = build_program(job, profile)
    path = export_gcode(program, tmp_path / "long.nc", profile)
    assert max(len(line) for line in path.read_text().splitlines()) < 80
