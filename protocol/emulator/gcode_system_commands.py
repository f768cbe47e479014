"""A G-code board's ``$`` commands: GRBL's settings, check mode, jogging, homing, help.

Split from :class:`~protocol.emulator.gcode_firmware.GcodeFirmware`, which
is built on it: the control cycle hands it a ``$`` line and queues what it
returns (blocks, or a GRBL error code).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from protocol.emulator import grbl_settings
from protocol.emulator.gcode_machine import GcodeConfig
from protocol.emulator.gcode_planner import Block, HoldState, Junctions, Move
from protocol.emulator.gcode_readouts import GcodeReadouts, axis_values
from protocol.emulator.gcode_work_systems import WorkSystems
from protocol.gcode.words import Word, WordError, split_words

# GRBL's error codes the ``$`` commands give (the parser's are in the interpreter).
INVALID_STATEMENT = 3
SETTING_DISABLED = 5
NOT_IDLE = 8
#: GRBL 1.1: a ``$J=`` line with a word a jog may not have (error:16).
INVALID_JOG = 16
UNDEFINED_FEED = 22
#: The G words a jog line may carry (GRBL's jogging documentation); F is required.
_JOG_G_WORDS = frozenset({20.0, 21.0, 53.0, 90.0, 91.0})
#: GRBL 1.1h's default settings, those the emulated board does not derive from its machine.
_GRBL_DEFAULTS: dict[int, float] = {
    0: 10, 1: 25, 2: 0, 3: 0, 4: 0, 5: 0, 6: 0, 10: 1, 11: 0.010, 12: 0.002, 13: 0,
    20: 0, 21: 0, 22: 0, 23: 0, 24: 25.0, 25: 500.0, 26: 250, 27: 1.0, 30: 1000, 31: 0, 32: 0,
}  # fmt: skip
#: GRBL's alarms for a reset in motion and for a reset while homing (mc_reset).
ABORT_CYCLE = 3
HOMING_FAIL_RESET = 6
#: Alarms GRBL raises through its reset (mc_reset): the banner and the unlock message follow.
RESETTING_ALARMS = frozenset({ABORT_CYCLE, HOMING_FAIL_RESET, 7, 8, 9, 10})
#: Hard and soft limits: GRBL adds "Reset to continue" and waits for the reset (protocol.c).
CRITICAL_ALARMS = frozenset({1, 2})
#: What follows ``$`` in GRBL 1.1's own commands; anything else is read as ``$N=value``.
_GRBL_COMMAND_LETTERS = "$#CGHIJNRSX"
_HELP = "[HLP:$$ $# $G $I $H $X ~ ! ? ctrl-x]"


class GcodeSystemCommands(GcodeReadouts):
    """The ``$`` half of the G-code firmware."""

    _settings_table: dict[int, float]
    _reset_after_answer: bool
    #: The board as built: what ``$RST=$`` restores its settings to (GRBL's compiled defaults).
    _factory_config: GcodeConfig
    #: Stop every motion at once and forget the queued blocks (the firmware's).
    _stop: Callable[[], None]

    def _system(self, command: str) -> list[Block] | int:
        """A ``$`` line; feedback lines go out before its ``ok``."""
        idle = self.state in ("Idle", "Alarm")
        if command == "$":
            self._send_line(_HELP)
        elif command == "$$":
            if self.state in ("Run", "Hold", "Home"):
                return NOT_IDLE
            for line in self._settings():
                self._send_line(line)
        elif command == "$G":
            self._send_line(self._interpreter.modes())
        elif command == "$#" and self.config.grbl:
            zeros = axis_values((0.0,) * len(self.config.axes))
            for number, stored in enumerate(self._interpreter.systems.stored):
                self._send_line(f"[G{54 + number}:{axis_values(stored)}]")
            for name in ("G28", "G30"):
                self._send_line(f"[{name}:{zeros}]")
            self._send_line(f"[G92:{axis_values(self._interpreter.offset)}]")
            self._send_line("[TLO:0.000]")
            self._send_line(f"[PRB:{zeros}:0]")
        elif command == "$I":
            if not idle:
                return NOT_IDLE
            self._send_line("[VER:1.1h.20190825:StepDeck emulator]")
            self._send_line(f"[OPT:V,{self._planner.capacity},{self.config.rx_buffer}]")
        elif command.startswith("$J=") and self.config.jogging:
            return self._jog(command[3:])
        elif command == "$X":
            if self._alarm is not None:
                self._alarm = None
                self._send_line("[MSG:Caution: Unlocked]")
                self._log("unlock")
        elif command == "$H":
            if not self.config.homing:
                return SETTING_DISABLED
            if not idle:
                return NOT_IDLE
            self._alarm = None
            start = self._interpreter.position
            home = (0.0,) * len(start)
            self._interpreter.position = home
            return [] if start == home else [self._interpreter.move(start, home, "home", None)]
        elif command == "$C" and self.config.grbl:
            return self._toggle_check_mode()
        elif command[1:2] == "R" and self.config.grbl:
            return self._restore(command)
        elif self.config.grbl and command[1:2] and command[1:2] not in _GRBL_COMMAND_LETTERS:
            return self._set(command)
        else:
            return INVALID_STATEMENT
        return []

    def _restore(self, command: str) -> list[Block] | int:
        """``$RST=$`` (the settings), ``$RST=#`` (G54…G59; G28 and G30 are zero here) or
        ``$RST=*`` (both), as GRBL 1.1h's system.c and settings_restore do: idle or in alarm
        only, then ``[MSG:Restoring defaults]``, the ``ok`` and a reset (its banner)."""
        if self.state not in ("Idle", "Alarm"):
            return NOT_IDLE
        if len(command) != 6 or not command.startswith("$RST=") or command[5] not in "$#*":
            return INVALID_STATEMENT
        if command[5] in "$*":
            self.config = self._factory_config
            self._settings_table = self._initial_settings()
            self._apply_settings()
        if command[5] in "#*":
            self._interpreter.systems = WorkSystems.zero(len(self.config.axes))
        self._send_line("[MSG:Restoring defaults]")
        self._reset_after_answer = True
        return []

    def _reset_alarm(self) -> None:
        """A 0x18 from the host, as GRBL's mc_reset takes it: while the axes move or brake
        into a hold the steppers are killed and ALARM:3 is said (6 while homing), before the
        reset's banner; standing (idle, a hold complete) it raises none (grbl-sim agrees)."""
        if not self.config.grbl or self._alarm is not None:
            return
        current = self._planner.current
        if isinstance(current, Move) and current.kind == "home":
            code = HOMING_FAIL_RESET
        elif self._planner.hold_state is not HoldState.HELD and self.state in (
            "Run",
            "Jog",
            "Hold",
        ):
            code = ABORT_CYCLE
        else:
            return
        self._stop()
        self._alarm = code
        self._send_line(f"ALARM:{code}")
        self._log("alarm", code=code, pos=self._where())

    def _toggle_check_mode(self) -> list[Block] | int:
        """``$C``: parse without moving; leaving check mode resets the board, as GRBL does."""
        if self._check_mode:
            self._check_mode = False
            self._send_line("[MSG:Disabled]")
            self._reset_after_answer = True
        elif self.state != "Idle":
            return NOT_IDLE
        else:
            self._check_mode = True
            self._send_line("[MSG:Enabled]")
        return []

    def _set(self, line: str) -> list[Block] | int:
        """``$N=value``: GRBL's settings (:mod:`~protocol.emulator.grbl_settings`); those that
        shape the machine act at once."""
        code = grbl_settings.store(self._settings_table, line, idle=self.state in ("Idle", "Alarm"))
        if code:
            return code
        self._apply_settings()
        return []

    def _initial_settings(self) -> dict[int, float]:
        if not self.config.grbl:
            return {}
        cfg = self.config
        table = dict(_GRBL_DEFAULTS)
        table.update({10: cfg.status_mask, 12: cfg.arc_tolerance})
        if cfg.junction_deviation is not None:
            table[11] = cfg.junction_deviation
        table.update({20: float(cfg.soft_limits), 22: float(cfg.homing)})
        for i, steps in enumerate(cfg.steps_per_unit):
            limits = cfg.travel[i]
            table[100 + i] = steps
            table[110 + i] = cfg.rates()[i] * 60.0
            table[120 + i] = cfg.accelerations()[i]
            table[130 + i] = 0.0 if limits is None else limits[1] - limits[0]
        return table

    def _apply_settings(self) -> None:
        table, cfg = self._settings_table, self.config
        count = len(cfg.axes)
        steps = tuple(table[100 + i] or cfg.steps_per_unit[i] for i in range(count))
        rate = min(table[110 + i] * s / 60.0 for i, s in enumerate(steps))
        acceleration = min(table[120 + i] * s for i, s in enumerate(steps))
        travel = tuple(
            None
            if cfg.travel[i] is None
            else (0.0, table[130 + i])
            if table[130 + i] > 0
            else cfg.travel[i]
            for i in range(count)
        )
        self.config = replace(
            cfg,
            steps_per_unit=steps,
            max_rate=rate if rate > 0 else cfg.max_rate,
            acceleration=acceleration if acceleration > 0 else cfg.acceleration,
            travel=travel,
            status_mask=int(table[10]),
            arc_tolerance=table[12] or cfg.arc_tolerance,
            soft_limits=bool(table[20]),
            homing=bool(table[22]),
            junction_deviation=None if cfg.junction_deviation is None else table[11],
            axis_rates=tuple(
                table[110 + i] / 60.0 if table[110 + i] > 0 else cfg.rates()[i]
                for i in range(count)
            ),
            axis_accelerations=tuple(
                table[120 + i] if table[120 + i] > 0 else cfg.accelerations()[i]
                for i in range(count)
            ),
        )
        self._planner.junctions = self._junctions()
        self._interpreter.config = self.config
        self._interpreter.step_rate = self.config.max_rate

    def _junctions(self) -> Junctions | None:
        """GRBL's planning settings, or None on a firmware whose moves start and end at rest."""
        cfg = self.config
        if cfg.junction_deviation is None:
            return None
        return Junctions(cfg.junction_deviation, cfg.accelerations())

    def _jog(self, body: str) -> list[Block] | int:
        """``$J=``: a move run as a jog, which leaves the parser's modal state as it was.

        Only G20/G21, G90/G91 and G53 may stand in it, and F is required; it is
        taken while idle or jogging, and its blocks report the ``Jog`` state.
        """
        if self.state not in ("Idle", "Jog"):
            return NOT_IDLE
        words = split_words(body)
        if isinstance(words, WordError):
            return words.code
        if any(w.letter == "G" and w.value not in _JOG_G_WORDS for w in words):
            return INVALID_JOG
        if any(w.letter not in ("G", "F", *self.config.axes) for w in words):
            return INVALID_JOG
        if not any(w.letter == "F" for w in words):
            return UNDEFINED_FEED
        saved = replace(self._interpreter.modal)
        result = self._interpreter.execute([Word("G", 1.0, "G1"), *words])
        self._interpreter.modal = saved
        if isinstance(result, int):
            return result
        return [replace(b, kind="jog") if isinstance(b, Move) else b for b in result]

    def _settings(self) -> list[str]:
        """``$$``: a few GRBL settings, per axis in the machine's axis order; all on GRBL."""
        if self._settings_table:
            return grbl_settings.setting_lines(self._settings_table)
        cfg = self.config
        lines = [f"$12={cfg.arc_tolerance:.3f}", "$13=0", "$20=1", "$22=1"]
        for group, values in (
            (100, cfg.steps_per_unit),
            (110, [cfg.max_rate / s * 60.0 for s in cfg.steps_per_unit]),
            (120, [cfg.acceleration / s for s in cfg.steps_per_unit]),
            (130, [0.0 if t is None else t[1] - t[0] for t in cfg.travel]),
        ):
            lines += [f"${group + i}={v:.3f}" for i, v in enumerate(values)]
        return lines
