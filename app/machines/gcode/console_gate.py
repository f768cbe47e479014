"""The console's gate: a raw line is judged against the travel before it may go.

The console is raw access, not a way around the motion gate: a line that
would move an axis past its travel goes only once the operator has confirmed
it.  The line is judged in the distance mode the board will be in when it
runs it (G90/G91 as the lines queued before it left it), so the gate follows
every line queued, console, panel and job alike (:meth:`ConsoleGate.note`).
A job's lines are queued on the transport's reader thread, so :attr:`relative`
is written only under the feeder's lock (see :mod:`app.machines.gcode.job_feed`).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.machine import MachineModel
from app.machines.gcode.line_targets import line_motion
from app.machines.motion_gate import MotionGate, Refusal
from protocol.gcode.codec import encode_line

#: GRBL's "setting disabled": for ``$H`` it means homing is off (``$22=0``, a new board's).
SETTING_DISABLED = 5


class ConsoleGate:
    """Judges console lines against the travel, in the distance mode the board will be in."""

    def __init__(self, model: MachineModel, gate: MotionGate) -> None:
        self._model = model
        self._gate = gate
        #: Whether the board is in G91 after the lines queued (a reset brings back G90).
        self.relative = False

    def note(self, line: str) -> None:
        """``line`` was queued: the distance mode it leaves (under the feeder's lock)."""
        self.relative = line_motion(line, self.relative, {}, ()).relative_after

    def reset(self) -> None:
        """GRBL's power-on and reset mode is G90 (under the feeder's lock)."""
        self.relative = False

    def beyond_travel(self, text: str) -> Refusal | None:
        """Why a console line would move the machine past its travel (None: it would not).

        A line the board could never take is no motion: the session refuses it on sending.
        """
        try:
            encode_line(text.strip())
        except ValueError:
            return None
        model = self._model
        axes = tuple(a.name for a in model.profile.axes)
        # The line's words are work coordinates (GRBL adds its offset); the travel is the
        # machine's.
        position = {a.name: a.work_position for a in model.axes}
        motion = line_motion(text, self.relative, position, axes)
        for name, target in motion.targets.items():
            index = axes.index(name)
            offset = 0.0 if motion.machine else model.axes[index].offset
            refusal = self._gate.refuse_target(index, target + offset)
            if refusal is not None:
                return Refusal(
                    QCoreApplication.translate("ConsoleGate", "{0} would move {1}").format(
                        repr(text.strip()), refusal
                    )
                )
        return None


def refusal_hint(line: str, code: int) -> str:
    """What the operator can do about a refusal the error's meaning alone does not explain."""
    if code == SETTING_DISABLED and line.replace(" ", "").upper().startswith("$H"):
        return QCoreApplication.translate(
            "ConsoleGate",
            ". Homing is switched off on the board ($22=0, GRBL's default): with end "
            "switches fitted, send $22=1 from the console; without them, move the machine "
            "to its origin by hand and set it there",
        )
    return ""
