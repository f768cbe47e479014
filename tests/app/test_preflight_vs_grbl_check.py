"""The pre-flight refuses only what GRBL refuses, and names GRBL's error (issue 34).

The judge is GRBL 1.1's own verdict on each line (its ``$C`` check mode):
``M8``/``M9`` (coolant) are answered ``ok`` by GRBL 1.1 (G7-04), so a file that
switches a fan with them is not refused on ``grbl-plotter``; a word outside a
machine's repertoire is refused with the code its firmware answers.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from app.jobs.formats.gcode.program import GcodeProgram
from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import JobFileError
from app.profiles import load_profile
from tests.helpers import grbl_sim, grbl_sim_timing
from tests.helpers.grbl_check import check_mode_verdicts


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


# -- GRBL's own verdict: every real file through grbl-sim's $C check mode --------------------

_CODE = re.compile(r"\(error:(\d+)\)$")


@pytest.fixture(scope="module")
def check_sim() -> Path:
    if grbl_sim.compiler() is None:
        pytest.skip("no C compiler and make: grbl-sim cannot be built (.ci/run installs them)")
    return grbl_sim_timing.build(Path(__file__).resolve().parents[1] / "third_party" / "grbl")


REAL_FILES = (
    "CNC-Drawinger_unicorn_BUNNY.gcode",
    "Escriba_gcodetools_calibration.gcode",
    "Makelangelo_polargraph_multi_shapes_path-circle-line-rect.gcode",
)


def _code(reason: str) -> str:
    """``error:N`` as the pre-flight names it for the refused line."""
    found = _CODE.search(reason)
    assert found is not None, reason
    return f"error:{found.group(1)}"


@pytest.mark.parametrize("name", REAL_FILES)
def test_g7_10_the_preflight_agrees_with_grbls_check_mode_on_a_real_file(
    name: str, check_sim: Path, data_dir: Path
) -> None:
    """Whole file: no line GRBL takes is refused, each refusal carries GRBL's code, and
    what the station sends of the file (pen commands translated) GRBL takes."""
    path = data_dir / "realdata" / "gcode" / name
    assert sorted(p.name for p in path.parent.glob("*.gcode")) == sorted(REAL_FILES)
    lines = path.read_text(encoding="ascii", errors="replace").splitlines()
    grbl = check_mode_verdicts(check_sim, lines)
    refused = preflight_refusals(path, "grbl-plotter")
    for number, reason in refused.items():
        code = _CODE.search(reason)
        assert code is not None, reason
        ours, theirs = f"error:{code.group(1)}", grbl[number - 1]
        assert theirs != "ok", f"line {number} refused, GRBL takes it: {lines[number - 1]}"
        assert ours == theirs, f"line {number}: {lines[number - 1]}"
    # What the station sends: translated pen lines, no operator pauses.  GRBL takes all
    # of it; its $ report commands answer error:8 in check mode (not idle), which is the
    # board's state, not the file's.
    machine = load_profile("grbl-plotter")
    options = JobOptions(gcode=machine.gcode, machine_title=machine.title)
    program = load_job(path, [axis.name for axis in machine.axes], options)
    assert isinstance(program, GcodeProgram)
    sent = [text for text in program.data.texts if text]
    verdicts = check_mode_verdicts(check_sim, sent)
    refusals = [
        verdict
        for text, verdict in zip(sent, verdicts, strict=True)
        if verdict != "ok" and not (text.startswith("$") and verdict == "error:8")
    ]
    # The only sent lines GRBL refuses are the ones the pre-flight refused (and the operator
    # was told of): as many, with the same codes but for the one pinned above.
    assert sorted(refusals) == sorted(_code(reason) for reason in refused.values())
    assert len(sent) > 100
