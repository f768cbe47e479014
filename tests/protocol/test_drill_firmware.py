"""The emulated PCB drill against docs/protocols.md §3, driven through encoded commands.

Every duration asserted here is worked out by hand from the defaults: X steps
1.3 ms, Y 1.5 ms and Z 2.5 ms per microstep with no ramps; at power-on the
carriage stands 1200 (X) and 900 (Y) microsteps off the switch edges and the
counters read 0 there; homing runs to the switch, backs off 1 microstep until
it opens, then steps the offset (X 3, Y 86: the original's Nulax/Nulay). A
drill stroke goes 400 + 12 = 412 microsteps down at 2.5 ms (1.03 s) with a 10
ms pause after every second one (2.06 s), waits 0.1 s, comes back 39 full
steps of 2 microsteps per 2.5 ms (0.0975 s) and waits 0.1 s: 3.3875 s; the
drill then hovers 78 microsteps above the bottom, so later strokes take 0.8825
s.
Control cycles are 5 ms; a procedure of duration d started at a cycle
boundary is answered ``D`` at the end of the cycle in which d elapses.
"""

from __future__ import annotations

import math

import pytest

from protocol.clock import ManualClock
from protocol.drill.codec import (
    DRILL,
    HOME,
    PARK,
    PEN_DOWN,
    PEN_UP,
    Command,
    Rejected,
    Reply,
    ReplyDecoder,
    ReplyKind,
    encode_command,
    move_x,
    move_y,
)
from protocol.emulator.drill_firmware import (
    CommandDone,
    DrillConfig,
    DrilledHole,
    DrillFirmware,
    ExecutedCommand,
    HomedAtPowerOn,
    PenEvent,
    StalledAtFrame,
    event_log_line,
)

START = 100.0
CYCLE = 0.005
HOME_SECONDS = (1200 + 1 + 3) * 0.0013 + (900 + 1 + 86) * 0.0015  # 1.5652 + 1.4805
DRILL_SECONDS = 412 * 0.0025 + 206 * 0.010 + 0.1 + 39 * 0.0025 + 0.1  # 3.3875
LATER_DRILL_SECONDS = 78 * 0.0025 + 39 * 0.010 + 0.1 + 39 * 0.0025 + 0.1  # 0.8825

Timed = tuple[float, Reply]


def received(letter: str) -> Reply:
    return Reply(ReplyKind.RECEIVED, letter)


def done(letter: str) -> Reply:
    return Reply(ReplyKind.DONE, letter)


def end_of_cycle(seconds: float) -> float:
    """When the ``D`` of a procedure of ``seconds`` started at a cycle boundary goes out."""
    return math.ceil(seconds / CYCLE - 1e-6) * CYCLE


class Bench:
    """The host's side of the wire, on a manual clock one control cycle at a time."""

    def __init__(self, config: DrillConfig | None = None) -> None:
        # A start far from 0 catches code that confuses absolute and elapsed time.
        self.clock = ManualClock(start=START)
        # Most tests drive the procedures from power-on, so by default it does not home itself.
        self.fw = DrillFirmware(self.clock, config or DrillConfig(home_at_power_on=False))
        self._out = bytearray()
        self.fw.set_output(self._out.extend)
        self._decoder = ReplyDecoder()
        self.replies: list[Timed] = []

    @property
    def elapsed(self) -> float:
        return self.clock.now() - START

    def send(self, *commands: Command) -> None:
        self.fw.receive(b"".join(encode_command(c) for c in commands))

    def send_raw(self, data: bytes) -> None:
        self.fw.receive(data)

    def run(self, seconds: float) -> list[Timed]:
        """Run whole cycles for ``seconds``; the replies that came, stamped with elapsed time."""
        got: list[Timed] = []
        for _ in range(round(seconds / CYCLE)):
            self.clock.advance(CYCLE)
            self.fw.run_until(self.clock.now())
            if self._out:
                for reply in self._decoder.feed(bytes(self._out)):
                    assert isinstance(reply, Reply), reply
                    got.append((round(self.elapsed, 6), reply))
                self._out.clear()
        self.replies += got
        return got

    def run_until_done(self, limit: float = 60.0) -> list[Timed]:
        got: list[Timed] = []
        while self.fw.busy:
            assert self.elapsed < limit, "the procedure never finished"
            got += self.run(CYCLE)
        return got

    def home(self) -> None:
        self.send(HOME)
        self.run_until_done()
        assert self.fw.positions == (0, 0, 0)


def test_receipt_comes_in_the_first_cycle_and_done_after_the_move() -> None:
    bench = Bench()
    bench.send(move_x(1000))
    assert bench.run(CYCLE) == [(0.005, received("X"))]
    replies = bench.run(2.0)
    # 1000 microsteps at 1.3 ms: 1.3 s from the start of the first cycle.
    assert replies == [(pytest.approx(1.3, abs=CYCLE), done("X"))]
    assert replies[0][0] == 1.3
    assert bench.fw.positions == (1000, 0, 0)


def test_y_moves_at_its_own_period_and_back_down() -> None:
    bench = Bench()
    bench.send(move_y(200))
    bench.run_until_done()
    bench.send(move_y(100))
    replies = bench.run_until_done()
    # 200 * 1.5 ms = 0.3 s up, then 100 * 1.5 ms = 0.15 s back from 0.3.
    assert replies[-1] == (0.45, done("Y"))
    assert bench.fw.positions == (0, 100, 0)


def test_a_move_to_where_the_axis_is_is_done_at_once() -> None:
    bench = Bench()
    bench.send(move_x(0))
    assert bench.run(CYCLE) == [(0.005, received("X")), (0.005, done("X"))]


def test_homing_runs_x_then_y_to_the_switches_and_on_to_the_offsets() -> None:
    bench = Bench()
    bench.send(HOME)
    # X first: while X seeks its switch Y has not moved.
    bench.run(1.0)
    x, y, _ = bench.fw.positions
    assert x == round(-1.0 / 0.0013) and y == 0  # 1.0 s of X: -769 microsteps
    assert not bench.fw.homed
    replies = bench.run(3.0)
    assert replies == [(round(end_of_cycle(HOME_SECONDS), 6), done("N"))]
    assert replies[0][0] == 3.05  # 3.0457 s, answered at the end of its cycle
    assert bench.fw.positions == (0, 0, 0)
    assert bench.fw.homed and bench.fw.motors_on
    # The zero lies offset + 1 microsteps off each switch edge: the mechanisms show it.
    x_axis, y_axis, _ = bench.fw.axes
    assert not x_axis.end_switch_low and not y_axis.end_switch_low


def test_s2_18_the_zero_lies_nulax_3_and_nulay_86_microsteps_off_the_switches() -> None:
    """The original's ``Const Nulax = 3`` / ``Const Nulay = 86``: N steps them off the switches."""
    assert DrillConfig().zero_offsets == (3, 86)
    bench = Bench()
    bench.home()
    # From the zero, N runs back to each switch (offset + 1 microsteps, the switch's
    # hysteresis), off it (1) and the offset out again: X 8 microsteps, Y 174.
    t0 = bench.elapsed
    bench.send(HOME)
    replies = bench.run_until_done()
    took = (3 + 1 + 1 + 3) * 0.0013 + (86 + 1 + 1 + 86) * 0.0015  # 0.2714 s
    assert replies[-1] == (round(t0 + end_of_cycle(took), 6), done("N"))


def test_after_homing_the_far_ends_of_the_travel_are_the_frame() -> None:
    """FIDELITY S2-27: X 4200 and Y 3000 microsteps, 212 by 152 mm, hold an A5 board;
    S2-29: the far ends are the frame, not switches (one sensor per axis, at home)."""
    bench = Bench()
    bench.home()
    bench.send(move_x(4200), move_y(3000))
    bench.run_until_done()
    assert bench.fw.positions == (4200, 3000, 0)
    assert 4200 / 19.8 >= 210.0 and 3000 / 19.7 >= 148.0
    assert not [e for e in bench.fw.event_log if isinstance(e, StalledAtFrame)]


def test_s2_29_past_the_far_end_the_carriage_stalls_at_the_frame_and_loses_steps() -> None:
    """ "Kazdy pohyb je ukoncen v jednom smeru cidlem": one sensor per axis, at the home end.

    ``X5000`` used to be clamped at 4200 and answered as if a switch stood there.  The
    firmware has no soft limits: it makes all 5000 steps' periods, the carriage stands
    at the frame for the last 800, and the counter says 5000.
    """
    bench = Bench()
    bench.home()
    t0 = bench.elapsed
    bench.send(move_x(5000))
    replies = bench.run_until_done()
    assert replies[-1] == (round(t0 + end_of_cycle(5000 * 0.0013), 6), done("X"))
    assert bench.fw.positions == (5000, 0, 0)  # the counter: every step counted
    x_axis = bench.fw.axes[0]
    assert x_axis.physical_um == 4200 + 3 + 1  # the carriage: at the frame
    (stall,) = [e for e in bench.fw.event_log if isinstance(e, StalledAtFrame)]
    assert (stall.axis, stall.end, stall.lost, stall.counter) == ("X", "far", 800, 5000)
    assert "stalled X at the far frame: 800 steps lost" in event_log_line(stall)
    # The steps lost make the counter lie: "X0" runs the carriage back 5000 steps, so it
    # meets the home end's stop after 4204 (796 = 800 lost - the 3 + 1 from the sensor's
    # edge to the zero), and N finds the zero again.
    bench.send(move_x(0))
    bench.run_until_done()
    assert x_axis.physical_um == 0.0
    stalls = [e for e in bench.fw.event_log if isinstance(e, StalledAtFrame)]
    assert (stalls[-1].end, stalls[-1].lost) == ("home", 796)
    bench.home()
    bench.send(move_x(1000))
    bench.run_until_done()
    assert x_axis.physical_um == 1000 + 3 + 1


def test_drilling_logs_one_hole_at_the_present_position_and_takes_the_stroke_time() -> None:
    """FIDELITY S2-22/S2-23: the first V from the top is the long one, later ones are short."""
    bench = Bench()
    bench.home()
    bench.send(move_x(1234), move_y(567))
    bench.run_until_done()
    t0 = bench.elapsed
    bench.send(DRILL)
    bench.run(3.08)  # 412 microsteps at 2.5 ms and 205 pauses of 10 ms: at the bottom
    assert bench.fw.positions == (1234, 567, 412)
    assert [h.position for h in bench.fw.drill_log] == [(1234, 567)]
    replies = bench.run(1.0)
    assert replies == [(round(t0 + end_of_cycle(DRILL_SECONDS), 6), done("V"))]
    # 39 full steps of 2 microsteps up: the drill hovers 78 microsteps above the bottom.
    assert bench.fw.positions == (1234, 567, 412 - 78)
    hole = bench.fw.drill_log[0]
    assert hole.time == pytest.approx(START + t0 + 412 * 0.0025 + 205 * 0.010)
    t1 = bench.elapsed
    bench.send(DRILL)
    replies = bench.run(1.0)
    assert replies[-1] == (round(t1 + end_of_cycle(LATER_DRILL_SECONDS), 6), done("V"))
    assert bench.fw.positions == (1234, 567, 334)


def test_each_v_drills_exactly_one_hole() -> None:
    bench = Bench()
    bench.home()
    bench.send(move_x(100), DRILL, move_x(200), move_y(50), DRILL)
    bench.run_until_done()
    assert [h.position for h in bench.fw.drill_log] == [(100, 0), (200, 50)]


def test_the_drill_depth_follows_the_sensor_setting() -> None:
    bench = Bench(DrillConfig(sensor_depth=100, dwell=0.0, after_wait=0.0, home_at_power_on=False))
    bench.send(DRILL)
    replies = bench.run(2.0)
    # 112 microsteps at 2.5 ms down (0.28 s) with 56 pauses (0.56 s), no waits, 39 full
    # steps up (0.0975 s): 0.9375 s, answered at the end of its cycle.
    assert replies == [(0.005, received("V")), (0.94, done("V"))]
    assert bench.fw.positions[2] == 112 - 78


def test_s2_24_kresli_and_zvedni_are_the_two_halves_of_the_drill_stroke() -> None:
    bench = Bench()
    bench.home()
    bench.send(move_x(40))
    bench.run_until_done()
    t0 = bench.elapsed
    bench.send(PEN_DOWN)
    replies = bench.run_until_done()
    # Vrtat's way down from the top: 412 microsteps at 2.5 ms, 206 pauses of 10 ms, 0.1 s.
    first_down = 412 * 0.0025 + 206 * 0.010 + 0.1  # 3.19 s
    assert replies == [
        (round(t0 + 0.005, 6), received("K")),
        (round(t0 + end_of_cycle(first_down), 6), done("K")),
    ]
    assert bench.fw.positions == (40, 0, 412)  # where the drill makes its hole
    assert bench.fw.pen_down and not bench.fw.drill_log
    t1 = bench.elapsed
    bench.send(PEN_UP)
    replies = bench.run_until_done()
    up = 39 * 0.0025 + 0.1  # its way back: 0.1975 s
    assert replies[-1] == (round(t1 + end_of_cycle(up), 6), done("Z"))
    assert bench.fw.positions == (40, 0, 412 - 78)  # hovering, as after a V
    # From the hover the pen comes down as a later V does: K + Z take one V.
    t2 = bench.elapsed
    bench.send(PEN_DOWN)
    replies = bench.run_until_done()
    later_down = 78 * 0.0025 + 39 * 0.010 + 0.1  # 0.685 s
    assert replies[-1] == (round(t2 + end_of_cycle(later_down), 6), done("K"))
    assert later_down + up == pytest.approx(LATER_DRILL_SECONDS)
    assert [(e.down, e.x, e.y) for e in bench.fw.pen_log] == [
        (True, 40, 0),
        (False, 40, 0),
        (True, 40, 0),
    ]


def test_s2_12_while_the_pen_is_down_the_following_coordinates_are_drawn() -> None:
    bench = Bench()
    bench.home()
    bench.send(move_x(100), move_y(50))  # pen up: travel, nothing drawn
    bench.run_until_done()
    assert not bench.fw.drawing
    bench.send(PEN_DOWN, move_x(300), move_y(250), move_x(100), PEN_UP)
    bench.run_until_done()
    # Each coordinate a stroke from where the pen stood: one axis at a time, X first.
    assert [(s.x0, s.y0, s.x1, s.y1) for s in bench.fw.drawing] == [
        (100, 50, 300, 50),
        (300, 50, 300, 250),
        (300, 250, 100, 250),
    ]
    bench.send(move_x(0), move_y(0))  # Zvedni ended the drawing
    bench.run_until_done()
    assert len(bench.fw.drawing) == 3
    assert "drawn X100 Y50 to X300 Y50" in event_log_line(bench.fw.drawing[0])


def test_park_runs_to_the_back_and_switches_the_motors_off() -> None:
    bench = Bench()
    bench.home()
    bench.send(move_x(1000), move_y(1000))
    bench.run_until_done()
    t0 = bench.elapsed
    bench.send(PARK)
    replies = bench.run_until_done()
    # X 1000 -> 0 at 1.3 ms (1.3 s), then Y 1000 -> 3000 at 1.5 ms (3.0 s).
    assert replies[-1] == (round(t0 + 4.3, 6), done("P"))
    assert bench.fw.positions == (0, 3000, 0)
    assert not bench.fw.motors_on


def test_motion_after_park_switches_the_motors_on_again() -> None:
    bench = Bench()
    bench.send(PARK)
    bench.run_until_done()
    assert not bench.fw.motors_on
    bench.send(move_x(10))
    bench.run_until_done()
    assert bench.fw.motors_on


@pytest.mark.parametrize(
    ("line", "answer"),
    [
        (b"Q\r", b"EQ\r\n"),
        (b"X\r", b"EX\r\n"),
        (b"Xabc\r", b"EX\r\n"),
        (b"X-5\r", b"EX\r\n"),
        (b"7\r", b"E?\r\n"),
    ],
)
def test_malformed_lines_are_answered_e_at_once_and_change_nothing(
    line: bytes, answer: bytes
) -> None:
    clock = ManualClock(start=START)
    fw = DrillFirmware(clock, DrillConfig(home_at_power_on=False))
    out = bytearray()
    fw.set_output(out.extend)
    fw.receive(line)
    clock.advance(CYCLE)
    fw.run_until(clock.now())
    assert bytes(out) == answer
    assert fw.positions == (0, 0, 0) and not fw.busy and fw.rejected == 1
    assert fw.command_log == (ExecutedCommand(START, fw.command_log[0].command, False),)
    assert isinstance(fw.command_log[0].command, Rejected)


def test_an_empty_line_is_ignored() -> None:
    bench = Bench()
    bench.send_raw(b"\r\r\n")
    assert bench.run(0.1) == []
    assert bench.fw.rejected == 0


def test_a_command_during_another_is_queued_and_done_in_order() -> None:
    bench = Bench()
    bench.send(move_x(100))  # 0.13 s
    bench.run(0.05)
    bench.send(move_y(100))  # 0.15 s, starting when X is done
    bench.run(0.05)
    bench.send_raw(b"Q\r")  # refused at once, whatever is running
    bench.run_until_done()
    assert bench.replies == [
        (0.005, received("X")),
        (0.055, received("Y")),
        (0.105, Reply(ReplyKind.ERROR, "Q")),
        (0.13, done("X")),
        (0.28, done("Y")),
    ]
    assert bench.fw.positions == (100, 100, 0)


def test_a_burst_of_commands_runs_back_to_back_with_exact_durations() -> None:
    bench = Bench()
    bench.send(move_x(10), move_y(10), move_x(0))
    replies = bench.run(0.1)
    # 13 ms, then 15 ms, then 13 ms: the steps end mid-cycle and the next starts at once.
    assert [t for t, r in replies if r.kind is ReplyKind.DONE] == [0.015, 0.03, 0.045]


def test_the_event_log_tells_the_whole_story_in_order() -> None:
    bench = Bench()
    bench.send(move_x(20), DRILL, PEN_DOWN)
    bench.send_raw(b"Q\r")
    bench.run_until_done()
    events = bench.fw.event_log
    kinds = [type(e).__name__ for e in events]
    assert kinds == [
        "ExecutedCommand",
        "ExecutedCommand",
        "ExecutedCommand",
        "ExecutedCommand",
        "CommandDone",
        "DrilledHole",
        "CommandDone",
        "PenEvent",
        "CommandDone",
    ]
    hole = events[5]
    assert isinstance(hole, DrilledHole)
    assert event_log_line(hole) == f"{hole.time:.6f} hole X20 Y0"
    assert event_log_line(events[0]) == f"{START:.6f} received X20"
    assert event_log_line(events[3]) == f"{START:.6f} refused b'Q\\r'"
    first_done = events[4]
    assert isinstance(first_done, CommandDone)
    assert first_done.time == pytest.approx(START + 0.026)
    assert event_log_line(first_done) == f"{START + 0.026:.6f} done X20"
    pen = events[7]
    assert isinstance(pen, PenEvent) and pen.down
    assert event_log_line(pen).endswith("pen down X20 Y0")


def test_a_long_leap_of_time_gives_the_same_result_as_small_steps() -> None:
    clock = ManualClock(start=START)
    fw = DrillFirmware(clock, DrillConfig(home_at_power_on=False))
    out = bytearray()
    fw.set_output(out.extend)
    fw.receive(b"N\rX1234\rY567\rV\rP\r")
    clock.advance(20.0)
    fw.run_until(clock.now())
    assert bytes(out) == b"RN\r\nRX\r\nRY\r\nRV\r\nRP\r\nDN\r\nDX\r\nDY\r\nDV\r\nDP\r\n"
    assert fw.positions == (0, 3000, 412 - 78)
    assert [h.position for h in fw.drill_log] == [(1234, 567)]


@pytest.mark.parametrize(
    "config",
    [
        {"travel": (0, 3000)},
        {"step_periods": (0.0013, 0.0, 0.0025)},
        {"zero_offsets": (-1, 40)},
        {"power_on": (5000, 900)},
        {"sensor_depth": 0},
        {"control_cycle": 0.0},
    ],
)
def test_nonsense_configurations_are_refused(config: dict[str, object]) -> None:
    with pytest.raises(ValueError):
        DrillConfig(**config)  # type: ignore[arg-type]


def test_the_firmware_homes_at_power_on_and_queues_what_comes_meanwhile() -> None:
    """FIDELITY S2-19: Nula is the first procedure after the MCU starts."""
    bench = Bench(DrillConfig())
    assert not bench.fw.homed and bench.fw.busy
    bench.send(move_x(100))
    replies = bench.run(HOME_SECONDS + 0.2)
    # The X was received at once and runs after the homing, which says nothing itself.
    assert replies[0] == (0.005, received("X"))
    assert replies[1] == (end_of_cycle(HOME_SECONDS + 100 * 0.0013), done("X"))
    assert bench.fw.homed and bench.fw.positions == (100, 0, 0)
    homed = [e for e in bench.fw.event_log if isinstance(e, HomedAtPowerOn)]
    assert len(homed) == 1 and homed[0].time == pytest.approx(START + HOME_SECONDS)
    assert event_log_line(homed[0]).endswith("homed at power-on")
