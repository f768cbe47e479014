"""``override`` and ``work`` in the scripting API, on the simulated GRBL plotter.

The asyncio form overrides the speed of a job while it runs (the blocking form would
wait for the job to end first); the emulator's log says how fast each stroke went, on
its own clock.
"""

from __future__ import annotations

import asyncio
import itertools
from pathlib import Path

import pytest

import stepdeck
from protocol.emulator.gcode_firmware import GcodeFirmware


def test_an_override_awaited_beside_a_running_job_slows_its_strokes(
    qapp: object, tmp_path: Path
) -> None:
    job = tmp_path / "strokes.gcode"
    job.write_text("G1 F600\n" + "".join(f"G1 X{x}\n" for x in range(5, 101, 5)), "ascii")

    async def scenario() -> tuple[tuple[int, int], GcodeFirmware]:
        machine = await stepdeck.aio.connect("grbl-plotter", emulator=True, simulated=True)
        try:
            running = asyncio.create_task(machine.run(job))
            while machine.position["X"] < 20.0:
                await asyncio.sleep(0)
            answer = await machine.override(feed=50)
            await running
            emulator = machine.machine.station.emulator
            assert isinstance(emulator, GcodeFirmware)
            return answer, emulator
        finally:
            machine.close()

    answer, emulator = asyncio.run(scenario())
    assert answer == (50, 100)
    strokes = [e for e in emulator.event_log if e["event"] == "move" and e["kind"] == "G1"]
    speeds = [5.0 / (float(b["t"]) - float(a["t"])) for a, b in itertools.pairwise(strokes)]
    assert speeds[1] == pytest.approx(10.0, rel=0.01)  # before: 10 mm/s
    assert speeds[-2] == pytest.approx(5.0, rel=0.01)  # after: half


def test_the_work_api_refuses_on_the_corexy_plotter(qapp: object) -> None:
    machine = stepdeck.connect("corexy-plotter", emulator=True, simulated=True)
    try:
        with pytest.raises(stepdeck.Unsupported, match="no work coordinate systems"):
            machine.work.zero()
        with pytest.raises(stepdeck.Unsupported, match="no feed or rapid override"):
            machine.override(feed=50)
    finally:
        machine.close()


def test_the_work_api_selects_reads_and_goes_to_zero(qapp: object) -> None:
    machine = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        machine.move_to(X=12, Y=7)
        assert machine.work.zero("y") == {"X": 0.0, "Y": 7.0}
        assert machine.work.select("g55") == {"X": 0.0, "Y": 0.0}
        assert machine.work.system == "G55"
        stored = machine.work.read()
        assert stored["G54"][:2] == (0.0, 7.0) and stored["G55"][:2] == (0.0, 0.0)
        assert machine.work.go_to_zero() == {"X": 0.0, "Y": 0.0}
        with pytest.raises(stepdeck.MotionRefused, match="none of G54"):
            machine.work.select("G60")
    finally:
        machine.close()


def test_the_work_system_unknown_at_connect_is_asked_of_the_board(qapp: object) -> None:
    """A board whose banner the station never heard (a native-USB board does not restart
    as its port opens) has not said its system: asking for it asks the board."""
    machine = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        session = machine.station.session
        assert session is not None
        work = session.work  # type: ignore[attr-defined]
        machine.work.select("G56")
        work.system = None  # as if nothing had been heard of it since the port opened
        assert machine.work.system == "G56"
    finally:
        machine.close()
