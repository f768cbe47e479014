"""Overrides and work zero through the scripting API, against the emulator in its own process
over a pseudo-terminal, judged from the emulator's ``--log`` (its timestamps and positions).

Real time, as a script on a lab computer drives a GRBL plotter: ``override(feed=50)``
returns once the board reports ``Ov:50``, and the log shows the next strokes drawn at
half their speed; ``work.zero()`` makes the pen's place the job's origin, the job draws
there, and a job that would leave the travel from that origin is refused before a byte.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import stepdeck
from tests.helpers.emulator_process import emulator_on_pty

PROFILE = ("--profile", "grbl-plotter")


def moves(log: Path) -> list[dict[str, object]]:
    events = [json.loads(line) for line in log.read_text(encoding="utf-8").splitlines()]
    return [e for e in events if e["event"] == "move"]


def test_feed_50_halves_the_speed_in_the_emulators_log(qapp: object, tmp_path: Path) -> None:
    log = tmp_path / "board.log"
    job = tmp_path / "strokes.gcode"
    # Two 6 mm strokes in line at F600 (10 mm/s): the second runs at its cruise speed.
    job.write_text("G1 X6 F600\nG1 X12\nG1 X18\n", encoding="ascii")
    with emulator_on_pty(*PROFILE, "--log", str(log)) as path:
        machine = stepdeck.connect("grbl-plotter", port=path)
        try:
            machine.run(job)
            assert machine.override(feed=50) == (50, 100)
            machine.move_to(X=0)
            machine.run(job)
            with pytest.raises(stepdeck.MotionRefused, match="outside 10…200"):
                machine.override(feed=250)
        finally:
            machine.close()
    done = [(float(str(m["t"])), m["pos"]["X"]) for m in moves(log) if m["kind"] == "G1"]  # type: ignore[index]
    assert [x for _, x in done] == [6.0, 12.0, 18.0, 6.0, 12.0, 18.0]
    full = 6.0 / (done[1][0] - done[0][0])
    half = 6.0 / (done[4][0] - done[3][0])
    assert full == pytest.approx(10.0, rel=0.02)
    assert half == pytest.approx(5.0, rel=0.02)


def test_zero_here_then_a_job_draws_from_there_and_one_past_the_travel_is_refused(
    qapp: object, tmp_path: Path
) -> None:
    log = tmp_path / "board.log"
    job = tmp_path / "square.gcode"
    job.write_text("G1 X10 Y0 F3000\nG1 X10 Y10\nG1 X0 Y10\nG1 X0 Y0\n", encoding="ascii")
    far = tmp_path / "far.gcode"
    far.write_text("G1 X100 Y0 F3000\n", encoding="ascii")
    with emulator_on_pty(*PROFILE, "--log", str(log)) as path:
        machine = stepdeck.connect("grbl-plotter", port=path)
        try:
            machine.move_to(X=30, Y=40)
            assert machine.work.zero() == {"X": 30.0, "Y": 40.0}
            assert machine.work.system == "G54"
            machine.run(job)
            machine.move_to(X=250, Y=40)
            assert machine.work.zero("X") == {"X": 250.0, "Y": 40.0}
            written = len(log.read_text(encoding="utf-8").splitlines())
            with pytest.raises(stepdeck.JobRefused):
                machine.run(far)  # work X100 is machine X350: beyond the 300 mm travel
            lines = [json.loads(x) for x in log.read_text(encoding="utf-8").splitlines()]
            assert not [e for e in lines[written:] if e["event"] == "line"]
            assert machine.work.go_to_zero() == {"X": 250.0, "Y": 40.0}
        finally:
            machine.close()
    corners = [(m["pos"]["X"], m["pos"]["Y"]) for m in moves(log) if m["kind"] == "G1"]  # type: ignore[index]
    assert corners == [(40.0, 40.0), (40.0, 50.0), (30.0, 50.0), (30.0, 40.0)]
