"""The emulated G-code boards against docs/protocols.md §4, driven through encoded lines.

Every duration is worked out by hand.  The GRBL plotter has 80 steps/mm,
motors of at most 8000 steps/s and 80 000 steps/s² (100 mm/s, 1000 mm/s²); a
move alone starts and ends at rest: ``G1 X100 F3000`` is 0.05 s (1.25 mm) up
to 50 mm/s, 1.95 s at speed, 0.05 s down, 2.05 s in all.  Moves that follow
each other join at speed as GRBL plans them (G7-09, ``test_junction_planner.py``).
Control cycles are 5 ms; a line sent between cycles is parsed, answered and
started at the start of the next cycle, and its reply goes out at that
cycle's end.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.profiles import load_profile
from protocol.clock import ManualClock
from protocol.emulator import servo_pwm
from protocol.emulator.gcode_firmware import (
    GcodeConfig,
    GcodeEvent,
    GcodeFirmware,
    corexy_plotter_config,
    event_log_line,
    grbl_plotter_config,
    string_art_config,
)
from protocol.emulator.gcode_machine import STRING_ART_BOARD_RADIUS_MM
from protocol.gcode import (
    AlarmReply,
    Banner,
    ErrorReply,
    Feedback,
    GcodeReply,
    LineStreamer,
    Ok,
    Rejected,
    StatusReport,
    StreamMode,
    encode_line,
    make_decoder,
)
from protocol.gcode.codec import GRBL_BANNER, PLOTTER_BANNER

START = 100.0
CYCLE = 0.005
MM_PER_STEP = 0.00245
X100_SECONDS = 2.05  # G1 X100 F3000 on the GRBL plotter, see above

Timed = tuple[float, GcodeReply]


class Bench:
    """The host's side of the wire on a manual clock, one control cycle at a time."""

    def __init__(self, config: GcodeConfig | None = None) -> None:
        # A start far from 0 catches code that confuses absolute and elapsed time.
        self.clock = ManualClock(start=START)
        self.fw = GcodeFirmware(self.clock, config)
        self._out = bytearray()
        self.fw.set_output(self._out.extend)
        self._decoder = make_decoder()
        banner = self.run(CYCLE)
        assert banner == [(CYCLE, Banner(self.fw.config.banner))]

    @property
    def elapsed(self) -> float:
        return round(self.clock.now() - START, 9)

    def send(self, *lines: str) -> None:
        self.fw.receive(b"".join(encode_line(line) for line in lines))

    def run(self, seconds: float) -> list[Timed]:
        """Run whole cycles for ``seconds``; the replies that came, stamped with elapsed time."""
        got: list[Timed] = []
        for _ in range(round(seconds / CYCLE)):
            self.clock.advance(CYCLE)
            self.fw.run_until(self.clock.now())
            if self._out:
                for reply in self._decoder.feed(bytes(self._out)):
                    assert not isinstance(reply, Rejected), reply
                    got.append((round(self.elapsed, 6), reply))
                self._out.clear()
        return got

    def replies(self, seconds: float = CYCLE) -> list[GcodeReply]:
        return [reply for _, reply in self.run(seconds)]

    def run_until_idle(self, limit: float = 120.0) -> list[GcodeReply]:
        got: list[GcodeReply] = []
        start = self.elapsed
        while self.fw.busy or self.fw.state in ("Run", "Hold", "Home"):
            assert self.elapsed - start < limit, f"still {self.fw.state} after {limit} s"
            got += self.replies()
        return got

    def do(self, *lines: str) -> list[GcodeReply]:
        """Send lines, run until the machine is idle again; every reply."""
        self.send(*lines)
        return self.run_until_idle()

    def status(self) -> StatusReport:
        self.fw.receive(b"?")
        reports = [r for r in self.replies() if isinstance(r, StatusReport)]
        assert len(reports) == 1
        return reports[0]

    def events(self, kind: str) -> list[GcodeEvent]:
        return [e for e in self.fw.event_log if e["event"] == kind]


def corexy_counts(x: float, y: float) -> tuple[int, int]:
    """Motor a = x - y, b = x + y, of each axis' whole steps (truncated, FIDELITY S1-03)."""
    sx, sy = math.trunc(x / MM_PER_STEP), math.trunc(y / MM_PER_STEP)
    return sx - sy, sx + sy


# -- kinematics ------------------------------------------------------------------------------


def test_corexy_square_moves_the_motors_a_x_minus_y_and_b_x_plus_y() -> None:
    bench = Bench(corexy_plotter_config())
    assert bench.fw.motor_counts() == (0, 0, 0)
    for x, y in ((100, 0), (100, 100), (0, 100), (0, 0)):
        assert bench.do(f"G1 X{x} Y{y}") == [Ok()]
        assert bench.fw.position() == {"X": x, "Y": y, "Z": 0.0}
        assert bench.fw.motor_counts() == (*corexy_counts(x, y), 0)
    # By hand: 100 / 0.00245 = 40816.3, truncated 40816 on each axis (FIDELITY S1-03:
    # rounding 200 / 0.00245 = 81632.7 would give 81633).
    assert corexy_counts(100, 0) == (40816, 40816)
    assert corexy_counts(100, 100) == (0, 81632)
    assert corexy_counts(0, 100) == (-40816, 40816)


def test_corexy_motor_counts_follow_the_tool_mid_move() -> None:
    bench = Bench(corexy_plotter_config())
    bench.send("G1 X10 Y10")
    bench.run(0.05)
    where = bench.fw.position()
    assert 0 < where["X"] == where["Y"] < 10
    a, b, _ = bench.fw.motor_counts()
    assert a == 0 and b == round(2 * where["X"] / MM_PER_STEP)


def test_the_corexy_plotter_answers_OK_and_ERROR() -> None:
    clock = ManualClock()
    board = GcodeFirmware(clock, corexy_plotter_config())
    out = bytearray()
    board.set_output(out.extend)
    clock.advance(CYCLE)
    board.run_until(clock.now())
    board.receive(b"G0 X1\nG7\n")
    clock.advance(0.05)  # OK once the 1 mm is drawn (408 steps at 40 000 a second)
    board.run_until(clock.now())
    assert bytes(out) == b"\r\n" + PLOTTER_BANNER.encode() + b"\r\nOK\r\nERROR:20\r\n"


def test_the_corexy_plotter_answers_OK_when_the_move_is_done_and_parses_after_it() -> None:
    """FIDELITY S1-04 (the original executes a line, then prints OK) and S1-03/S1-04: a
    move runs at one step interval from its first step to its last, mm → steps truncated."""
    bench = Bench(corexy_plotter_config())
    bench.send("G1 X10", "G1 X0")
    t0 = bench.elapsed
    got = bench.run(1.0)
    # 10 / 0.00245 = 4081.6: 4081 steps at 40 000 a second (25 µs), no ramp up or down.
    first = 4081 / 40_000
    oks = [t for t, reply in got if reply == Ok()]
    assert len(oks) == 2
    assert t0 + first <= oks[0] <= t0 + first + CYCLE
    (go, back) = bench.events("move")
    assert go["t"] == pytest.approx(START + t0 + first)
    # The second line is parsed only after the first's OK: at the next control cycle.
    assert first <= back["t"] - go["t"] <= first + CYCLE
    assert back["t"] - START <= oks[1] <= back["t"] - START + CYCLE
    assert Bench(corexy_plotter_config()).fw.config.motor_counts((0.00489, 0.0, 0.0)) == (
        1,
        1,
        0,
    )  # 1.996 steps: one whole step (rounding would make two)


def test_a_bare_g92_sets_the_corexy_plotters_origin() -> None:
    """FIDELITY S1-07: "G92 ; nastav aktuální pozici jako počátek" (GRBL refuses it)."""
    bench = Bench(corexy_plotter_config())
    assert bench.do("G1 X20 Y10", "G92") == [Ok(), Ok()]
    assert bench.fw.position() == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    assert bench.do("G1 X5") == [Ok()]
    assert bench.fw.position() == {"X": 5.0, "Y": 0.0, "Z": 0.0}
    assert Bench(grbl_plotter_config()).do("G92") == [ErrorReply(26)]


def test_the_corexy_plotter_draws_on_a_whole_a4_sheet() -> None:
    """FIDELITY S1-16: "Kreslící plocha plotteru bude rozměru alespoň A4" (297 by 210 mm)."""
    bench = Bench(corexy_plotter_config())
    assert bench.do("G1 X297 Y210") == [Ok()]
    assert bench.fw.position() == {"X": 297.0, "Y": 210.0, "Z": 0.0}
    assert bench.do("G1 Y210.5") == [ErrorReply(15)]
    profile = load_profile("corexy-plotter")  # the station's profile agrees
    assert [a.travel for a in profile.axes] == [300.0, 210.0]


def test_m99_lifts_the_corexy_pen_to_its_pwm_level() -> None:
    """FIDELITY S1-10: "Zdvihni popisovač do polohy odpovídající úrovni PWM z parametru"."""
    bench = Bench(corexy_plotter_config())
    assert bench.do("M4") == [Ok()]
    assert bench.fw.pen_down
    assert bench.do("M99 4000") == [Ok()]
    assert not bench.fw.pen_down and bench.fw.servo_level == 4000.0
    assert [e["down"] for e in bench.events("pen")] == [True, False]


def test_s1_11_servo_pwm_is_50_hz_with_the_originals_compare_values() -> None:
    """FIDELITY S1-11: clkdiv 40, wrap 62499 at 125 MHz is 50 Hz; Tab. 2 "Vztah střídy a
    polohy serva": 0.5 ms = 1562 … 2.5 ms = 7812."""
    assert servo_pwm.PWM_FREQUENCY_HZ == pytest.approx(50.0)
    assert servo_pwm.level_for_pulse(servo_pwm.SERVO_MIN_PULSE_S) == 1562
    assert servo_pwm.level_for_pulse(servo_pwm.SERVO_MAX_PULSE_S) == 7812
    assert servo_pwm.level_for_pulse(0.0015) == 4687  # the middle, 1.5 ms
    assert servo_pwm.pulse_width_s(1562) == pytest.approx(0.49984e-3)
    assert servo_pwm.pulse_width_s(7812) == pytest.approx(2.49984e-3)
    assert servo_pwm.compare_value(10**6) == 62_500  # above the wrap: high all period
    with pytest.raises(ValueError):
        servo_pwm.compare_value(-1)
    with pytest.raises(ValueError):
        servo_pwm.level_for_pulse(0.021)


def test_s1_11_the_plotters_state_shows_the_servo_pulse_of_its_m99_level() -> None:
    bench = Bench(corexy_plotter_config())
    assert bench.fw.servo_pulse_s is None  # no M99 yet
    assert bench.do("M99 7812") == [Ok()]
    assert bench.fw.servo_pulse_s == pytest.approx(2.49984e-3)
    assert bench.do("M99 1562") == [Ok()]
    assert bench.fw.servo_pulse_s == pytest.approx(0.49984e-3)


def test_bytes_sent_before_the_board_has_booted_are_lost() -> None:
    clock = ManualClock()
    board = GcodeFirmware(clock)
    out = bytearray()
    board.set_output(out.extend)
    board.receive(b"G0 X1\n?")  # before the first control cycle: still booting
    clock.advance(CYCLE)
    board.run_until(clock.now())
    assert make_decoder().feed(bytes(out)) == [Banner(GRBL_BANNER)]
    assert board.event_log[0] == {"t": CYCLE, "event": "boot", "lost": 7}
    assert board.unacknowledged == 0 and not board.busy


def test_string_art_axes_turn_9600_microsteps_per_turn() -> None:
    bench = Bench(string_art_config())
    assert bench.fw.config.axes == ("A", "X", "Z")
    assert bench.do("G0 A360 X10 Z3") == [Ok()]
    # 360° = 9600; 10 mm at 32/mm = 320; 3 mm at 133.3/mm = 399.9, rounded 400.
    assert bench.fw.motor_counts() == (9600, 320, 400)
    assert bench.do("G0 A-7200") == [Ok()]  # A turns freely: no travel to exceed
    assert bench.fw.motor_counts()[0] == -192_000
    assert bench.do("G0 X251") == [ErrorReply(15)]
    assert bench.do("G0 Y1") == [ErrorReply(20)]  # no Y on the winder


def test_string_art_rapid_is_limited_to_2000_steps_and_500_per_second_squared() -> None:
    bench = Bench(string_art_config())
    bench.send("G0 A360")
    t0 = bench.elapsed
    bench.run_until_idle()
    # 9600 steps: 4 s up to 2000 steps/s (4000 steps), 1600 steps at speed (0.8 s), 4 s down.
    (move,) = bench.events("move")
    assert move["t"] == pytest.approx(START + t0 + 8.8)


def test_the_winder_switches_drivers_off_until_their_axis_moves() -> None:
    """FIDELITY S0-25: the firmware disables its drivers while waiting and the drill's driver
    while winding (``digitalWrite(enablePinVrtani, LOW)``); emulated as ``M18 [axes]``."""
    bench = Bench(string_art_config())
    assert bench.do("G0 A10 X20 Z5", "M18") == [Ok(), Ok()]
    assert bench.fw.drivers_off == {"A", "X", "Z"}
    assert bench.fw.position() == {"A": 10.0, "X": 20.0, "Z": 5.0}  # nothing moved
    assert bench.do("G0 X30") == [Ok()]
    assert bench.fw.drivers_off == {"A", "Z"}  # a move switches on only what it moves
    assert bench.do("G0 A20 Z0", "M18 Z0") == [Ok(), Ok()]
    assert bench.fw.drivers_off == {"Z"} and bench.fw.position()["Z"] == 0.0
    assert [e["axes"] for e in bench.events("drivers off")] == ["AXZ", "Z"]
    assert bench.do("M18 G0 X1") == [ErrorReply(24)]  # motion on a driver line: refused
    assert Bench(corexy_plotter_config()).do("M18") == [ErrorReply(20)]  # the winder's only


# -- timing ----------------------------------------------------------------------------------


def test_a_single_move_takes_its_trapezoid_and_reports_its_progress() -> None:
    bench = Bench()
    bench.send("G1 X100 F3000")
    t0 = bench.elapsed
    report = bench.status()  # after 5 ms: 0.5 * 80000 * 0.005² = 1 step
    assert report.state == "Run" and report.mpos == (0.013, 0.0, 0.0)
    assert report.planner_free == 14 and report.rx_free == 128
    bench.run(0.995 - CYCLE)
    report = bench.status()  # at t0 + 1.0: 100 steps ramping, then 0.95 s at 4000/s
    assert report.state == "Run"
    assert report.mpos == (48.75, 0.0, 0.0)
    assert report.feed == 3000.0
    bench.run_until_idle()
    (move,) = bench.events("move")
    assert move["t"] == pytest.approx(START + t0 + X100_SECONDS)
    assert move["pos"] == {"X": 100.0, "Y": 0.0, "Z": 0.0} and move["kind"] == "G1"
    assert bench.status().state == "Idle"


def test_a_short_rapid_is_a_triangle() -> None:
    bench = Bench()
    # G0 X5: 400 steps; reaching 8000 steps/s would take 400 steps each way, so it
    # peaks at sqrt(400 * 80000) after sqrt(400 / 80000) s: 0.141421 s in all.
    bench.send("G0 X5")
    t0 = bench.elapsed
    bench.run_until_idle()
    (move,) = bench.events("move")
    assert move["t"] == pytest.approx(START + t0 + 2 * math.sqrt(400 / 80000))


def test_the_plotters_step_interval_sets_its_speed() -> None:
    bench = Bench(corexy_plotter_config())
    bench.send("M98 100", "M99 1500", "G1 X10")
    t0 = bench.elapsed
    bench.run_until_idle()
    assert bench.fw.step_rate == 10_000.0 and bench.fw.servo_level == 1500.0
    # 10 mm: 4081 whole steps on both motors, every one 100 µs apart (FIDELITY S1-04: no
    # ramps on the original), begun in the control cycle after M99's OK (the servo's).
    (move,) = bench.events("move")
    assert move["t"] == pytest.approx(START + t0 + CYCLE + 4081 / 10_000)


def _move_seconds(bench: Bench, line: str) -> float:
    """From the cycle the line was sent in to its move's end, on the emulated clock."""
    bench.send(line)
    t0 = START + bench.elapsed
    bench.run_until_idle()
    return float(bench.events("move")[-1]["t"]) - t0


def test_s1_01_the_corexy_plotter_ignores_f_and_runs_g0_as_g1_at_the_m98_interval() -> None:
    """FIDELITY S1-01: "Příkaz G0 a G1 je interpretován stejně"; only M98 sets the speed.

    ``G1 X10 F100`` used to take 6 s (F as GRBL reads it) and ``G0 X10`` 0.1 s.
    """
    bench = Bench(corexy_plotter_config())
    assert bench.do("M98 50") == [Ok()]
    fed = _move_seconds(bench, "G1 X10 F100")
    rapid = _move_seconds(bench, "G0 X0")
    plain = _move_seconds(bench, "G1 X10")
    # 10 mm: 4081 whole steps on both motors, 50 µs apart, from the cycle it arrived in.
    assert fed == pytest.approx(4081 * 50e-6)
    assert rapid == pytest.approx(fed) and plain == pytest.approx(fed)
    assert bench.do("M98 200") == [Ok()]
    assert _move_seconds(bench, "G0 X0 F10000") == pytest.approx(4081 * 200e-6)


def test_a_dwell_holds_the_next_move_in_order() -> None:
    bench = Bench()
    bench.send("G4 P0.5", "G0 X10", "G4 S0.25", "G0 X0")  # GRBL: P in seconds
    t0 = bench.elapsed
    bench.run_until_idle()
    # G0 X10 is 800 steps: 400 up to 8000 steps/s and 400 down, 0.2 s.
    moves = bench.events("move")
    dwells = bench.events("dwell")
    assert [d["seconds"] for d in dwells] == [0.5, 0.25]
    assert dwells[0]["t"] == pytest.approx(START + t0 + 0.5)
    assert moves[0]["t"] == pytest.approx(START + t0 + 0.7)
    assert dwells[1]["t"] == pytest.approx(START + t0 + 0.95)
    assert moves[1]["t"] == pytest.approx(START + t0 + 1.15)


def test_g8_grbl_answers_g4_only_after_the_dwell() -> None:
    """GRBL's mc_dwell: synchronise the planner, dwell, then answer ``ok``."""
    bench = Bench()
    bench.send("G0 X10", "G4 P0.5", "G0 X0")
    timed = bench.run(1.5)
    oks = [t for t, reply in timed if reply == Ok()]
    dwell = bench.events("dwell")[0]
    assert len(oks) == 3
    assert oks[1] >= round(dwell["t"] - START, 6) - 1e-9  # after the move (0.2 s) and 0.5 s
    assert oks[1] >= 0.7
    assert [e["line"] for e in bench.events("reply")] == ["G0 X10", "G4 P0.5", "G0 X0"]


# -- the receive buffer and character counting --------------------------------------------------


def test_bytes_beyond_the_receive_buffer_are_dropped_and_counted() -> None:
    bench = Bench()
    bench.fw.receive(b"G0 X1.000\n" * 20)  # 200 bytes at once; the buffer holds 127
    assert bench.fw.overflows == 73
    assert bench.fw.unacknowledged == bench.fw.max_unacknowledged == 127


def test_a_counting_host_never_overflows_the_board() -> None:
    bench = Bench()
    streamer: LineStreamer[int] = LineStreamer(StreamMode.COUNTING)
    lines = ["G1 F6000"] + [f"G1 X{i % 50 + 1}.5 Y{i % 30}.25" for i in range(200)]
    for i, text in enumerate(lines):
        streamer.queue(encode_line(text), i)
    acknowledged: list[int] = []
    for _ in range(200_000):
        for data, _ in streamer.sendable():
            bench.fw.receive(data)
        for reply in bench.replies():
            if isinstance(reply, Ok | ErrorReply):
                entry = streamer.acknowledge()
                assert isinstance(reply, Ok) and entry is not None
                acknowledged.append(entry[1])
        if streamer.idle and not bench.fw.busy:
            break
    assert acknowledged == list(range(len(lines)))
    assert bench.fw.overflows == 0
    assert 100 < bench.fw.max_unacknowledged <= 127
    assert all(e["unacknowledged"] <= 127 for e in bench.events("line"))
    assert len(bench.events("move")) == 200
    assert bench.fw.position() == {"X": 50.5, "Y": 19.25, "Z": 0.0}


def test_a_full_planner_withholds_the_replies() -> None:
    bench = Bench()
    # 20 collinear 1 mm moves at 1000 mm/s²: the planner lets X1 end at speed, so it
    # accelerates over its whole millimetre: sqrt(2 * 1 / 1000) = 0.0447 s, from 0.005 s.
    bench.send("G1 F3000", *(f"X{i}" for i in range(1, 21)))
    first = bench.replies()
    assert first == [Ok()] * 16  # G1 F3000 and 15 blocks: the planner is full
    assert bench.fw.planner_free == 0
    report = bench.status()
    assert (report.planner_free, report.rx_free) == (0, 128 - 5 * 4)  # X16…X20 still wait
    assert bench.replies(0.030) == []  # to 0.045 s: X1 still running
    # X1 ends at 0.0497: one slot, and GRBL parses one more line then, not a cycle later.
    assert bench.replies() == [Ok()]
    assert bench.run_until_idle().count(Ok()) == 4
    assert bench.fw.position()["X"] == 20.0


def test_the_log_records_each_line_with_the_bytes_then_unacknowledged() -> None:
    bench = Bench()
    bench.fw.receive(b"G0 X1\nG0 X2\nG0 X3\n")
    lines = bench.events("line")
    assert [(e["text"], e["unacknowledged"]) for e in lines] == [
        ("G0 X1", 6),
        ("G0 X2", 12),
        ("G0 X3", 18),
    ]
    bench.run(CYCLE)
    assert [(e["text"], e["line"]) for e in bench.events("reply")] == [
        ("ok", "G0 X1"),
        ("ok", "G0 X2"),
        ("ok", "G0 X3"),
    ]
    assert bench.fw.unacknowledged == 0


@pytest.mark.parametrize("config", [grbl_plotter_config, corexy_plotter_config])
def test_a_line_arriving_in_several_reads_is_logged_whole(
    config: Callable[[], GcodeConfig],
) -> None:
    """--log records the line the board's buffer received, not its last read's piece.

    Issue 34: a line split across reads was logged as its tail (``"56.78"``); the parser
    had taken its head out of the receive buffer between the reads.
    """
    bench = Bench(config())
    bench.fw.receive(b"G1 X12.34 Y")
    bench.run(3 * CYCLE)  # the parser reads the head meanwhile
    bench.fw.receive(b"56")
    bench.run(CYCLE)
    bench.fw.receive(b".78 F600\nG0 X1")
    bench.run(CYCLE)
    bench.fw.receive(b"\n")
    assert [e["text"] for e in bench.events("line")] == ["G1 X12.34 Y56.78 F600", "G0 X1"]
    bench.run_until_idle()
    assert [e["line"] for e in bench.events("reply")] == ["G1 X12.34 Y56.78 F600", "G0 X1"]


def test_a_line_longer_than_80_bytes_is_answered_error_11() -> None:
    bench = Bench(corexy_plotter_config())
    bench.fw.receive(b"G1 X1" + b" " * 100 + b"\n")  # 106 bytes: never fits a line
    assert bench.replies() == [ErrorReply(11)]
    assert bench.fw.unacknowledged == 0
    bench.fw.receive(b"(" + b"x" * 110)  # a run without a line end is taken out as it comes
    bench.run(CYCLE)
    bench.fw.receive(b"x" * 50 + b")\nG0 X1\n")
    # The CoreXY firmware answers a move once it is done (S1-07): run long enough for it.
    assert bench.replies(1.0) == [ErrorReply(11), Ok()]
    assert bench.fw.overflows == 0


def test_grbl_counts_only_what_it_keeps_of_a_line_towards_its_80_bytes() -> None:
    """G7-06, G7-07: GRBL drops spaces and comments as they arrive; 79 characters fit."""
    bench = Bench()
    bench.fw.receive(b"G1 X1" + b" " * 100 + b"F100\n")  # spaces never count
    assert [reply for _, reply in bench.run(CYCLE)] == [Ok()]
    bench.fw.receive(b"(" + b"x" * 110)  # a long comment: read on, never counted
    bench.run(CYCLE)
    bench.fw.receive(b"x" * 50 + b") G0 X2 ; and more words: ")
    bench.run(CYCLE)
    bench.fw.receive(b"y" * 80 + b"\n")
    assert bench.replies() == [Ok()]
    assert bench.fw.overflows == 0
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 2.0
    bench.fw.receive(b"G0X3" + b"0" * 76 + b"\n")  # 80 kept characters: one too many
    assert bench.replies() == [ErrorReply(11)]
    assert bench.do("G0X" + "0" * 75 + "3") == [Ok()]  # 79 fit
    assert bench.do("$I ; build info")[-1] == Ok()


def test_grbl_ends_a_line_at_a_lone_cr_and_answers_an_empty_line_ok() -> None:
    """G7-05: GRBL ends a line at CR or LF."""
    bench = Bench()
    bench.fw.receive(b"G0 X1\rG0 X2\r\n")
    # CR ends the first two lines; the LF after it ends an empty one, which GRBL answers ok.
    assert [reply for _, reply in bench.run(CYCLE)] == [Ok(), Ok(), Ok()]
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 2.0


def test_grbl_extended_real_time_bytes_never_enter_a_line() -> None:
    """G7-02: bytes 0x80-0xFF are real-time commands (overrides) in GRBL 1.1."""
    bench = Bench()
    bench.fw.receive(b"G0 X\x91\x9e1\n")  # feed override and spindle stop bytes mid-line
    assert [reply for _, reply in bench.run(CYCLE)] == [Ok()]
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 1.0


def test_grbl_takes_coolant_and_tool_words_and_shows_them_in_its_modes() -> None:
    """G7-04: GRBL 1.1 takes M8/M9 and a T word (it has no tool changer: M6 is error:20)."""
    bench = Bench()
    assert bench.do("M8", "T2", "G0 X1 T3") == [Ok()] * 3
    assert bench.do("$G")[0] == Feedback("[GC:G0 G54 G17 G21 G90 G94 M5 M8 T3 F0 S0]")
    assert bench.do("M9", "M6") == [Ok(), ErrorReply(20)]  # no tool changer in GRBL 1.1
    assert bench.do("$G")[0] == Feedback("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T3 F0 S0]")


def test_grbl_check_mode_parses_without_moving_and_leaving_it_resets() -> None:
    """G7-03: $C as GRBL 1.1 does it (seen on grbl-sim: Disabled, ok, then the banner)."""
    bench = Bench()
    assert bench.do("$C") == [Feedback("[MSG:Enabled]"), Ok()]
    assert bench.fw.state == "Check"
    assert bench.do("G0 X10", "G1 X5", "G0 X1 Y2") == [Ok(), ErrorReply(22), Ok()]
    assert bench.events("move") == []
    assert bench.do("$C")[:3] == [Feedback("[MSG:Disabled]"), Ok(), Banner(GRBL_BANNER)]
    assert bench.fw.state == "Idle" and bench.fw.position()["X"] == 0.0
    assert bench.do("G0 X1") == [Ok()]
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 1.0


def test_a_jog_line_behind_a_jog_cancel_waits_for_the_stop_then_runs() -> None:
    """G7-01: GRBL reads no line while a cancelled jog brakes; the next jog then runs."""
    bench = Bench()
    bench.send("$J=G91 X20 F3000")
    bench.run(0.1)
    assert bench.fw.state == "Jog"
    bench.fw.receive(b"\x85" + encode_line("$J=G91 X1 F3000"))
    replies = bench.run_until_idle()
    assert replies == [Ok()]  # the line behind the cancel: taken, not refused
    cancelled = bench.events("jog cancelled")[0]["pos"]["X"]
    assert bench.fw.position()["X"] == pytest.approx(cancelled + 1.0)


def test_grbl_soft_limits_are_off_by_default_and_settable() -> None:
    """G7-08: GRBL's $20=0: a move beyond the travel runs; with $20=1 it is error:15."""
    bench = Bench()
    assert bench.do("G0 X301") == [Ok()]
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 301.0
    assert bench.do("G0 X0") == [Ok()]
    bench.run_until_idle()
    assert bench.do("$20=1", "$130=250") == [Ok()] * 2
    assert bench.do("G0 X251") == [ErrorReply(15)]
    assert bench.do("G3 X20 Y0 I10 J0 F3000") == [ErrorReply(15)]  # an arc under Y = 0
    assert bench.do("G0 X250") == [Ok()]
    assert Feedback("$130=250.000") in bench.do("$$")
    assert bench.do("$999=1", "$20=-1") == [ErrorReply(3), ErrorReply(4)]


def test_grbl_rates_and_accelerations_are_settable() -> None:
    """G7-08: $110… and $120… change the motion."""
    bench = Bench()
    assert bench.do("$110=1200", "$111=1200", "$112=1200") == [Ok()] * 3
    bench.send("G0 X10")
    t0 = bench.elapsed
    bench.run_until_idle()
    # 1200 mm/min = 20 mm/s (1600 steps/s), reached in 0.02 s at 1000 mm/s²: 0.52 s for 10 mm.
    assert bench.events("move")[0]["t"] == pytest.approx(START + t0 + 0.52, abs=0.006)


def test_grbl_home_with_homing_disabled_is_error_5() -> None:
    """G8-06: GRBL's $22=0 answers $H with error:5 (setting disabled)."""
    bench = Bench()
    assert bench.do("$22=0", "$H") == [Ok(), ErrorReply(5)]


def test_grbl_status_mask_leaves_out_the_buffers_as_a_fresh_board_does() -> None:
    """G8-02: $10=1, GRBL's default, leaves Bf: out of the status reports."""
    bench = Bench()
    assert bench.status().planner_free == 15
    assert bench.do("$10=1") == [Ok()]
    report = bench.status()
    assert report.planner_free is None
    assert report.mpos == (0.0, 0.0, 0.0)


# -- errors ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("line", "code"),
    [
        ("G1 X10 Q1", 20),  # no such word
        ("G5 X1", 20),
        ("M98 100", 23),  # GRBL drops the space: M98100 does not fit its byte (gcode.c)
        ("M98", 20),  # the plotter's code, not GRBL's
        ("A10", 20),  # no A on a plotter
        ("T1.5", 20),
        ("T256 M6", 38),  # GRBL's bound on a tool number
        ("T1 T2", 25),
        ("T-1", 4),
        ("G1 X1.2.3 F100", 1),
        ("10", 1),
        ("G1 X F100", 2),
        ("G0 G1 X1", 21),
        ("G90 G91", 21),
        ("G1 X1 F-1", 4),
        ("G1 X1", 22),  # GRBL needs a feed rate first
        ("G28 G0 X1", 24),
        ("G0 X1 X2", 25),
        ("G92", 26),
        ("N-5 G0 X1", 27),
        ("G4", 28),
        ("G0 X1 P5", 36),
        ("G2 X10 Y0 F100", 35),
        ("G2 X10 Y0 R2 F100", 34),
        ("G2 X10 Y0 I1 J1 F100", 33),
        ("G2 X0 Y0 I1000000000 F100", 33),  # a circle of a thousand km: not flattened
        ("$Q", 2),  # read as $N=value, and Q is no number (grbl-sim answers so too)
    ],
)
def test_refused_lines_get_grbls_error_and_move_nothing(line: str, code: int) -> None:
    bench = Bench()
    assert bench.do(line) == [ErrorReply(code)]
    assert bench.fw.position() == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    assert bench.events("move") == []
    assert bench.do("G0 X1") == [Ok()]  # and the board goes on


def test_a_refused_line_changes_no_mode() -> None:
    bench = Bench()
    assert bench.do("G91 G1 X1 F100 Q2") == [ErrorReply(20)]
    assert bench.do("G0 X5") == [Ok()]  # still absolute, still G0
    assert bench.fw.position()["X"] == 5.0


def test_comments_line_numbers_and_empty_lines() -> None:
    bench = Bench()
    assert (
        bench.do("N10 G0 X5 (to the side) ; done", "", "(just a comment)", "; also") == [Ok()] * 4
    )
    assert bench.fw.position()["X"] == 5.0


@settings(max_examples=60, deadline=None)
@given(st.lists(st.binary(max_size=60), max_size=12), st.sampled_from(["grbl", "corexy"]))
def test_the_firmware_never_raises_on_any_input(chunks: list[bytes], which: str) -> None:
    config = grbl_plotter_config() if which == "grbl" else corexy_plotter_config()
    bench = Bench(config)
    for chunk in chunks:
        bench.fw.receive(chunk)
        bench.run(0.02)
    bench.fw.receive(b"\x18")
    assert Banner(config.banner) in bench.replies()
    assert bench.do("G0 X1") == [Ok()]


# -- real-time commands ------------------------------------------------------------------------


def test_feed_hold_brakes_and_resume_finishes_the_move() -> None:
    bench = Bench()
    bench.send("G1 X100 F3000")
    t0 = bench.elapsed
    bench.run(1.0)  # cruising at 4000 steps/s, 3900 steps made
    bench.fw.receive(b"!")
    report = bench.status()
    assert (report.state, report.substate) == ("Hold", "1")  # braking
    bench.run(0.05)  # 4000 / 80000 s of braking, 100 steps: stopped at 4000 steps
    report = bench.status()
    assert (report.state, report.substate, report.mpos) == ("Hold", "0", (50.0, 0.0, 0.0))
    bench.run(1.0)
    assert bench.fw.position()["X"] == pytest.approx(50.0)
    assert bench.events("move") == []
    bench.fw.receive(b"~")
    t1 = bench.elapsed
    bench.run_until_idle()
    # The remaining 4000 steps from rest: 0.05 + 3800 / 4000 + 0.05 = 1.05 s.
    (move,) = bench.events("move")
    assert move["t"] == pytest.approx(START + t1 + 1.05)
    assert bench.fw.position()["X"] == 100.0
    assert move["t"] > START + t0 + X100_SECONDS  # the hold cost its braking and its wait


def test_resume_is_ignored_until_the_hold_is_complete() -> None:
    bench = Bench()
    bench.send("G1 X100 F3000")
    bench.run(1.0)
    bench.fw.receive(b"!~")
    bench.run(0.1)
    assert bench.fw.state == "Hold"
    bench.fw.receive(b"~")
    bench.run(CYCLE)
    assert bench.fw.state == "Run"


def test_a_hold_while_idle_keeps_new_lines_waiting() -> None:
    bench = Bench()
    bench.fw.receive(b"!")
    assert bench.status().substate == "0"
    bench.send("G0 X10")
    assert bench.replies() == [Ok()]
    bench.run(1.0)
    assert bench.fw.position()["X"] == 0.0
    bench.fw.receive(b"~")
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 10.0


def test_m0_pauses_until_cycle_start() -> None:
    bench = Bench()
    bench.send("G0 X10", "M0", "G0 X20")
    assert bench.replies() == [Ok()] * 3
    bench.run(2.0)
    assert bench.fw.position()["X"] == 10.0
    report = bench.status()
    assert (report.state, report.substate) == ("Hold", "0")
    bench.fw.receive(b"~")
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 20.0
    assert [e["event"] for e in bench.fw.event_log if e["event"] in ("move", "pause")] == [
        "move",
        "pause",
        "move",
    ]


def test_soft_reset_stops_clears_and_sends_the_banner() -> None:
    bench = Bench()
    bench.send("G1 X100 F3000", "G1 X0", "G1 Y50")
    bench.run(1.0)
    bench.fw.receive(b"G1 X5")  # a partial line, lost with the reset
    bench.fw.receive(b"\x18")
    # A reset in motion: GRBL's ALARM:3, its banner, then the unlock message (grbl-sim says so).
    assert bench.fw.state == "Alarm" and bench.fw.unacknowledged == 0
    stopped = bench.fw.position()
    assert 0 < stopped["X"] < 100
    assert bench.replies() == [
        AlarmReply(3),
        Banner(GRBL_BANNER),
        Feedback("[MSG:'$H'|'$X' to unlock]"),
    ]
    bench.run(1.0)
    assert bench.fw.position() == stopped  # kept, and nothing queued runs
    assert bench.do("$X") == [Feedback("[MSG:Caution: Unlocked]"), Ok()]
    # The modes are GRBL's power-on ones again: G1 needs its feed rate anew.
    assert bench.do("G1 X0") == [ErrorReply(22)]
    assert bench.do("G1 X0 F3000") == [Ok()]


def test_real_time_bytes_inside_a_line_are_picked_out() -> None:
    bench = Bench()
    bench.fw.receive(b"G0 X?1\n")
    replies = bench.replies()
    assert isinstance(replies[0], Ok) and isinstance(replies[1], StatusReport)
    assert [e["text"] for e in bench.events("line")] == ["G0 X1"]


# -- the pen ---------------------------------------------------------------------------------


def test_corexy_pen_lifts_with_m3_and_lowers_with_m4() -> None:
    bench = Bench(corexy_plotter_config())
    assert bench.do("G0 X10", "M4", "G1 X20", "M3", "G0 X0") == [Ok()] * 5
    assert not bench.fw.pen_down
    pens = bench.events("pen")
    assert [(e["down"], e["pos"]["X"]) for e in pens] == [(True, 10.0), (False, 20.0)]
    assert [(m["pos"]["X"], m["pen"]) for m in bench.events("move")] == [
        (10.0, False),
        (20.0, True),
        (0.0, False),
    ]


def test_grbl_pen_lowers_with_m3_s_and_lifts_with_m5() -> None:
    bench = Bench()
    assert bench.do("M3 S0") == [Ok()]
    assert not bench.fw.pen_down  # the servo at 0: still up
    assert bench.do("S1000") == [Ok()]
    assert bench.fw.pen_down
    assert bench.status().spindle == 1000.0
    assert bench.do("M5") == [Ok()]
    assert not bench.fw.pen_down
    assert bench.do("M3 S800 G0 X10") == [Ok()]  # the pen first, then the move
    (move,) = bench.events("move")
    assert move["pen"] is True
    assert [e["down"] for e in bench.events("pen")] == [True, False, True]


# -- modes -----------------------------------------------------------------------------------


def test_g91_moves_relative_and_g90_absolute_again() -> None:
    bench = Bench()
    assert bench.do("G91", "G0 X10", "G0 X10", "Y5", "G90", "X1") == [Ok()] * 6
    assert [m["pos"]["X"] for m in bench.events("move")] == [10.0, 20.0, 20.0, 1.0]
    assert bench.fw.position() == {"X": 1.0, "Y": 5.0, "Z": 0.0}


def test_g20_takes_inches() -> None:
    bench = Bench()
    assert bench.do("G20 G0 X1 Y2") == [Ok()]
    assert bench.fw.position() == {"X": 25.4, "Y": 50.8, "Z": 0.0}


def test_g8_03_g92_sets_a_work_offset_and_the_machine_position_stays() -> None:
    """GRBL 1.1: G92 = MPos - WPos; MPos stays, absolute targets are work coordinates."""
    bench = Bench()
    assert bench.do("G0 X20 Y10", "G92 X0 Y0") == [Ok()] * 2
    assert bench.fw.position() == {"X": 20.0, "Y": 10.0, "Z": 0.0}
    assert bench.fw.work_offset() == {"X": 20.0, "Y": 10.0, "Z": 0.0}
    assert bench.fw.motor_counts() == (1600, 800, 0)
    # A relative move moves by what it says, not by the offset too.
    assert bench.do("G91 G0 X5", "G90") == [Ok()] * 2
    assert bench.fw.position()["X"] == 25.0
    # An absolute target is a work position: X2 is machine X22.
    assert bench.do("G0 X2 Y3") == [Ok()]
    assert bench.fw.position() == {"X": 22.0, "Y": 13.0, "Z": 0.0}
    # Only the named axes change their offset; inches count as inches.
    assert bench.do("G20 G92 X1", "G21") == [Ok()] * 2
    assert bench.fw.work_offset() == pytest.approx({"X": 22.0 - 25.4, "Y": 10.0, "Z": 0.0})
    assert bench.events("offset")[0]["offset"] == {"X": 20.0, "Y": 10.0, "Z": 0.0}


def test_g8_03_g92_1_clears_the_offset_and_a_soft_reset_does_too() -> None:
    bench = Bench()
    assert bench.do("G0 X20 Y10", "G92 X0 Y0", "G92.1", "G0 X2") == [Ok()] * 4
    assert bench.fw.position()["X"] == 2.0
    assert bench.fw.work_offset()["X"] == 0.0
    assert bench.do("G92 X0") == [Ok()]
    assert bench.fw.work_offset()["X"] == 2.0
    bench.fw.soft_reset()
    assert isinstance(bench.replies()[0], Banner)
    assert bench.fw.work_offset()["X"] == 0.0  # GRBL's gc_init: G92 is not kept
    assert bench.do("G92") == [ErrorReply(26)]  # no axis words, as GRBL


def test_g8_03_status_reports_carry_wco_and_wpos_as_grbl() -> None:
    bench = Bench()
    assert bench.do("G0 X20 Y10", "G92 X5 Y5") == [Ok()] * 2
    first = bench.status()
    assert first.fields["MPos"] == "20.000,10.000,0.000"
    assert first.fields["WCO"] == "15.000,5.000,0.000"
    # While idle, every 10th report carries WCO again.
    carried = ["WCO" in bench.status().fields for _ in range(20)]
    assert carried == ([False] * 9 + [True]) * 2
    # $10 bit 0 clear: WPos, the machine position minus the offset.
    assert bench.do("$10=0") == [Ok()]
    assert bench.status().fields["WPos"] == "5.000,5.000,0.000"
    assert bench.do("G0 X7") == [Ok()]
    assert bench.status().fields["WPos"] == "7.000,5.000,0.000"
    # A change of offset: the very next report carries WCO.
    assert bench.do("G92.1") == [Ok()]
    report = bench.status()
    assert report.fields["WCO"] == "0.000,0.000,0.000"
    assert report.fields["WPos"] == "22.000,10.000,0.000"


def test_g8_03_dollar_hash_lists_the_g92_offset() -> None:
    bench = Bench()
    replies = bench.do("G0 X20 Y10", "G92 X5 Y5", "$#")
    texts = [r.text for r in replies if isinstance(r, Feedback)]
    assert "[G92:15.000,5.000,0.000]" in texts
    assert "[G54:0.000,0.000,0.000]" in texts
    assert replies[-1] == Ok()


def test_g8_03_g92_is_answered_once_the_motion_before_it_is_done() -> None:
    """GRBL synchronises its planner on a work-offset change, then answers."""
    bench = Bench()
    bench.send("G1 X20 F1200", "G92 X0")  # 1 s of motion
    timed = bench.run(2.0)
    oks = [t for t, reply in timed if reply == Ok()]
    move = bench.events("move")[0]
    assert len(oks) == 2
    assert oks[0] < 0.1  # the move is answered once planned
    assert oks[1] >= round(move["t"] - START, 6) - 1e-9  # G92 once the move is done


def test_g28_and_dollar_h_go_home() -> None:
    bench = Bench()
    assert bench.do("G0 X20 Y10", "G28") == [Ok()] * 2
    assert bench.fw.position() == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    assert bench.do("G0 X20 Y10", "G28 X30") == [Ok()] * 2  # through X30 Y10
    assert [m["pos"]["X"] for m in bench.events("move")][-2:] == [30.0, 0.0]
    bench.do("G0 X20")
    bench.send("$H")
    bench.run(CYCLE)
    assert bench.fw.state == "Home"
    bench.run_until_idle()
    assert bench.fw.position()["X"] == 0.0


# -- arcs --------------------------------------------------------------------------------------


def test_arcs_are_flattened_and_end_exactly_at_the_target() -> None:
    bench = Bench()
    bench.send("G2 X20 Y0 I10 J0 F3000")
    assert bench.replies() == []  # 78 segments, more than the planner holds
    replies = bench.run_until_idle()
    assert replies == [Ok()]
    segments = [m for m in bench.events("move") if m["kind"] == "G2"]
    # Half a circle of radius 10 within 0.002 mm: floor(5π / sqrt(0.002 * 19.998)) = 78.
    assert len(segments) == 78
    assert segments[-1]["pos"] == {"X": 20.0, "Y": 0.0, "Z": 0.0}
    assert bench.fw.position() == {"X": 20.0, "Y": 0.0, "Z": 0.0}
    for segment in segments:
        x, y = segment["pos"]["X"], segment["pos"]["Y"]
        assert math.hypot(x - 10, y) == pytest.approx(10, abs=1e-5)
        assert y >= -1e-9  # clockwise from the left: over the top
    assert max(s["pos"]["Y"] for s in segments) == pytest.approx(10, abs=0.01)


def test_radius_arcs_and_full_circles() -> None:
    bench = Bench()
    assert bench.do("G0 X50 Y50", "G3 X70 Y50 R10 F3000") == [Ok()] * 2
    assert bench.fw.position() == {"X": 70.0, "Y": 50.0, "Z": 0.0}
    assert bench.do("G2 X70 Y50 I-10 J0") == [Ok()]  # start = end with offsets: a full turn
    circle = bench.events("move")[-157:]
    xs = [m["pos"]["X"] for m in circle]
    assert min(xs) == pytest.approx(50, abs=0.01) and max(xs) == pytest.approx(70, abs=1e-9)
    # From (70, 50) around (80, 50), (20, 0) is 78 mm off the circle: an invalid target.
    assert bench.do("G3 X20 Y0 I10 J0") == [ErrorReply(33)]


def test_an_arc_leaving_the_travel_is_refused_whole() -> None:
    bench = Bench()
    assert bench.do("$20=1") == [Ok()]  # soft limits on
    assert bench.do("G3 X20 Y0 I10 J0 F3000") == [ErrorReply(15)]  # under Y = 0
    assert bench.events("move") == []


def test_the_corexy_plotter_has_no_arcs() -> None:
    bench = Bench(corexy_plotter_config())
    assert bench.do("G2 X20 Y0 I10 J0") == [ErrorReply(20)]


# -- $ commands and the alarm -------------------------------------------------------------------


def test_dollar_commands_print_then_answer() -> None:
    bench = Bench()
    replies = bench.do("$$")
    assert Feedback("$100=80.000") in replies and Feedback("$130=300.000") in replies
    assert replies[-1] == Ok()
    assert bench.do("$G") == [Feedback("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]"), Ok()]
    replies = bench.do("$I")
    assert replies[-1] == Ok() and any(
        isinstance(r, Feedback) and r.text == "[OPT:V,15,128]" for r in replies
    )


def test_a_limit_alarm_is_silent_until_a_reset_then_locks_g_code_until_unlocked() -> None:
    """GRBL 1.1h's critical event (protocol.c, ``EXEC_CRITICAL_EVENT``): after ALARM:1/2 and
    "Reset to continue" it answers nothing, not ``?`` nor ``$X``, and loses every byte but
    0x18 (main.c clears its read buffer and flags on the reset); the reset keeps the alarm."""
    bench = Bench()
    bench.send("M3 S1000", "G1 X100 F3000")
    bench.run(0.5)
    bench.fw.trigger_alarm(1)
    assert bench.replies() == [AlarmReply(1), Feedback("[MSG:Reset to continue]")]
    assert bench.fw.state == "Alarm" and not bench.fw.pen_down
    stopped = bench.fw.position()
    bench.fw.receive(b"?$X\nG0 X1\n?!~\x90")
    assert bench.replies(2.0) == []
    assert bench.fw.position() == stopped
    bench.fw.receive(b"\x18")
    assert bench.replies() == [Banner(GRBL_BANNER), Feedback("[MSG:'$H'|'$X' to unlock]")]
    assert bench.fw.state == "Alarm" and bench.fw.position() == stopped
    assert bench.do("G0 X1") == [ErrorReply(9)]
    assert bench.do("") == [Ok()]
    assert bench.status().state == "Alarm"
    assert bench.do("$X") == [Feedback("[MSG:Caution: Unlocked]"), Ok()]
    assert bench.fw.state == "Idle" and bench.fw.position() == stopped
    assert bench.do("G0 X1") == [Ok()]


def test_a_soft_limit_answers_the_line_it_stopped_once_the_reset_ends_the_lock() -> None:
    """grbl-sim: the line that raised ALARM:2 is answered ``ok`` after the 0x18, before the
    banner (its gc_execute_line returns once the critical loop ends); a hard limit during a
    ``G4`` is answered the same way."""
    bench = Bench()
    bench.send("G4 P5")
    assert bench.replies(0.5) == []  # GRBL answers a dwell once it is done
    bench.fw.trigger_alarm(2)
    assert bench.replies(1.0) == [AlarmReply(2), Feedback("[MSG:Reset to continue]")]
    bench.fw.receive(b"\x18")
    assert bench.replies() == [
        Ok(),
        Banner(GRBL_BANNER),
        Feedback("[MSG:'$H'|'$X' to unlock]"),
    ]


def test_a_reset_alarm_is_not_a_lock() -> None:
    """ALARM:3…10 come with their own reset: the board answers at once (no critical loop)."""
    bench = Bench()
    bench.fw.trigger_alarm(9)
    bench.replies()
    bench.fw.receive(b"$X\n")
    assert bench.replies() == [Feedback("[MSG:Caution: Unlocked]"), Ok()]


def test_home_needs_the_machine_idle() -> None:
    bench = Bench()
    bench.send("G0 X100")
    bench.run(CYCLE)
    assert bench.do("$H") == [ErrorReply(8)]


# -- the log -----------------------------------------------------------------------------------


def test_every_log_entry_is_small_json() -> None:
    bench = Bench(corexy_plotter_config())
    bench.do("G0 X10", "M4", "G1 X20", "G4 P10", "M3")
    bench.fw.receive(b"!~\x18")
    bench.run(CYCLE)
    kinds = {e["event"] for e in bench.fw.event_log}
    assert {"line", "reply", "move", "pen", "dwell", "hold", "resume", "reset"} <= kinds
    for entry in bench.fw.event_log:
        text = event_log_line(entry)
        assert "\n" not in text and len(text) < 200
        assert json.loads(text) == entry
        assert entry["t"] >= START


def test_grbl_lists_its_settings_as_grbl_1_1h_does() -> None:
    """The ``$$`` of grbl-sim (GRBL 1.1h), with this plotter's own axis settings."""
    bench = Bench()
    listed = [r.text for r in bench.do("$$") if isinstance(r, Feedback)]
    assert listed[:8] == ["$0=10", "$1=25", "$2=0", "$3=0", "$4=0", "$5=0", "$6=0", "$10=3"]
    assert {"$11=0.010", "$12=0.002", "$20=0", "$22=1", "$24=25.000", "$27=1.000"} <= set(listed)
    assert "$100=80.000" in listed and "$110=6000.000" in listed and "$130=300.000" in listed


def test_s0_24_the_winders_white_button_frees_the_axes_then_sets_zero_at_the_board_radius() -> None:
    """FIDELITY S0-24: "první stisknutí tlačítka … vypne udržovací proud … druhé stisknutí …
    nastaví současnou pozici jako nulovou"; the linear zero is the board radius."""
    bench = Bench(string_art_config())
    assert bench.do("G0 A90 X50 Z5") == [Ok()]
    assert not bench.fw.turn_by_hand("A", 10.0)  # a driver that holds resists the hand
    assert bench.fw.white_button() == "drivers off"
    assert bench.fw.drivers_off == {"A", "X", "Z"}
    assert bench.fw.turn_by_hand("A", -30.0) and bench.fw.turn_by_hand("X", 25.0)
    assert bench.fw.position() == {"A": 60.0, "X": 75.0, "Z": 5.0}
    assert bench.fw.white_button() == "zero set"
    assert bench.fw.position() == {"A": 0.0, "X": STRING_ART_BOARD_RADIUS_MM, "Z": 0.0}
    # From here the program's coordinates hold: X 100 is 20 mm in from the board's edge.
    assert bench.do("G0 X100") == [Ok()]
    assert bench.fw.position()["X"] == 100.0 and "X" not in bench.fw.drivers_off
    # A machine without the buttons, or one that is running, ignores a press.
    assert Bench(corexy_plotter_config()).fw.white_button() == "ignored"
    bench.send("G0 X10")
    bench.run(0.1)
    assert bench.fw.state == "Run"
    assert bench.fw.white_button() == "ignored" and bench.fw.drivers_off == {"A", "Z"}


def test_an_alarm_grbl_raises_through_its_reset_is_followed_by_the_reset() -> None:
    """ALARM:3 (a reset in motion) and the homing failures (6…10) come from GRBL's mc_reset:
    its banner and the unlock message follow, the lines it held go unanswered."""
    bench = Bench()
    bench.send("G1 X100 F3000", "G1 X0", "G1 Y50")
    bench.run(0.5)
    bench.replies()
    bench.fw.trigger_alarm(3)
    assert bench.replies() == [
        AlarmReply(3),
        Banner(GRBL_BANNER),
        Feedback("[MSG:'$H'|'$X' to unlock]"),
    ]
    assert bench.fw.state == "Alarm" and bench.fw.unacknowledged == 0
    assert bench.do("G0 X1") == [ErrorReply(9)]


def test_restoring_defaults_waits_for_a_standing_board_and_is_grbls_form() -> None:
    bench = Bench()
    bench.send("G1 X100 F3000")
    bench.run(0.2)
    bench.replies()
    assert bench.do("$RST=#") == [ErrorReply(8)]  # moving: GRBL's idle-or-alarm rule first
    bench.run_until_idle()
    assert bench.do("$RST=") == [ErrorReply(3)]
    assert bench.do("$1=100", "$RST=$") == [
        Ok(),
        Feedback("[MSG:Restoring defaults]"),
        Ok(),
        Banner(GRBL_BANNER),
    ]
    assert dict(r.text.split("=") for r in bench.do("$$") if isinstance(r, Feedback))["$1"] == "25"
