"""The hostile-input corpus (tests/helpers/hostile_corpus.py) through ``stepdeck check`` and the
jobs dock.

Each case's outcome is exact: the refusal's ``file:line`` and a word of its
reason, or the number of operations loaded, or the choices the dock asks
between.  The same files go through the command line and through the dock,
so both say the same thing.
"""

from __future__ import annotations

import io
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.cli import check
from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams
from app.jobs.loaders import AmbiguousFormat
from app.jobs.run.runner import JobRunner
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.hostile_corpus import CASES, Asked, Case, Loaded, Refused, materialise
from widgets.jobs.dock import JobsDock

REPO = Path(__file__).resolve().parents[2]


def test_the_corpus_is_large_and_its_names_unique() -> None:
    assert len(CASES) >= 80
    assert len({case.id for case in CASES}) == len(CASES)


def _option(case: Case, flag: str) -> str | None:
    args = list(case.args)
    return args[args.index(flag) + 1] if flag in args else None


def _run_check(path: Path, case: Case) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    status = check.main([str(path), "--profile", case.profile, *case.args], out, err)
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.id)
def test_stepdeck_check(case: Case, tmp_path: Path) -> None:
    path = materialise(case, tmp_path / "job")
    status, out, err = _run_check(path, case)
    assert "\x1b" not in out and "\u202e" not in out  # names escaped, never raw
    assert all(len(line) < 400 for line in out.splitlines())  # a hostile line is quoted cut
    assert "nan…" not in out and "…nan" not in out  # a refusal names the travel, never NaN
    expect = case.expect
    first = out.splitlines()[0] if out else ""
    if isinstance(expect, Refused) and not expect.where:  # a usage error
        assert status == check.USAGE and out == ""
        assert err.startswith("stepdeck check:")
    elif isinstance(expect, Refused):
        assert status == check.REFUSED, out
        prefix = expect.where if expect.where.endswith(":") else f"{expect.where}: "
        assert first.startswith(prefix), first
        assert expect.word in first, first
    elif isinstance(expect, Loaded):
        assert status == check.OK, out
        assert first.endswith(f": {expect.operations} operations"), first
        assert expect.note in out
    else:
        assert isinstance(expect, Asked)
        assert status == check.REFUSED
        assert "which format?" in first and f"(choose one: {'|'.join(expect.choices)})" in first


@pytest.fixture
def docks(qtbot: QtBot, tmp_path: Path) -> Iterator[dict[str, object]]:
    made: dict[str, object] = {}
    yield made
    for harness in made.values():
        assert isinstance(harness, StationHarness)
        harness.close()


@pytest.mark.parametrize(
    "case",
    [c for c in CASES if not (isinstance(c.expect, Refused) and not c.expect.where)],
    ids=lambda c: c.id,
)
def test_the_jobs_dock(case: Case, qtbot: QtBot, tmp_path: Path, docks: dict[str, object]) -> None:
    path = materialise(case, tmp_path / "job")
    harness = StationHarness(load_profile(case.profile))
    docks["harness"] = harness
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    asked: list[tuple[str, ...]] = []
    board_text = _option(case, "--board")

    def ask_board(_needs: NeedsNailCount) -> StringArtParams | None:
        if board_text is None:
            return None
        tvar, nails, radius = board_text.split(",")
        return StringArtParams(int(tvar), int(nails), float(radius))

    def ask_format(ambiguous: AmbiguousFormat) -> str | None:
        asked.append(tuple(t.key for t in ambiguous.choices))
        return _option(case, "--format")

    dock = JobsDock(
        harness.station,
        runner,
        confirm=lambda _t: False,
        throttle_ms=0,
        ask_board=ask_board,
        ask_format=ask_format,
    )
    qtbot.addWidget(dock)
    dock.open_path(path, background=True)  # as the Open dialog and ``stepdeck JOB`` do
    qtbot.waitUntil(lambda: dock._loading is None, timeout=20_000)
    messages = dock.messages.toPlainText()
    assert "\x1b" not in messages and "\u202e" not in messages
    assert "Internal error" not in messages and "not loaded — " not in messages.replace(
        " — not loaded", ""
    ), messages  # no loader crash reached the operator as an exception text
    expect = case.expect
    if isinstance(expect, Loaded):
        assert runner.program is not None and len(runner.program) == expect.operations, messages
        plural = "" if expect.operations == 1 else "s"  # English plural forms, not "(s)"
        assert f"{expect.operations} operation{plural} loaded" in messages
        assert expect.note in messages
    elif isinstance(expect, Refused):
        assert runner.program is None, messages
        prefix = expect.where if expect.where.endswith(":") else f"{expect.where}: "
        line = next((m for m in messages.splitlines() if prefix in m), "")
        assert line and expect.word in line, messages
    else:
        assert isinstance(expect, Asked)
        assert asked == [expect.choices]
        assert runner.program is None and "which format?" in messages


def test_every_line_the_board_would_refuse_is_listed(tmp_path: Path, qtbot: QtBot) -> None:
    """Not only the first: a CI job fixing a generator sees them all, in file order."""
    job = tmp_path / "many.gcode"
    lines = ["G0 X1 Y1", "G1 X2 Y2", "F-5", "G1 X3 Y3 F100", "G2 X9 Y3 I1 J0", "G1 X4 Y4"]
    job.write_text("\n".join(lines) + "\n")
    out = io.StringIO()
    status = check.main([str(job), "--profile", "grbl-plotter"], out, io.StringIO())
    assert status == check.REFUSED
    assert [line.split(": ")[0] for line in out.getvalue().splitlines()] == [
        "many.gcode:2",  # G1 before any feed (error:22)
        "many.gcode:3",  # a negative F (error:4)
        "many.gcode:5",  # an arc whose end is off its circle (error:33)
    ]
    harness = StationHarness(load_profile("grbl-plotter"))
    try:
        dock = JobsDock(harness.station, JobRunner(harness.station, tmp_path / "c"), throttle_ms=0)
        qtbot.addWidget(dock)
        assert not dock.open_path(job)
        text = dock.messages.toPlainText()
        assert "many.gcode:2: feed rate undefined" in text
        assert "  many.gcode:3: negative value" in text and "  many.gcode:5: arc end" in text
    finally:
        harness.close()


def test_check_needs_no_display(tmp_path: Path) -> None:
    """The command line runs where there is no display at all (a CI job)."""
    job = tmp_path / "ok.gcode"
    job.write_text("G0 X1 Y1 F1000\nG1 X10 Y10\n")
    bad = tmp_path / "bad.gcode"
    bad.write_text("G0 X1 Y1\nG1 X10 Y10\n")
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.pop("QT_QPA_PLATFORM", None)
    run = subprocess.run(
        [sys.executable, "-m", "app", "check", str(job), str(bad), "--profile", "grbl-plotter"],
        capture_output=True,
        text=True,
        env=env,
        cwd=REPO,
        timeout=120,
        check=False,
    )
    assert run.returncode == check.REFUSED, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == "ok.gcode: 2 operations"
    assert any(line.startswith("bad.gcode:2: feed rate undefined") for line in lines)
    usage = subprocess.run(
        [sys.executable, "-m", "app", "check", str(job), "--profile", "no-such-machine"],
        capture_output=True,
        text=True,
        env=env,
        cwd=REPO,
        timeout=120,
        check=False,
    )
    assert usage.returncode == check.USAGE and "no-such-machine" in usage.stderr
