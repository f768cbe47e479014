"""The pre-flight refuses only what GRBL refuses, and names GRBL's error (issue 34).

The judge is GRBL 1.1's own verdict on each line (its ``$C`` check mode):
``M8``/``M9`` (coolant) are answered ``ok`` by GRBL 1.1 (G7-04), so a file that
switches a fan with them is not refused on ``grbl-plotter``; a word outside a
machine's repertoire is refused with the code its firmware answers.
"""

from __future__ import annotations

from pathlib import Path

from app.jobs.formats.gcode.program import GcodeProgram
from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import JobFileError
from app.profiles import load_profile


def preflight_refusals(path: Path, profile: str) -> dict[int, str]:
    """Line → the station's reasons for refusing it (at load, or the runner's at start)."""
    machine = load_profile(profile)
    options = JobOptions(gcode=machine.gcode, machine_title=machine.title)
    try:
        program = load_job(path, [axis.name for axis in machine.axes], options)
    except JobFileError as refused:
        return {error.line: error.reason for error in (refused, *refused.more)}
    assert isinstance(program, GcodeProgram)
    return {problem.line: problem.reason for problem in program.unsupported}


def test_g7_10_coolant_words_are_taken_on_grbl_as_grbl_takes_them(data_dir: Path) -> None:
    """``M8``/``M9`` in the gcodetools file: GRBL 1.1 answers ok, so nothing is refused."""
    path = data_dir / "realdata" / "gcode" / "Escriba_gcodetools_calibration.gcode"
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[5].startswith("M8") and lines[-1].startswith("M9")
    assert preflight_refusals(path, "grbl-plotter") == {}


def test_g7_10_every_refusal_names_the_error_the_firmware_answers(tmp_path: Path) -> None:
    """GRBL answers an unknown G/M code ``error:20`` and an unknown ``$`` command ``error:3``;
    the emulated firmwares answer the same, and the refusal says which."""
    path = tmp_path / "words.gcode"
    path.write_text("G21\nM7\nM8\n$Q\nG1 X1 F100\n", encoding="ascii")
    grbl = preflight_refusals(path, "grbl-plotter")
    assert set(grbl) == {2, 4}  # GRBL 1.1 has no mist (M7 is a build option), nor a $Q command
    assert grbl[2].endswith("cannot execute M7 (error:20)")
    assert grbl[4].endswith("cannot execute $Q (error:3)")
    corexy = preflight_refusals(path, "corexy-plotter")
    assert corexy[3].endswith("cannot execute M8 (error:20)")  # no coolant pin on that one
