"""What a G-code board shows of itself: its readouts, its replies and its event log.

:class:`~protocol.emulator.gcode_firmware.GcodeFirmware` is built on this
base, which holds what the GUI thread and the tests read (position, state,
the status report, the log) apart from what the control cycle does; the
state itself is the firmware's, set in its ``__init__`` and declared here.
"""

from __future__ import annotations

from collections import deque
from typing import Any

from protocol.emulator.cycles import ControlCycles
from protocol.emulator.gcode_interpreter import Interpreter
from protocol.emulator.gcode_machine import GcodeConfig
from protocol.emulator.gcode_overrides import OverrideState
from protocol.emulator.gcode_planner import Block, HoldState, Move, Planner
from protocol.emulator.servo_pwm import pulse_width_s

#: One event: ``{"t": seconds, "event": kind, ...}``, JSON-serialisable as it is.
GcodeEvent = dict[str, Any]

#: GRBL 1.1's REPORT_WCO_REFRESH_BUSY_COUNT and _IDLE_COUNT: reports between two ``WCO:``.
WCO_REFRESH_BUSY = 30
WCO_REFRESH_IDLE = 10


def axis_values(values: tuple[float, ...]) -> str:
    """GRBL's comma-separated axis values, three decimals (mm)."""
    return ",".join(f"{round(v, 3) + 0.0:.3f}" for v in values)


class GcodeReadouts(ControlCycles):
    """The introspection and reply half of the G-code firmware (its state is set by its init)."""

    config: GcodeConfig
    _planner: Planner
    _interpreter: Interpreter
    _rx: bytearray
    _pending: deque[Block]
    _running_line: tuple[int, str] | None
    _work_offset: tuple[float, ...]
    _wco_countdown: int
    _alarm: int | None
    _pen_down: bool
    _spindle: float
    _spindle_ccw: bool
    _overflows: int
    _unacked: int
    _max_unacked: int
    _outbox: list[bytes]
    _events: deque[GcodeEvent]
    _jog_cancelling: bool
    _drivers_off: set[str]
    _overrides: OverrideState
    _check_mode: bool
    _arriving: bytearray

    # -- introspection ---------------------------------------------------------------------

    def position(self) -> dict[str, float]:
        """Where the tool is now, per axis, in the machine's units."""
        with self._lock:
            return dict(zip(self.config.axes, self._planner.position(), strict=True))

    def work_offset(self) -> dict[str, float]:
        """GRBL's G92 offset in effect (machine minus work position); 0 on the other firmwares."""
        with self._lock:
            return dict(zip(self.config.axes, self._work_offset, strict=True))

    @property
    def overrides(self) -> tuple[int, int]:
        """GRBL's feed and rapid overrides in force, percent (100, 100 elsewhere)."""
        with self._lock:
            return self._overrides.values.feed, self._overrides.values.rapid

    def motor_counts(self) -> tuple[int, ...]:
        """Each motor's step counter: CoreXY (a, b, z), otherwise one per axis."""
        with self._lock:
            return self.config.motor_counts(self._planner.position())

    @property
    def pen_down(self) -> bool:
        with self._lock:
            return self._pen_down

    @property
    def state(self) -> str:
        """``Idle``, ``Run``, ``Hold``, ``Home`` or ``Alarm`` (without Hold's substate)."""
        with self._lock:
            if self._alarm is not None:
                return "Alarm"
            if self._check_mode:
                return "Check"
            current = self._planner.current
            jogging = isinstance(current, Move) and current.kind == "jog"
            if self._jog_cancelling or (jogging and self._planner.hold_state is HoldState.RUNNING):
                return "Jog"
            if self._planner.hold_state is not HoldState.RUNNING:
                return "Hold"
            if isinstance(current, Move) and current.kind == "home":
                return "Home"
            busy = len(self._planner) or self._pending or self._running_line
            return "Run" if busy else "Idle"

    @property
    def alarm(self) -> int | None:
        """The alarm code while in alarm."""
        with self._lock:
            return self._alarm

    @property
    def busy(self) -> bool:
        """A line waits to be parsed or a block to be executed."""
        with self._lock:
            return b"\n" in self._rx or bool(len(self._planner) or self._pending)

    @property
    def overflows(self) -> int:
        """Bytes dropped because the receive buffer was full (a correct host causes none)."""
        with self._lock:
            return self._overflows

    @property
    def unacknowledged(self) -> int:
        """Bytes received whose line has not been answered yet."""
        with self._lock:
            return self._unacked

    @property
    def max_unacknowledged(self) -> int:
        with self._lock:
            return self._max_unacked

    @property
    def planner_free(self) -> int:
        with self._lock:
            return self._planner.free

    @property
    def step_rate(self) -> float:
        """Top step rate of the motors, steps/s (``M98`` sets it on the plotter)."""
        with self._lock:
            return self._interpreter.step_rate

    @property
    def servo_level(self) -> float | None:
        """The last ``M99`` level, if any."""
        with self._lock:
            return self._interpreter.servo_level

    @property
    def servo_pulse_s(self) -> float | None:
        """The pen servo's pulse, seconds, at the last ``M99`` level (50 Hz PWM, S1-11)."""
        with self._lock:
            level = self._interpreter.servo_level
        return None if level is None else pulse_width_s(level)

    @property
    def drivers_off(self) -> frozenset[str]:
        """The axes whose drivers are off (``M18``) until a move of that axis."""
        with self._lock:
            return frozenset(self._drivers_off)

    @property
    def event_log(self) -> tuple[GcodeEvent, ...]:
        """Lines, replies, moves, pen changes, dwells, holds and resets, in order (``--log``)."""
        with self._lock:
            return tuple(self._events)

    def status_report(self) -> str:
        """What ``?`` answers now, ``<Run|MPos:1.000,2.000,0.000|FS:600,0>``."""
        with self._lock:
            state = self.state
            hold = self._planner.hold_state
            if state == "Hold":
                state += ":0" if hold is HoldState.HELD else ":1"
            position = self._planner.position()
            mask = self.config.status_mask
            kind = "MPos" if mask & 1 else "WPos"
            if not mask & 1:
                position = tuple(p - o for p, o in zip(position, self._work_offset, strict=True))
            where = axis_values(position)
            feed = self._planner.feed()
            free_rx = self.config.rx_buffer - len(self._rx)
            buffers = f"|Bf:{self._planner.free},{free_rx}" if mask & 2 else ""
            wco = ""
            if self.config.grbl:
                busy = state.split(":")[0] in ("Run", "Hold", "Home", "Jog")
                if self._wco_countdown > 0:
                    self._wco_countdown -= 1
                else:
                    self._wco_countdown = (WCO_REFRESH_BUSY if busy else WCO_REFRESH_IDLE) - 1
                    wco = "|WCO:" + axis_values(self._work_offset)
                    self._overrides.wco_reported()
                overrides = self._overrides.report_field(busy)
                wco += overrides + (self._accessories() if overrides else "")
            return f"<{state}|{kind}:{where}{buffers}|FS:{feed:.0f},{self._spindle:.0f}{wco}>"

    def _accessories(self) -> str:
        """GRBL 1.1h's ``|A:`` (report.c), after ``Ov:``: the spindle as its PWM output has it
        (on only with S > 0: S0 disables it), then flood coolant; "" with nothing on."""
        spindle = ("C" if self._spindle_ccw else "S") if self._spindle > 0 else ""
        flood = "F" if self._interpreter.modal.coolant else ""
        return f"|A:{spindle}{flood}" if spindle or flood else ""

    # -- replies and the log ------------------------------------------------------------------

    def _answer(self, reply: str, length: int, line: str, t: float | None = None) -> None:
        self._send_line(reply)
        self._unacked = max(self._unacked - length, 0)
        self._log("reply", t, text=reply, line=line)

    def _send_line(self, text: str) -> None:
        self._outbox.append(text.encode("ascii") + b"\r\n")

    def _send_banner(self) -> None:
        self._outbox.append(b"\r\n" + self.config.banner.encode("ascii") + b"\r\n")

    def _flush(self) -> None:
        if not self._outbox:
            return
        data = b"".join(self._outbox)
        self._outbox.clear()
        self._send_to_host(data)

    def _where(self, position: tuple[float, ...] | None = None) -> dict[str, float]:
        where = self._planner.position() if position is None else position
        return {axis: round(p, 6) + 0.0 for axis, p in zip(self.config.axes, where, strict=True)}

    def _log_arrival(self) -> None:
        """Log the line that has just ended, whole: all the bytes kept since the last line end.

        Looking back in the receive buffer would find only the last read's piece once the
        parser has taken the line's head out of it (GRBL reads on into its line buffer).
        """
        text = bytes(self._arriving[:-1]).decode("ascii", errors="replace").strip()
        self._arriving.clear()
        self._log("line", text=text, unacknowledged=self._unacked)

    def _log(self, event: str, t: float | None = None, **fields: Any) -> None:
        when = self.time if t is None else t
        self._events.append({"t": round(when, 6), "event": event, **fields})
