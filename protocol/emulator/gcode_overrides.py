"""The emulated GRBL board's feed and rapid overrides, as GRBL 1.1h keeps them.

The real-time bytes 0x90…0x97 are flags (``serial.c``): each kind received
since the last real-time pass counts once, and the pass (the emulator's: the
start of each control cycle) applies them (:func:`protocol.gcode.overrides.applied`).
A change re-plans every queued move at its new nominal speed (the planner's
``set_overrides``).  A soft reset and the end of a program (``M2``/``M30``,
GRBL's ``RESTORE_OVERRIDES_AFTER_PROGRAM_END``) put both back to 100 %.

``Ov:`` goes in a status report as ``report.c`` writes it: in the first
report after a change, after a reset and the one after a ``WCO:`` field (never
in the same report), then every 20th report while running, holding, homing or
jogging and every 10th while idle, and in the first report after a spindle change
(``spindle_set_state``).  ``A:`` follows ``Ov:``, in the same reports only: ``S``
for a spindle on clockwise (M3), ``C`` counter-clockwise (M4), ``F`` for flood
coolant (M8), the field left out when none is on.  The spindle override stays at 100 %: a pen
plotter's spindle is its servo, and its bytes are taken and ignored.
"""

from __future__ import annotations

from protocol.gcode.overrides import Overrides, applied

#: GRBL 1.1's REPORT_OVR_REFRESH_BUSY_COUNT and _IDLE_COUNT.
OV_REFRESH_BUSY = 20
OV_REFRESH_IDLE = 10


class OverrideState:
    """The percentages in force, the bytes waiting for the next pass, the report counter."""

    def __init__(self) -> None:
        self.values = Overrides()
        self._flags: set[int] = set()
        #: Reports left before the next ``Ov:`` (0: the next one carries it).
        self._countdown = 0

    def received(self, byte: int) -> None:
        """An override byte arrived; it acts at the next real-time pass."""
        self._flags.add(byte)

    def run_pass(self) -> bool:
        """The real-time pass: apply what came; True when a percentage changed."""
        if not self._flags:
            return False
        new = applied(self.values, frozenset(self._flags))
        self._flags.clear()
        if new == self.values:
            return False
        self.values = new
        self._countdown = 0  # GRBL: the change is reported at once
        return True

    def reset(self) -> bool:
        """Soft reset or program end: 100 % again; True when that is a change."""
        self._flags.clear()
        changed = self.values != Overrides()
        self.values = Overrides()
        self._countdown = 0
        return changed

    def refresh(self) -> None:
        """A spindle or coolant change: the next report carries ``Ov:`` (and ``A:``)."""
        self._countdown = 0

    def wco_reported(self) -> None:
        """A ``WCO:`` field went in this report: ``Ov:`` waits for the next (report.c)."""
        if self._countdown == 0:
            self._countdown = 1

    def report_field(self, busy: bool) -> str:
        """``|Ov:…`` when this report carries it, else ""."""
        if self._countdown > 0:
            self._countdown -= 1
            return ""
        self._countdown = (OV_REFRESH_BUSY if busy else OV_REFRESH_IDLE) - 1
        return "|" + self.values.field()
