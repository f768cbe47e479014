"""G7-09: the emulated GRBL plotter plans as GRBL 1.1 does, and the estimate plans with it.

Every figure is worked out by hand for the GRBL plotter: 80 steps/mm, each
axis at most 100 mm/s and 1000 mm/s², ``$11=0.010`` mm, 15 planner blocks.
A 50 mm move at F3000 (50 mm/s) takes 0.05 s (1.25 mm) to reach speed, the
same to stop, and 47.5 mm at speed: 1.05 s.  The host in these tests counts
characters as the station does, so the planner is kept as full as a real
sender keeps it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import numpy.typing as npt
import pytest

from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.formats.gcode.program import GcodeProgram
from app.jobs.loaders import JobOptions, load_job
from app.profiles import ProfileError, load_profile
from protocol.clock import ManualClock
from protocol.emulator.gcode_firmware import (
    GcodeEvent,
    GcodeFirmware,
    corexy_plotter_config,
    grbl_plotter_config,
)
from protocol.emulator.gcode_machine import GcodeConfig
from protocol.gcode.junctions import (
    junction_speed_sqr,
    lookahead_entries,
    profile,
    profile_seconds,
    replan,
)

CYCLE = 0.005
ACCEL = 1000.0  # mm/s², each axis
ONE_50_MM_MOVE = 50 / 50 + 50 / ACCEL  # 1.05 s at F3000


class Host:
    """A character-counting sender on a manual clock, one control cycle at a time."""

    def __init__(self, config: GcodeConfig | None = None) -> None:
        self.clock = ManualClock(start=0.0)
        self.fw = GcodeFirmware(self.clock, config)
        self._out = bytearray()
        self.fw.set_output(self._out.extend)
        self.cycle()  # the banner
        self._out.clear()
        self._queue: list[bytes] = []
        self._unanswered: list[int] = []

    def cycle(self) -> None:
        self.clock.advance(CYCLE)
        self.fw.run_until(self.clock.now())

    def send(self, *lines: str) -> None:
        self._queue += [line.encode("ascii") + b"\n" for line in lines]
        self._feed()

    def _feed(self) -> None:
        while self._queue and sum(self._unanswered) + len(self._queue[0]) <= 127:
            line = self._queue.pop(0)
            self._unanswered.append(len(line))
            self.fw.receive(line)

    def run(self, seconds: float) -> None:
        for _ in range(round(seconds / CYCLE)):
            self.cycle()
            self._answered()

    def run_until_idle(self, limit: float = 60.0) -> None:
        start = self.clock.now()
        while self._queue or self._unanswered or self.fw.busy or self.fw.state != "Idle":
            assert self.clock.now() - start < limit, f"still {self.fw.state}"
            self.cycle()
            self._answered()

    def _answered(self) -> None:
        text = bytes(self._out).decode("ascii")
        self._out.clear()
        for line in text.splitlines():
            if line.lower() == "ok" or line.lower().startswith("error"):
                self._unanswered.pop(0)
        self._feed()

    def events(self, kind: str) -> list[GcodeEvent]:
        return [e for e in self.fw.event_log if e["event"] == kind]

    def motion_seconds(self, first_line: str) -> float:
        """From the start of the cycle that parsed ``first_line`` to the last move's end."""
        began = next(e["t"] for e in self.events("reply") if e["line"] == first_line)
        return float(self.events("move")[-1]["t"] - began)


def test_g7_09_short_collinear_segments_join_at_full_speed() -> None:
    """100 x 0.5 mm on one line take as long as one 50 mm move: 1.05 s, not 4.47 s."""
    host = Host()
    host.send("G1 F3000")
    host.run_until_idle()
    lines = [f"G1 X{0.5 * (i + 1):.1f}" for i in range(100)]
    host.send(*lines)
    host.run_until_idle()
    assert host.fw.position()["X"] == 50.0
    # Braking from 50 mm/s takes 1.25 mm, and the planner always holds at least 13
    # blocks (6.5 mm) ahead, so no block ever slows down: exactly the single move.
    assert host.motion_seconds(lines[0]) == pytest.approx(ONE_50_MM_MOVE, abs=1e-9)
    rest_to_rest = 100 * 2 * math.sqrt(0.5 / ACCEL)  # what the emulator did before
    assert rest_to_rest == pytest.approx(4.472, abs=1e-3)


def test_g7_09_a_right_angle_is_taken_at_grbls_junction_speed() -> None:
    # The corner's change of direction is (-1, 1)/√2: each axis does 1/√2 of it, so the
    # axes allow 1000·√2 mm/s² across it; sin(90°/2) = √2/2, and GRBL's junction speed²
    # is a·δ·sin/(1 - sin) = 1414.21 · 0.01 · 0.70711 / 0.29289 = 34.142 mm²/s².
    v_sqr = junction_speed_sqr((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (ACCEL,) * 3, 0.010)
    assert v_sqr == pytest.approx(34.142, abs=1e-3)
    assert junction_speed_sqr((1.0, 0.0), (1.0, 0.0), (ACCEL,) * 2, 0.010) >= 1e38  # straight
    assert junction_speed_sqr((1.0, 0.0), (-1.0, 0.0), (ACCEL,) * 2, 0.010) == 0.0  # reversal

    host = Host()
    host.send("G1 F3000")
    host.run_until_idle()
    host.send("G1 X50", "G1 Y50")
    host.run_until_idle()
    # Each leg: 1.25 mm (0.05 s) up to 50 mm/s, down to 5.843 mm/s at the corner over
    # (2500 - 34.142)/2000 = 1.23293 mm (0.044157 s), the remaining 47.51707 mm at speed.
    corner = math.sqrt(34.142)
    leg = 0.05 + (50 - corner) / ACCEL + (50 - 1.25 - (2500 - 34.142) / 2000) / 50
    assert host.motion_seconds("G1 X50") == pytest.approx(2 * leg, abs=1e-6)
    assert 2 * leg == pytest.approx(2.0890, abs=1e-4)  # stopping at the corner: 2.1 s
    assert host.fw.position() == {"X": 50.0, "Y": 50.0, "Z": 0.0}


def test_g7_09_a_hold_mid_polyline_brakes_across_blocks_and_resumes_to_the_exact_end() -> None:
    host = Host()
    host.send("G1 F3000")
    host.run_until_idle()
    host.send(*(f"G1 X{0.5 * (i + 1):.1f}" for i in range(100)))
    host.run(0.5)
    # 0.5 s after the first segment was parsed (at the start of the first of those
    # cycles): 1.25 mm accelerating, then 0.45 s at 50 mm/s: at 23.75 mm, at full speed.
    assert host.fw.position()["X"] == pytest.approx(23.75, abs=1e-9)
    host.fw.receive(b"!")
    host.run(0.025)
    assert host.fw.state == "Hold"
    host.run(0.05)
    # Braking from 50 mm/s at 1000 mm/s² takes 1.25 mm: through two and a half segments.
    held = host.fw.position()["X"]
    assert held == pytest.approx(25.0, abs=1e-9)
    host.run(0.5)
    assert host.fw.position()["X"] == held  # it stays
    host.fw.receive(b"~")
    host.run_until_idle()
    assert host.fw.position() == {"X": 50.0, "Y": 0.0, "Z": 0.0}
    assert [e["pos"]["X"] for e in host.events("move")][-100:] == [
        0.5 * (i + 1) for i in range(100)
    ]


def test_g7_09_a_pen_change_or_a_dwell_stops_the_motion_first() -> None:
    """GRBL empties its planner before M3/M5 and G4: the moves around them start and end at rest."""
    host = Host()
    host.send("G1 F3000")
    host.run_until_idle()
    host.send("G1 X50", "M3 S1000", "G1 X100", "G4 P0.5", "G1 X150")
    host.run_until_idle()
    assert host.motion_seconds("G1 X50") == pytest.approx(3 * ONE_50_MM_MOVE + 0.5, abs=1e-9)


def test_g7_09_the_corexy_plotter_keeps_its_firmwares_timing() -> None:
    """Its firmware steps at one interval from the first step to the last, move by move."""
    host = Host(corexy_plotter_config())
    host.send(*(f"G1 X{i + 1}" for i in range(10)))
    host.run_until_idle()
    assert host.fw.config.junction_deviation is None
    # Each line is parsed at the start of a control cycle (after the previous one's OK)
    # and runs its lead motor's steps at 40 000 steps/s from the first step: X i -> i + 1
    # moves both motors trunc((i + 1) / 0.00245) - trunc(i / 0.00245) steps.
    moves = [e["t"] for e in host.events("move")]
    assert len(moves) == 10
    for i, ended in enumerate(moves):
        steps = math.trunc((i + 1) / 0.00245) - math.trunc(i / 0.00245)
        began = ended - steps / 40_000
        assert began / CYCLE == pytest.approx(round(began / CYCLE), abs=1e-6)
        if i:
            assert began >= moves[i - 1] - 1e-9  # one after the other, never blended


def test_g7_09_settings_11_and_120_change_the_plan() -> None:
    host = Host()
    host.send("$11=0.1", "$120=250", "$121=250", "G1 F3000")
    host.run_until_idle()
    host.send("G1 X50", "G1 Y50")
    host.run_until_idle()
    # Along X the block accelerates at 250 mm/s²; the corner: 250·√2·0.1·√2/2/(1 - √2/2).
    a = 250.0
    v_sqr = a * math.sqrt(2) * 0.1 * (math.sqrt(2) / 2) / (1 - math.sqrt(2) / 2)
    up = 2500 / (2 * a)
    down = (2500 - v_sqr) / (2 * a)
    leg = 50 / a + (50 - math.sqrt(v_sqr)) / a + (50 - up - down) / 50
    assert host.motion_seconds("G1 X50") == pytest.approx(2 * leg, abs=1e-6)


# -- the estimate plans as the emulator does --------------------------------------------------

SMALL_PROGRAM = """G21 G90
G0 X10 Y10
M3 S1000
G1 X30 Y10 F2400
G1 X30 Y25
G2 X40 Y35 I10 J0
G1 X41 Y35.2
G1 X42 Y35.6
G1 X43 Y36.2
M5
G0 X100 Y20
M5
G0 X104 Y22
M3 S1000
G1 X60 Y60 F1200
G1 X10 Y60
M5
G0 X0 Y0
"""


def _loaded(tmp_path: Path, text: str) -> GcodeProgram:
    machine = load_profile("grbl-plotter")
    path = tmp_path / "small.gcode"
    path.write_text(text, encoding="ascii")
    program = load_job(
        path,
        [axis.name for axis in machine.axes],
        JobOptions(gcode=machine.gcode, machine_title=machine.title),
    )
    assert isinstance(program, GcodeProgram)
    return program


def test_g7_09_the_estimate_equals_the_emulators_time_on_a_small_program(tmp_path: Path) -> None:
    program = _loaded(tmp_path, SMALL_PROGRAM)
    machine = load_profile("grbl-plotter")
    # The profile's limits are the emulated board's.
    config = grbl_plotter_config()
    assert [a.max_speed for a in machine.axes] == list(config.rates()[:2])
    assert [a.max_acceleration for a in machine.axes] == list(config.accelerations()[:2])
    assert machine.gcode is not None and machine.gcode.junction_deviation == 0.010
    estimated = estimate_gcode(program, machine).total_s

    host = Host()
    texts = [text for text in program.data.texts if text]
    host.send(*texts)
    host.run_until_idle()
    began = host.events("reply")[0]["t"]
    emulated = host.events("move")[-1]["t"] - began
    assert host.fw.position() == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    # The pen already up, the second M5 changes nothing and stops nothing, on either side.
    assert estimated == pytest.approx(emulated, abs=1e-5)  # the log keeps whole µs
    # Planned at rest between every block the same program takes clearly longer.
    rest = load_profile("corexy-plotter")  # no junction deviation in that profile
    assert rest.gcode is not None and rest.gcode.junction_deviation is None


def test_g7_09_the_whole_file_plan_is_the_block_by_block_plan_with_a_full_planner() -> None:
    """lookahead_entries (numpy, the estimate) against replan (the emulator), block by block."""
    lengths = [0.4, 2.0, 0.3, 0.3, 5.0, 0.2, 0.2, 0.2, 1.0, 0.5, 3.0, 0.1, 0.1, 0.1, 8.0] * 3
    accels = [ACCEL * (1.0 + 0.1 * (i % 3)) for i in range(len(lengths))]
    limits = [0.0] + [((i * 37) % 11) * 40.0 for i in range(1, len(lengths))]
    window = 15
    whole = lookahead_entries(
        *(list_to_array(x) for x in (lengths, accels, limits)), planner_blocks=window
    )
    # Block by block: when block j-1 is under way the planner holds j-1 … j+13.
    entry = 0.0
    for j in range(1, len(lengths)):
        stop = min(j - 1 + window, len(lengths))
        planned = replan(entry, lengths[j - 1 : stop], accels[j - 1 : stop], limits[j - 1 : stop])
        entry = planned[1]
        assert whole[j] == pytest.approx(entry, rel=1e-12, abs=1e-9)
    # And a block's time is its profile's time.
    nominal = [30.0] * len(lengths)
    entries = [math.sqrt(e) for e in whole]
    exits = [*entries[1:], 0.0]
    timed = profile_seconds(*(list_to_array(x) for x in (lengths, entries, exits, nominal, accels)))
    for i, seconds in enumerate(timed):
        phases = profile(lengths[i], entries[i], exits[i], nominal[i], accels[i])
        assert seconds == pytest.approx(sum(p[2] for p in phases), abs=1e-12)
        travelled = sum(v0 * t + 0.5 * a * t * t for v0, a, t in phases)
        assert travelled == pytest.approx(lengths[i], abs=1e-9)


def list_to_array(values: list[float]) -> npt.NDArray[np.float64]:
    return np.array(values, dtype=np.float64)


@pytest.mark.parametrize("value", ["-0.01", '"fast"'])
def test_g7_09_a_profile_junction_deviation_must_be_a_length(tmp_path: Path, value: str) -> None:
    shipped = Path(__file__).resolve().parents[2] / "resources" / "machines" / "grbl-plotter.toml"
    text = shipped.read_text(encoding="utf-8")
    assert "junction_deviation = 0.010" in text
    path = tmp_path / "bad.toml"
    path.write_text(text.replace("junction_deviation = 0.010", f"junction_deviation = {value}"))
    with pytest.raises(ProfileError, match="junction_deviation"):
        load_profile(path)
    path.write_text(text.replace("planner_blocks = 15", "planner_blocks = 1"))
    with pytest.raises(ProfileError, match="planner_blocks"):
        load_profile(path)
