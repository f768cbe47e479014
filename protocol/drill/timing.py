"""How long the reference PCB drill takes for each procedure (PROTOCOLS.md section 3).

One source for the job estimate and for the session's reply timeouts, so a
station that waits for a ``D`` waits as long as the estimate says the
procedure takes (plus a margin), and no longer.
"""

from __future__ import annotations

from collections.abc import Mapping

#: Seconds per microstep, per axis name.
STEP_PERIODS_S: Mapping[str, float] = {"X": 0.0013, "Y": 0.0015}
#: One ``V``: Z down to the sensor and 12 microsteps more at 2.5 ms, 0.2 s dwell, up in full steps.
DRILL_CYCLE_S = 1.35875
#: One ``K`` or ``Z``: the pen's solenoid settling.
PEN_TIME_S = 0.15
